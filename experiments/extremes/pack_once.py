"""One `frontpack pack` run of a scene text in a temporary folder, for the measurement scripts
here: (exit code, wall seconds, the run record or None, the radii of the CSV output, the last
column: a sphere's radius; with rows=True its rows instead, every column as a number)."""
import json
import os
import subprocess
import tempfile
import time

FRONTPACK = os.environ.get("FRONTPACK", "frontpack")


def pack(scene_text, extra=(), rows=False):
    with tempfile.TemporaryDirectory() as d:
        scene = os.path.join(d, "s.yaml")
        with open(scene, "w") as f:
            f.write(scene_text)
        t0 = time.monotonic()
        p = subprocess.run([FRONTPACK, "pack", scene, "-o", os.path.join(d, "p.csv"), "--record", os.path.join(d, "r.json"),
                            "-q", *extra], capture_output=True, text=True)
        wall = time.monotonic() - t0
        record = json.load(open(os.path.join(d, "r.json"))) if os.path.exists(os.path.join(d, "r.json")) else None
        radii = []
        if os.path.exists(os.path.join(d, "p.csv")):
            for line in open(os.path.join(d, "p.csv")).readlines()[1:]:
                cells = [float(v) for v in line.split(",")]
                radii.append(cells if rows else cells[-1])
        return p.returncode, wall, record, radii
