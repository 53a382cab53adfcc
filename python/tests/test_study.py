"""Studies from Python: the same results as `rackopt run`, from a file or a
dict, with the problem read from disk or held in memory."""

import json
import subprocess

import pytest

import rackopt

EVALUATE = {
    "study": {"name": "evaluate", "kind": "evaluate"},
    "objectives": [{"metric": "stiffness_fluctuation"}],
    "report": ["min_stiffness", "contact_ratio"],
}


def test_a_study_file_gives_what_the_command_line_gives(source, cli, tmp_path):
    study = str(source / "studies" / "rack_railway_sizing.yaml")
    ours = rackopt.run_study(study, out=tmp_path / "py", threads=1)
    run = subprocess.run([cli, "run", study, "--json", "--out", str(tmp_path / "cli"), "--threads", "1"],
                         capture_output=True, text=True, check=True)
    theirs = json.loads(run.stdout)
    assert ours["out_dir"] == str(tmp_path / "py")
    assert ours["status"] == theirs["status"] and ours["evaluations"] == theirs["evaluations"]
    assert ours["best"] == theirs["best"]
    assert (tmp_path / "py" / "report.md").exists() and (tmp_path / "py" / "evaluations.sqlite").exists()


def test_a_dict_study_with_its_problem_in_memory(problem_path, small_problem, tmp_path):
    drive = rackopt.load_problem(problem_path("gantry_axis.yaml"), set=["numerics.positions_per_period=24"])
    summary = rackopt.run_study(EVALUATE, problem=drive, out=tmp_path / "s")
    assert summary["status"] == "ok" and summary["ok"]
    direct = drive.metrics(["stiffness_fluctuation", "min_stiffness", "contact_ratio"])
    best = summary["best"]["metrics"]
    for label, value in direct.items():
        assert best[label]["value"] == value.value, label
    assert summary["problem"] == problem_path("gantry_axis.yaml")

    # The problem as a dict inside the study dict gives the same study.
    inline = dict(EVALUATE, problem=small_problem)
    inline_summary = rackopt.run_study(inline, out=tmp_path / "inline")
    given = rackopt.run_study(EVALUATE, problem=inline["problem"], out=tmp_path / "given")
    assert inline_summary["best"]["metrics"] == given["best"]["metrics"]


def test_resume_takes_every_design_from_the_record(source, tmp_path):
    study = str(source / "studies" / "rack_railway_sizing.yaml")
    first = rackopt.run_study(study, out=tmp_path / "r", set=["solver.max_evaluations=40"], threads=1)
    again = rackopt.run_study(study, out=tmp_path / "r", set=["solver.max_evaluations=40"], threads=1, resume=True)
    assert again["best"] == first["best"]
    assert again["reused_evaluations"] == first["evaluations"]


def test_study_errors_say_where(source, small_problem, tmp_path):
    with pytest.raises(rackopt.InputError) as e:
        rackopt.run_study(dict(EVALUATE, study={"kind": "evaluat"}), problem=small_problem, out=tmp_path / "e")
    assert e.value.file == "<dict>" and e.value.key_path == "study.kind" and e.value.line is None
    with pytest.raises(rackopt.InputError) as e:
        rackopt.run_study(str(source / "studies" / "rack_railway_sizing.yaml"), set=["solver.max_evaluation=3"],
                          out=tmp_path / "f")
    assert "max_evaluation" in str(e.value)
    with pytest.raises(rackopt.InputError) as e:  # a study without any problem
        rackopt.run_study(EVALUATE, out=tmp_path / "g")
    assert e.value.key_path == "problem"


def test_ctrl_c_stops_a_study_cleanly_and_raises(small_problem, tmp_path):
    import os
    import signal
    import sys
    import time

    # A sweep long enough to be interrupted: Ctrl-C after it has started.
    script = f"""
import rackopt, sys
study = {{"study": {{"name": "long", "kind": "sweep"}},
          "variables": {{"pinion.module": ["3 mm", "5 mm"], "rack.span": ["300 mm", "900 mm"]}},
          "objectives": [{{"metric": "stiffness_fluctuation"}}],
          "sweep": {{"method": "sobol", "points": 60000, "max_points": 60000}}}}
print("started", flush=True)
rackopt.run_study(study, problem={small_problem!r}, out={str(tmp_path / "long")!r}, threads=1)
"""
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=os.environ.copy())
    assert proc.stdout.readline().strip() == "started"
    time.sleep(1.0)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode != 0 and "KeyboardInterrupt" in err
    summary = json.loads((tmp_path / "long" / "summary.json").read_text())
    assert summary["status"] == "stopped" and 0 < summary["evaluations"] < 60000
