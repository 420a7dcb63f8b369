#!/usr/bin/env bash
# Runs the shipped studies (cases/studies/*.toml) and regenerates their figures in
# docs/studies/ and their index tables in results/studies/tables.md (the numbers quoted in
# docs/studies.md, "Findings").
#
#   scripts/make_studies.sh [STUDY ...]      default: every study in cases/studies/
#
# Environment: TEHL (default build/tehl), JOBS (scenes at once, default 2), OUT (default
# results/studies). Needs /usr/bin/python3 with matplotlib and h5py (Debian packages).
# A study whose results exist is not run again (tehl sweep --resume); delete OUT to rerun.
set -euo pipefail
cd "$(dirname "$0")/.."
TEHL=${TEHL:-build/tehl}
JOBS=${JOBS:-2}
OUT=${OUT:-results/studies}
PY=/usr/bin/python3
if [[ ! -x "$TEHL" ]]; then
  echo "make_studies.sh: $TEHL is not an executable (build tehl, or set TEHL)" >&2
  exit 2
fi
studies=("$@")
if [[ ${#studies[@]} -eq 0 ]]; then
  studies=(load speed lubricant load_sharing tooth_form roughness_amplitude roughness_wavelength tip_relief
    surface_temperature)
fi
mkdir -p "$OUT" docs/studies
tables="$OUT/tables.md"
: > "$tables"
status=0
for name in "${studies[@]}"; do
  study="cases/studies/$name.toml"
  start=$(date +%s)
  "$TEHL" sweep "$study" -j "$JOBS" -q --resume -o "$OUT/$name" || status=1
  echo "$name: $(( $(date +%s) - start )) s" >&2
  # The 2 x 2 figure along the path and the summaries against the varied parameter.
  "$PY" scripts/plot_study.py "$OUT/$name/index.h5" -o "$OUT/$name/png" --prefix "$name" \
    --dpi 80 > "$OUT/$name/png.txt"
  cp "$OUT/$name/png/${name}_path.png" docs/studies/
  # plot_study.py prints "wrote PATH" for each figure.
  for f in $(sed -n 's/^wrote //p' "$OUT/$name/png.txt" | grep -v '_path'); do cp "$f" docs/studies/; done
  {
    echo "### $name"
    echo
    "$PY" scripts/plot_study.py "$OUT/$name/index.h5" --table
    echo
  } >> "$tables"
done
echo "wrote docs/studies/*.png and $tables" >&2
exit $status
