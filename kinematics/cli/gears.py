"""``assur gears``: a gear train's meshes, DOF, exact speed ratios, balancing moment and losses.

Text or JSON (``--json``); ``--efficiency`` adds the mesh losses.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from structure.errors import MechanismError, UsageError
from structure.readwrite.edgelist import read_edgelist

from ..gears.trains import (
    balancing_moments,
    inertia_matrix,
    input_speeds,
    link_speeds,
    relation_text,
    speed_ratios,
    speed_relations,
    train_forces,
    train_losses,
)
from .output import EXIT_OK, check_finite, failed, input_limit, print_json, write_lines

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from structure.model import Mechanism

    from ..gears.trains import TrainForces, TrainLosses, TrainRatios

__all__ = ["run_gears"]


@dataclass(frozen=True)
class _TrainAnswer:
    """What ``assur gears`` found; the optional parts are ``None`` when they do not apply.

    With one input the moments and the inertia are single numbers (sympy); with
    several, a moment per input, an inertia matrix, and the links' speeds when
    the driver lines give the inputs' ``omega=``.
    """

    mechanism: Mechanism
    ratios: TrainRatios
    moments: dict[str, Any] | None  # sympy numbers: the balancing moment on each input, by power
    inertia: Any  # sympy number (one input) or Matrix (several): the inertia reduced to them
    speeds: dict[str, Any] | None  # sympy numbers: every link's speed (several inputs, omega=)
    forces: TrainForces | None  # planetary force balance (module= on every mesh)
    losses: TrainLosses | None  # with --efficiency
    efficiency: float | None

    @property
    def single(self) -> bool:
        return len(self.ratios.inputs) == 1

    @property
    def moment(self) -> Any:
        """The balancing moment on the single input, or None."""
        return None if self.moments is None or not self.single else self.moments[_only(self)]


def _only(answer: _TrainAnswer) -> str:
    return answer.ratios.inputs[0]


def run_gears(args: argparse.Namespace) -> int:
    """Analyse the gear train in ``args.file``; returns the exit code.

    Raises
    ------
    UsageError
        An ``--efficiency`` outside (0, 1] (the command line's exit status 2).
    """
    if args.efficiency is not None and not 0 < args.efficiency <= 1:
        raise UsageError("--efficiency is the efficiency of each mesh, a number in (0, 1]")
    try:
        answer = _solve_train(read_edgelist(args.file, input_limit(args)), args.efficiency)
        check_finite(_train_dict(answer))
    except MechanismError as exc:
        return failed(exc, args.json)
    if args.json:
        print_json(_train_dict(answer))
    else:
        write_lines(_train_lines(answer))
    return EXIT_OK


def _solve_train(mechanism: Mechanism, efficiency: float | None) -> _TrainAnswer:
    """Ratios or relations, then balancing moments, inertia, speeds, forces, losses."""
    ratios = speed_ratios(mechanism)
    single = len(ratios.inputs) == 1
    moments = balancing_moments(mechanism, ratios)
    inertia = None
    if any(x.kind == "mass" for x in mechanism.loads):
        matrix = inertia_matrix(mechanism, ratios)
        inertia = matrix[0, 0] if single else matrix
    given = input_speeds(mechanism, ratios)
    speeds = link_speeds(ratios, given) if given is not None and not single else None
    forces = None
    if moments is not None and all(m.pair.module for m in ratios.meshes):
        try:
            forces = train_forces(mechanism, ratios)
        except MechanismError:
            forces = None  # not a single-carrier planetary train: power only
    losses = None
    if efficiency is not None:
        if moments is None:
            raise MechanismError(
                "mesh losses need a moment load on the train (a 'moment LINK M' line)"
            )
        at = None if single or given is None else {x: float(v) for x, v in given.items()}
        losses = train_losses(mechanism, ratios, efficiency, at)
    return _TrainAnswer(mechanism, ratios, moments, inertia, speeds, forces, losses, efficiency)


def _exact(value: Any) -> dict[str, Any]:
    """An exact value and its float, as JSON."""
    return {"exact": str(value), "float": float(value)}


def _train_dict(answer: _TrainAnswer) -> dict[str, Any]:
    """The JSON answer."""
    mechanism, ratios = answer.mechanism, answer.ratios
    data: dict[str, Any] = {
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
    }
    if answer.single:
        data["speed_ratio"] = {link: _exact(value) for link, value in ratios.ratios.items()}
    else:
        data["relations"] = {
            link: {
                "exact": str(ratios.ratios[link]),
                "text": relation_text(link, row),
                "coefficients": {x: _exact(k) for x, k in row.items()},
            }
            for link, row in speed_relations(ratios).items()
        }
    if answer.speeds is not None:
        data["speeds"] = {link: _exact(value) for link, value in answer.speeds.items()}
    if answer.moments is not None:
        if answer.single:
            data["balancing_moment"] = _exact(answer.moment)
        else:
            data["balancing_moments"] = {x: _exact(v) for x, v in answer.moments.items()}
    if answer.inertia is not None:
        if answer.single:
            data["reduced_inertia"] = _exact(answer.inertia)
        else:
            data["inertia_matrix"] = [[_exact(v) for v in row] for row in answer.inertia.tolist()]
    if answer.losses is not None:
        losses = answer.losses
        if answer.single:
            data["with_losses"] = {
                "mesh_efficiency": answer.efficiency,
                "balancing_moment": losses.balancing_moment,
                "lost_power_per_input_speed": losses.lost_power,
                "efficiency": losses.efficiency,
            }
        else:
            data["with_losses"] = {
                "mesh_efficiency": answer.efficiency,
                "balancing_moments": dict(losses.balancing_moments),
                "lost_power": losses.lost_power,
                "efficiency": losses.efficiency,
            }
    if answer.forces is not None:
        forces = answer.forces
        if answer.single:
            data["balancing_moment_by_force_balance"] = forces.balancing_moment
        else:
            data["balancing_moments_by_force_balance"] = dict(forces.balancing_moments)
        data["planet_pin_forces"] = {
            planet: {"radial": f[0], "tangential": f[1], "magnitude": float(np.hypot(*f))}
            for planet, f in forces.pins.items()
        }
        data["tooth_forces"] = {
            mechanism.pair(pid).label: value for pid, value in forces.tooth.items()
        }
    return data


def _train_lines(answer: _TrainAnswer) -> list[str]:
    """The text answer."""
    mechanism, ratios = answer.mechanism, answer.ratios
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
    if answer.single:
        out.append("Speed ratios to the input (ω_link / ω_input):")
        for link, value in ratios.ratios.items():
            out.append(f"  {link}: {value} ≈ {float(value):.6g}")
    else:
        out.extend(_several_inputs_lines(answer))
    out.extend(_torque_lines(answer))
    return out


def _several_inputs_lines(answer: _TrainAnswer) -> list[str]:
    """The relations in the inputs' speeds and, when given, the speeds themselves."""
    ratios = answer.ratios
    out = ["Speeds as relations in the inputs' speeds (Willis, exact):"]
    for link, row in speed_relations(ratios).items():
        if link not in ratios.inputs:
            out.append(f"  {relation_text(link, row)}")
    if answer.speeds is None:
        out.append("  (give omega= on every driver line for the speeds themselves)")
        return out
    given = ", ".join(f"ω{x} = {answer.speeds[x]}" for x in ratios.inputs)
    out.append(f"Speeds with {given} rad/s (the driver lines):")
    for link, value in answer.speeds.items():
        if link not in ratios.inputs:
            out.append(f"  {link}: {value} ≈ {float(value):.6g} rad/s")
    return out


def _torque_lines(answer: _TrainAnswer) -> list[str]:
    """Balancing moments, losses, the planets' force balance, the reduced inertia."""
    out: list[str] = []
    losses, forces = answer.losses, answer.forces
    if answer.moments is not None and answer.single:
        moment = answer.moment
        out.append(f"Balancing moment on the input (by power): {moment} ≈ {float(moment):.6g} N·m")
    elif answer.moments is not None:
        out.append("Balancing moments on the inputs (by power):")
        for x, value in answer.moments.items():
            out.append(f"  {x}: {value} ≈ {float(value):.6g} N·m")
    if losses is not None and answer.single:
        out.append(
            f"With mesh efficiency {answer.efficiency:g}: balancing moment "
            f"{losses.balancing_moment:.6g} N·m, loss {losses.lost_power:.6g} W per rad/s of "
            f"the input, train efficiency {losses.efficiency:.4g}"
        )
    elif losses is not None:
        moments = ", ".join(f"{x}: {v:.6g} N·m" for x, v in losses.balancing_moments.items())
        out.append(
            f"With mesh efficiency {answer.efficiency:g}: balancing moments {moments}; "
            f"loss {losses.lost_power:.6g} W at these speeds, train efficiency "
            f"{losses.efficiency:.4g}"
        )
    if forces is not None and answer.single:
        out.append(
            f"Balancing moment from the planets' force balance: {forces.balancing_moment:.6g} N·m"
        )
    elif forces is not None:
        moments = ", ".join(f"{x}: {v:.6g} N·m" for x, v in forces.balancing_moments.items())
        out.append(f"Balancing moments from the planets' force balance: {moments}")
    if forces is not None:
        for planet, (fr, ft) in forces.pins.items():
            out.append(
                f"  pin of planet {planet}: radial {fr:.6g} N, tangential {ft:.6g} N "
                f"(|F| = {float(np.hypot(fr, ft)):.6g} N, pressure angle 20° included)"
            )
    if answer.inertia is not None and answer.single:
        out.append(
            f"Moment of inertia reduced to the input: {answer.inertia} ≈ "
            f"{float(answer.inertia):.6g} kg·m²"
        )
    elif answer.inertia is not None:
        out.append(f"Inertia matrix reduced to the inputs ({', '.join(answer.ratios.inputs)}):")
        for row in answer.inertia.tolist():
            out.append("  " + "  ".join(f"{v} ≈ {float(v):.6g}" for v in row) + " kg·m²")
    return out
