#!/usr/bin/env bash
# Installs, builds and runs the main job: the mesh cycle of the seed 004 gear pair (SAE 40,
# 10 kW at 1000 rpm, thermal) from A to E -- results/seed004_sae40.h5, its CSV and the
# figures -- plus the gear report and along-path table, and a film solve of the disc case.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p results
./build/tehl gear cases/seed004_sae40.toml --csv results/seed004_sae40_path.csv
./build/tehl run cases/seed004_sae40.toml -o results
./build/tehl plot results/seed004_sae40.h5 -o results
./build/tehl run cases/disc_steady.toml -o results
