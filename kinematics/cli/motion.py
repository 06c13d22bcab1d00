"""``assur kinematics``, ``sweep`` and ``animate``: the motion at the sketch pose and over a turn.

Text, JSON (``--json``), exact values (``--exact``) or the worked solution (``--explain``)
of one pose; the ranges over a sweep and its CSV; an animation of the turn.
"""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING

import numpy as np

from structure.errors import MechanismError
from structure.readwrite.atomic import atomic_path, write_text
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ..explain.worked import explain_kinematics
from ..html.cycle import inputs_text
from ..html.phrases import say
from ..results.serialization import exact_to_dict, state_to_dict
from ..solvers.exact import EXACT_TIMEOUT, solve_exact
from ..solvers.plan import make_plan
from ..solvers.solve import assembly_modes, solve_pose
from ..solvers.sweep import read_inputs, sweep
from ..solvers.travel import cycle_span, driver_rates, travel
from .output import (
    EXIT_OK,
    EXIT_USAGE,
    check_finite,
    check_outputs,
    fail,
    failed,
    input_limit,
    note,
    print_json,
    title_lines,
    vector,
    write_lines,
    write_stdout,
)
from .plotting import check_animation, check_plot, load_drawing

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from structure.report import StructuralReport

    from ..solvers.plan import SolvePlan
    from ..solvers.solve import KinematicState
    from ..solvers.sweep import Sweep
    from ..solvers.travel import Travel

__all__ = ["run_animate", "run_kinematics", "run_sweep"]


def run_kinematics(args: argparse.Namespace) -> int:
    """Solve the sketch pose of ``args.file`` group by group; returns the exit code."""
    if args.exact and args.flip:
        return fail(
            "--exact solves the sketch pose, and --flip asks for another assembly mode than "
            "the sketch's, whose coordinates are not exact: leave out one of them",
            EXIT_USAGE,
        )
    check_outputs([args.file], {"--plot": args.plot})
    try:
        report = analyze(read_edgelist(args.file, input_limit(args)))
        plan = make_plan(report, flip=args.flip)
        if args.modes:
            return _print_modes(report, plan, args.json)
        if args.exact:
            return _print_exact(report, plan, args.json, args.exact_timeout)
        state = solve_pose(plan)
        check_finite(state_to_dict(state))
        if args.plot:
            check_plot(args.plot)
            load_drawing().save_kinematics_sheet(report, plan, state, args.plot)
    except MechanismError as exc:
        return failed(exc, args.json)
    except ValueError as exc:  # a --flip that names no group
        return fail(str(exc), EXIT_USAGE)
    if args.json:
        print_json(state_to_dict(state))
    elif args.explain:
        write_stdout(explain_kinematics(report, plan, state, args.lang, args.explain))
    else:
        write_lines(_kinematics_lines(report, plan, state))
    return EXIT_OK


def _kinematics_lines(
    report: StructuralReport, plan: SolvePlan, state: KinematicState
) -> list[str]:
    """The text answer: drivers, solve order, then every link and point."""
    out = title_lines(report.mechanism)
    for d in plan.drivers:
        unit = ("ω", "rad/s", "ε", "rad/s²") if d.kind == "R" else ("v", "m/s", "a", "m/s²")
        assumed = "" if d.speed_given else " (not given in the file: assumed 0)"
        out.append(
            f"Driver {d.link}: {unit[0]} = {d.speed:g} {unit[1]}, "
            f"{unit[2]} = {d.acceleration:g} {unit[3]}{assumed}"
        )
    out.append("")
    out.append("Solved in this order:")
    for i, step in enumerate(plan.steps, start=1):
        kind = f" {step.kind}" if step.kind else ""
        out.append(f"  {i}. {step.label}{kind}: links {', '.join(step.links)}")
    out.append("")
    out.append("Links (angle turned from the sketch):")
    for name, link in state.links.items():
        out.append(
            f"  {name}: angle {link.angle:.6g} rad, ω = {link.omega:.6g} rad/s, "
            f"ε = {link.epsilon:.6g} rad/s²"
        )
    out.append("")
    out.append("Points:")
    for name, point in state.points.items():
        out.append(
            f"  {name} (on {point.link}): position {vector(point.position)} m, "
            f"v = {vector(point.velocity)} m/s (|v| = {float(np.hypot(*point.velocity)):.6g}), "
            f"a = {vector(point.acceleration)} m/s² "
            f"(|a| = {float(np.hypot(*point.acceleration)):.6g})"
        )
    return out


