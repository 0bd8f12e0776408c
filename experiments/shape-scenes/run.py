"""Every named scene of non-spherical particles, packed once with the scene's own seed: what a user
gets from `frontpack pack scenes/<name>.yaml`, through the Python module (the record in memory, no
files). Scenes whose run would take minutes (ellipsoids, polyhedra, clusters in 3D: the FCL and
cluster paths are slow) are packed with `stop: {time: 60}` set (as `--set 'stop={time: 60}'`);
the table says so.

  PYTHONPATH=build-test /usr/bin/python3 experiments/shape-scenes/run.py
"""
import fcntl
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import runkit  # noqa: E402

import frontpack

HERE = Path(__file__).resolve().parent
SCENES = ["perez-capsules-2d", "perez-capsules-3d", "shapes-polygons-2d", "shapes-ellipses-2d", "shapes-capsules-mesh",
          "shapes-clusters", "shapes-polyhedra", "shapes-ellipsoids"]
CAPPED = {"shapes-clusters", "shapes-polyhedra", "shapes-ellipsoids"}
CAP_SECONDS = 60


def main():
    rows = []
    for name in SCENES:
        with open(runkit.LOCK, "w") as lock:  # timed runs of different studies never overlap
            fcntl.flock(lock, fcntl.LOCK_EX)
            p = frontpack.pack(runkit.REPO / "scenes" / f"{name}.yaml", threads=1,
                               set={"stop": {"time": CAP_SECONDS}} if name in CAPPED else None)
        r = p.record
        m, c = r["metrics"], r["counters"]
        rows.append([name, r["dimension"], f"{r['n']:,}", f"{m['volume_fraction_container']:.4f}",
                     f"{m['particles_per_second']:,.1f}", f"{m['mean_coordination']:.2f}",
                     f"{m['max_overlap_over_smaller_radius']:.1e}", f"{m['max_outside_over_r']:.1e}", r["info"]["validation"],
                     r["info"]["stop_reason"] + (f" (cap {CAP_SECONDS} s set)" if name in CAPPED else ""),
                     f"{c['solves'] / max(1, r['n']):,.0f}", f"{c['fcl_queries'] / max(1, r['n']):,.0f}"])
        print(rows[-1], flush=True)
    lines = ["# The named scenes of non-spherical particles", ""]
    lines += runkit.provenance_lines(frontpack.__file__, sys.argv, f"the Python module, frontpack {frontpack.__version__}")
    lines += ["", "One run each, the scene's own seed, through the Python module (nothing written); figures from the "
              "run record (pack time on one core; VF = particle volume / container volume; overlap = validation's "
              "largest overlap / smaller circumscribed radius; outside = largest protrusion / circumscribed radius).", "",
              runkit.table(["scene", "D", "N", "VF container", "particles/s", "coordination", "max overlap",
                            "max outside", "validation", "stop", "solves / particle", "FCL queries / particle"], rows), ""]
    (HERE / "RESULTS.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
