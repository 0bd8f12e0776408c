#!/usr/bin/env python3
"""Tables (Markdown, on stdout) and figures of run.py's results.json: the paper's cases by group,
density reached against asked for each method (mean and spread over the seeds), coordination
histograms, time against N.
Usage: report.py OUT_DIR/results.json FIG_DIR   (needs Debian's python3-matplotlib)"""
import json
import statistics
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAPER = {"2d-R7": "0.826-0.860", "2d-R2": "0.787-0.814", "3d-R7": "0.667-0.703", "3d-R2": "0.553-0.597"}

rows = json.load(open(sys.argv[1]))
figs = Path(sys.argv[2])
figs.mkdir(parents=True, exist_ok=True)

cases = defaultdict(list)  # (group, phi, method) -> seeds
for r in rows.values():
    if r["case"].startswith("scaling-"):
        continue
    group, phi, method = r["case"].rsplit("-", 3)[0], r["phi"], r["case"].rsplit("-", 2)[1]
    cases[(group, phi, method)].append(r)


def ms(values, digits=4):
    m = statistics.fmean(values)
    s = statistics.stdev(values) if len(values) > 1 else 0.0
    return f"{m:.{digits}f} ± {s:.{digits}f}"


print("| group (paper's range) | φ asked | method | VF reached | left out of asked | cells sd | radii test p (min) | z | rattlers | s | particles / s |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for (group, phi, method), rs in sorted(cases.items(), key=lambda kv: (kv[0][0], kv[0][1], ["paper", "contacts_first", "front"].index(kv[0][2]))):
    left = " / ".join(f"{r['unplaced']} of {r['asked']}" for r in rs) if "asked" in rs[0] else "-"
    rate = statistics.fmean(r["particles"] / r["pack_seconds"] for r in rs)
    print(f"| {group} ({PAPER[group[:5]]}) | {phi} | {method} | {ms([r['vf'] for r in rs])} | {left} | "
          f"{ms([r['cells_sd'] for r in rs], 3)} | {min(r['radii_p'] for r in rs):.2g} | {ms([r['z'] for r in rs], 2)} | "
          f"{100 * statistics.fmean(r['rattlers'] for r in rs):.1f} % | {statistics.fmean(r['pack_seconds'] for r in rs):.2f} | "
          f"{rate:,.0f} |")

# Coordination histograms at the paper's low density (seed 1), stacking against the front.
fig, axes = plt.subplots(1, 4, figsize=(16, 3.6))
for ax, group in zip(axes, ["2d-R7-mass", "2d-R2-mass", "3d-R7-mass", "3d-R2-mass"]):
    phi = min(p for (g, p, _m) in cases if g == group)
    for method, style in (("paper", "o-"), ("contacts_first", "s-"), ("front", "^--")):
        rs = cases.get((group, phi, method))
        if not rs:
            continue
        h = rs[0]["z_histogram"]
        total = sum(h)
        ax.plot(range(len(h)), [c / total for c in h], style, label=f"{method} (VF {rs[0]['vf']:.3f})")
    ax.set_title(f"{group}, φ asked {phi}")
    ax.set_xlim(-0.5, 16.5)  # at R = 7 a large particle can touch 80 small ones: a long thin tail
    ax.set_xlabel("contacts per particle")
    ax.set_ylabel("share of particles")
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(figs / "coordination.png", dpi=110)

# Time against N.
fig, ax = plt.subplots(figsize=(5.5, 4))
for group in ("3d-R2-mass", "2d-R2-mass"):
    pts = sorted((r["particles"], r["pack_seconds"]) for r in rows.values() if r["case"].startswith(f"scaling-{group}-"))
    if pts:
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=group)
        n0, t0 = pts[0]
        ax.loglog([p[0] for p in pts], [t0 * p[0] / n0 for p in pts], ":", color="grey")
ax.set_xlabel("particles placed")
ax.set_ylabel("stacking time (s, one core)")
ax.set_title("time against N (dotted: linear)")
ax.legend()
fig.tight_layout()
fig.savefig(figs / "time_vs_n.png", dpi=110)

print()
print("| scaling case | particles | s | particles / s |")
print("|---|---|---|---|")
for r in sorted((r for r in rows.values() if r["case"].startswith("scaling-")), key=lambda r: (r["dimension"], r["particles"])):
    print(f"| {r['case']} | {r['particles']} | {r['pack_seconds']:.2f} | {r['particles'] / r['pack_seconds']:,.0f} |")
