"""Sand with a few gravel grains: a discrete law whose large class is rare by count (1 : 1000), at
size ratios 10 and 100, in boxes a few large diameters wide and in larger ones, beside the small
class alone in the same boxes; then the wide laws the same machinery meets (a 99 : 1 mix of radii
100 times apart, lognormal and uniform radii 50 times apart). What the front places of the large
class, what waited and never found room, the container's and the core's solid fractions, the radii
test and the exit code.

  FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/extremes/rare_large_class.py [--fines]

With --fines, a second table: laws whose large class holds nearly all of the volume, packed as a
skeleton of the large class with the fines put on it; how many fines each skeleton grain holds.

Seed 42 for every run, one thread, the default pool of 4. 'large' counts radii above half the
law's largest; 'expected' is the law's share of them times the particles placed. 'large centres
K-S' is the largest sqrt(n) D of the large centres' coordinates against uniform over the box
where a large centre fits (1.36: p = 0.05), a test of where they were put."""
import math
import sys

from pack_once import pack


def discrete(small, large):
    return f"{{distribution: discrete, values: [[{small}, 1000], [{large}, 1]]}}" if large else \
        f"{{distribution: constant, value: {small}}}"


CASES = [  # name, radius law, box side, largest radius, share of the large class by count
    ("0.01 : 0.1 (ratio 10)", discrete(0.01, 0.1), 0.5, 0.1, 1 / 1001),
    ("0.01 alone", discrete(0.01, None), 0.5, None, None),
    ("0.01 : 0.1 (ratio 10)", discrete(0.01, 0.1), 1.0, 0.1, 1 / 1001),
    ("0.01 alone", discrete(0.01, None), 1.0, None, None),
    ("0.01 : 0.1 (ratio 10)", discrete(0.01, 0.1), 2.0, 0.1, 1 / 1001),
    ("0.01 alone", discrete(0.01, None), 2.0, None, None),
    ("0.001 : 0.1 (ratio 100)", discrete(0.001, 0.1), 0.3, 0.1, 1 / 1001),
    ("0.001 : 0.1 (ratio 100)", discrete(0.001, 0.1), 0.6, 0.1, 1 / 1001),
    ("99 : 1 of [0.001, 0.0011] : [0.09, 0.1]",
     "{distribution: histogram, edges: [0.001, 0.0011, 0.09, 0.1], weights: [99, 0, 1]}", 0.6, 0.1, 0.01),
    ("lognormal, median 0.01, sigma 0.8, [0.002, 0.1]",
     "{distribution: lognormal, median: 0.01, sigma: 0.8, min: 0.002, max: 0.1}", 0.5, 0.1, None),
    ("uniform [0.001, 0.05]", "{distribution: uniform, min: 0.001, max: 0.05}", 1.0, 0.05, None),
]


def run(law, side):
    return pack(f"dimension: 3\nseed: 42\ncontainer: {{type: box, min: [0,0,0], max: [{side},{side},{side}]}}\n"
                f"particles: {{radius: {law}}}\n", rows=True)


def uniformity(centres, lo, hi):
    """The largest sqrt(n) D over the axes of the centres against uniform on [lo, hi]."""
    worst = 0.0
    for axis in range(3):
        u = sorted((c[axis] - lo) / (hi - lo) for c in centres)
        n = len(u)
        if n == 0:
            return float("nan")
        d = max(max((i + 1) / n - x, x - i / n) for i, x in enumerate(u))
        worst = max(worst, d * math.sqrt(n))
    return worst


def fraction(v):
    return "-" if v is None else f"{v:.3f}"


print("| radii | box side | placed | large placed (expected) | waited / never found room | large centres K-S | "
      "container VF | core VF | radii test | exit | time (s) |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for name, law, side, largest, share in CASES:
    code, wall, rec, rows = run(law, side)
    radii = [row[-1] for row in rows]
    m, c = rec["metrics"], rec["counters"]
    n = len(radii)
    test = rec["analysis"]["validation"].get("radii", {})
    large, ks = "-", "-"
    if largest:
        big = sum(r > 0.5 * largest for r in radii)
        large = f"{big} ({n * share:.1f})" if share else str(big)
        ks = f"{uniformity([row[1:4] for row in rows if row[-1] > 0.5 * largest], largest, side - largest):.2f}"
    waited = f"{c.get('radii_waited', '-')} / {c.get('radii_never_fit', '-')}"  # '-': a frontpack without them
    print(f"| {name} | {side} | {n} | {large} | {waited} | {ks} | {fraction(m['volume_fraction_container'])} | "
          f"{fraction(m['volume_fraction_core'])} | p = {test.get('p', float('nan')):.2g} | {code} | {wall:.1f} |")


def fines_per_grain(rows, threshold):
    """Per skeleton grain (radius above threshold) the fines touching it (centre distance within
    1e-9 of the sum of radii; each fine counted with the first grain it touches); fines touching
    none."""
    import numpy as np
    a = np.array(rows)
    big, small = a[a[:, -1] > threshold], a[a[:, -1] <= threshold]
    order = np.argsort(small[:, 1])
    small = small[order]
    counts, taken = [], np.zeros(len(small), dtype=bool)
    for g in big:
        reach = g[-1] + small[:, -1].max() + 1e-9
        lo, hi = np.searchsorted(small[:, 1], [g[1] - reach, g[1] + reach])
        d = np.linalg.norm(small[lo:hi, 1:4] - g[1:4], axis=1)
        touch = (np.abs(d - (g[-1] + small[lo:hi, -1])) <= 1e-9 * g[-1]) & ~taken[lo:hi]
        taken[lo:hi] |= touch
        counts.append(int(touch.sum()))
    return counts, int((~taken).sum())


if "--fines" in sys.argv:
    print()
    print("| radii | box side | placed | skeleton grains | fines | fines per grain: mean / sd (binomial sd) / min / max | "
          "fines touching no grain | container VF | core VF | radii test | exit | time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, law, side in [("0.001 : 0.1 (ratio 100)", discrete(0.001, 0.1), 0.6),
                            ("0.001 : 0.1 (ratio 100)", discrete(0.001, 0.1), 1.2),
                            ("0.001 : 0.1 (ratio 100)", discrete(0.001, 0.1), 2.0),
                            ("99 : 1 of [0.001, 0.0011] : [0.09, 0.1]",
                             "{distribution: histogram, edges: [0.001, 0.0011, 0.09, 0.1], weights: [99, 0, 1]}", 1.2)]:
        code, wall, rec, rows = run(law, side)
        m = rec["metrics"]
        counts, loose = fines_per_grain(rows, 0.05)
        n_fines = sum(counts) + loose
        mean = sum(counts) / len(counts)
        sd = math.sqrt(sum((c - mean) ** 2 for c in counts) / max(1, len(counts) - 1))
        binomial = math.sqrt(sum(counts) * (1 / len(counts)) * (1 - 1 / len(counts)))
        test = rec["analysis"]["validation"].get("radii", {})
        print(f"| {name} | {side} | {len(rows)} | {len(counts)} | {n_fines} | {mean:.0f} / {sd:.1f} ({binomial:.1f}) / "
              f"{min(counts)} / {max(counts)} | {loose} | {fraction(m['volume_fraction_container'])} | "
              f"{fraction(m['volume_fraction_core'])} | p = {test.get('p', float('nan')):.2g} | {code} | {wall:.1f} |", flush=True)
