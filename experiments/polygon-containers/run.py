#!/usr/bin/env python3
"""Polygon containers with many vertices: pack time and wall time of `frontpack pack`
and `frontpack analyze` for n = 10^3 .. 10^6 vertices, before and after the edge tree
(core/geometry/edge_chain_tree.hpp). Writes RESULTS.md next to this file, entirely.

    FRONTPACK=/path/to/new/frontpack FRONTPACK_BEFORE=/path/to/old/frontpack \\
        /usr/bin/python3 experiments/polygon-containers/run.py

Scenes (written to out/polygon-containers/, the largest is 45 MB): a regular n-gon of radius 0.5
(`ngon`), a star whose n/2 teeth are 0.05 deep (`star`: r alternates 0.5, 0.45) and a wavy
coastline with a fine zig-zag (`coast`: r = 0.5 (1 + 0.1 sin 7a + 0.03 sin 53a) +- 0.002), disks
with radii U[0.01, 0.02], seed 1. Each command runs under the shared benchmark lock; "after" runs
3 times up to 10^5 vertices (median), once above; "before" once, and only up to --before-max-n
(the old code is O(n) per query: 10^6 would take hours). Where both ran, the packing files and the
analyses (timings left out) are compared byte for byte.
"""
import argparse
import hashlib
import json
import math
import os
import platform
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
LOCK = "/tmp/frontpack-bench.lock"
WORK = os.path.join(ROOT, "out", "polygon-containers")


def vertices(kind, n):
    pts = []
    for k in range(n):
        a = 2 * math.pi * k / n
        if kind == "ngon":
            r = 0.5
        elif kind == "star":
            r = 0.5 if k % 2 == 0 else 0.45
        else:  # coast
            r = 0.5 * (1 + 0.1 * math.sin(7 * a) + 0.03 * math.sin(53 * a)) + (0.002 if k % 2 else -0.002)
        pts.append((r * math.cos(a), r * math.sin(a)))
    return pts


def write_scene(kind, n):
    path = os.path.join(WORK, f"{kind}{n}.yaml")
    if not os.path.exists(path):
        with open(path + ".tmp", "w") as f:
            f.write("dimension: 2\nseed: 1\ncontainer:\n  type: polygon\n  vertices: [")
            f.write(", ".join("[%.17g, %.17g]" % p for p in vertices(kind, n)))
            f.write("]\nparticles:\n  radius: {distribution: uniform, min: 0.01, max: 0.02}\n")
        os.replace(path + ".tmp", path)
    return path


