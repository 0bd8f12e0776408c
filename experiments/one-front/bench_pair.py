#!/usr/bin/python3
"""Pairs two builds of frontpack_bench on the sphere front's benchmarks (BM_Front*): four rounds,
alternating which binary runs first, five repetitions of 0.3 s each per round; prints the best
and median particles per second of each and their ratios.
Usage: bench_pair.py OLD_BENCH NEW_BENCH"""
import collections
import subprocess
import sys

bins = {'old': sys.argv[1], 'new': sys.argv[2]}
rates = collections.defaultdict(list)
for r in range(4):
    for b, path in (list(bins.items()) if r % 2 == 0 else list(bins.items())[::-1]):
        out = subprocess.run([path, '--benchmark_filter=BM_Front', '--benchmark_min_time=0.3', '--benchmark_repetitions=5',
                              '--benchmark_format=csv'], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            if line.startswith('"BM_') and not any(s in line for s in ('_mean', '_median', '_stddev', '_cv')):
                f = line.split(',')
                rates[(f[0].strip('"'), b)].append(float(f[6]))
med = lambda v: sorted(v)[len(v) // 2]
for name in sorted({k[0] for k in rates}):
    o, n = rates[(name, 'old')], rates[(name, 'new')]
    print('| %s | %d | %d | %d | %d | %.3f | %.3f |' % (name, max(o), med(o), max(n), med(n), max(n) / max(o), med(n) / med(o)))
