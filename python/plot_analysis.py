#!/usr/bin/env python3
"""Figures of a frontpack analysis, called by `frontpack analyze --plots DIR`.

    plot_analysis.py ANALYSIS.json RADIUS_CDF.csv OUT_DIR [SECTIONS.csv OUTLINE.csv [POLYGONS.csv]]

ANALYSIS.json is core/io/analysis_json.hpp's layout; RADIUS_CDF.csv has columns
r,empirical,requested (requested empty without a scene). Writes vf_curve.png,
wall_profile.png, coordination.png, radii.png, rdf.png, partial_coordination.png and fabric.png,
and bed_profile.png for a bed. With SECTIONS.csv (plane,normal,offset,u,v,radius,size: each
sphere's exact section by a plane, core/metrics/packing_sections.hpp) and OUTLINE.csv
(plane,u0,v0,u1,v1: the container's section as segments), also section_<plane>.png for each
plane: the sections coloured by the particle's size, the container's outline in black.
POLYGONS.csv (plane,particle,size,template,u,v: the loops of the other shapes' sections, a
particle's points in order, contact/shape_sections.hpp) adds them, filled.
Exit code 3 when matplotlib is missing (Debian: apt-get install python3-matplotlib).
"""
import csv
import json
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.stderr.write("plot_analysis.py: matplotlib is missing (apt-get install python3-matplotlib)\n")
    sys.exit(3)


def save(fig, out_dir, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, name), dpi=120)
    plt.close(fig)


def vf_curve(a, out_dir):
    c = a["volume_fraction"]["curve"]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(c["r_ref"], c["vf"], "o-", ms=3)
    ax.set_xlabel("reference sphere radius r_ref")
    ax.set_ylabel("volume fraction in the reference sphere")
    ax.set_title("VF against r_ref (paper 002, Eq. 2)")
    ax.grid(alpha=0.3)
    save(fig, out_dir, "vf_curve.png")


def wall_profile(a, out_dir):
    vf = a["volume_fraction"]
    w = vf.get("wall_profile", {})
    if not w.get("vf"):
        return
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.errorbar(w["distance"], w["vf"], yerr=w["std_error"], fmt="o-", ms=3, capsize=2, label="shells of the container")
    ax.axhline(vf["core"]["value"], color="grey", ls="--", lw=0.8, label="core (2 r_max inside)")
    ax.axhline(vf["container"]["value"], color="grey", ls=":", lw=0.8, label="whole container")
    ax.set_xlabel("distance from the container's boundary")
    ax.set_ylabel("solid fraction")
    ax.set_title("wall layers: %.4f within 2 r_max" % w["layer"])
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, out_dir, "wall_profile.png")


def bed_profile(a, out_dir):
    b = a["volume_fraction"].get("bed_profile")
    if not b or not b.get("vf"):
        return
    fig, ax = plt.subplots(figsize=(4.5, 5))
    ax.plot(b["vf"], b["slab_middle"], "o-", ms=2.5, label="slabs of %.3g" % b["width"])
    if b.get("bulk") is not None:
        ax.axvline(b["bulk"], color="grey", ls="--", lw=0.8, label="bulk %.4f" % b["bulk"])
    ax.axhline(b["height"], color="black", lw=0.8, label="level")
    if b.get("half_bulk_height") is not None:
        ax.axhline(b["half_bulk_height"], color="grey", ls=":", lw=0.8, label="half the bulk")
    ax.set_xlabel("solid fraction")
    ax.set_ylabel("height above the floor")
    ax.set_title("bed profile")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, out_dir, "bed_profile.png")


def coordination(a, out_dir):
    c = a["coordination"]
    h = c["histogram"]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.bar(range(len(h)), h)
    ax.set_xlabel("contacts per particle (particles only)")
    ax.set_ylabel("particles")
    ax.set_title("coordination: mean %.3f (%.3f with walls)" % (c["mean"], c["mean_with_walls"]))
    save(fig, out_dir, "coordination.png")


