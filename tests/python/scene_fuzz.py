"""Random scene dicts for frontpack.pack, run by test_scene_fuzz.py in a child process (a crash
is then that test's failure, not a dead pytest).

    PYTHONPATH=<build> /usr/bin/python3 tests/python/scene_fuzz.py SEED COUNT

Each case is a small valid scene (a box or rectangle of a few particle diameters, or shapes)
changed at random: values replaced by wrong types, numpy scalars and arrays, huge, negative, NaN
or infinite numbers; keys removed, added, renamed; mappings nested in lists and the reverse.
A case either packs or raises SceneError, ValueError or TypeError. Before each case its index
goes to stderr (the last one names a crash); at the end one JSON line on stdout: the counts and
every case that raised anything else, with its scene as repr().
"""
import copy
import json
import random
import sys
import time

import numpy as np

import frontpack

SPHERES_3D = {
    "dimension": 3,
    "seed": 1,
    "container": {"type": "box", "min": [0, 0, 0], "max": [0.2, 0.2, 0.2]},
    "particles": {"radius": {"distribution": "uniform", "min": 0.02, "max": 0.04}},
    "packer": {"front": "closest"},
    "stop": {"particles": 5},
}
DISKS_2D = {
    "dimension": 2,
    "seed": 2,
    "container": {"type": "rectangle", "min": [0, 0], "max": [1, 1]},
    "particles": {"radius": {"distribution": "constant", "value": 0.05}},
    "stop": {"particles": 5},
}
ELLIPSES_2D = {
    "dimension": 2,
    "container": {"type": "rectangle", "min": [0, 0], "max": [2, 2]},
    "particles": [{"shape": "ellipse", "axes": [1, 0.5], "size": {"distribution": "uniform", "min": 0.2, "max": 0.3}}],
    "stop": {"particles": 5},
}
BALL_3D = {
    "dimension": 3,
    "container": {"type": "sphere", "center": [1e6, 0, -3], "radius": 0.3},
    "particles": {"radius": {"distribution": "constant", "value": 0.05}},
    "stop": {"particles": 5},
}
BASES = [SPHERES_3D, DISKS_2D, ELLIPSES_2D, BALL_3D]

# Keys a scene may have (and a few it may not), for keys added or renamed.
KEYS = ["dimension", "seed", "container", "particles", "packer", "stop", "target", "densify", "material", "output",
        "type", "min", "max", "radius", "distribution", "value", "shape", "size", "axes", "center", "threads", "front",
        "particles ", "Seed", "", "volume_fraction", "solid_fraction", "time", "regions", "least_squares"]
NAMES = ["box", "rectangle", "sphere", "uniform", "constant", "lognormal", "ellipse", "mesh", "closest", "fifo", "random",
         "tet_mesh", "", "\u00e9", "a" * 300, "0x10", "1e3", "~", "null", ".nan", "-.inf"]


def scalar(rng):
    """A value of any kind a scene may be given, right or wrong."""
    k = rng.randrange(16)
    if k == 0:
        return rng.choice([0, 1, 2, 3, -1, 5, 2**31, 2**63 - 1, 2**64, 2**64 + 1, -(2**63), 10**30])
    if k == 1:
        return rng.choice([0.0, -0.0, 1e-300, 5e-324, 0.5, 1e300, 1.7976931348623157e308, -1e308, 0.03, 0.1])
    if k == 2:
        return rng.choice([float("nan"), float("inf"), -float("inf")])
    if k == 3:
        return rng.choice(NAMES)
    if k == 4:
        return rng.choice([True, False, None])
    if k == 5:
        return rng.choice([np.int64(3), np.int32(-2), np.uint64(2**64 - 1), np.int8(1), np.uint8(200)])
    if k == 6:
        return rng.choice([np.float64(0.05), np.float32(0.25), np.float16(2), np.float64("nan"), np.float32("inf")])
    if k == 7:
        return rng.choice([np.bool_(True), np.bool_(False), np.str_("box")])
    if k == 8:
        return np.array([rng.uniform(-1, 1) for _ in range(rng.randrange(0, 5))])
    if k == 9:
        return np.array([[0, 0, 0], [1, 1, 1]], dtype=rng.choice([np.int64, np.float32, np.uint8]))
    if k == 10:
        return np.array(rng.choice([3, 0.5, np.nan]))  # 0-d
    if k == 11:
        return [scalar(rng) for _ in range(rng.randrange(0, 4))]
    if k == 12:
        return rng.uniform(-10, 10)
    if k == 13:
        return rng.randrange(-10, 10)
    if k == 14:
        return {rng.choice(KEYS): scalar(rng)}
    return rng.choice([[0, 0, 0], [1, 1, 1], [0.3, 0.3], [0, 0, 0, 0], (0.1, 0.2, 0.3)])


