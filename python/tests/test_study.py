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


def _wait_for_the_first_evaluation(wal, proc, quiet=0.3, seconds=120):
    """Waits until the store's write-ahead log grows again after its set-up:
    the first growth that follows `quiet` seconds without one is the first
    evaluation's commit (the store holds the database locked, so it cannot
    be read while the study runs). Returns early when the process ended."""
    import time

    size, changed = 0, time.monotonic()
    deadline = changed + seconds
    while proc.poll() is None and time.monotonic() < deadline:
        now_size = wal.stat().st_size if wal.exists() else 0
        if now_size != size:
            if size > 32 and time.monotonic() - changed >= quiet:
                return
            size, changed = now_size, time.monotonic()
        time.sleep(0.01)


def test_ctrl_c_inside_the_last_batch_of_a_long_study_stops_it_reports_and_raises(source, tmp_path):
    """Ctrl-C while the study's last batch runs (one sweep chunk of designs
    whose Monte Carlo life at R takes over a second each, about 12 s in all):
    nothing polls between batches any more, so only the models' own stop
    request can end it. The study stops, its report says so, KeyboardInterrupt
    is raised, and resume=True finishes it with what was recorded."""
    import os
    import signal
    import sys
    import time

    out = tmp_path / "life"
    study = {"study": {"name": "long life at R", "kind": "sweep", "seed": 1},
             "problem": str(source / "problems" / "gantry_axis.yaml"),
             "variables": {"pinion.face_width": {"lower": "30 mm", "upper": "60 mm"}},
             "objectives": [{"metric": "wear_life_at_R(0.9)", "sense": "maximize"}],
             "metric_options": {"exact_quantile": "off", "reliability_samples": 3000},
             "sweep": {"method": "grid", "levels": 8},
             "output": {"plots": "off", "stiffness_curve": "off"}}
    script = f"""
import rackopt, sys
try:
    rackopt.run_study({study!r}, out={str(out)!r}, threads=1)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
    sys.exit(130)
print("returned", flush=True)
"""
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=os.environ.copy())
    # The start design (the objective's scale) is recorded first; the eight
    # sweep designs then run as one batch.
    _wait_for_the_first_evaluation(out / "evaluations.sqlite-wal", proc)
    assert proc.poll() is None, "the study ended before it could be interrupted"
    proc.send_signal(signal.SIGINT)
    printed, err = proc.communicate(timeout=120)
    assert printed.strip() == "KeyboardInterrupt", (printed, err)
    assert proc.returncode == 130, err
    summary = json.loads((out / "summary.json").read_text())
    # Stopped inside the batch: only the start design is recorded.
    assert summary["status"] == "stopped" and 1 <= summary["evaluations"] < 9
    assert "stopped" in (out / "report.md").read_text()

    resumed = rackopt.run_study(study, out=out, threads=2, resume=True)
    assert resumed["status"] == "ok" and resumed["evaluations"] == 9
    assert resumed["reused_evaluations"] == summary["evaluations"]


def test_a_fifo_is_refused_at_once(tmp_path):
    """A FIFO as the problem or study file: InputError naming it, without
    waiting for a writer (run in a child with a time limit, so that a
    regression fails instead of hanging)."""
    import os
    import sys

    fifo = tmp_path / "input.yaml"
    os.mkfifo(fifo)
    script = f"""
import rackopt
for call in (rackopt.load_problem, rackopt.run_study):
    try:
        call({str(fifo)!r})
        print("read", flush=True)
    except rackopt.InputError as e:
        print(e.file, "|", e.message, flush=True)
"""
    try:
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60,
                             env=os.environ.copy())
    except subprocess.TimeoutExpired:
        pytest.fail("waited on the FIFO")
    lines = run.stdout.splitlines()
    assert len(lines) == 2, (run.stdout, run.stderr)
    for line in lines:
        assert line.startswith(str(fifo) + " |") and "FIFO (named pipe), not a regular file" in line, line
