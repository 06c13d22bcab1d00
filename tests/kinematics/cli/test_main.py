"""The ``assur`` program itself (kinematics.cli.commands): usage errors, --help, ``python -m``."""

from __future__ import annotations

import importlib
import subprocess
import sys

import pytest

from kinematics.cli.commands import RUNNERS
from kinematics.cli.parser import COMMANDS
from structure.explain.document import FORMATS

from .conftest import ROOT, fixture, run


# ------------------------------------------------------------------ usage errors: exit 2
@pytest.mark.parametrize(
    "argv",
    [
        pytest.param(["classify", fixture("fourbar"), "--bogus"], id="unknown-option"),
        pytest.param(["classify"], id="missing-file"),
        pytest.param([], id="no-command"),
        pytest.param(["solve", fixture("fourbar")], id="unknown-command"),
        pytest.param(["classify", fixture("fourbar"), "--driver"], id="driver-without-link"),
    ],
)
def test_usage_error_exits_2(capsys, argv):
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert out == ""
    assert "usage:" in err


def test_help_exits_0(capsys):
    code, out, _ = run(capsys, "classify", "--help")
    assert code == 0
    assert "--all-drivers" in out


@pytest.mark.parametrize("command", ["classify", "kinematics", "forces"])
def test_help_names_every_explain_format(capsys, command):
    code, out, _ = run(capsys, command, "--help")
    assert code == 0
    said = " ".join(out.split())
    assert all(f in said for f in FORMATS), FORMATS


@pytest.mark.parametrize("command", ["sweep", "animate", "convert"])
def test_help_says_inputs_are_taken_from_the_sketch(capsys, command):
    code, out, _ = run(capsys, command, "--help")
    said = " ".join(out.split())
    assert code == 0
    assert "from the sketch" in said or "as for 'assur sweep --inputs'" in said


# ------------------------------------------------------------------ as a program
def test_python_dash_m_kinematics(tmp_path):
    result = subprocess.run(
        [sys.executable, "-m", "kinematics", "classify", fixture("fourbar")],
        capture_output=True,
        text=True,
        encoding="utf-8",
        cwd=tmp_path,
        timeout=120,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert "W = 3·3 − (2·4 + 0) + 0 − 0 = 1" in result.stdout.splitlines()
    assert "Structural formula: I(1) → II(2,3)" in result.stdout.splitlines()


def test_python_dash_m_structure_says_where_the_command_line_went(tmp_path):
    """structure imports nothing of kinematics, so it cannot run the command line itself."""
    result = subprocess.run(
        [sys.executable, "-m", "structure", "classify", fixture("fourbar")],
        capture_output=True,
        text=True,
        encoding="utf-8",
        cwd=tmp_path,
        timeout=120,
        check=False,
    )
    assert result.returncode == 2
    assert "python -m kinematics" in result.stderr


# ------------------------------------------------------------------ the dispatch table
def test_every_command_has_a_runner():
    """Each command the parser knows is dispatched to a function of a module of the CLI."""
    assert {name for name, _, _ in COMMANDS} == set(RUNNERS)
    for module_name, function_name in RUNNERS.values():
        module = importlib.import_module(f"kinematics.cli.{module_name}")
        assert callable(getattr(module, function_name))


def test_classify_starts_without_the_solvers_or_matplotlib():
    """Issue 12: ``assur classify`` imports only the structure side and the CLI's cheap modules."""
    script = (
        "import sys\n"
        "from kinematics.cli.commands import main\n"
        f"assert main(['classify', {fixture('fourbar')!r}]) == 0\n"
        "print(' '.join(sorted(sys.modules)))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", script],
        capture_output=True,
        text=True,
        encoding="utf-8",
        cwd=ROOT,  # this checkout's packages, not an installed copy
        timeout=120,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    loaded = set(result.stdout.splitlines()[-1].split())
    assert "matplotlib" not in loaded
    kinematics = {name for name in loaded if name.startswith("kinematics.")}
    assert kinematics <= {
        "kinematics.cli",
        "kinematics.cli.classify",
        "kinematics.cli.commands",
        "kinematics.cli.output",
        "kinematics.cli.parser",
        "kinematics.cli.plotting",
    }
