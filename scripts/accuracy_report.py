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
reference); for the grid series the observed order and a Richardson estimate of the
reference's own error are given from the three finest grids. The steps series is instead
compared with the controlled-step film (the time_tolerance of the time_tol series' finest
run) at the same step count (CONTROLLED_REFERENCE), so that both sample the cycle at the same
step ends. h_c is the central film interpolated linearly to the pitch point C between the two
steps around it.
Times: every run reads its FFTW plans from a wisdom file (TEHL_FFTW_WISDOM) warmed before the
measured runs, one grid size at a time, so that no run counts the one-off FFTW planning of its
grid size (reported separately); the CPU time (user + system) of each process from wait4, less
the start-up of the binary (the least CPU time of `tehl --version`), is
the time of the table and of the relative costs. The result file's wall time is shown beside
it (the HDF5 wall_time of a mesh cycle: the whole run; the sum of the wall_time_s column of a
disc's _steps.csv: the solve).
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
              "effects.transient": "true",
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
              ("steps", "numerics.steps", ["40", "80", "150", "300", "640"]),
              ("tol", "numerics.newton_tolerance", ["1e-4", "1e-6", "1e-8", "1e-10"]),
              ("time_tol", "numerics.time_tolerance", ["0", "1e-2", "1e-3", "1e-4"]),
              INLET],
    "disc": [("N", "numerics.grid_points", ["129", "257", "513", "1025"]),
             ("Nz", "numerics.film_nodes", ["5", "7", "11", "21"]),
             ("tol", "numerics.newton_tolerance", ["1e-4", "1e-6", "1e-8", "1e-10"]),
             INLET],
    "heavy": [("N", "numerics.grid_points", ["257", "513", "1025", "2049", "4097", "8193"])],
}
# The series whose own finest run is not its reference: (case, series) -> the series whose
# reference setting gives the reference. Each run of the steps series (time_tolerance 0) is
# compared with the run at the same step count under the time_tolerance of that series'
# finest value (the controlled film: substeps sized by the local time-error estimate,
# restarting at the load jumps of B and D), run beside it as the series "<label> reference".
# The same step count keeps both at the same step ends: max p_max over the step ends depends
# on how densely they sample the pressure peak after B.
CONTROLLED_REFERENCE = {("cycle", "steps"): "time_tol"}
# Series that vary the same thing (the time discretization) and share their references: in
# the combinations of the recommendations one run of the group is taken, not one of each.
GROUPS = {"cycle": [("steps", "time_tol")]}
# Runs beside the series (case, label, key, value, series): compared with the reference of
# that series (none: run for the text only).
EXTRA = [("heavy", "automatic grid", "numerics.grid_points", "0", "N"),
         ("cycle", "time_tol check", "numerics.time_tolerance", "1e-5", "time_tol"),
         ("cycle", "quasi-steady film", "effects.transient", "false", None)]
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


def timed(args, env, log):
    """Runs args in its own process (output to log); returns exit code, wall and CPU time (user
    + system, from wait4) of the process."""
    t0 = time.monotonic()
    with open(log, "w") as out:
        p = subprocess.Popen(args, stdout=out, stderr=subprocess.STDOUT, env=env)
        _, status, usage = os.wait4(p.pid, 0)
    return (os.waitstatus_to_exitcode(status), time.monotonic() - t0,
            usage.ru_utime + usage.ru_stime)


def run_one(tehl, case, env=None):
    """Runs one case in its own process; returns wall and CPU time of the process."""
    rc, wall, cpu = timed([tehl, "run", case], env, case[:-5] + ".log")
    info = {"case": case, "rc": rc, "process_wall_s": wall, "cpu_s": cpu}
    with open(case[:-5] + ".json", "w") as f:
        json.dump(info, f)
    return info


def grid_sizes(files):
    """The node counts (grid_points > 0) of scene files; the automatic grid (0) is left out."""
    sizes = set()
    for name in files:
        with open(name) as f:
            for line in f:
                m = re.match(r"grid_points\s*=\s*(\d+)", line)
                if m and int(m.group(1)) > 0:
                    sizes.add(int(m.group(1)))
    return sorted(sizes)


