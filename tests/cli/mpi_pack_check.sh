#!/bin/sh
# MPI end to end (built with FRONTPACK_MPI): `mpirun -np K frontpack pack` writes the bytes that
# `frontpack pack -j 2` writes (the same blocks), for K = 2 and 3, in 3D and 2D; rank 0 alone
# writes (its summary once); a scene of shapes and a bad scene fail on every rank, with the exit
# code of the failure and nothing written, and do not hang.
# Usage: mpi_pack_check.sh FRONTPACK MPIEXEC
set -eu
here=$(cd "$(dirname "$0")" && pwd)
fp=$1
mpi="$2 --allow-run-as-root --oversubscribe"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
. "$here/block_scenes.sh"
for s in s3 s2; do
  "$fp" pack $s.yaml -j 2 -q -o $s-threads.csv
  for k in 2 3; do
    timeout 300 $mpi -np $k "$fp" pack $s.yaml -o $s-np$k.csv > $s-np$k.out
    cmp $s-threads.csv $s-np$k.csv || { echo "FAIL: $s: mpirun -np $k differs from -j 2"; exit 1; }
    n=$(grep -c "^  validation     ok" $s-np$k.out)
    [ "$n" = 1 ] || { echo "FAIL: $s -np $k: $n summaries (rank 0 alone prints one)"; cat $s-np$k.out; exit 1; }
  done
done
cat > shapes.yaml <<'S'
dimension: 2
seed: 1
container: {type: rectangle, min: [0, 0], max: [20, 20]}
particles:
  - {shape: polygon, vertices: [[0, 0], [1, 0], [0.5, 0.8]], size: {distribution: uniform, min: 0.5, max: 1}}
S
set +e
timeout 120 $mpi -np 2 "$fp" pack shapes.yaml -o shapes.csv > shapes.out 2>&1
code=$?
set -e
[ $code -ne 0 ] && [ $code -ne 124 ] || { echo "FAIL: shapes under mpirun: exit $code"; cat shapes.out; exit 1; }
grep -q "spheres (disks) only" shapes.out || { echo "FAIL: no message for shapes under mpirun"; cat shapes.out; exit 1; }
[ ! -e shapes.csv ] || { echo "FAIL: shapes.csv written"; exit 1; }
printf 'dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n' > bad.yaml
set +e
timeout 120 $mpi -np 2 "$fp" pack bad.yaml -o bad.csv > bad.out 2>&1
code=$?
set -e
[ $code -eq 2 ] || { echo "FAIL: a bad scene under mpirun: exit $code (expected 2)"; cat bad.out; exit 1; }
[ ! -e bad.csv ] || { echo "FAIL: bad.csv written"; exit 1; }
echo "mpirun -np 2 and 3 match -j 2 (3D, 2D); shapes and bad scenes refused on every rank"
