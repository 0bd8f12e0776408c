"""A bed filled to a height (`container.bed`), measured.

For each case: `frontpack pack` (time, count, exit), `frontpack validate` of the file against its
scene, `frontpack analyze --json` for the bed's profile as frontpack reports it, and for the beds
of constant cross-section (vertical cylinders, rectangles) the profile again from the CSV alone:
each sphere's exact sections summed in slabs of r_max / 2, the bulk (the slabs 2 r_max from floor
and level) and the height where the profile, read down from the level, falls to half the bulk.
References: the same container cut at the fill height by a wall of its own, and the full container's
core. Writes results.json and prints the RESULTS.md tables.

    FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/bed/run.py
"""
import json
import math
import os
import subprocess
import tempfile
import time

FRONTPACK = os.environ.get("FRONTPACK", "frontpack")
HERE = os.path.dirname(os.path.abspath(__file__))

U46 = "{radius: {distribution: uniform, min: 0.04, max: 0.06}}"
CYL = "type: cylinder, base: [0, 0, 0], radius: 1, height: {H}"
# (name, dimension, container, particles, constant cross-section area or None, fill height, r_max)
CASES = [
    ("cylinder, bed 1.2, free", 3, "{" + CYL.format(H=3) + ", bed: {height: 1.2}}", U46, math.pi, 1.2, 0.06),
    ("cylinder, bed 1.2, flat", 3, "{" + CYL.format(H=3) + ", bed: {height: 1.2, surface: flat}}", U46, math.pi, 1.2, 0.06),
    ("cylinder 1.2 high (reference: cut by its own wall)", 3, "{" + CYL.format(H=1.2) + "}", U46, math.pi, 1.2, 0.06),
    ("cylinder, bed 2.4, free", 3, "{" + CYL.format(H=3) + ", bed: {height: 2.4}}", U46, math.pi, 2.4, 0.06),
    ("cylinder, bed 1.2, lognormal 0.02-0.08", 3, "{" + CYL.format(H=3) + ", bed: {height: 1.2}}",
     "{radius: {distribution: lognormal, median: 0.04, sigma: 0.3, min: 0.02, max: 0.08}}", math.pi, 1.2, 0.08),
    ("drum (axis x), half full, free", 3,
     "{type: cylinder, base: [0, 0, 0], axis: [1, 0, 0], radius: 1, height: 1, bed: {height: 1}}", U46, None, 1.0, 0.06),
    ("ball, bed 0.7 along [1, 1, 1]", 3, "{type: sphere, center: [0, 0, 0], radius: 1, bed: {height: 0.7, up: [1, 1, 1]}}",
     U46, None, 0.7, 0.06),
    ("rectangle 4 wide, bed 2, free", 2, "{type: rectangle, min: [0, 0], max: [4, 5], bed: {height: 2}}",
     "{radius: {distribution: uniform, min: 0.02, max: 0.04}}", 4.0, 2.0, 0.04),
    ("capsules L/D = 1 in a cylinder 1.5, bed 1.5, free", 3,
     "{type: cylinder, base: [0, 0, 0], radius: 1.5, height: 5, bed: {height: 1.5}}",
     "[{shape: spherocylinder, aspect_ratio: 0.5, size: {distribution: uniform, min: 0.15, max: 0.2}}]", None, 1.5, 0.2),
    ("large: cylinder radius 2, bed 3, r 0.02-0.03", 3,
     "{type: cylinder, base: [0, 0, 0], radius: 2, height: 8, bed: {height: 3}}",
     "{radius: {distribution: uniform, min: 0.02, max: 0.03}}", 4 * math.pi, 3.0, 0.03),
]
FULL = ("full cylinder 3 high (core reference)", 3, "{" + CYL.format(H=3) + "}", U46)


def below(dim, r, t):
    t = max(-r, min(r, t))
    if dim == 3:
        return math.pi * (r * r * (t + r) - (t ** 3 + r ** 3) / 3)
    return r * r * (math.asin(t / r) + math.pi / 2) + t * math.sqrt(max(r * r - t * t, 0.0))


