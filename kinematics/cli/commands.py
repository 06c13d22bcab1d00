"""The ``assur`` command line: parse argv, then run the command's module, imported only then.

Exit codes: 0 success, 1 a mechanism error (bad file, impossible mechanism),
2 a usage error, 3 a bug in assur. A :class:`MechanismError` is an ``error:`` line, never a
traceback; any other exception is a bug, reported in one line that asks to report it (the
traceback follows only when the environment variable ``ASSUR_DEBUG`` is set, e.g. to 1).
A reader that closes the output early (``assur classify F --json | head -1``) ends the
command quietly.
A new command is a module of this package with its ``run_<command>(args) -> int``, an
entry in :data:`RUNNERS` and one in :data:`kinematics.cli.parser.COMMANDS`.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
import traceback
from collections.abc import Sequence

from structure.errors import MechanismError, UsageError, clipped

from .output import EXIT_BUG, EXIT_OK, EXIT_USAGE, fail, failed
from .parser import build_parser

__all__ = ["DEBUG_VARIABLE", "EXIT_INTERRUPTED", "RUNNERS", "main"]

#: the environment variable that, set (and not 0), adds the traceback of a bug to its error line
DEBUG_VARIABLE = "ASSUR_DEBUG"

#: the exit code of a run stopped by Ctrl-C (128 + SIGINT, as a shell reports it)
EXIT_INTERRUPTED = 130

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
    "cam": ("cam", "run_cam"),
    "dynamics": ("dynamics", "run_dynamics"),
    "balance": ("dynamics", "run_balance"),
    "synthesize": ("synthesize", "run_synthesize"),
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
    try:
        run = getattr(importlib.import_module(f"{__package__}.{module_name}"), function_name)
        return run(args)
    except BrokenPipeError:
        return _output_closed()
    except KeyboardInterrupt:  # Ctrl-C: a line, no traceback, no half-written file
        return fail("interrupted", EXIT_INTERRUPTED)
    except UsageError as exc:
        return fail(str(exc), EXIT_USAGE)
    except MechanismError as exc:  # one the command did not catch: still no traceback
        return failed(exc, getattr(args, "json", False))
    except Exception as exc:  # anything else is a bug in assur, not a problem of the input
        return _bug(exc)


def _output_closed() -> int:
    """The reader of stdout has gone (``| head -1``): stop quietly, without a last flush."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())  # Python's own flush at exit writes nowhere
    except (OSError, ValueError):  # stdout is no file (captured in-process): nothing to redirect
        pass
    return EXIT_OK


def _bug(exc: Exception) -> int:
    """One line about a bug in assur; its traceback too when :data:`DEBUG_VARIABLE` is set."""
    fail(
        f"internal error in assur ({type(exc).__name__}: {clipped(str(exc))}); this is a bug: "
        f"please report it with the command and its input file "
        f"(set {DEBUG_VARIABLE}=1 to see the traceback)"
    )
    if os.environ.get(DEBUG_VARIABLE, "") not in ("", "0"):
        traceback.print_exception(exc, file=sys.stderr)
    return EXIT_BUG


if __name__ == "__main__":
    sys.exit(main())
