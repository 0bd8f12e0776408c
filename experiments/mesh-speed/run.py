#!/usr/bin/python3
"""Mesh containers against a box, an old build against a new one, interleaved.

Usage: run.py OLD_FRONTPACK NEW_FRONTPACK OUTDIR [repeats]

Per scene and binary: `repeats` whole-process runs, alternating old and new, each
`frontpack pack SCENE -q -o X.csv` (no record: the validation runs, the analysis does not where
the binary knows to skip it) timed by /usr/bin/time (user + system CPU seconds, wall seconds);
then one run with --record for the counts (particles, solves, wall contacts, VF) and the pack
time. Prints a markdown table of medians and writes OUTDIR/runs.csv.
"""
import csv
import json
import os
import pathlib
import statistics
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def scene(path, container, radius):
    path.write_text("dimension: 3\nseed: 1\ncontainer: %s\nparticles:\n  radius: %s\n" % (container, radius))
    return path


def scenes(out):
    femur = ROOT / "tests/data/meshes/femur.off"
    torus = ROOT / "tests/fuzz/corpus/mesh/torus.obj"
    turbine = out / "turbine.off"
    subprocess.run(["/usr/bin/python3", str(HERE / "turbine_mesh.py"), str(turbine)], check=True)
    side = 0.02027 ** (1 / 3)  # the femur's volume
    return [
        ("femur U[0.005, 0.01]", scene(out / "femur.yaml", "{type: mesh, file: %s}" % femur,
                                       "{distribution: uniform, min: 0.005, max: 0.01}")),
        ("box of the femur's volume, same radii", scene(out / "box.yaml",
                                                        "{type: box, min: [0, 0, 0], max: [%.6f, %.6f, %.6f]}" % (side, side, side),
                                                        "{distribution: uniform, min: 0.005, max: 0.01}")),
        ("femur r = 0.01 (spheres as large as the facets)", scene(out / "femur-r01.yaml", "{type: mesh, file: %s}" % femur,
                                                                  "{distribution: constant, value: 0.01}")),
        ("femur r = 0.0028", scene(out / "femur-r0028.yaml", "{type: mesh, file: %s}" % femur,
                                   "{distribution: constant, value: 0.0028}")),
        ("turbine-like mesh (16,896 facets) U[0.01, 0.02]", scene(out / "turbine.yaml", "{type: mesh, file: %s}" % turbine,
                                                                  "{distribution: uniform, min: 0.01, max: 0.02}")),
        ("torus (fuzz corpus) U[0.02, 0.04]", scene(out / "torus.yaml", "{type: mesh, file: %s, scale: 1}" % torus,
                                                    "{distribution: uniform, min: 0.02, max: 0.04}")),
    ]


def timed(binary, scene_path, out):
    csv_path = out / "x.csv"
    r = subprocess.run(["/usr/bin/time", "-f", "%U %S %e %M", binary, "pack", str(scene_path), "-q", "-o", str(csv_path)],
                       capture_output=True, text=True)
    if r.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        raise SystemExit("%s failed on %s: %s" % (binary, scene_path, r.stderr[-500:]))
    user, system, wall, rss = r.stderr.strip().splitlines()[-1].split()
    return float(user) + float(system), float(wall), int(rss)


def recorded(binary, scene_path, out):
    rec = out / "x.json"
    p = subprocess.run([binary, "pack", str(scene_path), "-q", "-o", str(out / "y.csv"), "--record", str(rec)])
    if p.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        raise SystemExit("%s failed on %s (exit %d)" % (binary, scene_path, p.returncode))
    d = json.loads(rec.read_text())
    return {"n": d["n"], "vf": d["metrics"]["volume_fraction_container"], "pack": d["timings"]["pack"],
            "solves": d["counters"]["solves"]}


def main():
    old, new, out = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3]).resolve()
    repeats = int(sys.argv[4]) if len(sys.argv) > 4 else 5
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    print("| scene | build | particles | VF container | solves / particle | pack s (recorded run) | whole process, CPU s (median of %d) | spheres per CPU-second |" % repeats)
    print("|---|---|---|---|---|---|---|---|")
    for name, path in scenes(out):
        times = {old: [], new: []}
        for _ in range(repeats):
            for b in (old, new):
                times[b].append(timed(b, path, out))
        for label, b in (("old", old), ("new", new)):
            info = recorded(b, path, out)
            cpu = statistics.median(t[0] for t in times[b])
            rows.append({"scene": name, "build": label, **info, "cpu_median": cpu, "cpu_all": " ".join("%.3f" % t[0] for t in times[b]),
                         "wall_median": statistics.median(t[1] for t in times[b]), "peak_kb": max(t[2] for t in times[b])})
            print("| %s | %s | %d | %.4f | %.0f | %.3f | %.3f | %.0f |" % (
                name, label, info["n"], info["vf"], info["solves"] / max(info["n"], 1), info["pack"], cpu,
                info["n"] / cpu))
            sys.stdout.flush()
    with open(out / "runs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