def warm_plans(tehl, sizes, scratch, env):
    """Plans the FFTs of every grid size into the wisdom file of env, one size at a time (so
    that no concurrent process overwrites a size's plans): the steady isothermal disc of
    cases/disc_steady.toml at each node count, run twice. The first run measures the plans
    and writes them back, the second reads them; the difference of their CPU times is the
    one-off planning a fresh process pays for that size. Returns {size: (cold CPU, warm CPU)}."""
    files = expand(tehl, "fftw_plans", os.path.join(ROOT, "cases/disc_steady.toml"),
                   [{"numerics.grid_points": str(n)} for n in sizes], scratch)
    out = {}
    for n, case in zip(sizes, files):
        cpu = []
        for _ in range(2):
            rc, _, c = timed([tehl, "run", case], env, case[:-5] + ".log")
            if rc != 0:
                fail(f"{case}: the planning run failed (rc {rc}): see {case[:-5]}.log")
            cpu.append(c)
        out[n] = tuple(cpu)
    return out


def startup_cpu(tehl, scratch, env, repeats=5):
    """The start-up of the binary: the least CPU time of `tehl --version` (loading the program
    and its shared libraries) over `repeats` processes."""
    log = os.path.join(scratch, "startup.log")
    return min(timed([tehl, "--version"], env, log)[2] for _ in range(repeats))


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


def at_s(s, v, s0):
    """v at s0, linear between the two steps around it (s increasing along the path; the end
    value outside it). The pitch point C is in general no step end: the nearest step can lie
    a large part of a step away (118 um at 40 steps of the seed 004 cycle)."""
    return float(np.interp(s0, s, v))


def read_result(info):
    """Summaries of one run: the seed's quantities and the times."""
    stem = info["case"][:-5]
    row = dict(info)
    h5 = stem + ".h5"
    if os.path.isfile(h5):
        with h5py.File(h5, "r") as f:
            c = f["cycle"]
            s = c["s"][:]
            row["h_min"] = float(np.min(c["h_min"][:]))
            row["h_c"] = at_s(s, c["h_c"][:], float(c.attrs["s_C"]))
            row["p_max"] = float(np.max(c["p_max"][:]))
            row["T_max"] = float(np.max(c["T_max"][:])) if "T_max" in c else None
            row["mu"] = float(np.mean(c["mu"][:])) if "mu" in c else None
            row["wall_s"] = float(f.attrs["wall_time"])
            row["steps_run"] = len(s) - 1
            # For the text on the time step: where max p_max lies (from B), the largest
            # per-step time-error estimate and where (from D), the loads around B.
            s_b, s_d = float(c.attrs["s_B"]), float(c.attrs["s_D"])
            row["p_max_after_B"] = float(s[int(np.argmax(c["p_max"][:]))] - s_b)
            if "solver/time_error" in f:
                te = f["solver/time_error"][:]
                row["time_error_max"] = float(np.max(te))
                row["time_error_after_D"] = float(s[int(np.argmax(te))] - s_d)
            w = c["w"][:]
            i_b = int(np.argmin(np.abs(s - s_b)))
            if i_b + 1 < len(s):
                row["w_at_B"] = [float(w[i_b]), float(w[i_b + 1])]
            row["C_after_B"] = float(c.attrs["s_C"]) - s_b
            row["C_offset"] = float(np.min(np.abs(s - float(c.attrs["s_C"]))))
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


def run_all(tehl, cases, jobs, reuse, env=None):
    def one(case):
        cached = case[:-5] + ".json"
        if reuse and os.path.isfile(cached):
            with open(cached) as f:
                return json.load(f)
        return run_one(tehl, case, env)

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
    if t is None:
        return "-"
    return f"{t:.3f}" if t < 1 else f"{t:.2f}" if t < 10 else f"{t:.1f}"


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


def references(case_name, label, rows_by_series):
    """The reference of each run of a series (None where there is none): the finest converged
    run of the series, or for a series of CONTROLLED_REFERENCE its controlled run at the same
    setting (the series "<label> reference")."""
    rows = rows_by_series[label]
    if (case_name, label) in CONTROLLED_REFERENCE:
        return [r if r["ok"] else None for r in rows_by_series[label + " reference"]]
    return [reference(rows)] * len(rows)


def base_row(rows):
    return next((r for r in rows if r["is_base"]), None)


def base_cpu_of(case_name, rows_by_series):
    """The CPU time of the base run of a case (the base of its first series)."""
    b = base_row(rows_by_series[SERIES[case_name][0][0]])
    return b["cpu_s"] if b else None


