#!/usr/bin/env bash
# Regenerates doc/peer-benchmark.md: issue 16's peer benchmark. PCL's
# SACSegmentation and region growing and CGAL's Efficient RANSAC and region
# growing beside planar-mapper, on the same clouds, with one parameter rule
# for all (peer-bench's header): the points of four simulated worlds mapped
# with their true poses, the cluttered one at two noise levels (scored against
# the simulator's ground-truth planes)
# and MRPT's Kinect frame (no ground truth: planes and time only).
# Not part of the product: it installs libpcl-dev and libcgal-dev itself
# (apt-get; sudo when not root) and builds peer-bench in its own folder with
# -DPMAP_PEER_BENCH=ON.
# Usage: scripts/peer-benchmark.sh [BUILD_DIR (default build-peers)]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/report-lib.sh
build="${1:-build-peers}"

if ! dpkg -s libpcl-dev libcgal-dev > /dev/null 2>&1; then
  sudo_=""
  [ "$(id -u)" -ne 0 ] && sudo_=sudo
  $sudo_ apt-get install -y --no-install-recommends libpcl-dev libcgal-dev
fi
fresh=()
[ -f "$build/CMakeCache.txt" ] || fresh=(-DCMAKE_BUILD_TYPE=Release -DPMAP_BUILD_TESTS=OFF)
cmake -S . -B "$build" "${fresh[@]}" -DPMAP_PEER_BENCH=ON > /dev/null
cmake --build "$build" -j"$(nproc)" --target peer-bench planar-mapper indoor-sim > /dev/null
bin="$build/bin"
bench="$build/bench/peer-bench"

# ours_ini BASE POINTS OUT: BASE with the rule's sigma (sigma_m = auto is the
# same estimate) and minimum support for a cloud of POINTS points.
ours_ini() {
  local support
  support=$(python3 -c "print(max(200, int(0.005 * $2)))")
  sed -e 's/^sigma_m = [^;]*/sigma_m = auto /' -e "s/^min_support = [0-9]*/min_support = $support/" \
    -e "s#^@include icp.ini#@include $PWD/config/icp.ini#" "$1" > "$3"
}

# bench_cloud NAME CLOUD BASE_INI [GT]: ours (BASE_INI with the rule's sigma
# and support, on all points and coarse to fine) and the four library methods
# on CLOUD.
bench_cloud() {
  local name=$1 cloud=$2 base=$3 gt=${4:-} n
  n=$(python3 - "$cloud" <<'PY'
import sys
with open(sys.argv[1], "rb") as f:
    for line in f:
        if line.startswith(b"element vertex"):
            print(int(line.split()[2])); break
PY
)
  ours_ini "$base" "$n" "$work/$name.ini"
  grep -v '^coarse_points' "$work/$name.ini" > "$work/$name-all.ini"
  sed -e 's/^\(min_support = .*\)$/\1\ncoarse_points = 20000/' "$work/$name-all.ini" \
    > "$work/$name-coarse.ini"
  local gt_args=()
  [ -n "$gt" ] && gt_args=(--gt "$gt")
  for v in coarse all; do
    "$bin/planar-mapper" --config "$work/$name-$v.ini" --cloud "$cloud" --out "$work/$name-ours-$v" \
      -q --no-textures 2>/dev/null
    "$bench" --cloud "$cloud" "${gt_args[@]}" --ours "$work/$name-ours-$v" --only none \
      --json "$work/$name-ours-$v.json"
  done
  "$bench" --cloud "$cloud" "${gt_args[@]}" --json "$work/$name-peers.json"
  echo "peer-benchmark: $name done" >&2
}

# Simulated clouds: NAME:WORLD:SIGMA. Ours uses config/default.ini for all:
# the rule sets the sigma, the only key config/sigma5.ini changes.
for c in default:default:0.02 office:office:0.02 cluttered:cluttered:0.02 cluttered5:cluttered:0.05 \
  glass-office:glass-office:0.02; do
  IFS=: read -r name w s <<< "$c"
  "$bin/indoor-sim" --world "config/worlds/$w.json" --seed 1 --sigma "$s" --no-cameras --quiet \
    --out "$work/$name" 2>/dev/null
  "$bin/planar-mapper" --rawlog "$work/$name.rawlog" --poses "$work/$name.poses.txt" \
    --config config/default.ini --out "$work/$name-map" -q --no-textures 2>/dev/null
  bench_cloud "$name" "$work/$name-map/points.ply" config/default.ini "$work/$name.gt.json"
done
"$bin/planar-mapper" --config config/mrpt-rgbd.ini --rawlog /usr/share/mrpt/datasets/tests_rgbd.rawlog \
  --out "$work/kinect-map" -q --no-textures 2>/dev/null
bench_cloud kinect "$work/kinect-map/points.ply" config/mrpt-rgbd.ini

python3 scripts/peer_report.py "$work" "$(git rev-parse --short HEAD)" "$(nproc)" \
  > doc/peer-benchmark.md
echo "peer-benchmark: wrote doc/peer-benchmark.md" >&2
