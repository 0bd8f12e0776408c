#!/usr/bin/python3
"""coordination.png: frequency of the coordination number c (particle-particle contacts) per particle
for the two Valera cube packings, seed 1, default and paper settings (cf. paper 002, Fig. 6).

Reads coordination_hist.csv written by run.py in this folder. Needs Debian's python3-matplotlib.
    /usr/bin/python3 experiments/valera2015-table1/plot.py
"""

import csv
import os
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
LABEL = {"valera-cube": "cube 0.9, U[0.01, 0.02]", "valera-db": "cube 266, D_B"}
STYLE = {"valera-cube": "-", "valera-db": "--"}
COLOR = {"default": "tab:blue", "paper": "tab:red"}


def main():
    hist = defaultdict(dict)
    with open(os.path.join(HERE, "coordination_hist.csv")) as f:
        for row in csv.DictReader(f):
            if row["scene"] in LABEL:
                hist[(row["scene"], row["settings"])][int(row["z"])] = int(row["count"])
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for (scene, settings), h in sorted(hist.items()):
        n = sum(h.values())
        zs = list(range(0, max(h) + 1))
        mean = sum(z * c for z, c in h.items()) / n
        ax.plot(zs, [100.0 * h.get(z, 0) / n for z in zs], STYLE[scene], color=COLOR[settings], marker="o", ms=3,
                label=f"{LABEL[scene]}, {settings} settings (mean {mean:.2f})")
    ax.set_xlabel("coordination number c (particle contacts)")
    ax.set_ylabel("particles (%)")
    ax.set_title("frontpack, seed 1 (paper 002 Fig. 6: mean 6.31)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "coordination.png"), dpi=120)


if __name__ == "__main__":
    main()
