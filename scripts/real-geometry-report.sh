#!/usr/bin/env bash
# Regenerates doc/real-geometry.md and doc/images/real-*.png: planar-mapper on
# MRPT's real 3D data (Debian mrpt-common) in the default mode with the
# shipped configs: the Kinect frame (tests_rgbd.rawlog, config/mrpt-rgbd.ini)
# and the VLP-16 sweep (test_velodyne_VLP16.rawlog, config/mrpt-velodyne.ini).
# EM times: median of RUNS runs on one thread, coarse to fine and on all
# points alternating (the ratio is measured in the same run).
# Usage: scripts/real-geometry-report.sh [BUILD_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/report-lib.sh
bin="${1:-build}/bin"
runs="${2:-5}"
data=/usr/share/mrpt/datasets
kinect="$data/tests_rgbd.rawlog"
vlp="$data/test_velodyne_VLP16.rawlog"

# The same config with every point in every iteration (coarse_points = 0).
sed -e 's/^coarse_points = [0-9]*/coarse_points = 0/' -e "s#^@include icp.ini#@include $PWD/config/icp.ini#" \
  config/mrpt-rgbd.ini > "$work/rgbd-all.ini"

coarse_t=()
all_t=()
for r in $(seq "$runs"); do
  "$bin/planar-mapper" --config config/mrpt-rgbd.ini --rawlog "$kinect" --out "$work/k$r" -q \
    2>/dev/null
  coarse_t+=("$(json "$work/k$r/summary.json" "'%.2f' % d['timing_s']['em']")")
  "$bin/planar-mapper" --config "$work/rgbd-all.ini" --rawlog "$kinect" --out "$work/a$r" -q \
    2>/dev/null
  all_t+=("$(json "$work/a$r/summary.json" "'%.2f' % d['timing_s']['em']")")
  echo "real-geometry: Kinect run $r of $runs" >&2
done
k="$work/k1/summary.json"
a="$work/a1/summary.json"
# The same points as an unorganised cloud (--cloud): nearest neighbours
# instead of pixel neighbours (one run).
"$bin/planar-mapper" --config config/mrpt-rgbd.ini --cloud "$work/k1/points.ply" --out "$work/c" -q \
  2>/dev/null
c="$work/c/summary.json"

# The wall (largest surface), surfaces at its place, the nearest large
# camera-facing surface (the bookshelf's front).
wall_facts() {  # DIR
  python3 - "$1/surfaces.csv" <<'PY'
import csv, math, sys
rows = [dict((k, float(v)) for k, v in r.items()) for r in csv.DictReader(open(sys.argv[1]))]
wall = max(rows, key=lambda r: r["support"])
n = (wall["nx"], wall["ny"], wall["nz"])
copies = [r for r in rows if r is not wall
          and abs(r["nx"] * n[0] + r["ny"] * n[1] + r["nz"] * n[2]) > math.cos(math.radians(10))
          and abs(abs(r["offset"]) - abs(wall["offset"])) < 0.1]
print("%d points, %.2f m away, normal (%.2f, %.2f, %.2f); other surfaces within 10 deg and 10 cm "
      "of it: %d" % (wall["support"], abs(wall["offset"]), n[0], n[1], n[2], len(copies)))
PY
}

surface_table() {  # DIR
  python3 - "$1/surfaces.csv" <<'PY'
import csv, sys
for r in sorted(csv.DictReader(open(sys.argv[1])), key=lambda r: -int(r["support"])):
    print("| %s | (%.2f, %.2f, %.2f) | %.3f | %s |" % (r["id"], float(r["nx"]), float(r["ny"]),
          float(r["nz"]), abs(float(r["offset"])), r["support"]))
PY
}

"$bin/planar-mapper" --config config/mrpt-velodyne.ini --rawlog "$vlp" --out "$work/v" -q 2>/dev/null
v="$work/v/summary.json"
vlp_facts=$(python3 - "$work/v/surfaces.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
flat = [r for r in rows if abs(float(r["nz"])) > math.cos(math.radians(10))]
walls = [r for r in rows if abs(float(r["nz"])) < math.sin(math.radians(10))]
big = lambda rs: sorted(rs, key=lambda r: -int(r["support"]))
g = big(flat)
w = big(walls)
print("%d horizontal surfaces (the largest: %s points, %.2f m below the sensor; the others %s), "
      "%d vertical ones (the largest: %s points, %.1f m from the sensor)" % (
      len(flat), g[0]["support"] if g else "-", abs(float(g[0]["offset"])) if g else 0,
      ", ".join("%s points at %.2f m" % (r["support"], abs(float(r["offset"]))) for r in g[1:5]) or "none",
      len(walls), w[0]["support"] if w else "-", abs(float(w[0]["offset"])) if w else 0))
PY
)

