#!/usr/bin/python3
"""Figures of a tehl study (index.h5 of `tehl sweep`, layout in docs/studies.md) as PNG files.

    plot_study.py INDEX.h5 [-o DIR] [--prefix P] [--dpi D] [--table]

writes
  P_path_<q>.png           one curve per scene of q = h_min, h_c, p_max, T_max, mu along the
                           path of contact (s), from each scene's result /cycle
  P_path.png               h_min, p_max, T_max and mu along the path in one 2 x 2 figure
                           (the layout of seed 004 Figs. 9-10, 13-16, 19-22, 25-28)
  P_<label>.png            the summary quantities (h_min min, h_c at C, p_max max, T_max max,
                           mu mean) against each varied parameter
P is "study" unless --prefix is given. Parameters that take one value in every scene (a key a
study only overrides, e.g. the grid) and zip parameters that repeat an earlier one scene by
scene get no summary figure. --table prints the index as a Markdown table (varied values,
summaries in um, GPa, K) instead of drawing.
Quantities a result does not hold (T_max, mu of an isothermal run) are left out; in a study
that mixes isothermal and thermal scenes the isothermal ones get no temperature point.
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
           ("mu_mean", "mean mu [-]", 1.0), ("T_surface_max", "max surface T [K]", 1.0)]

# Summaries that are 0 where a scene's result has none (the temperatures of an isothermal
# scene, docs/studies.md): drawn without a point there, not at 0 K.
NO_VALUE_AT_ZERO = ("T_max_max", "T_surface_max")


def fail(message):
    print(f"plot_study.py: {message}", file=sys.stderr)
    sys.exit(2)


def text(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def value_text(v):
    """A varied value as shown: numbers with %g, a TOML string literal without its quotes."""
    if isinstance(v, (bytes, str)):
        t = text(v)
        if len(t) >= 2 and t[0] == t[-1] and t[0] in "\"'" and "\\" not in t:
            return t[1:-1]
        return t
    return f"{v:g}"


def scene_label(index, row, labels):
    return ", ".join(f"{lab} = {value_text(index['parameters'][lab][row])}" for lab in labels)


def shown_labels(index, labels):
    """The varied parameters that tell scenes apart: not constant, not a repeat of another."""
    shown, seen = [], []
    for lab in labels:
        values = [value_text(v) for v in index["parameters"][lab][:]]
        if len(set(values)) < 2 or values in seen:
            continue
        seen.append(values)
        shown.append(lab)
    return shown


def read_cycles(results):
    cycles = []
    for row, path in enumerate(results):
        if not path:
            continue  # a failed scene: no result file
        if not os.path.isfile(path):
            print(f"plot_study.py: warning: scene {row}: its result {path} is missing: no curve",
                  file=sys.stderr)
            continue
        try:
            with h5py.File(path, "r") as r:
                cycles.append((row, {k: r["cycle"][k][:] for k in r["cycle"].keys()
                                     if k != "zone"}))
        except (OSError, KeyError) as e:
            print(f"plot_study.py: warning: scene {row}: {path} is not readable ({e}): no curve",
                  file=sys.stderr)
    return cycles


def draw_path(ax, cycles, q, scale, label_of):
    for row, c in cycles:
        if q in c:
            ax.plot(c["s"] * 1e3, c[q] * scale, lw=1.1, label=label_of(row))
    ax.grid(alpha=0.3)


def print_table(f, labels, status):
    cols = [("h_min_min", "min h_min [um]", 1e6, "{:.4f}"), ("h_c_pitch", "h_c at C [um]", 1e6,
                                                              "{:.4f}"),
            ("p_max_max", "max p_max [GPa]", 1e-9, "{:.4f}"),
            ("T_max_max", "max T_max [K]", 1.0, "{:.1f}"), ("mu_mean", "mean mu", 1.0, "{:.4f}"),
            ("mu_max", "max mu", 1.0, "{:.4f}"),
            ("T_surface_max", "max T_surface [K]", 1.0, "{:.1f}"),
            ("dT_flash_blok_max", "max Blok rise [K]", 1.0, "{:.2f}"),
            ("wall_time", "wall [s]", 1.0, "{:.3g}")]
    cols = [c for c in cols if c[0] in f["summary"]]  # index files of earlier versions
    head = ["scene"] + labels + [c[1] for c in cols] + ["steps", "status"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for row in range(len(status)):
        cells = [str(row)] + [value_text(f["parameters"][lab][row]) for lab in labels]
        cells += [fmt.format(f["summary"][k][row] * sc) if f["summary"][k][row] != 0 else "-"
                  for k, _, sc, fmt in cols]
        cells += [str(f["steps"][row]), status[row]]
        print("| " + " | ".join(cells) + " |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("index")
    ap.add_argument("-o", "--output-dir", default=None)
    ap.add_argument("--prefix", default="study")
    ap.add_argument("--dpi", type=int, default=120)
    ap.add_argument("--table", action="store_true")
    a = ap.parse_args()
    if not os.path.isfile(a.index):
        fail(f"{a.index}: no such file")
    try:
        f = h5py.File(a.index, "r")
    except OSError as e:
        fail(f"{a.index}: not an HDF5 file ({e})")
    if "summary" not in f or "parameters" not in f or "status" not in f:
        fail(f"{a.index}: no /summary, /parameters or /status: not a tehl study index")
    all_labels = [text(x) for x in f["parameter_labels"][:]]
    labels = shown_labels(f, all_labels) or all_labels[:1]
    status = [text(x) for x in f["status"][:]]
    if a.table:
        print_table(f, labels, status)
        return
    out = a.output_dir or os.path.dirname(os.path.abspath(a.index))
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as e:
        fail(f"-o/--output-dir {out}: cannot create the folder for the figures ({e.strerror})")
    # Result paths are absolute (indexes of earlier versions: relative to the working directory
    # of the sweep); fall back to the index's scenes/ folder when the study was moved.
    base = os.path.dirname(os.path.abspath(a.index))
    results = []
    for x in f["result"][:]:
        path = text(x)
        if path and not os.path.isfile(path):
            moved = os.path.join(base, "scenes", os.path.basename(path))
            path = moved if os.path.isfile(moved) else path
        results.append(path)
    written = []

    def label_of(row):
        return scene_label(f, row, labels) + ("" if status[row] == "ok" else f" ({status[row]})")

    def save(fig, name):
        path = os.path.join(out, f"{a.prefix}_{name}.png")
        fig.tight_layout()
        try:
            fig.savefig(path, dpi=a.dpi)
        except OSError as e:
            fail(f"{path}: cannot write the figure ({e.strerror})")
        plt.close(fig)
        written.append(path)

    # Quantities along the path, one curve per scene (mesh-cycle studies only).
    if text(f.attrs.get("kind", b"")) == "mesh_cycle":
        cycles = read_cycles(results)
        xlabel = "s, distance from A along the line of action [mm]"
        for q, ylabel, scale in PATH_QUANTITIES:
            if not any(q in c for _, c in cycles):
                continue
            fig, ax = plt.subplots(figsize=(7, 4.5))
            draw_path(ax, cycles, q, scale, label_of)
            ax.set_xlabel(xlabel)
            ax.set_ylabel(ylabel)
            ax.legend(fontsize=7)
            save(fig, f"path_{q}")
        panels = [p for p in PATH_QUANTITIES if p[0] in ("h_min", "p_max", "T_max", "mu") and
                  any(p[0] in c for _, c in cycles)]
        if panels:
            fig, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True, squeeze=False)
            for ax, (q, ylabel, scale) in zip(axes.flat, panels):
                draw_path(ax, cycles, q, scale, label_of)
                ax.set_ylabel(ylabel)
            for ax in axes.flat[len(panels):]:
                ax.set_visible(False)
            for col in range(2):
                shown = [ax for ax in axes[:, col] if ax.get_visible()]
                if shown:
                    shown[-1].xaxis.set_tick_params(labelbottom=True)
                    shown[-1].set_xlabel(xlabel, fontsize=8)
            axes[0, 0].legend(fontsize=7)
            fig.suptitle(text(f.attrs.get("name", b"")), fontsize=10)
            save(fig, "path")

    # Summary quantities against each varied parameter.
    ok = np.array([s == "ok" for s in status])
    quantities = [(k, yl, sc) for k, yl, sc in SUMMARY
                  if k in f["summary"] and np.any(f["summary"][k][:] != 0)]
    for lab in labels:
        x = f["parameters"][lab][:]
        if not np.issubdtype(x.dtype, np.number):
            ticks = list(dict.fromkeys(value_text(v) for v in x))  # distinct, in order
            x = np.array([ticks.index(value_text(v)) for v in x], dtype=float)
        else:
            ticks = None
        # Lengths of roughness and relief (um) read better than tiny metres on the axis.
        unit = text(f["parameters"][lab].attrs.get("unit", b""))
        if ticks is None and unit == "m" and 0 < np.nanmax(np.abs(x)) < 1e-3:
            x, unit = x * 1e6, "um"
        # One line per combination of the other varied parameters, along this one.
        others = [o for o in labels if o != lab]
        groups = {}
        for row in range(len(x)):
            if ok[row]:
                groups.setdefault(scene_label(f, row, others), []).append(row)
        if others and all(len(rows) == 1 for rows in groups.values()):
            # Parameters varied together (zip mode): one line through all scenes.
            groups, others = {"": [r for rows in groups.values() for r in rows]}, []
        fig, axes = plt.subplots(len(quantities), 1, figsize=(5, 1.6 * len(quantities) + 0.6),
                                 sharex=True, squeeze=False)
        for ax, (k, ylabel, scale) in zip(axes[:, 0], quantities):
            y = f["summary"][k][:] * scale
            if k in NO_VALUE_AT_ZERO:  # an isothermal scene has no temperature: no point
                y = np.where(y > 0, y, np.nan)
            for name, rows in groups.items():
                rows = sorted(rows, key=lambda r: x[r])
                ax.plot(x[rows], y[rows], "o-", lw=1.2, label=name or None)
            ax.set_ylabel(ylabel, fontsize=8)
            ax.tick_params(labelsize=8)
            ax.grid(alpha=0.3)
        if others:
            axes[0, 0].legend(fontsize=6)
        axes[-1, 0].set_xlabel(f"{lab} [{unit}]" if ticks is None else lab)
        # Values over more than a decade and a half (a log range): a logarithmic axis.
        if ticks is None and np.all(x > 0) and np.nanmax(x) >= 30 * np.nanmin(x):
            axes[-1, 0].set_xscale("log")
        if ticks is not None:
            axes[-1, 0].set_xticks(range(len(ticks)), ticks)
        save(fig, lab.replace("/", "_").replace(".", "_"))
    for w in written:
        print(f"wrote {w}")


if __name__ == "__main__":
    main()
