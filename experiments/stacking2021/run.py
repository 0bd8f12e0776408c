#!/usr/bin/python3
"""Paper 003's Tables 1-3 cases: graded stacking (`packer: {method: stacking}`) at the paper's
densities, 2D and 3D, R = 7 and R = 2, gradations uniform by mass (and by count for 2D R = 7),
both orders, three seeds; the front with the homogeneous target (`target:`) at the same solid
fractions beside them; coordination histograms; time against N.

Every run is `frontpack.pack(scene, threads=1)` (the Python module: the command line's run, its
record in memory); the record gives the solid fraction, the cells' spread, the radii test, z and
its histogram, the stacking's counters and the time.

Usage: PYTHONPATH=build-test run.py OUT_DIR [--seeds N] [--only GROUP,...]   (OUT_DIR/results.json; report.py)
"""
import json
import sys
import time
from pathlib import Path

import frontpack

MASS7 = {"distribution": "gradation", "basis": "mass", "curve": [[0.058, 0], [0.4, 100]]}
COUNT7 = {"distribution": "uniform", "min": 0.029, "max": 0.2}
MASS2 = {"distribution": "gradation", "basis": "mass", "curve": [[0.2, 0], [0.4, 100]]}


def box(d, a):
    return {"type": "box", "min": [0] * 3, "max": [a] * 3} if d == 3 else {"type": "rectangle", "min": [0, 0], "max": [a, a]}


# group: dimension, container edge (cm), law, the paper's densities (low, middle, high)
GROUPS = {
    "2d-R7-mass": (2, 20, MASS7, [0.826, 0.843, 0.860]),
    "2d-R7-count": (2, 20, COUNT7, [0.826, 0.843, 0.860]),
    "2d-R2-mass": (2, 50, MASS2, [0.787, 0.800, 0.814]),
    "3d-R7-mass": (3, 3, MASS7, [0.667, 0.685, 0.703]),
    "3d-R2-mass": (3, 5, MASS2, [0.553, 0.575, 0.597]),
}
# time against N: the same law in growing containers
SCALING = {"3d-R2-mass": [3, 5, 8, 12, 18, 24], "2d-R2-mass": [25, 50, 100, 200]}
STACKING = {"paper": {"method": "stacking", "order": "paper"}, "contacts_first": {"method": "stacking", "order": "contacts_first"},
            "front": None}


def run_case(name, d, edge, law, method, phi, seed):
    scene = {"dimension": d, "seed": seed, "container": box(d, edge), "particles": {"radius": law},
             "target": {"solid_fraction": phi}}
    if STACKING[method]:
        scene["packer"] = STACKING[method]
    t0 = time.monotonic()
    p = frontpack.pack(scene, threads=1)
    wall = time.monotonic() - t0
    r = p.record
    m, c, a = r["metrics"], r["counters"], r["analysis"]
    row = {"case": name, "dimension": d, "edge": edge, "phi": phi, "seed": seed, "exit": 0 if p.valid else 3,
           "particles": r["n"], "vf": m["volume_fraction_container"], "cells_sd": m.get("volume_fraction_cells_std"),
           "radii_p": a["radii_fit"]["p"],
           "z": m["mean_coordination"], "z_histogram": a["coordination"]["histogram"], "rattlers": m["rattler_fraction"],
           "pack_seconds": r["timings"]["pack"], "wall_seconds": wall}
    if "stacking_asked" in c:
        row.update({"asked": c["stacking_asked"], "unplaced": c["stacking_unplaced"]})
    return row


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    seeds = int(sys.argv[sys.argv.index("--seeds") + 1]) if "--seeds" in sys.argv else 3
    only = sys.argv[sys.argv.index("--only") + 1].split(",") if "--only" in sys.argv else None
    path = out / "results.json"
    results = json.loads(path.read_text()) if path.exists() else {}

    def keep(row):
        results[row["case"]] = row
        path.write_text(json.dumps(results, indent=1) + "\n")
        extra = f", {row['unplaced']} of {row['asked']} unplaced" if "asked" in row else ""
        print(f"{row['case']}: N {row['particles']} VF {row['vf']:.4f} (asked {row['phi']}){extra}, z {row['z']:.2f}, "
              f"{row['pack_seconds']:.2f} s", flush=True)

    for group, (d, edge, law, phis) in GROUPS.items():
        if only and group not in only:
            continue
        for phi in phis:
            for seed in range(1, seeds + 1):
                for method in STACKING:
                    name = f"{group}-{phi}-{method}-s{seed}"
                    if name not in results:
                        keep(run_case(name, d, edge, law, method, phi, seed))
    for group, edges in SCALING.items():
        if only and group not in only:
            continue
        d, _, law, phis = GROUPS[group]
        for edge in edges:
            name = f"scaling-{group}-{edge}"
            if name not in results:
                keep(run_case(name, d, edge, law, "contacts_first", phis[0], 1))


if __name__ == "__main__":
    main()
