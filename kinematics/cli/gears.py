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
    balancing_moment,
    reduced_inertia,
    speed_ratios,
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
    """What ``assur gears`` found; the optional parts are ``None`` when they do not apply."""

    mechanism: Mechanism
    ratios: TrainRatios
    moment: Any  # a sympy number: the balancing moment by power (one input only)
    inertia: Any  # a sympy number: the inertia reduced to the input (one input, masses)
    forces: TrainForces | None  # planetary force balance (module= on every mesh)
    losses: TrainLosses | None  # with --efficiency
    efficiency: float | None


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
    """Ratios, then what a single input allows: balancing moment, inertia, forces, losses."""
    ratios = speed_ratios(mechanism)
    single_input = len(ratios.inputs) == 1
    moment = balancing_moment(mechanism, ratios) if single_input else None
    inertia = (
        reduced_inertia(mechanism, ratios)
        if single_input and any(x.kind == "mass" for x in mechanism.loads)
        else None
    )
    forces = None
    if moment is not None and all(m.pair.module for m in ratios.meshes):
        try:
            forces = train_forces(mechanism, ratios)
        except MechanismError:
            forces = None  # not a single-carrier planetary train: power only
    losses = None
    if efficiency is not None:
        if forces is None:
            raise MechanismError(
                "mesh losses need a planetary train with module= on every mesh and a moment load"
            )
        losses = train_losses(mechanism, ratios, efficiency)
    return _TrainAnswer(mechanism, ratios, moment, inertia, forces, losses, efficiency)


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
        "speed_ratio": {link: _exact(value) for link, value in ratios.ratios.items()},
    }
    if answer.moment is not None:
        data["balancing_moment"] = _exact(answer.moment)
    if answer.inertia is not None:
        data["reduced_inertia"] = _exact(answer.inertia)
    if answer.losses is not None:
        data["with_losses"] = {
            "mesh_efficiency": answer.efficiency,
            "balancing_moment": answer.losses.balancing_moment,
            "lost_power_per_input_speed": answer.losses.lost_power,
            "efficiency": answer.losses.efficiency,
        }
    if answer.forces is not None:
        data["balancing_moment_by_force_balance"] = answer.forces.balancing_moment
        data["planet_pin_forces"] = {
            planet: {"radial": f[0], "tangential": f[1], "magnitude": float(np.hypot(*f))}
            for planet, f in answer.forces.pins.items()
        }
        data["tooth_forces"] = {
            mechanism.pair(pid).label: value for pid, value in answer.forces.tooth.items()
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
    out.append("Speed ratios to the input (ω_link / ω_input):")
    for link, value in ratios.ratios.items():
        out.append(f"  {link}: {value} ≈ {float(value):.6g}")
    moment, losses, forces = answer.moment, answer.losses, answer.forces
    if moment is not None:
        out.append(f"Balancing moment on the input (by power): {moment} ≈ {float(moment):.6g} N·m")
    if losses is not None:
        out.append(
            f"With mesh efficiency {answer.efficiency:g}: balancing moment "
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
    if answer.inertia is not None:
        out.append(
            f"Moment of inertia reduced to the input: {answer.inertia} ≈ "
            f"{float(answer.inertia):.6g} kg·m²"
        )
    return out
