#!/usr/bin/python3
"""2D against 3D (README: Comparative studies): study.yaml through the Python module, then the
figure the study's own do not draw: each family's 2D area fraction against its 3D volume
fraction, and its coordination in 2D against 3D, and the table of RESULTS.md.

    PYTHONPATH=build-test /usr/bin/python3 experiments/2d-vs-3d/run.py     (from the repository)
"""
import os
import statistics
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import frontpack

HERE = os.path.dirname(os.path.abspath(__file__))
FIGURES = (("metrics.volume_fraction_core", "solid fraction of the core (2 r_max from the walls)"),
           ("metrics.mean_coordination", "mean coordination (particle contacts)"))


def main():
    out = frontpack.study(os.path.join(HERE, "study.yaml"),
                          progress=lambda done, total, row: print(f"[{done}/{total}] {row['run']} {row['status']}", flush=True))
    if out["failed"] or out["invalid"]:
        sys.exit(f"{out['failed']} runs failed, {out['invalid']} invalid: see {out['csv']}")
    groups = {}
    for row in out["rows"]:
        groups.setdefault((row["family"], row["dimension"]), []).append(row)
    families = list(dict.fromkeys(row["family"] for row in out["rows"]))

    def stat(family, dim, key):
        values = [r[key] for r in groups[(family, dim)]]
        return statistics.mean(values), statistics.stdev(values) if len(values) > 1 else 0.0

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, (key, label) in zip(axes, FIGURES):
        for family in families:
            (x, sx), (y, sy) = stat(family, 2, key), stat(family, 3, key)
            ax.errorbar(x, y, xerr=sx, yerr=sy, marker="o", capsize=3, label=family)
        ax.set_xlabel(f"2D: {label}")
        ax.set_ylabel(f"3D: {label}")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("the same template and size law in 2D and 3D (mean and sd over the seeds)")
    fig.savefig(os.path.join(HERE, "2d_vs_3d.png"), dpi=110, bbox_inches="tight")

    print("\n| family | D | N | solid fraction container | core | coordination | rattlers | particles/s |")
    print("|---|---|---|---|---|---|---|---|")
    for family in families:
        for dim in (2, 3):
            rows = groups[(family, dim)]
            def ms(key, fmt):
                m, s = stat(family, dim, key)
                return f"{m:{fmt}} ± {s:{fmt}}"
            print(f"| {family} | {dim} | {statistics.mean(r['n'] for r in rows):,.0f} | "
                  f"{ms('metrics.volume_fraction_container', '.4f')} | {ms('metrics.volume_fraction_core', '.4f')} | "
                  f"{ms('metrics.mean_coordination', '.3f')} | {ms('metrics.rattler_fraction', '.3f')} | "
                  f"{ms('metrics.particles_per_second', ',.0f')} |")
    for family in families:
        (a2, _), (v3, _) = stat(family, 2, "metrics.volume_fraction_core"), stat(family, 3, "metrics.volume_fraction_core")
        print(f"{family}: core 3D/2D = {v3 / a2:.3f}")


if __name__ == "__main__":
    main()
