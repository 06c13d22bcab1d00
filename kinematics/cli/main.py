"""The ``assur`` command line: parse argv, then run the command's module, imported only then.

Exit codes: 0 success, 1 a mechanism error (bad file, impossible mechanism),
2 a usage error. A :class:`MechanismError` is an ``error:`` line, never a traceback.
A new command is a module of this package with its ``run_<command>(args) -> int``, an
entry in :data:`RUNNERS` and one in :data:`kinematics.cli.parser.COMMANDS`.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from structure.errors import MechanismError

from .output import EXIT_USAGE, fail, failed
from .parser import build_parser

__all__ = ["RUNNERS", "main"]

#: command -> (module of this package, its function that runs the command and gives the exit code);
#: the module is imported only when its command runs, so ``assur classify`` starts without the
#: solvers, sympy's exact values or matplotlib
RUNNERS: dict[str, tuple[str, str]] = {
    "classify": ("classify", "run_classify"),
    "kinematics": ("motion", "run_kinematics"),
    "forces": ("forces", "run_forces"),
    "gears": ("gears", "run_gears"),
    "sweep": ("motion", "run_sweep"),
    "animate": ("motion", "run_animate"),
    "convert": ("convert", "run"),
    "atlas": ("atlas", "run"),
    "report": ("report", "run_report"),
}


def _conflict(args: argparse.Namespace) -> str | None:
    """A combination of options the parser cannot refuse by itself, or ``None``."""
    if getattr(args, "explain", None) and (args.json or getattr(args, "exact", False)):
        return "--explain cannot be combined with --json or --exact"
    return None


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line.

    Parameters
    ----------
    argv
        The arguments after the program name; ``None`` reads ``sys.argv``.

    Returns
    -------
    int
        The exit code: 0 success, 1 a mechanism error, 2 a usage error.
    """
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help
        return int(exc.code or 0)
    problem = _conflict(args)
    if problem:
        return fail(problem, EXIT_USAGE)
    module_name, function_name = RUNNERS[args.command]
    run = getattr(importlib.import_module(f"{__package__}.{module_name}"), function_name)
    try:
        return run(args)
    except MechanismError as exc:  # one the command did not catch: still no traceback
        return failed(exc, getattr(args, "json", False))


if __name__ == "__main__":
    sys.exit(main())
