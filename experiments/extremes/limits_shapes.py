"""Measures behind a limit of the scene check (README "What is guaranteed"): cluster members (the
rare-large-class mixture moved to rare_large_class.py).

  FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/extremes/limits_shapes.py

Clusters: n members at random in a cube of side 2 (radii 0.2-0.4, random.seed(n)), in a box of 6,
sizes U[0.5, 1]. 'check' is the whole run with stop.particles 1 (the union's exact volume
dominates); 'rate' the particles a 10 s time stop leaves, and when the stop ended the pack phase."""
import random

from pack_once import pack as run


def cluster(n, stop):
    random.seed(n)
    centers = [[round(random.uniform(-1, 1), 4) for _ in range(3)] for _ in range(n)]
    radii = [round(random.uniform(0.2, 0.4), 4) for _ in range(n)]
    return (f"dimension: 3\ncontainer: {{type: box, min: [0,0,0], max: [6,6,6]}}\nstop: {stop}\nparticles:\n"
            f"  - shape: cluster\n    centers: {centers}\n    radii: {radii}\n"
            f"    size: {{distribution: uniform, min: 0.5, max: 1}}\n")


print("| members | check (s, whole run, 1 particle) | placed in a 10 s stop | pack phase (s) |")
print("|---|---|---|---|")
for n in (5, 10, 20, 50, 100, 200):
    _, check_wall, _, _ = run(cluster(n, "{particles: 1}"))
    rate = "-"
    if n <= 50:
        code, wall, rec, _ = run(cluster(n, "{time: 10}"))
        rate = f"{rec['n']} | {rec['timings']['pack']:.2f}" if rec else f"exit {code}"
    else:
        rate = "- | -"
    print(f"| {n} | {check_wall:.2f} | {rate} |")
