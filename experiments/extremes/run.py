"""Numerical stability at the extremes: every case packed by one binary,
each with a timeout, its own validation verdict and `frontpack validate` of the written file,
and compared with its reference case (the same scene at the origin, scale 1).

  FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/extremes/run.py [--label after] [--timeout 120]

Each run appends its rows to runs-<label>.csv; RESULTS.md is rebuilt from every runs-*.csv present
(a "before" run of the binary of main before the issue, an "after" run of the current one).
The cases mirror the ctest suite tests/front/test_front_extremes.cpp, which asserts them.
"""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import runkit  # noqa: E402

HERE = Path(__file__).resolve().parent
FEMUR = runkit.REPO / "tests" / "data" / "meshes" / "femur.off"


# ---- meshes -------------------------------------------------------------------------------

def read_off(path):
    rows = [l.split() for l in Path(path).read_text().splitlines() if l.strip() and not l.startswith("#")]
    nv, nf = int(rows[1][0]), int(rows[1][1])
    v = [tuple(float(x) for x in r[:3]) for r in rows[2:2 + nv]]
    f = [tuple(int(x) for x in r[1:1 + int(r[0])]) for r in rows[2 + nv:2 + nv + nf]]
    return v, f


def write_off(path, v, f):
    lines = ["OFF", f"{len(v)} {len(f)} 0"]
    lines += [" ".join(repr(c) for c in p) for p in v]
    lines += [f"{len(t)} " + " ".join(str(i) for i in t) for t in f]
    Path(path).write_text("\n".join(lines) + "\n")


def trefoil_tube(turns=240, around=16, tube=0.035, scale=0.1):
    """A closed tube around a trefoil knot: a mesh with long thin parts (tube radius 0.035)."""
    def centre(t):
        return (scale * (math.sin(t) + 2 * math.sin(2 * t)), scale * (math.cos(t) - 2 * math.cos(2 * t)),
                scale * -math.sin(3 * t))
    v, f = [], []
    for i in range(turns):
        t = 2 * math.pi * i / turns
        c, c2 = centre(t), centre(t + 1e-4)
        d = [b - a for a, b in zip(c, c2)]
        n = math.sqrt(sum(x * x for x in d))
        d = [x / n for x in d]
        a = [0.0, 0.0, 1.0] if abs(d[2]) < 0.9 else [1.0, 0.0, 0.0]
        e1 = [a[1] * d[2] - a[2] * d[1], a[2] * d[0] - a[0] * d[2], a[0] * d[1] - a[1] * d[0]]
        n1 = math.sqrt(sum(x * x for x in e1))
        e1 = [x / n1 for x in e1]
        e2 = [d[1] * e1[2] - d[2] * e1[1], d[2] * e1[0] - d[0] * e1[2], d[0] * e1[1] - d[1] * e1[0]]
        for k in range(around):
            phi = 2 * math.pi * k / around
            v.append(tuple(c[j] + tube * (math.cos(phi) * e1[j] + math.sin(phi) * e2[j]) for j in range(3)))
    for i in range(turns):
        for k in range(around):
            a, b = i * around + k, i * around + (k + 1) % around
            c, d = ((i + 1) % turns) * around + k, ((i + 1) % turns) * around + (k + 1) % around
            f += [(a, c, b), (b, c, d)]
    return v, f


def translated(v, offset):
    return [tuple(c + offset for c in p) for p in v]


# ---- scenes ---------------------------------------------------------------------------------

def yaml_list(xs):
    return "[" + ", ".join(repr(float(x)) if not isinstance(x, list) else yaml_list(x) for x in xs) + "]"


def uniform(lo, hi):
    return f"{{distribution: uniform, min: {lo!r}, max: {hi!r}}}"


def bimodal(lo, hi, width=0.1, small_weight=50, large_weight=50):
    """Two narrow modes, [lo, lo (1 + width)] and [hi (1 - width), hi], weights by count."""
    return (f"{{distribution: histogram, edges: {yaml_list([lo, lo * (1 + width), hi * (1 - width), hi])}, "
            f"weights: [{small_weight}, 0, {large_weight}]}}")


def scene(dimension, container, radius, seed=42, packer=None, stop=None):
    text = f"dimension: {dimension}\nseed: {seed}\ncontainer: {container}\nparticles: {{radius: {radius}}}\n"
    if packer:
        text += f"packer: {packer}\n"
    if stop:
        text += f"stop: {stop}\n"
    return text


