"""``assur convert IN OUT``: a mechanism into another format, or its drawing or its sweep.

IN is read by :func:`structure.readwrite.formats.read_mechanism` (the edge
list, our JSON, pylinkage's JSON, a pyslvs expression or Pyslvs-UI project).
OUT's extension says what is written:

* ``.edges``, ``.json``, ``.pyslvs``: the mechanism itself;
* ``.svg``, ``.png``, ``.pdf``: the drawing at the pose (matplotlib, the ``plot`` extra);
* ``.dxf``: the drawing at the pose, one layer per Assur group (ezdxf, the ``dxf`` extra);
* ``.csv``, ``.parquet``: the sweep over one turn of the drivers (``--steps``) or
  over ``--inputs`` (pyarrow, the ``parquet`` extra, for Parquet).

The pose is the sketch's, or ``--pose`` (each driver's rotation from the
sketch in degrees, or its slide in metres). Exit codes: 0 written, 1 a
mechanism error (a bad file, a pose that does not assemble, a format that
cannot hold the mechanism), 2 a usage error (an unknown OUT extension).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from structure.errors import MechanismError
from structure.readwrite.atomic import write_text
from structure.readwrite.formats import (
    WRITE_SUFFIXES,
    mechanism_left_out,
    read_mechanism,
    write_mechanism,
)
from structure.report import analyze

from ..results.export import drawing_left_out, dxf_left_out, write_dxf, write_parquet
from ..results.serialization import check_finite
from ..solvers.plan import make_plan
from ..solvers.solve import solve_pose
from ..solvers.sweep import parse_inputs, read_inputs, sweep
from .output import (
    EXIT_MECHANISM,
    EXIT_OK,
    EXIT_USAGE,
    check_outputs,
    fail,
    input_limit,
    warn,
    write_stdout,
)
from .parser import DRAWING_SUFFIXES, SWEEP_SUFFIXES
from .plotting import load_drawing

__all__ = ["run"]


def _suffix(path: str) -> str:
    return Path(path).suffix.lower()


def _plan(args: argparse.Namespace):
    report = analyze(read_mechanism(args.file, input_limit(args)), args.driver)
    return report, make_plan(report, flip=args.flip)


def _drawing(args: argparse.Namespace) -> tuple[str, ...]:
    """Draw the mechanism at the pose; what the drawing leaves out of it."""
    report, plan = _plan(args)
    inputs = None
    if args.pose:
        inputs = tuple(parse_inputs([" ".join(args.pose)], plan, "--pose")[0])
    state = solve_pose(plan, inputs)
    if _suffix(args.out) == ".dxf":
        write_dxf(report, plan, state, args.out)
        return dxf_left_out(report.mechanism)
    load_drawing().save_mechanism_drawing(report, plan, state, args.out)
    return drawing_left_out(report.mechanism)


def _sweep(args: argparse.Namespace) -> None:
    _, plan = _plan(args)
    inputs = read_inputs(args.inputs, plan, input_limit(args)) if args.inputs else None
    result = sweep(plan, inputs, steps=args.steps)
    check_finite(result.as_dict())
    if _suffix(args.out) == ".parquet":
        write_parquet(result, args.out)
        return
    write_text(args.out, result.to_csv())


def _mechanism(args: argparse.Namespace) -> tuple[str, ...]:
    """Write the mechanism in OUT's format; what that format leaves out of it."""
    mechanism = read_mechanism(args.file, input_limit(args))
    if args.driver:
        mechanism = mechanism.with_drivers(args.driver)
    write_mechanism(mechanism, args.out)
    return mechanism_left_out(mechanism, _suffix(args.out))


def run(args: argparse.Namespace) -> int:
    """Convert ``args.file`` to ``args.out``; returns the exit code.

    What OUT's format cannot hold of the mechanism is named on stderr, a
    ``warning:`` line per kind (a pyslvs project has no loads, a drawing no
    driver motion, ...); the edge list and the JSON form hold everything.
    """
    suffix = _suffix(args.out)
    known = (*WRITE_SUFFIXES, *DRAWING_SUFFIXES, *SWEEP_SUFFIXES)
    if suffix not in known:
        return fail(
            f"{args.out}: unknown format {suffix or '(no extension)'!r}: use {', '.join(known)}",
            EXIT_USAGE,
        )
    if args.steps < 1:
        return fail("--steps must be at least 1", EXIT_USAGE)
    check_outputs([args.file, args.inputs], {"OUT": args.out})
    try:
        if suffix in WRITE_SUFFIXES:
            dropped = _mechanism(args)
        elif suffix in DRAWING_SUFFIXES:
            dropped = _drawing(args)
        else:
            _sweep(args)
            dropped = ()
    except MechanismError as exc:
        return fail(str(exc), EXIT_MECHANISM)
    except ValueError as exc:  # a --flip that names no dyad
        return fail(str(exc), EXIT_USAGE)
    for line in dropped:
        warn(f"{args.out}: {line}")
    write_stdout(f"wrote {args.out}\n")
    return EXIT_OK