# The cluttered simulated worlds (config/worlds/cluttered.json and
# glass-office.json, written by scripts/make-cluttered-world.py) at 2 and 5 cm
# range noise, with true and ICP poses, the shipped configs (default.ini,
# sigma5.ini), online.
: > "$work/cluttered.txt"
for w in cluttered glass-office; do
  for s in 0.02 0.05; do
    sim_cases "$bin" "$w" "$s" "$work/cluttered.txt" --no-textures
  done
done
# The per-scan times again (TIMING_RUNS runs in all, the map itself is the
# same every time): the table quotes the median p99 and decile ratio.
timing_runs="${TIMING_RUNS:-3}"
while read -r w s poses ini out; do
  extra=()
  [ "$poses" = true ] && extra=(--poses "$work/$w-$s.poses.txt")
  for r in $(seq 2 "$timing_runs"); do
    "$bin/planar-mapper" --rawlog "$work/$w-$s.rawlog" "${extra[@]}" --config "$ini" \
      --out "$out-t$r" -q --no-textures
  done
  echo "real-geometry: $w sigma $s $poses poses timed $timing_runs times" >&2
done < "$work/cluttered.txt"
cluttered_table=$(python3 - "$work/cluttered.txt" "$timing_runs" <<'PY'
import json, os, statistics, sys
print("| world | σ (cm) | poses | explained | ratio counting polygons | surfaces | fine triangles "
      "| walls matched / eligible | all matched / eligible | walls mapped twice > 3σ apart "
      "| clutter and people kept off surfaces | points no plane explains "
      "| rectangles' points on a surface | EM p99 per scan (ms) "
      "| last tenth ÷ second (EM median) | pose ATE (m) |")
print("|" + "---|" * 16)
for line in open(sys.argv[1]):
    world, s, poses, _, d = line.split()
    sm = json.load(open(os.path.join(d, "summary.json")))
    e = json.load(open(os.path.join(d, "eval.json")))
    sigma = float(s)
    kinds = e["matched_by_kind"]
    walls = [k for k in kinds if k in ("wall", "room_wall")]
    wm = sum(kinds[k]["matched"] for k in walls)
    wg = sum(kinds[k]["gt"] for k in walls)
    twice = [p for p in e["per_surface"] if p["kind"] in ("wall", "room_wall")
             and p.get("matching_spread_m", 0) > 3 * sigma]
    timed = [json.load(open(os.path.join(t, "summary.json")))
             for t in [d] + ["%s-t%d" % (d, r) for r in range(2, int(sys.argv[2]) + 1)]]
    p99 = statistics.median(t["em_per_scan_ms"]["p99"] for t in timed)
    tenth = statistics.median(t["em_per_scan_ms_by_decile"][9] / t["em_per_scan_ms_by_decile"][1]
                              for t in timed)
    ratio = (sm["raw_triangles"] / 2) / max(1, sm["surfaces"] + sm["fine_triangles"])
    kept = e.get("clutter_rejected_fraction")
    truth = e["points_by_truth"]
    total = sum(t["points"] for t in truth.values())
    beyond = sum(truth[k]["points"] for k in ("cylinder", "person", "no_object") if k in truth)
    rect = truth.get("rectangle", {"points": 0, "on_map_surface": 0})
    print("| %s | %.0f | %s | %.1f %% | 1:%.0f | %d | %d | %d / %d | %d / %d | %d%s | %s | %.1f %% | %.1f %% | %.2f | %.2f | %.3f |" % (
        world, 100 * sigma, "true" if poses == "true" else "ICP", 100 * sm["explained_fraction"], ratio,
        sm["surfaces"], sm["fine_triangles"], wm, wg, e["matched_surfaces"], e["gt_surfaces"],
        len(twice), (" (" + ", ".join("%.2f m" % p["matching_spread_m"] for p in twice) + ")") if twice else "",
        "%.1f %%" % (100 * kept) if kept is not None else "-", 100 * beyond / max(1, total),
        100 * rect["on_map_surface"] / max(1, rect["points"]), p99, tenth,
        e["pose_ate_m"] if e.get("pose_ate_m") is not None else float("nan")))
PY
)

if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 scripts/plot_surfaces.py "$work/k1/points.ply" doc/images/real-rgbd-surfaces.png \
    "tests_rgbd.rawlog, default mode: $(json "$k" "d['surfaces']") surfaces, colour = surface, black = outlier class"
  /usr/bin/python3 scripts/plot_surfaces.py "$work/v/points.ply" doc/images/real-vlp16-surfaces.png \
    "test_velodyne_VLP16.rawlog: $(json "$v" "d['surfaces']") surfaces, colour = surface, black = outlier class (within 30 m)" 30
fi

