#!/bin/sh
# The real consumer of the YADE text files: Debian's YADE (`yade`, batch mode) loads what
# `frontpack pack` writes, spheres with ymport.text and clusters with ymport.textClumps, and runs
# 200 DEM steps without gravity (Cundall-Strack contacts): every particle is read (and every clump
# made) and nothing moves (largest displacement <= 1e-9 r_min: no overlap to push apart). A copy
# with one radius grown by 10 % must move (the check can fail). Exit 77 (skipped) without yade.
# Usage: yade_read_check.sh FRONTPACK
set -eu
here=$(cd "$(dirname "$0")" && pwd)
fp=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
command -v yade > /dev/null || { echo "SKIPPED: no yade (Debian package yade; scripts/install-deps.sh --test installs it)"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
. "$here/block_scenes.sh"

# The README's YADE script (snippet yade) as written, for the file and kind given on the command
# line (clumps: the third line becomes ymport.textClumps, as the README says), with the test's
# counting around its run.
. "$here/readme_snippet.sh"
readme_snippet yade > snippet.py
{
  echo 'import sys'
  echo 'path, kind = sys.argv[1], sys.argv[2]'
  awk '/^O\.bodies\.append\(ymport\.text\(/ {print "if kind == \"spheres\":"; print "    O.bodies.append(ymport.text(path))"
                                                print "else:"; print "    ymport.textClumps(path)"; next}
       /^O\.run\(/ {print "start = [b.state.pos for b in O.bodies]"; print; next}
       {print}' snippet.py
  cat <<'P'
moved = max((b.state.pos - p).norm() for b, p in zip(O.bodies, start))
spheres = sum(1 for b in O.bodies if isinstance(b.shape, Sphere))
clumps = sum(1 for b in O.bodies if b.isClump)
print("RESULT %d %d %.6g" % (spheres, clumps, moved))
P
} > check.py
grep -q 'ymport.text(path)' check.py || { echo "FAIL: the README's YADE block has no ymport.text line"; exit 1; }

# run_yade FILE KIND: prints "SPHERES CLUMPS MAX_DISPLACEMENT"
run_yade() {
  yade -n -x check.py "$1" "$2" > yade.out 2>&1 || { echo "FAIL: yade could not run $1"; cat yade.out; exit 1; }
  sed -n 's/^RESULT //p' yade.out | tail -1
}

check() {  # check FILE KIND R_MIN EXPECTED_SPHERES EXPECTED_CLUMPS
  set -- "$@" $(run_yade "$1" "$2")
  [ "$6" = "$4" ] && [ "$7" = "$5" ] || { echo "FAIL: $1: YADE made $6 spheres and $7 clumps, the file has $4 and $5"; cat yade.out; exit 1; }
  awk -v d="$8" -v r="$3" 'BEGIN {exit !(d <= 1e-9 * r)}' || { echo "FAIL: $1: particles moved by $8 (r_min $3)"; exit 1; }
  echo "$1: $4 spheres, $5 clumps read, 200 steps, largest displacement $8"
}

grep -v '^packer:' s3.yaml > s3-front.yaml
"$fp" pack s3-front.yaml -q -o spheres.txt
n=$(grep -vc '^#' spheres.txt)
check spheres.txt spheres 0.01 "$n" 0

# The count stop leaves the box unfilled: exit 4 (incomplete), the file written.
"$fp" pack clumps3.yaml -q -o clumps.txt || [ $? -eq 4 ]
check clumps.txt clumps 0.2 "$(grep -vc '^#' clumps.txt)" 150

# The control: one sphere grown by 10 % overlaps its neighbours, and YADE pushes them apart.
awk '!/^#/ && !done {$4 = $4 * 1.1; done = 1} {print}' spheres.txt > grown.txt
set -- $(run_yade grown.txt spheres)
awk -v d="$3" 'BEGIN {exit !(d > 1e-9 * 0.01)}' || { echo "FAIL: an overlapping sphere did not move anything (displacement $3)"; exit 1; }
echo "control: a sphere grown by 10 % moved its neighbours by $3"
