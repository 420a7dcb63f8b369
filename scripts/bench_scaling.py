#!/usr/bin/env python3
"""Cold-solve scaling of the Newton-Krylov film solver over separate processes.

Runs build/bench/ehl_bench K times (each a fresh process: FFTW plans and memory layout differ
between processes, and so do cold times, by up to 2x at one grid size), collects
BM_Steady/<n>/<code>/ (cold and warm solve times) and BM_FftConvolution, and prints the
median over the processes of each time and the ratios time(n)/time(n/2) (docs/performance.md,
"The default solver today").

    python3 scripts/bench_scaling.py [--runs 6] [--code 2] [--bench build/bench/ehl_bench]

code: 2 = Newton-Krylov with the two-level preconditioner, 4 = with the UMFPACK hierarchy.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=6, help="separate processes (default 6)")
    ap.add_argument("--code", type=int, default=2, choices=(2, 4), help="solver code")
    ap.add_argument("--bench", default="build/bench/ehl_bench", help="benchmark program")
    args = ap.parse_args()
    if not os.access(args.bench, os.X_OK):
        sys.exit(f"bench_scaling: {args.bench} is not an executable (build with "
                 "-DTEHL_BUILD_BENCH=ON)")
    cold, warm, fft = {}, {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.runs):
            out = os.path.join(tmp, f"run{r}.json")
            subprocess.run([args.bench,
                            f"--benchmark_filter=BM_FftConvolution|BM_Steady/.*/{args.code}/",
                            f"--benchmark_out={out}", "--benchmark_out_format=json"],
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            with open(out) as f:
                for b in json.load(f)["benchmarks"]:
                    parts = b["name"].split("/")
                    n = int(parts[1])
                    if parts[0] == "BM_Steady":
                        if not (b["cold_ok"] and b["warm_ok"]):
                            sys.exit(f"bench_scaling: a solve at n = {n} failed in run {r + 1}")
                        cold.setdefault(n, []).append(b["cold_s"])
                        warm.setdefault(n, []).append(b["warm_s"])
                    elif parts[0] == "BM_FftConvolution":
                        fft.setdefault(n, []).append(b["real_time"])
    ns = sorted(cold)
    med = {n: statistics.median(cold[n]) for n in ns}
    print(f"{'n':>6} {'FFT [us]':>9} {'cold [s]':>9} {'warm [s]':>9} {'cold ratio':>11}"
          f"  cold per process [s]")
    for i, n in enumerate(ns):
        ratio = f"{med[n] / med[ns[i - 1]]:11.2f}" if i else " " * 11
        per = " ".join(f"{c:.4f}" for c in cold[n])
        print(f"{n:6d} {statistics.median(fft[n]):9.1f} {med[n]:9.4f} "
              f"{statistics.median(warm[n]):9.4f} {ratio}  {per}")
    doublings = len(ns) - 1
    if doublings > 0:
        print(f"per doubling over {ns[0]} ... {ns[-1]}: "
              f"{(med[ns[-1]] / med[ns[0]]) ** (1.0 / doublings):.2f}")


if __name__ == "__main__":
    main()
