"""What the Python module promises beyond the numbers (python/frontpack_module.cpp): bad input is
a clear exception that loses nothing, never a crash.

* No output is an input: Packing.write and frontpack.study refuse (OutputPathError, a
  ValueError) to write over the scene, a mesh, the study file, and leave them as they were (bytes
  and inode).
* A packing is validated and analysed against any scene it can be in, anywhere in space; a scene
  it cannot be in (another dimension, shapes for spheres) is a ValueError, not a crash.
* Scene dicts may hold numpy values; threads=, jobs= and progress= are checked.
* A packing the command line calls incomplete (exit 4) says so: Packing.complete, .incomplete,
  and an IncompletePackingWarning from frontpack.pack.
"""
import json
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

import frontpack

BINARY = os.environ.get("FRONTPACK_BINARY", "frontpack")

BOX = {
    "dimension": 3,
    "seed": 1,
    "container": {"type": "box", "min": [0, 0, 0], "max": [0.15, 0.15, 0.15]},
    "particles": {"radius": {"distribution": "uniform", "min": 0.01, "max": 0.02}},
}
SQUARE = {
    "dimension": 2,
    "seed": 1,
    "container": {"type": "rectangle", "min": [0, 0], "max": [0.5, 0.5]},
    "particles": {"radius": {"distribution": "uniform", "min": 0.01, "max": 0.02}},
}
ELLIPSES = {
    "dimension": 2,
    "seed": 2,
    "container": {"type": "rectangle", "min": [0, 0], "max": [3, 3]},
    "particles": [{"shape": "ellipse", "axes": [1, 0.5], "size": {"distribution": "uniform", "min": 0.5, "max": 1}}],
}


def write_scene(folder, scene, name="s.yaml"):
    path = folder / name
    path.write_text(json.dumps(scene, indent=1))
    return path


def state(path):
    """A file as it is: its bytes and its inode (a file replaced by a rename has a new one)."""
    st = os.stat(path)
    return path.read_bytes(), st.st_ino, st.st_dev


def cli(*args, cwd):
    return subprocess.run([BINARY, *map(str, args)], cwd=cwd, capture_output=True, text=True)


def isolated(code, cwd):
    """Runs `code` (after import frontpack) in a child interpreter: a crash is an exit code there."""
    return subprocess.run([sys.executable, "-c", "import frontpack, json, sys\n" + code], cwd=cwd, capture_output=True,
                          text=True, timeout=120)


# --- no output is an input --------------------------------------------------------------------

def test_write_refuses_the_scene_it_was_packed_from(tmp_path, monkeypatch):
    scene = write_scene(tmp_path, BOX)
    p = frontpack.pack(scene)
    before = state(scene)
    monkeypatch.chdir(tmp_path)
    link = tmp_path / "link.csv"
    link.symlink_to("s.yaml")
    os.link(scene, tmp_path / "hard.csv")
    for target, fmt in [(scene, "csv"), (str(scene), "csv"), ("s.yaml", "json"), ("./sub/../s.yaml", "csv"),
                        (link, ""), ("hard.csv", "")]:
        (tmp_path / "sub").mkdir(exist_ok=True)
        with pytest.raises(frontpack.OutputPathError, match=r"Packing.write: output '.*' is the scene file .*never writes over what it reads"):
            p.write(target, format=fmt)
        assert state(scene) == before, target
    assert isinstance(frontpack.OutputPathError("x"), ValueError)
    assert sorted(f.name for f in tmp_path.iterdir()) == ["hard.csv", "link.csv", "s.yaml", "sub"]
    # Another name is written.
    p.write(tmp_path / "out.csv")
    assert (tmp_path / "out.csv").stat().st_size > 0 and state(scene) == before


def test_write_refuses_the_mesh_the_container_was_read_from(tmp_path):
    source = os.path.join(os.path.dirname(__file__), "..", "data", "meshes", "cube.stl")
    mesh = tmp_path / "cube.stl"
    mesh.write_bytes(open(source, "rb").read())
    scene = {"dimension": 3, "container": {"type": "mesh", "file": str(mesh)},
             "particles": {"radius": {"distribution": "constant", "value": 0.1}}, "stop": {"particles": 10}}
    p = frontpack.pack(scene)
    before = state(mesh)
    with pytest.raises(frontpack.OutputPathError, match=r"is the mesh file"):
        p.write(mesh, format="csv")
    assert state(mesh) == before


