# Sourced by the checks that run the README's DEM inputs in the real programs
# (lammps_read_check.sh, liggghts_read_check.sh, yade_read_check.sh), so that what the README
# shows is what the tests run. Needs $here, the folder of tests/cli.
# readme_snippet NAME: the README's code block after the line "<!-- snippet: NAME -->", its
# comments and trailing blanks stripped; fails when there is no such block.
readme_snippet() {
  awk -v mark="<!-- snippet: $1 -->" '$0 == mark {found = 1; next}
    found == 1 && /^```/ {found = 2; next} found == 2 && /^```/ {exit} found == 2 {print}' "$here/../../README.md" |
    sed 's/ *#.*$//; s/[[:space:]]*$//' > "snippet-$1.txt"
  [ -s "snippet-$1.txt" ] || { echo "FAIL: the README has no block '<!-- snippet: $1 -->'" >&2; exit 1; }
  cat "snippet-$1.txt"
}
