#!/usr/bin/env bash
# Installs, builds and runs the test suite (everything but the `slow` label).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" -LE slow
