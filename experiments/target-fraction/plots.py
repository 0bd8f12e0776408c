#!/usr/bin/env python3
"""Figures of experiments/target-fraction: the solid fraction in slabs across the box (target against
stop, seed 1) and the per-cell standard deviation against phi for every scene (mean over seeds).
Usage: plots.py OUT_DIR (reads OUT_DIR/results.json, writes OUT_DIR/slabs.png and cells.png)"""
import json
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    out = sys.argv[1]
    rows = json.load(open(os.path.join(out, "results.json")))
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    for a, scene in zip(ax, ["box", "box-R7-large", "disks"]):
        phis = sorted({r["phi"] for r in rows if r["scene"] == scene})
        for k, phi in enumerate(phis):
            for mode, style in (("target", "o-"), ("stop", "x--")):
                r = next(x for x in rows if x["scene"] == scene and x["phi"] == phi and x["mode"] == mode and x["seed"] == 1)
                n = len(r["slabs"])
                a.plot([(q + 0.5) / n for q in range(n)], r["slabs"], style, c=f"C{k}",
                       label=f"{mode} {phi}" if mode == "target" or k == 0 else None)
        a.set_title(scene), a.set_xlabel("x / side (6 slabs)"), a.set_ylabel("solid fraction in the slab")
    ax[0].legend(fontsize=7, ncol=2)
    fig.tight_layout(), fig.savefig(os.path.join(out, "slabs.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6, 4))
    for k, scene in enumerate(sorted({r["scene"] for r in rows})):
        for mode, style in (("target", "o-"), ("stop", "x--")):
            g = [r for r in rows if r["scene"] == scene and r["mode"] == mode and r["reached"]]
            phis = sorted({r["phi"] for r in g})
            ax.plot(phis, [statistics.fmean(r["cells_sd"] for r in g if r["phi"] == p) for p in phis], style, c=f"C{k}",
                    label=f"{scene} ({mode})")
    ax.set_xlabel("phi asked"), ax.set_ylabel("sd of the cells' solid fraction"), ax.set_yscale("log")
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout(), fig.savefig(os.path.join(out, "cells.png"), dpi=110)


if __name__ == "__main__":
    main()