def expect_side_file_refused(tmp_path, scene_dict, side, output):
    """A scene saved as `side`, a side file of `output`: writing `output` is refused, nothing changes."""
    scene = write_scene(tmp_path, dict(scene_dict, stop={"particles": 5}), side)
    p = frontpack.pack(scene)
    before = state(scene)
    with pytest.raises(frontpack.OutputPathError, match=rf"the side file of output '.*{output}'.* is the scene file"):
        p.write(tmp_path / output)
    assert state(scene) == before and not (tmp_path / output).exists()


def test_write_refuses_a_side_file_that_is_the_scene(tmp_path):
    # A packing of shapes written as vtu writes <name>.surfaces.vtu beside it.
    expect_side_file_refused(tmp_path, ELLIPSES, "p.surfaces.vtu", "p.vtu")


def test_a_vtu_output_has_the_container_beside_it_and_it_may_not_be_the_scene(tmp_path):
    # Written beside every vtu output of a packing whose scene is known: the container's
    # boundary, for ParaView (core/io/container_vtu.hpp; its geometry is tested in test_cli).
    p = frontpack.pack(dict(BOX, stop={"particles": 5}))
    p.write(tmp_path / "p.vtu")
    assert sorted(f.name for f in tmp_path.iterdir()) == ["p.container.vtu", "p.vtu"]
    assert (tmp_path / "p.container.vtu").read_bytes().startswith(b"<?xml")
    p.write(tmp_path / "p.csv")
    assert not (tmp_path / "p.container.csv").exists()
    expect_side_file_refused(tmp_path, BOX, "q.container.vtu", "q.vtu")


def test_write_refuses_a_path_it_cannot_write_and_writes_nothing(tmp_path):
    p = frontpack.pack(dict(BOX, stop={"particles": 5}))
    with pytest.raises(frontpack.OutputPathError, match="does not exist"):
        p.write(tmp_path / "no-such-folder" / "p.csv")
    with pytest.raises(frontpack.OutputPathError, match="is a folder"):
        p.write(tmp_path, format="csv")
    assert list(tmp_path.iterdir()) == []


def test_study_refuses_an_output_folder_holding_its_base_scene(tmp_path, monkeypatch):
    (tmp_path / "o").mkdir()
    scene = write_scene(tmp_path / "o", BOX, "results.csv")
    before = state(scene)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(frontpack.OutputPathError,
                       match=r"results table 'o/results.csv' is the scene file 'o/results.csv'.*never writes over what it reads"):
        frontpack.study({"scene": "o/results.csv", "output": "o"}, plots=False)
    assert state(scene) == before
    assert sorted(f.name for f in (tmp_path / "o").iterdir()) == ["results.csv"]
    # A run's record is removed before its run: a scene there is refused too.
    (tmp_path / "o/runs/seed=1").mkdir(parents=True)
    record = write_scene(tmp_path / "o/runs/seed=1", BOX, "record.json")
    kept = state(record)
    with pytest.raises(frontpack.OutputPathError, match=r"run record 'o/runs/seed=1/record.json' is the scene file"):
        frontpack.study({"scene": "o/runs/seed=1/record.json", "output": "o"}, plots=False)
    assert state(record) == kept and state(scene) == before
    # The command line refuses the same study (bad input: exit 2) and leaves the files alone.
    (tmp_path / "st.yaml").write_text("scene: o/results.csv\noutput: o\n")
    r = cli("study", "st.yaml", "--no-plots", cwd=tmp_path)
    assert r.returncode == 2 and "results table 'o/results.csv' is the scene file 'o/results.csv'" in r.stderr, r.stderr
    assert state(scene) == before and state(record) == kept


# --- a packing in another scene ---------------------------------------------------------------

@pytest.fixture(scope="module")
def packings():
    return {3: frontpack.pack(dict(BOX, stop={"particles": 30})), 2: frontpack.pack(dict(SQUARE, stop={"particles": 30}))}


