#!/usr/bin/python3
"""Figures of a tehl study (index.h5 of `tehl sweep`, layout in docs/studies.md) as PNG files.

    plot_study.py INDEX.h5 [-o DIR]

writes
  study_path_<q>.png       one curve per scene of q = h_min, h_c, p_max, T_max, mu along the
                           path of contact (s), from each scene's result /cycle
  study_<label>.png        the summary quantities (h_min min, h_c at C, p_max max, T_max max,
                           mu mean) against each numeric varied parameter
Quantities a result does not hold (T_max, mu before the thermal model) are left out.
Exit codes: 0 done, 2 the file is missing or not a study index.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PATH_QUANTITIES = [("h_min", "h_min [um]", 1e6), ("h_c", "h_c [um]", 1e6),
                   ("p_max", "p_max [GPa]", 1e-9), ("T_max", "T_max [K]", 1.0),
                   ("mu", "mu [-]", 1.0)]
SUMMARY = [("h_min_min", "min h_min [um]", 1e6), ("h_c_pitch", "h_c at C [um]", 1e6),
           ("p_max_max", "max p_max [GPa]", 1e-9), ("T_max_max", "max T_max [K]", 1.0),
           ("mu_mean", "mean mu [-]", 1.0)]


def fail(message):
    print(f"plot_study.py: {message}", file=sys.stderr)
    sys.exit(2)


def text(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def scene_label(index, row, labels):
    parts = []
    for lab in labels:
        v = index["parameters"][lab][row]
        parts.append(f"{lab} = {text(v) if not np.issubdtype(type(v), np.number) else f'{v:g}'}")
    return ", ".join(parts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("index")
    ap.add_argument("-o", "--output-dir", default=None)
    a = ap.parse_args()
    if not os.path.isfile(a.index):
        fail(f"{a.index}: no such file")
    try:
        f = h5py.File(a.index, "r")
    except OSError as e:
        fail(f"{a.index}: not an HDF5 file ({e})")
    if "summary" not in f or "parameters" not in f or "status" not in f:
        fail(f"{a.index}: no /summary, /parameters or /status: not a tehl study index")
    out = a.output_dir or os.path.dirname(os.path.abspath(a.index))
    os.makedirs(out, exist_ok=True)
    labels = [text(x) for x in f["parameter_labels"][:]]
    status = [text(x) for x in f["status"][:]]
    results = [text(x) for x in f["result"][:]]
    written = []

    # Quantities along the path, one curve per scene (mesh-cycle studies only).
    if f.attrs.get("kind", b"") in (b"mesh_cycle", "mesh_cycle"):
        cycles = []
        for row, path in enumerate(results):
            if not path or not os.path.isfile(path):
                continue
            with h5py.File(path, "r") as r:
                cycles.append((row, {k: r["cycle"][k][:] for k in r["cycle"].keys()
                                     if k != "zone"}))
        for q, ylabel, scale in PATH_QUANTITIES:
            if not any(q in c for _, c in cycles):
                continue
            fig, ax = plt.subplots(figsize=(7, 4.5))
            for row, c in cycles:
                if q in c:
                    ax.plot(c["s"] * 1e3, c[q] * scale, lw=1.2,
                            label=scene_label(f, row, labels) +
                            ("" if status[row] == "ok" else f" ({status[row]})"))
            ax.set_xlabel("s, distance from A along the line of action [mm]")
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
            name = os.path.join(out, f"study_path_{q}.png")
            fig.tight_layout()
            fig.savefig(name, dpi=120)
            plt.close(fig)
            written.append(name)

    # Summary quantities against each numeric parameter.
    ok = np.array([s == "ok" for s in status])
    for lab in labels:
        x = f["parameters"][lab][:]
        if not np.issubdtype(x.dtype, np.number):
            x = np.arange(len(x))
            ticks = [text(v) for v in f["parameters"][lab][:]]
        else:
            ticks = None
        quantities = [(k, yl, sc) for k, yl, sc in SUMMARY if np.any(f["summary"][k][:] != 0)]
        fig, axes = plt.subplots(len(quantities), 1, figsize=(6, 2.2 * len(quantities)),
                                 sharex=True, squeeze=False)
        for ax, (k, ylabel, scale) in zip(axes[:, 0], quantities):
            y = f["summary"][k][:] * scale
            ax.plot(x[ok], y[ok], "o-", lw=1.2)
            ax.set_ylabel(ylabel, fontsize=8)
            ax.grid(alpha=0.3)
        unit = f["parameters"][lab].attrs.get("unit", b"")
        axes[-1, 0].set_xlabel(f"{lab} [{text(unit)}]" if ticks is None else lab)
        if ticks is not None:
            axes[-1, 0].set_xticks(x, ticks)
        name = os.path.join(out, f"study_{lab.replace('/', '_').replace('.', '_')}.png")
        fig.tight_layout()
        fig.savefig(name, dpi=120)
        plt.close(fig)
        written.append(name)
    for w in written:
        print(w)


if __name__ == "__main__":
    main()