def csv_profile(path, dim, section, height, r_max):
    balls = []
    with open(path) as f:
        next(f)
        for line in f:
            if line.startswith("#"):
                continue
            v = [float(x) for x in line.split(",")]
            balls.append((v[dim], v[-1]))  # height (last coordinate), radius
    n = math.ceil(height / (0.5 * r_max))
    w = height / n
    solid = [0.0] * n
    for h, r in balls:
        k0 = max(0, int((h - r) / w))
        for k in range(k0, min(n, int((h + r) / w) + 1)):
            solid[k] += below(dim, r, (k + 1) * w - h) - below(dim, r, k * w - h)
    vf = [s / (section * w) for s in solid]
    bulk_k = [k for k in range(n) if k * w >= 2 * r_max - 1e-12 and (k + 1) * w <= height - 2 * r_max + 1e-12]
    bulk = sum(solid[k] for k in bulk_k) / (section * w * len(bulk_k))
    half = next(((k + 1) * w for k in range(n - 1, -1, -1) if vf[k] >= 0.5 * bulk), float("nan"))
    return {"bulk": bulk, "half_bulk_top_slab": half, "top_slab": vf[-1], "floor_slab": vf[0]}


def run(folder, name, dim, container, particles):
    scene = os.path.join(folder, name + ".yaml")
    with open(scene, "w") as f:
        f.write(f"dimension: {dim}\nseed: 1\ncontainer: {container}\nparticles: {particles}\n")
    out = os.path.join(folder, name + (".json" if particles.startswith("[") else ".csv"))  # shapes need JSON
    t0 = time.monotonic()
    p = subprocess.run([FRONTPACK, "pack", scene, "-q", "-o", out, "--record", os.path.join(folder, name + ".rec")],
                       capture_output=True, text=True)
    wall = time.monotonic() - t0
    v = subprocess.run([FRONTPACK, "validate", out, "--scene", scene, "-q"])
    a = subprocess.run([FRONTPACK, "analyze", out, "--scene", scene, "-q", "--json", os.path.join(folder, name + ".analysis")],
                       capture_output=True, text=True)
    with open(os.path.join(folder, name + ".analysis")) as f:
        analysis = json.load(f)
    with open(os.path.join(folder, name + ".rec")) as f:
        record = json.load(f)
    return p.returncode, v.returncode, a.returncode, wall, record, analysis, out


def main():
    rows = []
    with tempfile.TemporaryDirectory() as d:
        _, _, _, _, _, full, _ = run(d, "full", FULL[1], FULL[2], FULL[3])
        core = full["volume_fraction"]["core"]["value"]
        for i, (name, dim, container, particles, section, height, r_max) in enumerate(CASES):
            code, vcode, acode, wall, record, a, csv = run(d, f"case{i}", dim, container, particles)
            vf = a["volume_fraction"]
            bed = vf.get("bed_profile", {})
            row = {"case": name, "exit": code, "validate": vcode, "analyze": acode, "particles": a["particles"],
                   "wall_seconds": round(wall, 2), "pack_seconds": record["timings"]["pack"],
                   "vf_container": vf["container"]["value"], "vf_core": vf["core"]["value"],
                   "bulk": bed.get("bulk"), "top_layer": bed.get("top_layer"), "half_bulk_height": bed.get("half_bulk_height"),
                   "surface": bed.get("surface"), "height": height, "r_max": r_max}
            if section:
                row["csv"] = csv_profile(csv, dim, section, height, r_max)
            rows.append(row)
            print(json.dumps(row))
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump({"full_cylinder_core": core, "rows": rows}, f, indent=1)
    print(f"\nfull cylinder 3 high, core VF {core:.4f}\n")
    print("| case | particles | pack s | exit / validate | bulk (frontpack) | bulk (CSV) | top 2 r_max | half bulk at | "
          "surface tops mean / sd / min |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        s = r["surface"]
        tops = f"{s['mean']:.4f} / {s['sd']:.4f} / {s['min']:.4f}" if s else "—"
        csvb = f"{r['csv']['bulk']:.4f}" if "csv" in r else "—"
        bulk = f"{r['bulk']:.4f}" if r["bulk"] is not None else "—"
        top = f"{r['top_layer']:.4f}" if r["top_layer"] is not None else "—"
        half = f"{r['half_bulk_height']:.4f} of {r['height']}" if r["half_bulk_height"] is not None else "—"
        pack_s = f"{r['pack_seconds']:.2f}" if r["pack_seconds"] is not None else f"{r['wall_seconds']:.2f} (wall)"
        print(f"| {r['case']} | {r['particles']} | {pack_s} | {r['exit']} / {r['validate']} | {bulk} | {csvb} | {top} | "
              f"{half} | {tops} |")


if __name__ == "__main__":
    main()
