#!/usr/bin/env python3
"""A target solid fraction for the whole container: `target: {solid_fraction: phi}`
(the packer's own density, then thinned evenly: densify/thinning.hpp) against
`stop: {volume_fraction: phi}` (growth stopped at phi), same scenes and seeds.

Usage: run.py FRONTPACK OUT_DIR [seeds]   (writes OUT_DIR/results.json and prints the tables)
Each run is `frontpack pack SCENE --record REC -o CSV -q`; the figures come from the run record
(the independent validation and analysis of `pack`: container VF, the VF in cells of 8 mean
diameters 2 r_max from the walls, radii test, contacts); the slabs (solid fraction in 6 slabs
across the box, exact sphere-slab volumes) from the CSV."""
import json
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

SCENES = {
    "box": ("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [0.9, 0.9, 0.9]}\n"
            "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n"),
    "box-R7": ("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [0.9, 0.9, 0.9]}\n"
               "particles: {radius: {distribution: uniform, min: 0.004, max: 0.028}}\n"),
    "box-R7-large": ("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1.8, 1.8, 1.8]}\n"
                     "particles: {radius: {distribution: uniform, min: 0.004, max: 0.028}}\n"),
    "cylinder": ("dimension: 3\ncontainer: {type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 0.3, height: 0.8}\n"
                 "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n"),
    "femur": ("dimension: 3\ncontainer: {type: mesh, file: " + os.path.join(REPO, "tests/data/meshes/femur.off") + "}\n"
              "particles: {radius: {distribution: uniform, min: 0.005, max: 0.01}}\n"),
    "disks": ("dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
              "particles: {radius: {distribution: uniform, min: 0.005, max: 0.01}}\n"),
}
PHIS = {"disks": [0.40, 0.50, 0.60, 0.70, 0.78]}
DEFAULT_PHIS = [0.40, 0.45, 0.50, 0.55, 0.58]


def slabs(csv, dim, side=0.9, n=6):
    """Solid fraction in n slabs across x of a box (cube) of the given side: exact sphere-slab volumes."""
    rows = [l.split(",") for l in open(csv).read().splitlines()[1:]]
    out = [0.0] * n
    for r in rows:
        x, rad = float(r[1]), float(r[-1])
        for k in range(n):
            a, b = k * side / n, (k + 1) * side / n

            def below(t):
                t = max(-rad, min(rad, t))
                h = t + rad
                return math.pi * h * h * (3 * rad - h) / 3 if dim == 3 else \
                    rad * rad * math.acos(max(-1.0, min(1.0, 1 - h / rad))) - (rad - h) * math.sqrt(max(0.0, h * (2 * rad - h)))
            out[k] += below(b - x) - below(a - x)
    area = side ** (dim - 1)
    return [v / (area * side / n) for v in out]


def run(frontpack, out, name, mode, phi, seed):
    tag = f"{name}-{mode}-{phi}-s{seed}"
    scene = f"seed: {seed}\n" + SCENES[name] + (f"target: {{solid_fraction: {phi}}}\n" if mode == "target"
                                                  else f"stop: {{volume_fraction: {phi}}}\n")
    path = os.path.join(out, tag + ".yaml")
    open(path, "w").write(scene)
    rec, csv = os.path.join(out, tag + ".json"), os.path.join(out, tag + ".csv")
    t0 = time.perf_counter()
    p = subprocess.run([frontpack, "pack", path, "--record", rec, "-o", csv, "-q"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        raise SystemExit(f"{tag}: exit {p.returncode}: {p.stderr}")
    r = json.load(open(rec))
    m, c, a = r["metrics"], r["counters"], r["analysis"]
    cells = a["volume_fraction"]["cells"]
    row = {"tag": tag, "scene": name, "mode": mode, "phi": phi, "seed": seed, "n": r["n"],
           "vf_container": m["volume_fraction_container"], "vf_core": m["volume_fraction_core"],
           "cells_mean": cells["mean"], "cells_sd": cells["std_dev"], "cells_min": cells["min"], "cells_max": cells["max"],
           "cells": cells["cells"], "cell_diameters": cells["diameters"],
           "radii_p": m["radii_pvalue"], "z": m["mean_coordination"], "rattlers": m["rattler_fraction"],
           "pack_s": r["timings"]["pack"], "wall_s": wall,
           "level": c.get("thinning_contact_level"), "lost_all": c.get("thinning_lost_every_contact"),
           "thinning_s": m.get("thinning_seconds"), "before": m.get("thinning_volume_fraction_before"),
           "reached": r["info"].get("target_volume_fraction") != "not reached"}
    if name in ("box", "box-R7", "box-R7-large", "disks"):
        row["slabs"] = slabs(csv, 2 if name == "disks" else 3, {"disks": 1.0, "box-R7-large": 1.8}.get(name, 0.9))
    os.remove(csv)
    return row


def main():
    frontpack, out = sys.argv[1], sys.argv[2]
    seeds = [int(s) for s in sys.argv[3].split(",")] if len(sys.argv) > 3 else [1, 2, 3]
    os.makedirs(out, exist_ok=True)
    rows = []
    for name in SCENES:
        for phi in PHIS.get(name, DEFAULT_PHIS):
            for mode in ("target", "stop"):
                for seed in seeds:
                    rows.append(run(frontpack, out, name, mode, phi, seed))
                    print(json.dumps({k: v for k, v in rows[-1].items() if k != "slabs"}), flush=True)
    json.dump(rows, open(os.path.join(out, "results.json"), "w"), indent=1)


if __name__ == "__main__":
    main()
