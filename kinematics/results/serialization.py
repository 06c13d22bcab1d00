"""Kinematic results as plain data (JSON-ready dicts), SI units and radians, never NaN.

Each ``*_to_dict`` checks its answer with :func:`~structure.validation.check_finite`: a value that
overflowed is a :class:`~structure.errors.NotFiniteError`, not a NaN in the output.

>>> check_finite({"reactions": [{"force": [1.0, float("nan")]}]})
Traceback (most recent call last):
...
structure.errors.NotFiniteError: reactions[0].force[1] is not finite: the result overflowe...

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan, solve_pose
>>> m = parse_edgelist(["driver 1 omega=2", "0 1 R A", "point A 0 0"])
>>> state_to_dict(solve_pose(make_plan(analyze(m))))["links"]["1"]["omega"]
2.0
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from structure.validation import check_finite

if TYPE_CHECKING:  # annotations only: importing the exact solver would import sympy
    from ..kinetostatics.forces import ForceSolution
    from ..solvers.exact import ExactForces, ExactState
    from .state import KinematicState

__all__ = [
    "check_finite",
    "exact_forces_to_dict",
    "exact_to_dict",
    "forces_to_dict",
    "state_to_dict",
]


def _both(x: Any) -> dict[str, Any]:
    """An exact value (a sympy expression) as its text and its float."""
    return {"value": str(x), "float": float(x)}


def exact_forces_to_dict(result: ExactForces) -> dict[str, Any]:
    """Exact reactions and balancing moment, each as ``{"value": "50*sqrt(2)", "float": ...}``."""
    out: dict[str, Any] = {
        "balancing_moment": {k: _both(v) for k, v in result.balancing_moment.items()},
        "reactions": [
            {
                "point": point,
                "links": list(links),
                "kind": kind,
                "force": [_both(f) for f in force],
                **({"couple": _both(couple)} if kind == "P" else {}),
            }
            for point, links, kind, force, couple in result.reactions
        ],
    }
    if result.balancing_force is not None:
        out["balancing_force"] = [_both(f) for f in result.balancing_force]
    check_finite(out)
    return out


def forces_to_dict(result: ForceSolution) -> dict[str, Any]:
    """The JSON form: balancing moment, reactions (point, links, force, magnitude), residual.

    ``inputs`` is the pose (driver inputs from the sketch); a sliding driver's
    balancing force along its slide (N) is in ``balancing_moment`` as before and,
    by its own name, in ``balancing_slide_force``.
    """
    out: dict[str, Any] = {
        "inputs": list(result.inputs),
        "order": list(result.order),
        "balancing_moment": (
            next(iter(result.balancing_moment.values()))
            if len(result.balancing_moment) == 1
            else dict(result.balancing_moment)
        ),
        "reactions": [
            {
                "point": r.point,
                "links": list(r.links),
                "kind": r.kind,
                "force": r.force.tolist(),
                "magnitude": r.magnitude,
                **({"couple": r.couple} if r.kind == "P" else {}),
                **(
                    {"contacts": [c.tolist() for c in r.contacts]} if r.contacts is not None else {}
                ),
            }
            for r in result.reactions
        ],
        "power_residual": result.power_residual,
    }
    if result.balancing_slide_force:
        out["balancing_slide_force"] = dict(result.balancing_slide_force)
    if result.balancing_force is not None:
        out["balancing_force"] = result.balancing_force.tolist()
    if result.friction_loss is not None:
        out["friction_loss"] = result.friction_loss
    if result.pin_forces:
        out["compound_pins"] = {
            point: {link: f.tolist() for link, f in forces.items()}
            for point, forces in result.pin_forces.items()
        }
    check_finite(out)
    return out


def exact_to_dict(state: ExactState) -> dict[str, Any]:
    """Exact values as ``{"value": "50*sqrt(3)", "float": 86.60...}`` pairs."""
    out = {
        "links": {
            name: {"omega": _both(v["omega"]), "epsilon": _both(v["epsilon"])}
            for name, v in state.links.items()
        },
        "points": {
            name: {
                "velocity": [_both(x) for x in v["velocity"]],
                "acceleration": [_both(x) for x in v["acceleration"]],
            }
            for name, v in state.points.items()
        },
    }
    check_finite(out)
    return out


def state_to_dict(state: KinematicState) -> dict[str, Any]:
    """``{"links": {NAME: {"angle", "omega", "epsilon"}}, "points": {NAME: {...}}}``.

    Raises
    ------
    NotFiniteError
        When a value overflowed (the values of the file are too large).
    """
    out = {
        "inputs": list(state.inputs),
        "links": {
            name: {"angle": link.angle, "omega": link.omega, "epsilon": link.epsilon}
            for name, link in state.links.items()
        },
        "points": {
            name: {
                "link": point.link,
                "position": point.position.tolist(),
                "velocity": point.velocity.tolist(),
                "acceleration": point.acceleration.tolist(),
            }
            for name, point in state.points.items()
        },
    }
    check_finite(out)
    return out
