"""``assur report``: everything about a mechanism on one self-contained HTML page.

The page (:mod:`kinematics.html`) holds the drawing and the graph, the
structural analysis, the kinematics and forces at the sketch pose, the
cycle's animation and plots, the gear train and the worked solution, in
English or Vietnamese (``--lang``); it needs no network and opens from disk.
"""

from __future__ import annotations

import argparse
import importlib
from pathlib import Path
from types import ModuleType

from structure.errors import MechanismError
from structure.limits import check_size
from structure.model import Mechanism
from structure.readwrite.atomic import write_text
from structure.readwrite.edgelist import read_edgelist

from .output import EXIT_OK, EXIT_USAGE, check_outputs, fail, input_limit, write_stdout

__all__ = ["REPORT_BYTES_PER_POSE_ITEM", "check_report_size", "run_report"]


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
    """Write the report of ``args.file`` to ``args.output``; returns the exit code.

    The page is written whole or not at all, and never over the file it reads
    (``assur report m.html`` with no ``-o`` would name its own input: refused).
    """
    if args.steps < 1:
        return fail("--steps must be at least 1", EXIT_USAGE)
    output = Path(args.output or Path(args.file).with_suffix(".html").name)
    check_outputs([args.file], {"-o" if args.output else "the page": str(output)})
    try:
        mechanism = read_edgelist(args.file, input_limit(args))
        check_report_size(args.steps, mechanism)
        page = _load_page()
        contents = page.gather(mechanism, steps=args.steps)
        text = page.report_page(contents, args.lang)
        write_text(output, text)
    except MechanismError as exc:
        return fail(str(exc))
    write_stdout(f"wrote {output}\n")
    return EXIT_OK


#: memory one pose of the report's cycle takes, per named point and link: its sweep, the
#: animation's poses as page text, the plots' curves (measured: the peak of ``assur report``
#: on the four-bar, 5 points and 3 links, is 175, 183 and 238 MB for 120, 2,400 and 24,000
#: poses: 2.6 kB a pose, 330 bytes an item)
REPORT_BYTES_PER_POSE_ITEM = 400


def check_report_size(steps: int, mechanism: Mechanism) -> None:
    """Refuse a report of more poses (``--steps``) than fit in memory.

    Raises
    ------
    SizeError
        Naming the memory the poses would take and how many fit.
    """
    items = len(mechanism.points) + len(mechanism.moving_links)
    check_size(
        steps,
        REPORT_BYTES_PER_POSE_ITEM * max(items, 1),
        f"a report of {steps} poses",
        "ask for at most {fit} poses (--steps)",
    )
