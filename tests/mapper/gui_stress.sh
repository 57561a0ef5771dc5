#!/usr/bin/env bash
# planar-mapper --gui, RUNS times in a row on a loaded machine: one CPU hog
# per core runs beside it. Fails if any run does not exit 0 (a crash, a
# hang past 120 s or an error); prints the log of each failed run.
# Needs an X display (DISPLAY; CTest runs it under xvfb-run).
# Usage: gui_stress.sh PLANAR_MAPPER OUT_DIR [RUNS] [-- PLANAR_MAPPER_ARGS...]
#   default args: --to-index 40 --gui-hold 0 -q
set -u
if [ $# -lt 2 ]; then
  echo "usage: $0 PLANAR_MAPPER OUT_DIR [RUNS] [-- ARGS...]" >&2
  exit 2
fi
mapper=$1
out=$2
runs=${3:-20}
shift $(($# < 3 ? $# : 3))
[ "${1:-}" = "--" ] && shift
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(--to-index 40 --gui-hold 0 -q)
if [ -z "${DISPLAY:-}" ]; then
  echo "gui_stress: DISPLAY is not set (run under xvfb-run)" >&2
  exit 2
fi

# The hogs spin only while this script lives, so they end even if it is
# killed (SIGKILL included); the trap ends them at once on a normal exit.
hogs=()
stop_hogs() {
  for pid in "${hogs[@]}"; do
    kill "$pid" 2>/dev/null
  done
  wait "${hogs[@]}" 2>/dev/null
}
trap stop_hogs EXIT
trap 'exit 130' INT TERM
script_pid=$$
for _ in $(seq "$(nproc)"); do
  (while kill -0 "$script_pid" 2>/dev/null; do :; done) &
  hogs+=($!)
done

mkdir -p "$out"
failed=0
for i in $(seq "$runs"); do
  log="$out/run$i.log"
  rm -rf "$out/run$i"
  timeout -k 10 120 "$mapper" --gui --out "$out/run$i" "${args[@]}" >"$log" 2>&1
  rc=$?
  if [ $rc -ne 0 ]; then
    failed=$((failed + 1))
    echo "gui_stress: run $i exited $rc; the end of its log:"
    if [ -s "$log" ]; then sed 's/^/  | /' "$log" | tail -n 20; else echo "  | (empty)"; fi
  fi
  rm -rf "$out/run$i"
done
echo "gui_stress: $((runs - failed)) of $runs runs exited 0 (with $(nproc) CPU hogs)"
[ $failed -eq 0 ]
