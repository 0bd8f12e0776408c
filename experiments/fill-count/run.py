"""N particles that fill the container (`stop: {particles: N, scale_sizes: true}`), measured.

For each case: the count stop alone (the front ended at N: a cluster around the seed point, exit 4),
then scale_sizes (the radius law scaled so that N fill the container), then the full packing at
the scale found (the scaled law written out, no stop), and `frontpack validate` of the
scale_sizes file against its scene file alone. Writes results.json and prints the RESULTS.md table.

    FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/fill-count/run.py
"""
import json
import os
import subprocess
import tempfile
import time

FRONTPACK = os.environ.get("FRONTPACK", "frontpack")
HERE = os.path.dirname(os.path.abspath(__file__))

CYLINDER = "{type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 1, height: 2}"
CASES = [  # (name, dimension, container, law with the scale {s} applied to its lengths, N)
    ("cylinder, lognormal", 3, CYLINDER,
     "{{distribution: lognormal, median: {m}, sigma: 0.3, min: {lo}, max: {hi}}}", (0.02, 0.01, 0.05), 2000),
    ("cylinder, lognormal", 3, CYLINDER,
     "{{distribution: lognormal, median: {m}, sigma: 0.3, min: {lo}, max: {hi}}}", (0.02, 0.01, 0.05), 20000),
    ("cylinder, lognormal", 3, CYLINDER,
     "{{distribution: lognormal, median: {m}, sigma: 0.3, min: {lo}, max: {hi}}}", (0.02, 0.01, 0.05), 200000),
    ("disk, uniform", 2, "{type: disk, center: [0, 0], radius: 1}",
     "{{distribution: uniform, min: {lo}, max: {hi}}}", (None, 0.01, 0.03), 20000),
    ("box 3.1 (million.yaml), uniform", 3, "{type: box, min: [0, 0, 0], max: [3.1, 3.1, 3.1]}",
     "{{distribution: uniform, min: {lo}, max: {hi}}}", (None, 0.01, 0.02), 1000000),
]


def law(template, lengths, s):
    m, lo, hi = lengths
    return template.format(m=repr(m * s) if m else "", lo=repr(lo * s), hi=repr(hi * s))


def pack(folder, name, text):
    scene = os.path.join(folder, name + ".yaml")
    with open(scene, "w") as f:
        f.write(text)
    t0 = time.monotonic()
    p = subprocess.run([FRONTPACK, "pack", scene, "-q", "-o", os.path.join(folder, name + ".csv"), "--record",
                        os.path.join(folder, name + ".json")], capture_output=True, text=True)
    wall = time.monotonic() - t0
    with open(os.path.join(folder, name + ".json")) as f:
        return p.returncode, wall, json.load(f)


def main():
    rows = []
    for name, dim, container, template, lengths, n in CASES:
        base = f"dimension: {dim}\nseed: 1\ncontainer: {container}\n"
        with tempfile.TemporaryDirectory() as d:
            unscaled = base + f"particles: {{radius: {law(template, lengths, 1.0)}}}\n"
            code_cut, _, cut = pack(d, "cut", unscaled + f"stop: {{particles: {n}}}\n")
            code, wall, r = pack(d, "scaled", unscaled + f"stop: {{particles: {n}, scale_sizes: true}}\n")
            v = subprocess.run([FRONTPACK, "validate", os.path.join(d, "scaled.csv"), "--scene", os.path.join(d, "scaled.yaml"), "-q"])
            s = r["metrics"]["size_scale"]
            code_full, _, full = pack(d, "full", base + f"particles: {{radius: {law(template, lengths, s)}}}\n")
        m, mf = r["metrics"], full["metrics"]
        rows.append({"case": name, "N": n, "cut_exit": code_cut, "cut_vf": cut["metrics"]["volume_fraction_container"],
                     "exit": code, "validate": v.returncode, "n": r["n"], "scale": s, "fitted": m["size_scale_fitted"],
                     "trials": r["counters"]["size_scale_trials"], "full_count": r["counters"]["size_scale_full_count"],
                     "vf": m["volume_fraction_container"], "vf_core": m["volume_fraction_core"],
                     "full_exit": code_full, "full_n": full["n"], "full_vf": mf["volume_fraction_container"],
                     "full_vf_core": mf["volume_fraction_core"], "trial_s": m["size_scale_seconds"],
                     "pack_s": r["timings"]["pack"], "wall_s": wall})
        print(json.dumps(rows[-1]), flush=True)
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(rows, f, indent=1)
    print("| case | N | count stop alone: VF container (exit) | scale s (fitted) | trials | full count at s | "
          "VF container / core | full packing at s: N, VF container / core | validate | trials s / pack s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for x in rows:
        print(f"| {x['case']} | {x['N']:,} | {x['cut_vf']:.3f} ({x['cut_exit']}) | {x['scale']:.4f} ({x['fitted']:.4f}) | "
              f"{x['trials']} | {x['full_count']:,} | {x['vf']:.4f} / {x['vf_core']:.4f} | {x['full_n']:,}, "
              f"{x['full_vf']:.4f} / {x['full_vf_core']:.4f} | {x['validate']} | {x['trial_s']:.1f} / {x['pack_s']:.1f} |")


if __name__ == "__main__":
    main()
