#!/usr/bin/python3
"""Ellipsoids and ellipses packed by one frontpack binary, per contact solver.
Usage: run.py BINARY LABEL [SECONDS]  -- appends one row per (scene, solver) to runs.csv.
Scenes: scenes/shapes-ellipsoids.yaml (3D, [1, 0.7, 0.5], cube 12) and shapes-ellipses-2d.yaml,
each with `packer.contact_solver` auto (the ellipsoid solver where registered) and minimisation,
cut at SECONDS (default 30) of packing."""
import csv
import json
import os
import subprocess
import sys
import tempfile

root = subprocess.run(['git', '-C', os.path.dirname(os.path.abspath(__file__)), 'rev-parse', '--show-toplevel'],
                      capture_output=True, text=True, check=True).stdout.strip()
binary, label = os.path.abspath(sys.argv[1]), sys.argv[2]
seconds = float(sys.argv[3]) if len(sys.argv) > 3 else 30.0
rows = []
with tempfile.TemporaryDirectory() as tmp:
    for scene in ('shapes-ellipsoids', 'shapes-ellipses-2d'):
        text = open(os.path.join(root, 'scenes', scene + '.yaml')).read()
        text = text.replace('stop:\n', 'stop:\n  time: %g\n' % seconds, 1) if 'stop:\n' in text else text + '\nstop:\n  time: %g\n' % seconds
        for solver in ('auto', 'minimisation'):
            path = os.path.join(tmp, '%s-%s.yaml' % (scene, solver))
            open(path, 'w').write(text + '\npacker:\n  contact_solver: %s\n' % solver)
            record = os.path.join(tmp, 'record.json')
            p = subprocess.run([binary, 'pack', path, '-q', '-o', os.path.join(tmp, 'out.csv'), '--record', record])
            if p.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
                raise SystemExit('%s: frontpack failed (exit %d)' % (path, p.returncode))
            d = json.load(open(record))
            m, c = d['metrics'], d['counters']
            rows.append({'binary': label, 'scene': scene, 'solver': solver, 'particles': d['n'],
                         'fraction': round(m['volume_fraction_container'], 4), 'seconds': round(d['timings']['pack'], 2),
                         'per_second': round(d['n'] / d['timings']['pack'], 1), 'solves': c['solves'],
                         'closed_form_solves': c['analytic_solves'], 'gap_evaluations': c['gap_evaluations'],
                         'fcl_queries': c['fcl_queries'], 'max_contact_gap_over_rmin': m['max_contact_gap_over_smaller_radius'],
                         'max_overlap_over_rmin': m['max_overlap_over_smaller_radius'], 'stop': d['info']['stop_reason'],
                         'validation': d['info']['validation']})
            print(rows[-1], flush=True)
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'runs.csv')
new = not os.path.exists(out)
with open(out, 'a', newline='') as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    if new:
        w.writeheader()
    w.writerows(rows)