def series_tables(case_name, rows_by_series):
    out = []
    for label, key, values, *_ in SERIES[case_name]:
        rows = rows_by_series[label]
        refs = references(case_name, label, rows_by_series)
        base_cpu = next((r["cpu_s"] for r in rows if r["is_base"]), None)
        if (case_name, label) in CONTROLLED_REFERENCE:
            other = CONTROLLED_REFERENCE[(case_name, label)]
            o_key, o_values = next((k, v) for lb, k, v, *_ in SERIES[case_name] if lb == other)
            head = (f"reference: each run against the controlled-step film at the same {label} "
                    f"(`{o_key}` = {o_values[-1]}, the reference of the series {other}), not "
                    f"against the finest run of the series")
        else:
            ref = refs[0]
            head = "reference: " + (f"{label} = {values[rows.index(ref)]}" if ref
                                    else "none (no run converged)")
        out.append(f"\n**{case_name}, {label}** (`{key}`; {head})\n")
        out.append("| " + " | ".join([label] + [f"err {q} [%]" for q, _ in QUANTITIES] +
                                      ["wall [s]", "CPU [s]", "CPU / base", "status"]) + " |")
        out.append("|" + "---|" * (len(QUANTITIES) + 5))
        for v, r, ref in zip(values, rows, refs):
            errs = [("ref" if r is ref else pct(rel_error(r[q], ref[q])) if r["ok"] and ref
                     else "-") for q, _ in QUANTITIES]
            rel = "-" if not base_cpu else f"{r['cpu_s'] / base_cpu:.2f}"
            out.append("| " + " | ".join([v] + errs + [fmt_t(r["wall_s"]), fmt_t(r["cpu_s"]),
                                                      rel, "ok" if r["ok"] else
                                                      f"failed (rc {r['rc']})"]) + " |")
        if (case_name, label) in CONTROLLED_REFERENCE:
            crows = rows_by_series[label + " reference"]
            out.append("\nThe controlled runs (the references): max p_max " +
                       ", ".join(f"{r['p_max'] / 1e9:.3f}" if r["ok"] else "-" for r in crows) +
                       f" GPa at {', '.join(values)} {label}; CPU " +
                       ", ".join(fmt_t(r["cpu_s"]) for r in crows) + " s.\n")
        if label == "N" and len(rows) >= 3 and all(r["ok"] for r in rows[-3:]):
            ref = refs[-1]
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
    """The runs beside the series (EXTRA), each against the reference of its series."""
    out = []
    base_cpu = base_cpu_of(case_name, rows_by_series)
    for name, label, key, v, series in EXTRA:
        if name != case_name or label not in rows_by_series or series is None:
            continue
        ref = reference(rows_by_series.get(series, []))
        ref_v = next((x["value"] for x in rows_by_series[series] if x is ref), None)
        r = rows_by_series[label][0]
        n = chosen_nodes(r["case"]) if key == "numerics.grid_points" else None
        errs = ", ".join(f"{q} {pct(rel_error(r[q], ref[q]))} %" for q, _ in QUANTITIES
                         if r["ok"] and ref and ref[q] is not None)
        out.append(f"\n**{case_name}, {label}** (`{key} = {v}`): " +
                   (f"chose {n} nodes; " if n else
                    "node count not in its log; " if key == "numerics.grid_points" else "") +
                   (f"differences from the reference of the series {series} ({series} = "
                    f"{ref_v}): {errs}; " if errs else "did not converge; ") +
                   f"CPU {fmt_t(r['cpu_s'])} s" +
                   (f" ({r['cpu_s'] / base_cpu:.2f} of the base)" if base_cpu else "") + ".\n")
    return out


def option_groups(case_name, rows_by_series):
    """The settings a combination chooses from: one group per series, or one per group of
    GROUPS (series that vary the same thing; a run of one of them keeps the others at the
    base). Each option: (text, {quantity: error against its reference}, CPU / base). Only
    converged runs with a reference count; None when a series has no converged base."""
    groups = []
    grouped = {}
    for g in GROUPS.get(case_name, []):
        for label in g:
            grouped[label] = g
    done = set()
    for label, _, _, *_ in SERIES[case_name]:
        g = grouped.get(label, (label,))
        if g in done:
            continue
        done.add(g)
        opts = []
        for lb in g:
            rows = rows_by_series[lb]
            base = base_row(rows)
            if base is None or not base["ok"]:
                return None
            for r, ref in zip(rows, references(case_name, lb, rows_by_series)):
                if not r["ok"] or ref is None:
                    continue
                errs = {q: (0.0 if r is ref else rel_error(r[q], ref[q])) for q, _ in QUANTITIES
                        if ref[q] is not None}
                # A quantity missing from a run (a result file of an earlier format) is left out.
                errs = {q: e for q, e in errs.items() if e is not None}
                text = ", ".join(f"{x} = " + (r["value"] if x == lb else
                                              base_row(rows_by_series[x])["value"]) for x in g)
                opts.append((text, errs, r["cpu_s"] / base["cpu_s"]))
        groups.append(opts)
    return groups


