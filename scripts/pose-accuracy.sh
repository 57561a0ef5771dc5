#!/usr/bin/env bash
# Measures the pose stage on simulated runs against the simulator's ground
# truth and writes doc/pose-accuracy.md (issue 15's simulated targets): with
# the shipped config/default.ini (loop closure on), the same with loop
# closure off, and odometry alone, on seeds 1-5 of the default world, seed 1 of second and office
# (full runs: the planar map's error too) and seed 1 of the loop and
# aliasing worlds (--poses-only); the full worlds also offline without and
# with [Poses] plane_refinement. The real-data half (ACES) is
# doc/loop-closure.md, written by scripts/loop-closure-report.sh.
# Usage: scripts/pose-accuracy.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build}/bin"
source scripts/report-lib.sh
cp config/default.ini "$work/lc-true.ini"
sed 's/^loop_closure = true /loop_closure = false/' config/default.ini > "$work/lc-false.ini"
grep -q "^loop_closure = false" "$work/lc-false.ini"
sed 's/^loop_closure = true /loop_closure = true\nkeyframe_refinement = false\n#/' config/default.ini \
  > "$work/lc-norefine.ini"
grep -q "^keyframe_refinement = false" "$work/lc-norefine.ini"
sed 's/^pose_laser = LASER_H .*/pose_laser = none/' config/default.ini > "$work/odometry.ini"
sed 's/^loop_closure = true /loop_closure = true\nplane_refinement = true\n#/' config/default.ini \
  > "$work/planes.ini"
grep -q "^plane_refinement = true" "$work/planes.ini"
cp config/icp.ini "$work/"

