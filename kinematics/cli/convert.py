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
import sys
from pathlib import Path

from structure.errors import MechanismError
from structure.readwrite.formats import WRITE_SUFFIXES, read_mechanism, write_mechanism
from structure.report import analyze

from ..results.export import write_dxf, write_parquet
from ..results.serialization import check_finite
from ..solvers.plan import make_plan
from ..solvers.solve import solve_pose
from ..solvers.sweep import parse_inputs, read_inputs, sweep
from .parser import DRAWING_SUFFIXES, SWEEP_SUFFIXES
from .plotting import load_drawing

__all__ = ["run"]

def _suffix(path: str) -> str:
    return Path(path).suffix.lower()


def _plan(args: argparse.Namespace):
    report = analyze(read_mechanism(args.file), args.driver)
    return report, make_plan(report, flip=args.flip)


def _drawing(args: argparse.Namespace) -> None:
    report, plan = _plan(args)
    inputs = None
    if args.pose:
        inputs = tuple(parse_inputs([" ".join(args.pose)], plan, "--pose")[0])
    state = solve_pose(plan, inputs)
    if _suffix(args.out) == ".dxf":
        write_dxf(report, plan, state, args.out)
        return
    load_drawing(args.out).save_mechanism_drawing(report, plan, state, args.out)


def _sweep(args: argparse.Namespace) -> None:
    _, plan = _plan(args)
    inputs = read_inputs(args.inputs, plan) if args.inputs else None
    result = sweep(plan, inputs, steps=args.steps)
    check_finite(result.as_dict())
    if _suffix(args.out) == ".parquet":
        write_parquet(result, args.out)
        return
    try:
        Path(args.out).write_text(result.to_csv(), encoding="utf-8")
    except OSError as exc:
        raise MechanismError(f"cannot write {args.out}: {exc.strerror or exc}") from exc


def run(args: argparse.Namespace) -> int:
    """Convert ``args.file`` to ``args.out``; returns the exit code."""
    suffix = _suffix(args.out)
    known = (*WRITE_SUFFIXES, *DRAWING_SUFFIXES, *SWEEP_SUFFIXES)
    if suffix not in known:
        sys.stderr.write(
            f"error: {args.out}: unknown format {suffix or '(no extension)'!r}: "
            f"use {', '.join(known)}\n"
        )
        return 2
    if args.steps < 1:
        sys.stderr.write("error: --steps must be at least 1\n")
        return 2
    try:
        if suffix in WRITE_SUFFIXES:
            mechanism = read_mechanism(args.file)
            if args.driver:
                mechanism = mechanism.with_drivers(args.driver)
            write_mechanism(mechanism, args.out)
        elif suffix in DRAWING_SUFFIXES:
            _drawing(args)
        else:
            _sweep(args)
    except MechanismError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1
    except ValueError as exc:  # a --flip that names no dyad
        sys.stderr.write(f"error: {exc}\n")
        return 2
    sys.stdout.write(f"wrote {args.out}\n")
    return 0
