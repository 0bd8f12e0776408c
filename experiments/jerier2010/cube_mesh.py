#!/usr/bin/env python3
"""A tetrahedral mesh of a cube for paper 000's experiments, written as Gmsh MSH 2.2 ASCII:
n x n x n sub-cubes, each cut into the 6 tetrahedra around its main diagonal (Kuhn), every
tetrahedron positively oriented, all in physical volume 1 "cube"; nodes optionally jittered
(by a fraction of the spacing, interior nodes only, deterministic) so the edges are not all
of three lengths.

Usage: cube_mesh.py N SIDE OUT.msh [JITTER]     (6 N^3 tetrahedra; N = 6: 1,296)"""
import itertools
import random
import sys


def cube_mesh(n, side, jitter=0.0, seed=1):
    rng = random.Random(seed)
    h = side / n
    nodes = {}
    for i, j, k in itertools.product(range(n + 1), repeat=3):
        p = [i * h, j * h, k * h]
        if jitter and 0 < i < n and 0 < j < n and 0 < k < n:
            p = [x + jitter * h * (2 * rng.random() - 1) for x in p]
        nodes[(i, j, k)] = (len(nodes) + 1, p)
    tets = []
    for i, j, k in itertools.product(range(n), repeat=3):
        for perm in itertools.permutations(range(3)):
            corner = [i, j, k]
            path = [tuple(corner)]
            for axis in perm:
                corner[axis] += 1
                path.append(tuple(corner))
            t = [nodes[c][0] for c in path]
            a, b, c, d = (nodes[x][1] for x in path)
            u = [b[m] - a[m] for m in range(3)]
            v = [c[m] - a[m] for m in range(3)]
            w = [d[m] - a[m] for m in range(3)]
            vol = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]))
            if vol < 0:
                t[2], t[3] = t[3], t[2]
            tets.append(t)
    return sorted(nodes.values()), tets


def write_msh(path, nodes, tets):
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"cube\"\n$EndPhysicalNames\n")
        f.write(f"$Nodes\n{len(nodes)}\n")
        for tag, p in nodes:
            f.write(f"{tag} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
        f.write(f"$EndNodes\n$Elements\n{len(tets)}\n")
        for e, t in enumerate(tets, 1):
            f.write(f"{e} 4 2 1 1 {t[0]} {t[1]} {t[2]} {t[3]}\n")
        f.write("$EndElements\n")


if __name__ == "__main__":
    n, side, out = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
    jitter = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
    nodes, tets = cube_mesh(n, side, jitter)
    write_msh(out, nodes, tets)
    print(f"{out}: {len(nodes)} nodes, {len(tets)} tetrahedra")
