#!/usr/bin/python3
"""How dense the front packs each shape family, against the physical references, per lever of the
orientation choice (the roll, orientation trials, pocket trials), what each lever costs, and the
texture it leaves about the seed point.

Every run is one whole `frontpack pack` process on one core (flock'ed against other timed runs),
with the issue's protocol: circumscribed radii U[0.5, 1], isotropic orientations, a box of side 12
(3D; 6 largest diameters) or a square of side 30 (2D). Figures come from each run's record: the
solid fraction of the core (2 r_max inside every wall) and of the whole container, within 2 r_max
of the walls, coordination, the orientation tests' smallest p and the nematic order about z, the
validation's verdict; the texture about the seed point is computed here from the packing
(radial_texture); the rate is particles per CPU-second of the whole process (user + system
time of the child, so the analysis and the output are in it) and per second of packing.

    FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/shape-density/run.py [all|families|sweeps|mixture|report] [FAMILY,...]

results.json keeps every run (a rerun of one part replaces its rows); `report` (also run after
each part) writes RESULTS.md's measured tables and the figures rate_vs_core.png, aspect_ratio.png,
wall_layers.png.
"""
import fcntl
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import runkit  # noqa: E402

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results.json"
SEEDS = [1, 2, 3]
SIZE = "size: {distribution: uniform, min: 0.5, max: 1}"

# Family: (dimension, the template's shape lines, reference (value, source), optional cap in seconds).
FAMILIES = {
    "sphere": (3, "shape: sphere", (0.645, "RCP of U[r, 2r] spheres (issue's reference)")),
    "cube": (3, "shape: polyhedron\n    preset: cube", (0.637, "maximally dense random, Liu et al. 2017; vibrated dice 0.67, Baker & Kudrolli 2010")),
    "tetrahedron": (3, "shape: polyhedron\n    preset: tetrahedron", (0.76, "dice poured and shaken 0.76 +- 0.02, Jaoshvili et al. 2010; MRJ 0.763 (Jiao & Torquato 2011, recalled)")),
    "icosahedron": (3, "shape: polyhedron\n    preset: icosahedron", (0.707, "MRJ (Jiao & Torquato 2011, recalled); vibrated dice 0.59, Baker & Kudrolli 2010")),
    "capsule L/D 0.5": (3, "shape: spherocylinder\n    aspect_ratio: 0.6666666666666666", (0.72, "MRJ 0.721 at L/D 0.45, Imaz Gonzalez et al. 2023")),
    "capsule L/D 1": (3, "shape: spherocylinder\n    aspect_ratio: 0.5", (0.70, "MRJ at L/D = 1, Imaz Gonzalez et al. 2023 (issue's reference)")),
    "capsule L/D 2": (3, "shape: spherocylinder\n    aspect_ratio: 0.3333333333333333", (0.66, "MRJ near L/D = 2, read off Imaz Gonzalez et al. 2023's curve (approximate)")),
    "ellipsoid 1.25:1:0.8": (3, "shape: ellipsoid\n    axes: [1.25, 1, 0.8]", (0.735, "Donev et al. 2004; 0.74 +- 0.005 in experiment, Man et al. 2005")),
    "dimer": (3, "shape: cluster\n    preset: dimer", (0.70, "tangent dimers, mean field 0.707 (Baule et al. 2013); simulated peak near aspect 1.5")),
    "trimer": (3, "shape: cluster\n    preset: trimer", (0.64, "closed tangent trimers below the monomer's 0.64 (Griffith & Hoy 2019, ranking only)")),
    "cylinder": (3, "shape: cylinder\n    aspect_ratio: 1", (None, "no reference found"), 120),
    "disk": (2, "shape: sphere", (0.84, "polydisperse disks, Meer et al. 2024; bidisperse 0.84, Schreck et al. 2011")),
    "square": (2, "shape: polygon\n    sides: 4", (None, "no random jammed value found")),
    "hexagon": (2, "shape: polygon\n    sides: 6", (None, "no random jammed value found")),
    "ellipse 1.5:1": (2, "shape: ellipse\n    axes: [1.5, 1]", (0.89, "jammed ellipses peak 0.891-0.897 at aspect 1.3-1.45 (Donev 2007, Rocks & Hoy 2023)")),
    "stadium L/D 1": (2, "shape: spherocylinder\n    aspect_ratio: 0.5", (None, "peak of 2D spherocylinders near this shape (Marschall & Teitel 2018), value not found")),
    "disk dimer": (2, "shape: cluster\n    preset: dimer", (None, "Schreck, Xu & O'Hern 2010, value not found")),
}
# Lever: the packer keys it sets. The lab frame's levers turn particles about any axis (the
# defaults before the radial frame); the radial frame's turn them about the radius only.
LEVERS = {
    "lab: plain": {"orientation_frame": "lab", "roll_steps": 0, "orientation_trials": 1, "pocket_trials": 0},
    "lab: roll 60": {"orientation_frame": "lab", "roll_steps": 60, "orientation_trials": 1, "pocket_trials": 0},
    "lab: roll 60, trials 4": {"orientation_frame": "lab", "roll_steps": 60, "orientation_trials": 4, "pocket_trials": 0},
    "lab: roll 60, trials 2 face to face": {"orientation_frame": "lab", "roll_steps": 60, "orientation_trials": 2,
                                            "pocket_trials": 0, "face_to_face": "true"},
    "lab: roll 60, pocket 32": {"orientation_frame": "lab", "roll_steps": 60, "orientation_trials": 1, "pocket_trials": 32},
    "radial: plain": {"orientation_frame": "radial", "roll_steps": 0, "orientation_trials": 1, "pocket_trials": 0},
    "radial: roll 60, pocket 32 (default)": {"orientation_frame": "radial", "roll_steps": 60, "orientation_trials": 1,
                                             "pocket_trials": 32},
    "radial: roll 60, trials 4, pocket 32": {"orientation_frame": "radial", "roll_steps": 60, "orientation_trials": 4,
                                             "pocket_trials": 32},
}
DEFAULT = "radial: roll 60, pocket 32 (default)"
# The face-to-face trials apply to polytopes only.
POLYTOPES = {"cube", "tetrahedron", "icosahedron", "square", "hexagon"}
# The aspect-ratio sweeps (default lever): prolate spheroids [a, 1, 1] and capsules by L/D.
SPHEROIDS = [1.0, 1.25, 1.5, 2.0, 3.0]
CAPSULES = [0.25, 0.5, 1.0, 2.0, 3.0]


