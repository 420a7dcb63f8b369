#!/usr/bin/env bash
# Prints the hard-case table of docs/robustness.md (markdown) from one run of the hard-case
# binaries: the fast one (hard_cases_test) and, unless --fast-only, the full-resolution one
# (hard_cases_slow_test). Each test prints "HARDCASE|case|parameters|grid/steps|status|
# iterations|stages/substeps|time"; this script only reformats those lines.
# Usage: scripts/robustness_table.sh [BUILD_DIR] [--fast-only]
set -euo pipefail
build="${1:-build}"
fast_only="${2:-}"
cd "$(dirname "$0")/.."
run() {  # binary label
  local bin="$build/tests/regression/$1"
  if [[ ! -x "$bin" ]]; then
    echo "missing $bin (cmake --build $build --target $1)" >&2
    exit 1
  fi
  "$bin" 2>/dev/null | awk -F'|' -v label="$2" '
    /^HARDCASE\|/ { print "| " $2 " | " $3 " | " label ": " $4 " | " $5 " | " $6 " | " $7 " | " $8 " |" }
    /^\[  FAILED  \] .*\(/ { failed = failed "\n" label ": " $0 }
    END { if (failed != "") print "FAILED TESTS:" failed > "/dev/stderr" }
  '
}
echo "| case | parameters | version: grid / steps | result | Newton iterations | max continuation stages / substeps | wall time [s] |"
echo "|---|---|---|---|---|---|---|"
run hard_cases_test fast
if [[ "$fast_only" != "--fast-only" ]]; then
  run hard_cases_slow_test full
fi
echo
echo "Machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the end of the run; $(date -u +%Y-%m-%d)."
