#!/usr/bin/python3
"""The front on threads: the single front against blocks on 2 threads, and the
quality at block faces.

Usage: run.py FRONTPACK OUTDIR [repeats]

1. Speed and quality. Per scene: `repeats` whole-process runs of `frontpack pack SCENE -q -o X.csv`
   with -j 1 (the single front) and -j 2 (blocks), interleaved, timed by /usr/bin/time (wall,
   user + system CPU); then one run each with --record for the figures (particles, VF, pack
   seconds, particles trimmed by a count stop, blocks). Every run validates its packing (a failed
   validation exits non-zero and stops this script).
2. The same packing for every thread count: -j 2, -j 3 and -j 1 with the same blocks
   (packer.block_edge set) are compared byte for byte.
3. Block faces: boxes cut into blocks of a known edge; the packing fraction of slabs of width r_max
   centred on the block faces, and the loosest slab at offsets up to 3 r_max from them, against
   the slabs inside the blocks (3 r_max or more from a face
   and from a wall), on the three axes, with the single front's packing of the same box as the
   reference (whose "faces" are the same planes).
Prints markdown tables; writes OUTDIR/runs.csv.
"""
import csv
import filecmp
import json
import pathlib
import statistics
import subprocess
import sys

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def run(binary, scene, threads, out, record=False):
    cmd = ["/usr/bin/time", "-f", "%U %S %e %M", binary, "pack", str(scene), "-q", "-j", str(threads), "-o", str(out / "x.csv")]
    if record:
        cmd += ["--record", str(out / "x.json")]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        raise SystemExit("%s failed: %s" % (" ".join(cmd), r.stderr[-800:]))
    user, system, wall, rss = r.stderr.strip().splitlines()[-1].split()
    return float(user) + float(system), float(wall), int(rss)


def figures(out):
    d = json.loads((out / "x.json").read_text())
    m, c = d["metrics"], d["counters"]
    return {"n": d["n"], "vf_container": m["volume_fraction_container"], "vf_core": m["volume_fraction_core"],
            "vf_ref": m["volume_fraction_reference_sphere"], "pack": d["timings"]["pack"],
            "trimmed": c.get("trimmed", 0), "blocks": c.get("blocks", 0)}


def speed(binary, out, repeats):
    cases = [("valera-cube (27,600 spheres)", ROOT / "scenes/valera-cube.yaml"),
             ("femur mesh U[0.005, 0.01]", ROOT / "scenes/mesh.yaml"),
             ("million (10^6 spheres, count stop)", ROOT / "scenes/million.yaml"),
             ("disks-million (10^6 disks, count stop)", ROOT / "scenes/disks-million.yaml"),
             ("capsules in the femur", ROOT / "scenes/shapes-capsules-mesh.yaml")]
    rows = []
    print("| scene | threads | particles | trimmed | VF container | VF core | VF ref sphere | pack s | whole process wall s (median of %d) | CPU s | peak MB |" % repeats)
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, scene in cases:
        times = {1: [], 2: []}
        for _ in range(repeats):
            for j in (1, 2):
                times[j].append(run(binary, scene, j, out))
        for j in (1, 2):
            run(binary, scene, j, out, record=True)
            f = figures(out)
            cpu = statistics.median(t[0] for t in times[j])
            wall = statistics.median(t[1] for t in times[j])
            rss = max(t[2] for t in times[j]) / 1024
            rows.append(dict(scene=name, threads=j, cpu=cpu, wall=wall, rss=rss, **f))
            print("| %s | %d%s | %d | %d | %.4f | %.4f | %.4f | %.2f | %.2f | %.2f | %.0f |" % (
                name, j, " (blocks: %d)" % f["blocks"] if f["blocks"] else " (single front)", f["n"], f["trimmed"],
                f["vf_container"], f["vf_core"], f["vf_ref"], f["pack"], wall, cpu, rss))
    return rows


