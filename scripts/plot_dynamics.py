#!/usr/bin/python3
"""Dynamic load factor against pinion speed from `tehl dynamics --speeds` sweeps (PNG).

    plot_dynamics.py SWEEP.csv [SWEEP2.csv ...] -o OUT.png [--labels L1 [L2 ...]]

Each SWEEP.csv is a NAME_dynamics_sweep.csv written by `tehl dynamics CASE --speeds A:B:H`.
One curve per file: the dynamic load factor (peak mesh force / static mesh force), solid,
and the tracked pair's load factor (peak pair load / peak static pair load), dashed; speeds
where the response was not periodic in one mesh period are marked with a cross. Dotted
vertical lines mark where the mesh frequency meets f_n, f_n/2 and f_n/3 of each pair.
Exit codes: 0 done, 2 a file is missing or not a sweep table.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

NEEDED = ("pinion_speed_rpm", "dynamic_load_factor", "pair_load_factor", "periodic",
          "resonance_rpm")


def fail(message):
    print(f"plot_dynamics.py: {message}", file=sys.stderr)
    sys.exit(2)


def read(path):
    if not os.path.isfile(path):
        fail(f"{path}: no such file")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or any(k not in rows[0] for k in NEEDED):
        fail(f"{path}: not a sweep table of `tehl dynamics` (columns {', '.join(NEEDED)})")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sweeps", nargs="+")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--labels", nargs="+", default=None)
    a = ap.parse_args()
    labels = a.labels or [os.path.basename(p).replace("_dynamics_sweep.csv", "") for p in a.sweeps]
    if len(labels) != len(a.sweeps):
        fail("give one label per sweep file")
    fig, ax = plt.subplots(figsize=(8, 4.6))
    for i, (path, label) in enumerate(zip(a.sweeps, labels)):
        t = read(path)
        color = f"C{i}"
        n = t["pinion_speed_rpm"]
        ax.plot(n, t["dynamic_load_factor"], color=color, lw=1.4,
                label=f"{label}: peak F / F_s")
        ax.plot(n, t["pair_load_factor"], color=color, lw=1.0, ls="--",
                label=f"{label}: tracked pair")
        bad = [j for j, p in enumerate(t["periodic"]) if p < 0.5]
        if bad:
            ax.plot([n[j] for j in bad], [t["dynamic_load_factor"][j] for j in bad], "x",
                    color=color, ms=4, label=f"{label}: not periodic")
        nr = t["resonance_rpm"][0]
        for h in (1, 2, 3):
            if n[0] <= nr / h <= n[-1]:
                ax.axvline(nr / h, color=color, lw=0.8, ls=":")
                ax.text(nr / h, 1.0 + 0.04 * i, f" f_n/{h}" if h > 1 else " f_n",
                        transform=ax.get_xaxis_transform(), va="bottom", ha="center",
                        fontsize=8, color=color)
    ax.axhline(1.0, color="0.5", lw=0.6)
    ax.set_xlabel("pinion speed [rpm]")
    ax.set_ylabel("dynamic load factor [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out_dir = os.path.dirname(os.path.abspath(a.output))
    os.makedirs(out_dir, exist_ok=True)
    fig.savefig(a.output, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
