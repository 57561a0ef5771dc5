# Helpers shared by the scripts that regenerate doc/ results (sourced).
# json FILE EXPR: prints the Python expression EXPR over the JSON document d.
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }
# median V...: the median of the numbers.
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
# A scratch directory, removed on exit: $work.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# sim_cases BIN WORLD SIGMA RUNS [planar-mapper options]: simulates
# config/worlds/WORLD.json at range noise SIGMA (m; seed 1, no cameras), maps
# it with its true poses and with the ICP front end's (config/default.ini,
# config/sigma5.ini at 0.05), scores each with map-eval, and appends a line
# "WORLD SIGMA POSES INI OUT" per case to RUNS (POSES: true or icp).
sim_cases() {
  local bin=$1 w=$2 s=$3 runs=$4
  shift 4
  local sim="$work/$w-$s" ini=config/default.ini poses out
  "$bin/indoor-sim" --world "config/worlds/$w.json" --seed 1 --sigma "$s" --no-cameras --quiet \
    --out "$sim" 2>/dev/null
  [ "$s" = 0.05 ] && ini=config/sigma5.ini
  for poses in true icp; do
    local extra=()
    [ "$poses" = true ] && extra=(--poses "$sim.poses.txt")
    out="$work/map-$w-$s-$poses"
    "$bin/planar-mapper" --rawlog "$sim.rawlog" "${extra[@]}" --config "$ini" --out "$out" -q "$@"
    "$bin/map-eval" --map "$out" --gt "$sim.gt.json" --out "$out/eval.json" -q
    echo "$w $s $poses $ini $out" >> "$runs"
    echo "$(basename "$0" .sh): $w sigma $s $poses poses done" >&2
  done
}