def cheapest(case_name, rows_by_series, q, target):
    """The cheapest combination of one setting per series (per group of GROUPS) whose
    estimated error in q is within target. Model (one setting varied at a time): the error of
    a combination is the sum of the errors of its settings, each against the reference of its
    run, and its CPU time is the base CPU time times the product of the settings' CPU / base.
    Only converged runs count."""
    groups = option_groups(case_name, rows_by_series)
    if not groups:
        return None
    options = [[o for o in g if q in o[1]] for g in groups]
    base_cpu = base_cpu_of(case_name, rows_by_series)
    best = None
    for combo in itertools.product(*options):
        err = sum(o[1][q] for o in combo)
        cost = base_cpu * float(np.prod([o[2] for o in combo]))
        if err <= target and (best is None or cost < best[0]):
            best = (cost, err, combo)
    return best


def combinations(case_name, rows_by_series):
    """(estimated CPU time, estimated largest error over the quantities) of every combination
    of one setting per series (per group), with the additive error model of cheapest()."""
    groups = option_groups(case_name, rows_by_series)
    if not groups:
        return []
    base_cpu = base_cpu_of(case_name, rows_by_series)
    out = []
    for combo in itertools.product(*groups):
        qs = set.intersection(*(set(o[1]) for o in combo))
        if not qs:
            continue
        err = max(sum(o[1][q] for o in combo) for q in qs)
        out.append((base_cpu * float(np.prod([o[2] for o in combo])), err))
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
            xs, ys = [], []
            for v, r, ref in zip(values, rows, references(case_name, label, data[case_name])):
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
        ax.set_xlabel("CPU time of the run (less the start-up; no FFTW planning) [s]")
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
    # Every run reads the FFTW plans of its grid size from this file (warmed below), so that
    # no run's time counts the one-off planning (docs/performance.md, "One-off cost").
    wisdom = os.path.join(scratch, "fftw.wisdom")
    env = dict(os.environ, TEHL_FFTW_WISDOM=wisdom)

    # Expand every scene first (so that input problems show before anything runs).
    plan = []  # (case name, series label, value, is_base, scene file)
    for case_name, base_case, base in CASES:
        scenes, meta = [], []
        for label, key, values, *extra in SERIES[case_name]:
            for v in values:
                more = extra[0].get(v, {}) if extra else {}
                scenes.append(dict(base, **{key: v}, **more))
                meta.append((case_name, label, v, v == base[key] and not more))
            if (case_name, label) in CONTROLLED_REFERENCE:
                other = CONTROLLED_REFERENCE[(case_name, label)]
                o_key, o_values = next((k, vs) for lb, k, vs, *_ in SERIES[case_name]
                                       if lb == other)
                for v in values:
                    scenes.append(dict(base, **{key: v, o_key: o_values[-1]}))
                    meta.append((case_name, label + " reference", v, False))
        for name, label, key, v, _ in EXTRA:
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
    meta = os.path.join(scratch, "meta.json")
    if a.reuse and os.path.isfile(meta):  # the figures of the run that computed the results
        with open(meta) as f:
            m = json.load(f)
        if not isinstance(m, dict) or "startup" not in m:
            fail(f"{meta}: written by an earlier version of this script: run without --reuse")
    else:
        m = {}
        if os.path.exists(wisdom):
            os.remove(wisdom)
        sizes = grid_sizes(to_run)
        print(f"accuracy_report.py: planning the FFTs of {len(sizes)} grid sizes",
              file=sys.stderr)
        m["planning"] = {str(n): c for n, c in warm_plans(tehl, sizes, scratch, env).items()}
        m["startup"] = startup_cpu(tehl, scratch, env)
    print(f"accuracy_report.py: {len(to_run)} runs, {a.jobs} at a time", file=sys.stderr)
    results = {r["case"]: r for r in run_all(tehl, to_run, a.jobs, a.reuse, env)}
    # CPU time of the run: the process's, less the start-up of the binary.
    for r in results.values():
        r["process_cpu_s"] = r["cpu_s"]
        r["cpu_s"] = max(r["cpu_s"] - m["startup"], 0.0)

    data = {name: {} for name, _, _ in CASES}
    for case_name, label, v, is_base, f in plan:
        r = dict(results[first_of[(case_name, settings(f))]], is_base=is_base, value=v)
        data[case_name].setdefault(label, []).append(r)
    effects = [results[f] for f in effect_files]
    if "elapsed" not in m:
        m.update(elapsed=time.monotonic() - started, load_before=load_before,
                 load_after=os.getloadavg())
        with open(meta, "w") as f:
            json.dump(m, f)

    pareto_plot(data, os.path.join(a.docs, "accuracy_pareto.png"))
    write_markdown(a, data, effects, m)


