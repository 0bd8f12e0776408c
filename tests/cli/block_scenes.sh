# Sourced by the end-to-end checks of packings grown in blocks and by the checks in the DEM codes
# (mpi_pack_check.sh, lammps_read_check.sh, liggghts_read_check.sh, yade_read_check.sh): writes
# s3.yaml (3D, blocks of 8 r_max, a count stop), s2.yaml (2D, blocks of 12.5 r_max), and
# clumps3.yaml, clumps2.yaml (150 clusters of 3 spheres, member radius 0.2 and more, in a box
# and a rectangle they do not fill: their count stop exits 4) into the current folder.
cat > s3.yaml <<'S'
dimension: 3
seed: 11
container: {type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
packer: {block_edge: 0.16}
stop: {particles: 5000}
S
cat > s2.yaml <<'S'
dimension: 2
seed: 12
container: {type: rectangle, min: [0, 0], max: [1, 1]}
particles: {radius: {distribution: uniform, min: 0.004, max: 0.008}}
packer: {block_edge: 0.1}
S
for dim in 3 2; do
  if [ $dim = 3 ]; then box='{type: box, min: [0, 0, 0], max: [6, 6, 6]}'; centers='[[-0.5, 0, 0], [0.5, 0, 0], [0.5, 0.8, 0]]'
  else box='{type: rectangle, min: [0, 0], max: [20, 20]}'; centers='[[-0.5, 0], [0.5, 0], [0.5, 0.8]]'; fi
  cat > clumps$dim.yaml <<S
dimension: $dim
seed: 3
container: $box
particles:
  - shape: cluster
    centers: $centers
    radii: [0.5, 0.5, 0.4]
    size: {distribution: uniform, min: 0.5, max: 1}
stop: {particles: 150}
S
done
