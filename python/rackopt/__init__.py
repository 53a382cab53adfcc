"""rackopt from Python: rack-and-pinion drive models, metrics and studies.

    import rackopt
    p = rackopt.load_problem("problems/rack_railway.yaml")
    curve = p.stiffness_curve()
    print(curve.k_min, "N/m at", curve.travel_at_min, "m")

Every number is SI (m, rad, N/m, Pa, s). Problems and studies come from a
file path, a YAML string or a dict; a bad input raises rackopt.InputError
with the file, line, column and key path the command line would print.
docs/python.md is the reference.
"""

import json
import os
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Union

import numpy as np


def _other_interpreter_message() -> Optional[str]:
    """Why the compiled module cannot load when it was built for another
    Python (its file name carries that Python's ABI tag), naming the
    interpreter it was built with; None when that is not the reason."""
    import glob
    import sys
    import sysconfig

    here = os.path.dirname(os.path.abspath(__file__))
    built = sorted(os.path.basename(p) for p in glob.glob(os.path.join(here, "_rackopt*.so")))
    suffix = sysconfig.get_config_var("EXT_SUFFIX") or ".so"
    if not built or any(name.endswith(suffix) for name in built):
        return None
    try:
        from ._build import PYTHON_EXECUTABLE as interpreter
    except ImportError:
        interpreter = "the python3 rackopt was built with"
    return (f"rackopt's compiled module {built[0]} was built for another Python than this one "
            f"({sys.executable}, which loads *{suffix}): run {interpreter} instead, or rebuild rackopt "
            f"with -DPython3_EXECUTABLE={sys.executable} (docs/python.md)")


try:
    from . import _rackopt
except ImportError as _error:
    _message = _other_interpreter_message()
    if _message is None:
        raise
    raise ImportError(_message) from _error
from ._rackopt import DesignError, InputError

__version__ = _rackopt.__version__
# Shown and caught as rackopt.InputError / rackopt.DesignError.
InputError.__module__ = DesignError.__module__ = __name__
__all__ = [
    "DesignError",
    "InputError",
    "Problem",
    "StiffnessCurve",
    "MetricValue",
    "load_problem",
    "metric_definitions",
    "run_study",
]

DICT_SOURCE = "<dict>"


def _dict_text(d: dict) -> str:
    # JSON is YAML: the dict goes through the same loader as a file, with
    # every key check and unit ("60 mm") the file would get.
    return json.dumps(d, indent=2)


def _dict_errors(call, *args, **kwargs):
    """Calls `call`; an InputError about a dict loses its line and column,
    which would point into the dict's JSON rendering, not into user code."""
    try:
        return call(*args, **kwargs)
    except InputError as e:
        if getattr(e, "file", None) == DICT_SOURCE:
            e.line = None
            e.column = None
            e.args = (f"{DICT_SOURCE}: {e.key_path}: {e.message}" if e.key_path
                      else f"{DICT_SOURCE}: {e.message}",)
        raise


@dataclass
class StiffnessCurve:
    """The mesh stiffness over one rack span (SI).

    travel, stiffness, approach, local_stiffness, pairs_in_mesh: one value per
    sample (a discontinuity gives two samples at the same travel: the left and
    the right limit). breakdown: per-pair quantities, each an array of shape
    (samples, pair slots) with NaN where the slot holds no pair; in_mesh is
    the boolean mask. Compliances (c_*) are in m/N.
    """

    travel: np.ndarray
    stiffness: np.ndarray
    approach: np.ndarray
    local_stiffness: np.ndarray
    pairs_in_mesh: np.ndarray
    breakpoints: np.ndarray
    k_min: float
    k_max: float
    k_mean: float
    k_fluctuation: float
    travel_at_min: float
    travel_at_max: float
    breakdown: Dict[str, np.ndarray] = field(default_factory=dict)
    warnings: List[str] = field(default_factory=list)


@dataclass
class MetricValue:
    """One metric of one design: value in SI (None when it failed), the
    display text ("61.2 yr"), and for a failure its code, message and cause
    (the model that failed, or "metric")."""

    label: str
    ok: bool
    value: Optional[float]
    display: str
    error_code: str
    message: str
    cause: str


