"""frontpack.pack on a few hundred random scene dicts (scene_fuzz.py, a fixed seed): each packs or
raises SceneError, ValueError or TypeError; never another exception, never a crash.

Run alone by ctest (tests/CMakeLists.txt, python_scene_fuzz) with a time limit; the child
process makes a crash (SIGSEGV, abort) this test's failure, named by the case it died on.
"""
import json
import os
import pathlib
import subprocess
import sys

FUZZ = pathlib.Path(__file__).with_name("scene_fuzz.py")
SEED = 20240611
CASES = 400


def test_random_scene_dicts_pack_or_are_refused():
    r = subprocess.run([sys.executable, str(FUZZ), str(SEED), str(CASES)], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ, PYTHONFAULTHANDLER="1"))
    started = [line for line in r.stderr.splitlines() if line.isdigit()]
    assert r.returncode == 0, f"the child died (exit {r.returncode}) in case {started[-1:]}: {r.stderr[-3000:]}"
    report = json.loads(r.stdout.strip().splitlines()[-1])
    counts = report["counts"]
    assert report["others"] == [], json.dumps(report["others"], indent=1)
    assert counts["packed"] + counts["refused"] == CASES
    # The fuzz reaches both sides: scenes that pack and scenes refused.
    assert counts["packed"] >= CASES // 10 and counts["refused"] >= CASES // 10, counts
