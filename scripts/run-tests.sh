#!/usr/bin/env bash
# Builds and runs every test with CTest. The last line printed is CTest's
# summary line ("N% tests passed, M tests failed out of K"); the exit status
# is CTest's.
set -uo pipefail
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build}"
scripts/build.sh || exit 1
log="$build_dir/ctest-last.log"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
summary=$(grep -E '^[0-9]+% tests passed' "$log" | tail -n 1)
echo
echo "${summary:-CTest printed no summary (status $status)}"
exit "$status"