class Problem:
    """A drive problem: YAML text, the name its messages carry, and `--set`
    assignments over it. Immutable; with_set / with_values return new ones.
    Build one with load_problem, Problem.from_file, from_yaml or from_dict."""

    def __init__(self, impl: "_rackopt.Problem"):
        self._impl = impl

    @staticmethod
    def from_file(path: Union[str, os.PathLike], set: Sequence[str] = ()) -> "Problem":
        return Problem(_rackopt.Problem.from_file(os.fspath(path), list(set)))

    @staticmethod
    def from_yaml(text: str, name: str = "<string>", set: Sequence[str] = ()) -> "Problem":
        return Problem(_rackopt.Problem(text, name, list(set)))

    @staticmethod
    def from_dict(d: dict, set: Sequence[str] = ()) -> "Problem":
        return Problem(_dict_errors(_rackopt.Problem, _dict_text(d), DICT_SOURCE, list(set)))

    @property
    def name(self) -> str:
        """The drive's name (the file's `name`, else the file stem)."""
        return self._impl.name

    @property
    def source(self) -> str:
        """Where the problem came from: a path, "<string>" or "<dict>"."""
        return self._impl.source

    @property
    def overrides(self) -> List[str]:
        return list(self._impl.overrides)

    def with_set(self, *assignments: str) -> "Problem":
        """The problem with more `--set` assignments: with_set("pinion.module=8 mm")."""
        return Problem(_dict_errors(self._impl.with_overrides, list(assignments)))

    def with_values(self, values: Dict[str, float]) -> "Problem":
        """The problem with numeric keys set to SI values, bit for bit:
        with_values({"pinion.module": 0.008, "rack.span": 1.2})."""
        return Problem(_dict_errors(self._impl.with_values, dict(values)))

    def geometry(self) -> dict:
        """Pinion, rack, path of contact, n-pair zones and contact ratio (SI)."""
        return self._impl.geometry()

    def stiffness_curve(self, positions_per_period: int = 0) -> StiffnessCurve:
        """The mesh stiffness over one span with each pair's breakdown.
        positions_per_period > 0 overrides numerics.positions_per_period."""
        return StiffnessCurve(**self._impl.stiffness_curve(positions_per_period))

    def wear_life(self) -> dict:
        """The nominal Archard wear life: life (s), life_cycles, life_years,
        criterion, the worn profiles as arrays, snapshots over the life."""
        return self._impl.wear_life()

    def wear_reliability(self, samples: Optional[int] = None, seed: Optional[int] = None,
                         threads: int = 0) -> dict:
        """Life at reliability R over the problem's random inputs, as
        `rackopt wear --json` reports it, plus the sample lives (s) as an array."""
        return self._impl.wear_reliability(samples, seed, threads)

    def life_at_R(self, R: float, samples: Optional[int] = None, seed: Optional[int] = None) -> float:
        """Wear life at reliability R [s] (the metric wear_life_at_R(R))."""
        return self.metric(f"wear_life_at_R({R!r})", reliability_samples=samples, reliability_seed=seed)

    def metrics(self, names: Sequence[str], positions_per_period: Optional[int] = None,
                reliability_samples: Optional[int] = None, reliability_seed: Optional[int] = None,
                threads: int = 1) -> Dict[str, MetricValue]:
        """Metrics by name (docs/metrics.md), each model computed once: label -> MetricValue.
        A design the models reject gives failed values, not an exception."""
        r = self._impl.metrics(list(names), positions_per_period, reliability_samples, reliability_seed, threads)
        return {v["label"]: MetricValue(**v) for v in r["values"]}

    def metric(self, name: str, **options) -> float:
        """One metric's SI value; raises DesignError when the design cannot have it."""
        (v,) = self.metrics([name], **options).values()
        if not v.ok:
            err = DesignError(f"{v.label}: {v.message}")
            err.code = v.error_code
            err.message = v.message
            raise err
        return v.value

    def __repr__(self) -> str:
        return f"rackopt.Problem({self.name!r} from {self.source!r})"


def load_problem(source: Union[str, os.PathLike, dict, Problem], set: Sequence[str] = ()) -> Problem:
    """A problem from a file path, a dict (the file's sections) or a Problem."""
    if isinstance(source, Problem):
        return source.with_set(*set) if set else source
    if isinstance(source, dict):
        return Problem.from_dict(source, set)
    return Problem.from_file(source, set)


def metric_definitions() -> List[dict]:
    """Every metric: name, unit (SI), display_unit, description, models, parameter."""
    return _rackopt.metric_definitions()


def run_study(study: Union[str, os.PathLike, dict], out: Optional[Union[str, os.PathLike]] = None,
              problem: Union[None, str, os.PathLike, dict, Problem] = None, set: Sequence[str] = (),
              threads: int = 0, resume: bool = False) -> dict:
    """Runs a study like `rackopt run` and returns its summary.json as a dict
    (plus "out_dir"). `study` is a study file or a dict of its sections.
    `problem`, when given, is the study's problem held in memory (a Problem,
    a dict or a path) and replaces the study's `problem:` key. `set` are
    `--set` assignments; `out` defaults to out/<study name>."""
    if problem is not None and not isinstance(problem, Problem):
        problem = load_problem(problem)
    impl = problem._impl if problem is not None else None
    if isinstance(study, dict):
        text, name, base = _dict_text(study), DICT_SOURCE, os.getcwd()
    else:
        path = os.fspath(study)
        text, name, base = _rackopt.read_input_file(path), path, os.path.dirname(path)
    out_dir = "" if out is None else os.fspath(out)
    return _dict_errors(_rackopt.run_study_text, text, name, base, list(set), impl, out_dir, threads, resume)
