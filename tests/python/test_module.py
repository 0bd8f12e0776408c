"""The Python module `frontpack` (python/frontpack_module.cpp) against the command line.

Run by ctest (tests/CMakeLists.txt) as
    PYTHONPATH=<build> FRONTPACK_BINARY=<build>/cli/frontpack /usr/bin/python3 -m pytest tests/python
The same scene and seed must give the command line's numbers exactly: the particles, the record's
metrics and counters, the analysis and the verdict.
"""
import json
import os
import subprocess
import time

import numpy as np
import pytest

import frontpack

BINARY = os.environ.get("FRONTPACK_BINARY", "frontpack")

BOX = {
    "dimension": 3,
    "seed": 1,
    "container": {"type": "box", "min": [0, 0, 0], "max": [0.3, 0.3, 0.3]},
    "particles": {"radius": {"distribution": "uniform", "min": 0.01, "max": 0.02}},
}


def cli(*args, cwd):
    return subprocess.run([BINARY, *map(str, args)], cwd=cwd, capture_output=True, text=True)


def write_scene(folder, scene, name="s.yaml"):
    path = folder / name
    path.write_text(json.dumps(scene, indent=1))  # JSON is YAML: the command line reads it as is
    return path


def read_csv(path):
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


# Time-dependent figures: everything else in the record must match the command line's exactly.
TIMED = {"particles_per_second"}


def untimed(record):
    metrics = {k: v for k, v in record["metrics"].items() if k not in TIMED}
    return metrics, record["counters"], {k: v for k, v in record["info"].items()}


@pytest.fixture(scope="module")
def box_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("box")
    scene = write_scene(folder, BOX)
    r = cli("pack", scene, "-o", "cli.csv", "--record", "cli.json", "--seed", 3, "-q", cwd=folder)
    assert r.returncode == 0, r.stderr
    return folder, scene, frontpack.pack(scene, seed=3)


def test_pack_gives_the_command_lines_particles_and_record(box_run):
    folder, _, p = box_run
    expected = read_csv(folder / "cli.csv")
    assert p.dimension == 3 and not p.shapes and len(p) == len(expected) > 500
    assert p.centers.shape == (len(p), 3) and p.radii.shape == (len(p),)
    assert np.array_equal(p.centers, expected[:, 1:4])
    assert np.array_equal(p.radii, expected[:, 4])
    cli_record = json.loads((folder / "cli.json").read_text())
    assert untimed(p.record) == untimed(cli_record)
    assert p.record["seed"] == 3
    assert p.valid and p.record["info"]["validation"] == "ok"
    assert p.analysis == cli_record["analysis"]


def test_a_dict_is_the_scene_file(box_run):
    _, _, p = box_run
    q = frontpack.pack(dict(BOX, seed=3))
    assert np.array_equal(p.centers, q.centers) and np.array_equal(p.radii, q.radii)
    assert q.scene_path == "<dict>"


def test_analyze_and_validate_are_the_commands(box_run):
    folder, scene, p = box_run
    r = cli("analyze", "cli.csv", "--scene", scene, "--json", "an.json", "-q", cwd=folder)
    assert r.returncode == 0, r.stderr
    assert frontpack.analyze(p) == json.loads((folder / "an.json").read_text())
    v = frontpack.validate(p)
    assert v["ok"] and v["overlap_count"] == 0 and v["outside_count"] == 0 and v["particles"] == len(p)
    assert {k: v[k] for k in p.analysis["validation"]} == p.analysis["validation"]
    assert v["contacts"] == p.record["counters"]["contacts"]
    assert cli("validate", "cli.csv", "--scene", scene, "-q", cwd=folder).returncode == 0
    # Against another scene: the container is half as tall, most particles are outside it.
    smaller = write_scene(folder, dict(BOX, container={"type": "box", "min": [0, 0, 0], "max": [0.3, 0.3, 0.15]}), "half.yaml")
    w = frontpack.validate(p, scene=smaller)
    assert not w["ok"] and w["outside_count"] > len(p) // 3 and "FAILED" in w["line"]