rows=""
plane_rows=""
# Planes correct poses: the same run offline, without and with
# [Poses] plane_refinement (its defaults).
run_planes() {  # run_planes WORLD SEED (the simulated log is there already)
  local p="$work/$1-$2" cells=""
  for v in off on; do
    local ini="$work/lc-true.ini"
    [[ $v == on ]] && ini="$work/planes.ini"
    "$bin/planar-mapper" --config "$ini" --rawlog "$p.rawlog" --mode offline --no-textures \
      --out "$p-planes-$v" -q
    "$bin/map-eval" --map "$p-planes-$v" --gt "$p.gt.json" --out "$p-planes-$v/eval.json" -q
    python3 scripts/pose_errors.py "$p.poses.txt" "$p-planes-$v/poses.txt" \
      > "$p-planes-$v/errors.json"
  done
  plane_rows+="| $1 | $2 | $(json "$p-planes-off/errors.json" "'%.3f' % d['ate_m']") / \
$(json "$p-planes-on/errors.json" "'%.3f' % d['ate_m']") | \
$(json "$p-planes-off/errors.json" "'%.3f' % d['max_m']") / \
$(json "$p-planes-on/errors.json" "'%.3f' % d['max_m']") | \
$(json "$p-planes-off/eval.json" "'%.1f' % (1000 * d['planar_map']['mean_error_m'])") / \
$(json "$p-planes-on/eval.json" "'%.1f' % (1000 * d['planar_map']['mean_error_m'])") | \
$(json "$p-planes-on/summary.json" "'%d / %d / %d' % (lambda r: (r['knots'], r['surfaces'], r['residuals']))(d['poses']['plane_refinement'][0])") | \
$(json "$p-planes-on/summary.json" "'%.3f / %.2f' % (lambda r: (r['max_shift_m'], r['max_turn_deg']))(d['poses']['plane_refinement'][0])") | \
$(json "$p-planes-on/summary.json" "'%.2f' % d['poses']['plane_refinement'][0]['seconds']") | \
$(json "$p-planes-off/summary.json" "'%.1f' % d['timing_s']['total']") / \
$(json "$p-planes-on/summary.json" "'%.1f' % d['timing_s']['total']") |"$'\n'
}
run_one() {  # run_one WORLD SEED full|poses
  local world=$1 seed=$2 p="$work/$1-$2" extra=()
  [[ $3 == poses ]] && extra=(--poses-only)
  "$bin/indoor-sim" --world "config/worlds/$world.json" --seed "$seed" --no-cameras --quiet \
    --out "$p" 2>/dev/null
  "$bin/planar-mapper" --config "$work/odometry.ini" --rawlog "$p.rawlog" --poses-only \
    --out "$p-odo" -q
  "$bin/planar-mapper" --config "$work/lc-norefine.ini" --rawlog "$p.rawlog" --poses-only \
    --out "$p-norefine" -q
  python3 scripts/pose_errors.py "$p.poses.txt" "$p-norefine/poses.txt" > "$p-norefine/errors.json"
  local cells=() on_surface=() map_mm=() p99=()
  for lc in false true; do
    "$bin/planar-mapper" --config "$work/lc-$lc.ini" --rawlog "$p.rawlog" "${extra[@]}" \
      --no-textures --out "$p-$lc" -q
    python3 scripts/pose_errors.py "$p.poses.txt" "$p-$lc/poses.txt" "$p-$lc/summary.json" \
      > "$p-$lc/errors.json"
    p99+=("$(json "$p-$lc/summary.json" "'%.2f' % d['pose_per_scan_ms']['p99']")")
    if [[ $3 == full ]]; then
      "$bin/map-eval" --map "$p-$lc" --gt "$p.gt.json" --out "$p-$lc/eval.json" -q
      on_surface+=("$(json "$p-$lc/eval.json" "'%.4f' % d['label_check']['fraction_within_3sigma']")")
      map_mm+=("$(json "$p-$lc/eval.json" "'%.1f' % (1000 * d['planar_map']['mean_error_m'])")")
    else
      on_surface+=("-")
      map_mm+=("-")
    fi
  done
  python3 scripts/pose_errors.py "$p.poses.txt" "$p-odo/poses.txt" > "$p-odo/errors.json"
  local e0="$p-false/errors.json" e1="$p-true/errors.json"
  rows+="| $world | $seed | $(json "$p-odo/errors.json" "'%.3f' % d['ate_m']") | \
$(json "$e0" "'%.3f' % d['ate_m']") | $(json "$p-norefine/errors.json" "'%.3f' % d['ate_m']") | \
$(json "$e1" "'%.3f' % d['ate_m']") | \
$(json "$e0" "'%.3f' % d['max_m']") / $(json "$e1" "'%.3f' % d['max_m']") | \
$(json "$e1" "'%d (%.2f m)' % (d['loops'], d['worst_loop_m'])") | \
${on_surface[0]} / ${on_surface[1]} | ${map_mm[0]} / ${map_mm[1]} | ${p99[0]} / ${p99[1]} |"$'\n'
  [[ $3 == full ]] && run_planes "$world" "$seed"
  echo "pose-accuracy: $world $seed done" >&2
}
for seed in 1 2 3 4 5; do run_one default "$seed" full; done
run_one second 1 full
run_one office 1 full
run_one loop 1 poses
run_one aliasing 1 poses

# The pose stage's p99 per pose-laser scan without and with the pose graph
# (--poses-only): as fast as the machine goes, median of 5 runs each, and fed
# at 10 times the log's pace (--playback-rate 10, as a robot 10 times faster
# would feed it), median of 3; alternating off and on; plus the time the
# front end waited for loop searches in the last paced run.
p99_median() {  # p99_median WORLD-SEED RUNS [planar-mapper options]: "off on"
  local wp=$1 runs=$2
  shift 2
  declare -A p99s=([false]="" [true]="")
  for ((rep = 1; rep <= runs; rep++)); do
    for lc in false true; do
      "$bin/planar-mapper" --config "$work/lc-$lc.ini" --rawlog "$work/$wp.rawlog" --poses-only \
        "$@" --out "$work/p99-$lc" -q
      p99s[$lc]+=" $(json "$work/p99-$lc/summary.json" "d['pose_per_scan_ms']['p99']")"
    done
  done
  echo "$(median ${p99s[false]}) $(median ${p99s[true]})"
}
p99_rows=""
for wp in default-1 second-1 office-1 loop-1 aliasing-1; do
  read -r off on <<< "$(p99_median "$wp" 5)"
  wait_fast=$(json "$work/p99-true/summary.json" "'%.2f' % d['poses']['loop_closure']['wait_s']")
  read -r off10 on10 <<< "$(p99_median "$wp" 3 --playback-rate 10)"
  wait10=$(json "$work/p99-true/summary.json" "'%.3f' % d['poses']['loop_closure']['wait_s']")
  p99_rows+="| ${wp%-*} | ${wp##*-} | $(printf '%.2f' "$off") | $(printf '%.2f' "$on") | \
$(python3 -c "print('%.2f' % ($on / $off))") | $wait_fast | $(printf '%.2f' "$off10") | \
$(printf '%.2f' "$on10") | $(python3 -c "print('%.2f' % ($on10 / $off10))") | $wait10 |"$'\n'
done
echo "pose-accuracy: p99 medians done" >&2

