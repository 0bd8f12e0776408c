#!/bin/bash
# Usage: sphere_scenes.sh BINARY OUTDIR -- packs the named sphere/disk scenes and lever variants to OUTDIR/*.csv
# (compare two binaries with cmp). Scenes with relative mesh paths are rewritten to absolute ones.
B=$(realpath "$1"); O=$(realpath -m "$2"); mkdir -p $O/scenes
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel); S=$ROOT/scenes
for s in demo ratio7 valera-cube valera-db cylinder mesh; do cp $S/$s.yaml $O/scenes/; done
mk() { # name base extra-yaml-packer-lines
  python3 - "$S/$2.yaml" "$O/scenes/$1.yaml" "$3" <<'PY'
import sys,re
src,dst,extra=sys.argv[1:]
t=open(src).read()
if re.search(r'^packer:',t,re.M):
    t=re.sub(r'^packer:\n',"packer:\n"+extra,t,flags=re.M)
else:
    t+="\npacker:\n"+extra
open(dst,'w').write(t)
PY
}
mk demo-random demo "  front: random\n"
mk demo-fifo demo "  front: fifo\n"
mk demo-first demo "  candidate: first\n  pair_order: index\n"
mk demo-cball demo "  contact_bodies: all\n"
mk demo-pool1 demo "  radius_pool: 1\n"
mk demo-probe demo "  probe_smallest: true\n  radius_pool: 8\n"
mk demo-nowalls demo "  walls: false\n"
mk ratio7-probe ratio7 "  probe_smallest: true\n"
sed -i "s#\.\./tests#$ROOT/tests#" $O/scenes/mesh.yaml
sed "s/1000000/60000/" $S/disks-million.yaml > $O/scenes/disks.yaml
sed "s/1000000/60000/" $S/disks-million.yaml > $O/scenes/disks-random.yaml; printf "packer:\n  front: random\n  radius_pool: 4\n" >> $O/scenes/disks-random.yaml
for f in $O/scenes/*.yaml; do sed -i 's/\\n/\n/g' $f; done
cd $ROOT
for f in $O/scenes/*.yaml; do n=$(basename $f .yaml); $B pack $f -q -o $O/$n.csv >/dev/null 2>$O/$n.err || echo "FAIL $n"; done

