#!/usr/bin/env python3
"""Figures of experiments/jerier2010 from run.py's results.json, beside paper 000's Figs. 4, 6, 7, 8.
Usage: plots.py OUT_DIR (reads OUT_DIR/results.json, writes OUT_DIR/fig*.png and prints the tables)."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    out = sys.argv[1]
    rows = json.load(open(os.path.join(out, "results.json")))
    pick = lambda prefix: [r for r in rows if r["tag"].startswith(prefix)]

    # Fig. 4: phi (probe) and z against R.
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for name, prefix, style in [("filled, eps 0", "fig4a-R", "o-"), ("filled, eps 0.05", "fig4a-R", "s--"),
                                ("filled + r_min fallback", "fig4a-R", "^-."), ("phi0 0.46 loose, eps 0", "fig4b-R", "v:")]:
        rs = [r for r in pick(prefix) if (("fallback" in name) == r["fallback"])
              and (r["eps"] == (0.05 if "0.05" in name else 0.0))]
        rs.sort(key=lambda r: r["R"])
        ax[0].plot([r["R"] for r in rs], [r["phi_probe"] for r in rs], style, label=name)
        ax[1].plot([r["R"] for r in rs], [r["z"] for r in rs], style, label=name)
    ax[0].set_xlabel("R = r_max / r_min"), ax[0].set_ylabel("solid fraction in the probe (Eq. 16)"), ax[0].legend()
    ax[1].set_xlabel("R = r_max / r_min"), ax[1].set_ylabel("coordination z"), ax[1].legend()
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig4.png"), dpi=110)

    # Fig. 6: z(xi) and the radii's pdf at R = 7, loose (phi0 0.46) and dense.
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for name, tag in [("loose, phi0 0.46", "fig4b-R7-eps0.0"), ("dense", "fig4a-R7-eps0.0"), ("dense + r_min fallback", "fig4a-R7-fallback")]:
        r = next(x for x in rows if x["tag"] == tag)
        ax[0].plot(r["partial_z"]["xi"], r["partial_z"]["z"], "o-", label=f"{name} (phi {r['phi_probe']:.3f})")
        bins = len(r["radii_pdf"])
        centres = [r["r_min"] + (k + 0.5) * (r["r_max"] - r["r_min"]) / bins for k in range(bins)]
        ax[1].plot(centres, r["radii_pdf"], "-", label=name)
    ax[0].set_xlabel("xi"), ax[0].set_ylabel("z(xi)"), ax[0].legend()
    ax[1].set_xlabel("radius"), ax[1].set_ylabel("pdf"), ax[1].set_yscale("log"), ax[1].legend()
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig6.png"), dpi=110)

    # Fig. 7: fabric eigenvalues against R; g(r).
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    rs = sorted([r for r in pick("fig4a-R") if r["eps"] == 0.0 and not r["fallback"]], key=lambda r: r["R"])
    for k in range(3):
        ax[0].plot([r["R"] for r in rs], [sorted(r["fabric"]["eigenvalues"])[k] for r in rs], "o-", label=f"F{k + 1}")
    ax[0].axhline(1 / 3, ls="--", c="k"), ax[0].set_xlabel("R"), ax[0].set_ylabel("fabric eigenvalues"), ax[0].legend()
    for r in rs[::2]:
        ax[1].plot(r["rdf_r"], r["rdf_g"], label=f"R = {r['R']}")
    ax[1].set_xlabel("r / <d>"), ax[1].set_ylabel("g(r)"), ax[1].legend()
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig7.png"), dpi=110)

    # Fig. 8: time against the number of tetrahedra (phi0 0.6) and against phi0.
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    rs = sorted(pick("fig8a-"), key=lambda r: r["tets"])
    ax[0].plot([r["tets"] for r in rs], [r["pack_s"] for r in rs], "o-", label="pack (steps 2-7b)")
    ax[0].set_xlabel("tetrahedra"), ax[0].set_ylabel("seconds"), ax[0].legend()
    rs = sorted(pick("fig8b-"), key=lambda r: r["phi0"])
    ax[1].plot([r["phi_container"] for r in rs], [r["pack_s"] for r in rs], "o-")
    ax[1].set_xlabel("solid fraction reached (container)"), ax[1].set_ylabel("seconds")
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig8.png"), dpi=110)

    print("| run | tets | R | eps | N | phi probe | phi container | phi core | z | F1 F2 F3 | pack s | max overlap / r_min |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        ev = sorted(r["fabric"]["eigenvalues"])
        print(f"| {r['tag']} | {r['tets']} | {r['R']} | {r['eps']} | {r['N']} | {r['phi_probe']:.4f} | {r['phi_container']:.4f} | "
              f"{r['phi_core']:.4f} | {r['z']:.2f} | {ev[0]:.3f} {ev[1]:.3f} {ev[2]:.3f} | {r['pack_s']:.2f} | {r['max_overlap_rmin']:.2g} |")


if __name__ == "__main__":
    main()