# Online repair after a closure: the default world driven there and back
# (its only loops), a full online run with the shipped config.
ret="$work/default-return"
"$bin/indoor-sim" --world config/worlds/default-return.json --seed 1 --no-cameras --quiet \
  --out "$ret" 2>/dev/null
"$bin/planar-mapper" --config config/default.ini --rawlog "$ret.rawlog" --no-textures \
  --out "$ret-on" -q
python3 scripts/pose_errors.py "$ret.poses.txt" "$ret-on/poses.txt" "$ret-on/summary.json" \
  > "$ret-on/errors.json"
repair_row=$(python3 - "$ret-on/summary.json" "$ret-on/errors.json" <<'EOP'
import json, sys
s = json.load(open(sys.argv[1]))
e = json.load(open(sys.argv[2]))
lc = s["poses"]["loop_closure"]
r = lc["online_repairs"]
ms = r["ms"]
fmt = lambda v: "-" if v is None else "%.1f" % v
print("| %d | %d | %d | %d | %s / %s / %s | %.1f | %.3f |" % (
    lc["accepted"], r["count"], r["scans_moved"], r["points_moved"], fmt(ms["p50"]),
    fmt(ms["p99"]), fmt(ms["max"]), r["ms_total"], e["ate_m"]))
EOP
)
echo "pose-accuracy: default-return done" >&2

cat > doc/pose-accuracy.md <<EOM
# Pose accuracy on simulated runs

