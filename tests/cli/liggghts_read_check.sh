#!/bin/sh
# The real consumer of the LAMMPS data files in LIGGGHTS: Debian's LIGGGHTS (`liggghts`, 3.8)
# reads what `frontpack pack -o X.data` writes, 3D and 2D, with the README's input as written
# (atom_style granular; clumps as atom_style hybrid granular molecular with fix rigid molecule),
# and runs Hertz-Mindlin steps without gravity: every atom is kept and nothing moves (largest
# displacement <= 1e-9 r_min: no overlap to push apart), every clump is one rigid body with all
# its members. A copy with one diameter grown by 10 % must move (the check can fail).
# Exit 77 (skipped) without liggghts.
# Usage: liggghts_read_check.sh FRONTPACK
set -eu
here=$(cd "$(dirname "$0")" && pwd)
fp=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
command -v liggghts > /dev/null || { echo "SKIPPED: no liggghts (Debian package liggghts; scripts/install-deps.sh --test installs it)"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
. "$here/block_scenes.sh"

. "$here/readme_snippet.sh"
readme_snippet liggghts-spheres > snippet.in

# liggghts_input DATA DIM STYLE STEPS: the README's input for DATA with the changes it states for
# 2D and for clumps, and a displacement compute before its run.
liggghts_input() {
  awk -v data="$1" -v dim="$2" -v style="$3" -v steps="$4" '
    /^read_data/ {print "read_data " data; next}
    /^boundary/ && dim == 2 {print "dimension 2"; print "boundary f f p"; next}
    /^atom_style/ && style == "clumps" {print "atom_style hybrid granular molecular"; next}
    /^fix +move/ {print (style == "clumps" ? "fix move all rigid molecule" : $0); if (dim == 2) print "fix 2d all enforce2d"; next}
    /^run/ {print "compute d all displace/atom"; print "compute dmax all reduce max c_d[4]"
            print "thermo_style custom step atoms c_dmax"; print "thermo_modify lost error"; print "run " steps; next}
    {print}' snippet.in
}

# run_liggghts DATA DIM STYLE STEPS: prints "ATOMS_READ ATOMS_AFTER MAX_DISPLACEMENT [BODIES ATOMS_IN_BODIES]"
run_liggghts() {
  liggghts_input "$@" > in.liggghts
  liggghts -in in.liggghts -log none -echo none > liggghts.out 2>&1 || { echo "FAIL: liggghts could not run $1"; cat liggghts.out; exit 1; }
  if grep -q '^ERROR' liggghts.out; then echo "FAIL: liggghts stopped on $1"; cat liggghts.out; exit 1; fi
  read=$(sed -n 's/^ *\([0-9]*\) atoms$/\1/p' liggghts.out | head -1)
  last=$(awk -v s="$4" '$1 == s && NF == 3 {print $2, $3}' liggghts.out | tail -1)
  bodies=$(sed -n 's/^ *\([0-9]*\) rigid bodies with \([0-9]*\) atoms$/\1 \2/p' liggghts.out | head -1)
  echo "$read $last $bodies"
}

atoms_in() { awk '/^Atoms/ {on = 1; next} on && NF >= 7 {c++} END {print c + 0}' "$1"; }

check() {  # check DATA DIM R_MIN LABEL
  n=$(atoms_in "$1")
  set -- "$@" $(run_liggghts "$1" "$2" spheres 100)
  [ "$5" = "$n" ] && [ "$6" = "$n" ] || { echo "FAIL: $4: $n atoms in the file, LIGGGHTS read $5 and kept $6"; exit 1; }
  awk -v d="$7" -v r="$3" 'BEGIN {exit !(d <= 1e-9 * r)}' || { echo "FAIL: $4: atoms moved by $7 (r_min $3)"; exit 1; }
  echo "$4: $n atoms read and kept by LIGGGHTS, largest displacement $7"
}

grep -v '^packer:' s3.yaml > s3-front.yaml
"$fp" pack s3-front.yaml -q -o s3.data
check s3.data 3 0.01 "3D spheres"
"$fp" pack s2.yaml -q -o s2.data
check s2.data 2 0.004 "2D disks"

# Clumps: the clusters' data file as written, one rigid body per clump with every member.
clumps_check() {  # clumps_check DIM
  "$fp" pack clumps$1.yaml -q -o clumps$1.data || [ $? -eq 4 ]  # 4: the count stop leaves the box unfilled
  atoms=$(awk '/^Atoms/ {on = 1; next} on && NF >= 8 {c++} END {print c + 0}' clumps$1.data)
  set -- "$1" $(run_liggghts clumps$1.data "$1" clumps 1000)
  [ "$2 $3" = "$atoms $atoms" ] && [ "$5 $6" = "150 $atoms" ] ||
    { echo "FAIL: ${1}D clumps: LIGGGHTS read $2, kept $3 of $atoms atoms, made '$5 $6' (rigid bodies, atoms) of 150 clumps"; exit 1; }
  awk -v d="$4" 'BEGIN {exit !(d <= 1e-9 * 0.2)}' || { echo "FAIL: ${1}D clumps moved by $4 in 1,000 steps"; exit 1; }
  echo "${1}D clumps: 150 rigid bodies of $atoms atoms in LIGGGHTS, 1,000 steps, largest displacement $4"
}
clumps_check 3
clumps_check 2

# The control: one sphere grown by 10 % overlaps its neighbours, and LIGGGHTS pushes them apart.
awk '/^Atoms/ {on = 1; print; next} on && NF >= 7 && !done {$3 = $3 * 1.1; done = 1} {print}' s3.data > grown.data
set -- $(run_liggghts grown.data 3 spheres 100)
awk -v d="$3" 'BEGIN {exit !(d > 1e-9 * 0.01)}' || { echo "FAIL: an overlapping sphere did not move anything in LIGGGHTS (displacement $3)"; exit 1; }
echo "control: a sphere grown by 10 % moved its neighbours by $3 in LIGGGHTS"