cat > doc/real-geometry.md <<EOM
# Real geometry: MRPT's Kinect frame and VLP-16 sweep

Generated by \`scripts/real-geometry-report.sh\` on $(date -u +%Y-%m-%d), commit
$(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(nproc) cores (shared machine; the EM on one thread).
Both inputs come with Debian's \`mrpt-common\` (\`/usr/share/mrpt/datasets\`);
both are single frames at the identity pose, run in the default mode with
the shipped configs and no other flag:

    planar-mapper --config config/mrpt-rgbd.ini --rawlog $kinect
    planar-mapper --config config/mrpt-velodyne.ini --rawlog $vlp

A range image (and an unorganised cloud) has no scan-line order for the
online EM: the default mode maps it with the offline EM and says so
(summary.json \`mode\`: $(json "$k" "d['mode']"), \`mode_note\`: "$(json "$k" "d.get('mode_note', '')")").

## Kinect frame (tests_rgbd.rawlog, config/mrpt-rgbd.ini)
A bookshelf in front of a wall, 1.8-2.6 m away: $(json "$k" "d['points']") points of 640 x 480 pixels.
The EM runs coarse to fine (\`coarse_points = 20000\`, doc/em.md): model
selection on a uniform sample of 20,000 points, then 5 E/M steps and the
removal test on all points.

| | coarse to fine (shipped) | every point, every iteration (\`coarse_points = 0\`) |
|---|---|---|
| EM time, median of ${runs} (s) | $(median "${coarse_t[@]}") | $(median "${all_t[@]}") |
| all runs (s) | ${coarse_t[*]} | ${all_t[*]} |
| explained | $(json "$k" "'%.1f %%' % (100 * d['explained_fraction'])") | $(json "$a" "'%.1f %%' % (100 * d['explained_fraction'])") |
| surfaces | $(json "$k" "d['surfaces']") | $(json "$a" "d['surfaces']") |
| fine triangles | $(json "$k" "d['fine_triangles']") | $(json "$a" "d['fine_triangles']") |
| EM | $(json "$k" "d['em_message']") | $(json "$a" "d['em_message']") |
| the wall | $(wall_facts "$work/k1") | $(wall_facts "$work/a1") |

The same points as an unorganised cloud (\`--cloud\` with the frame's
points.ply, the same config; one run): \`timing_s.em\` $(json "$c" "'%.2f' % d['timing_s']['em']") s including
the nearest-neighbour graph (which looks within an eighth of
\`cloud_neighbour_radius_m\` first: 21 s before, hundreds of points lie within
the 10 cm radius), $(json "$c" "'%.1f %%' % (100 * d['explained_fraction'])") explained, $(json "$c" "d['surfaces']") surfaces.

What made the wall one surface and the frame ≥ 95 % explained (both
described with their reasons in doc/em.md):
- **The disparity staircase and the depth distortion.** The wall's 136,000
  points take only 49 distinct depths between 1.87 and 2.54 m (steps of 10
  to 19 mm, growing as depth squared), and the wall bends by ±3 cm towards
  the image corners (the Kinect's depth distortion; residuals of one plane
  fitted to the wall, in 40 x 40 pixel blocks: from -33 mm at the corners to
  +40 mm in the centre). Two interleaved planes 1.3 cm and 1.4° apart
  explain that by over 7,000 nats better than one, at σ 2, 3, 4 or 5 cm
  alike (all tried), so before this change the wall came out as two
  surfaces interleaved in diagonal stripes (commit 8abfaa9: 14 surfaces,
  95.7 % explained, 20 s). Now two surfaces that occupy the same place
  (overlapping by more than a quarter of the smaller, planes within the
  split test's 4 cm over the overlap) are one surface: surfaces are opaque.
- **Shallow bends are not curves on this sensor.** A side wall seen at a
  grazing angle "bent" with a radius under 1 m but only 1-2.5 cm deep; the
  curvature test removed it with its 11,764 points and barred them from
  seeding (explained 98.8 → 94.7 %). \`min_curvature_depth_m = 0.04\` in
  config/mrpt-rgbd.ini; the default stays 0 (any depth), because on the
  simulated worlds at σ 5 cm a bin's strips are only 6.7-13 cm deep.

![tests_rgbd surfaces](images/real-rgbd-surfaces.png)

| id | normal | distance (m) | points |
|---|---|---|---|
$(surface_table "$work/k1")

## VLP-16 sweep (test_velodyne_VLP16.rawlog, config/mrpt-velodyne.ini)
Outdoors (a road, trees, a building), ranges to 100 m: $(json "$v" "d['points']") returns in a grid of
$(json "$v" "d['measurements']") cells (16 rings by the sweep's azimuth steps, doc/input.md); EM
$(json "$v" "'%.2f' % d['timing_s']['em']") s, $(json "$v" "d['em_message']").

- $(json "$v" "d['surfaces']") surfaces explaining $(json "$v" "'%.1f' % (100 * d['explained_fraction'])") % of the returns: ${vlp_facts}.
- The ground is not one plane: the road and its verges lie at different
  heights (the horizontal surfaces above), each ring's arc on them a few
  centimetres off its neighbours'; the trees are most of the unexplained
  returns (fine triangles: $(json "$v" "d['fine_triangles']")).
- Before this change the sweep was an unorganised cloud whose 4 nearest
  neighbours all lie on one ring (rings 2° apart, 35 cm at 10 m; returns
  0.2-0.4° apart), so seeding's three adjacent points were nearly collinear,
  and config/mrpt-rgbd.ini (the only config shipped for it then, set for the
  Kinect: outlier range 5 m) found 0 surfaces.

![VLP-16 surfaces](images/real-vlp16-surfaces.png)

| id | normal | distance (m) | points |
|---|---|---|---|
$(surface_table "$work/v")

## Two cluttered simulated worlds
Both written by \`scripts/make-cluttered-world.py\`.
\`config/worlds/cluttered.json\`: an L-shaped office corridor (legs 20 m and 16.5 m, 2.4 m wide, 2.8 m high)
turned 23° off the axes, with a slanted end wall 30° off square, three rooms
with desks, shelves and a cabinet seen through open doorways, five doors,
furniture along the walls (a radiator, a column, bins, cabinets, a shelf, a
pillar) and ceiling clutter (nine lamps, a duct, a beam across the corridor,
a pipe); the lasers have the errors of real sensors (doc/simulator.md,
\`noise\`: range noise growing by 2 mm per metre and with the incidence, no
return beyond 85° from the normal, 2 % lost returns, 0.5 % spurious ones,
mixed returns at half of the depth edges).
\`config/worlds/glass-office.json\`: a U-shaped corridor (legs 16, 9 and
15 m, 2.2 m wide, 2.6 m high) turned −37° off the axes, with two meeting
rooms behind glass fronts 4 m and 3 m wide (a beam goes through the glass
and returns from the room behind it, 30 % of those are lost, unless it meets
the pane within 10° of its normal and returns from the pane), two people
walking to and fro along the corridor at 1.1 and 1.3 m/s, two doors,
furniture (a radiator, cabinets, bins, shelves, a bench, a column), ceiling
clutter (ten lamps, a beam across, a duct, a pipe), a slanted end wall 20°
off square and the same laser errors (doc/simulator.md, "Glass" and
"People"). \`indoor-sim --seed 1 --sigma S
--no-cameras\`, then \`planar-mapper\` online (the default mode) with
\`config/default.ini\` (σ 2 cm) or \`config/sigma5.ini\` (σ 5 cm),
\`--no-textures\`, with the true poses (\`--poses\`) or the ICP front end's,
and \`map-eval --gt\`. "Walls mapped twice": matched walls whose matching map
surfaces lie more than 3σ apart (map-eval's \`matching_spread_m\`); "last
tenth ÷ second": summary.json's \`em_per_scan_ms_by_decile\`, the median EM
time per scan in the last tenth of the run over the second tenth (this
column and the EM p99: the median of ${timing_runs} runs of the same map); "clutter
and people kept off surfaces": map-eval's \`clutter_rejected_fraction\`, the
share of the points on clutter and people that no map surface holds; "points
no plane explains": map-eval's \`points_by_truth\`, the share of the mapped
points whose true ray hit a cylinder (bins, columns), a person or nothing
(spurious and mixed returns), so that explained can reach at most 100 %
minus that (boxes have flat faces a surface may hold); "rectangles' points on
a surface": the share of the points on the world's rectangles that a map
surface holds. Walls
are the kinds wall and room_wall (glass panes are their own kind, counted in
"all"). One map per case; shared machine.

${cluttered_table}

Issue 16 asks, on such worlds: explained ≥ 95 %, ratio counting polygons
≥ 1:200, walls matched ≥ 95 % of eligible, no wall mapped twice more than
3σ apart, EM p99 per scan ≤ 2 ms, last tenth ÷ second ≤ 1.2.

## Not measured here (issue 16)
The peer benchmark (PCL, CGAL) is doc/peer-benchmark.md
(\`scripts/peer-benchmark.sh\`). The cost of cloud mode against the
number of points (0.25M to 5M) is in doc/cloud-scaling.md
(\`scripts/cloud-scaling-report.sh\`), with spatial blocks (doc/em.md). The voxel
mode (geb079) and \`sigma_m = auto\` are in doc/simulator.md and doc/em.md.
EOM
echo "wrote doc/real-geometry.md"