def scene_text(dimension, shape, packer, seed, container=None, extra=""):
    container = container or ("{type: box, min: [0, 0, 0], max: [12, 12, 12]}" if dimension == 3
                              else "{type: rectangle, min: [0, 0], max: [30, 30]}")
    keys = ", ".join(f"{k}: {v}" for k, v in packer.items())
    return (f"dimension: {dimension}\nseed: {seed}\ncontainer: {container}\nparticles:\n  - {shape}\n    {SIZE}\n"
            f"packer: {{{keys}}}\n{extra}")


def radial_texture(packing, dimension, core_margin=2.0):
    """The orientations' texture about the seed point (the box's centre), from the packing file:
    over the particles of the core farther than 2 from the seed, the mean P2 of the body x axis
    against the radius (3D <P2(a.r)>, 2D <cos 2 psi>; 0 when isotropic) and the mean of
    sum_i (e_i.r)^4 over the body axes (isotropic: 3/5 in 3D, 3/4 in 2D; above it, a face or axis
    of the body along the radius, below it across), which sees the texture of cubes that the axis'
    P2 cannot. Returns (p2, p2 noise, c4, c4 noise, particles counted)."""
    import numpy as np
    d = json.loads(Path(packing).read_text())
    P = np.array([p["position"] for p in d["particles"]], dtype=float)
    w, x, y, z = np.array([p["quaternion"] for p in d["particles"]], dtype=float).T
    axes = np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], 1),
                     np.stack([2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)], 1),
                     np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], 1)], 1)[:, :dimension, :dimension]
    side = 12.0 if dimension == 3 else 30.0
    c = np.full(dimension, side / 2)
    r = P[:, :dimension] - c
    rn = np.linalg.norm(r, axis=1)
    keep = (rn > 2) & np.all(np.abs(r) < side / 2 - core_margin, axis=1)
    if keep.sum() < 10:
        return None
    dots = np.einsum("kij,kj->ki", axes[keep], r[keep] / rn[keep][:, None])
    p2 = 1.5 * dots[:, 0] ** 2 - 0.5 if dimension == 3 else 2 * dots[:, 0] ** 2 - 1
    c4 = np.sum(dots ** 4, axis=1)
    n = int(keep.sum())
    return float(p2.mean()), float(p2.std() / n ** 0.5), float(c4.mean()), float(c4.std() / n ** 0.5), n


