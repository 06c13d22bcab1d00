"""The ``assur`` program itself (kinematics.cli.main): usage errors, --help, ``python -m``."""

from __future__ import annotations

import subprocess
import sys

import pytest

from .conftest import fixture, run


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
