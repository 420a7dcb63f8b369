#!/usr/bin/python3
"""Accuracy against run time of tehl: writes docs/accuracy.md and docs/accuracy_pareto.png.

    accuracy_report.py --tehl PATH [--scratch DIR] [--jobs N] [--docs DIR] [--reuse]

Runs (scenes expanded and checked by `tehl sweep --dry-run`, each run by `tehl run` in its
own process, N at a time):
  - the seed 004 SAE 40 mesh cycle, thermal with the Ree-Eyring film
    (cases/seed004_sae40.toml), one setting at a time around a base (257 nodes, 11 film
    nodes, 80 steps, Newton tolerance 1e-8, no time-error control): grid N, film_nodes Nz,
    steps, newton_tolerance, time_tolerance, the inlet end;
  - a steady thermal Ree-Eyring disc (cases/disc_steady.toml with sliding, SRR 0.4), the
    series N, Nz and newton_tolerance;
  - the cost of each effect on the cycle (129 nodes, 80 steps): isothermal, rigid, steady,
    rough, Ree-Eyring against the thermal elastic transient smooth Newtonian base.
The error of each quantity is relative to the finest converged run of its series (the
reference); for
the grid series the observed order and a Richardson estimate of the reference's own error are
given from the three finest grids. Times: the result file's wall time (the HDF5 wall_time of
a mesh cycle, the sum of the wall_time_s column of a disc's _steps.csv) and the CPU time (user + system) of the process from wait4; on a loaded machine the CPU time is the
stable measure, so the Pareto plot and the relative costs use it.
--reuse reads results of an earlier run from the scratch folder instead of running again.
"""
import argparse
import csv
import itertools
import json
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
QUANTITIES = [("h_min", "h_min"), ("h_c", "h_c"), ("p_max", "p_max"), ("T_max", "T_max"),
              ("mu", "mu")]

CYCLE_BASE = {"effects.thermal": "true", "effects.non_newtonian": "true",
              "numerics.grid_points": "257",
              "numerics.film_nodes": "11", "numerics.steps": "80",
              "numerics.newton_tolerance": "1e-8", "numerics.x_start_b": "-4.5",
              "numerics.time_tolerance": "0"}
DISC_BASE = {"contact.speed_1_m_s": "1.2", "contact.speed_2_m_s": "0.8",
             "effects.thermal": "true", "effects.non_newtonian": "true",
             "numerics.grid_points": "257", "numerics.film_nodes": "11",
             "numerics.newton_tolerance": "1e-8", "numerics.x_start_b": "-4.5"}
# A heavily loaded, slow disc (p_H = 1.9 GPa): its Hertzian edge is narrow (docs/results.md,
# "The edge note"), so its films need far finer grids than the base's; the automatic grid
# (grid_points = 0, docs/case_format.md) is run beside the series.
HEAVY_BASE = {"contact.load_n_per_m": "1.0e6", "contact.speed_1_m_s": "0.12",
              "contact.speed_2_m_s": "0.08", "effects.thermal": "true",
              "effects.non_newtonian": "true", "numerics.grid_points": "513",
              "numerics.film_nodes": "11", "numerics.newton_tolerance": "1e-8",
              "numerics.x_start_b": "-4.5"}
# The inlet end of the grid, with grid_points raised with the domain so that the node spacing
# stays that of the base (6 b / 256) and x = 0 stays a node: the error of a truncated inlet
# alone, and its cost.
INLET = ("inlet", "numerics.x_start_b", ["-3", "-4.5", "-6", "-8", "-12", "-16"],
         {"-3": {"numerics.grid_points": "193"}, "-6": {"numerics.grid_points": "321"},
          "-8": {"numerics.grid_points": "419"}, "-12": {"numerics.grid_points": "577"},
          "-16": {"numerics.grid_points": "771"}})
