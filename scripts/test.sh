#!/usr/bin/env bash
# Newcomer command 2: install what is missing, build everything, run every test (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=Release -DFRONTPACK_BUILD_TESTS=ON -DFRONTPACK_BUILD_BENCH=ON \
  -DFRONTPACK_MPI=ON -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build-test -j"$(nproc)"
ctest --test-dir build-test --output-on-failure -j"$(nproc)" "$@"
