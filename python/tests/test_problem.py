"""Problems from a file, YAML text or a dict; their models as NumPy arrays;
errors as exceptions that say where."""

import json
import re
import subprocess
import threading

import numpy as np
import pytest

import rackopt

# conftest.SMALL_PROBLEM written as YAML.
SMALL_YAML = """
pinion: {teeth: 20, module: 4 mm, pressure_angle: 20 deg, face_width: 40 mm}
rack: {span: 500 mm, body_height: 31 mm}
materials:
  steel: {E: 210 GPa, nu: 0.3}
load: {force: 6 kN}
numerics: {positions_per_period: 24}
"""
def test_version_is_the_projects(source):
    text = (source / "CMakeLists.txt").read_text()
    assert re.search(r"project\(rackopt VERSION (\S+)", text).group(1) == rackopt.__version__


def test_the_same_problem_from_a_file_text_and_dict(problem_path, small_problem):
    from_file = rackopt.load_problem(problem_path("rack_railway.yaml"))
    from_text = rackopt.Problem.from_yaml(open(problem_path("rack_railway.yaml")).read(), name="railway.yaml")
    a, b = from_file.stiffness_curve(), from_text.stiffness_curve()
    assert np.array_equal(a.stiffness, b.stiffness) and a.k_min == b.k_min
    assert from_text.source == "railway.yaml"

    yaml_curve = rackopt.Problem.from_yaml(SMALL_YAML).stiffness_curve()
    dict_curve = rackopt.load_problem(small_problem).stiffness_curve()
    assert np.array_equal(yaml_curve.travel, dict_curve.travel)
    assert np.array_equal(yaml_curve.stiffness, dict_curve.stiffness)


def test_curve_equals_the_command_lines(problem_path, cli, tmp_path):
    path = problem_path("gantry_axis.yaml")
    out = subprocess.run([cli, "stiffness", path, "--json", "--out", str(tmp_path)], capture_output=True, text=True,
                         check=True)
    summary = json.loads(out.stdout)
    curve = rackopt.load_problem(path).stiffness_curve()
    for key in ("k_min", "k_max", "k_mean", "travel_at_min", "travel_at_max"):
        assert getattr(curve, key) == summary[key], key
    assert curve.travel.size == summary["samples"]


def test_breakdown_is_laid_out_by_sample_and_slot(problem_path):
    curve = rackopt.load_problem(problem_path("gantry_axis.yaml")).stiffness_curve()
    b = curve.breakdown
    n = curve.travel.size
    slots = b["in_mesh"].shape[1]
    assert slots >= 2 and b["in_mesh"].shape == (n, slots)
    assert np.array_equal(b["in_mesh"].sum(axis=1), curve.pairs_in_mesh)
    # NaN exactly where a slot holds no pair.
    assert np.array_equal(np.isnan(b["c_hertz"]), ~b["in_mesh"])
    # Every sample's load shares sum to one, and its rigid-body stiffness is
    # the sum of its pairs' local stiffnesses (no relief in this problem).
    assert np.allclose(np.nansum(b["load_share"], axis=1), 1.0, atol=1e-12)
    local = sum(b[k] for k in ("c_pinion_bending", "c_pinion_shear", "c_pinion_axial", "c_fillet", "c_hertz",
                               "c_rack_bending", "c_rack_shear", "c_rack_axial", "c_rack_foundation"))
    assert np.allclose(np.nansum(1.0 / local, axis=1), curve.local_stiffness, rtol=1e-12)
    assert curve.stiffness.min() == pytest.approx(curve.k_min, rel=1e-6)


def test_geometry_and_metrics(problem_path):
    p = rackopt.load_problem(problem_path("gantry_axis.yaml"))
    g = p.geometry()
    assert g["contact_ratio"] == p.metric("contact_ratio")
    assert g["pinion"]["pitch_radius"] == pytest.approx(0.004 * 20 / 2, rel=1e-15)
    values = p.metrics(["min_stiffness", "contact_ratio", "root_bending_safety"])
    assert list(values) == ["min_stiffness", "contact_ratio", "root_bending_safety"]
    assert all(v.ok for v in values.values())
    assert values["min_stiffness"].value == p.stiffness_curve().k_min
    names = [d["name"] for d in rackopt.metric_definitions()]
    assert "wear_life_at_R" in names and "min_stiffness" in names


