#!/usr/bin/env python3
"""Figures of experiments/jerier2010 from run.py's results.json, beside paper 000's Figs. 4, 6, 7, 8.
Usage: plots.py OUT_DIR [--unstructured] (reads OUT_DIR/results.json, or results-unstructured.json, writes
OUT_DIR/fig*.png (fig*-unstructured.png) and prints the tables)."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def stats(values):
    n = len(values)
    mean = sum(values) / n
    return mean, (sum((v - mean) ** 2 for v in values) / (n - 1)) ** 0.5 if n > 1 else 0.0


def unstructured(out):
    """Figs. 4, 6, 7, 8 on the STL cube meshed by frontpack, mean and spread over the seeds."""
    rows = json.load(open(os.path.join(out, "results-unstructured.json")))
    seeds = sorted({r["seed"] for r in rows})
    group = lambda stem: [r for r in rows if r["tag"].rsplit("-s", 1)[0] == stem]

    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for name, stem in [("filled, eps 0", "u4a-R{}-eps0.0"), ("filled, eps 0.05", "u4a-R{}-eps0.05"),
                       ("phi0 0.46 loose", "u4b-R{}")]:
        Rs = [2, 3, 4, 5, 6, 7]
        for k, key in enumerate(["phi_probe", "z"]):
            ms = [stats([r[key] for r in group(stem.format(R))]) for R in Rs]
            ax[k].errorbar(Rs, [m for m, _ in ms], yerr=[e for _, e in ms], fmt="o-", capsize=3, label=name)
    ax[0].set_xlabel("R"), ax[0].set_ylabel("solid fraction in the probe (Eq. 16)"), ax[0].legend()
    ax[1].set_xlabel("R"), ax[1].set_ylabel("coordination z"), ax[1].legend()
    fig.suptitle(f"unstructured mesh (STL cube meshed by frontpack), seeds {seeds}")
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig4-unstructured.png"), dpi=110)

    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for name, stem, c in [("loose, phi0 0.46", "u4b-R7", "C0"), ("dense", "u4a-R7-eps0.0", "C1"),
                          ("dense + r_min fallback", "u4a-R7-eps0.0-fallback", "C2")]:
        for k, r in enumerate(group(stem)):
            label = f"{name} (phi {stats([x['phi_probe'] for x in group(stem)])[0]:.3f})" if k == 0 else None
            ax[0].plot(r["partial_z"]["xi"], r["partial_z"]["z"], "o-", c=c, ms=3, label=label)
            bins = len(r["radii_pdf"])
            centres = [r["r_min"] + (q + 0.5) * (r["r_max"] - r["r_min"]) / bins for q in range(bins)]
            ax[1].plot(centres, r["radii_pdf"], "-", c=c, label=name if k == 0 else None)
    ax[0].set_xlabel("xi"), ax[0].set_ylabel("z(xi)"), ax[0].legend()
    ax[1].set_xlabel("radius"), ax[1].set_ylabel("pdf"), ax[1].set_yscale("log"), ax[1].legend()
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig6-unstructured.png"), dpi=110)

    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    Rs = [2, 3, 4, 5, 6, 7]
    for k in range(3):
        ms = [stats([sorted(r["fabric"]["eigenvalues"])[k] for r in group(f"u4a-R{R}-eps0.0")]) for R in Rs]
        ax[0].errorbar(Rs, [m for m, _ in ms], yerr=[e for _, e in ms], fmt="o-", capsize=3, label=f"F{k + 1}")
    ax[0].axhline(1 / 3, ls="--", c="k"), ax[0].set_xlabel("R"), ax[0].set_ylabel("fabric eigenvalues"), ax[0].legend()
    for R in [2, 4, 6]:
        r = group(f"u4a-R{R}-eps0.0")[0]
        ax[1].plot(r["rdf_r"], r["rdf_g"], label=f"R = {R}")
    ax[1].set_xlabel("r / <d>"), ax[1].set_ylabel("g(r)"), ax[1].legend()
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig7-unstructured.png"), dpi=110)

    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for seed in seeds:
        rs = sorted([r for r in rows if r["tag"].startswith("u8a-") and r["seed"] == seed], key=lambda r: r["tets"])
        ax[0].plot([r["tets"] for r in rs], [r["pack_s"] for r in rs], "o-", label=f"seed {seed}")
        rs = sorted([r for r in rows if r["tag"].startswith("u8b-") and r["seed"] == seed], key=lambda r: r["phi0"])
        ax[1].plot([r["phi_container"] for r in rs], [r["pack_s"] for r in rs], "o-", label=f"seed {seed}")
    ax[0].set_xlabel("tetrahedra"), ax[0].set_ylabel("pack seconds (steps 2-7b)"), ax[0].legend()
    ax[1].set_xlabel("solid fraction reached (container)"), ax[1].set_ylabel("pack seconds"), ax[1].legend()
    fig.tight_layout(), fig.savefig(os.path.join(out, "fig8-unstructured.png"), dpi=110)

    print("| runs | tets | R | eps | N | phi probe | phi container | z | F1 F2 F3 | pack s | max overlap / r_min |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    stems = []
    for r in rows:
        stem = r["tag"].rsplit("-s", 1)[0]
        if stem not in stems:
            stems.append(stem)
    for stem in stems:
        g = group(stem)
        ev = [stats([sorted(r["fabric"]["eigenvalues"])[k] for r in g])[0] for k in range(3)]
        pm, ps = stats([r["phi_probe"] for r in g])
        cm, cs = stats([r["phi_container"] for r in g])
        zm, zs = stats([r["z"] for r in g])
        print(f"| {stem} (x{len(g)}) | {g[0]['tets']} | {g[0]['R']} | {g[0]['eps']} | {stats([r['N'] for r in g])[0]:.0f} | "
              f"{pm:.4f} +- {ps:.4f} | {cm:.4f} +- {cs:.4f} | {zm:.2f} +- {zs:.2f} | {ev[0]:.3f} {ev[1]:.3f} {ev[2]:.3f} | "
              f"{min(r['pack_s'] for r in g):.2f} .. {max(r['pack_s'] for r in g):.2f} | {max(r['max_overlap_rmin'] for r in g):.2g} |")


def main():
    out = sys.argv[1]
    if "--unstructured" in sys.argv:
        unstructured(out)
        return
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
