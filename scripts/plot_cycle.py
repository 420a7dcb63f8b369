#!/usr/bin/python3
"""Figures of a tehl mesh-cycle result (HDF5, layout in docs/results.md) as PNG files.

    plot_cycle.py RESULT.h5 [-o DIR]

writes, like seed 004 Figs. 3-6:
  <name>_cycle.png     C_RT = R/R0, C_UT = um/u0, C_WT = w/w0 along the path (Fig. 3)
  <name>_profiles.png  film pressure and thickness over x at A, B, the pitch point, D, E (Fig. 4)
  <name>_path.png      h_min, h_c and p_max along the path (Fig. 6)
  <name>_thermal.png   thermal runs: T_max, mid-film and surface temperatures (with Blok's
                       flash temperature for the film's mu) and the friction
                       coefficient along the path, with the slide-to-roll ratio (Figs. 5-6)
  <name>_temperature.png  thermal runs: mid-film and surface temperatures over x at A, the
                       pitch point and E
Exit codes: 0 done, 2 the file is missing or not a mesh-cycle result.
"""
import argparse
import re
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def fail(message):
    print(f"plot_cycle.py: {message}", file=sys.stderr)
    sys.exit(2)


def mark_points(ax, cyc, mm):
    """Vertical lines at B, the pitch point C and D (s in mm)."""
    for name in ("s_B", "s_C", "s_D"):
        s = cyc.attrs[name] * mm
        ax.axvline(s, color="0.6", lw=0.8, ls="--")
        ax.text(s, 1.0, " " + name[-1], transform=ax.get_xaxis_transform(), va="bottom",
                ha="center", fontsize=8, color="0.3")


def restarted_steps(f):
    """Steps whose film is the steady one that replaced a failed time step
    (/solver/steady_restart; absent in older files)."""
    if "solver/steady_restart" not in f:
        return []
    return [int(k) for k in np.flatnonzero(f["solver/steady_restart"][:])]


def failed_steps(f):
    """Steps that did not converge (/solver/termination): the one where a run stopped, or
    steps left behind with [numerics] failed_step = "steady_restart_or_skip"."""
    if "solver/termination" not in f:
        return []
    return [i for i, t in enumerate(f["solver/termination"][:]) if t.decode() != "converged"]


def film_curve(cyc, name, failed):
    """A film quantity along the path, with the steps that did not converge left out (NaN):
    their rows hold a failed attempt, not a film."""
    v = np.array(cyc[name][:], dtype=float)
    v[failed] = np.nan
    return v


def mark_restarts(ax, s, restarts):
    """A red dotted line at each restarted step (labelled once)."""
    for i, k in enumerate(restarts):
        ax.axvline(s[k], color="C3", lw=0.8, ls=":",
                   label="steady restart of a failed step" if i == 0 else None)


def nearest(s, target):
    return int(np.argmin(np.abs(s - target)))


def path_ends(cyc):
    """The first and last solved films: A and E, or A' and E' when a tip relief lifts the
    tracked pair off near the ends (attributes s_begin, s_end; absent in older files)."""
    begin = cyc.attrs["s_begin"] if "s_begin" in cyc.attrs else 0.0
    end = cyc.attrs["s_end"] if "s_end" in cyc.attrs else cyc.attrs["length"]
    a = ("A", begin) if begin <= 0 else ("A'", begin)
    e = ("E", end) if end >= cyc.attrs["length"] else ("E'", end)
    return a, e


