"""``assur report``: everything about a mechanism on one self-contained HTML page.

The page (:mod:`kinematics.html`) holds the drawing and the graph, the
structural analysis, the kinematics and forces at the sketch pose, the
cycle's animation and plots, the gear train and the worked solution, in
English or Vietnamese (``--lang``); it needs no network and opens from disk.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path
from types import ModuleType

from structure.errors import MechanismError
from structure.readwrite.edgelist import read_edgelist

from .output import EXIT_OK, EXIT_USAGE, fail

__all__ = ["run_report"]


def _load_page() -> ModuleType:
    """:mod:`kinematics.html`, imported now: it draws with matplotlib, the optional ``plot`` extra.

    Deferred as :func:`kinematics.cli.plotting.load_drawing` is, so that a missing
    matplotlib is an error line, not a traceback.

    Raises
    ------
    MechanismError
        When matplotlib is not installed.
    """
    try:
        return importlib.import_module("kinematics.html")
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise MechanismError("report needs matplotlib: pip install 'assur[plot]'") from exc


def run_report(args: argparse.Namespace) -> int:
    """Write the report of ``args.file`` to ``args.output``; returns the exit code."""
    if args.steps < 1:
        return fail("--steps must be at least 1", EXIT_USAGE)
    output = Path(args.output or Path(args.file).with_suffix(".html").name)
    try:
        page = _load_page()
        contents = page.gather(read_edgelist(args.file), steps=args.steps)
        text = page.report_page(contents, args.lang)
    except MechanismError as exc:
        return fail(str(exc))
    try:
        output.write_text(text, encoding="utf-8")
    except OSError as exc:
        return fail(f"cannot write {output}: {exc.strerror or exc}")
    sys.stdout.write(f"wrote {output}\n")
    return EXIT_OK