def timed(cmd, timeout):
    """(wall s, peak MB) of cmd under the benchmark lock, or None on timeout."""
    try:
        out = subprocess.run(["flock", LOCK, "/usr/bin/time", "-f", "%e %M"] + cmd, capture_output=True, text=True,
                             cwd=ROOT, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    if out.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        sys.exit(f"failed ({out.returncode}): {' '.join(cmd)}\n{out.stderr}")
    wall, kb = out.stderr.strip().splitlines()[-1].split()
    return float(wall), int(kb) / 1024.0


def strip_times(x):
    if isinstance(x, dict):
        return {k: strip_times(v) for k, v in x.items() if k not in ("timings", "particles_per_second")}
    if isinstance(x, list):
        return [strip_times(v) for v in x]
    return x


def measure(fp, tag, kind, n, reps, timeout):
    """One binary on one scene: median pack wall, pack and metrics seconds (run record), analyze wall."""
    scene = write_scene(kind, n)
    base = os.path.join(WORK, f"{kind}{n}.{tag}")
    packs, analyses = [], []
    for _ in range(reps):
        t = timed([fp, "pack", scene, "-q", "-o", base + ".csv", "--record", base + ".record.json"], timeout)
        if t is None:
            return {"timeout": timeout}
        with open(base + ".record.json") as f:
            rec = json.load(f)
        packs.append((t[0], t[1], rec["timings"]["pack"], rec["timings"]["metrics"], rec["n"]))
        a = timed([fp, "analyze", base + ".csv", "--scene", scene, "--json", base + ".analysis.json", "-q"], timeout)
        if a is None:
            return {"timeout": timeout}
        analyses.append(a)
    packs.sort()
    analyses.sort()
    wall, mb, pack, metrics, particles = packs[len(packs) // 2]
    return {"wall": wall, "mb": max(p[1] for p in packs), "pack": pack, "metrics": metrics, "particles": particles,
            "analyze": analyses[len(analyses) // 2][0], "analyze_mb": max(a[1] for a in analyses)}


def same_outputs(kind, n):
    a, b = (os.path.join(WORK, f"{kind}{n}.{t}") for t in ("before", "after"))
    with open(a + ".csv", "rb") as f, open(b + ".csv", "rb") as g:
        if f.read() != g.read():
            return "packing differs"
    for suffix in (".analysis.json", ".record.json"):
        with open(a + suffix) as f, open(b + suffix) as g:
            if strip_times(json.load(f)) != strip_times(json.load(g)):
                return suffix[1:-5] + " differs"
    return "identical"


def sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:16]


def fmt(x, key):
    if x is None:
        return "not run"
    if "timeout" in x:
        return f"> {x['timeout']:.0f} (stopped)"
    return f"{x[key]:.2f}" if x[key] < 100 else f"{x[key]:.0f}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--before-max-n", type=int, default=100_000)
    ap.add_argument("--timeout", type=float, default=1200)
    ap.add_argument("--report-only", action="store_true", help="rewrite RESULTS.md from runs.json")
    args = ap.parse_args()
    if args.report_only:
        with open(os.path.join(HERE, "runs.json")) as f:
            report(json.load(f))
        return
    after = os.environ.get("FRONTPACK", os.path.join(ROOT, "build/cli/frontpack"))
    before = os.environ.get("FRONTPACK_BEFORE")
    for b in [after] + ([before] if before else []):
        if not os.access(b, os.X_OK):
            sys.exit(f"frontpack not found: {b}")
    os.makedirs(WORK, exist_ok=True)
    cases = [("ngon", n) for n in (1_000, 10_000, 30_000, 100_000, 1_000_000)] + \
            [(k, n) for k in ("star", "coast") for n in (10_000, 100_000, 1_000_000)]
    rows = []
    for kind, n in cases:
        new = measure(after, "after", kind, n, 3 if n <= 100_000 else 1, args.timeout)
        old = measure(before, "before", kind, n, 1, args.timeout) if before and n <= args.before_max_n else None
        same = same_outputs(kind, n) if old and "timeout" not in old else "-"
        rows.append((kind, n, old, new, same))
        print(kind, n, "before", old, "after", new, same, flush=True)

    model = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                            cwd=ROOT).stdout.strip()
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], capture_output=True, text=True,
                           cwd=ROOT).stdout.strip() != ""
    env = "".join(f"{k}={shlex.quote(os.environ[k])} " for k in ("FRONTPACK", "FRONTPACK_BEFORE") if k in os.environ)
    argv = " ".join(shlex.quote(a) for a in sys.argv[1:])
    runs = {
        "command": f"{env}/usr/bin/python3 experiments/polygon-containers/run.py{(' ' + argv) if argv else ''}",
        "machine": f"{subprocess.run(['nproc'], capture_output=True, text=True).stdout.strip()} CPUs (`nproc`), "
                   f"{model}, Linux {platform.release()}",
        "commit": commit + (" (tracked files modified)" if dirty else ""),
        "after": f"`{after}` (sha256 {sha(after)}…)",
        "before": f"`{before}` (sha256 {sha(before)}…)" if before else None,
        "rows": [{"kind": k, "n": n, "before": o, "after": a, "outputs": same} for k, n, o, a, same in rows],
    }
    with open(os.path.join(HERE, "runs.json"), "w") as f:
        json.dump(runs, f, indent=1)
    report(runs)