@pytest.mark.parametrize("call", ["validate", "analyze"])
def test_a_scene_of_the_other_dimension_is_a_value_error_not_a_crash(tmp_path, call):
    for d, other, scene in [(3, 2, SQUARE), (2, 3, BOX)]:
        first = BOX if d == 3 else SQUARE
        code = (f"p = frontpack.pack({first!r} | {{'stop': {{'particles': 30}}}})\n"
                f"for s in ({scene!r}, 's.yaml'):\n"
                f"    try:\n"
                f"        frontpack.{call}(p, scene=s)\n"
                f"    except ValueError as e:\n"
                f"        print(type(e).__name__, e)\n")
        write_scene(tmp_path, scene)
        r = isolated(code, tmp_path)
        assert r.returncode == 0, f"{d}D packing, {other}D scene: exit {r.returncode}\n{r.stderr}"
        lines = r.stdout.splitlines()
        assert lines == [f"ValueError the packing is {d}D, the scene <dict> {other}D",
                         f"ValueError the packing is {d}D, the scene s.yaml {other}D"], r.stdout


def test_spheres_against_a_scene_of_shapes_and_the_reverse_are_refused(packings):
    shapes = frontpack.pack(dict(ELLIPSES, stop={"particles": 5}))
    with pytest.raises(ValueError, match="the packing is of spheres, the scene <dict> of shapes"):
        frontpack.validate(packings[2], scene=ELLIPSES)
    with pytest.raises(ValueError, match="the packing is of shapes, the scene <dict> of spheres"):
        frontpack.analyze(shapes, scene=SQUARE)
    assert frontpack.validate(shapes, scene=ELLIPSES)["ok"]