def run(name, text, **info):
    """One frontpack pack of the scene text: the figures of its record and the CPU time of the process."""
    with tempfile.TemporaryDirectory(prefix="fp-shape-density-") as tmp:
        scene = Path(tmp) / "scene.yaml"
        scene.write_text(text)
        record = Path(tmp) / "record.json"
        with open(runkit.LOCK, "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.monotonic()
            p = subprocess.run([runkit.FRONTPACK, "pack", str(scene), "-o", str(Path(tmp) / "out.json"), "--record", str(record)],
                               capture_output=True, text=True)
            wall = time.monotonic() - t0
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        if p.returncode not in (0, 3, 4) or not record.exists():  # 3: a failed verdict, 4: a stop left the box unfilled
            raise SystemExit(f"{name}: frontpack failed ({p.returncode}): {p.stderr[-800:]}")
        r = json.loads(record.read_text())
        texture = radial_texture(Path(tmp) / "out.json", r["dimension"]) if Path(tmp, "out.json").exists() else None
    m, c, a = r["metrics"], r["counters"], r["analysis"]
    fits = [f for f in a["validation"].get("orientations", []) if f]
    row = dict(info, name=name, n=r["n"], core=m["volume_fraction_core"], container=m["volume_fraction_container"],
               wall_layer=m.get("volume_fraction_wall_layer"), coordination=m["mean_coordination"],
               rattlers=m["rattler_fraction"], order=m.get("orientation_order"),
               axis_order=fits[0]["order"] if fits else None, axis_noise=fits[0]["order_noise"] if fits else None,
               orientation_p=min((t["p"] for f in fits for t in f["tests"].values()), default=None),
               sizes_p=m["radii_pvalue"], valid=r["info"]["validation"], stop=r["info"]["stop_reason"],
               pack_seconds=r["timings"]["pack"], cpu_seconds=cpu, wall_seconds=wall,
               roll_turns=c.get("roll_turns", 0), roll_kept=c.get("roll_kept", 0), solves=c["solves"],
               pocket_kept=c.get("pocket_kept", 0), radial_p2=texture[0] if texture else None,
               radial_p2_noise=texture[1] if texture else None, radial_c4=texture[2] if texture else None,
               radial_c4_noise=texture[3] if texture else None,
               minimisations=c.get("minimisations", 0), wall_profile=a["volume_fraction"].get("wall_profile"))
    print(f"{name:60s} n={row['n']:6d} core {row['core']:.4f} container {row['container']:.4f} "
          f"{row['n'] / cpu:8.0f}/cpu-s  orientation p {row['orientation_p'] if row['orientation_p'] is not None else float('nan'):.3g} "
          f"{row['valid']}", flush=True)
    return row


def families(only=None):
    rows = []
    for family, spec in FAMILIES.items():
        if only and family not in only:
            continue
        dimension, shape, _ = spec[:3]
        cap = spec[3] if len(spec) > 3 else None
        levers = ["lab: plain", "lab: roll 60", DEFAULT] if cap else [l for l in LEVERS if "face" not in l or family in POLYTOPES]
        seeds = SEEDS[:1] if cap else SEEDS
        for lever in levers:
            for seed in seeds:
                extra = f"stop: {{time: {cap}}}\n" if cap else ""
                rows.append(run(f"{family} / {lever} / seed {seed}", scene_text(dimension, shape, LEVERS[lever], seed, extra=extra),
                                part="families", family=family, lever=lever, seed=seed, dimension=dimension, cap=cap))
    return rows


def sweeps():
    rows = []
    for a in SPHEROIDS:
        for seed in SEEDS[:2]:
            rows.append(run(f"spheroid {a} / seed {seed}", scene_text(3, f"shape: ellipsoid\n    axes: [{a}, 1, 1]", {}, seed),
                            part="sweeps", sweep="spheroid", aspect=a, seed=seed))
    for ld in CAPSULES:
        for seed in SEEDS[:2]:
            rows.append(run(f"capsule L/D {ld} / seed {seed}",
                            scene_text(3, f"shape: spherocylinder\n    aspect_ratio: {1 / (1 + ld)!r}", {}, seed),
                            part="sweeps", sweep="capsule", aspect=ld, seed=seed))
    return rows


def mixture():
    # Half cubes, half spheres by number, in a cylinder (the case), capped at 120 s.
    text = ("dimension: 3\nseed: 1\ncontainer: {type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 6, height: 12}\n"
            f"particles:\n  - shape: polyhedron\n    preset: cube\n    {SIZE}\n  - shape: sphere\n    {SIZE}\n"
            "stop: {time: 120}\n")
    return [run("cubes and spheres in a cylinder / seed 1", text, part="mixture", seed=1)]


def mean_sd(values):
    values = [v for v in values if v is not None]
    if not values:
        return float("nan"), float("nan")
    m = sum(values) / len(values)
    return m, (sum((v - m) ** 2 for v in values) / (len(values) - 1)) ** 0.5 if len(values) > 1 else 0.0


def decorate(ax, xlabel, ylabel, title, fontsize=7):
    """An axis' labels, title, grid and legend, alike in every figure."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=fontsize)


def save(fig, name):
    import matplotlib.pyplot as plt
    fig.tight_layout()
    fig.savefig(HERE / name, dpi=110)
    plt.close(fig)


def report(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = []
    fam = [r for r in rows if r["part"] == "families"]
    table_rows = []
    for family, spec in FAMILIES.items():
        ref, source = spec[2]
        for lever in LEVERS:
            g = [r for r in fam if r["family"] == family and r["lever"] == lever]
            if not g:
                continue
            core, core_sd = mean_sd([r["core"] for r in g])
            cont, _ = mean_sd([r["container"] for r in g])
            layer, _ = mean_sd([r["wall_layer"] for r in g])
            rate, _ = mean_sd([r["n"] / r["cpu_seconds"] for r in g])
            z, _ = mean_sd([r["coordination"] for r in g])
            s, _ = mean_sd([r["axis_order"] for r in g])
            noise, _ = mean_sd([r["axis_noise"] for r in g])
            op = min((r["orientation_p"] for r in g if r["orientation_p"] is not None), default=float("nan"))
            p2, _ = mean_sd([r.get("radial_p2") for r in g])
            p2_noise, _ = mean_sd([r.get("radial_p2_noise") for r in g])
            c4, _ = mean_sd([r.get("radial_c4") for r in g])
            c4_noise, _ = mean_sd([r.get("radial_c4_noise") for r in g])
            texture = (f"{p2:+.3f} / {c4 - (0.6 if spec[0] == 3 else 0.75):+.3f} (±{2 * p2_noise / len(g) ** 0.5:.3f} / "
                       f"±{2 * c4_noise / len(g) ** 0.5:.3f})" if p2 == p2 and family != "sphere" and family != "disk" else "–")
            valid = "all ok" if all(r["valid"] == "ok" for r in g) else ", ".join(sorted({r["valid"] for r in g}))
            ratio = f"{core / ref:.3f}" if ref else "–"
            cap = f" (cap {g[0]['cap']} s)" if g[0].get("cap") else ""
            table_rows.append([f"{family}{cap}", lever, len(g), f"{mean_sd([r['n'] for r in g])[0]:,.0f}",
                               f"{core:.4f} ± {core_sd:.4f}", f"{ref:.3f}" if ref else "–", ratio, f"{cont:.4f}", f"{layer:.4f}",
                               f"{rate:,.0f}", f"{z:.2f}", f"{s:+.3f} ({noise:.3f})", f"{op:.2g}", texture, valid])
    out += ["### Every family, every lever", "",
            runkit.table(["family", "lever", "runs", "N", "core VF (mean ± sd)", "reference", "core / reference",
                          "container VF", "within 2 r_max of walls", "particles / CPU-s", "z",
                          "order S about z (noise)", "smallest orientation p",
                          "texture about the seed: radial P2 / c4 - isotropic (2 sd)", "validation"], table_rows), ""]
    out += ["References (core VF's yardstick):", ""]
    out += [f"* {family}: {spec[2][0] if spec[2][0] else '–'}: {spec[2][1]}" for family, spec in FAMILIES.items()]
    out += [""]

    sw = [r for r in rows if r["part"] == "sweeps"]
    if sw:
        srows = []
        for kind, values in (("spheroid", SPHEROIDS), ("capsule", CAPSULES)):
            for a in values:
                g = [r for r in sw if r["sweep"] == kind and r["aspect"] == a]
                if g:
                    core, core_sd = mean_sd([r["core"] for r in g])
                    srows.append([kind, a, len(g), f"{core:.4f} ± {core_sd:.4f}", f"{mean_sd([r['container'] for r in g])[0]:.4f}",
                                  f"{mean_sd([r['n'] / r['cpu_seconds'] for r in g])[0]:,.0f}",
                                  "all ok" if all(r["valid"] == "ok" for r in g) else "FAILED"])
        out += ["### Solid fraction against aspect ratio (defaults)", "",
                runkit.table(["family", "aspect (spheroid a/b; capsule L/D)", "runs", "core VF", "container VF",
                              "particles / CPU-s", "validation"], srows), ""]
        fig, ax = plt.subplots(figsize=(5.5, 3.8))
        for kind, values, label in (("spheroid", SPHEROIDS, "prolate spheroids, a/b"), ("capsule", CAPSULES, "spherocylinders, 1 + L/D")):
            xs, ys, es = [], [], []
            for a in values:
                g = [r["core"] for r in sw if r["sweep"] == kind and r["aspect"] == a]
                if g:
                    m, e = mean_sd(g)
                    xs.append(a if kind == "spheroid" else 1 + a)
                    ys.append(m)
                    es.append(e)
            ax.errorbar(xs, ys, yerr=es, marker="o", capsize=3, label=label)
        decorate(ax, "aspect ratio (length / width)", "core solid fraction", "frontpack defaults; physics peaks near 1.4-1.5",
              fontsize=8)
        save(fig, "aspect_ratio.png")

    mix = [r for r in rows if r["part"] == "mixture"]
    if mix:
        r = mix[0]
        out += ["### Cubes and spheres in a cylinder", "",
                runkit.table(["N", "container VF", "core VF", "particles / CPU-s", "minimisations", "stop", "validation"],
                             [[r["n"], f"{r['container']:.4f}", f"{r['core']:.4f}", f"{r['n'] / r['cpu_seconds']:,.1f}",
                               r["minimisations"], r["stop"], r["valid"]]]), ""]

    if fam:
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
        for ax, dimension in zip(axes, (3, 2)):
            for family, spec in FAMILIES.items():
                if spec[0] != dimension:
                    continue
                colour = None
                for frame, style in (("lab", "o-"), ("radial", "s--")):
                    xs, ys = [], []
                    for lever in LEVERS:
                        g = [r for r in fam if r["family"] == family and r["lever"] == lever and lever.startswith(frame)]
                        if g:
                            xs.append(mean_sd([r["core"] for r in g])[0])
                            ys.append(mean_sd([r["n"] / r["cpu_seconds"] for r in g])[0])
                    if xs:
                        line, = ax.plot(xs, ys, style, ms=4, color=colour, label=family if colour is None else None)
                        colour = line.get_color()
                if colour and spec[2][0]:
                    ax.axvline(spec[2][0], color=colour, lw=0.6, ls=":")
            ax.set_yscale("log")
            decorate(ax, "core solid fraction (dotted: the family's reference)", "particles per CPU-second (whole run)",
                  f"{dimension}D levers: lab frame (solid), radial frame (dashed)")
        save(fig, "rate_vs_core.png")

    if fam:
        # The wall layers of every family with the defaults (seed 1): the profile from the walls.
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
        for ax, dimension in zip(axes, (3, 2)):
            for k, (family, spec) in enumerate(f for f in FAMILIES.items() if f[1][0] == dimension):
                g = [r for r in fam if r["family"] == family and r["lever"] == DEFAULT and r["seed"] == 1]
                if not g or not g[0].get("wall_profile"):
                    continue
                w = g[0]["wall_profile"]
                style = "o-" if k < 10 else "s--"  # the colour cycle has 10
                line, = ax.plot([d / (4 * w["width"]) for d in w["distance"]], w["vf"], style, ms=3, label=family)
                ax.axhline(g[0]["core"], color=line.get_color(), lw=0.6, ls=":")
            decorate(ax, "distance from the walls / r_max (shells of r_max / 4)", "solid fraction in the shell (dotted: the core)",
                  f"{dimension}D wall layers, defaults (seed 1)")
        save(fig, "wall_layers.png")

    text = "\n".join(out) + "\n"
    (HERE / "measured.md").write_text(text)
    print(text)


def main():
    part = sys.argv[1] if len(sys.argv) > 1 else "all"
    only = set(sys.argv[2].split(",")) if len(sys.argv) > 2 else None  # families: a subset (comma-separated names)
    rows = json.loads(RESULTS.read_text())["rows"] if RESULTS.exists() else []
    parts = {"families": families, "sweeps": sweeps, "mixture": mixture}
    todo = list(parts) if part == "all" else [] if part == "report" else [part]
    for p in todo:
        new = parts[p](only) if p == "families" else parts[p]()
        replaced = {(r["family"], r["lever"]) for r in new} if p == "families" and only else None
        rows = [r for r in rows if r["part"] != p or (replaced is not None and (r["family"], r["lever"]) not in replaced)] + new
        RESULTS.write_text(json.dumps({"provenance": runkit.provenance_lines(runkit.FRONTPACK, sys.argv), "rows": rows}))
    report(rows)


if __name__ == "__main__":
    main()
