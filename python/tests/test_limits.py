"""The library keeps the limits of docs/input_limits.md for a Python caller,
not only for the files the loaders read: counts out of range, a path with a
NUL byte, and messages in a Python caller's words."""

import glob
import os
import shutil
import subprocess
import sys

import pytest

import rackopt

from test_study import EVALUATE


@pytest.fixture
def wear_problem(problem_path):
    return rackopt.load_problem(problem_path("ship_lift.yaml"))


@pytest.mark.parametrize("kwargs, key, allowed", [
    # -1 first: today's failure mode is an internal message, not a long run.
    ({"samples": -1}, "samples", "1 .. 1000000"),
    ({"samples": 0}, "samples", "1 .. 1000000"),
    ({"seed": -1}, "seed", "0 .. 2000000000"),
    ({"seed": 2 ** 62}, "seed", "0 .. 2000000000"),
    ({"threads": -1}, "threads", "0 .. 1024"),
    ({"threads": 5000}, "threads", "0 .. 1024"),
    ({"samples": 2_000_000}, "samples", "1 .. 1000000"),
])
def test_wear_reliability_refuses_counts_outside_the_limits(wear_problem, kwargs, key, allowed):
    with pytest.raises(rackopt.InputError) as e:
        wear_problem.wear_reliability(**kwargs)
    assert e.value.key_path == key and allowed in e.value.message, str(e.value)


@pytest.mark.parametrize("kwargs, key", [
    ({"reliability_samples": -1}, "reliability_samples"),
    ({"reliability_seed": -1}, "reliability_seed"),
    ({"reliability_seed": 2 ** 62}, "reliability_seed"),
    ({"positions_per_period": 3}, "positions_per_period"),
    ({"threads": -1}, "threads"),
])
def test_metrics_refuse_counts_outside_the_limits(wear_problem, kwargs, key):
    with pytest.raises(rackopt.InputError) as e:
        wear_problem.metrics(["wear_life_at_R(0.9)"], **kwargs)
    assert e.value.key_path == key, str(e.value)


def test_a_path_with_a_nul_byte_is_refused(problem_path, tmp_path):
    with pytest.raises(rackopt.InputError) as e:
        rackopt.load_problem(problem_path("ship_lift.yaml") + "\0.bak")
    assert "NUL" in str(e.value)
    with pytest.raises(rackopt.InputError) as e:
        rackopt.run_study(EVALUATE, problem=problem_path("gantry_axis.yaml"), out=str(tmp_path / "a") + "\0b")
    assert "NUL" in str(e.value)
    assert not (tmp_path / "a").exists()


def test_a_folder_conflict_speaks_python(problem_path, tmp_path):
    drive = problem_path("gantry_axis.yaml")
    rackopt.run_study(EVALUATE, problem=drive, out=tmp_path / "s")
    with pytest.raises(Exception) as e:
        rackopt.run_study(EVALUATE, problem=drive, out=tmp_path / "s")
    assert "resume=True" in str(e.value) and "--resume" not in str(e.value), str(e.value)


def test_a_study_name_too_long_for_a_folder_names_the_key(problem_path, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    study = dict(EVALUATE, study={"name": "n" * 300, "kind": "evaluate"})
    with pytest.raises(rackopt.InputError) as e:
        rackopt.run_study(study, problem=problem_path("gantry_axis.yaml"))
    assert e.value.key_path == "study.name" and "255" in e.value.message, str(e.value)
    assert not (tmp_path / "out").exists()


def test_a_module_built_for_another_python_names_the_interpreter(tmp_path):
    package = os.path.dirname(rackopt.__file__)
    copy = tmp_path / "rackopt"
    shutil.copytree(package, copy, ignore=shutil.ignore_patterns("__pycache__"))
    (built,) = glob.glob(str(copy / "_rackopt*.so"))
    # The same file under another interpreter's ABI tag, as a build for
    # another Python leaves it.
    os.rename(built, str(copy / "_rackopt.cpython-39-x86_64-linux-gnu.so"))
    run = subprocess.run([sys.executable, "-c", "import rackopt"], capture_output=True, text=True,
                         env=dict(os.environ, PYTHONPATH=str(tmp_path)))
    assert run.returncode != 0
    from rackopt._build import PYTHON_EXECUTABLE
    assert "built for another Python" in run.stderr and f"run {PYTHON_EXECUTABLE} instead" in run.stderr, run.stderr
