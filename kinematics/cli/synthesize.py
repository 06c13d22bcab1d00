"""``assur synthesize path|function|motion``: a design from targets, written as a mechanism file.

Each prints a readable summary (link lengths, pivots, Grashof type,
transmission angles, errors) or, with ``--json``, one object whose keys are a
contract (``error_max``, ``error_rms``, ``transmission_deg``, ``grashof``,
``seed``, ``evaluations``, ``seconds`` for a path; ``precision_x``,
``error_max`` for a function; ``designs``, ``chosen`` for motion), writes the
design with ``-o`` (``.edges`` or ``.json``: the marker ``P`` and the
targets included, for ``classify``, ``sweep`` and ``report``) and draws it
with ``--plot``.
"""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from structure.errors import MechanismError, UsageError
from structure.parallel import MissingExtraError
from structure.readwrite.formats import WRITE_SUFFIXES, write_mechanism

from ..synthesis.formula import read_function
from ..synthesis.function import FunctionLinkage, FunctionProblem, synthesize_function
from ..synthesis.linkages import Linkage
from ..synthesis.motion import synthesize_motion
from ..synthesis.path import PathProblem, synthesize_path
from ..synthesis.targets import read_rows_file
from .output import EXIT_OK, fail, failed, print_json, write_lines
from .plotting import check_plot, load_drawing
from .tables import check_run_options

__all__ = ["run_synthesize"]


def _suffix_ok(out: str | None) -> None:
    if out is not None and not any(out.lower().endswith(s) for s in WRITE_SUFFIXES):
        raise UsageError(f"{out}: write the design as {', '.join(WRITE_SUFFIXES)}")


def run_synthesize(args: argparse.Namespace) -> int:
    """Run ``assur synthesize KIND ...``; the exit code."""
    _suffix_ok(args.output)
    try:
        check_plot(getattr(args, "plot", None))
        return {"path": _path, "function": _function, "motion": _motion}[args.kind](args)
    except MissingExtraError as exc:
        raise UsageError(str(exc)) from None
    except MechanismError as exc:
        return failed(exc, args.json)


def _xy(v) -> list[float]:
    return [float(v[0]), float(v[1])]


def _write(mechanism, args) -> None:
    if args.output:
        write_mechanism(mechanism, args.output)


def _plot(args, save) -> None:
    if getattr(args, "plot", None):
        save()(args.plot)


# ------------------------------------------------------------------ path
def _path(args: argparse.Namespace) -> int:
    problem = check_run_options(_with_format(args))
    if problem:
        raise UsageError(problem)
    rows = read_rows_file(args.targets, 3 if args.timing else 2)
    if args.generations < 1 or args.population < 4 or args.restarts < 1:
        raise UsageError("--generations and --restarts must be at least 1, --population 4")
    spec = PathProblem(
        rows[:, :2],
        rows[:, 2] if args.timing else None,
        Linkage(args.linkage),
        transmission_min=args.transmission,
        ratio_max=args.ratio,
        allow_rocker=args.allow_rocker,
        seed=args.seed,
        restarts=args.restarts,
        generations=args.generations,
        population=args.population,
    )
    design = synthesize_path(
        spec, jobs=args.jobs, scheduler=args.scheduler, dask_local=args.dask_local
    )
    _write(design.mechanism, args)
    m = design.mechanism
    pivots = {k: _xy((m.points[k].x, m.points[k].y)) for k in ("A", "D", "G") if k in m.points}
    answer: dict[str, Any] = {
        "linkage": str(spec.linkage),
        "error_max": design.error_max,
        "error_rms": design.error_rms,
        "transmission_deg": list(design.transmission_deg),
        "grashof": design.grashof,
        "seed": spec.seed,
        "evaluations": design.evaluations,
        "seconds": design.seconds,
        "errors": [float(e) for e in design.errors],
        "inputs_deg": [float(v) for v in design.inputs_deg],
        "in_order": design.in_order,
        "pivots": pivots,
        "parameters": design.parameters,
        "rejections": design.rejections,
        "output": args.output,
    }
    _plot(args, lambda: _target_figure(m))
    if args.json:
        print_json(answer)
        return EXIT_OK
    p = design.parameters
    lines = [f"{m.name}  (targets {args.targets}, seed {spec.seed})", ""]
    links = "links: ground d = {d:.6g}, crank a = {a:.6g}, coupler b = {b:.6g}, rocker c = {c:.6g}"
    lines.append(links.format(**p))
    if "e" in p:
        lines.append("dyad to G: e = {e:.6g}, f = {f:.6g}".format(**p))
    for k, xy in pivots.items():
        lines.append(f"fixed pivot {k}: ({xy[0]:.6g}, {xy[1]:.6g})")
    lines.append(f"Grashof: {design.grashof}")
    low, high = design.transmission_deg
    lines.append(f"transmission angle over the motion: {low:.4g}° to {high:.4g}°")
    lines.append(
        f"error: largest {design.error_max:.6g}, rms {design.error_rms:.6g} "
        f"(targets {'with' if args.timing else 'without'} timing)"
    )
    lines.append(f"{design.evaluations} candidates in {design.seconds:.3g} s")
    if args.output:
        lines.append(f"written: {args.output}")
    write_lines(lines)
    return EXIT_OK


