#!/bin/sh
# The real consumer of the LAMMPS data files: Debian's LAMMPS (`lmp`) reads what `frontpack pack`
# writes, 3D and 2D, from the single front, from threads and (with MPIEXEC, a FRONTPACK_MPI
# build) from `mpirun -np 2`, and runs granular steps without gravity: every atom stays in the
# box and nothing moves (largest displacement <= 1e-9 r_min: no overlap to push apart); the masses
# LAMMPS computes are the file's density (the scene's material) x 4/3 pi r^3; clusters run as
# rigid clumps (fix rigid/small molecule) as written. A copy
# with one diameter grown by 10 % must move (the check can fail). Exit 77 (skipped) without lmp.
# Usage: lammps_read_check.sh FRONTPACK [MPIEXEC]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
fp=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
mpi=${2:+"$2 --allow-run-as-root --oversubscribe"}
command -v lmp > /dev/null || { echo "SKIPPED: no lmp (Debian package lammps; scripts/install-deps.sh --test installs it)"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
. "$here/block_scenes.sh"

. "$here/readme_snippet.sh"
readme_snippet lammps-spheres > spheres.in
readme_snippet lammps-clumps > clumps.in

# lammps_input SNIPPET DATA DIM STEPS: the README's input for DATA with the changes it states for
# 2D, and a displacement compute before its run.
lammps_input() {
  awk -v data="$2" -v dim="$3" -v steps="$4" '
    /^read_data/ {print "read_data " data; next}
    /^boundary/ && dim == 2 {print "dimension 2"; print "boundary f f p"; next}
    /^fix +1 +all +nve\/sphere/ && dim == 2 {print "fix 1 all nve/sphere disc"; print "fix 2 all enforce2d"; next}
    /^fix +1 +all +rigid/ && dim == 2 {print; print "fix 2 all enforce2d"; next}
    /^run/ {print "compute d all displace/atom"; print "compute dmax all reduce max c_d[4]"
            print "thermo_style custom step atoms c_dmax"; print "thermo_modify format float %.6g lost error"
            print "thermo " steps; print "run " steps; next}
    {print}' "$1"
}

# run_lammps DATA DIM: prints "ATOMS_READ ATOMS_AFTER MAX_DISPLACEMENT"
run_lammps() {
  lammps_input spheres.in "$1" "$2" 100 > in.lmp
  lmp -in in.lmp -log none -echo none > lmp.out 2>&1 || { echo "FAIL: lmp could not run $1"; cat lmp.out; exit 1; }
  read=$(sed -n 's/^ *\([0-9]*\) atoms$/\1/p' lmp.out | head -1)
  last=$(awk '$1 == "100" && NF == 3 {print $2, $3}' lmp.out | tail -1)
  echo "$read $last"
}

check() {  # check DATA DIM R_MIN LABEL
  n=$(awk '/^Atoms/ {on = 1; next} on && NF >= 7 {c++} END {print c + 0}' "$1")
  set -- "$@" $(run_lammps "$1" "$2")
  [ "$5" = "$n" ] && [ "$6" = "$n" ] || { echo "FAIL: $4: $n atoms in the file, LAMMPS read $5 and kept $6"; exit 1; }
  awk -v d="$7" -v r="$3" 'BEGIN {exit !(d <= 1e-9 * r)}' || { echo "FAIL: $4: atoms moved by $7 (r_min $3)"; exit 1; }
  echo "$4: $n atoms read and kept, largest displacement $7"
}

for s in s3 s2; do
  dim=${s#s}
  rmin=$( [ $dim = 3 ] && echo 0.01 || echo 0.004 )
  grep -v '^packer:' $s.yaml > $s-front.yaml  # no block_edge: one front
  "$fp" pack $s-front.yaml -q -o $s-front.data
  check $s-front.data $dim $rmin "$s single front"
  "$fp" pack $s.yaml -j 2 -q -o $s-threads.data
  check $s-threads.data $dim $rmin "$s -j 2"
  if [ -n "$mpi" ]; then
    timeout 300 $mpi -np 2 "$fp" pack $s.yaml -q -o $s-np2.data
    check $s-np2.data $dim $rmin "$s mpirun -np 2"
  fi
done

# Masses: LAMMPS takes each atom's mass as density x 4/3 pi r^3 from the file (2D too: a disk's
# mass is a sphere's there); the total it reads must be the file's, and the density the scene's
# material (default 2650).
mass_check() {  # mass_check DATA DIM DENSITY
  if [ "$2" = 2 ]; then head='dimension 2
boundary f f p'; else head='boundary f f f'; fi
  cat > mass.lmp <<L
$head
atom_style sphere
read_data $1
compute m all property/atom mass
compute total all reduce sum c_m
thermo_style custom step c_total
thermo_modify format float %.15g norm no
run 0
L
  lmp -in mass.lmp -log none -echo none > mass.out 2>&1 || { echo "FAIL: lmp could not read $1"; cat mass.out; exit 1; }
  got=$(awk '$1 == "0" && NF == 2 {print $2}' mass.out | tail -1)
  awk -v got="$got" -v rho="$3" '/^Atoms/ {on = 1; next} on && NF >= 7 {
      if ($4 != rho) {print "FAIL: density " $4 " in the file, not " rho; bad = 1; exit 1}
      m += $4 * 4 / 3 * 3.141592653589793 * ($3 / 2) ^ 3 }
    END {if (bad) exit 1; rel = (got - m) / m; if (rel < 0) rel = -rel
         if (!(rel < 1e-12)) {print "FAIL: LAMMPS mass " got ", the file " m; exit 1}}' "$1" || exit 1
  echo "$1: LAMMPS mass $got = the file's density x volume (density $3)"
}
mass_check s3-front.data 3 2650
mass_check s2-front.data 2 2650
printf 'material: {density: 7850}\n' | cat s3-front.yaml - > steel.yaml
"$fp" pack steel.yaml -q -o steel.data
mass_check steel.data 3 7850

# Clumps (clusters of spheres): the data file gives each member its clump as molecule id, and
# the README's input (snippet lammps-clumps) runs them with fix rigid/small molecule as written: LAMMPS finds one rigid
# body per clump with every member, and 1,000 steps without gravity move nothing (no overlap).
clumps_check() {  # clumps_check DIM
  "$fp" pack clumps$1.yaml -q -o clumps$1.data || [ $? -eq 4 ]
  atoms=$(awk '/^Atoms/ {on = 1; next} on && NF >= 8 {c++} END {print c + 0}' clumps$1.data)
  clumps=$(awk '/^Atoms/ {on = 1; next} on && NF >= 8 && $8 > m {m = $8} END {print m + 0}' clumps$1.data)
  [ "$clumps" = 150 ] || { echo "FAIL: ${1}D clumps: $clumps clumps in the file, the scene asks 150"; exit 1; }
  lammps_input clumps.in clumps$1.data "$1" 1000 > clumps.lmp
  lmp -in clumps.lmp -log none -echo none > clumps.out 2>&1 || { echo "FAIL: lmp could not run clumps$1.data"; cat clumps.out; exit 1; }
  bodies=$(sed -n 's/^ *\([0-9]*\) rigid bodies with \([0-9]*\) atoms$/\1 \2/p' clumps.out | head -1)
  [ "$bodies" = "150 $atoms" ] || { echo "FAIL: ${1}D clumps: LAMMPS made '$bodies' (rigid bodies, atoms) of 150 clumps, $atoms atoms"; cat clumps.out; exit 1; }
  last=$(awk '$1 == "1000" && NF == 3 {print $2, $3}' clumps.out | tail -1)
  set -- "$1" $last
  [ "$2" = "$atoms" ] && awk -v d="$3" 'BEGIN {exit !(d <= 1e-9 * 0.2)}' ||
    { echo "FAIL: ${1}D clumps after 1,000 steps: '$last' (atoms, largest displacement)"; exit 1; }
  echo "${1}D clumps: 150 rigid bodies of $atoms atoms, 1,000 steps, largest displacement $3"
}
clumps_check 3
clumps_check 2

# The control: one sphere grown by 10 % overlaps its neighbours, and LAMMPS pushes them apart.
awk '/^Atoms/ {on = 1; print; next} on && NF >= 7 && !done {$3 = $3 * 1.1; done = 1} {print}' s3-front.data > grown.data
set -- $(run_lammps grown.data 3)
awk -v d="$3" 'BEGIN {exit !(d > 1e-9 * 0.01)}' || { echo "FAIL: an overlapping sphere did not move anything (displacement $3)"; exit 1; }
echo "control: a sphere grown by 10 % moved its neighbours by $3"
