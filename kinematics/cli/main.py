"""The ``assur`` command line: parse argv, then run the command's module, imported only then.

Exit codes: 0 success, 1 a mechanism error (bad file, impossible mechanism),
2 a usage error. A :class:`MechanismError` is an ``error:`` line, never a traceback.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from .output import EXIT_USAGE, fail
from .parser import build_parser

__all__ = ["main"]

#: command -> (module of this package, its function that runs the command and gives the exit code);
#: the module is imported only when its command runs, so ``assur classify`` starts without the
#: solvers, sympy's exact values or matplotlib
_COMMANDS: dict[str, tuple[str, str]] = {
    "classify": ("classify", "run_classify"),
    "kinematics": ("motion", "run_kinematics"),
    "forces": ("forces", "run_forces"),
    "gears": ("gears", "run_gears"),
    "sweep": ("motion", "run_sweep"),
    "animate": ("motion", "run_animate"),
}


def _conflict(args: argparse.Namespace) -> str | None:
    """A combination of options the parser cannot refuse by itself, or ``None``."""
    if getattr(args, "explain", None) and (args.json or getattr(args, "exact", False)):
        return "--explain cannot be combined with --json or --exact"
    return None


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit code."""
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help
        return int(exc.code or 0)
    problem = _conflict(args)
    if problem:
        return fail(problem, EXIT_USAGE)
    module_name, function_name = _COMMANDS[args.command]
    module = importlib.import_module(f"{__package__}.{module_name}")
    return getattr(module, function_name)(args)


if __name__ == "__main__":
    sys.exit(main())
