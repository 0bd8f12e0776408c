#!/usr/bin/env python3
"""Void filling after the front: the front alone against the front followed by
`densify:` (paper 000 step 7b), same scenes and seeds, at R = r_max / r_min = 2, 7 and 50, and a
Fuller gradation by mass at R = 7.

Usage: run.py FRONTPACK OUT_DIR [seeds]   (writes OUT_DIR/results.json and prints the tables)
Each run is `frontpack pack SCENE --record REC -q`; every figure comes from the run record (the
independent validation and analysis of `pack`). A split run whose voids cannot take their share
fails the radii test (exit 3): its record is kept and its row says so."""
import json
import os
import subprocess
import sys

R_MAX = 0.05


def split_radius(name):
    """Where the split mode cuts the law: r_min R^(1/3) (the front packs above, the voids below)."""
    ratio = 7.0 if name == "fuller-R7" else float(name.split("R")[1])
    return R_MAX / ratio * ratio ** (1 / 3)


def law(name):
    """The particles block of a scene and the box side for each law."""
    if name.startswith("uniform"):
        ratio = float(name.split("R")[1])
        side = 1.0 if ratio <= 7 else 0.6
        return f"{{radius: {{distribution: uniform, min: {R_MAX / ratio!r}, max: {R_MAX}}}}}", side
    if name == "fuller-R7":  # passing fraction by mass (d / d_max)^0.5, sieves from d_min to d_max
        d_max, d_min = 2 * R_MAX, 2 * R_MAX / 7
        pts = []
        for k in range(7):
            d = d_min * (d_max / d_min) ** (k / 6)
            p = 100 * (d ** 0.5 - d_min ** 0.5) / (d_max ** 0.5 - d_min ** 0.5)
            pts.append(f"[{d:.6g}, {p:.6g}]")
        return f"{{radius: {{distribution: gradation, basis: mass, curve: [{', '.join(pts)}]}}}}", 0.8
    raise ValueError(name)


MODES = {
    "front": "",
    "+voids (law)": "densify: {radii: distribution}\n",
    "+voids (law, split)": "densify: {radii: distribution, split: SPLIT}\n",
    "+voids (fit, eps 0)": "densify: {radii: fit}\n",
    "+voids (fit, eps 0.05)": "densify: {radii: fit, overlap: 0.05}\n",
}


def run(frontpack, out, law_name, mode, seed):
    particles, side = law(law_name)
    scene = (f"dimension: 3\nseed: {seed}\ncontainer: {{type: box, min: [0, 0, 0], max: [{side}, {side}, {side}]}}\n"
             f"particles: {particles}\n" + MODES[mode].replace("SPLIT", repr(split_radius(law_name))))
    tag = f"{law_name}-{mode.replace(' ', '').replace('(', '').replace(')', '').replace(',', '-')}-{seed}"
    path = os.path.join(out, tag + ".yaml")
    with open(path, "w") as f:
        f.write(scene)
    rec = os.path.join(out, tag + ".json")
    p = subprocess.run([frontpack, "pack", path, "--record", rec, "-q"], capture_output=True, text=True)
    if p.returncode in (3, 4) and os.path.exists(rec):  # written, the radii test failed or a target missed: a row still
        pass
    elif p.returncode != 0:
        return {"law": law_name, "mode": mode, "seed": seed, "exit": p.returncode, "error": p.stderr.strip()}
    r = json.load(open(rec))
    m, c, t = r["metrics"], r["counters"], r["timings"]
    return {
        "law": law_name, "mode": mode, "seed": seed, "exit": 0, "verdict": r["info"]["validation"], "n": r["n"],
        "vf_container": m["volume_fraction_container"], "vf_ref": m["volume_fraction_reference_sphere"],
        "vf_core": m["volume_fraction_core"], "z": m["mean_coordination"],
        "vf_before": m.get("densify_volume_fraction_before", m["volume_fraction_container"]),
        "added": c.get("densify_added", 0), "ks_d": m.get("radii_statistic"), "ks_p": m.get("radii_pvalue"),
        "max_overlap_rmin": m["max_overlap_over_rmin"], "pack_s": t["pack"], "densify_s": m.get("densify_seconds", 0.0),
        "unplaced": c.get("densify_radii_unplaced", 0),
    }


def main():
    frontpack, out = sys.argv[1], sys.argv[2]
    seeds = [int(s) for s in sys.argv[3].split(",")] if len(sys.argv) > 3 else [1, 2, 3]
    os.makedirs(out, exist_ok=True)
    rows = []
    for law_name in ["uniform-R2", "uniform-R7", "uniform-R50", "fuller-R7"]:
        for mode in MODES:
            for seed in seeds:
                rows.append(run(frontpack, out, law_name, mode, seed))
                print(json.dumps(rows[-1]), flush=True)
    json.dump(rows, open(os.path.join(out, "results.json"), "w"), indent=1)
    print("\n| law | mode | N | VF container | VF ref. ball | VF core | z | added | radii K-S D (p) | max overlap / r_min | pack + fill s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for law_name in ["uniform-R2", "uniform-R7", "uniform-R50", "fuller-R7"]:
        for mode in MODES:
            rs = [r for r in rows if r["law"] == law_name and r["mode"] == mode and r["exit"] == 0]
            if not rs:
                print(f"| {law_name} | {mode} | failed | | | | | | | | |")
                continue
            mean = lambda k: sum(r[k] for r in rs) / len(rs)
            spread = lambda k: (max(r[k] for r in rs) - min(r[k] for r in rs)) / 2
            print(f"| {law_name} | {mode} | {mean('n'):.0f} | {mean('vf_container'):.4f} ± {spread('vf_container'):.4f} | "
                  f"{mean('vf_ref'):.4f} | {mean('vf_core'):.4f} | {mean('z'):.2f} | {mean('added'):.0f} | "
                  f"{mean('ks_d'):.4f} ({min(r['ks_p'] for r in rs):.2g}) | {max(r['max_overlap_rmin'] for r in rs):.2g} | "
                  f"{mean('pack_s'):.2f} |")


if __name__ == "__main__":
    main()