def listed(rows, fmt):
    """fmt(row) of each converged row, '-' for the others, joined by commas."""
    return ", ".join(fmt(r) if r["ok"] else "-" for r in rows)


def time_step_lines(cyc):
    """Why max p_max of the cycle converges slowly with equal steps, in the measured numbers
    of the steps series, its controlled references, the time_tol series and the quasi-steady
    film."""
    steps, crefs = cyc["steps"], cyc["steps reference"]
    tt = cyc["time_tol"]
    tt_ref = reference(tt)
    values = [r["value"] for r in steps]
    controlled = next((r for r in crefs if r["ok"]), None)
    if controlled is None or tt_ref is None or "w_at_B" not in controlled:
        return ["The controlled runs did not converge: no account of the time step.\n"]
    w0, w1 = controlled["w_at_B"]
    qs = cyc.get("quasi-steady film", [None])[0]
    ok_c = [r for r in crefs if r["ok"]]

    def spread(q):
        v = [r[q] for r in ok_c]
        return (max(v) - min(v)) / min(v)

    gpa = (lambda r: f"{r['p_max'] / 1e9:.3f}")
    t1 = next((r for r in tt if r["value"] == "1e-3"), None)
    t0 = next((r for r in tt if r["is_base"]), None)
    out = [
        f"The static load sharing makes the tooth load jump at B (from {w0 / 1e3:.1f} to "
        f"{w1 / 1e3:.1f} kN/m, the single pair taking the whole load) and back at D. The jump "
        f"at B starts a squeeze transient of the film through the single-tooth zone B-D, and "
        f"max p_max of the cycle is a peak of it: {1e3 * tt_ref['p_max_after_B']:.2f} mm "
        f"after B in the controlled film at {tt_ref['value']} (C lies "
        f"{1e3 * tt_ref['C_after_B']:.2f} mm after B)" +
        (f"; without the squeeze term (`[effects] transient = false`, 80 steps) max p_max is "
         f"{gpa(qs)} GPa" if qs is not None and qs["ok"] else "") + ".",
        "",
        f"- Equal steps (`time_tolerance` 0) resolve that transient the better the shorter "
        f"they are, and max p_max keeps rising with the step count: {listed(steps, gpa)} GPa "
        f"at {', '.join(values)} steps.",
        f"- The controlled film (`time_tolerance` = {tt_ref['value']}) at the same step counts: "
        f"{listed(crefs, gpa)} GPa. Its film hardly depends on the step count (h_min within "
        f"{pct(spread('h_min'))} %, h_c at C within {pct(spread('h_c'))} % with the "
        f"interpolation between step ends), but its peak is "
        f"sampled only at the step ends, so the maximum over them still depends on how close a "
        f"step end falls to the peak. That is why each equal-step run is compared with the "
        f"controlled run of its own step count.",
        f"- Against the single controlled run at {tt_ref['steps_run']} steps (the reference "
        f"of the series time_tol) the equal-step runs' max p_max would be " +
        listed(steps, lambda r: f"{100 * (r['p_max'] / tt_ref['p_max'] - 1):+.1f}") + " % off" +
        (f": the {values[-1]}-step run lies above it because its denser step ends come closer "
         f"to the peak, not because it is more accurate than that run (it is "
         f"{pct(rel_error(steps[-1]['p_max'], crefs[-1]['p_max']))} % below the controlled "
         f"film at its own step count)." if steps[-1]["ok"] and crefs[-1]["ok"] and
         steps[-1]["p_max"] > tt_ref["p_max"] else "."),
        "- The largest per-step time-error estimate (`/solver/time_error`) of the equal-step "
        "runs grows with the step count: " +
        listed(steps, lambda r: f"{r['time_error_max']:.2f}") + ", each " +
        listed(steps, lambda r: f"{1e3 * r['time_error_after_D']:.2f}") +
        " mm after D, where the load drops; after a load drop equal steps do not converge "
        "(docs/case_format.md, `time_tolerance`).",
        f"- `time_tolerance` is the way to control it: each step is split into substeps until "
        f"every local estimate is below the tolerance, and the integration restarts at the "
        f"jumps. At {tt_ref['value']} the largest estimate is {tt_ref['time_error_max']:.3g}" +
        (f"; {t1['value']} brings max p_max within {pct(rel_error(t1['p_max'], tt_ref['p_max']))}"
         f" % of {tt_ref['value']} at {t1['cpu_s'] / t0['cpu_s']:.1f} times the CPU time of no "
         f"control" if t1 and t0 and t1["ok"] and t0["ok"] else "") + ".",
        "- The jump is that of the stepped load sharing (`load_sharing = \"stiffness\"`, the "
        "default). With `load_sharing = \"loaded\"` (the pairs beyond A and E join by corner "
        "contact: docs/gear.md, \"Load and load sharing\") the load is continuous at B and D "
        "and equal steps converge: max p_max 0.5157, 0.5205, 0.5252, 0.5252 GPa at 40, 80, "
        "160, 320 steps on the isothermal cycle at 257 nodes (test "
        "`LoadedSharingCycle.LargestPressureConvergesInTheStepCount`; not a run of this "
        "report).\n",
    ]
    return out