Generated by \`scripts/pose-accuracy.sh\` on $(date -u +%Y-%m-%d), commit
$(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(nproc) cores. The real-data
half (the Radish ACES log, relation errors, MRPT's icp-slam) is
[loop-closure.md](loop-closure.md).

Poses: the shipped \`config/default.ini\` (MRPT's CMetricMapBuilderICP with
\`config/icp.ini\`, fed odometry and the horizontal laser, and the pose
graph with loop closure, refined keyframe edges and refined scans behind
it: "+ pose graph"), the same with \`[Poses] keyframe_refinement = false\` ("unrefined
edges": the front end's relative poses between keyframes, as before the
refinement; poses only), and with \`[Poses] loop_closure = false\` ("ICP",
"off": no pose graph at all); odometry alone:
\`[Sensors] pose_laser = none\`. The simulator's odometry drifts 2 % in
distance and 1 deg/m in heading; range noise sigma 2 cm. default, second and
office are full runs (\`--no-textures\`), loop and aliasing \`--poses-only\`.

- ATE: RMS position error after the best rigid 2D alignment
  (\`scripts/pose_errors.py\`, the same as map-eval's \`pose_ate_m\`); max: the
  largest error after that alignment.
- loops: loop closures accepted, and in brackets the largest distance between
  an accepted closure's match and the true relative pose of its keyframes (a
  false loop would be metres).
- on surface: share of mapped vertical-laser points within 3 sigma of the
  ground-truth surface their beam hit (map-eval's label check).
- map error: map-eval's planar map mean error, ground truth to map (mm).
- pose p99: the pose stage's 99th percentile wall time per pose-laser scan
  (ms, one run on a shared machine: compare the two in a row, not across rows).

| world | seed | odometry ATE (m) | ICP ATE (m) | + pose graph, unrefined edges ATE (m) | + pose graph ATE (m) | max (m) off / on | loops | on surface off / on | map error (mm) off / on | pose p99 (ms) off / on |
|---|---|---|---|---|---|---|---|---|---|---|
${rows}
Issue 15's targets: ATE <= 0.03 m on second, office, loop and aliasing; the
planar map's mean error <= 10 mm on default, second and office; on the loop-free
default world, loop closure must not cost more than 5 mm of ATE.

The "unrefined edges" column is an ablation, not a shipped setting: its
keyframe edges are the front end's relative poses with generic sigmas (5 % of
the distance, 0.5 deg plus 5 % of the turn per edge, about 1 deg per metre of
heading random walk), and no odometry calibration. A loop is kept when the
graph's own uncertainty admits it (poses.md, "Which loops are kept"): with
that loose chain the twin corridors' false loops (6 m, and up to 14 m off)
are admitted, hence metres of ATE on the loop and aliasing worlds; the
refined edges' information comes from the matches and the calibrated
odometry, and no false loop is admitted (the "loops" column: the worst
accepted loop's distance from the truth).

## Pose stage p99 per scan

Issue 15 asks that the front end's p99 per scan stay within 20 % of what it
was without the pose graph. The pose stage's 99th percentile wall time per
pose-laser scan (ms; summary.json \`pose_per_scan_ms\`), \`--poses-only\`,
\`config/default.ini\` with \`[Poses] loop_closure\` false / true, the two
alternating on the same shared machine. "on" includes everything the pose
graph adds to the front end's thread (the keyframe and scan refinements,
applying a job's result: the nodes a kept loop moved, the trajectory's
rewrite and the front end map's rebuild; waiting for a job that is not
done). A job, on the worker thread, is one keyframe's loop search and, when
it finds a loop, the graph solve that tests it (on the front end's thread
until 4bc521a). Two ways of feeding the log:

- as fast as the machine goes (the median of 5 runs each): the loop searches
  run on one worker thread and each is applied one keyframe after its own
  (\`loop_search_latency_keyframes\` 1); when the jobs take more CPU than
  the front end leaves between keyframes, the front end waits for them
  ("wait": seconds in all, in the last run);
- at 10 times the log's pace (\`--playback-rate 10\`, the median of 3 runs
  each): what a robot driving 10 times as fast would see; the same poses to
  the bit (the result does not depend on the threads' speed), and the worker
  keeps up.

| world | seed | fast: p99 off (ms) | p99 on (ms) | on / off | wait (s) | 10x pace: p99 off (ms) | p99 on (ms) | on / off | wait (s) |
|---|---|---|---|---|---|---|---|---|---|
${p99_rows}
## Planes correct poses (offline, optional)

\`[Poses] plane_refinement = true\` (poses.md, "Planes correct poses"; off in
the shipped configs): after the offline EM, one Ceres problem moves the
trajectory (an SE(2) correction every metre of path) and the vertical planes
together, so that each structure scan's points lie on the surfaces the EM
gave them, held by relative-motion priors along the path and a prior on each
correction; then the scans and poses are moved and the offline EM runs again.
The same logs as above, \`--mode offline --no-textures\` with
\`config/default.ini\`, without / with it. Problem: knots / vertical surfaces
/ point residuals; max correction: the largest knot shift (m) / turn (deg);
fit: the Ceres solve (s); run: planar-mapper's whole run (s, one run each on a
shared machine).

| world | seed | ATE (m) off / on | max (m) off / on | map error (mm) off / on | problem | max correction | fit (s) | run (s) off / on |
|---|---|---|---|---|---|---|---|---|
${plane_rows}
## Online repair after a closure

\`config/worlds/default-return.json\` (the default world driven there and back,
seed 1), one online run with \`config/default.ini\` (\`--no-textures\`). Each
accepted closure that moves past poses triggers a repair: every structure scan
placed so far is compared with its corrected pose, the moved ones are re-placed
in the point map and moved in the online EM, and the surfaces that hold them are
refitted (poses.md, "The map follows"). Times: wall time of each repair on the
mapping thread (one run on a shared machine).

| loops accepted | repairs | scans moved | points moved | ms per repair p50 / p99 / max | ms in all | ATE (m) |
|---|---|---|---|---|---|---|
${repair_row}
EOM
echo "wrote doc/pose-accuracy.md"