def _print_modes(report: StructuralReport, plan: SolvePlan, as_json: bool) -> int:
    """Print each group's assembly modes at the sketch's inputs: its inner pins in each."""
    modes = assembly_modes(plan)
    inner = {
        step.label: [p.point for p in step.group.internal_pairs if p.point]
        for step in plan.steps
        if step.group is not None
    }

    def pins(label: str, mode) -> dict[str, list[float]]:
        return {k: [float(x) for x in mode.pins[k]] for k in inner[label] if k in mode.pins}

    if as_json:
        print_json(
            {
                "modes": {
                    label: [{"mode": m.index, "pins": pins(label, m)} for m in found]
                    for label, found in modes.items()
                }
            }
        )
        return EXIT_OK
    out = title_lines(report.mechanism, ", assembly modes at the sketch's inputs")
    out.append("(--flip GROUP=K assembles a group in mode K; mode 0 is the one it takes itself)")
    for label, found in modes.items():
        out.append(f"  {label}: {len(found)} mode{'' if len(found) == 1 else 's'}")
        for m in found:
            where = ", ".join(f"{k} {vector(np.array(v))}" for k, v in pins(label, m).items())
            out.append(f"    {m.index}: {where}")
    write_lines(out)
    return EXIT_OK


def _print_exact(
    report: StructuralReport, plan: SolvePlan, as_json: bool, timeout: float | None
) -> int:
    """Print the exact velocities and accelerations at the sketch pose (sympy).

    Nothing is printed before the whole answer is known (a time limit leaves no half answer).
    """
    state = solve_exact(plan, timeout=EXACT_TIMEOUT if timeout is None else timeout)
    for approximation in state.approximations:  # what is not exact, on stderr
        note(approximation)
    if as_json:
        print_json(exact_to_dict(state))
        return EXIT_OK
    out = title_lines(report.mechanism, ", exact values at the sketch pose")
    for name, values in state.links.items():
        out.append(f"  {name}: ω = {values['omega']} rad/s, ε = {values['epsilon']} rad/s²")
    out.append("")
    for name, values in state.points.items():
        v, a = values["velocity"], values["acceleration"]
        out.append(f"  {name}: v = ({v[0]}, {v[1]}) m/s, a = ({a[0]}, {a[1]}) m/s²")
    write_lines(out)
    return EXIT_OK


def run_sweep(args: argparse.Namespace) -> int:
    """Solve ``args.steps`` poses over a turn (or the ``--inputs`` poses); returns the exit code."""
    if args.steps < 1:
        return fail("--steps must be at least 1", EXIT_USAGE)
    check_outputs([args.file, args.inputs], {"--csv": args.csv, "--plot": args.plot})
    try:
        check_plot(args.plot)
        plan = make_plan(analyze(read_edgelist(args.file, input_limit(args))))
        inputs = read_inputs(args.inputs, plan, input_limit(args)) if args.inputs else None
        result = sweep(plan, inputs, steps=args.steps)
        check_finite(result.as_dict())
        if args.plot:
            load_drawing().save_sweep_figure(result, plan, args.plot)
        out = _sweep_lines(args, plan, result)  # the ranges and balancing, computed when read
        if args.csv:
            write_text(args.csv, result.to_csv())
            out.append(f"wrote {args.csv}")
    except MechanismError as exc:
        return fail(str(exc))
    write_lines(out)
    return EXIT_OK