def box3(o=0.0, s=1.0, **kw):
    lo, hi = [o] * 3, [o + 0.5 * s] * 3
    return scene(3, f"{{type: box, min: {yaml_list(lo)}, max: {yaml_list(hi)}}}", uniform(0.01 * s, 0.02 * s), **kw)


def rect2(o=0.0, s=1.0, **kw):
    lo, hi = [o] * 2, [o + 0.6 * s] * 2
    return scene(2, f"{{type: rectangle, min: {yaml_list(lo)}, max: {yaml_list(hi)}}}", uniform(0.004 * s, 0.008 * s),
                 **kw)


def cyl3(o=0.0, s=1.0):
    return scene(3, f"{{type: cylinder, base: {yaml_list([o] * 3)}, axis: [0, 0, 1], radius: {0.3 * s!r}, "
                    f"height: {0.5 * s!r}}}", uniform(0.01 * s, 0.02 * s))


def ball3(o=0.0, s=1.0):
    return scene(3, f"{{type: sphere, center: {yaml_list([o] * 3)}, radius: {0.3 * s!r}}}", uniform(0.01 * s, 0.02 * s))


def disk2(o=0.0, s=1.0):
    return scene(2, f"{{type: disk, center: {yaml_list([o] * 2)}, radius: {0.35 * s!r}}}", uniform(0.004 * s, 0.008 * s))


L_SHAPE = [[0, 0], [0.6, 0], [0.6, 0.25], [0.25, 0.25], [0.25, 0.6], [0, 0.6]]


def poly2(o=0.0, s=1.0):
    v = [[o + s * x, o + s * y] for x, y in L_SHAPE]
    return scene(2, f"{{type: polygon, vertices: {yaml_list(v)}}}", uniform(0.004 * s, 0.008 * s))


def mesh3(file, radius, o=0.0, scale=1.0):
    del o  # the offset is in the file
    return scene(3, f"{{type: mesh, file: {file}, scale: {scale!r}}}", radius, seed=1)


def many_gon(n, R=0.5):
    return [[R * math.cos(2 * math.pi * k / n), R * math.sin(2 * math.pi * k / n)] for k in range(n)]


