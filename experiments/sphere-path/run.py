"""A spheres-only scene must not pay for general shapes: the sphere packer of the binary before
the general-shape work (FRONTPACK_BEFORE) against the current one (FRONTPACK), alternating runs
on the sphere scenes of experiments/performance. Same packing (N, VF) and the same speed expected.

  FRONTPACK=build/cli/frontpack FRONTPACK_BEFORE=/tmp/fp-old/build/cli/frontpack \
      /usr/bin/python3 experiments/sphere-path/run.py
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import runkit  # noqa: E402

HERE = Path(__file__).resolve().parent
SCENES = [("valera-cube", 5), ("disks-million", 3), ("million", 3)]


def run(binary, scene, folder):
    record = Path(folder) / "record.json"
    p = subprocess.run(["flock", "/tmp/frontpack-bench.lock", binary, "pack", str(runkit.REPO / "scenes" / f"{scene}.yaml"),
                        "-q", "-o", str(Path(folder) / "out.csv"), "--record", str(record)])
    if p.returncode not in (0, 4):  # 4: valid, but the scene's stop left the container unfilled, as asked
        raise SystemExit(f"{scene}: frontpack failed (exit {p.returncode})")
    r = json.loads(record.read_text())
    m = r["metrics"]
    vf = m.get("volume_fraction_reference_sphere", m.get("volume_fraction_container"))
    return {"n": r["n"], "pack": r["timings"]["pack"], "vf": vf}


def main():
    new, old = os.environ["FRONTPACK"], os.environ["FRONTPACK_BEFORE"]
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for scene, repeats in SCENES:
            runs = {"before": [], "now": []}
            for _ in range(repeats):
                runs["before"].append(run(old, scene, folder))
                runs["now"].append(run(new, scene, folder))
            b, n = runs["before"], runs["now"]
            tb = statistics.median(x["pack"] for x in b)
            tn = statistics.median(x["pack"] for x in n)
            same = all(x["n"] == b[0]["n"] and x["vf"] == b[0]["vf"] for x in b + n)
            rows.append([scene, repeats, b[0]["n"], f"{b[0]['vf']:.4f}", "yes" if same else "NO",
                         f"{tb:.3f}", f"{tn:.3f}", f"{b[0]['n'] / tb:,.0f}", f"{n[0]['n'] / tn:,.0f}", f"{tn / tb:.3f}"])
    lines = ["# The sphere path does not pay for general shapes", ""]
    lines += runkit.provenance_lines(new, sys.argv)
    lines += [f"* before: `{old}` ({runkit.sh(old, '--version')}), the commit before the general-shape work", "",
              "Alternating runs of the same scene with the binary before the general-shape work and the current",
              "one; medians of the pack time (one core). The sphere packer (front/advancing_front.hpp, library",
              "fp_front) links no FCL, libccd or NLopt: the ctest `sphere_path_links_no_fcl_nlopt` checks it.", "",
              runkit.table(["scene", "runs each", "N", "VF", "identical packing", "pack s before", "pack s now",
                            "particles/s before", "particles/s now", "now / before"], rows), ""]
    (HERE / "RESULTS.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