def radii(cdf_path, a, out_dir):
    r, emp, req = [], [], []
    with open(cdf_path, newline="") as f:
        for row in csv.DictReader(f):
            r.append(float(row["r"]))
            emp.append(float(row["empirical"]))
            req.append(float(row["requested"]) if row["requested"] else None)
    # Shapes: the size of the one template against its law, else the volume-equivalent radius.
    shapes = a["radii"].get("name", "r") != "r"
    label = "radius" if not shapes else ("size" if req and all(v is not None for v in req) else "volume-equivalent radius r_eq")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.5))
    ax1.hist(r, bins=min(40, max(5, len(r) // 20)), density=True, alpha=0.7, label="placed (sample)")
    ax1.set_xlabel(label)
    ax1.set_ylabel("probability density")
    ax2.step(r, emp, where="post", label="placed")
    if req and all(v is not None for v in req):
        ax2.step(r, req, "--", where="post", label="requested")  # a step CDF stays one for a discrete law
        fit = a["radii_fit"]
        ax2.set_title("%s: %.4g, p = %.3g" % (fit["test"], fit["statistic"], fit["p"]))
    ax2.set_xlabel(label)
    ax2.set_ylabel("CDF")
    ax2.legend()
    ax1.legend()
    save(fig, out_dir, "radii.png")


def rdf(a, out_dir):
    g = a["rdf"]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(g["r"], g["g"], lw=1)
    ax.axhline(1.0, color="grey", lw=0.5)
    ax.set_xlabel("r / mean diameter")
    ax.set_ylabel("g(r)")
    ax.set_title("radial distribution function")
    save(fig, out_dir, "rdf.png")


def partial_coordination(a, out_dir):
    p = a["coordination"]["partial"]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(p["xi"], p["z"], "o-", ms=3)
    ax.set_xlabel("xi = (r - r_min) / (r_max - r_min)")
    ax.set_ylabel("z(xi)")
    ax.set_title("partial coordination (paper 000)")
    ax.grid(alpha=0.3)
    save(fig, out_dir, "partial_coordination.png")


def fabric(a, out_dir):
    f = a["fabric"]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    d = a["dimension"]
    width = 0.35
    for k, (name, key) in enumerate([("per contact", "per_contact"), ("per particle", "per_particle")]):
        ev = f[key]["eigenvalues"]
        ax.bar([i + k * width for i in range(len(ev))], ev, width, label=name)
    ax.axhline(1.0 / d, color="grey", lw=0.8, ls="--", label="isotropic 1/%d" % d)
    ax.set_xticks([i + width / 2 for i in range(d)])
    ax.set_xticklabels(["λ%d" % (i + 1) for i in range(d)])
    ax.set_ylabel("eigenvalue")
    ax.set_title("fabric tensor eigenvalues")
    ax.legend()
    save(fig, out_dir, "fabric.png")


def sections(disks_path, outline_path, out_dir, polygons_path=None):
    from matplotlib.collections import LineCollection, PatchCollection
    from matplotlib.patches import Circle, Polygon

    planes = {}
    with open(disks_path) as f:
        for row in csv.DictReader(f):
            p = planes.setdefault(row["plane"], {"normal": row["normal"], "offset": float(row["offset"]), "disks": [],
                                                 "outline": [], "loops": {}})
            if row["u"]:
                p["disks"].append((float(row["u"]), float(row["v"]), float(row["radius"]), float(row["size"])))
    with open(outline_path) as f:
        for row in csv.DictReader(f):
            planes[row["plane"]]["outline"].append(((float(row["u0"]), float(row["v0"])), (float(row["u1"]), float(row["v1"]))))
    if polygons_path:
        with open(polygons_path) as f:
            for row in csv.DictReader(f):  # one loop per (particle, loop): its points in order
                key = (int(row["particle"]), int(row["loop"]))
                loop = planes[row["plane"]]["loops"].setdefault(key, {"size": float(row["size"]), "points": []})
                loop["points"].append((float(row["u"]), float(row["v"])))
    sizes = [d[3] for p in planes.values() for d in p["disks"]] + [l["size"] for p in planes.values() for l in p["loops"].values()]
    lo, hi = (min(sizes), max(sizes)) if sizes else (0.0, 1.0)
    for name, p in planes.items():
        fig, ax = plt.subplots(figsize=(6, 5.4))
        patches = [Circle((u, v), r) for u, v, r, _ in p["disks"]] + [Polygon(l["points"], closed=True) for l in p["loops"].values()]
        if patches:
            shown = PatchCollection(patches, cmap="viridis", linewidths=0)
            shown.set_array([d[3] for d in p["disks"]] + [l["size"] for l in p["loops"].values()])
            shown.set_clim(lo, hi if hi > lo else lo + 1e-300)
            ax.add_collection(shown)
            fig.colorbar(shown, ax=ax, label="particle radius" if p["disks"] else "particle size", shrink=0.8)
        if p["outline"]:
            ax.add_collection(LineCollection(p["outline"], colors="black", linewidths=1.0))
        ax.autoscale_view()
        ax.set_aspect("equal")
        ax.set_xlabel(name[0])
        ax.set_ylabel(name[1])
        where = "" if p["normal"] == "z" and len(planes) == 1 else " at %s = %.6g" % (p["normal"], p["offset"])
        cut = len(p["disks"]) + len({particle for particle, _ in p["loops"]})
        ax.set_title("section%s: %d particles cut" % (where, cut))
        save(fig, out_dir, "section_%s.png" % name)


def main():
    if len(sys.argv) not in (4, 6, 7):
        sys.stderr.write(__doc__)
        return 2
    with open(sys.argv[1]) as f:
        a = json.load(f)
    out_dir = sys.argv[3]
    vf_curve(a, out_dir)
    wall_profile(a, out_dir)
    coordination(a, out_dir)
    radii(sys.argv[2], a, out_dir)
    rdf(a, out_dir)
    partial_coordination(a, out_dir)
    fabric(a, out_dir)
    bed_profile(a, out_dir)
    if len(sys.argv) >= 6:
        sections(sys.argv[4], sys.argv[5], out_dir, sys.argv[6] if len(sys.argv) == 7 else None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
