"""docs/python.md's examples run as written (from the repository's root)."""

import os
import re

import pytest


def blocks(source):
    text = (source / "docs" / "python.md").read_text()
    return re.findall(r"```python\n(.*?)```", text, re.S)


def test_the_plotting_example_draws_its_plot(source, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    os.environ.setdefault("MPLBACKEND", "Agg")
    first = blocks(source)[0]
    assert "savefig" in first
    code = first.replace('"problems/', '"' + str(source / "problems") + '/')
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "docs/python.md", "exec"), {})
    assert (tmp_path / "railway_stiffness.png").stat().st_size > 10000


def test_the_study_example_runs(source, tmp_path, monkeypatch):
    study = blocks(source)[1]
    code = "import rackopt\n" + study.replace('"problems/', '"' + str(source / "problems") + '/')
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "docs/python.md", "exec"), {})
    assert (tmp_path / "out" / "module_sweep" / "summary.json").exists()
