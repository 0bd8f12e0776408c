#!/bin/sh
# First measurements of the graded stacking (paper 003): 3D and 2D at R = 7, the paper's order
# against contacts_first, a uniform law by count and a gradation uniform by mass.
# Usage: run.sh FRONTPACK OUT_DIR   (prints one block per run: the summary's stacking, VF and radii lines)
set -e
B=$1; OUT=$2; mkdir -p "$OUT"
run() {  # name dimension box law target order
  f="$OUT/$1.yaml"
  if [ "$2" = 3 ]; then c="{type: box, min: [0, 0, 0], max: [$3, $3, $3]}"; else c="{type: rectangle, min: [0, 0], max: [$3, $3]}"; fi
  printf 'dimension: %s\nseed: 1\ncontainer: %s\nparticles: {radius: %s}\npacker: {method: stacking, order: %s}\ntarget: {solid_fraction: %s}\n' \
    "$2" "$c" "$4" "$6" "$5" > "$f"
  echo "== $1"
  "$B" pack "$f" -o "$OUT/$1.csv" 2>&1 | grep -E "stacking   |VF container|VF cells|radii test|coordination z" || true
}
U3='{distribution: uniform, min: 0.029, max: 0.2}'
M3='{distribution: gradation, basis: mass, curve: [[0.058, 0], [0.4, 100]]}'
for order in paper contacts_first; do
  run 3d-uniform-0.6-$order 3 4 "$U3" 0.6 $order
  run 3d-mass-0.667-$order 3 3 "$M3" 0.667 $order
  run 3d-mass-0.703-$order 3 3 "$M3" 0.703 $order
  run 2d-uniform-0.80-$order 2 20 "$U3" 0.80 $order
  run 2d-uniform-0.826-$order 2 20 "$U3" 0.826 $order
done