def write_markdown(a, data, effects, m):
    elapsed, load_before, load_after = m["elapsed"], m["load_before"], m["load_after"]
    cyc = data["cycle"]
    far = max((r for r in cyc["steps"] if "C_offset" in r), key=lambda r: r["C_offset"])
    c_off = (far["value"], f"{1e6 * far['C_offset']:.0f}")
    tt_ref = reference(cyc["time_tol"])
    tt_ref_v = tt_ref["value"] if tt_ref else "-"
    base_c = references("cycle", "steps", cyc)[[r["value"] for r in cyc["steps"]].index(
        CYCLE_BASE["numerics.steps"])]
    base_time_err = pct(rel_error(base_row(cyc["steps"])["p_max"], base_c["p_max"])) \
        if base_c else "-"
    disc_base = base_row(data["disc"]["N"])
    c257 = m["planning"].get(DISC_BASE["numerics.grid_points"])
    plan_257 = fmt_t(c257[0] - c257[1]) if c257 else "-"
    md = []
    md.append("# Accuracy against run time\n")
    md.append("Generated by `scripts/accuracy_report.sh` (runs `scripts/accuracy_report.py`; "
              "scratch results in `results/accuracy/`). Do not edit the tables by hand: "
              "rerun the script.\n")
    md.append(f"This run: {elapsed / 60:.1f} min in all, {a.jobs} runs at a time; load "
              f"average {load_before[0]:.1f} at the start, {load_after[0]:.1f} at the end on "
              f"a 2-core machine shared with other work. **Wall times are noisy** (a run got "
              f"a fraction of a core); the CPU time of each run (below) is the stable "
              f"measure, and the relative costs (CPU / base) are the numbers to carry to "
              f"another machine.\n")
    md.append("## What was run\n")
    md.append("- **cycle**: `cases/seed004_sae40.toml` (seed 004 SAE 40, 10 kW, 1000 rpm) "
              "with `thermal = true` and the Ree-Eyring film (`non_newtonian = true`, "
              "tau0 = 5 MPa), the film model of the shipped studies; base 257 nodes, "
              "`film_nodes` 11, 80 steps, `newton_tolerance` 1e-8, `time_tolerance` 0 (no "
              "substeps for the time error; the series **time_tol** sets it: docs/case_format.md). "
              "Quantities over the step ends of the cycle: min of h_min; h_c at the pitch point "
              "C, interpolated linearly in s between the two step ends around C (C is in "
              "general no step end: at " + c_off[0] + " steps the nearest lies " + c_off[1] +
              " um from it); max of p_max; max of T_max; mean of mu.")
    md.append("- **disc**: `cases/disc_steady.toml` (steel discs, R = 10 mm, SAE 40, "
              "100 kN/m, p_H = 0.60 GPa) with sliding (u1 = 1.2, u2 = 0.8 m/s, SRR 0.4), "
              "thermal and Ree-Eyring, steady; base 257 nodes, 11 film nodes, tolerance 1e-8. "
              "Quantities from the [contact] result (`_steps.csv`): h_min, h_c and p_max of "
              "the (single) steady step, max of `t_max_k`, mean of `mu`.")
    md.append("- One setting varied at a time, the others at the base. The error is relative "
              "to the finest converged run of the same series (the reference, 'ref'), except "
              "for the series **steps** (next item); a run "
              "that did not converge, or had a time step replaced by the steady film "
              "(`[numerics] failed_step`), has no error ('-'). For the grid the Richardson "
              "estimate below each table says how far that reference itself is from the grid "
              "limit. The thermal coupling tolerance (0.01 K) has no case key and is not "
              "varied.")
    md.append(f"- **steps** (equal steps, `time_tolerance` 0): its finest run is no reference, "
              f"because max p_max has not converged in the step count (section 'The time step "
              f"and max p_max'). Each run is compared with the controlled-step film "
              f"(`time_tolerance` = {tt_ref_v}, the reference of the series **time_tol**, "
              f"which `time_tolerance` = 1e-5 confirms below its table) run at the same step "
              f"count, so that both are sampled at the same step ends. The other cycle series "
              f"(N, Nz, tol, inlet) run at the base's 80 equal steps and measure their setting "
              f"at that step; the base itself is {base_time_err} % off the controlled film in "
              f"max p_max (steps = 80).")
    md.append(f"- **Times.** 'wall' is the run's own clock: a cycle's HDF5 `wall_time` (the "
              f"whole run inside the process), a disc's sum of the `wall_time_s` column of its "
              f"`_steps.csv` (the solve of its step). 'CPU' is the CPU time of the run's "
              f"process (user + system, from wait4) less the start-up of the binary "
              f"({fmt_t(m['startup'])} s: the least CPU time of `tehl --version`, which loads "
              f"the program and its libraries); 'CPU / base' and the recommendations use it. "
              f"Every run reads its FFTW plans from a wisdom file (`TEHL_FFTW_WISDOM`, "
              f"docs/performance.md 'One-off cost') planned before the runs, one grid size at a "
              f"time, so no time here contains the one-off FFTW planning of a grid size, which "
              f"a single `tehl run` without that file pays once per process. Measured (CPU time "
              f"of a steady isothermal disc run without and with the plans): " +
              ", ".join(f"{fmt_t(c[0] - c[1])} s at {n}" for n, c in
                        sorted(m["planning"].items(), key=lambda x: int(x[0]))) +
              f" nodes. On the disc that planning is several times the solve (the base disc: "
              f"{plan_257} s of planning, {fmt_t(disc_base['cpu_s'])} s CPU, "
              f"{fmt_t(disc_base['wall_s'])} s of solve wall time).")
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
    md.append("\n## The time step and max p_max\n")
    md += time_step_lines(data["cycle"])
    md.append("\n![largest error against CPU time](accuracy_pareto.png)\n")
    md.append("The figure's error is the largest of the five quantities; on the cycle it is "
              "mostly that of max p_max, the peak of the squeeze transient after B, which "
              "converges slowly with the grid (see its Richardson order) and with the step "
              "(above). Grey: every combination of one setting per series (one run of steps "
              "or time_tol: both vary the time step), its error estimated as the sum of the "
              "settings' errors and its time as the product of their relative costs (the model "
              "of the recommendations below); markers: measured runs.\n")
    md.append("## Recommended settings\n")
    md.append("The cheapest combination of one setting per series whose estimated error is "
              "within the target (steps and time_tol count as one series: a run of one keeps "
              "the other at the base); the error of a combination is estimated as the sum of "
              "its settings' errors (each measured with the others at the base) and its CPU "
              "time as the base time times the product of the settings' CPU / base. The errors "
              "are against the references of the tables, not the exact solution (see the "
              "Richardson line of the grid).\n")
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
                              f"{fmt_t(cost)} s CPU: " + ", ".join(o[0] for o in combo) +
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
