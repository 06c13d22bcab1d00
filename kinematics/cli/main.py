"""The ``assur`` command line: the edge of the project, where argv is parsed and text printed.

Exit codes: 0 success, 1 a mechanism error (bad file, impossible mechanism),
2 a usage error.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from structure.errors import MechanismError, MobilityError
from structure.explain.structural import FORMATS, LANGUAGES, explain_structure
from structure.readwrite.edgelist import read_edgelist
from structure.report import (
    all_driver_choices,
    analyze,
    format_mobility_error,
    format_report,
    mobility_error_dict,
    report_to_dict,
)

from ..exact import forces_exact, solve_exact
from ..explain.worked import explain_forces, explain_kinematics
from ..forces import solve_forces
from ..gears.trains import (
    balancing_moment,
    reduced_inertia,
    speed_ratios,
    train_forces,
    train_losses,
)
from ..plan import make_plan
from ..serialization import (
    exact_forces_to_dict,
    exact_to_dict,
    forces_to_dict,
    state_to_dict,
)
from ..solve import solve_pose
from ..sweep import read_inputs, sweep
from . import atlas as atlas_command
from . import batch as batch_command

__all__ = ["main"]


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assur",
        description="Planar mechanisms by Assur groups: structure, kinematics, forces, gear "
        "trains, figures and worked solutions.",
    )
    sub = parser.add_subparsers(dest="command", required=True)
    classify = sub.add_parser(
        "classify",
        help="mobility, higher-pair replacement, Assur groups, class and structural formula",
    )
    classify.add_argument("file", help="edge-list file (.edges) or its JSON form (.json)")
    classify.add_argument(
        "--driver", action="append", metavar="L", help="driving link (repeat for several)"
    )
    classify.add_argument(
        "--all-drivers",
        action="store_true",
        help="list the groups for every admissible driver choice",
    )
    classify.add_argument("--json", action="store_true", help="print one JSON object")
    classify.add_argument(
        "--plot",
        metavar="OUT",
        help="draw the kinematic graph (and the mechanism, when the file has coordinates) "
        "(.png, .svg, .pdf)",
    )
    kin = sub.add_parser(
        "kinematics",
        help="positions, velocities and accelerations at the sketch pose, group by group",
    )
    kin.add_argument("file", help="edge-list file with point coordinates and driver motion")
    kin.add_argument("--json", action="store_true", help="print one JSON object")
    kin.add_argument(
        "--exact", action="store_true", help="exact values (radicals, fractions) with sympy"
    )
    kin.add_argument(
        "--plot",
        metavar="OUT",
        help="draw the mechanism and its velocity and acceleration polygons (.png, .svg, .pdf)",
    )
    kin.add_argument(
        "--flip",
        action="append",
        metavar="GROUP",
        default=[],
        help="assemble this dyad (e.g. 'II(2,3)') in the other mode than the sketch's",
    )
    fo = sub.add_parser("forces", help="joint reactions and balancing moment, farthest group first")
    fo.add_argument("file", help="edge-list file with coordinates, driver motion and loads")
    fo.add_argument("--json", action="store_true", help="print one JSON object")
    fo.add_argument(
        "--exact", action="store_true", help="exact values (radicals, fractions) with sympy"
    )
    fo.add_argument(
        "--minimum-norm",
        action="store_true",
        help="for an over-constrained mechanism, give the minimum-norm reactions",
    )
    fo.add_argument(
        "--plot",
        metavar="OUT",
        help="draw the mechanism and the force polygon of each group and driver (.png, .svg, .pdf)",
    )
    ge = sub.add_parser(
        "gears", help="gear train: meshes, carriers, DOF, exact speed ratios, balancing moment"
    )
    ge.add_argument("file", help="edge-list file with 'a b H gear z=za,zb' meshes")
    ge.add_argument("--json", action="store_true", help="print one JSON object")
    ge.add_argument(
        "--efficiency",
        type=float,
        metavar="ETA",
        help="efficiency of each mesh (e.g. 0.98): losses, balancing moment with them",
    )
    sw = sub.add_parser("sweep", help="the kinematics over a whole turn of the driver(s)")
    sw.add_argument("file", help="edge-list file with point coordinates and driver motion")
    sw.add_argument("--steps", type=int, default=360, help="poses per turn (default 360)")
    sw.add_argument("--csv", metavar="OUT", help="write every pose to this CSV file")
    sw.add_argument(
        "--inputs",
        metavar="FILE",
        help="the poses to solve instead of one turn: a line per pose, a column per driver "
        "(degrees, or metres for a sliding driver); a first line 'drivers 4 1' sets the order",
    )
    sw.add_argument(
        "--plot",
        metavar="OUT",
        help="plot paths, ω, ε, |v|, |a|, transmission angle, balancing (.png, .svg, .pdf)",
    )
    an = sub.add_parser(
        "animate", help="an animation of the mechanism over one turn of the driver(s)"
    )
    an.add_argument("file", help="edge-list file with point coordinates")
    an.add_argument("out", metavar="OUT", help="the animation: .gif (or .mp4 with ffmpeg)")
    an.add_argument("--steps", type=int, default=36, help="frames per turn (default 36)")
    an.add_argument("--fps", type=float, default=12.0, help="frames per second (default 12)")
    an.add_argument(
        "--inputs", metavar="FILE", help="the frames' driver inputs, as for 'assur sweep --inputs'"
    )
    for command in (classify, kin, fo):
        _add_explain(command)
    atlas_command.add_arguments(
        sub.add_parser("atlas", help="every chain of N links and F DOF, every mechanism classified")
    )
    batch_command.add_arguments(
        sub.add_parser("classify-batch", help="classify many files, directories or globs at once")
    )
    return parser


def _add_explain(command: argparse.ArgumentParser) -> None:
    """``--explain [FORMAT]`` and ``--lang``: the worked solution instead of the plain answer."""
    command.add_argument(
        "--explain",
        nargs="?",
        const="text",
        choices=FORMATS,
        metavar="FORMAT",
        help="print the worked solution, step by step as the textbook writes it: "
        "text (default), markdown or latex",
    )
    command.add_argument(
        "--lang", choices=LANGUAGES, default="en", help="language of --explain (default en)"
    )


def _classify(args: argparse.Namespace) -> int:
    try:
        _check_plot(args.plot)
        mechanism = read_edgelist(args.file)
        report = analyze(mechanism, args.driver)
        choices = all_driver_choices(report) if args.all_drivers else ()
        if args.plot:
            _save_plot(args.plot, lambda figures: _structure_figure(figures, report))
    except MobilityError as exc:
        if args.json:
            _print_json(mobility_error_dict(exc))
        else:
            sys.stderr.write(format_mobility_error(exc))
        return 1
    except MechanismError as exc:
        return _failed(exc, args.json)
    if args.json:
        _print_json(report_to_dict(report, choices))
    elif args.explain:
        sys.stdout.write(explain_structure(report, args.lang, args.explain))
    else:
        sys.stdout.write(format_report(report, choices))
    return 0


def _plot(report, plan, state, path: str) -> None:
    """Save the kinematics sheet."""
    _save_plot(path, lambda figures: figures.kinematics_sheet(report, plan, state))


_PLOT_FORMATS = (".png", ".svg", ".pdf")


def _check_plot(path: str | None) -> None:
    """Refuse a --plot file of an unsupported format before any work is done."""
    if path is not None and Path(path).suffix.lower() not in _PLOT_FORMATS:
        raise MechanismError(
            f"cannot plot to {path}: unsupported figure format "
            f"{Path(path).suffix or '(none)'!r}, use .png, .svg or .pdf"
        )


def _save_plot(path: str, draw) -> None:
    """Save the figure ``draw(kinematics.figures)`` makes.

    matplotlib is the optional ``plot`` extra, imported here.
    """
    _check_plot(path)
    try:
        from .. import figures
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise MechanismError("--plot needs matplotlib: pip install 'assur[plot]'") from exc
    try:
        figures.save(draw(figures), path)
    except ValueError as exc:
        raise MechanismError(str(exc)) from exc
    except OSError as exc:
        raise MechanismError(f"cannot write {path}: {exc.strerror or exc}") from exc


def _structure_figure(figures, report):
    """The kinematic graph, with the mechanism at its sketch pose when the file has one."""
    plan = state = None
    if report.mechanism.points:
        try:
            plan = make_plan(report)
            state = solve_pose(plan)
        except MechanismError:  # an incomplete sketch: the graph alone
            plan = state = None
    return figures.structure_sheet(report, plan, state)


def _print_json(data: object) -> None:
    print(json.dumps(data, indent=2, ensure_ascii=False))


def _title(mechanism, suffix: str = "") -> list[str]:
    """The first lines of a text answer: the mechanism's name and file."""
    return [f"{mechanism.name or 'mechanism'}  ({mechanism.source}){suffix}", ""]