SERIES = {
    "cycle": [("N", "numerics.grid_points", ["129", "257", "513", "1025"]),
              ("Nz", "numerics.film_nodes", ["5", "7", "11", "21"]),
              ("steps", "numerics.steps", ["40", "80", "150", "300"]),
              ("tol", "numerics.newton_tolerance", ["1e-4", "1e-6", "1e-8", "1e-10"]),
              ("time_tol", "numerics.time_tolerance", ["0", "1e-2", "1e-3", "1e-4"]),
              INLET],
    "disc": [("N", "numerics.grid_points", ["129", "257", "513", "1025"]),
             ("Nz", "numerics.film_nodes", ["5", "7", "11", "21"]),
             ("tol", "numerics.newton_tolerance", ["1e-4", "1e-6", "1e-8", "1e-10"]),
             INLET],
    "heavy": [("N", "numerics.grid_points", ["257", "513", "1025", "2049", "4097", "8193"])],
}
# Runs beside the series (case, label, key, value): compared with the reference of the case's
# grid series.
EXTRA = [("heavy", "automatic grid", "numerics.grid_points", "0")]
CASES = [("cycle", "cases/seed004_sae40.toml", CYCLE_BASE),
         ("disc", "cases/disc_steady.toml", DISC_BASE),
         ("heavy", "cases/disc_steady.toml", HEAVY_BASE)]
EFFECT_BASE = {"effects.thermal": "true", "numerics.grid_points": "129",
               "numerics.steps": "80"}
EFFECTS = [("base: thermal, elastic, transient, smooth, Newtonian", {}),
           ("isothermal", {"effects.thermal": "false"}),
           ("rigid", {"effects.elastic": "false"}),
           ("steady (no squeeze term)", {"effects.transient": "false"}),
           ("rough (0.1 um, 50 um; steps raised by the roughness rule)",
            {"effects.roughness": "true", "numerics.steps": "0",
             "surfaces.surface1.roughness": '"sinusoidal"',
             "surfaces.surface1.amplitude_m": "1e-7",
             "surfaces.surface1.wavelength_m": "5e-5",
             "surfaces.surface2.roughness": '"sinusoidal"',
             "surfaces.surface2.amplitude_m": "1e-7",
             "surfaces.surface2.wavelength_m": "5e-5"}),
           ("Ree-Eyring (non_newtonian, tau0 = 5 MPa)", {"effects.non_newtonian": "true"})]


def fail(message):
    print(f"accuracy_report.py: {message}", file=sys.stderr)
    sys.exit(2)


def expand(tehl, name, base_case, scenes, scratch):
    """Writes a zip study of `scenes` (dicts key -> TOML literal) and expands it with
    `tehl sweep --dry-run`; returns the scene case files."""
    keys = sorted({k for s in scenes for k in s})
    folder = os.path.join(scratch, name)
    os.makedirs(folder, exist_ok=True)
    lines = [f'[study]\nbase = "{base_case}"\nmode = "zip"\nname = "{name}"\n'
             f'output = "{folder}"\n']
    for k in keys:
        missing = [i for i, s in enumerate(scenes) if k not in s]
        if missing:
            fail(f"{name}: key {k} missing in scenes {missing}")
        lines.append(f'[[vary]]\nkey = "{k}"\nvalues = [{", ".join(s[k] for s in scenes)}]\n')
    study = os.path.join(folder, "study.toml")
    with open(study, "w") as f:
        f.write("\n".join(lines))
    r = subprocess.run([tehl, "sweep", study, "--dry-run", "-q"], capture_output=True,
                       text=True)
    if r.returncode != 0:
        fail(f"tehl sweep --dry-run {study}:\n{r.stdout}{r.stderr}")
    return [os.path.join(folder, "scenes", f"scene_{i:04d}.toml") for i in range(len(scenes))]


