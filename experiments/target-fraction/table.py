#!/usr/bin/env python3
"""Tables of experiments/target-fraction from run.py's results.json: mean (and spread) over seeds.
Usage: table.py OUT_DIR"""
import json
import os
import statistics
import sys


def main():
    rows = json.load(open(os.path.join(sys.argv[1], "results.json")))
    keys = []
    for r in rows:
        k = (r["scene"], r["phi"], r["mode"])
        if k not in keys:
            keys.append(k)
    print("| scene | phi | mode | N | VF container | VF cells mean | cells sd | cells min .. max | radii p (min) | z | rattlers | contact level | pack s | thinning s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for k in keys:
        g = [r for r in rows if (r["scene"], r["phi"], r["mode"]) == k]
        m = lambda key: statistics.fmean(r[key] for r in g)
        lvl = sorted({r["level"] for r in g if r["level"] is not None})
        th = [r["thinning_s"] for r in g if r["thinning_s"] is not None]
        reached = all(r["reached"] for r in g)
        vf = f"{m('vf_container'):.4f}" + ("" if reached else " (not reached)")
        print(f"| {k[0]} | {k[1]} | {k[2]} | {m('n'):.0f} | {vf} | {m('cells_mean'):.4f} | {m('cells_sd'):.4f} | "
              f"{min(r['cells_min'] for r in g):.3f} .. {max(r['cells_max'] for r in g):.3f} | {min(r['radii_p'] for r in g):.3f} | "
              f"{m('z'):.2f} | {m('rattlers'):.3f} | {','.join(map(str, lvl)) or '-'} | {m('pack_s'):.2f} | "
              f"{statistics.fmean(th):.3f} |" if th else
              f"| {k[0]} | {k[1]} | {k[2]} | {m('n'):.0f} | {vf} | {m('cells_mean'):.4f} | {m('cells_sd'):.4f} | "
              f"{min(r['cells_min'] for r in g):.3f} .. {max(r['cells_max'] for r in g):.3f} | {min(r['radii_p'] for r in g):.3f} | "
              f"{m('z'):.2f} | {m('rattlers'):.3f} | - | {m('pack_s'):.2f} | - |")
    print()
    print("| scene | phi | mode | slabs across x (seed 1) |")
    print("|---|---|---|---|")
    for k in keys:
        g = [r for r in rows if (r["scene"], r["phi"], r["mode"]) == k and "slabs" in r]
        if g:
            print(f"| {k[0]} | {k[1]} | {k[2]} | {' '.join(f'{v:.3f}' for v in g[0]['slabs'])} |")


if __name__ == "__main__":
    main()