def cases(folder):
    """(group, name, reference name or None, scene text). Mesh files are written into `folder`."""
    out = []
    fv, ff = read_off(FEMUR)
    kv, kf = trefoil_tube()
    write_off(folder / "femur.off", fv, ff)
    write_off(folder / "knot.off", kv, kf)
    for off in [1e6, 1e9]:
        write_off(folder / f"femur_{off:g}.off", translated(fv, off), ff)
        write_off(folder / f"knot_{off:g}.off", translated(kv, off), kf)
    femur_r, knot_r = uniform(0.005, 0.01), uniform(0.004, 0.008)

    builders = [("box 3D", box3), ("rectangle 2D", rect2), ("cylinder", cyl3), ("sphere", ball3), ("disk 2D", disk2),
                ("polygon 2D", poly2)]
    for label, build in builders:
        out.append(("offset", f"{label}, origin", None, build()))
        for off, name in [(1e3, "1e3"), (2.0**20, "2^20"), (1e6, "1e6"), (1e9, "1e9")]:
            out.append(("offset", f"{label}, offset {name}", f"{label}, origin", build(o=off)))
    for label, mesh, r in [("femur", "femur", femur_r), ("knot", "knot", knot_r)]:
        out.append(("offset", f"{label} mesh, origin", None, mesh3(f"{mesh}.off", r)))
        for off in [1e6, 1e9]:
            out.append(("offset", f"{label} mesh, offset {off:g}", f"{label} mesh, origin",
                        mesh3(f"{mesh}_{off:g}.off", r)))
    for label, build in [("box 3D", box3), ("rectangle 2D", rect2)]:
        for k in [-60, -30, 30, 60]:
            out.append(("scale", f"{label}, scale 2^{k}", f"{label}, origin", build(s=2.0**k)))
    for k in [-60, 60]:
        s = 2.0**k
        out.append(("scale", f"femur mesh, scale 2^{k}", "femur mesh, origin",
                    mesh3("femur.off", uniform(0.005 * s, 0.01 * s), scale=s)))
    # Wide size ratios: uniform in radius, and two narrow modes (50/50 by count).
    for ratio in [100, 1000]:
        rmax = 0.05
        rmin = rmax / ratio
        box = "{type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}"
        rect = "{type: rectangle, min: [0, 0], max: [0.6, 0.6]}"
        out.append(("ratio", f"box 3D, uniform, ratio {ratio}", None, scene(3, box, uniform(rmin, rmax))))
        out.append(("ratio", f"box 3D, bimodal, ratio {ratio}", None, scene(3, box, bimodal(rmin, rmax))))
        out.append(("ratio", f"rectangle 2D, uniform, ratio {ratio}", None, scene(2, rect, uniform(rmin, rmax))))
        out.append(("ratio", f"rectangle 2D, bimodal, ratio {ratio}", None, scene(2, rect, bimodal(rmin, rmax))))
    # The wide mixes: mostly small particles, 1 % of large ones, by count, in a unit box.
    for ratio in [100, 1000]:
        rmax = 0.1
        out.append(("ratio", f"box 1, bimodal 99:1, ratio {ratio}", None,
                    scene(3, "{type: box, min: [0, 0, 0], max: [1, 1, 1]}",
                          bimodal(rmax / ratio, rmax, small_weight=99, large_weight=1))))
        out.append(("ratio", f"square 1, bimodal 99:1, ratio {ratio}", None,
                    scene(2, "{type: rectangle, min: [0, 0], max: [1, 1]}",
                          bimodal(rmax / ratio, rmax, small_weight=99, large_weight=1))))
    # Thin containers: a monolayer cell 2.05 r_max thick, a strip, needles, a thin-necked polygon.
    rr = uniform(0.01, 0.02)
    out.append(("thin", "slab 3D, 2.05 r_max thick", None, scene(3, "{type: box, min: [0, 0, 0], max: [1, 1, 0.041]}", rr)))
    out.append(("thin", "strip 2D, 2.05 r_max wide", None, scene(2, "{type: rectangle, min: [0, 0], max: [2, 0.041]}", rr)))
    out.append(("thin", "slab 3D, 4 r_max thick", None, scene(3, "{type: box, min: [0, 0, 0], max: [1, 1, 0.08]}", rr)))
    out.append(("thin", "needle cylinder along z, radius 1.5 r_max", None,
                scene(3, "{type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 0.03, height: 2}", rr)))
    out.append(("thin", "needle cylinder along (1,1,1), radius 1.5 r_max", None,
                scene(3, "{type: cylinder, base: [0, 0, 0], axis: [1, 1, 1], radius: 0.03, height: 2}", rr)))
    out.append(("thin", "long cylinder along (1,1,1), radius 4 r_max", None,
                scene(3, "{type: cylinder, base: [0, 0, 0], axis: [1, 1, 1], radius: 0.08, height: 2}", rr)))
    neck = [[0, 0], [0.5, 0], [0.5, 0.24], [0.52, 0.24], [0.52, 0], [1, 0], [1, 0.5], [0.52, 0.5], [0.52, 0.26],
            [0.5, 0.26], [0.5, 0.5], [0, 0.5]]
    out.append(("thin", "polygon, two rooms joined by a 1 r_max neck", None,
                scene(2, f"{{type: polygon, vertices: {yaml_list(neck)}}}", uniform(0.005, 0.01))))
    out.append(("thin", "knot mesh, tube 3.5 r_max", None, mesh3("knot.off", uniform(0.005, 0.01))))
    # Degenerate and huge.
    out.append(("degenerate", "box one particle thick (2 r, constant r)", None,
                scene(3, "{type: box, min: [0, 0, 0], max: [1, 1, 0.02]}", "{distribution: constant, value: 0.01}")))
    out.append(("degenerate", "constant radius, box", None,
                scene(3, "{type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}", "{distribution: constant, value: 0.015}")))
    out.append(("degenerate", "discrete 50/50, box", None,
                scene(3, "{type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}",
                      "{distribution: discrete, values: [[0.01, 1], [0.02, 1]]}")))
    out.append(("degenerate", "seed point on a wall", None, box3(packer="{seed_point: [0, 0.25, 0.25]}")))
    out.append(("degenerate", "seed point in a corner", None, box3(packer="{seed_point: [0, 0, 0]}")))
    out.append(("degenerate", "box 1e6 wide, stop at 20000", None,
                scene(3, "{type: box, min: [0, 0, 0], max: [1000000, 1000000, 1000000]}", uniform(0.01, 0.02),
                      stop="{particles: 20000}")))
    out.append(("degenerate", "polygon with 10^5 vertices", None,
                scene(2, f"{{type: polygon, vertices: {yaml_list(many_gon(100000))}}}", uniform(0.01, 0.02))))
    out.append(("degenerate", "polygon with 10^4 vertices", None,
                scene(2, f"{{type: polygon, vertices: {yaml_list(many_gon(10000))}}}", uniform(0.01, 0.02))))
    # Limits (checked before any work): a run that could never end well is refused.
    big = lambda side: f"{{type: box, min: [0, 0, 0], max: [{side!r}, {side!r}, {side!r}]}}"
    out.append(("limits", "box 1e300 wide", None, scene(3, big(1e300), uniform(0.01, 0.02))))
    out.append(("limits", "box from -1e308 to 1e308", None,
                scene(3, "{type: box, min: [-1e308, -1e308, -1e308], max: [1e308, 1e308, 1e308]}", uniform(1e306, 2e306))))
    out.append(("limits", "box 2e-150 wide, radii 1e-152", None, scene(3, big(2e-150), uniform(1e-152, 2e-152))))
    out.append(("limits", "box 100 wide, no stop (5e10 spheres)", None, scene(3, big(100.0), uniform(0.01, 0.02))))
    out.append(("limits", "box 1e17 wide, no stop", None, scene(3, big(1e17), uniform(0.01, 0.02))))
    out.append(("limits", "box 1e17 wide, stop at 20000", None,
                scene(3, big(1e17), uniform(0.01, 0.02), stop="{particles: 20000}")))
    out.append(("limits", "box 15 wide, no stop (32 GB)", None, scene(3, big(15.0), uniform(0.01, 0.02))))
    out.append(("limits", "radius_pool 1000000, box 0.2", None,
                scene(3, big(0.2), uniform(0.01, 0.02), packer="{radius_pool: 1000000}")))
    for pool in [16, 64, 256]:
        out.append(("limits", f"radius_pool {pool}, box 0.2 (about 300 spheres)", None,
                    scene(3, big(0.2), uniform(0.01, 0.02), packer=f"{{radius_pool: {pool}}}")))
    return out