def _with_format(args: argparse.Namespace) -> argparse.Namespace:
    """The run options as :func:`check_run_options` reads them (no table format here)."""
    copy = argparse.Namespace(**vars(args))
    copy.format = "json"
    return copy


# ------------------------------------------------------------------ function
def _function(args: argparse.Namespace) -> int:
    x0, x1 = args.x
    spec = FunctionProblem(
        read_function(args.expr),
        x0,
        x1,
        args.input_range,
        args.output_range,
        points=args.points,
        linkage=FunctionLinkage(args.linkage),
        input_start=args.input_start,
        output_start=args.output_start,
        spacing=args.spacing,
        size=args.size,
    )
    design = synthesize_function(spec)
    _write(design.mechanism, args)
    y0, y1 = (float(v) for v in spec.function(np.array([x0, x1])))
    answer = {
        "linkage": str(spec.linkage),
        "precision_x": list(design.precision_x),
        "error_max": design.error_max,
        "error_max_percent": 100.0 * design.error_max / abs(y1 - y0),
        "error_at_precision": design.error_at_precision,
        "precision_input_deg": list(design.precision_input),
        "precision_output": list(design.precision_output),
        "input_start_deg": design.input_start,
        "output_start": design.output_start,
        "lengths": design.lengths,
        "grashof": design.grashof,
        "transmission_deg": list(design.transmission_deg),
        "output": args.output,
    }
    _plot(args, lambda: _error_figure(design))
    if args.json:
        print_json(answer)
        return EXIT_OK
    unit = "°" if spec.linkage is FunctionLinkage.FOURBAR else " m"
    lines = [f"{design.mechanism.name}, x in [{x0:g}, {x1:g}]", ""]
    lines.append("precision points x: " + ", ".join(f"{v:.6g}" for v in design.precision_x))
    lines.append("lengths: " + ", ".join(f"{k} = {v:.6g}" for k, v in design.lengths.items()))
    lines.append(
        f"input starts at {design.input_start:.6g}°, output at {design.output_start:.6g}{unit}"
    )
    lines.append(f"type: {design.grashof}")
    low, high = design.transmission_deg
    lines.append(f"transmission angle over the range: {low:.4g}° to {high:.4g}°")
    lines.append(
        f"structural error: largest {design.error_max:.6g} "
        f"({answer['error_max_percent']:.4g} % of the output range); at the precision "
        f"points {design.error_at_precision:.3g}"
    )
    if args.output:
        lines.append(f"written: {args.output}")
    write_lines(lines)
    return EXIT_OK


# ------------------------------------------------------------------ motion
def _motion(args: argparse.Namespace) -> int:
    poses = read_rows_file(args.poses, 3)
    designs = synthesize_motion(poses, check=args.check)
    shown = designs[: args.designs]
    chosen = 0 if designs and designs[0].defects.ok and designs[0].checked else None
    if chosen is not None:
        _write(designs[chosen].mechanism, args)
    answer = {
        "designs": [
            {
                "pivots": {k: list(v) for k, v in d.pivots.items()},
                "lengths": d.lengths,
                "defects": d.defects.names(),
                "reason": d.defects.reason,
                "transmission_deg": list(d.transmission_deg),
                "inputs_deg": list(d.inputs_deg),
                "checked_by_solver": d.checked,
            }
            for d in shown
        ],
        "chosen": chosen,
        "output": args.output if chosen is not None else None,
    }
    if chosen is not None:
        _plot(args, lambda: _target_figure(designs[chosen].mechanism))
    if args.json:
        print_json(answer)
    else:
        lines = [f"{len(designs)} four-bars for {len(poses)} poses ({args.poses})", ""]
        for k, d in enumerate(shown):
            mark = "*" if k == chosen else " "
            defects = ", ".join(d.defects.names()) or "none"
            piv = "  ".join(f"{n}({x:.4g}, {y:.4g})" for n, (x, y) in d.pivots.items())
            low, high = d.transmission_deg
            lines.append(f"{mark}{k}: {piv}  μ {low:.3g}°–{high:.3g}°  defects: {defects}")
        if args.output and chosen is not None:
            lines.append(f"written: {args.output} (design {chosen})")
        write_lines(lines)
    if chosen is None:
        return fail("no defect-free four-bar for these poses: see the designs' defects")
    return EXIT_OK


# ------------------------------------------------------------------ figures
def _target_figure(mechanism):
    return lambda path: load_drawing().save_target_figure(mechanism, path)


def _error_figure(design):
    return lambda path: load_drawing().save_structural_error(design, path)
