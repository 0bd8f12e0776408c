# Sourced by the end-to-end checks of packings grown in blocks (mpi_pack_check.sh,
# lammps_read_check.sh): writes s3.yaml (3D, blocks of 8 r_max, a count stop) and s2.yaml (2D,
# blocks of 12.5 r_max) into the current folder.
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
