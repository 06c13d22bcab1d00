"""The cycle a report shows: a turn of the driver(s), or as much of it as the mechanism allows.

:func:`solve_cycle` sweeps one turn of each rotating driver (a sliding one
moves to and fro, as in :func:`kinematics.figures.animation.turn_inputs`).
When a pose cannot be assembled or is a dead centre, the cycle is the
stretch the mechanism can reach from the sketch: forward up to the first pose
that fails and backward likewise, joined into one run of poses, with the
error that stopped it kept to say so.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0.1 0", "point C 0.3 0.3", "point D 0.4 0"])
>>> cycle = solve_cycle(make_plan(analyze(m)), 12)
>>> cycle.complete, cycle.sketch, cycle.poses["3"].shape
(True, 0, (12, 3))
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError, SingularPoseError
from ..figures.animation import turn_inputs
from ..solvers.plan import SolvePlan
from ..solvers.solve import solve_poses
from ..solvers.sweep import Sweep, sweep

__all__ = ["Cycle", "inputs_text", "solve_cycle"]


@dataclass(frozen=True)
class Cycle:
    """The poses of a report's cycle.

    ``sweep`` holds the kinematics of every pose (:func:`kinematics.solvers.sweep.sweep`),
    ``poses[link]`` each link's pose ``(x, y, θ)`` (shape (poses, 3)); ``sketch``
    is the index of the sketch's pose; ``complete`` is true for a whole turn (the
    poses loop), false for a stretch, which ``stop`` (the error at its end) explains.
    """

    sweep: Sweep
    poses: Mapping[str, np.ndarray]
    sketch: int
    complete: bool
    stop: str = ""


def _reachable(plan: SolvePlan, rows: np.ndarray) -> tuple[int, str]:
    """How many of ``rows`` (from the first) solve in one run, and the error after them."""
    end, stop = len(rows), ""
    while end > 1:
        try:
            solve_poses(plan, rows[:end])
        except (AssemblyError, SingularPoseError) as exc:
            stop = stop or str(exc)
            failed = np.asarray(exc.pose if exc.pose is not None else rows[end - 1], dtype=float)
            apart = (rows[:end] - failed.reshape(1, -1)) / plan.driver_scale  # radians, sizes
            nearest = int(np.argmin(np.linalg.norm(apart, axis=1)))
            end = max(1, min(end - 1, nearest))
            continue
        return end, stop
    return 1, stop


def solve_cycle(plan: SolvePlan, steps: int) -> Cycle:
    """The report's cycle of ``steps`` poses per turn, or the stretch the mechanism reaches.

    Raises
    ------
    MechanismError
        The mechanism cannot move away from the sketch at all (a cam, whose profile
        the format does not hold), or the forces over the cycle are indeterminate.
    """
    forward = turn_inputs(plan, steps)
    ahead, stop = _reachable(plan, forward)
    if ahead == len(forward):
        rows, sketch, complete = forward, 0, True
    else:
        behind, _ = _reachable(plan, -forward)
        rows = np.concatenate([-forward[1:behind][::-1], forward[:ahead]])
        sketch, complete = behind - 1, False
    motion = solve_poses(plan, rows)
    poses = {link: np.asarray(q, dtype=float) for link, q in motion.q.items()}
    return Cycle(sweep(plan, rows), poses, sketch, complete, stop)


def inputs_text(plan: SolvePlan, row: np.ndarray) -> str:
    """The driver inputs of one pose as the page shows them: ``φ1 = 30°`` or ``s1 = 0.01 m``.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan
    >>> plan = make_plan(analyze(parse_edgelist(["driver 1", "0 1 R A", "point A 0 0"])))
    >>> inputs_text(plan, np.array([math.pi / 6]))
    'φ1 = 30°'
    """
    return ", ".join(
        f"φ{d.link} = {math.degrees(float(x)):.4g}°"
        if d.kind == "R"
        else f"s{d.link} = {float(x):.4g} m"
        for d, x in zip(plan.drivers, row, strict=False)
    )