# ---- running ----------------------------------------------------------------------------------

def run_case(binary, folder, name, text, timeout):
    scene_path = folder / "scene.yaml"
    scene_path.write_text(text)
    out, record = folder / "out.csv", folder / "record.json"
    for p in (out, record):
        if p.exists():
            p.unlink()
    t0 = time.time()
    try:
        proc = subprocess.run([binary, "pack", str(scene_path), "-q", "-o", str(out), "--record", str(record)],
                              capture_output=True, text=True, timeout=timeout)
        code, err = proc.returncode, proc.stderr.strip().splitlines()
    except subprocess.TimeoutExpired:
        code, err = "timeout", []
    wall = time.time() - t0
    row = {"case": name, "exit": code, "wall_s": f"{wall:.2f}", "n": "", "vf": "", "pack_s": "", "validate": "",
           "message": next((l for l in err if "error" in l), err[-1] if err else "")[:160]}
    if record.exists():
        r = json.loads(record.read_text())
        row["n"] = r["n"]
        m = r["metrics"]
        vf = m["volume_fraction_container"]
        row["vf"] = "nan" if vf is None else f"{vf:.4f}"  # JSON has no NaN: the record writes null
        row["pack_s"] = f"{r['timings']['pack']:.2f}"
    if out.exists():
        try:
            v = subprocess.run([binary, "validate", str(out), "--scene", str(scene_path), "-q"], timeout=timeout)
            row["validate"] = v.returncode
        except subprocess.TimeoutExpired:
            row["validate"] = "timeout"
    return row


def results():
    runs = {}
    for path in sorted(HERE.glob("runs-*.csv")):
        label = path.stem[len("runs-"):]
        with open(path) as f:
            runs[label] = {r["case"]: r for r in csv.DictReader(f)}
    return runs