def run_one(tehl, case):
    """Runs one case in its own process; returns wall and CPU time of the process."""
    log = case[:-5] + ".log"
    t0 = time.monotonic()
    with open(log, "w") as out:
        p = subprocess.Popen([tehl, "run", case], stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
        p.returncode = os.waitstatus_to_exitcode(status)
    info = {"case": case, "rc": p.returncode, "process_wall_s": time.monotonic() - t0,
            "cpu_s": usage.ru_utime + usage.ru_stime}
    with open(case[:-5] + ".json", "w") as f:
        json.dump(info, f)
    return info


def read_contact_steps(path):
    """Summaries of a [contact] run's NAME_steps.csv (columns in docs/results.md): the film at
    the last step; max over the steps of t_max_k, mean of mu (the cycle's definitions); the
    wall time the sum of the steps' wall_time_s. A file without those columns (written before
    they existed) gives None for them; a file without steps gives None."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return None
    last = rows[-1]
    head = rows[0].keys()

    def column(name):
        return [float(r[name]) for r in rows] if name in head else None

    t_max, mu, wall = column("t_max_k"), column("mu"), column("wall_time_s")
    restarts = column("steady_restart")
    return {"h_min": float(last["h_min_m"]), "h_c": float(last["h_c_m"]),
            "p_max": float(last["p_max_pa"]),
            "T_max": max(t_max) if t_max else None,
            "mu": sum(mu) / len(mu) if mu else None,
            "wall_s": sum(wall) if wall else None,
            "steps_run": len(rows) - 1,
            "restarts": int(sum(restarts)) if restarts else 0}


def read_result(info):
    """Summaries of one run: the seed's quantities and the times."""
    stem = info["case"][:-5]
    row = dict(info)
    h5 = stem + ".h5"
    if os.path.isfile(h5):
        with h5py.File(h5, "r") as f:
            c = f["cycle"]
            s = c["s"][:]
            i_c = int(np.argmin(np.abs(s - c.attrs["s_C"])))
            row["h_min"] = float(np.min(c["h_min"][:]))
            row["h_c"] = float(c["h_c"][i_c])
            row["p_max"] = float(np.max(c["p_max"][:]))
            row["T_max"] = float(np.max(c["T_max"][:])) if "T_max" in c else None
            row["mu"] = float(np.mean(c["mu"][:])) if "mu" in c else None
            row["wall_s"] = float(f.attrs["wall_time"])
            row["steps_run"] = len(s) - 1
            # A run whose failed time steps were replaced by the steady film (docs/results.md)
            # is not a converged transient run: it neither has an error nor serves as a
            # reference.
            restarts = int(np.sum(f["solver/steady_restart"][:])) \
                if "solver/steady_restart" in f else 0
            row["ok"] = str(f.attrs["converged"]) in ("true", "b'true'") and restarts == 0
        return row
    steps = stem + "_steps.csv"
    summary = read_contact_steps(steps) if os.path.isfile(steps) else None
    if summary is not None:
        row.update(summary)
        row["ok"] = info["rc"] == 0 and summary["restarts"] == 0
        return row
    row.update({q: None for q, _ in QUANTITIES})
    row.update({"wall_s": None, "steps_run": 0, "ok": False})
    return row


def run_all(tehl, cases, jobs, reuse):
    def one(case):
        cached = case[:-5] + ".json"
        if reuse and os.path.isfile(cached):
            with open(cached) as f:
                return json.load(f)
        return run_one(tehl, case)

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        infos = list(pool.map(one, cases))
    return [read_result(i) for i in infos]


def rel_error(v, ref):
    if v is None or ref is None or ref == 0:
        return None
    return abs(v - ref) / abs(ref)


def pct(e):
    return "-" if e is None else (f"{100 * e:.2g}" if e >= 1e-4 else "<0.01")


def fmt_t(t):
    return "-" if t is None else f"{t:.1f}"


def richardson(values, ratio=2.0):
    """Observed order and the extrapolated limit from three values on grids refined by
    `ratio` (coarse to fine): p = log(|f1 - f2| / |f2 - f3|) / log(r)."""
    f1, f2, f3 = values
    if None in values or f2 == f3 or f1 == f2 or (f1 - f2) * (f2 - f3) <= 0:
        return None, None
    p = np.log(abs(f1 - f2) / abs(f2 - f3)) / np.log(ratio)
    return p, f3 + (f3 - f2) / (ratio ** p - 1)


def reference(rows):
    """The finest converged run of a series (rows coarse to fine), or None."""
    ok = [r for r in rows if r["ok"]]
    return ok[-1] if ok else None


def series_tables(case_name, rows_by_series):
    out = []
    for label, key, values, *_ in SERIES[case_name]:
        rows = rows_by_series[label]
        ref = reference(rows)
        base_cpu = next((r["cpu_s"] for r in rows if r["is_base"]), None)
        ref_v = values[rows.index(ref)] if ref else "none (no run converged)"
        out.append(f"\n**{case_name}, {label}** (`{key}`; reference: {label} = {ref_v})\n")
        out.append("| " + " | ".join([label] + [f"err {q} [%]" for q, _ in QUANTITIES] +
                                      ["wall [s]", "CPU [s]", "CPU / base", "status"]) + " |")
        out.append("|" + "---|" * (len(QUANTITIES) + 5))
        for v, r in zip(values, rows):
            errs = [("ref" if r is ref else pct(rel_error(r[q], ref[q])) if r["ok"] and ref
                     else "-") for q, _ in QUANTITIES]
            rel = "-" if not base_cpu else f"{r['cpu_s'] / base_cpu:.2f}"
            out.append("| " + " | ".join([v] + errs + [fmt_t(r["wall_s"]), fmt_t(r["cpu_s"]),
                                                      rel, "ok" if r["ok"] else
                                                      f"failed (rc {r['rc']})"]) + " |")
        if label == "N" and len(rows) >= 3 and all(r["ok"] for r in rows[-3:]):
            notes = []
            for q, _ in QUANTITIES:
                p, lim = richardson([r[q] for r in rows[-3:]])
                if p is not None:
                    notes.append(f"{q}: order {p:.2f}, reference error "
                                 f"{pct(rel_error(ref[q], lim))} %")
                elif ref[q] is not None:
                    notes.append(f"{q}: not monotone (no Richardson estimate)")
            out.append("\nRichardson from the three finest grids (ratio 2): " +
                       "; ".join(notes) + ".\n")
    return out


def chosen_nodes(case):
    """The node count a run printed (`grid N nodes (...)`, or a cycle's `grid N nodes`), or
    None."""
    try:
        with open(case[:-5] + ".log") as f:
            m = re.search(r"grid (\d+) nodes", f.read())
    except OSError:
        return None
    return int(m.group(1)) if m else None


def extra_lines(case_name, rows_by_series):
    """The runs beside the series (EXTRA), each against the reference of the grid series."""
    out = []
    ref = reference(rows_by_series.get("N", []))
    for name, label, key, v in EXTRA:
        if name != case_name or label not in rows_by_series:
            continue
        r = rows_by_series[label][0]
        n = chosen_nodes(r["case"])
        base_cpu = next((x["cpu_s"] for x in rows_by_series["N"] if x["is_base"]), None)
        errs = ", ".join(f"{q} {pct(rel_error(r[q], ref[q]))} %" for q, _ in QUANTITIES
                         if r["ok"] and ref and ref[q] is not None)
        out.append(f"\n**{case_name}, {label}** (`{key} = {v}`): "
                   f"{'chose ' + str(n) + ' nodes' if n else 'node count not in its log'}; " +
                   (f"errors against the reference: {errs}; " if errs else "did not converge; ") +
                   f"CPU {fmt_t(r['cpu_s'])} s" +
                   (f" ({r['cpu_s'] / base_cpu:.2f} of the base)" if base_cpu else "") + ".\n")
    return out


def cheapest(case_name, rows_by_series, q, target):
    """The cheapest combination of one setting per series whose estimated error in q is within
    target. Model (one setting varied at a time): the error of a combination is the sum of the
    errors of its settings, each against the reference of its series, and its CPU time is the
    base CPU time times the product of the settings' CPU / base. Only converged runs count."""
    options = []
    for label, _, values, *_ in SERIES[case_name]:
        rows = rows_by_series[label]
        ref = reference(rows)
        base = next((r for r in rows if r["is_base"]), None)
        if ref is None or base is None or not base["ok"]:
            return None
        opts = []
        for v, r in zip(values, rows):
            e = 0.0 if r is ref else rel_error(r[q], ref[q])
            if r["ok"] and e is not None:
                opts.append((label, v, e, r["cpu_s"] / base["cpu_s"]))
        options.append(opts)
    base_cpu = next(r for r in rows_by_series[SERIES[case_name][0][0]] if r["is_base"])["cpu_s"]
    best = None
    for combo in itertools.product(*options):
        err = sum(o[2] for o in combo)
        cost = base_cpu * float(np.prod([o[3] for o in combo]))
        if err <= target and (best is None or cost < best[0]):
            best = (cost, err, combo)
    return best


def combinations(case_name, rows_by_series):
    """(estimated CPU time, estimated largest error over the quantities) of every combination
    of one setting per series, with the additive error model of cheapest()."""
    options = []
    for label, _, values, *_ in SERIES[case_name]:
        rows = rows_by_series[label]
        ref = reference(rows)
        base = next((r for r in rows if r["is_base"]), None)
        if ref is None or base is None or not base["ok"]:
            return []
        opts = []
        for r in rows:
            if not r["ok"]:
                continue
            errs = {q: (0.0 if r is ref else rel_error(r[q], ref[q])) for q, _ in QUANTITIES
                    if ref[q] is not None}
            # A quantity missing from a run (a result file of an earlier format) is left out.
            errs = {q: e for q, e in errs.items() if e is not None}
            opts.append((errs, r["cpu_s"] / base["cpu_s"]))
        options.append(opts)
    base_cpu = next(r for r in rows_by_series[SERIES[case_name][0][0]] if r["is_base"])["cpu_s"]
    out = []
    for combo in itertools.product(*options):
        qs = set.intersection(*(set(o[0]) for o in combo))
        if not qs:
            continue
        err = max(sum(o[0][q] for o in combo) for q in qs)
        out.append((base_cpu * float(np.prod([o[1] for o in combo])), err))
    return out


def pareto_plot(data, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    markers = {"N": "o", "Nz": "s", "steps": "^", "tol": "D", "inlet": "v", "time_tol": "P"}
    for ax, case_name in zip(axes, ["cycle", "disc"]):
        combos = sorted(combinations(case_name, data[case_name]))
        if combos:
            ax.plot([c[0] for c in combos], [100 * max(c[1], 1e-7) for c in combos], ".",
                    color="0.75", ms=3, label="combinations (estimated)")
            front, best = [], np.inf
            for x, y in combos:
                if y < best:
                    front.append((x, 100 * max(y, 1e-7)))
                    best = y
            ax.step([p[0] for p in front], [p[1] for p in front], "k-", lw=1.0, where="post",
                    label="Pareto front of the combinations")
        for label, _, values, *_ in SERIES[case_name]:
            rows = data[case_name][label]
            ref = reference(rows)
            xs, ys = [], []
            for v, r in zip(values, rows):
                if ref is None or r is ref or not r["ok"]:
                    continue
                errs = [rel_error(r[q], ref[q]) for q, _ in QUANTITIES]
                errs = [e for e in errs if e is not None]
                if not errs:
                    continue
                e = max(max(errs), 1e-7)
                xs.append(r["cpu_s"])
                ys.append(100 * e)
                ax.annotate(v, (r["cpu_s"], 100 * e), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
            ax.plot(xs, ys, markers[label], label=f"{label} varied, others at base (measured)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time of the run [s]")
        ax.set_ylabel("largest relative error [%]")
        ax.set_title({"cycle": "seed 004 mesh cycle, thermal Ree-Eyring",
                      "disc": "steady thermal Ree-Eyring disc, SRR 0.4"}[case_name] +
                     "\nerror: max over h_min, h_c, p_max, T_max, mu", fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tehl", default=os.path.join(ROOT, "build", "tehl"))
    ap.add_argument("--scratch", default=os.path.join(ROOT, "results", "accuracy"))
    ap.add_argument("--docs", default=os.path.join(ROOT, "docs"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--reuse", action="store_true")
    a = ap.parse_args()
    tehl = os.path.abspath(a.tehl)
    if not os.access(tehl, os.X_OK):
        fail(f"{tehl}: not an executable (build tehl first, or pass --tehl)")
    scratch = os.path.abspath(a.scratch)
    os.makedirs(scratch, exist_ok=True)
    started = time.monotonic()
    load_before = os.getloadavg()

    # Expand every scene first (so that input problems show before anything runs).
    plan = []  # (case name, series label, value, is_base, scene file)
    for case_name, base_case, base in CASES:
        scenes, meta = [], []
        for label, key, values, *extra in SERIES[case_name]:
            for v in values:
                more = extra[0].get(v, {}) if extra else {}
                scenes.append(dict(base, **{key: v}, **more))
                meta.append((case_name, label, v, v == base[key] and not more))
        for name, label, key, v in EXTRA:
            if name == case_name:
                scenes.append(dict(base, **{key: v}))
                meta.append((case_name, label, v, False))
        files = expand(tehl, f"{case_name}_settings", os.path.join(ROOT, base_case), scenes,
                       scratch)
        plan += [m + (f,) for m, f in zip(meta, files)]
    effect_scenes = []
    keys = sorted({k for _, d in EFFECTS for k in d} | set(EFFECT_BASE))
    for _, d in EFFECTS:
        s = dict(EFFECT_BASE, **d)
        defaults = {"effects.thermal": "true", "effects.elastic": "true",
                    "effects.transient": "true", "effects.roughness": "false",
                    "effects.non_newtonian": "false", "numerics.steps": "80",
                    "surfaces.surface1.roughness": '"smooth"',
                    "surfaces.surface1.amplitude_m": "0.0",
                    "surfaces.surface1.wavelength_m": "5e-5",
                    "surfaces.surface2.roughness": '"smooth"',
                    "surfaces.surface2.amplitude_m": "0.0",
                    "surfaces.surface2.wavelength_m": "5e-5"}
        effect_scenes.append({k: s.get(k, defaults.get(k)) for k in keys})
    effect_files = expand(tehl, "effects", os.path.join(ROOT, "cases/seed004_sae40.toml"),
                          effect_scenes, scratch)

    # Identical settings (the base of each series) are run once.
    def settings(f):
        return "".join(x for x in open(f) if "scene_" not in x)

    first_of = {}
    for p in plan:
        first_of.setdefault((p[0], settings(p[4])), p[4])
    to_run = list(dict.fromkeys(first_of.values())) + effect_files
    print(f"accuracy_report.py: {len(to_run)} runs, {a.jobs} at a time", file=sys.stderr)
    results = {r["case"]: r for r in run_all(tehl, to_run, a.jobs, a.reuse)}

    data = {name: {} for name, _, _ in CASES}
    for case_name, label, v, is_base, f in plan:
        r = dict(results[first_of[(case_name, settings(f))]], is_base=is_base, value=v)
        data[case_name].setdefault(label, []).append(r)
    effects = [results[f] for f in effect_files]
    elapsed = time.monotonic() - started
    load_after = os.getloadavg()
    meta = os.path.join(scratch, "meta.json")
    if a.reuse and os.path.isfile(meta):  # the figures of the run that computed the results
        with open(meta) as f:
            elapsed, load_before, load_after = json.load(f)
    else:
        with open(meta, "w") as f:
            json.dump([elapsed, load_before, load_after], f)

    pareto_plot(data, os.path.join(a.docs, "accuracy_pareto.png"))
    write_markdown(a, data, effects, elapsed, load_before, load_after)


def write_markdown(a, data, effects, elapsed, load_before, load_after):
    md = []
    md.append("# Accuracy against run time\n")
    md.append("Generated by `scripts/accuracy_report.sh` (runs `scripts/accuracy_report.py`; "
              "scratch results in `results/accuracy/`). Do not edit the tables by hand: "
              "rerun the script.\n")
    md.append(f"This run: {elapsed / 60:.1f} min in all, {a.jobs} runs at a time; load "
              f"average {load_before[0]:.1f} at the start, {load_after[0]:.1f} at the end on "
              f"a 2-core machine shared with other work. **Wall times are noisy** (a run got "
              f"a fraction of a core); the CPU time of each run's process (user + system, "
              f"from wait4) is the stable measure, and the relative costs (CPU / base) are "
              f"the numbers to carry to another machine.\n")
    md.append("## What was run\n")
    md.append("- **cycle**: `cases/seed004_sae40.toml` (seed 004 SAE 40, 10 kW, 1000 rpm) "
              "with `thermal = true` and the Ree-Eyring film (`non_newtonian = true`, "
              "tau0 = 5 MPa), the film model of the shipped studies; base 257 nodes, "
              "`film_nodes` 11, 80 steps, `newton_tolerance` 1e-8, `time_tolerance` 0 (no "
              "substeps for the time error; the series **time_tol** sets it: docs/case_format.md). "
              "Quantities: min over the "
              "cycle of h_min, h_c at the pitch point, max of p_max, max of T_max, mean of mu.")
    md.append("- **disc**: `cases/disc_steady.toml` (steel discs, R = 10 mm, SAE 40, "
              "100 kN/m, p_H = 0.60 GPa) with sliding (u1 = 1.2, u2 = 0.8 m/s, SRR 0.4), "
              "thermal and Ree-Eyring, steady; base 257 nodes, 11 film nodes, tolerance 1e-8. "
              "Quantities from the [contact] result (`_steps.csv`): h_min, h_c and p_max of "
              "the (single) steady step, max of `t_max_k`, mean of `mu`; the wall time is the "
              "sum of its `wall_time_s` column (the solve only).")
    md.append("- One setting varied at a time, the others at the base. The error is relative "
              "to the finest converged run of the same series (the reference, 'ref'); a run "
              "that did not converge, or had a time step replaced by the steady film "
              "(`[numerics] failed_step`), has no error ('-'). For the grid the Richardson "
              "estimate below each table says how far that reference itself is from the grid "
              "limit. The thermal coupling tolerance (0.01 K) has no case key and is not "
              "varied.")
    md.append("- **inlet**: `numerics.x_start_b` from -3 to -16 (Hertz half-widths b of the "
              "largest contact; the default is -4.5) with `grid_points` raised with the "
              "domain (193, 257, 321, 419, 577 and 771 nodes), so that the node spacing stays "
              "that of the base and the error is that of the truncated inlet alone. In a "
              "recommendation below, 'inlet = -8' with 'N = 513' means `x_start_b = -8` and "
              "`grid_points` about 513 (1.5 + 8) / 6, the spacing of 513 nodes on the default "
              "domain.")
    md.append("- Why the Ree-Eyring film: it is the film model of the shipped studies, and "
              "the Newtonian thermal film does not converge on the sliding disc (SRR >= 0.2; "
              "docs/thermal.md, 'Open points'), so the disc series could not use it. The "
              "Newtonian seed 004 cycle itself converges at 513 and 1025 nodes and with 21 "
              "film nodes (docs/thermal.md, 'The seed 004 cycle at full resolution').")
    md.append("- **heavy**: the disc of **disc** at 1 MN/m (p_H = 1.9 GPa) and 0.12 / 0.08 m/s "
              "(SRR 0.4), thermal and Ree-Eyring, steady; only the grid is varied, from 257 to "
              "8193 nodes (base 513). Its Hertzian edge is narrow (docs/results.md, 'The edge "
              "note'): about 3.6 cells on 513 nodes. Beside the series, the automatic grid "
              "(`grid_points = 0`, the default: docs/case_format.md), with the node count it "
              "chose.\n")
    md.append("## Settings\n")
    for case_name, _, _ in CASES:
        md += series_tables(case_name, data[case_name])
        md += extra_lines(case_name, data[case_name])
    md.append("\n![largest error against CPU time](accuracy_pareto.png)\n")
    md.append("The figure's error is the largest of the five quantities; on the cycle it is "
              "that of max p_max, the pressure spike near the outlet, which converges slowly "
              "with the grid (see its Richardson order) and depends on where the steps fall "
              "in the single-tooth zone B-D. Grey: every combination of one setting per "
              "series, its error estimated as the sum of the settings' errors and its time "
              "as the product of their relative costs (the model of the recommendations "
              "below); markers: measured runs.\n")
    md.append("## Recommended settings\n")
    md.append("The cheapest combination of one setting per series whose estimated error is "
              "within the target; the error of a combination is estimated as the sum of its "
              "settings' errors (each measured with the others at the base) and its CPU time "
              "as the base time times the product of the settings' CPU / base. The errors are "
              "against the finest runs, not the exact solution (see the Richardson line of "
              "the grid).\n")
    for case_name, _, _ in CASES:
        for q in ["h_min", "h_c", "p_max", "T_max", "mu"]:
            grid = data[case_name]["N"]
            ref = reference(grid)
            if ref is None or ref[q] is None:
                continue
            lim = None
            if grid[-1] is ref and all(r["ok"] for r in grid[-3:]):
                lim = richardson([r[q] for r in grid[-3:]])[1]
            for target in [0.01, 0.001]:
                ref_err = rel_error(ref[q], lim) if lim is not None else None
                if ref_err is not None and ref_err > target:
                    md.append(f"- {case_name}: {100 * target:g} % on {q} is not reached by "
                              f"these runs: the finest grid is itself {pct(ref_err)} % from "
                              f"the Richardson limit.")
                    continue
                b = cheapest(case_name, data[case_name], q, target)
                if b:
                    cost, err, combo = b
                    md.append(f"- {case_name}: {100 * target:g} % on {q} costs about "
                              f"{cost:.1f} s CPU: " + ", ".join(f"{o[0]} = {o[1]}"
                                                                 for o in combo) +
                              f" (estimated error {pct(err)} %).")
    md.append("")
    md.append("## Cost of each effect\n")
    md.append("The seed 004 cycle at 129 nodes and 80 steps (the rough run: the steps raised "
              "so that the roughness moves at most one node per step), each effect switched "
              "against the thermal, elastic, transient, smooth, Newtonian base. Differences "
              "are relative to the base run.\n")
    md.append("| run | steps | h_min [um] | h_c [um] | p_max [GPa] | T_max [K] | mu | "
              "wall [s] | CPU [s] | CPU / base | status |")
    md.append("|" + "---|" * 11)
    base = effects[0]
    for (name, _), r in zip(EFFECTS, effects):
        def cell(q, scale, digits):
            if r.get(q) is None or not r["ok"]:
                return "-"
            d = rel_error(r[q], base[q]) if r is not base and base.get(q) else None
            return f"{r[q] * scale:.{digits}f}" + (f" ({100 * (r[q] / base[q] - 1):+.0f} %)"
                                                   if d is not None else "")
        status = "ok" if r["ok"] else f"failed at step {r['steps_run']} (rc {r['rc']})"
        md.append(f"| {name} | {r['steps_run']} | {cell('h_min', 1e6, 3)} | "
                  f"{cell('h_c', 1e6, 3)} | {cell('p_max', 1e-9, 3)} | {cell('T_max', 1, 1)} |"
                  f" {cell('mu', 1, 4)} | {fmt_t(r['wall_s'])} | {fmt_t(r['cpu_s'])} | "
                  f"{r['cpu_s'] / base['cpu_s']:.2f} | {status} |")
    md.append("")
    with open(os.path.join(a.docs, "accuracy.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    with open(os.path.join(a.scratch, "data.json"), "w") as f:
        json.dump({"data": data, "effects": effects}, f, indent=1, default=str)
    print(os.path.join(a.docs, "accuracy.md"))


if __name__ == "__main__":
    main()