def report(runs):
    rows = [(r["kind"], r["n"], r["before"], r["after"], r["outputs"]) for r in runs["rows"]]
    L = [
        "# Polygon containers with many vertices: before and after the edge tree",
        "",
        "_Written entirely by `run.py` in this folder; re-run it to refresh every number._",
        "",
        f"Command: `{runs['command']}` (from the repository root); measurements kept in `runs.json` "
        "(`run.py --report-only` rewrites this file from them)",
        "",
        f"* machine: {runs['machine']}; every command single-threaded, under a shared lock (other sessions "
        "shared the machine and do not all take the lock: single runs, the `before` ones above all, carry "
        "some 10-30 % of noise)",
        f"* repository commit: `{runs['commit']}`",
        f"* after: {runs['after']}" + (f"; before: {runs['before']}" if runs["before"] else ""),
        "* per scene: `frontpack pack S.yaml -q -o P.csv --record R.json`, then "
        "`frontpack analyze P.csv --scene S.yaml --json A.json -q`; wall times by `/usr/bin/time`, "
        "pack and metrics seconds from the run record (metrics = the analysis and validation that "
        "`pack` runs on its result); total = wall time of the whole `pack` command (reading the YAML "
        "scene, building the container, packing, metrics, writing)",
        "* scenes: `ngon` regular n-gon of radius 0.5; `star` with n/2 teeth 0.05 deep (r alternates 0.5 "
        "and 0.45: half the vertices reflex, teeth 800 times longer than wide at 10^5); `coast` a wavy "
        "coastline with a zig-zag of amplitude 0.002 (r = 0.5 (1 + 0.1 sin 7a + 0.03 sin 53a) +- 0.002); "
        "radii U[0.01, 0.02], seed 1",
        "",
        "| scene | vertices | particles | before: pack s | before: total s | before: analyze s | "
        "after: pack s | after: metrics s | after: total s | after: analyze s | after: peak MB | outputs |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for kind, n, old, new, same in rows:
        L.append(f"| {kind} | {n:,} | {new.get('particles', '?')} | {fmt(old, 'pack')} | {fmt(old, 'wall')} | "
                 f"{fmt(old, 'analyze')} | {fmt(new, 'pack')} | {fmt(new, 'metrics')} | {fmt(new, 'wall')} | "
                 f"{fmt(new, 'analyze')} | {fmt(new, 'mb')} | {same} |")
    ng = {n: new for kind, n, old, new, same in rows if kind == "ngon"}
    L += [
        "",
        f"Target: 10^5 vertices well under 10 s for `frontpack pack` of the n-gon: "
        f"{ng[100_000]['wall']:.2f} s. From 10^5 to 10^6 vertices the total grows "
        f"{ng[1_000_000]['wall'] / ng[100_000]['wall']:.1f}x (10x the vertices).",
        "",
        "## Where the time went (profile of the old code)",
        "",
        "`perf record -g` (cpu-clock) of the old binary (main at 0951485) packing the 10^4-vertex n-gon:",
        "97 % of the samples in `PolygonContainer::locate` (the loop over every edge behind `inside` and",
        "`signed_distance`); by caller: the quasi-Monte-Carlo region measures of the metrics 86 % (VF",
        "core 53 %, the g(r) reference region 34 %: 16 x 4096 points each, every one a full loop), the",
        "deepest-point search of the constructor 6 % (one signed distance for each of the n edge",
        "midpoints, then up to 40000 probes), the packing itself 3.7 %, YAML 1.5 %.",
        "",
        "After: every query goes through the edge tree (core/geometry/edge_chain_tree.hpp): runs of",
        "consecutive edges bounded by their box and by a box aligned with their chord; the nearest edge by",
        "depth-first search, nearer child first; the inside test sums whole every run that meets the",
        "point's height only left or only right of it (the winding terms telescope) and looks at the few",
        "edges that meet it near the point; walls by a range search; the simplicity check is CGAL's exact",
        "sweep (O(n log n); the old sweep over x alone was quadratic for long edges side by side). The",
        "deepest-point search is unchanged and costs O(log n) a probe now. Every answer is the same double",
        "as the old loops' (tests/geometry/polygon_loops.hpp keeps them as the reference), so the",
        "packings and every figure are unchanged (column `outputs`). The metrics needed no change of",
        "their own: they are linear in the particles and were slow only through the container's queries.",
        "",
        "At 10^6 vertices most of the remaining time is yaml-cpp reading the 45 MB scene and freeing its",
        "node tree (about 85 % of the samples of `pack`); the construction (simplicity sweep, tree,",
        "deepest point) is about 10 %, packing and metrics about 5 %: linear, but a file of vertices",
        "read without YAML would be the next step.",
        "",
        "Packing time on the coastline grows faster than n (0.3 s at 10^5, 9 s at 10^6) for a fixed",
        "number of particles: its edges (3e-6 long at 10^6) are far shorter than the particles, and the",
        "front tries every edge and reflex corner within reach of a boundary particle as a body to",
        "touch (tens of thousands at 10^6), each with its contact solve and containment test. That is",
        "the front's wall handling (front/), not the container's queries.",
        "",
    ]
    with open(os.path.join(HERE, "RESULTS.md"), "w") as f:
        f.write("\n".join(L))
    print("wrote", os.path.join(HERE, "RESULTS.md"))


if __name__ == "__main__":
    main()
