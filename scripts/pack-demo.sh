#!/usr/bin/env bash
# Newcomer command 1: install what is missing, build `frontpack`, pack the default scene.
# Outputs go to out/ (VTU, YADE, LAMMPS, CSV, JSON) and a summary is printed.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFRONTPACK_BUILD_TESTS=OFF -DFRONTPACK_BUILD_BENCH=OFF >/dev/null
cmake --build build --target frontpack -j"$(nproc)"
mkdir -p out
build/cli/frontpack pack scenes/demo.yaml --record out/demo.record.json "$@"
