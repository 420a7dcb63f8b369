#!/usr/bin/env bash
# Robustness checks of CI (.ci/run runs this after scripts/test.sh). Exits non-zero on any
# failure. Each stage prints its wall time.
#  1. The mutated malformed-input corpus is what scripts/make_malformed.py makes.
#  2. AddressSanitizer + UndefinedBehaviorSanitizer: one combined build (gcc, TEHL_SANITIZE=ON)
#     in build-asan; the fast tests (ctest -LE 'slow|install': every test binary that
#     scripts/test.sh runs) must pass with no sanitizer report. A UBSan report stops the process
#     (-fno-sanitize-recover, halt_on_error=1); ASan reports errors and leaks at exit.
#  3. libFuzzer: tests/fuzz/case_parser_fuzz (clang, TEHL_BUILD_FUZZ=ON) in build-fuzz, seeded
#     with the shipped cases and lubricants and the malformed corpus, for TEHL_FUZZ_SECONDS
#     (default 60). A finding is written to build-fuzz/findings/ and fails the run
#     (tests/fuzz/README.md: how to reproduce it).
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

if [ "${TEHL_CI_SKIP_ASAN:-0}" != 1 ]; then
  stage "ASan + UBSan build (build-asan)"
  # RelWithDebInfo: optimised like the release build, with line numbers in the reports.
  # No benchmarks: the tests do not run them.
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTEHL_SANITIZE=ON \
        -DTEHL_BUILD_BENCH=OFF > build-asan.configure.log
  cmake --build build-asan -j "$JOBS"
  stage "ASan + UBSan tests (ctest -LE 'slow|install')"
  export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
  # Every test binary of scripts/test.sh runs. Left out: the `install` label (install_consumer,
  # a packaging check: its consumer program is built without the sanitizers and cannot load
  # the instrumented library; scripts/test.sh runs it).
  ctest --test-dir build-asan --output-on-failure -j "$JOBS" -LE 'slow|install'
  unset ASAN_OPTIONS UBSAN_OPTIONS
fi

if [ "${TEHL_CI_SKIP_FUZZ:-0}" != 1 ]; then
  stage "libFuzzer build (build-fuzz, clang)"
  cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTEHL_BUILD_FUZZ=ON \
        -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DBUILD_TESTING=OFF \
        -DTEHL_BUILD_BENCH=OFF -DTEHL_WITH_MPI=OFF > build-fuzz.configure.log
  cmake --build build-fuzz -j "$JOBS" --target case_parser_fuzz
  stage "fuzzing the case and lubricant parsers for ${FUZZ_SECONDS} s"
  rm -rf build-fuzz/corpus build-fuzz/findings
  mkdir -p build-fuzz/corpus build-fuzz/findings
  # New inputs go to build-fuzz/corpus; the seed folders are only read.
  build-fuzz/tests/fuzz/case_parser_fuzz -max_total_time="$FUZZ_SECONDS" -seed=1 -timeout=30 \
      -rss_limit_mb=2048 -max_len=8192 -dict=tests/fuzz/toml.dict -print_final_stats=1 \
      -artifact_prefix=build-fuzz/findings/ \
      build-fuzz/corpus cases lubricants tests/malformed/case tests/malformed/lubricant \
      > build-fuzz/fuzz.log 2>&1 || {
    tail -n 60 build-fuzz/fuzz.log
    echo "ci_extra: the fuzzer found a problem: build-fuzz/findings/ (tests/fuzz/README.md)"
    exit 1
  }
  grep -E "^stat::|Done [0-9]+ runs" build-fuzz/fuzz.log || true
fi
stage "done"
