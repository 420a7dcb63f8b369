#!/usr/bin/env bash
# Installs, builds and runs the main job on the seed 004 case.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/tehl gear cases/seed004_sae40.toml