def _failed(exc: MechanismError, as_json: bool) -> int:
    """Report a mechanism error (JSON on stdout when asked, text on stderr); exit code 1."""
    if as_json:
        _print_json({"error": str(exc)})
    sys.stderr.write(f"error: {exc}\n")
    return 1


def _vector(v: object) -> str:
    x, y = v  # type: ignore[misc]
    return f"({x:.6g}, {y:.6g})"


def _kinematics(args: argparse.Namespace) -> int:
    try:
        report = analyze(read_edgelist(args.file))
        plan = make_plan(report, flip=args.flip)
        if args.exact:
            return _print_exact(report, plan, args.json)
        state = solve_pose(plan)
        if args.plot:
            _plot(report, plan, state, args.plot)
    except MechanismError as exc:
        return _failed(exc, args.json)
    except ValueError as exc:  # a --flip that names no dyad
        sys.stderr.write(f"error: {exc}\n")
        return 2
    if args.json:
        _print_json(state_to_dict(state))
        return 0
    if args.explain:
        sys.stdout.write(explain_kinematics(report, plan, state, args.lang, args.explain))
        return 0
    m = report.mechanism
    out = _title(m)
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
            f"  {name} (on {point.link}): position {_vector(point.position)} m, "
            f"v = {_vector(point.velocity)} m/s (|v| = {float(np.hypot(*point.velocity)):.6g}), "
            f"a = {_vector(point.acceleration)} m/s² "
            f"(|a| = {float(np.hypot(*point.acceleration)):.6g})"
        )
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _print_exact(report, plan, as_json: bool) -> int:
    state = solve_exact(plan)
    if as_json:
        _print_json(exact_to_dict(state))
        return 0
    m = report.mechanism
    out = _title(m, ", exact values at the sketch pose")
    for name, values in state.links.items():
        out.append(f"  {name}: ω = {values['omega']} rad/s, ε = {values['epsilon']} rad/s²")
    out.append("")
    for name, values in state.points.items():
        v, a = values["velocity"], values["acceleration"]
        out.append(f"  {name}: v = ({v[0]}, {v[1]}) m/s, a = ({a[0]}, {a[1]}) m/s²")
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _forces(args: argparse.Namespace) -> int:
    try:
        _check_plot(args.plot)
        report = analyze(read_edgelist(args.file))
        if args.plot:
            plan = make_plan(report)
            numeric = solve_forces(plan, minimum_norm=args.minimum_norm)
            _save_plot(args.plot, lambda figures: figures.forces_sheet(report, plan, numeric))
        if args.exact:
            return _print_exact_forces(report, make_plan(report), args.json)
        result = solve_forces(make_plan(report), minimum_norm=args.minimum_norm)
    except MechanismError as exc:
        return _failed(exc, args.json)
    if args.json:
        _print_json(forces_to_dict(result))
        return 0
    if args.explain:
        plan = make_plan(report)
        sys.stdout.write(explain_forces(report, plan, result, args.lang, args.explain))
        return 0
    m = report.mechanism
    out = _title(m)
    out.append("Solved in this order (farthest group first): " + " → ".join(result.order))
    out.append("")
    out.append("Reactions (the force the first link exerts on the second):")
    for r in result.reactions:
        angle = math.degrees(math.atan2(r.force[1], r.force[0]))
        couple = f", couple {r.couple:.6g} N·m" if r.kind == "P" else ""
        out.append(
            f"  {r.point or '?'} ({r.links[0]} on {r.links[1]}, {r.kind}): "
            f"F = {_vector(r.force)} N, |F| = {r.magnitude:.6g} N at {angle:.4g}°{couple}"
        )
        if r.contacts is not None:
            n1, n2 = r.contacts
            out.append(f"      two contacts: N1 = {_vector(n1)} N, N2 = {_vector(n2)} N")
    for point, forces in result.pin_forces.items():
        parts = ", ".join(f"on {link} {_vector(f)}" for link, f in forces.items())
        out.append(f"  compound pin {point}: the pin pushes {parts} N")
    out.append("")
    for link, value in result.balancing_moment.items():
        if link in result.balancing_slide_force:
            out.append(f"Balancing force on driver {link}: {value:.6g} N along its slide")
        else:
            out.append(f"Balancing moment on driver {link}: {value:.6g} N·m (counter-clockwise +)")
    if result.balancing_force is not None:
        out.append(f"Balancing force: {_vector(result.balancing_force)} N")
    if result.friction_loss is not None:
        out.append(f"Power lost to friction: {result.friction_loss:.6g} W")
    out.append(f"Virtual-power check: residual {result.power_residual:.2e} of the largest term")
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _print_exact_forces(report, plan, as_json: bool) -> int:
    result = forces_exact(plan)
    if as_json:
        _print_json(exact_forces_to_dict(result))
        return 0
    m = report.mechanism
    out = _title(m, ", exact values at the sketch pose")
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
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _gears(args: argparse.Namespace) -> int:
    try:
        mechanism = read_edgelist(args.file)
        ratios = speed_ratios(mechanism)
        moment = balancing_moment(mechanism, ratios) if len(ratios.inputs) == 1 else None
        inertia = (
            reduced_inertia(mechanism, ratios)
            if len(ratios.inputs) == 1 and any(x.kind == "mass" for x in mechanism.loads)
            else None
        )
        forces = None
        if moment is not None and all(m.pair.module for m in ratios.meshes):
            try:
                forces = train_forces(mechanism, ratios)
            except MechanismError:
                forces = None  # not a single-carrier planetary train: power only
        losses = None
        if args.efficiency is not None:
            if forces is None:
                raise MechanismError(
                    "mesh losses need a planetary train with module= on every mesh and a "
                    "moment load"
                )
            losses = train_losses(mechanism, ratios, args.efficiency)
    except MechanismError as exc:
        return _failed(exc, args.json)
    if args.json:
        data = {
            "dof": ratios.dof,
            "inputs": list(ratios.inputs),
            "meshes": [
                {
                    "pair": mesh.pair.label,
                    "carrier": mesh.carrier,
                    "z": [mesh.za, mesh.zb],
                    "internal": mesh.internal,
                }
                for mesh in ratios.meshes
            ],
            "teeth_found": [
                {"pair": mechanism.pair(pid).label, "side": side, "z": z}
                for (pid, side), z in ratios.teeth_found.items()
            ],
            "speed_ratio": {
                link: {"exact": str(value), "float": float(value)}
                for link, value in ratios.ratios.items()
            },
        }
        if moment is not None:
            data["balancing_moment"] = {"exact": str(moment), "float": float(moment)}
        if inertia is not None:
            data["reduced_inertia"] = {"exact": str(inertia), "float": float(inertia)}
        if losses is not None:
            data["with_losses"] = {
                "mesh_efficiency": args.efficiency,
                "balancing_moment": losses.balancing_moment,
                "lost_power_per_input_speed": losses.lost_power,
                "efficiency": losses.efficiency,
            }
        if forces is not None:
            data["balancing_moment_by_force_balance"] = forces.balancing_moment
            data["planet_pin_forces"] = {
                planet: {"radial": f[0], "tangential": f[1], "magnitude": float(np.hypot(*f))}
                for planet, f in forces.pins.items()
            }
            data["tooth_forces"] = {
                mechanism.pair(pid).label: value for pid, value in forces.tooth.items()
            }
        _print_json(data)
        return 0
    out = [f"{mechanism.name or 'gear train'}  ({mechanism.source})", ""]
    for mesh in ratios.meshes:
        kind = "internal" if mesh.internal else "external"
        out.append(
            f"  mesh {mesh.pair.label}: z = {mesh.za}, {mesh.zb} ({kind}), carrier {mesh.carrier}"
        )
    for (pid, side), z in ratios.teeth_found.items():
        pair = mechanism.pair(pid)
        out.append(f"  from coaxiality: z of {pair.links[side - 1]} in {pair.label} = {z}")
    out.append(f"DOF of the train: {ratios.dof}; input(s): {', '.join(ratios.inputs)}")
    out.append("Speed ratios to the input (ω_link / ω_input):")
    for link, value in ratios.ratios.items():
        out.append(f"  {link}: {value} ≈ {float(value):.6g}")
    if moment is not None:
        out.append(f"Balancing moment on the input (by power): {moment} ≈ {float(moment):.6g} N·m")
    if losses is not None:
        out.append(
            f"With mesh efficiency {args.efficiency:g}: balancing moment "
            f"{losses.balancing_moment:.6g} N·m, loss {losses.lost_power:.6g} W per rad/s of "
            f"the input, train efficiency {losses.efficiency:.4g}"
        )
    if forces is not None:
        out.append(
            f"Balancing moment from the planets' force balance: {forces.balancing_moment:.6g} N·m"
        )
        for planet, (fr, ft) in forces.pins.items():
            out.append(
                f"  pin of planet {planet}: radial {fr:.6g} N, tangential {ft:.6g} N "
                f"(|F| = {float(np.hypot(fr, ft)):.6g} N, pressure angle 20° included)"
            )
    if inertia is not None:
        out.append(
            f"Moment of inertia reduced to the input: {inertia} ≈ {float(inertia):.6g} kg·m²"
        )
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _sweep(args: argparse.Namespace) -> int:
    if args.steps < 1:
        sys.stderr.write("error: --steps must be at least 1\n")
        return 2
    try:
        _check_plot(args.plot)
        plan = make_plan(analyze(read_edgelist(args.file)))
        inputs = read_inputs(args.inputs, plan) if args.inputs else None
        result = sweep(plan, inputs, steps=args.steps)
        if args.plot:
            _save_plot(args.plot, lambda figures: figures.sweep_figure(result, plan))
    except MechanismError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1
    if args.inputs:
        out = [f"{len(result.inputs)} poses of {args.inputs} for {args.file}", ""]
    else:
        out = [f"{args.steps} poses over one turn of the driver(s) of {args.file}", ""]
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
    if args.csv:
        with open(args.csv, "w", encoding="utf-8") as handle:
            handle.write(result.to_csv())
        out.append(f"wrote {args.csv}")
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _animate(args: argparse.Namespace) -> int:
    if args.steps < 1 or not args.fps > 0:
        sys.stderr.write("error: --steps must be at least 1 and --fps positive\n")
        return 2
    try:
        try:
            from ..figures.animation import animate, turn_inputs
        except ImportError as exc:  # pragma: no cover - depends on the environment
            raise MechanismError("animate needs matplotlib: pip install 'assur[plot]'") from exc
        report = analyze(read_edgelist(args.file))
        plan = make_plan(report)
        inputs = read_inputs(args.inputs, plan) if args.inputs else turn_inputs(plan, args.steps)
        animate(report, plan, inputs, args.out, fps=args.fps)
    except MechanismError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1
    except OSError as exc:
        sys.stderr.write(f"error: cannot write {args.out}: {exc.strerror or exc}\n")
        return 1
    frames = len(inputs)
    sys.stdout.write(f"wrote {args.out}: {frames} frames at {args.fps:g} frames/s\n")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit code."""
    parser = _parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help
        return int(exc.code or 0)
    if getattr(args, "explain", None) and (args.json or getattr(args, "exact", False)):
        sys.stderr.write("error: --explain cannot be combined with --json or --exact\n")
        return 2
    if args.command == "classify":
        return _classify(args)
    if args.command == "kinematics":
        return _kinematics(args)
    if args.command == "sweep":
        return _sweep(args)
    if args.command == "forces":
        return _forces(args)
    if args.command == "gears":
        return _gears(args)
    if args.command == "animate":
        return _animate(args)
    if args.command == "atlas":
        return atlas_command.run(args)
    if args.command == "classify-batch":
        return batch_command.run(args)
    parser.error(f"unknown command {args.command}")
    return 2


if __name__ == "__main__":
    sys.exit(main())
