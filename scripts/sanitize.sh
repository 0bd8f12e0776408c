#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (g++), in build-asan.
#   scripts/sanitize.sh [CTEST ARGS...]      e.g. scripts/sanitize.sh -R test_io
# Any sanitizer report ends the process that made it with a non-zero status, so its test fails.
# JOBS (default 1: the reference machine has 2 cores, shared) sets the build's parallelism,
# CTEST_JOBS (default 1) ctest's. The first run took 2 h 14 min on the shared 2-core reference
# machine (build 1 h 44 min, ctest 30 min; experiments/robustness/RESULTS.md); later runs rebuild
# only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
scripts/install-deps.sh --test

flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# halt_on_error: the first report ends the process; detect_leaks: a leak is a report too.
# Exported before the build as well: gtest_discover_tests runs every test binary once.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:print_summary=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$root/tests/fuzz/ubsan.supp"
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0"

# The benchmarks are not tests (ctest never runs them): not built here.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" \
  -DFRONTPACK_BUILD_TESTS=ON -DFRONTPACK_BUILD_BENCH=OFF \
  -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DFRONTPACK_PYTHON_TEST_PRELOAD="$(g++ -print-file-name=libasan.so):$(g++ -print-file-name=libubsan.so)" \
  >/dev/null
cmake --build build-asan -j"${JOBS:-1}"
ctest --test-dir build-asan --output-on-failure -j"${CTEST_JOBS:-1}" "$@"