def same_for_every_thread_count(binary, out):
    print("\n| scene | compared | identical |")
    print("|---|---|---|")
    for name, text in [("valera-cube", (ROOT / "scenes/valera-cube.yaml").read_text()),
                       ("disks-million", (ROOT / "scenes/disks-million.yaml").read_text().replace("1000000", "200000"))]:
        scene = out / (name + ".yaml")
        scene.write_text(text)
        files = []
        for j in (2, 3):
            subprocess.run([binary, "pack", str(scene), "-q", "-j", str(j), "-o", str(out / ("%s-j%d.csv" % (name, j)))], check=True)
            files.append(out / ("%s-j%d.csv" % (name, j)))
        print("| %s | -j 2 against -j 3 | %s |" % (name, "yes" if filecmp.cmp(files[0], files[1], shallow=False) else "NO"))


def slab_fraction(c, r, axis, lo, hi, area):
    z_hi = np.clip(hi - c[:, axis], -r, r)
    z_lo = np.clip(lo - c[:, axis], -r, r)
    below = lambda z: np.pi * (r * r * (z + r) - (z ** 3 + r ** 3) / 3)
    return float(np.sum(below(z_hi) - below(z_lo))) / (area * (hi - lo))


def faces(binary, out):
    print("\n| box | block edge | packing | VF container | VF core | slabs centred on faces | worst slab within 3 r_max of a face (offset) | slabs inside blocks | centred - inside | worst - inside |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for side, edge, seed in [(0.9, 0.3, 1), (0.6, 0.2, 21), (1.2, 0.4, 3)]:
        for blocks in (False, True):
            scene = out / "faces.yaml"
            packer = "packer: {block_edge: %g}\n" % edge if blocks else ""
            scene.write_text("dimension: 3\nseed: %d\ncontainer: {type: box, min: [0, 0, 0], max: [%g, %g, %g]}\n"
                             "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n%s" % (seed, side, side, side, packer))
            subprocess.run([binary, "pack", str(scene), "-q", "-j", "2" if blocks else "1", "-o", str(out / "faces.csv"),
                            "--record", str(out / "x.json")], check=True)
            d = np.genfromtxt(out / "faces.csv", delimiter=",", names=True)
            c, r = np.stack([d["x"], d["y"], d["z"]], 1), d["r"]
            w, area = 0.02, side * side
            planes = [edge * k for k in range(1, int(round(side / edge)))]
            # Slabs of r_max at offsets of -3 .. +3 r_max (steps of r_max / 2), averaged over the faces.
            offsets = [k * w / 2 for k in range(-6, 7)]
            at = [np.mean([slab_fraction(c, r, a, f + o - w / 2, f + o + w / 2, area) for a in range(3) for f in planes])
                  for o in offsets]
            worst = int(np.argmin(at))
            inside = []
            for a in range(3):
                lo = 0.04
                while lo + w <= side - 0.04 + 1e-12:
                    if min(abs(lo + w / 2 - f) for f in planes) >= 0.06:
                        inside.append(slab_fraction(c, r, a, lo, lo + w, area))
                    lo += w
            m = json.loads((out / "x.json").read_text())["metrics"]
            print("| %g | %g | %s | %.4f | %.4f | %.4f | %.4f (%+.1f r_max) | %.4f | %+.4f | %+.4f |" % (
                side, edge, "blocks" if blocks else "single front", m["volume_fraction_container"],
                m["volume_fraction_core"], at[6], at[worst], offsets[worst] / w, np.mean(inside),
                at[6] - np.mean(inside), at[worst] - np.mean(inside)), flush=True)


def main():
    binary, out = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    out.mkdir(parents=True, exist_ok=True)
    if "--faces-only" in sys.argv:
        return faces(binary, out)
    rows = speed(binary, out, repeats)
    with open(out / "runs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    same_for_every_thread_count(binary, out)
    faces(binary, out)


if __name__ == "__main__":
    main()
