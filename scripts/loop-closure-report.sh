#!/usr/bin/env bash
# Measures loop closure on the Radish ACES log (real 2D laser, published
# reference relations, ../shared/data/radish/README.md) and writes
# doc/loop-closure.md: the pose stage without and with [Poses] loop_closure,
# the Kümmerle relation error of each, and the median wall time of 3 runs;
# the pose stage with the aperture the log carries (90 deg, wrong: input.md,
# "Scan aperture"); the occupancy grids of aces, intel and mit-csail with
# loop closure (doc/images/radish-<log>-grid.png, 10 cm cells); MRPT's own
# icp-slam (Debian mrpt-apps) with its shipped icp-slam_demo_LM.ini, when
# installed.
# Usage: scripts/loop-closure-report.sh [BUILD_DIR] [RADISH_DIR] [RELATION_TOOL]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build}/bin"
radish="${2:-../shared/data/radish}"
tool="${3:-../shared/tools/relation_error.py}"
for f in "$radish/aces.rawlog" "$radish/aces.scan_relations.txt" "$tool"; do
  [[ -f $f ]] || { echo "loop-closure-report: $f not found" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed "s#^@include icp.ini#@include $PWD/config/icp.ini#" config/radish.ini > "$work/on.ini"
sed 's/^loop_closure = true/loop_closure = false/' "$work/on.ini" > "$work/off.ini"
sed '/^pose_laser_aperture_deg/d' "$work/off.ini" > "$work/off-file-aperture.ini"
printf '@include %s\n[Output]\ngrid_resolution_m = 0.1\n' "$work/on.ini" > "$work/grid.ini"

median_seconds() {  # median_seconds CMD...: median wall time (s) of 3 runs of CMD
  local t=()
  for _ in 1 2 3; do
    local t0
    t0=$(date +%s.%N)
    "$@"
    t+=("$(python3 -c "import sys; print('%.1f' % (float(sys.argv[1]) - float(sys.argv[2])))" \
      "$(date +%s.%N)" "$t0")")
  done
  printf '%s\n' "${t[@]}" | sort -n | sed -n 2p
}

map_aces() {  # map_aces INI OUT: the pose stage on aces.rawlog
  rm -rf "$2"
  "$bin/planar-mapper" --config "$1" --rawlog "$radish/aces.rawlog" --poses-only --out "$2" -q
}

row() {  # row NAME INI
  local out="$work/$1"
  scored "$1" "$out/poses.txt" "$(median_seconds map_aces "$2" "$out")"
}

scored() {  # scored NAME POSES SECONDS: a table row
  local errs
  errs=$(python3 "$tool" "$2" "$radish/aces.scan_relations.txt")
  grep -q ' 0 relations past the end skipped' <<<"$errs" || {
    echo "loop-closure-report: $1: relations skipped: $errs" >&2
    exit 1
  }
  local all short loop
  all=$(grep '^all:' <<<"$errs" | sed 's/.*translation \([^ ]*\) ± \([^ ]*\) m, rotation \([^ ]*\) ± \([^ ]*\) deg/\1 ± \2 | \3 ± \4/')
  short=$(grep '^short' <<<"$errs" | sed 's/.*translation \([^ ]*\) ± \([^ ]*\) m.*/\1 ± \2/')
  loop=$(grep '^loop' <<<"$errs" | sed 's/.*translation \([^ ]*\) ± \([^ ]*\) m, rotation \([^ ]*\) ± \([^ ]*\) deg/\1 ± \2 | \3 ± \4/')
  echo "| $1 | $all | $short | $loop | $3 | $(python3 -c "import sys; print(round(1365 / float(sys.argv[1])))" "$3") |"
}

# icp-slam_row: MRPT's icp-slam, its shipped LM ini with the display and
# periodic logs off, on the log as converted (icp-slam has no way to replace
# the aperture). log_estimated_path.txt has one line per rawlog entry; the log
# alternates ODOMETRY and FLASER, so scan i is entry 2i + 1.
icp_slam_row() {
  local lm=/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_LM.ini
  if ! command -v icp-slam > /dev/null || [[ ! -f $lm ]]; then
    echo "| MRPT icp-slam, icp-slam_demo_LM.ini | not run: icp-slam (Debian mrpt-apps) not installed |||||||"
    return
  fi
  sed -e "s#^logOutput_dir=.*#logOutput_dir=$work/icp-slam#" -e 's#^LOG_FREQUENCY=.*#LOG_FREQUENCY=0#' \
    -e 's#^SAVE_3D_SCENE=.*#SAVE_3D_SCENE=0#' -e 's#^CAMERA_3DSCENE_FOLLOWS_ROBOT=.*#CAMERA_3DSCENE_FOLLOWS_ROBOT=0#' \
    -e 's#^SHOW_PROGRESS_3D_REAL_TIME=.*#SHOW_PROGRESS_3D_REAL_TIME=false#' \
    -e 's#^SHOW_LASER_SCANS_3D.*#SHOW_LASER_SCANS_3D = false#' "$lm" > "$work/icp-slam.ini"
  run_icp_slam() {
    icp-slam "$work/icp-slam.ini" "$radish/aces.rawlog" < /dev/null > "$work/icp-slam.log" 2>&1
  }
  local secs
  secs=$(median_seconds run_icp_slam)
  awk 'NR % 2 == 0 {print NR / 2, $2, $3, 0, $4, 0, 0}' "$work/icp-slam/log_estimated_path.txt" \
    > "$work/icp-slam-poses.txt"
  scored "MRPT icp-slam, icp-slam_demo_LM.ini, the file's aperture" "$work/icp-slam-poses.txt" "$secs"
}

file=$(row "ICP only, the file's aperture (90 deg)" "$work/off-file-aperture.ini")
off=$(row "ICP only" "$work/off.ini")
on=$(row "ICP + loop closure" "$work/on.ini")
mrpt=$(icp_slam_row)
grid_row() {  # grid_row LOG: runs it, keeps its grid picture, prints a line
  local out="$work/grid-$1"
  "$bin/planar-mapper" --config "$work/grid.ini" --rawlog "$radish/$1.rawlog" --poses-only \
    --out "$out" -q
  cp "$out/grid.png" "doc/images/radish-$1-grid.png"
  python3 - "$out/summary.json" "$1" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
lc, g = s["poses"]["loop_closure"], s["poses"]["grid"]
print(f"- {sys.argv[2]}: {s['poses']['count']} poses, {lc['keyframes']} keyframes, "
      f"{lc['accepted']} loops accepted of {lc['candidates']} candidates; grid "
      f"{g['cols']} x {g['rows']} cells of {g['resolution_m']:.2f} m. "
      f"![{sys.argv[2]}](images/radish-{sys.argv[2]}-grid.png)")
PY
}
grids=$(for log in aces intel mit-csail; do grid_row "$log"; done)

cat > doc/loop-closure.md <<DOC
# Loop closure on real data (ACES)

Written by \`scripts/loop-closure-report.sh\` ($(date -u +%Y-%m-%d)). The pose stage of
planar-mapper on the Radish ACES log (7,374 scans, 1,365 s, several loops;
\`config/radish.ini\`, \`--poses-only\`), scored with the Kümmerle et al.
relation error against the benchmark's 1,279 reference relations (mean ±
std; "short": relations under 20 scans apart, "loop": the 116 longer ones,
which close loops). Time: median wall time of 3 runs on a shared 2-core
machine; "x real time" = 1,365 s / that. How loop closure works: poses.md,
"Loop closure".

| run | all: translation (m) | all: rotation (deg) | short: translation (m) | loop: translation (m) | loop: rotation (deg) | time (s) | x real time |
|---|---|---|---|---|---|---|---|
$file
$off
$on
$mrpt

Published on this log (translation): Cartographer about 0.04 ± 0.04 m,
graph SLAM in Kümmerle et al. about 0.04 m. The first row is the pose stage
on the log as converted (0.5 deg per beam: every scan squeezed to half its
width); the others use \`pose_laser_aperture_deg = 180\` from
\`config/radish.ini\` (input.md, "Scan aperture").

## Occupancy grids (\`grid.png\`, loop closure on, 10 cm cells)
$grids

What the pictures showed when this page was last looked at (2026-12-07,
with one-sided normals in the keyframe refinement, poses.md "Keyframe
edges"): ACES is the building's grid of corridors with thin single walls;
no doubled wall is visible. Intel comes out as one building: the outer ring
and rooms are single, but the two long inner corridor walls come out
bowed, as arcs, where the real ones are straight: heading drift the loops
did not take out there (issue 15). MIT CSAIL holds together: the central
rectangular block sits square with the corridors around it and the long
diagonal corridor is single (130 loops accepted of 260 candidates).
Until this change it did not (86 of 170: the block turned against the
corridors, two corridors doubled, the rooms at the upper right smeared),
and the outcome was fragile: it turned on millimetres in the first
closures (2026-12-05: the same code gave a good picture on 2026-12-04 and
a distorted one after a change that leaves the solves the same). Checked
the same way for the new rule, one run each, MIT CSAIL with small
perturbations, without / with one-sided normals (loops accepted, and the
picture): as shipped 86 distorted / 130 holds; \`loop_search_latency_keyframes
= 0\` 89 distorted / 133 holds; \`keyframe_refine_sigma_m = 0.031\` 84
distorted / 107 holds (the rooms at the upper right a little smeared);
\`loop_min_score = 0.41\` 134 holds / 124 holds (a faint second line along
the diagonal corridor). Without the rule the log held together in one case
of four, with it in four of four.
DOC
echo "wrote doc/loop-closure.md"
