"""Kinematic results as plain data (JSON-ready dicts), SI units and radians.

>>> from structure.edgelist import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.plan import make_plan
>>> from kinematics.solve import solve_pose
>>> m = parse_edgelist(["driver 1 omega=2", "0 1 R A", "point A 0 0"])
>>> state_to_dict(solve_pose(make_plan(analyze(m))))["links"]["1"]["omega"]
2.0
"""

from __future__ import annotations

from typing import Any

from .exact import ExactState
from .solve import KinematicState

__all__ = ["exact_to_dict", "state_to_dict"]


def exact_to_dict(state: ExactState) -> dict[str, Any]:
    """Exact values as ``{"value": "50*sqrt(3)", "float": 86.60...}`` pairs."""

    def both(x: Any) -> dict[str, Any]:
        return {"value": str(x), "float": float(x)}

    return {
        "links": {
            name: {"omega": both(v["omega"]), "epsilon": both(v["epsilon"])}
            for name, v in state.links.items()
        },
        "points": {
            name: {
                "velocity": [both(x) for x in v["velocity"]],
                "acceleration": [both(x) for x in v["acceleration"]],
            }
            for name, v in state.points.items()
        },
    }


def state_to_dict(state: KinematicState) -> dict[str, Any]:
    """``{"links": {NAME: {"angle", "omega", "epsilon"}}, "points": {NAME: {...}}}``."""
    return {
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
