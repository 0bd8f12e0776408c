#!/usr/bin/env bash
# libFuzzer (clang) with ASan and UBSan over the fuzz harnesses of tests/fuzz, in build-fuzz.
#   scripts/fuzz.sh [SECONDS_PER_TARGET]      (default 60)
# First replays each target's seed corpus and regressions, then fuzzes it for the given time from
# a copy of its seed corpus (build-fuzz/corpus/<target>, which keeps growing across runs) with its
# dictionary. A finding stops the script with a non-zero status; its input is in
# build-fuzz/findings/<target>/ and is replayed by: build-fuzz/tests/fuzz/fuzz_<target> FILE
# (or, without clang, by the ctest build's: build-test/tests/fuzz/fuzz_<target> --replay FILE).
# JOBS (default 1: the reference machine has 2 cores, shared) sets the build's parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
seconds=${1:-60}
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "usage: scripts/fuzz.sh [SECONDS_PER_TARGET]" >&2; exit 2; }

scripts/install-deps.sh --fuzz  # the libraries frontpack builds with, clang 16 and its runtime

targets=(scene mesh packing)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-16 \
  -DFRONTPACK_FUZZ=ON -DFRONTPACK_BUILD_TESTS=OFF -DFRONTPACK_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"${JOBS:-1}" --target "${targets[@]/#/fuzz_}"

# Any sanitizer report is a finding (libFuzzer then saves the input).
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:print_summary=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$root/tests/fuzz/ubsan.supp"
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0"
for t in "${targets[@]}"; do
  binary=build-fuzz/tests/fuzz/fuzz_$t
  corpus=build-fuzz/corpus/$t
  findings=build-fuzz/findings/$t
  mkdir -p "$corpus" "$findings"
  cp -n tests/fuzz/corpus/$t/* "$corpus"/
  replay=(tests/fuzz/corpus/$t)
  [[ -d tests/fuzz/regressions/$t ]] && replay+=(tests/fuzz/regressions/$t)
  echo "== fuzz_$t: replaying ${replay[*]}"
  "$binary" -runs=0 -timeout=10 -artifact_prefix="$findings/" "${replay[@]}" >build-fuzz/replay-$t.log 2>&1 || {
    tail -30 build-fuzz/replay-$t.log; echo "fuzz_$t: a seed or a regression fails (log: build-fuzz/replay-$t.log)" >&2; exit 1; }
  echo "== fuzz_$t: fuzzing for $seconds s (log: build-fuzz/fuzz-$t.log)"
  # Inputs of at most 64 KiB, 10 s each; one allocation beyond 256 MiB is a finding, as in
  # tests/fuzz/mutation_driver.cpp.
  if ! "$binary" -max_total_time="$seconds" -max_len=65536 -timeout=10 -malloc_limit_mb=256 -rss_limit_mb=2048 \
      -dict=tests/fuzz/dict/$t.dict -artifact_prefix="$findings/" -print_final_stats=1 "$corpus" \
      >build-fuzz/fuzz-$t.log 2>&1; then
    tail -40 build-fuzz/fuzz-$t.log
    echo "fuzz_$t: FINDING, input saved in $findings/ (replay: $binary $findings/<file>)" >&2
    exit 1
  fi
  grep -E "^#[0-9]+[[:space:]]+(INITED|DONE)|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb" build-fuzz/fuzz-$t.log || true
done
echo "no finding in ${#targets[@]} targets x $seconds s"
