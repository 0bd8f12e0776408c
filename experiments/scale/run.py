#!/usr/bin/python3
"""The plan for 10^9 spheres: what a rank does, measured on this machine with
K = 1, 2, 4, 8 ranks (oversubscribed beyond 2: the CPU time per rank is what counts there, not the
wall time), and the order of growth of front/block_front.hpp simulated for many ranks.

Usage: run.py FRONTPACK OUTDIR [sizes...]    (sizes: particle counts, default 100000 1000000)

1. Measured. Boxes that hold about N spheres U[0.01, 0.02] (filled: no count stop, nothing
   trimmed), blocks of 0.32 (16 r_max, the automatic edge's floor). K = 1: `pack -j 1` (the same
   blocks on one thread); K > 1: `mpirun -np K pack` (same bytes, checked). Per run: wall time,
   peak memory of the one-process run, the record's per-rank work (blocks, particles, fixed
   particles of other blocks grown against, MB sent, seconds growing and waiting), the CSV and
   VTU sizes.
2. Simulated. The blocks' dependency graph (block (i, j, k) after its lower-rank neighbours,
   rank i + 2j + 4k) for n^3 blocks, its longest chain, and list scheduling on K workers with
   blocks dealt out in index order (index mod K, as front/block_front.hpp) and equal block costs: the speed-up the order of growth
   allows, up to 1,000 ranks.
Prints markdown tables.
"""
import heapq
import json
import os
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe"]
MEAN_BALL = 4 / 3 * 3.141592653589793 * (0.02 ** 4 - 0.01 ** 4) / (4 * 0.01)  # E[4/3 pi r^3], r ~ U[0.01, 0.02]


def box_scene(path, n):
    side = (n * MEAN_BALL / 0.6) ** (1 / 3)
    path.write_text("dimension: 3\nseed: 1\ncontainer: {type: box, min: [0, 0, 0], max: [%.4f, %.4f, %.4f]}\n"
                    "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\npacker: {block_edge: 0.32}\n"
                    % (side, side, side))
    return side


def run(binary, scene, k, out):
    csv = out / ("k%d.csv" % k)
    rec = out / ("k%d.json" % k)
    cmd = ([binary, "pack", str(scene), "-j", "1"] if k == 1 else MPIRUN + ["-np", str(k), binary, "pack", str(scene)])
    cmd = ["/usr/bin/time", "-f", "%e %M"] + cmd + ["-q", "-o", str(csv), "--record", str(rec)]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        raise SystemExit("failed: %s\n%s" % (" ".join(cmd), r.stderr[-1500:]))
    wall, rss = r.stderr.strip().splitlines()[-1].split()
    d = json.loads(rec.read_text())
    ranks = [v for key, v in d["info"].items() if key.startswith("rank_")] if isinstance(d["info"], dict) else \
        [v for key, v in d["info"] if key.startswith("rank_")]
    return {"wall": float(wall), "rss_mb": int(rss) / 1024, "n": d["n"], "pack": d["timings"]["pack"],
            "blocks": d["counters"]["blocks"], "ranks": ranks, "csv": csv}


def measured(binary, out, sizes):
    print("| spheres | box side | ranks K | blocks | pack s (wall) | whole process s (wall) | peak MB (K = 1) | bytes per sphere (K = 1) | per rank: blocks, particles, fixed, sent, grew, waited |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n in sizes:
        scene = out / ("n%d.yaml" % n)
        side = box_scene(scene, n)
        first = None
        for k in (1, 2, 4, 8):
            r = run(binary, scene, k, out)
            if first is None:
                first = r
                vtu = out / "k1.vtu"
                subprocess.run([binary, "pack", str(scene), "-j", "1", "-q", "-o", str(vtu)], check=True)
                io = (os.path.getsize(first["csv"]) / r["n"], os.path.getsize(vtu) / r["n"])
            elif first["csv"].read_bytes() != r["csv"].read_bytes():
                raise SystemExit("K = %d wrote other bytes than K = 1" % k)
            print("| %d | %.3f | %d | %d | %.2f | %.2f | %s | %s | %s |" % (
                r["n"], side, k, r["blocks"], r["pack"], r["wall"], "%.0f" % r["rss_mb"] if k == 1 else "",
                "%.0f" % (r["rss_mb"] * 2 ** 20 / r["n"]) if k == 1 else "", "<br>".join(r["ranks"])))
        print("| | | | | | | | CSV %.1f B, VTU %.1f B per sphere | |" % io)


def rank_of(i, j, k):
    return i + 2 * j + 4 * k


def simulate(n, workers):
    """Longest chain of the dependency graph of n^3 blocks, and the makespan of list scheduling
    on `workers` (blocks dealt out by index mod workers, each worker taking its lowest-rank ready block),
    in block costs of 1."""
    blocks = [(i, j, k) for k in range(n) for j in range(n) for i in range(n)]
    index = {b: t for t, b in enumerate(blocks)}
    earlier = [[] for _ in blocks]
    later = [[] for _ in blocks]
    for t, (i, j, k) in enumerate(blocks):
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                for dk in (-1, 0, 1):
                    m = (i + di, j + dj, k + dk)
                    if m == (i, j, k) or not all(0 <= c < n for c in m):
                        continue
                    (earlier if rank_of(*m) < rank_of(i, j, k) else later)[t].append(index[m])
    order = sorted(range(len(blocks)), key=lambda t: rank_of(*blocks[t]))
    depth = [0] * len(blocks)
    for t in order:
        depth[t] = 1 + max((depth[e] for e in earlier[t]), default=0)
    chain = max(depth)
    waiting = [len(e) for e in earlier]
    ready = [[] for _ in range(workers)]
    for t in range(len(blocks)):
        if waiting[t] == 0:
            heapq.heappush(ready[t % workers], (rank_of(*blocks[t]), t))
    events = []  # (finish time, worker, block)
    time, done = 0, 0
    idle = set(range(workers))
    while done < len(blocks):
        for w in sorted(idle):
            if ready[w]:
                _, t = heapq.heappop(ready[w])
                heapq.heappush(events, (time + 1, w, t))
                idle.discard(w)
        time = events[0][0]
        while events and events[0][0] == time:  # every block finishing now frees its worker
            _, w, t = heapq.heappop(events)
            done += 1
            idle.add(w)
            for m in later[t]:
                waiting[m] -= 1
                if waiting[m] == 0:
                    heapq.heappush(ready[m % workers], (rank_of(*blocks[m]), m))
    return chain, time


def simulated():
    print("\n| blocks per axis n | blocks | longest chain | workers K | makespan (block costs) | speed-up | efficiency |")
    print("|---|---|---|---|---|---|---|")
    for n, ks in [(8, (2, 8, 16)), (16, (2, 16, 64)), (32, (32, 256, 1000))]:
        for k in ks:
            chain, span = simulate(n, k)
            print("| %d | %d | %d | %d | %d | %.1f | %.2f |" % (n, n ** 3, chain, k, span, n ** 3 / span, n ** 3 / span / k))


def main():
    binary, out = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
    sizes = [int(a) for a in sys.argv[3:]] or [100000, 1000000]
    out.mkdir(parents=True, exist_ok=True)
    if sizes != [0]:
        measured(binary, out, sizes)
    simulated()


if __name__ == "__main__":
    main()
