#!/usr/bin/python3
"""Wrapper intersection against potential minimisation (paper 004, Sect. 3.1 and 3.2): the same
scenes packed with `packer.contact_solver: auto` (the closed-form wrapper solvers where they reach,
contact/*_wrapper_solver.cpp, and the gap Newton solver for 3D capsules) and `minimisation` (every
contact problem by NLopt + FCL), 3 seeds:
particles per second, the fraction filled, the contact accuracy (the largest |gap| among the
contacts, relative to the smaller circumscribed radius), the largest overlap and the coordination.
Paper 004, Fig. 6: 2D clusters of 4 disks in a square of side 20 by wrappers, 73 particles at
1.05 particles/s, area fraction 77.21 %; 3D clusters (capsule approximations) in a cube of side 40
by approximate wrappers, 4,778 particles at 172.3 particles/s, volume fraction 36.68 %.

Usage (from anywhere):
    FRONTPACK=/path/to/frontpack /usr/bin/python3 experiments/wrappers-vs-minimisation/run.py [--report]
Writes RESULTS.md, runs.csv, figures/rate-vs-fraction.png and the scenes that were run (scenes/).
Runs already in runs.csv are kept (delete it to start over); --report rebuilds RESULTS.md and the
figure from runs.csv alone. Every run is wrapped in
`flock /tmp/frontpack-bench.lock` so that timed runs never overlap.
"""
import csv
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from runkit import FRONTPACK, LOCK, mean, provenance_lines, sd, table  # noqa: E402

HERE = Path(__file__).resolve().parent
SEEDS = [1, 2, 3]
SOLVERS = ["auto", "minimisation"]

U12 = {"distribution": "uniform", "min": 1, "max": 2}


def row_cluster(D, n):
    """n balls in a row, a capsule approximation (the paper's Fig. 6 clusters)."""
    centres = [[-0.5 + i / (n - 1)] + [0] * (D - 1) for i in range(n)]
    return {"shape": "cluster", "centers": centres, "radii": [0.5] * n, "size": U12, "orientation": "random"}


def box(D, side):
    return {"type": "box" if D == 3 else "rectangle", "min": [0] * D, "max": [side] * D}


