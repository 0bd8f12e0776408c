#!/usr/bin/env python3
"""Paper 000 (Jerier, Richefeu, Imbault, Donze 2010) reproduced with frontpack's tetrahedral-mesh
packer (`packer: {method: tet_mesh}`, steps 2-7b): its Fig. 4 (solid fraction and coordination
against R = r_max / r_min, filled until no sphere fits, and with the target phi0 = 0.46), Fig. 6
(z(xi) and the radii's pdf at R = 7, loose and dense), Fig. 7 (fabric eigenvalues against R, g(r)),
Fig. 8 (time against the number of tetrahedra at phi0 = 0.6, and against phi0), each with
epsilon = 0 and a small epsilon.

Usage: run.py FRONTPACK OUT_DIR [--quick] [--only-stl | --unstructured]
The meshes are Kuhn cubes (cube_mesh.py: n^3 sub-cubes of 6 tetrahedra, interior nodes jittered by
0.2 of the spacing); radii sized as the paper does, mean radius = mean edge / 8. The solid
fraction phi is the paper's Eq. 16, in a spherical probe (the analysis' reference ball, radius
half the side), beside the container's. Every figure comes from the run record of `frontpack pack`."""
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import cube_mesh  # noqa: E402


def mesh(out, n):
    path = os.path.join(out, f"cube{n}.msh")
    if not os.path.exists(path):
        nodes, tets = cube_mesh.cube_mesh(n, 1.0, 0.2)
        cube_mesh.write_msh(path, nodes, tets)
    return path


def mean_edge(n):
    # Kuhn cube of spacing h: edges h (axes), h sqrt 2 (face diagonals), h sqrt 3 (the diagonal);
    # per cube 3 + 3 + 1 of them: mean (3 + 3 sqrt 2 + sqrt 3) / 7 h.
    h = 1.0 / n
    return (3 + 3 * 2 ** 0.5 + 3 ** 0.5) / 7 * h


# The unit cube's surface (tests/data/meshes/cube.stl), meshed by frontpack itself (CGAL Mesh_3) with
# edges of 0.15: 1,302 tetrahedra, whose mean volume makes a regular tetrahedron of edge 0.187.
STL_CUBE = os.path.join(HERE, "..", "..", "tests", "data", "meshes", "cube.stl")
# Other edges scale the mean edge alike (1.247 times the edge asked for).
STL_EDGE, STL_MEAN_EDGE = 0.15, 0.187


def run(frontpack, out, tag, n, ratio, eps=0.0, phi0=None, loose=False, seed=1, fallback=False, stl_edge=STL_EDGE):
    """n > 0: a Kuhn cube of n^3 sub-cubes; n = 0: the STL cube meshed by frontpack with edges stl_edge."""
    r_mean = (mean_edge(n) if n else STL_MEAN_EDGE * stl_edge / STL_EDGE) / 8
    r_min = 2 * r_mean / (1 + ratio)
    r_max = ratio * r_min
    packer = (f"{{method: tet_mesh, overlap: {eps}{', loose: true' if loose else ''}"
              f"{', fallback_r_min: true' if fallback else ''}{'' if n else f', mesh_edge: {stl_edge}'}}}")
    container = mesh(out, n) if n else os.path.abspath(STL_CUBE)
    scene = (f"dimension: 3\nseed: {seed}\ncontainer: {{type: mesh, file: {container}}}\n"
             f"particles: {{radius: {{distribution: uniform, min: {r_min!r}, max: {r_max!r}}}}}\npacker: {packer}\n")
    if phi0:
        scene += f"stop: {{volume_fraction: {phi0}}}\n"
    path = os.path.join(out, tag + ".yaml")
    with open(path, "w") as f:
        f.write(scene)
    rec = os.path.join(out, tag + ".json")
    csv = os.path.join(out, tag + ".csv")
    start = time.perf_counter()
    p = subprocess.run([frontpack, "pack", path, "--record", rec, "-o", csv, "-q"], capture_output=True, text=True)
    wall = time.perf_counter() - start
    if p.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        raise SystemExit(f"{tag}: exit {p.returncode}: {p.stderr}")
    r = json.load(open(rec))
    m, a, c = r["metrics"], r["analysis"], r["counters"]
    return {
        "tag": tag, "seed": seed, "n_mesh": n, "tets": c["tet_tetrahedra"], "R": ratio, "eps": eps, "phi0": phi0, "loose": loose,
        "fallback": fallback,
        "N": r["n"], "phi_probe": m["volume_fraction_reference_sphere"], "phi_container": m["volume_fraction_container"],
        "phi_core": m["volume_fraction_core"], "z": m["mean_coordination"], "z_walls": m["mean_coordination_with_walls"],
        "fabric": a["fabric"]["per_contact"], "partial_z": a["coordination"]["partial"],
        "rdf_r": a["rdf"]["r"], "rdf_g": a["rdf"]["g"], "pack_s": r["timings"]["pack"], "wall_s": wall,
        "fill_s": m["tet_fill_seconds"], "voids_s": m["densify_seconds"], "max_overlap_rmin": m["max_overlap_over_rmin"],
        "csv": os.path.basename(csv), "r_min": r_min, "r_max": r_max, "radii_pdf": radii_pdf(csv, r_min, r_max),
    }