def test_a_bed_is_packed_and_profiled_as_on_the_command_line(tmp_path):
    bed = dict(BOX, container={"type": "cylinder", "base": [0, 0, 0], "radius": 0.3, "height": 1,
                               "bed": {"height": 0.25, "surface": "free"}})
    scene = write_scene(tmp_path, bed)
    r = cli("pack", scene, "-o", "cli.csv", "-q", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    p = frontpack.pack(bed)
    expected = read_csv(tmp_path / "cli.csv")
    assert np.array_equal(p.centers, expected[:, 1:4]) and np.array_equal(p.radii, expected[:, 4])
    assert p.complete and p.valid
    assert (p.centers[:, 2] + p.radii).max() <= 0.25
    profile = p.analysis["volume_fraction"]["bed_profile"]
    assert profile["height"] == 0.25 and len(profile["vf"]) == len(profile["slab_middle"]) > 20
    assert 0.5 < profile["bulk"] < 0.7 and 0.25 - 0.04 <= profile["half_bulk_height"] <= 0.25
    assert profile["surface"]["max"] <= 0.25 and profile["surface"]["columns"] > 10


def test_figures_are_the_command_lines(tmp_path):
    pytest.importorskip("matplotlib")
    caps = dict(BOX, container={"type": "box", "min": [0, 0, 0], "max": [1.2, 1.2, 2], "bed": {"height": 0.8}},
                particles=[{"shape": "spherocylinder", "aspect_ratio": 0.5,
                            "size": {"distribution": "uniform", "min": 0.1, "max": 0.12}}])
    p = frontpack.pack(caps)
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    a = frontpack.analyze(p, plots=tmp_path / "py")
    assert a == frontpack.analyze(p)
    p.write(str(tmp_path / "caps.json"))
    scene = write_scene(tmp_path, caps)
    r = cli("analyze", "caps.json", "--scene", scene, "--plots", "cli", "-q", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    drawn = sorted(f.name for f in (tmp_path / "py").iterdir())
    assert drawn == sorted(f.name for f in (tmp_path / "cli").iterdir())
    assert {"section_xy.png", "section_xz.png", "section_yz.png", "bed_profile.png", "wall_profile.png"} <= set(drawn)
    with pytest.raises(RuntimeError, match="does not exist"):
        frontpack.analyze(p, plots=tmp_path / "none")


def test_the_surfaces_side_file_fine_coarse_or_none(tmp_path):
    caps = dict(BOX, container={"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]},
                particles=[{"shape": "spherocylinder", "elongation": 2,
                            "size": {"distribution": "uniform", "min": 0.1, "max": 0.12}}])
    p = frontpack.pack(caps)
    sizes = {}
    for detail in ("fine", "coarse", "none"):
        p.write(tmp_path / f"{detail}.vtu", surfaces=detail)
        side = tmp_path / f"{detail}.surfaces.vtu"
        assert side.exists() == (detail != "none")
        sizes[detail] = side.stat().st_size if side.exists() else 0
    assert 0 < sizes["coarse"] < 0.4 * sizes["fine"]
    with pytest.raises(ValueError, match="fine, coarse, none"):
        p.write(tmp_path / "x.vtu", surfaces="rough")
    with pytest.raises(ValueError, match="beside a vtu output"):
        p.write(tmp_path / "x.csv", surfaces="coarse")


def test_arrays_are_read_only_views_that_keep_the_packing(box_run):
    _, _, p = box_run
    radii = p.radii
    assert radii.ctypes.data == p.radii.ctypes.data, "the same memory each time: no copy"
    assert p.centers.ctypes.data == p.centers.ctypes.data
    with pytest.raises(ValueError):
        radii[0] = 1.0
    q = frontpack.pack(BOX)
    centers, n = q.centers, len(q)
    del q  # the arrays keep the packing alive
    assert centers.shape == (n, 3) and np.all(np.isfinite(centers))


def test_write_is_the_command_lines_file(box_run, tmp_path):
    folder, _, p = box_run
    p.write(str(tmp_path / "py.csv"))
    assert (tmp_path / "py.csv").read_bytes() == (folder / "cli.csv").read_bytes()
    p.write(str(tmp_path / "py.data"), format="lammps")
    assert (tmp_path / "py.data").stat().st_size > 0
    with pytest.raises(ValueError, match="extension"):
        p.write(str(tmp_path / "py.unknown"))


def test_far_from_the_origin_the_centres_are_absolute(tmp_path):
    far = dict(BOX, container={"type": "box", "min": [1e9, -1e9, 5e8], "max": [1e9 + 0.2, -1e9 + 0.2, 5e8 + 0.2]})
    path = write_scene(tmp_path, far)
    assert cli("pack", path, "-o", "cli.csv", "-q", cwd=tmp_path).returncode == 0
    p = frontpack.pack(path)
    expected = read_csv(tmp_path / "cli.csv")
    assert len(p) == len(expected) > 100
    # The file holds origin + local as a decimal to 17 places, the array rounded to a double: at
    # most one unit in the last place apart (they differ at a tie, rounded either way).
    assert np.all(np.abs(p.centers - expected[:, 1:4]) <= np.spacing(np.abs(expected[:, 1:4])))
    assert np.all(p.centers[:, 0] > 1e9) and np.all(p.centers[:, 1] < -1e9 + 0.2)
    assert np.array_equal(p.radii, expected[:, 4])


def test_bad_scenes_raise_the_command_lines_messages(tmp_path):
    bad = dict(BOX, packer={"nuclei": 5})
    path = write_scene(tmp_path, bad)
    r = cli("pack", path, "-q", cwd=tmp_path)
    assert r.returncode == 2
    with pytest.raises(frontpack.SceneError) as e:
        frontpack.pack(path)
    assert str(e.value) in r.stderr and "packer.nuclei" in str(e.value) and "s.yaml:" in str(e.value)
    with pytest.raises(frontpack.SceneError, match="packer.nuclei"):
        frontpack.pack(bad)
    with pytest.raises(frontpack.SceneError, match="no-such.yaml"):
        frontpack.pack(tmp_path / "no-such.yaml")
    with pytest.raises(ValueError):  # SceneError is a ValueError
        frontpack.pack({"dimension": 4})


def test_progress_can_stop_the_run():
    def stop(n, s, vf):
        raise KeyError("enough")

    with pytest.raises(KeyError, match="enough"):
        frontpack.pack(dict(BOX, container={"type": "box", "min": [0, 0, 0], "max": [3, 3, 3]}), progress=stop)


def test_progress_is_reported():
    big = dict(BOX, container={"type": "box", "min": [0, 0, 0], "max": [1.2, 1.2, 1.2]})
    calls = []
    p = frontpack.pack(big, progress=lambda n, s, vf: calls.append((n, s, vf)))
    if p.record["timings"]["pack"] < 0.6:
        pytest.skip("packed in under 0.6 s: no progress report was due (one every 0.5 s)")
    assert calls and all(0 < vf < 1 and 0 < n <= len(p) for n, _, vf in calls)
    assert [c[0] for c in calls] == sorted(c[0] for c in calls)


def test_shapes_have_poses(tmp_path):
    scene = {
        "dimension": 2,
        "seed": 2,
        "container": {"type": "rectangle", "min": [0, 0], "max": [6, 6]},
        "particles": [{"shape": "ellipse", "axes": [1, 0.5], "size": {"distribution": "uniform", "min": 0.5, "max": 1}}],
    }
    p = frontpack.pack(scene)
    n = len(p)
    assert p.shapes and n > 10
    assert p.positions.shape == (n, 2) and p.orientations.shape == (n,) and p.sizes.shape == (n,)
    assert set(p.template_ids.tolist()) == {0} and len(p.template_names) == 1
    assert np.all((p.sizes >= 0.5) & (p.sizes <= 1))
    assert np.all((p.positions > 0) & (p.positions < 6))
    assert frontpack.validate(p)["ok"]
    with pytest.raises(AttributeError):
        p.centers
    path = write_scene(tmp_path, scene)
    assert cli("pack", path, "-o", "cli.json", "-q", cwd=tmp_path).returncode == 0
    cli_particles = json.loads((tmp_path / "cli.json").read_text())["particles"]
    assert len(cli_particles) == n


def test_the_shape_families_and_their_dimensions():
    families = frontpack.shape_families()
    assert families["sphere"]["dimensions"] == [2, 3] and families["ellipse"]["dimensions"] == [2]
    assert families["polyhedron"]["dimensions"] == [3]
    assert set(families["cluster"]["parameters"]) == {"centers", "radii", "preset"}
    assert families["spherocylinder"]["size_on"][0] == "circumscribed_radius" and "length" in families["spherocylinder"]["size_on"]
    for name, family in families.items():
        dims = family["dimensions"]
        assert family["summary"] and all(family["parameters"].values())
        scene = {"dimension": dims[0], "container": {"type": "box" if dims[0] == 3 else "rectangle",
                                                     "min": [0] * dims[0], "max": [1] * dims[0]},
                 "particles": [{"shape": name, "size": {"distribution": "constant", "value": 0.1}}],
                 "stop": {"particles": 20}}
        try:
            assert len(frontpack.pack(scene, threads=1)) == 20
        except frontpack.SceneError as e:  # a family that needs parameters says which
            assert "particles[0]" in str(e), str(e)


def test_a_large_packing_is_returned_without_copies():
    big = dict(BOX, container={"type": "box", "min": [0, 0, 0], "max": [1.5, 1.5, 1.5]})
    start = time.perf_counter()
    p = frontpack.pack(big)
    total = time.perf_counter() - start
    record = p.record
    inside = record["timings"]["pack"] + record["timings"]["metrics"]
    assert len(p) > 100000
    # Beyond packing and checking: building the Python object (views, no copies).
    assert total - inside < 0.5, (total, inside)


def test_pack_with_set_is_the_command_lines_set(tmp_path):
    scene = write_scene(tmp_path, BOX)
    r = cli("pack", scene, "-o", "cli.csv", "-q", "--set", "particles.radius.max=0.03", "--set",
            "container.max=[0.3, 0.2, 0.3]", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    p = frontpack.pack(scene, set={"particles.radius.max": 0.03, "container.max": [0.3, 0.2, 0.3]})
    assert np.array_equal(np.column_stack([p.centers, p.radii]), read_csv(tmp_path / "cli.csv")[:, 1:5])
    assert p.record["scene"]["overrides"] == ["particles.radius.max=0.03", "container.max=[0.3, 0.2, 0.3]"]
    assert p.radii.max() > 0.02
    with pytest.raises(frontpack.SceneError, match=r"set\[packer.front\]: key 'packer.front': unknown value 'fifoo'"):
        frontpack.pack(scene, set={"packer.front": "fifoo"})


def test_study_from_a_dict_is_the_command_lines_study(tmp_path, monkeypatch):
    write_scene(tmp_path, BOX, "base.yaml")
    study = {"scene": "base.yaml", "seeds": [1, 2], "jobs": 2,
             "parameters": [{"key": "particles.radius.max", "name": "r_max", "values": [0.02, 0.03]},
                            {"key": "packer.front", "values": ["closest", "fifo"]}]}
    (tmp_path / "s.yaml").write_text(json.dumps(study))
    r = cli("study", "s.yaml", "--no-plots", "-q", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    seen = []
    monkeypatch.chdir(tmp_path)  # a dict's relative paths start at the working directory
    out = frontpack.study(dict(study, output="py.out"), plots=False, progress=lambda done, total, row: seen.append((done, total)))
    assert (out["runs"], out["ran"], out["failed"], out["invalid"]) == (8, 8, 0, 0)
    assert sorted(seen) == [(k, 8) for k in range(1, 9)]
    cli_rows = list(__import__("csv").DictReader(open(tmp_path / "s.out/results-full.csv")))
    assert [row["run"] for row in out["rows"]] == [row["run"] for row in cli_rows]
    for mine, theirs in zip(out["rows"], cli_rows):
        assert mine["metrics.volume_fraction_container"] == float(theirs["metrics.volume_fraction_container"])
        assert mine["n"] == int(theirs["n"]) and mine["status"] == "ok" and mine["r_max"] in (0.02, 0.03)
        assert (tmp_path / "py.out/runs" / mine["run"] / "packing.csv").read_bytes() == \
            (tmp_path / "s.out/runs" / mine["run"] / "packing.csv").read_bytes()
    # results.csv: the main figures; results-full.csv (and the rows): every figure of the record.
    full_rows = list(__import__("csv").DictReader(open(out["full_csv"])))
    assert out["csv"] == "py.out/results.csv" and out["full_csv"] == "py.out/results-full.csv"
    assert [row["run"] for row in full_rows] == [row["run"] for row in out["rows"]]
    assert set(out["rows"][0]) == set(full_rows[0]) and "counters.contacts" in full_rows[0]
    short_rows = list(__import__("csv").DictReader(open(tmp_path / "s.out/results.csv")))
    assert set(short_rows[0]) < set(full_rows[0]) and "counters.contacts" not in short_rows[0]
    assert [abs(float(a["metrics.volume_fraction_container"]) / float(b["metrics.volume_fraction_container"]) - 1) < 1e-4
            for a, b in zip(short_rows, cli_rows)] == [True] * 8
    again = frontpack.study(dict(study, output="py.out"), plots=False)
    assert (again["kept"], again["ran"]) == (8, 0)
    # One number put into a key through an expression: the runs are those of the values written out.
    bound = frontpack.study({"scene": "base.yaml", "output": "bound.out",
                             "parameters": [{"name": "ratio", "values": [1.5, 2],
                                             "set": {"particles.radius.max": "${0.02 * ratio}"}}]}, plots=False)
    assert [row["run"] for row in bound["rows"]] == ["ratio=1.5,seed=1", "ratio=2,seed=1"]
    for row, r_max in zip(bound["rows"], ("0.03", "0.04")):
        r = cli("pack", "base.yaml", "-q", "-o", "bound.csv", "--set", "particles.radius.max=" + r_max, cwd=tmp_path)
        assert r.returncode == 0, r.stderr
        assert (tmp_path / "bound.csv").read_bytes() == (tmp_path / "bound.out/runs" / row["run"] / "packing.csv").read_bytes()
    with pytest.raises(frontpack.SceneError, match=r"<dict>:\d+:\d+: key 'seed': unknown key \(did you mean 'seeds'\?\)"):
        frontpack.study({"scene": "base.yaml", "seed": 2})