def containers(node):
    """Every (parent, key) in the scene: dict keys and list indices."""
    out = []
    if isinstance(node, dict):
        for k, v in node.items():
            out.append((node, k))
            out += containers(v)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out.append((node, i))
            out += containers(v)
    return out


def mutate(scene, rng):
    spots = containers(scene)
    if not spots:
        return
    parent, key = rng.choice(spots)
    k = rng.randrange(9)
    if k <= 2:  # a value replaced
        parent[key] = scalar(rng)
    elif k == 3 and isinstance(parent, dict):  # a key removed
        del parent[key]
    elif k == 4 and isinstance(parent, dict):  # a key renamed
        parent[rng.choice(KEYS)] = parent.pop(key)
    elif k == 5 and isinstance(parent, dict):  # a key added
        parent[rng.choice(KEYS)] = scalar(rng)
    elif k == 6:  # nested one level deeper
        parent[key] = rng.choice([[parent[key]], {rng.choice(KEYS): parent[key]}])
    elif k == 7:  # a number as numpy
        v = parent[key]
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            parent[key] = np.float64(v) if isinstance(v, float) else np.int64(max(min(v, 2**63 - 1), -(2**63)))
        elif isinstance(v, list) and v and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v):
            parent[key] = np.array(v)
    else:  # a number scaled far away
        v = parent[key]
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            parent[key] = v * rng.choice([1e9, -1, 1e-9, 0, 1e300])


def case(rng):
    scene = copy.deepcopy(rng.choice(BASES))
    for _ in range(rng.randrange(0, 4)):
        mutate(scene, rng)
    if rng.random() < 0.05:  # deep nesting
        for _ in range(rng.choice([50, 3000])):
            scene = {"particles": scene}
    return scene


def small_stop(scene):
    """Whether the scene still stops after a few particles; else the run is given stop.particles 5."""
    stop = scene.get("stop") if isinstance(scene, dict) else None
    n = stop.get("particles") if isinstance(stop, dict) else None
    return isinstance(n, (int, np.integer)) and not isinstance(n, bool) and 0 < n <= 50


def main():
    seed, count = int(sys.argv[1]), int(sys.argv[2])
    rng = random.Random(seed)
    counts = {"packed": 0, "refused": 0, "other": 0}
    others = []
    start = time.perf_counter()
    for i in range(count):
        scene = case(rng)
        print(i, file=sys.stderr, flush=True)
        kwargs = {} if small_stop(scene) else {"set": {"stop.particles": 5}}
        try:
            p = frontpack.pack(scene, threads=1, **kwargs)
            assert len(p) <= 50, len(p)
            counts["packed"] += 1
        except (frontpack.SceneError, ValueError, TypeError):
            counts["refused"] += 1
        except BaseException as e:  # noqa: BLE001 - every other kind is what the fuzz looks for
            counts["other"] += 1
            others.append({"case": i, "error": f"{type(e).__name__}: {e}"[:500], "scene": repr(scene)[:2000]})
    counts["seconds"] = round(time.perf_counter() - start, 2)
    print(json.dumps({"counts": counts, "others": others}))


if __name__ == "__main__":
    main()