# (name, dimension, container, particle templates, stop, seeds, solvers, note)
CASES = [
    ("2D clusters of 4 disks, square 20 (Fig. 6)", 2, box(2, 20), [row_cluster(2, 4)], None, SEEDS, SOLVERS,
     "paper, wrappers: 73 particles, 1.05 particles/s, AF 0.7721"),
    ("2D capsules, square 20 (Fig. 6)", 2, box(2, 20),
     [{"shape": "spherocylinder", "aspect_ratio": 0.5, "size": U12, "size_on": "circumscribed_radius", "orientation": "random"}],
     None, SEEDS, SOLVERS, "paper, minimisation: 77 particles, 0.0094 particles/s, AF 0.8220"),
    ("2D hexagons, square 20", 2, box(2, 20), [{"shape": "polygon", "sides": 6, "size": U12, "orientation": "random"}], None, SEEDS,
     SOLVERS, ""),
    ("2D hexagons and triangles (shapes-polygons-2d)", 2, box(2, 15),
     [{"shape": "polygon", "sides": 6, "size": {"distribution": "uniform", "min": 0.5, "max": 1}, "fraction": 3},
      {"shape": "polygon", "vertices": [[0, 0], [2, 0], [0, 1]], "size": {"distribution": "uniform", "min": 0.5, "max": 1}, "fraction": 1}],
     None, SEEDS, SOLVERS, ""),
    ("3D clusters of 3 spheres (shapes-clusters)", 3, box(3, 12),
     [{"shape": "cluster", "centers": [[-0.5, 0, 0], [0.5, 0, 0], [0.5, 0.8, 0]], "radii": [0.5, 0.5, 0.4],
       "size": {"distribution": "uniform", "min": 0.5, "max": 1}}], None, SEEDS, SOLVERS, ""),
    ("3D cubes, cube 12", 3, box(3, 12), [{"shape": "polyhedron", "preset": "cube", "size": U12, "orientation": "random"}], None,
     SEEDS, SOLVERS, ""),
    ("3D icosahedra, cube 12", 3, box(3, 12), [{"shape": "polyhedron", "preset": "icosahedron", "size": U12, "orientation": "random"}],
     None, SEEDS, SOLVERS, ""),
    ("3D cubes and octahedra (shapes-polyhedra)", 3, box(3, 12),
     [{"shape": "polyhedron", "vertices": [[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)],
       "size": {"distribution": "uniform", "min": 0.5, "max": 1}, "fraction": 2},
      {"shape": "polyhedron", "vertices": [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
       "size": {"distribution": "uniform", "min": 0.5, "max": 1}, "fraction": 1}], None, SEEDS, SOLVERS, ""),
    ("3D capsules, aspect 0.5, cube 20 (gap Newton)", 3, box(3, 20),
     [{"shape": "spherocylinder", "aspect_ratio": 0.5, "size": U12, "size_on": "circumscribed_radius", "orientation": "random"}],
     None, SEEDS, SOLVERS, ""),
    ("3D capsules, aspect 0.5, cube 40 (perez-capsules-3d, gap Newton)", 3, box(3, 40),
     [{"shape": "spherocylinder", "aspect_ratio": 0.5, "size": U12, "size_on": "circumscribed_radius", "orientation": "random"}],
     None, [1], SOLVERS, "paper, minimisation: 5,901 particles, 3.90 particles/s, VF 0.4577"),
    ("3D clusters of 4 spheres, cube 40 (Fig. 6)", 3, box(3, 40), [row_cluster(3, 4)], None, [1], SOLVERS,
     "paper, approximate wrappers: 4,778 particles, 172.3 particles/s, VF 0.3668"),
]


def scene_text(name, D, container, templates, stop, solver):
    doc = {"dimension": D, "seed": 1, "container": container, "particles": templates, "packer": {"contact_solver": solver}}
    if stop:
        doc["stop"] = stop
    return f"# Generated by experiments/wrappers-vs-minimisation/run.py: {name}, contact_solver {solver}\n" + \
        yaml.safe_dump(doc, default_flow_style=None, sort_keys=False)


def slug(name, solver):
    keep = "".join(c if c.isalnum() else "-" for c in name.split(" (")[0].lower())
    return "-".join(p for p in keep.split("-") if p) + "-" + solver


FIELDS = ["case", "solver", "seed", "n", "fraction", "pack_s", "rate", "contact_gap", "overlap", "coordination", "stop"]


def run_all():
    """Runs every (case, solver, seed) not yet in runs.csv, appending each row as it finishes."""
    csv_path = HERE / "runs.csv"
    done = {(r["case"], r["solver"], r["seed"]) for r in load()} if csv_path.exists() else set()
    if not csv_path.exists():
        with open(csv_path, "w", newline="") as f:
            csv.DictWriter(f, fieldnames=FIELDS).writeheader()
    (HERE / "scenes").mkdir(exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="fp-wrappers-") as tmp:
        for name, D, container, templates, stop, seeds, solvers, _ in CASES:
            for solver in solvers:
                path = HERE / "scenes" / f"{slug(name, solver)}.yaml"
                path.write_text(scene_text(name, D, container, templates, stop, solver))
                for seed in seeds:
                    if (name, solver, seed) in done:
                        continue
                    out, rec = Path(tmp) / "out.csv", Path(tmp) / "rec.json"
                    cmd = ["flock", LOCK, FRONTPACK, "pack", str(path), "--seed", str(seed), "-q", "-o", str(out), "--record", str(rec)]
                    p = subprocess.run(cmd, capture_output=True, text=True)
                    if p.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
                        raise SystemExit(f"{' '.join(cmd)} failed ({p.returncode}): {p.stderr}")
                    r = json.loads(rec.read_text())
                    m = r["metrics"]
                    row = {"case": name, "solver": solver, "seed": seed, "n": r["n"], "fraction": m["volume_fraction_container"],
                           "pack_s": r["timings"]["pack"], "rate": m["particles_per_second"],
                           "contact_gap": m["max_contact_gap_over_smaller_radius"], "overlap": m["max_overlap_over_smaller_radius"],
                           "coordination": m["mean_coordination"], "stop": r["info"]["stop_reason"]}
                    print(row, flush=True)
                    with open(csv_path, "a", newline="") as f:
                        csv.DictWriter(f, fieldnames=FIELDS).writerow(row)


def load():
    with open(HERE / "runs.csv") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in ("n", "seed"):
            r[k] = int(r[k])
        for k in ("fraction", "pack_s", "rate", "contact_gap", "overlap", "coordination"):
            r[k] = float(r[k])
    return rows


def fmt(rows, k, digits):
    m = mean(rows, k)
    return f"{m:.{digits}f}" + (f" ± {sd(rows, k):.{digits}f}" if len(rows) > 1 else "")


def report(argv):
    rows = load()
    lines = ["# Wrapper intersection against potential minimisation", ""]
    lines += provenance_lines(FRONTPACK, argv)
    lines += ["", "Every scene packed with `frontpack pack SCENE --seed S -q -o out.csv --record rec.json` (one core; the other",
              "core of this 2-core machine was busy with builds meanwhile: rates ±30 %), once with",
              "`packer: {contact_solver: auto}` (the default: the wrapper solvers where they reach, the gap Newton",
              "solver for 3D capsules, minimisation elsewhere) and once with `contact_solver: minimisation` (every problem by NLopt `slsqp` through FCL).",
              "Scenes: `scenes/`. `fraction` is the area (2D) or volume (3D) fraction of the container; `contact |gap|` the",
              "largest |gap| among the contacting pairs (|gap| <= 1e-6 x the smaller circumscribed radius), relative to",
              "that radius: how exactly the solver made them touch; `overlap` the largest overlap, likewise. Mean ± sd",
              "over the seeds.", ""]
    header = ["case", "solver", "seeds", "N", "fraction", "particles/s", "speed-up", "contact |gap|", "overlap", "coordination", "stop"]
    out = []
    cases = []
    for r in rows:
        if r["case"] not in cases:
            cases.append(r["case"])
    for case in cases:
        by = {s: [r for r in rows if r["case"] == case and r["solver"] == s] for s in SOLVERS}
        for s in SOLVERS:
            g = by[s]
            if not g:
                continue
            other = by["minimisation"] if s == "auto" else []
            speed = f"{mean(g, 'rate') / mean(other, 'rate'):.1f}x" if other else ""
            out.append([case, s, len(g), fmt(g, "n", 0), fmt(g, "fraction", 4), fmt(g, "rate", 0), speed,
                        f"{max(r['contact_gap'] for r in g):.1e}", f"{max(r['overlap'] for r in g):.1e}", fmt(g, "coordination", 2),
                        g[0]["stop"]])
    lines += [table(header, out), ""]
    notes = [(c[0], c[7]) for c in CASES if c[7]]
    lines += ["Paper 004's figures for the same cases:", ""] + [f"* {c}: {n}" for c, n in notes] + [""]
    lines += ["![rate against fraction](figures/rate-vs-fraction.png)", ""]
    (HERE / "RESULTS.md").write_text("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for case in cases:
        pts = []
        for s, marker in (("auto", "o"), ("minimisation", "s")):
            g = [r for r in rows if r["case"] == case and r["solver"] == s]
            if g and g[0]["stop"] != "time limit":
                pts.append((mean(g, "fraction"), mean(g, "rate"), marker))
        if len(pts) == 2:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], color="0.7", zorder=1)
        for x, y, marker in pts:
            ax.scatter([x], [y], marker=marker, color="C0" if marker == "o" else "C3", zorder=2)
        if pts:
            ax.annotate(case.split(" (")[0], (pts[0][0], pts[0][1]), fontsize=7, xytext=(4, 3), textcoords="offset points")
    ax.scatter([], [], marker="o", color="C0", label="auto (wrappers, gap Newton)")
    ax.scatter([], [], marker="s", color="C3", label="minimisation")
    ax.set_yscale("log")
    ax.set_xlabel("fraction of the container filled")
    ax.set_ylabel("particles per second (one core)")
    ax.legend()
    ax.grid(alpha=0.3)
    (HERE / "figures").mkdir(exist_ok=True)
    fig.tight_layout()
    fig.savefig(HERE / "figures" / "rate-vs-fraction.png", dpi=120)


if __name__ == "__main__":
    if "--report" not in sys.argv[1:]:
        run_all()
    report(sys.argv)