def test_values_are_set_bit_for_bit(problem_path):
    p = rackopt.load_problem(problem_path("gantry_axis.yaml"))
    q = p.with_values({"pinion.module": 0.005, "pinion.teeth": 24})
    assert q.geometry()["pinion"]["pitch_radius"] == 0.005 * 24 / 2
    assert p.geometry()["pinion"]["pitch_radius"] == pytest.approx(0.04)  # p itself unchanged
    assert q.with_set("pinion.module=4 mm").metric("contact_ratio") == pytest.approx(
        p.with_values({"pinion.teeth": 24}).metric("contact_ratio"), rel=1e-14)


def test_wear_life_and_life_at_R(problem_path):
    p = rackopt.load_problem(problem_path("ship_lift.yaml"))
    w = p.wear_life()
    assert w["life"] == p.metric("wear_life") and w["life"] > 0
    assert w["criterion"] in ("max_depth", "case_depth", "contact_ratio")
    assert w["rack"]["depth"].shape == w["rack"]["s"].shape and w["rack"]["depth"].max() > 0
    life_90 = p.life_at_R(0.9)
    assert 0 < life_90 == p.metric("wear_life_at_R(0.9)")
    assert p.life_at_R(0.99) < life_90  # more reliability, shorter life
    r = p.wear_reliability(samples=200, seed=3, threads=1)
    assert r["lives"].shape == (200,) and len(r["input_values"]) == 200
    assert r["nominal"]["life"] == w["life"]
    # The same samples on any number of threads.
    assert np.array_equal(r["lives"], p.wear_reliability(samples=200, seed=3, threads=2)["lives"])


def test_input_errors_say_where(problem_path):
    with pytest.raises(rackopt.InputError) as e:
        rackopt.Problem.from_yaml("pinion:\n  teeth: 20\n  module: 3 kN\n", name="mine.yaml")
    assert (e.value.file, e.value.line, e.value.key_path) == ("mine.yaml", 3, "pinion.module")
    assert e.value.column > 0 and "kN" in e.value.message
    assert str(e.value).startswith("mine.yaml:3:")
    assert isinstance(e.value, ValueError)

    with pytest.raises(rackopt.InputError) as e:
        rackopt.load_problem({"pinion": {"teeth": 20, "modul": "3 mm"}})
    assert e.value.file == "<dict>" and e.value.line is None and e.value.key_path.startswith("pinion.modul")
    assert str(e.value).startswith("<dict>: pinion.modul")

    with pytest.raises(rackopt.InputError) as e:
        rackopt.load_problem(problem_path("gantry_axis.yaml"), set=["pinion.face_width=-1 mm"])
    assert e.value.key_path == "pinion.face_width" and e.value.file == "<command line>"

    with pytest.raises(rackopt.InputError):
        rackopt.load_problem(problem_path("no_such_file.yaml"))


def test_an_impossible_design_is_a_design_error(problem_path):
    p = rackopt.load_problem(problem_path("gantry_axis.yaml"), set=["pinion.teeth=8", "pinion.profile_shift=1.0"])
    with pytest.raises(rackopt.DesignError) as e:
        p.geometry()
    assert e.value.code == "pointed_tooth"
    with pytest.raises(rackopt.DesignError) as e:
        p.metric("min_stiffness")
    assert e.value.code == "pointed_tooth"
    v = p.metrics(["min_stiffness"])["min_stiffness"]
    assert not v.ok and v.value is None and v.error_code == "pointed_tooth" and v.cause == "geometry"


def test_long_calls_release_the_gil(problem_path):
    p = rackopt.load_problem(problem_path("ship_lift.yaml"))
    started = threading.Event()
    result = {}

    def work():
        started.set()
        result["curve"] = p.stiffness_curve(positions_per_period=3000)

    t = threading.Thread(target=work)
    t.start()
    started.wait()
    spins = 0
    while t.is_alive():  # counts only while this thread holds the GIL
        spins += 1
    t.join()
    # With the GIL held through the call this thread would not run at all
    # until the call ended; released, it spins the whole time (millions).
    assert spins > 10000
    assert result["curve"].k_min == p.stiffness_curve(positions_per_period=3000).k_min