def radii_pdf(csv, r_min, r_max, bins=24):
    """The pdf of the radii (paper Fig. 6), from the packing's csv."""
    counts = [0] * bins
    n = 0
    with open(csv) as f:
        next(f)
        for line in f:
            r = float(line.rsplit(",", 1)[1])
            k = min(bins - 1, max(0, int((r - r_min) / (r_max - r_min) * bins)))
            counts[k] += 1
            n += 1
    width = (r_max - r_min) / bins
    return [c / (n * width) for c in counts]


def unstructured(frontpack, out):
    """Figs. 4, 6, 7 and 8 on the STL cube meshed by frontpack, three seeds each (the seed moves the
    radii drawn and so every sphere; the mesh is the mesher's, the same for every seed)."""
    rows = []

    def add(*args, **kw):
        rows.append(run(frontpack, out, *args, **kw))
        print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z", "radii_pdf")}), flush=True)

    for seed in (1, 2, 3):
        for R in [2, 3, 4, 5, 6, 7]:
            add(f"u4a-R{R}-eps0.0-s{seed}", 0, R, 0.0, seed=seed)
            add(f"u4a-R{R}-eps0.05-s{seed}", 0, R, 0.05, seed=seed)
            add(f"u4b-R{R}-s{seed}", 0, R, 0.0, phi0=0.46, loose=True, seed=seed)
        for eps in (0.0, 0.05, 0.1, 0.2):  # the densest: voids whose own sphere fails take one of r_min
            add(f"u4a-R7-eps{eps}-fallback-s{seed}", 0, 7, eps, fallback=True, seed=seed)
        for edge in (0.3, 0.2, 0.15, 0.1, 0.07, 0.05, 0.035):  # Fig. 8a at phi0 = 0.6, R = 4
            add(f"u8a-e{edge}-s{seed}", 0, 4, 0.0, phi0=0.6, seed=seed, stl_edge=edge)
        for phi0 in [0.45, 0.5, 0.55, 0.6, 0.62, 0.64, 0.66]:  # Fig. 8b against phi0
            add(f"u8b-phi{phi0}-s{seed}", 0, 4, 0.0, phi0=phi0, seed=seed, stl_edge=0.1)
    json.dump(rows, open(os.path.join(out, "results-unstructured.json"), "w"))


def main():
    frontpack, out = sys.argv[1], sys.argv[2]
    quick = "--quick" in sys.argv
    os.makedirs(out, exist_ok=True)
    rows = []
    if "--unstructured" in sys.argv:
        unstructured(frontpack, out)
        return
    if "--only-stl" in sys.argv:  # the unstructured rows alone
        for R in [2, 3, 4, 5, 6, 7]:
            for tag, kw in [(f"fig4a-R{R}-stl", {}), (f"fig4b-R{R}-stl", {"phi0": 0.46, "loose": True})]:
                rows.append(run(frontpack, out, tag, 0, R, 0.0, **kw))
                print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z")}), flush=True)
        json.dump(rows, open(os.path.join(out, "results-stl.json"), "w"))
        return
    ratios = [2, 3, 4, 5, 6, 7]
    for eps in (0.0, 0.05):
        for R in ratios:  # Fig. 4a, 6b, 7: filled until no sphere fits
            rows.append(run(frontpack, out, f"fig4a-R{R}-eps{eps}", 6, R, eps))
            print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z")}), flush=True)
        for R in ratios:  # Fig. 4b, 6a: phi0 = 0.46, loose
            rows.append(run(frontpack, out, f"fig4b-R{R}-eps{eps}", 6, R, eps, phi0=0.46, loose=True))
            print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z")}), flush=True)
    for R in ratios:  # Fig. 4a beyond the paper: voids whose own sphere fails take one of r_min
        rows.append(run(frontpack, out, f"fig4a-R{R}-fallback", 6, R, 0.0, fallback=True))
        print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z")}), flush=True)
    for R in ratios:  # Fig. 4 on an unstructured mesh (frontpack's own meshing of the STL cube)
        for tag, kw in [(f"fig4a-R{R}-stl", {}), (f"fig4b-R{R}-stl", {"phi0": 0.46, "loose": True})]:
            rows.append(run(frontpack, out, tag, 0, R, 0.0, **kw))
            print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z")}), flush=True)
    sizes = [4, 6, 8, 10, 13] if quick else [4, 6, 8, 10, 13, 16, 20, 27]
    for n in sizes:  # Fig. 8a: time against the number of tetrahedra, phi0 = 0.6
        rows.append(run(frontpack, out, f"fig8a-n{n}", n, 4, 0.0, phi0=0.6))
        print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z")}), flush=True)
    for phi0 in [0.45, 0.5, 0.55, 0.6, 0.62, 0.64, 0.66]:  # Fig. 8b: time against phi0
        rows.append(run(frontpack, out, f"fig8b-phi{phi0}", 8, 4, 0.0, phi0=phi0))
        print(json.dumps({k: v for k, v in rows[-1].items() if k not in ("rdf_r", "rdf_g", "partial_z")}), flush=True)
    json.dump(rows, open(os.path.join(out, "results.json"), "w"))


if __name__ == "__main__":
    main()