def _cycle_text(plan: SolvePlan, inputs: np.ndarray) -> str:
    """What the default sweep covers: one turn, a cycle of several drivers, or a stroke."""
    rates = driver_rates(plan)
    span = cycle_span(plan, rates)
    if span is None:
        ends = ", ".join(
            f"{d.link} from {inputs[0, k]:.4g} m to {inputs[-1, k]:.4g} m"
            for k, d in enumerate(plan.drivers)
            if rates[k]
        )
        return f"the stroke of the sliding driver(s) ({ends})"
    turns = rates * span / (2 * math.pi)
    if len(turns) == 1 or np.all(turns == 1.0):
        return "one turn of the driver(s)"
    each = ", ".join(
        f"{d.link} {_turns_text(t) if d.kind == 'R' else f'{t * 2 * math.pi:.4g} m'}"
        for d, t in zip(plan.drivers, turns, strict=True)
    )
    return f"one cycle of the drivers, at the ratio of their speeds ({each})"


def _turns_text(turns: float) -> str:
    """``2 turns``, ``1 turn back``, ``held``."""
    if turns == 0:
        return "held"
    count = f"{abs(turns):.4g} turn{'' if abs(turns) == 1 else 's'}"
    return count if turns > 0 else f"{count} back"


def _sweep_lines(args: argparse.Namespace, plan: SolvePlan, result: Sweep) -> list[str]:
    """The text answer of a sweep: the ranges of ω, ε, transmission angles and balancing."""
    if args.inputs:
        out = [f"{len(result.inputs)} poses of {args.inputs} for {args.file}", ""]
    else:
        out = [
            f"{len(result.inputs)} poses over {_cycle_text(plan, result.inputs)} of {args.file}",
            "",
        ]
    out.append("link   ω min … max (rad/s)        ε min … max (rad/s²)")
    for name, values in result.links.items():
        w, e = values["omega"], values["epsilon"]
        out.append(
            f"{name:6} {w.min():11.6g} … {w.max():<11.6g} {e.min():11.6g} … {e.max():<11.6g}"
        )
    for label, mu in result.transmission.items():
        out.append(
            f"transmission angle of {label}: {np.degrees(mu.min()):.4g}° … "
            f"{np.degrees(mu.max()):.4g}°"
        )
    for name, values in result.balancing.items():
        out.append(f"balancing {name}: {values.min():.6g} … {values.max():.6g}")
    return out


def run_animate(args: argparse.Namespace) -> int:
    """Write an animation of the mechanism over a turn to ``args.out``; returns the exit code."""
    if args.steps < 1:
        return fail("--steps must be at least 1", EXIT_USAGE)
    check_outputs([args.file, args.inputs], {"OUT": args.out})
    check_animation(args.out, args.fps)
    try:
        drawing = load_drawing("animate")
        report = analyze(read_edgelist(args.file, input_limit(args)))
        plan = make_plan(report)
        notes = []
        if args.inputs:
            inputs = read_inputs(args.inputs, plan, input_limit(args))
        else:
            drawing.check_frames(args.steps, plan)
            way = travel(plan, args.steps)
            inputs = way.inputs
            if not way.complete:
                inputs = drawing.there_and_back(inputs)
                notes.append(_stretch_note(plan, way))
        drawing.check_frames(len(inputs), plan)
        with atomic_path(args.out) as temporary:
            drawing.animate(report, plan, inputs, temporary, fps=args.fps)
    except MechanismError as exc:
        return fail(str(exc))
    write_stdout(f"wrote {args.out}: {len(inputs)} frames at {args.fps:g} frames/s\n")
    if notes:
        write_lines(notes)
    return EXIT_OK


def _stretch_note(plan: SolvePlan, way: Travel) -> str:
    """What an animation of a stretch shows: how far the mechanism reaches, and there and back."""
    low, high = (
        say("en", f"limit_{limit.stop.name.lower()}", at=inputs_text(plan, limit.at),
            group=limit.group)
        for limit in way.limits or ()
    )  # fmt: skip
    what = "not a whole turn" if any(d.kind == "R" for d in plan.drivers) else "the stroke"
    return (
        f"{what}: the mechanism reaches from {low}, to {high}; the frames go over that "
        "stretch and back"
    )
