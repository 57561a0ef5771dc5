#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (-DPMAP_FUZZ=ON: fuzzer + ASan +
# UBSan) in ./build-fuzz (or $FUZZ_BUILD_DIR, e.g. build-asan after
# scripts/sanitize-tests.sh) and runs each one for
# $FUZZ_SECONDS seconds (default 60) from its committed corpus
# (tests/fuzz/corpus/<target>, read only; new inputs go to
# build-fuzz/corpus/<target>), with a memory cap. Prints the executions per
# target. A crash, leak, timeout or out-of-memory writes its reproducer to
# build-fuzz/crashes/<target>/ and fails the script: copy it to
# tests/fuzz/crashes/<target>/ with the fix, the ordinary build replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${FUZZ_BUILD_DIR:-build-fuzz}"
seconds="${FUZZ_SECONDS:-60}"
targets=(rawlog_reader ini_loader plane_fit)

# A tree of scripts/sanitize-tests.sh (FUZZ_BUILD_DIR=build-asan) is reused
# as it is: it was configured with PMAP_FUZZ=ON and the same compiler and
# flags, and has the fuzz targets built.
if ! grep -qs '^PMAP_FUZZ:BOOL=ON' "$build_dir/CMakeCache.txt"; then
  cmake -S . -B "$build_dir" -DCMAKE_CXX_COMPILER=clang++ -DPMAP_FUZZ=ON -DPMAP_BUILD_TESTS=OFF \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1"
fi
cmake --build "$build_dir" -j"${JOBS:-$(nproc)}" --target "${targets[@]/#/fuzz_}"

# As in scripts/sanitize-tests.sh: a huge malloc fails (OpenCV then throws
# for a corrupted image size) instead of being reported. Memory use itself is
# capped by -rss_limit_mb; single mallocs are not (-malloc_limit_mb would
# flag OpenCV's failed attempts), our own allocation guard caps C++ ones.
export ASAN_OPTIONS="allocator_may_return_null=1:abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"

status=0
summary=()
for t in "${targets[@]}"; do
  work="$build_dir/corpus/$t"
  crashes="$build_dir/crashes/$t"
  mkdir -p "$work" "$crashes"
  log="$build_dir/fuzz-$t.log"
  rc=0
  "$build_dir/fuzz/fuzz_$t" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=1000000 \
    -timeout=20 -max_len=65536 -print_final_stats=1 -artifact_prefix="$crashes/" \
    "$work" "tests/fuzz/corpus/$t" > "$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  line="fuzz_$t: ${execs:-?} executions in ${seconds} s (${rate:-?}/s), exit $rc"
  if [ "$rc" -ne 0 ]; then
    line+=" -- FINDING, reproducer in $crashes (log: $log)"
    tail -n 40 "$log" >&2
    status=1
  fi
  summary+=("$line")
done
printf '%s\n' "${summary[@]}"
exit "$status"
