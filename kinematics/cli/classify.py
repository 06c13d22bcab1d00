"""``assur classify``: mobility, replacement, Assur groups, class, as text, JSON or worked text.

Imports the structure package only: no solver, no matplotlib (they come with ``--plot``).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path

from structure.errors import MechanismError, MobilityError
from structure.explain.structural import explain_structure
from structure.readwrite.edgelist import read_edgelist
from structure.readwrite.reports import (
    format_mobility_error,
    format_report,
    mobility_error_dict,
    write_report_json,
)
from structure.report import all_driver_choices, analyze

from .output import (
    EXIT_MECHANISM,
    EXIT_OK,
    check_outputs,
    escaped,
    failed,
    input_limit,
    print_json,
    printable,
    write_stdout,
)
from .plotting import check_plot, load_drawing

__all__ = ["run_classify"]


def _is_batch(args: argparse.Namespace) -> bool:
    """Several inputs, a directory, a glob, stdin, or a table's options: a batch."""
    one = args.file
    return bool(
        args.more
        or one == "-"
        or Path(one).is_dir()
        or (not Path(one).exists() and any(c in one for c in "*?["))
        or args.format != "text"
        or args.output
        or args.jobs != 1
        or args.scheduler
        or args.dask_local
    )


def run_classify(args: argparse.Namespace) -> int:
    """Classify the mechanism in ``args.file``, or many inputs into one table; the exit code."""
    if _is_batch(args):
        args.inputs = [args.file, *args.more]
        return importlib.import_module(f"{__package__}.batch").run(args)
    check_outputs([args.file], {"--plot": args.plot})
    try:
        check_plot(args.plot)
        report = analyze(read_edgelist(args.file, input_limit(args)), args.driver)
        choices = all_driver_choices(report) if args.all_drivers else ()
        if args.plot:
            load_drawing().save_structure_sheet(report, args.plot)
    except MobilityError as exc:
        if args.json:
            print_json(mobility_error_dict(exc))
        else:
            sys.stderr.write(printable(format_mobility_error(exc)))
        return EXIT_MECHANISM
    except MechanismError as exc:
        return failed(exc, args.json)
    if args.json:
        write_report_json(report, escaped(sys.stdout, json_text=True), choices)
    elif args.explain:
        write_stdout(explain_structure(report, args.lang, args.explain))
    else:
        write_stdout(format_report(report, choices))
    return EXIT_OK