def finite_peclet(f):
    """Whether the run's case (/case, the TOML as run) switched effects.finite_peclet on."""
    if "case" not in f:
        return False
    raw = f["case"][()]
    text = raw.decode() if isinstance(raw, bytes) else str(raw)
    return re.search(r"(?m)^\s*finite_peclet\s*=\s*true", text) is not None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("result")
    ap.add_argument("-o", "--output-dir", default=None)
    a = ap.parse_args()
    if not os.path.isfile(a.result):
        fail(f"{a.result}: no such file")
    try:
        f = h5py.File(a.result, "r")
    except OSError as e:
        fail(f"{a.result}: not an HDF5 file ({e})")
    if "cycle" not in f or "profiles" not in f:
        fail(f"{a.result}: no /cycle or /profiles group: not a tehl mesh-cycle result")
    out = a.output_dir or os.path.dirname(os.path.abspath(a.result))
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as e:
        fail(f"-o/--output-dir {out}: cannot create the folder for the figures ({e.strerror})")
    failed = failed_steps(f)
    if len(failed) == len(f["cycle/s"]):
        term = f["solver/termination"][failed[0]].decode() if failed else "?"
        print(f"plot_cycle.py: {a.result}: no step converged (step {failed[0] if failed else 0}: "
              f"{term}): nothing to plot", file=sys.stderr)
        sys.exit(4)  # tehl plot: exit 1, not converged
    if f.attrs.get("converged", "true") == "false":
        term = f["solver/termination"][:] if "solver/termination" in f else []
        where = f"step {failed[0]} ({term[failed[0]].decode()})" if failed else "a step"
        if len(failed) > 1:
            listed = ", ".join(str(k) for k in failed[:8]) + (", ..." if len(failed) > 8 else "")
            print(f"warning: {a.result}: {len(failed)} steps did not converge (steps {listed}; "
                  f"the first at {where}); the curves leave them out", file=sys.stderr)
        else:
            print(f"warning: {a.result}: the run did not converge at {where}; the figures show "
                  f"{len(f['cycle/s'])} step(s) written; the last did not converge and is left out",
                  file=sys.stderr)
    name = os.path.splitext(os.path.basename(a.result))[0]
    cyc = f["cycle"]
    mm, um = 1e3, 1e6
    s = cyc["s"][:] * mm
    restarts = restarted_steps(f)
    if restarts:
        listed = ", ".join(f"{k} (s = {s[k]:.3f} mm)" for k in restarts[:8])
        print(f"note: {a.result}: {len(restarts)} step(s) did not converge and show the steady "
              f"film at their point, marked by red dotted lines: {listed}", file=sys.stderr)
    written = []

    # Fig. 3: the dimensionless curvature, speed and load along the path.
    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(s, cyc["C_RT"][:], label=r"$C_{RT} = R/R_0$")
    ax.plot(s, cyc["C_UT"][:], label=r"$C_{UT} = u_m/u_0$")
    ax.plot(s, cyc["C_WT"][:], label=r"$C_{WT} = w/w_0$")
    mark_points(ax, cyc, mm)
    ax.set_xlabel("s, distance from A along the line of action [mm]")
    ax.set_ylabel("relative to the pitch point [-]")
    ax.set_title(f"{name}: curvature, entrainment speed and load along the path", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    written.append(os.path.join(out, f"{name}_cycle.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    # Fig. 4: pressure and film over x at A, B, C, D, E.
    prof = f["profiles"]
    if "p" in prof and "h" in prof:
        x = prof["x"][:] * mm
        p, h = prof["p"], prof["h"]
        first, last = path_ends(cyc)
        picks = [first, ("B", cyc.attrs["s_B"]), ("pitch", cyc.attrs["s_C"]),
                 ("D", cyc.attrs["s_D"]), last]
        fig, (ap_, ah) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True)
        for label, target in picks:
            # The nearest step that converged (a failed step's row holds a failed attempt).
            usable = np.setdiff1d(np.arange(min(len(s), p.shape[0])), failed)
            if usable.size == 0:
                continue
            k = int(usable[nearest(s[usable], target * mm)])
            tag = f"{label} (s = {s[k]:.2f} mm)"
            ap_.plot(x, p[k, :] / 1e9, label=tag)
            ah.plot(x, h[k, :] * um, label=tag)
        ap_.set_ylabel("pressure p [GPa]")
        ah.set_ylabel("film thickness h [um]")
        ah.set_xlabel("x [mm]")
        top = np.percentile(h[:, :] * um, 60)
        ah.set_ylim(0, max(top, 1e-3))
        for axis in (ap_, ah):
            axis.grid(alpha=0.3)
            axis.legend(fontsize=8)
        ap_.set_title(f"{name}: film pressure and thickness along the mesh", fontsize=10)
        fig.tight_layout()
        written.append(os.path.join(out, f"{name}_profiles.png"))
        fig.savefig(written[-1], dpi=120)
        plt.close(fig)

    # Fig. 6: film thickness and pressure along the path.
    fig, (ah, ap_) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ah.plot(s, film_curve(cyc, "h_c", failed) * um, label=r"$h_c$ (x = 0)")
    ah.plot(s, film_curve(cyc, "h_min", failed) * um, label=r"$h_{min}$")
    ah.set_ylabel("film thickness [um]")
    ap_.plot(s, film_curve(cyc, "p_max", failed) / 1e9, color="C3", label=r"$p_{max}$")
    ap_.set_ylabel("maximum pressure [GPa]")
    ap_.set_xlabel("s, distance from A along the line of action [mm]")
    for axis in (ah, ap_):
        mark_points(axis, cyc, mm)
        mark_restarts(axis, s, restarts)
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    ah.set_title(f"{name}: film thickness and pressure along the path", fontsize=10)
    fig.tight_layout()
    written.append(os.path.join(out, f"{name}_path.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    # Figs. 5-6: temperature and friction along the path, with the slide-to-roll ratio.
    if "T_max" in cyc:
        fig, (at, af) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True)
        at.plot(s, film_curve(cyc, "T_max", failed) - 273.15, label=r"$T_{max}$ (film)")
        at.plot(s, film_curve(cyc, "T_mid", failed) - 273.15, ls="--", label=r"mid-film $T_{max}$")
        # The surfaces' model: the high-speed form of seed 004, or Jaeger's kernel at each
        # tooth's Peclet number (docs/thermal.md "Surface temperatures at any Peclet number").
        model = " (finite Pe)" if finite_peclet(f) else ""
        at.plot(s, film_curve(cyc, "T1_max", failed) - 273.15, label="pinion surface" + model)
        at.plot(s, film_curve(cyc, "T2_max", failed) - 273.15, label="wheel surface" + model)
        if "dT_flash_blok" in cyc and "T0" in cyc.attrs:
            # Blok's estimate with the film's own mu (docs/thermal.md "Flash temperature").
            at.plot(s, cyc.attrs["T0"] + film_curve(cyc, "dT_flash_blok", failed) - 273.15, color="0.3",
                    lw=0.9, ls="-.", label=r"surface by Blok (film's $\mu$)" + model)
        at.set_ylabel("temperature [°C]")
        af.plot(s, film_curve(cyc, "mu", failed), color="C3", label=r"friction coefficient $\mu$")
        af.set_ylabel(r"$\mu$ [-]")
        srr = af.twinx()
        srr.plot(s, cyc["SRR"][:], color="0.4", lw=0.9, ls=":", label="SRR")
        srr.set_ylabel("slide-to-roll ratio [-]")
        af.set_xlabel("s, distance from A along the line of action [mm]")
        for axis in (at, af):
            mark_points(axis, cyc, mm)
            mark_restarts(axis, s, restarts)
            axis.grid(alpha=0.3)
            axis.legend(fontsize=8, loc="upper center")
        srr.legend(fontsize=8, loc="upper right")
        at.set_title(f"{name}: temperature and friction along the path", fontsize=10)
        fig.tight_layout()
        written.append(os.path.join(out, f"{name}_thermal.png"))
        fig.savefig(written[-1], dpi=120)
        plt.close(fig)
    if "T_mid" in prof:
        x = prof["x"][:] * mm
        fig, ax = plt.subplots(figsize=(7, 4.2))
        first, last = path_ends(cyc)
        for label, target, color in [(*first, "C0"), ("pitch", cyc.attrs["s_C"], "C1"),
                                     (*last, "C2")]:
            k = min(nearest(s, target * mm), prof["T_mid"].shape[0] - 1)
            ax.plot(x, prof["T_mid"][k, :] - 273.15, color=color, label=f"{label}: mid-film")
            ax.plot(x, prof["T1"][k, :] - 273.15, color=color, ls="--", lw=0.9,
                    label=f"{label}: pinion surface")
            ax.plot(x, prof["T2"][k, :] - 273.15, color=color, ls=":", lw=0.9,
                    label=f"{label}: wheel surface")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("temperature [°C]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=3)
        ax.set_title(f"{name}: temperature across the contact", fontsize=10)
        fig.tight_layout()
        written.append(os.path.join(out, f"{name}_temperature.png"))
        fig.savefig(written[-1], dpi=120)
        plt.close(fig)

    for w in written:
        print(f"wrote {w}")


if __name__ == "__main__":
    main()
