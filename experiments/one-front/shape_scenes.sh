#!/bin/bash
# Usage: shape_scenes.sh BINARY OUTDIR -- the named shape scenes with a 25 s limit each; one line per scene (n, VF, time, rate, solves)
B=$(realpath $1)
ROOT=$(git -C "$(dirname "$0")" rev-parse --show-toplevel); OUT=$(realpath -m "$2"); mkdir -p $OUT; cd $ROOT
for s in shapes-polygons-2d shapes-ellipses-2d perez-capsules-2d perez-capsules-3d shapes-polyhedra shapes-clusters shapes-capsules-mesh shapes-ellipsoids; do
  sed "s#\.\./tests#$ROOT/tests#" scenes/$s.yaml > $OUT/$s.yaml
  if grep -q "^stop:" $OUT/$s.yaml; then sed -i "s/^stop:/stop:\n  time: 25/" $OUT/$s.yaml; else printf "\nstop:\n  time: 25\n" >> $OUT/$s.yaml; fi
  $B pack $OUT/$s.yaml -q -o $OUT/$s.csv --record $OUT/$s.json 2>$OUT/$s.err || echo "FAIL $s $(head -c 300 $OUT/$s.err)"
  python3 -c "
import json,sys;d=json.load(open('$OUT/$s.json'));m=d['metrics'];c=d['counters']
print('%-22s n=%6d VF=%.4f t=%.2f rate=%.0f solves=%d'%('$s',d['n'],m['volume_fraction_container'],d['timings']['pack'],d['n']/d['timings']['pack'],c['solves']))"
done
