"""Helpers of the command-line tests: a fixture's path, and one run of ``main`` with its output."""

from __future__ import annotations

from pathlib import Path

from kinematics.cli.commands import main

ROOT = Path(__file__).resolve().parents[3]
FIXTURES = ROOT / "fixtures"


def fixture(name: str) -> str:
    return str(FIXTURES / f"{name}.edges")


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err
