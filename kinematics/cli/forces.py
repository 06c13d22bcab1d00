"""``assur forces``: joint reactions and the balancing moment, farthest group first.

Text, JSON (``--json``), exact values (``--exact``) or the worked solution (``--explain``).
"""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING

from structure.errors import MechanismError
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ..explain.worked import explain_forces
from ..kinetostatics.forces import solve_forces
from ..results.serialization import exact_forces_to_dict, forces_to_dict
from ..solvers.exact import EXACT_TIMEOUT, forces_exact
from ..solvers.plan import make_plan
from .output import (
    EXIT_OK,
    check_finite,
    check_outputs,
    failed,
    input_limit,
    note,
    print_json,
    title_lines,
    vector,
    write_lines,
    write_stdout,
)
from .plotting import check_plot, load_drawing

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from structure.report import StructuralReport

    from ..kinetostatics.forces import ForceSolution
    from ..solvers.plan import SolvePlan

__all__ = ["run_forces"]


def run_forces(args: argparse.Namespace) -> int:
    """Solve the joint reactions of ``args.file`` at its sketch pose; returns the exit code."""
    check_outputs([args.file], {"--plot": args.plot})
    try:
        check_plot(args.plot)
        report = analyze(read_edgelist(args.file, input_limit(args)))
        if args.plot:
            plan = make_plan(report)
            numeric = solve_forces(plan, minimum_norm=args.minimum_norm)
            load_drawing().save_forces_sheet(report, plan, numeric, args.plot)
        if args.exact:
            return _print_exact_forces(report, make_plan(report), args.json, args.exact_timeout)
        result = solve_forces(make_plan(report), minimum_norm=args.minimum_norm)
        check_finite(forces_to_dict(result))
    except MechanismError as exc:
        return failed(exc, args.json)
    if args.json:
        print_json(forces_to_dict(result))
    elif args.explain:
        plan = make_plan(report)
        write_stdout(explain_forces(report, plan, result, args.lang, args.explain))
    else:
        write_lines(_forces_lines(report, result))
    return EXIT_OK


def _forces_lines(report: StructuralReport, result: ForceSolution) -> list[str]:
    """The text answer: solve order, reactions, pin forces, balancing and the power check."""
    out = title_lines(report.mechanism)
    out.append("Solved in this order (farthest group first): " + " → ".join(result.order))
    out.append("")
    out.append("Reactions (the force the first link exerts on the second):")
    for r in result.reactions:
        angle = math.degrees(math.atan2(r.force[1], r.force[0]))
        couple = f", couple {r.couple:.6g} N·m" if r.kind == "P" else ""
        out.append(
            f"  {r.point or '?'} ({r.links[0]} on {r.links[1]}, {r.kind}): "
            f"F = {vector(r.force)} N, |F| = {r.magnitude:.6g} N at {angle:.4g}°{couple}"
        )
        if r.contacts is not None:
            n1, n2 = r.contacts
            out.append(f"      two contacts: N1 = {vector(n1)} N, N2 = {vector(n2)} N")
    for point, forces in result.pin_forces.items():
        parts = ", ".join(f"on {link} {vector(f)}" for link, f in forces.items())
        out.append(f"  compound pin {point}: the pin pushes {parts} N")
    out.append("")
    for link, value in result.balancing_moment.items():
        if link in result.balancing_slide_force:
            out.append(f"Balancing force on driver {link}: {value:.6g} N along its slide")
        else:
            out.append(f"Balancing moment on driver {link}: {value:.6g} N·m (counter-clockwise +)")
    if result.balancing_force is not None:
        out.append(f"Balancing force: {vector(result.balancing_force)} N")
    if result.friction_loss is not None:
        out.append(f"Power lost to friction: {result.friction_loss:.6g} W")
    out.append(f"Virtual-power check: residual {result.power_residual:.2e} of the largest term")
    return out


def _print_exact_forces(
    report: StructuralReport, plan: SolvePlan, as_json: bool, timeout: float | None
) -> int:
    """Print the exact reactions and balancing moment at the sketch pose (sympy).

    Nothing is printed before the whole answer is known (a time limit leaves no half answer).
    """
    result = forces_exact(plan, timeout=EXACT_TIMEOUT if timeout is None else timeout)
    for approximation in result.approximations:  # what is not exact, on stderr
        note(approximation)
    if as_json:
        print_json(exact_forces_to_dict(result))
        return EXIT_OK
    out = title_lines(report.mechanism, ", exact values at the sketch pose")
    for point, links, kind, force, couple in result.reactions:
        extra = f", couple {couple} N·m" if kind == "P" else ""
        out.append(
            f"  {point} ({links[0]} on {links[1]}, {kind}): F = ({force[0]}, {force[1]}) N{extra}"
        )
    sliding = {d.link for d in plan.drivers if d.kind == "P"}
    for link, value in result.balancing_moment.items():
        if link in sliding:
            out.append(f"Balancing force on driver {link}: {value} N along its slide")
        else:
            out.append(f"Balancing moment on driver {link}: {value} N·m")
    if result.balancing_force is not None:
        f = result.balancing_force
        out.append(f"Balancing force: ({f[0]}, {f[1]}) N")
    write_lines(out)
    return EXIT_OK
