"""Every named scene of non-spherical particles, packed once with the scene's own seed: what a user
gets from `frontpack pack scenes/<name>.yaml`. Scenes whose run would take minutes (ellipsoids,
polyhedra, clusters in 3D: the FCL and cluster paths are slow) are packed with `stop: {time: 60}`
added, written to a temporary copy; the table says so.

  FRONTPACK=build/cli/frontpack /usr/bin/python3 experiments/shape-scenes/run.py
"""
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import runkit  # noqa: E402

HERE = Path(__file__).resolve().parent
SCENES = ["perez-capsules-2d", "perez-capsules-3d", "shapes-polygons-2d", "shapes-ellipses-2d", "shapes-capsules-mesh",
          "shapes-clusters", "shapes-polyhedra", "shapes-ellipsoids"]
CAPPED = {"shapes-clusters", "shapes-polyhedra", "shapes-ellipsoids"}
CAP_SECONDS = 60


def main():
    frontpack = os.environ["FRONTPACK"]
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for name in SCENES:
            src = runkit.REPO / "scenes" / f"{name}.yaml"
            text = src.read_text()
            # outputs dropped (the record is what is measured); a mesh path made absolute
            text = re.sub(r"(?ms)^output:.*\Z", "", text)
            text = re.sub(r"file: (\S+)", lambda m: "file: " + str((src.parent / m.group(1)).resolve()), text)
            if name in CAPPED:
                text = re.sub(r"(?m)^stop:\n(  .*\n)*", "", text) + f"stop: {{time: {CAP_SECONDS}}}\n"
            scene = Path(folder) / f"{name}.yaml"
            scene.write_text(text)
            record = Path(folder) / f"{name}.json"
            subprocess.run(["flock", "/tmp/frontpack-bench.lock", frontpack, "pack", str(scene), "-q", "--record",
                            str(record)], check=True)
            r = json.loads(record.read_text())
            m, c = r["metrics"], r["counters"]
            rows.append([name, r["dimension"], f"{r['n']:,}", f"{m['volume_fraction_container']:.4f}",
                         f"{m['particles_per_second']:,.1f}", f"{m['mean_coordination']:.2f}",
                         f"{m['max_overlap_over_smaller_radius']:.1e}", f"{m['max_outside_over_r']:.1e}", r["info"]["validation"],
                         r["info"]["stop_reason"] + (f" (cap {CAP_SECONDS} s added)" if name in CAPPED else ""),
                         f"{c['solves'] / max(1, r['n']):,.0f}", f"{c['fcl_queries'] / max(1, r['n']):,.0f}"])
            print(rows[-1], flush=True)
    lines = ["# The named scenes of non-spherical particles", ""]
    lines += runkit.provenance_lines(frontpack, sys.argv)
    lines += ["", "One run each, the scene's own seed, outputs dropped; figures from the run record (pack time on one "
              "core; VF = particle volume / container volume; overlap = validation's largest overlap / smaller "
              "circumscribed radius; outside = largest protrusion / circumscribed radius).", "",
              runkit.table(["scene", "D", "N", "VF container", "particles/s", "coordination", "max overlap",
                            "max outside", "validation", "stop", "solves / particle", "FCL queries / particle"], rows), ""]
    (HERE / "RESULTS.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
