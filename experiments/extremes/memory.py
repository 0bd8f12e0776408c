"""Memory per particle and per mesh face of whole `frontpack pack` runs: the figures behind the
limits checked before any work (core/io/scene_limits.hpp, core/geometry/mesh_container.cpp).

  FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/extremes/memory.py

Each case is packed twice, at a small and a large particle (or face) count, under
`/usr/bin/time -f %M` (peak RSS), written as CSV. (A VTU output of non-spherical particles also
keeps their display surfaces in memory up to 256 MB, shapes/io/shape_packing_writers.cpp; the
last case measures that cap.) The cost of one more particle is the slope between the two runs,
(RSS_large - RSS_small) / (N_large - N_small), both counts large enough that the packing
outgrows the ~25 MB the program peaks at while it reads its inputs (below that, the particles
reuse memory freed by then and RSS does not grow); RSS / N is shown beside it. Writes memory.csv; run.py puts the table in RESULTS.md.
"""
import csv
import math
import os
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import runkit  # noqa: E402

HERE = Path(__file__).resolve().parent


def uv_sphere_stl(path, n):
    """A closed binary STL sphere of n rings and 2n segments: 4n(n-1) triangles."""
    def p(i, j):
        th = math.pi * i / n
        ph = 0.0 if i in (0, n) else 2 * math.pi * (j % (2 * n)) / (2 * n)
        return (math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th))
    body, count = bytearray(), 0
    for i in range(n):
        for j in range(2 * n):
            a, b, c, d = p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)
            if i != 0:
                body += struct.pack("<12fH", 0, 0, 0, *a, *b, *d, 0)
                count += 1
            if i != n - 1:
                body += struct.pack("<12fH", 0, 0, 0, *b, *c, *d, 0)
                count += 1
    Path(path).write_bytes(b"\0" * 80 + struct.pack("<I", count) + bytes(body))
    return count


def cases(folder):
    """(name, unit, [(count, scene text)])."""
    r = "{radius: {distribution: uniform, min: 0.01, max: 0.02}}"
    caps = lambda lo, hi: f"[{{shape: spherocylinder, aspect_ratio: 0.5, size: {{distribution: uniform, min: {lo}, max: {hi}}}}}]"
    out = [("spheres 3D, U[0.01, 0.02], box 3.5", "particle",
            [(n, f"dimension: 3\ncontainer: {{type: box, min: [0, 0, 0], max: [3.5, 3.5, 3.5]}}\nparticles: {r}\nstop: {{particles: {n}}}\n")
             for n in (100000, 1000000)]),
           ("disks 2D, U[0.01, 0.02], square 35", "particle",
            [(n, f"dimension: 2\ncontainer: {{type: rectangle, min: [0, 0], max: [35, 35]}}\nparticles: {r}\nstop: {{particles: {n}}}\n")
             for n in (100000, 1000000)]),
           ("capsules 2D, aspect 0.5, square 1200", "particle",
            [(n, f"dimension: 2\ncontainer: {{type: rectangle, min: [0, 0], max: [1200, 1200]}}\nparticles: {caps(1, 2)}\n"
                 f"stop: {{particles: {n}}}\n") for n in (100000, 400000)]),
           ("capsules 3D, aspect 0.5, box 45", "particle",
            [(n, f"dimension: 3\ncontainer: {{type: box, min: [0, 0, 0], max: [45, 45, 45]}}\nparticles: {caps(0.5, 1)}\n"
                 f"packer: {{radius_pool: 1}}\nstop: {{particles: {n}}}\n") for n in (20000, 60000)])]
    meshes = []
    for rings in (100, 400):
        faces = uv_sphere_stl(folder / f"sphere{rings}.stl", rings)
        meshes.append((faces, f"dimension: 3\ncontainer: {{type: mesh, file: sphere{rings}.stl}}\nparticles: {r}\n"
                              f"stop: {{particles: 100}}\n"))
    out.append(("mesh container, binary STL sphere (100 spheres packed)", "face", meshes))
    return out


def surfaces_case():
    """3D capsules written as VTU: the display surfaces' cache, capped at 256 MB."""
    caps = "[{shape: spherocylinder, aspect_ratio: 0.5, size: {distribution: uniform, min: 0.5, max: 1}}]"
    return [(n, f"dimension: 3\ncontainer: {{type: box, min: [0, 0, 0], max: [30, 30, 30]}}\nparticles: {caps}\n"
                f"packer: {{radius_pool: 1}}\nstop: {{particles: {n}}}\n") for n in (2000, 20000)]


def peak_rss_kb(binary, folder, text, out="out.csv"):
    scene = folder / "scene.yaml"
    scene.write_text(text)
    p = subprocess.run(["/usr/bin/time", "-f", "%M", binary, "pack", str(scene), "-q", "-o", str(folder / out)],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(p.stderr)
    return int(p.stderr.strip().splitlines()[-1])


def main():
    binary = os.environ.get("FRONTPACK", str(runkit.REPO / "build" / "cli" / "frontpack"))
    rows = []
    with tempfile.TemporaryDirectory() as d:
        folder = Path(d)
        for name, unit, runs in cases(folder):
            (n1, t1), (n2, t2) = runs
            k1, k2 = peak_rss_kb(binary, folder, t1), peak_rss_kb(binary, folder, t2)
            row = {"case": name, "unit": unit, "n_small": n1, "rss_small_kb": k1, "n_large": n2, "rss_large_kb": k2,
                   "bytes_per_unit": f"{(k2 - k1) * 1024 / (n2 - n1):.0f}", "rss_over_n": f"{k2 * 1024 / n2:.0f}"}
            print(row, flush=True)
            rows.append(row)
        (n1, t1), (n2, t2) = surfaces_case()
        k1, k2 = peak_rss_kb(binary, folder, t1, "out.vtu"), peak_rss_kb(binary, folder, t2, "out.vtu")
        row = {"case": "capsules 3D written as VTU (surfaces cached up to 256 MB)", "unit": "particle", "n_small": n1,
               "rss_small_kb": k1, "n_large": n2, "rss_large_kb": k2,
               "bytes_per_unit": f"{(k2 - k1) * 1024 / (n2 - n1):.0f}", "rss_over_n": f"{k2 * 1024 / n2:.0f}"}
        print(row, flush=True)
        rows.append(row)
    with open(HERE / "memory.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