def write_results(argv, binary):
    runs = results()
    labels = sorted(runs, key=lambda s: (s != "before", s))
    with tempfile.TemporaryDirectory() as d:
        order = [(g, n, ref) for g, n, ref, _ in cases(Path(d))]
    lines = ["# Numerical stability at the extremes", ""]
    lines += runkit.provenance_lines(binary, argv)
    lines += ["",
              "Every case packed with `frontpack pack SCENE -q -o out.csv --record r.json` under a timeout, then",
              "`frontpack validate out.csv --scene SCENE` (the file read back in the container's frame). `exit` is",
              "the pack's exit code (0 ok, 2 refused, 3 failed its own validation, 4 valid but incomplete), `val` the validate exit code.",
              "`N / ref` and `ΔVF` compare with the reference case: the same scene at the origin and scale 1.",
              "Scene texts: `cases()` in run.py; the ctest suites tests/front/test_front_far_and_scaled.cpp,",
              "test_front_thin.cpp and test_front_extremes.cpp assert them (the bad-input cases are in",
              "tests/cli/test_cli_hostile.cpp, the limits in tests/cli/test_cli_limits.cpp).", "",
              "* `before`: the binary of main at 00bb899, the commit before the extremes work (timeout 60 s, 120 s for the 99:1 mixes);",
              "* `after`: the current binary (timeout 120 s). Times are of one core of a shared 2-core machine",
              "  (other builds ran meanwhile: +-30 %).", ""]
    for label in labels:
        lines += [f"## {label}", ""]
        rows = []
        for group, name, ref in order:
            r = runs[label].get(name)
            if r is None:
                continue
            base = runs[label].get(ref) if ref else None
            ratio = dvf = ""
            if base and r["n"] and base["n"]:
                ratio = f"{int(r['n']) / int(base['n']):.4f}"
                if r["vf"] not in ("", "nan") and base["vf"] not in ("", "nan"):
                    dvf = f"{float(r['vf']) - float(base['vf']):+.4f}"
            rows.append([group, name, r["exit"], r["validate"], r["n"], r["vf"], ratio, dvf, r["pack_s"], r["wall_s"],
                         r["message"].replace("|", "/")])
        lines += [runkit.table(["group", "case", "exit", "val", "N", "VF container", "N / ref", "ΔVF", "pack s",
                                "wall s", "last message"], rows), ""]
    lines += memory_lines()
    (HERE / "RESULTS.md").write_text("\n".join(lines))


def memory_lines():
    """The section measured by memory.py (memory.csv), the figures behind the limits' memory rule."""
    path = HERE / "memory.csv"
    if not path.exists():
        return []
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return ["## Limits: memory per particle and per mesh face", "",
            "Command: `FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/extremes/memory.py` (same machine;",
            "memory does not depend on the load). Each case packed twice (`-o out.csv`, peak RSS by `/usr/bin/time -f %M`);",
            "`bytes per unit` is the slope (RSS_large - RSS_small) / (N_large - N_small), the figure the limits use",
            "(core/io/scene_limits.hpp: 200 per sphere, 150 per disk, 500 per 2D shape, 2000 per 3D shape, plus 300 MB per",
            "run; core/geometry/mesh_container.cpp: 500 per face). The last row writes VTU, whose display surfaces of",
            "non-spherical particles are cached up to 256 MB (shapes/io/shape_packing_writers.cpp).", "",
            runkit.table(["case", "unit", "N small", "RSS small (kB)", "N large", "RSS large (kB)", "bytes per unit",
                          "RSS / N (bytes)"],
                         [[r["case"], r["unit"], r["n_small"], r["rss_small_kb"], r["n_large"], r["rss_large_kb"],
                           r["bytes_per_unit"], r["rss_over_n"]] for r in rows]), ""]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--label", default="after")
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--only", default="", help="run only cases whose name contains this")
    ap.add_argument("--table-only", action="store_true")
    a = ap.parse_args()
    binary = os.environ.get("FRONTPACK", str(runkit.REPO / "build" / "cli" / "frontpack"))
    if not a.table_only:
        rows = []
        with tempfile.TemporaryDirectory() as d:
            folder = Path(d)
            for group, name, ref, text in cases(folder):
                if a.only and a.only not in name and a.only != group:
                    continue
                row = run_case(binary, folder, name, text, a.timeout)
                print(group, "|", " | ".join(str(row[k]) for k in ["case", "exit", "validate", "n", "vf", "pack_s", "wall_s"]),
                      flush=True)
                rows.append(row)
        path = HERE / f"runs-{a.label}.csv"
        old = results().get(a.label, {}) if a.only else {}
        merged = {**old, **{r["case"]: r for r in rows}}
        with open(path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["case", "exit", "validate", "n", "vf", "pack_s", "wall_s", "message"])
            w.writeheader()
            for r in merged.values():
                w.writerow(r)
    write_results(sys.argv, binary)


if __name__ == "__main__":
    main()
