#!/usr/bin/env bash
# Regenerates doc/RESULTS.md and doc/images/results-*.png: the planar map
# against the raw triangle map and OctoMap (5 and 10 cm) on three simulated
# worlds (default, second, office), each at sigma 2 cm and 5 cm, with true
# and with estimated (ICP) poses. One configuration for all runs:
# config/default.ini at 2 cm, config/sigma5.ini at 5 cm (it changes only the
# model's sigma_m). One run per case (times are single runs); plus one
# textured run (default world, 2 cm, true poses) for the texture bytes
# (TEXTURED=0 skips it).
# Usage: scripts/results-report.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/report-lib.sh
bin="${1:-build}/bin"
textured="${TEXTURED:-1}"
worlds=(default second office)
sigmas=(0.02 0.05)

runs="$work/runs.txt"
: > "$runs"
for w in "${worlds[@]}"; do
  for s in "${sigmas[@]}"; do
    sim_cases "$bin" "$w" "$s" "$runs"
  done
done

if [ "$textured" = 1 ]; then
  "$bin/indoor-sim" --seed 1 --quiet --out "$work/textured" 2>/dev/null
  out="$work/map-textured"
  "$bin/planar-mapper" --rawlog "$work/textured.rawlog" --poses "$work/textured.poses.txt" \
    --out "$out" -q
  "$bin/map-eval" --map "$out" --gt "$work/textured.gt.json" --out "$out/eval.json" -q
  echo "default 0.02 true-textured config/default.ini $out" >> "$runs"
fi

cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=$(git diff --quiet HEAD -- . ":!doc" 2>/dev/null || echo " (with uncommitted changes outside doc/)")
/usr/bin/python3 scripts/results_report.py "$runs" doc/RESULTS.md doc/images \
  "$(date -u +%Y-%m-%d)" "$commit$dirty" "$(nproc)" "$cpu"
echo "wrote doc/RESULTS.md"