def test_a_packing_is_validated_against_a_container_anywhere(tmp_path):
    # Packed far from the origin; checked against a larger box around it, whose frame origin is
    # another (1e9 + 1 and 1e9): the verdict, as `frontpack validate` and `analyze` give it.
    far = dict(BOX, container={"type": "box", "min": [1e9 + 1, -5e8 + 1, 3], "max": [1e9 + 1.15, -5e8 + 1.15, 3.15]})
    larger = dict(BOX, container={"type": "box", "min": [1e9, -5e8, 2], "max": [1e9 + 2, -5e8 + 2, 4]})
    path = write_scene(tmp_path, far)
    larger_path = write_scene(tmp_path, larger, "larger.yaml")
    assert cli("pack", path, "-o", "p.csv", "-q", cwd=tmp_path).returncode == 0
    p = frontpack.pack(path)
    v = frontpack.validate(p, scene=larger_path)
    assert v["ok"] and v["particles"] == len(p) and v["outside_count"] == 0 and v["overlap_count"] == 0, v["summary"]
    r = cli("analyze", "p.csv", "--scene", larger_path, "--json", "an.json", "-q", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    expected = json.loads((tmp_path / "an.json").read_text())
    assert {k: v[k] for k in expected["validation"]} == expected["validation"]
    assert frontpack.analyze(p, scene=larger_path) == expected
    assert cli("validate", "p.csv", "--scene", larger_path, "-q", cwd=tmp_path).returncode == 0
    # Against a box away from it: every particle outside.
    away = dict(BOX, container={"type": "box", "min": [10, 10, 10], "max": [10.15, 10.15, 10.15]})
    w = frontpack.validate(p, scene=away)
    assert not w["ok"] and w["outside_count"] == len(p)
    near = frontpack.pack(dict(BOX, stop={"particles": 30}))
    assert frontpack.validate(near, scene=far)["outside_count"] == len(near)
    # Its own scene given again is its own frame: the verdict of pack.
    assert frontpack.validate(p, scene=path)["ok"] and frontpack.validate(p, scene=path)["contacts"] == frontpack.validate(p)["contacts"]


# --- arguments --------------------------------------------------------------------------------

def test_numpy_values_in_a_scene_dict_are_the_plain_values():
    plain = dict(BOX, seed=3)
    p = frontpack.pack(plain)
    numpy_scene = {
        "dimension": np.int64(3),
        "seed": np.uint64(3),
        "container": {"type": np.str_("box"), "min": np.array([0, 0, 0], dtype=np.int8), "max": np.array([0.15, 0.15, 0.15])},
        "particles": {"radius": {"distribution": "uniform", "min": np.float64(0.01), "max": np.array(0.02)}},
    }
    q = frontpack.pack(numpy_scene)
    assert np.array_equal(p.centers, q.centers) and np.array_equal(p.radii, q.radii)
    r = frontpack.pack(dict(BOX, seed=3), set={"container.max": np.array([0.15, 0.15, 0.15]), "seed": np.int32(3)})
    assert np.array_equal(p.centers, r.centers)
    with pytest.raises(TypeError, match="a scene value is a number, text, flag, list or dict .*not set"):
        frontpack.pack(dict(BOX, seed={1, 2}))
    with pytest.raises(ValueError, match="nested too deeply"):
        deep = BOX
        for _ in range(5000):
            deep = {"particles": deep}
        frontpack.pack(deep)


def test_threads_jobs_and_progress_are_checked(packings, tmp_path):
    small = dict(BOX, stop={"particles": 5})
    for bad in (-1, 4097, 10**9, 10**12):
        with pytest.raises(ValueError, match=rf"threads must be an integer from 0 \(every hardware thread\) to 4096 \(got {bad}\)"):
            frontpack.pack(small, threads=bad)
        with pytest.raises(ValueError, match="threads must be an integer from 0"):
            frontpack.validate(packings[3], threads=bad)
        with pytest.raises(ValueError, match="threads must be an integer from 0"):
            frontpack.analyze(packings[3], threads=bad)
    assert len(frontpack.pack(small, threads=0)) == len(frontpack.pack(small, threads=4096)) == 5
    with pytest.raises(TypeError, match=r"progress must be callable, progress\(n, seconds, volume_fraction\), or None \(got int\)"):
        frontpack.pack(small, progress=5)
    with pytest.raises(ValueError, match="tolerance must be a finite number"):
        frontpack.validate(packings[3], tolerance=float("nan"))
    write_scene(tmp_path, BOX, "base.yaml")
    study = {"scene": str(tmp_path / "base.yaml"), "output": str(tmp_path / "o")}
    with pytest.raises(TypeError, match=r"progress must be callable, progress\(done, total, row\)"):
        frontpack.study(study, plots=False, progress="yes")
    for bad in (-1, 1025):
        with pytest.raises(ValueError, match=rf"jobs must be an integer from 0 \(the study's\) to 1024 \(got {bad}\)"):
            frontpack.study(study, plots=False, jobs=bad)
    assert sorted(f.name for f in tmp_path.iterdir()) == ["base.yaml"]


def test_an_incomplete_packing_warns_and_says_why():
    cut = dict(BOX, stop={"particles": 20})
    with pytest.warns(frontpack.IncompletePackingWarning, match=r"stop\.particles \(20\) ended the packing"):
        p = frontpack.pack(cut)
    assert len(p) == 20 and p.valid and not p.complete
    assert p.incomplete.startswith("stop.particles (20) ended the packing before it filled the container")
    assert p.record["info"]["incomplete"] == p.incomplete
    assert repr(p).endswith(", incomplete>")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a complete packing warns of nothing
        full = frontpack.pack(BOX)
    assert full.complete and full.incomplete == "" and "incomplete" not in full.record["info"]
    with warnings.catch_warnings():
        warnings.simplefilter("error", frontpack.IncompletePackingWarning)
        with pytest.raises(frontpack.IncompletePackingWarning):
            frontpack.pack(cut)


def test_scaled_sizes_give_n_particles_that_fill_the_container():
    scene = dict(BOX, stop={"particles": 400, "scale_sizes": True})
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # complete: no warning
        p = frontpack.pack(scene)
    assert len(p) == 400 and p.valid and p.complete
    m = p.record["metrics"]
    assert abs(m["size_scale_fitted"] / m["size_scale"] - 1) < 0.02
    assert 400 <= p.record["counters"]["size_scale_full_count"] <= 404
    ratio = p.radii.max() / p.radii.min()
    assert ratio <= 2 * (1 + 1e-12)  # the law's shape: U[0.01, 0.02] scaled
    assert frontpack.validate(p)["ok"]
