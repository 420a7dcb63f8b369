#!/usr/bin/env bash
# Regenerates docs/accuracy.md and docs/accuracy_pareto.png (accuracy against run time of the
# seed 004 thermal mesh cycle and a thermal disc; the cost of each effect).
#
#   scripts/accuracy_report.sh [--reuse]
#
# Environment: TEHL (default build/tehl), JOBS (runs at once, default 2), SCRATCH (default
# results/accuracy). About 1.5 minutes on the 2-core machine (the FFT plans of 12 grid sizes, one
# at a time, then 56 runs, 2 at a time). Needs /usr/bin/python3 with matplotlib and h5py (Debian
# packages).
set -euo pipefail
cd "$(dirname "$0")/.."
exec /usr/bin/python3 scripts/accuracy_report.py --tehl "${TEHL:-build/tehl}" \
  --jobs "${JOBS:-2}" --scratch "${SCRATCH:-results/accuracy}" --docs docs "$@"
