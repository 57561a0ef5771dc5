#!/usr/bin/env bash
# Builds and runs the Google Benchmark micro-benchmarks (benchmarks/) and a
# planar-mapper run of the default world for its stage timings, and writes
# doc/performance.md. Medians over REPS repetitions.
# Usage: scripts/bench.sh [BUILD_DIR] [REPS]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/report-lib.sh
build="${1:-build}"
reps="${2:-5}"
cmake -S . -B "$build" -DPMAP_BUILD_BENCHMARKS=ON > /dev/null
nice -n 10 cmake --build "$build" -j2 --target bench_em_steps bench_online_em indoor-sim \
  planar-mapper > /dev/null
for b in em_steps online_em; do
  "$build/bench/bench_$b" --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
    --benchmark_format=json --benchmark_out="$work/$b.json" --benchmark_out_format=json > /dev/null
done
"$build/bin/indoor-sim" --seed 1 --no-cameras --quiet --out "$work/sim"
for poses in true icp; do
  extra=()
  [ "$poses" = true ] && extra=(--poses "$work/sim.poses.txt")
  for r in $(seq "$reps"); do
    "$build/bin/planar-mapper" --rawlog "$work/sim.rawlog" "${extra[@]}" \
      --out "$work/map-$poses-$r" -q
  done
done
cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
/usr/bin/python3 scripts/bench_report.py "$work" "$reps" doc/performance.md \
  "$(date -u +%Y-%m-%d)" "$(git rev-parse --short HEAD 2>/dev/null || echo unknown)" \
  "$(nproc)" "$cpu"
echo "wrote doc/performance.md"
