#!/usr/bin/env bash
# Installs the Debian packages frontpack needs, only those missing (run as root).
#   scripts/install-deps.sh          what `frontpack pack` needs to build
#   scripts/install-deps.sh --test   plus GoogleTest, Google Benchmark and the Python modules the tests use
#   scripts/install-deps.sh --fuzz   plus clang 16 and its runtime (libFuzzer, sanitizers): Debian 12's
#                                    default clang (14) cannot build scene_yaml.cpp, whose lambdas
#                                    capture structured bindings (C++20, clang >= 16)
set -euo pipefail
packages=(build-essential cmake libeigen3-dev libcgal-dev libfcl-dev libccd-dev libnlopt-cxx-dev libnlopt-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev)
if [[ "${1:-}" == "--fuzz" ]]; then
  packages+=(clang-16 libclang-rt-16-dev)
fi
if [[ "${1:-}" == "--test" ]]; then
  # python3-vtk9: the VTU files are read back by VTK itself; numpy: independent cross-checks;
  # matplotlib: `frontpack analyze --plots`.
  # libopenmpi-dev, openmpi-bin: the test build has FRONTPACK_MPI on (mpirun -np 2 and 3 are tested).
  # lammps: the LAMMPS data files are read and run by LAMMPS itself (about 10 s to install).
  # yade: the YADE text files (spheres, clumps) are loaded and run by YADE itself (about 60 s).
  # liggghts: the same data files run in LIGGGHTS as the README writes it (about 50 s).
  # pybind11-dev, python3-pytest: the Python module frontpack and its tests (13 s to install).
  packages+=(libgtest-dev libgmock-dev libbenchmark-dev python3 python3-numpy python3-vtk9 python3-matplotlib pybind11-dev python3-pytest
             libopenmpi-dev openmpi-bin lammps yade liggghts)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; else SUDO=; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
