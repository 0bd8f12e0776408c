#!/usr/bin/python3
"""The figures of `frontpack study` (cli/study_command.cpp runs this with Debian's python3).

    plot_study.py RESULTS.csv PLOTS.json OUT_DIR

For each parameter P, P.png: volume fraction (area fraction in 2D), mean coordination and
placement rate against P's values, the mean over the seeds with the standard deviation as bars,
one line per combination of the other parameters (their mean over them beyond 8 lines);
rate_vs_vf.png: every run's rate against its volume fraction, a colour per combination; and
<y>_vs_<x>.png for each figure PLOTS.json asks for. The names drawn go to OUT_DIR/figures.txt.
Exit 3 when matplotlib is missing.
"""
import csv
import json
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(3)

VF = "metrics.volume_fraction_container"
Z = "metrics.mean_coordination"
RATE = "metrics.particles_per_second"
LABELS = {VF: "volume (area) fraction", Z: "mean coordination", RATE: "particles placed / s"}
MAX_LINES = 8


def number(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def mean_sd(values):
    n = len(values)
    m = sum(values) / n
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (n - 1)) if n > 1 else 0.0
    return m, sd


def save(fig, out_dir, name, drawn):
    path = os.path.join(out_dir, name)
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)
    drawn.append(name)


def x_positions(parameter):
    """The x of each value: its number (the value, or the entry a list of numbers varies in),
    or its place in the study's order."""
    if parameter["numeric"]:
        return dict(zip(parameter["values"], parameter["axis"]))
    return {v: i for i, v in enumerate(parameter["values"])}


def series(rows, parameters, x_name, y_key):
    """{line label: [(x value label, mean, sd, n)]}: rows grouped by the other parameters."""
    others = [p["name"] for p in parameters if p["name"] != x_name]
    combos = list(dict.fromkeys(tuple(r[o] for o in others) for r in rows))  # the study's order
    if len(combos) > MAX_LINES:
        others, combos = [], [()]
    x_values = next(p["values"] for p in parameters if p["name"] == x_name)
    lines = {}
    for combo in combos:
        label = ", ".join(f"{o}={v}" for o, v in zip(others, combo)) or "all runs"
        points = []
        for xv in x_values:
            ys = [number(r[y_key]) for r in rows if r[x_name] == xv and tuple(r[o] for o in others) == combo]
            ys = [y for y in ys if y is not None]
            if ys:
                m, sd = mean_sd(ys)
                points.append((xv, m, sd, len(ys)))
        if points:
            lines[label] = points
    return lines


def draw_against(ax, rows, parameters, x_name, y_key):
    parameter = next(p for p in parameters if p["name"] == x_name)
    xs = x_positions(parameter)
    for label, points in series(rows, parameters, x_name, y_key).items():
        ax.errorbar([xs[p[0]] for p in points], [p[1] for p in points], yerr=[p[2] for p in points],
                    marker="o", capsize=3, label=label)
    values = [y for line in ax.get_lines() for y in line.get_ydata()]
    positive = [v for v in values if v > 0]
    if positive and len(positive) == len(values) and max(positive) > 30 * min(positive):
        ax.set_yscale("log")  # rates of different families span orders of magnitude
    if not parameter["numeric"]:
        ax.set_xticks(list(xs.values()))
        ax.set_xticklabels(list(xs.keys()), rotation=30 if len(xs) > 4 else 0)
    ax.set_xlabel(parameter.get("axis_label", x_name))
    ax.set_ylabel(LABELS.get(y_key, y_key))
    ax.grid(alpha=0.3)


def main():
    csv_path, request_path, out_dir = sys.argv[1:4]
    with open(request_path) as f:
        request = json.load(f)
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("status") in ("ok", "invalid", "incomplete")]
    parameters = request["parameters"]
    seeds = request["seeds"]
    drawn = []
    os.makedirs(out_dir, exist_ok=True)
    for p in parameters:
        fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), gridspec_kw={"wspace": 0.3})
        for ax, key in zip(axes, (VF, Z, RATE)):
            if any(key in r for r in rows):
                draw_against(ax, rows, parameters, p["name"], key)
        axes[0].legend(fontsize=8)
        fig.suptitle(f"against {p['name']}: mean and standard deviation over {seeds} seed(s)")
        save(fig, out_dir, f"{p['name']}.png".replace("/", "_"), drawn)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    names = [p["name"] for p in parameters]
    groups = {}
    for r in rows:
        x, y = number(r.get(VF)), number(r.get(RATE))
        if x is not None and y is not None:
            groups.setdefault(", ".join(f"{n}={r[n]}" for n in names) or "all runs", []).append((x, y))
    for i, (label, points) in enumerate(groups.items()):
        ax.scatter([p[0] for p in points], [p[1] for p in points], s=18, label=label if i < 12 else None)
    ax.set_xlabel(LABELS[VF])
    ax.set_ylabel(LABELS[RATE])
    ax.set_yscale("log")
    ax.grid(alpha=0.3)
    if groups:
        ax.legend(fontsize=7)
    ax.set_title("rate against volume fraction, every run")
    save(fig, out_dir, "rate_vs_vf.png", drawn)
    for plot in request["plots"]:
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        draw_against(ax, rows, parameters, plot["x"], plot["y"])
        ax.legend(fontsize=8)
        save(fig, out_dir, f"{plot['y']}_vs_{plot['x']}.png".replace("/", "_"), drawn)
    with open(os.path.join(out_dir, "figures.txt"), "w") as f:
        f.write("\n".join(drawn) + "\n")


if __name__ == "__main__":
    main()
