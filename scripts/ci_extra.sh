#!/usr/bin/env bash
# Robustness checks of CI (.ci/run runs this after scripts/test.sh). Exits non-zero on any
# failure. Each stage prints its wall time.
#  1. The mutated malformed-input corpus is what scripts/make_malformed.py makes.
#  2. One clang build in build-san with AddressSanitizer + UndefinedBehaviorSanitizer
#     (TEHL_BUILD_FUZZ=ON: the whole library and every test are instrumented; UBSan reports are
#     fatal, -fno-sanitize-recover) serves both checks below, so the library is compiled once
#     more, not twice. -O1 with line tables keeps the build short and the reports readable.
#  3. The fast tests (ctest -LE 'slow|install|mpi': every test binary that scripts/test.sh
#     runs) pass with no sanitizer report; ASan reports errors and leaks at exit.
#  4. libFuzzer: tests/fuzz/case_parser_fuzz, seeded with the shipped cases and lubricants and
#     the malformed corpus, for TEHL_FUZZ_SECONDS (default 60). A finding is written to
#     build-san/findings/ and fails the run (tests/fuzz/README.md: how to reproduce it).
# Environment: TEHL_CI_JOBS (default nproc), TEHL_FUZZ_SECONDS (default 60),
# TEHL_CI_SKIP_ASAN=1 / TEHL_CI_SKIP_FUZZ=1 to leave a stage out when running by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS="${TEHL_CI_JOBS:-$(nproc)}"
FUZZ_SECONDS="${TEHL_FUZZ_SECONDS:-60}"

stage() { echo "ci_extra: $1 ($(( SECONDS - T0 )) s since the start)"; }
T0=$SECONDS

stage "mutated corpus is up to date"
python3 scripts/make_malformed.py --check

stage "ASan + UBSan build with the fuzz target (build-san, clang)"
# No benchmarks (the tests do not run them), no MPI (Open MPI's start-up allocations, made in
# plugins it unloads, are reported as leaks no suppression can name; scripts/test.sh runs the
# two-rank sweep test).
cmake -S . -B build-san -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DTEHL_BUILD_FUZZ=ON \
      -DTEHL_BUILD_BENCH=OFF -DTEHL_WITH_MPI=OFF > build-san.configure.log
cmake --build build-san -j "$JOBS"

if [ "${TEHL_CI_SKIP_ASAN:-0}" != 1 ]; then
  stage "ASan + UBSan tests (ctest -LE 'slow|install|mpi')"
  export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
  # Every test binary of scripts/test.sh runs but install_consumer (label `install`: a
  # packaging check whose consumer program is built without the sanitizers; scripts/test.sh
  # runs it). Left out by name: the long physics regressions (whole mesh cycles, time-order
  # studies, the hard-case suite: 20-100 s each under the sanitizers, together two thirds of
  # the sanitizer run). They exercise the same code as the tests that stay, which include a
  # thermal and an isothermal mesh cycle with checkpoints; scripts/test.sh runs them all.
  LONG='ThermalCycleSeed004|Bdf[12]Is|MeshCycleDynamic.Seed004|M5000L25|MovingWaviness'
  LONG="$LONG|MeshCycleSeed004|SameFilmFromPerturbed|TransientLoadChange|Sweep.Index|HardCase|SlidingNewtonianDisc|ThermalCoupling|StepRestart"
  ctest --test-dir build-san --output-on-failure -j "$JOBS" -LE 'slow|install|mpi' -E "$LONG"
  unset ASAN_OPTIONS UBSAN_OPTIONS
fi

if [ "${TEHL_CI_SKIP_FUZZ:-0}" != 1 ]; then
  stage "fuzzing the case and lubricant parsers for ${FUZZ_SECONDS} s"
  rm -rf build-san/corpus build-san/findings
  mkdir -p build-san/corpus build-san/findings
  # New inputs go to build-san/corpus; the seed folders are only read.
  build-san/tests/fuzz/case_parser_fuzz -max_total_time="$FUZZ_SECONDS" -seed=1 -timeout=30 \
      -rss_limit_mb=2048 -max_len=8192 -dict=tests/fuzz/toml.dict -print_final_stats=1 \
      -artifact_prefix=build-san/findings/ \
      build-san/corpus cases lubricants tests/malformed/case tests/malformed/lubricant \
      > build-san/fuzz.log 2>&1 || {
    tail -n 60 build-san/fuzz.log
    echo "ci_extra: the fuzzer found a problem: build-san/findings/ (tests/fuzz/README.md)"
    exit 1
  }
  grep -E "^stat::|Done [0-9]+ runs" build-san/fuzz.log || true
fi
stage "done"
