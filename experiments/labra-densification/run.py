#!/usr/bin/env python3
"""Least-squares densification (paper 001, `least_squares:`) of front, thinned, stacking and
void-filled packings, 2D and 3D, and of a tool tooth of ~25,000 spheres in a closed mesh.

Each case: `pack` makes the packing given (record: its own figures), `analyze` measures it at the
stage's tolerance (1e-6, so that contacts before and after are counted alike), `densify` with the
case's `least_squares:` densifies it (record: VF before/after, radii and centre moves, time), and
its exit code says whether the independent validation passed.

Usage: run.py OUT_DIR [--only NAME,...]   (writes OUT_DIR/results.json; table.py makes RESULTS.md)
"""
import json
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from runkit import FRONTPACK  # noqa: E402

HERE = Path(__file__).resolve().parent
U3 = "{distribution: uniform, min: 0.5, max: 1.0}"
R7 = "{distribution: uniform, min: 0.029, max: 0.2}"
M7 = "{distribution: gradation, basis: mass, curve: [[0.058, 0], [0.4, 100]]}"
TOOTH = "{type: mesh, file: " + str(HERE / "tooth.off") + "}"


def box(d, a):
    return f"{{type: box, min: [0, 0, 0], max: [{a}, {a}, {a}]}}" if d == 3 else f"{{type: rectangle, min: [0, 0], max: [{a}, {a}]}}"


# name, dimension, container, law, what makes the packing given, least_squares options
CASES = [
    ("front-3d", 3, box(3, 20), U3, "", "{radii: range}"),
    ("front-3d-fixed", 3, box(3, 20), U3, "", "{radii: fixed}"),
    ("front-3d-all-edges", 3, box(3, 20), U3, "", "{radii: range, edge_gap: 0}"),
    ("thinned-0.45-3d", 3, box(3, 20), U3, "target: {solid_fraction: 0.45}\n", "{radii: range}"),
    ("thinned-0.45-3d-fixed", 3, box(3, 20), U3, "target: {solid_fraction: 0.45}\n", "{radii: fixed}"),
    ("front-2d", 2, box(2, 60), U3, "", "{radii: range}"),
    ("thinned-0.70-2d", 2, box(2, 60), U3, "target: {solid_fraction: 0.70}\n", "{radii: range}"),
    ("stacking-3d-R7", 3, box(3, 3), M7, "packer: {method: stacking, order: contacts_first}\ntarget: {solid_fraction: 0.667}\n",
     "{radii: range}"),
    ("void-filled-3d-R7", 3, box(3, 4), R7, "densify: {radii: fit}\n", "{radii: range}"),
    ("tooth-3d", 3, TOOTH, "{distribution: uniform, min: 0.045, max: 0.09}", "", "{radii: range}"),
    ("front-3d-box40", 3, box(3, 40), U3, "", "{radii: range}"),
    ("front-3d-box60", 3, box(3, 60), U3, "", "{radii: range}"),
]


def write_tooth(path):
    """An excavator tooth as a convex hexahedron: a 4 x 3 base at x = 0 tapering to a 3 x 0.6 tip
    at x = 10 (each side face is planar), 12 triangles, outward."""
    v = [(0, -2, -1.5), (0, 2, -1.5), (0, 2, 1.5), (0, -2, 1.5),
         (10, -1.5, -0.3), (10, 1.5, -0.3), (10, 1.5, 0.3), (10, -1.5, 0.3)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    tris = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    lines = ["OFF", f"{len(v)} {len(tris)} 0"] + [f"{x} {y} {z}" for x, y, z in v] + [f"3 {a} {b} {c}" for a, b, c in tris]
    path.write_text("\n".join(lines) + "\n")


def run(cmd):
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, time.monotonic() - t0, p.stdout + p.stderr


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    only = sys.argv[sys.argv.index("--only") + 1].split(",") if "--only" in sys.argv else None
    if not (HERE / "tooth.off").exists():
        write_tooth(HERE / "tooth.off")
    results_path = out / "results.json"
    results = json.loads(results_path.read_text()) if results_path.exists() else {}
    for name, d, container, law, making, ls in CASES:
        if only and name not in only:
            continue
        head = f"dimension: {d}\nseed: 1\ncontainer: {container}\nparticles: {{radius: {law}}}\n"
        (out / f"{name}-given.yaml").write_text(head + making)
        (out / f"{name}-ls.yaml").write_text(head + f"least_squares: {ls}\n")
        code, _, text = run([FRONTPACK, "pack", str(out / f"{name}-given.yaml"), "-o", str(out / f"{name}-given.csv"), "-q",
                             "--record", str(out / f"{name}-given.json")])
        if code not in (0, 3, 4):
            print(text)
            raise SystemExit(f"{name}: pack failed ({code})")
        run([FRONTPACK, "analyze", str(out / f"{name}-given.csv"), "--scene", str(out / f"{name}-ls.yaml"), "--tolerance", "1e-6",
             "--json", str(out / f"{name}-before.json"), "-q"])
        code, seconds, text = run([FRONTPACK, "densify", str(out / f"{name}-given.csv"), "--scene", str(out / f"{name}-ls.yaml"),
                                   "-o", str(out / f"{name}-after.csv"), "--record", str(out / f"{name}-after.json"), "-q", "-j", "1"])
        before = json.loads((out / f"{name}-before.json").read_text())
        rec = json.loads((out / f"{name}-after.json").read_text())
        m, c = rec["metrics"], rec["counters"]
        row = {
            "case": name, "dimension": d, "least_squares": ls, "exit": code, "particles": rec["n"],
            "vf_before": m["least_squares_volume_fraction_before"], "vf_optimum": m["least_squares_volume_fraction_optimum"],
            "vf_after": m["least_squares_volume_fraction_after"],
            "vf_ref_before": before["volume_fraction"]["reference"]["value"], "vf_ref_after": m["volume_fraction_reference_sphere"],
            "z_before": before["coordination"]["mean"], "z_after": m["mean_coordination"],
            "rattlers_before": before["coordination"]["rattlers"] / rec["n"], "rattlers_after": m["rattler_fraction"],
            "radius_change_mean": m["least_squares_mean_radius_change"], "radius_change_max": m["least_squares_max_radius_change"],
            "move_mean": m["least_squares_mean_move"], "kept_share": m["least_squares_kept_share"],
            "max_overlap_optimum": m["least_squares_max_overlap_optimum"], "edges": c["least_squares_edges"],
            "relax_rounds": c["least_squares_relax_rounds"], "stage_seconds": m["least_squares_seconds"],
            "triangulation_seconds": m["least_squares_triangulation_seconds"], "solve_seconds": m["least_squares_solve_seconds"],
            "command_seconds": seconds,
        }
        results[name] = row
        print(f"{name}: N {row['particles']} VF {row['vf_before']:.4f} -> {row['vf_after']:.4f} (optimum {row['vf_optimum']:.4f}), "
              f"ref {row['vf_ref_before']:.4f} -> {row['vf_ref_after']:.4f}, z {row['z_before']:.2f} -> {row['z_after']:.2f}, "
              f"{row['stage_seconds']:.2f} s, exit {code}", flush=True)
        results_path.write_text(json.dumps(results, indent=1) + "\n")


if __name__ == "__main__":
    main()
