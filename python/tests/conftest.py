"""Shared set-up of the Python tests: the source tree's problems and studies,
and the command-line program the bindings are compared with."""

import copy
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("RACKOPT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source():
    return SOURCE


@pytest.fixture
def problem_path():
    return lambda name: str(SOURCE / "problems" / name)


@pytest.fixture
def cli():
    """The rackopt program of the same build, or skip when it is not known."""
    path = os.environ.get("RACKOPT_CLI")
    if not path or not os.path.exists(path):
        pytest.skip("RACKOPT_CLI not set (ctest sets it)")
    return path


# A small gantry-like drive as a dict of the problem file's sections.
SMALL_PROBLEM = {
    "pinion": {"teeth": 20, "module": "4 mm", "pressure_angle": "20 deg", "face_width": "40 mm"},
    "rack": {"span": "500 mm", "body_height": "31 mm"},
    "materials": {"steel": {"E": "210 GPa", "nu": 0.3}},
    "load": {"force": "6 kN"},
    "numerics": {"positions_per_period": 24},
}


@pytest.fixture
def small_problem():
    return copy.deepcopy(SMALL_PROBLEM)
