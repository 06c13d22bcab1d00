"""The cycle a report shows: the drivers' cycle, or as much of it as the mechanism allows.

:func:`solve_cycle` sweeps one cycle of the drivers
(:func:`kinematics.solvers.travel.travel`: a turning driver one turn, several
at the ratio of their speeds, a sliding driver its stroke). When the
mechanism cannot make the whole cycle, the cycle is the stretch it reaches
from the sketch, backward and forward to the first pose each way it cannot
take, and the two limits say what stops it there (a dead point, a change
point, a singular pose).

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

from ..solvers.plan import SolvePlan
from ..solvers.solve import solve_poses
from ..solvers.sweep import Sweep, sweep
from ..solvers.travel import Limit, travel
from .phrases import say

__all__ = ["Cycle", "inputs_text", "solve_cycle", "stretch_text"]


@dataclass(frozen=True)
class Cycle:
    """The poses of a report's cycle.

    ``sweep`` holds the kinematics of every pose (:func:`kinematics.solvers.sweep.sweep`),
    ``poses[link]`` each link's pose ``(x, y, θ)`` (shape (poses, 3)); ``sketch``
    is the index of the sketch's pose; ``complete`` is true for a whole cycle (the
    poses loop), false for a stretch, whose ends ``limits`` (backward, forward)
    give, and ``stop`` the errors beyond them.
    """

    sweep: Sweep
    poses: Mapping[str, np.ndarray]
    sketch: int
    complete: bool
    stop: str = ""
    limits: tuple[Limit, Limit] | None = None


def solve_cycle(plan: SolvePlan, steps: int) -> Cycle:
    """The report's cycle of ``steps`` poses, or the stretch the mechanism reaches.

    Raises
    ------
    MechanismError
        The mechanism cannot move away from the sketch at all (a cam, whose profile
        the format does not hold; a driver blocked both ways), or the forces over
        the cycle are indeterminate.
    """
    way = travel(plan, steps)
    rows = way.inputs
    motion = solve_poses(plan, rows)
    poses = {link: np.asarray(q, dtype=float) for link, q in motion.q.items()}
    stop = ""
    if way.limits is not None:
        stop = "; ".join(dict.fromkeys(limit.reason for limit in way.limits if limit.reason))
    return Cycle(sweep(plan, rows), poses, way.sketch, way.complete, stop, way.limits)


def inputs_text(plan: SolvePlan, row: np.ndarray) -> str:
    """The driver inputs of one pose as the page shows them: ``φ1 = 30°`` or ``s1 = 0.01 m``.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan
    >>> plan = make_plan(analyze(parse_edgelist(["driver 1", "0 1 R A", "point A 0 0"])))
    >>> inputs_text(plan, np.array([math.pi / 6]))
    'φ1 = 30°'
    """
    return ", ".join(
        f"φ{d.link} = {math.degrees(float(x)) + 0.0:.4g}°"
        if d.kind == "R"
        else f"s{d.link} = {float(x) + 0.0:.4g} m"
        for d, x in zip(plan.drivers, row, strict=False)
    )


def stretch_text(plan: SolvePlan, cycle: Cycle, lang: str) -> str:
    """What a cycle that is not whole shows: how far the mechanism reaches and what stops it.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan
    >>> m = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
    ...                     "point A 0 0", "point B 0.0855 0.2349", "point C 0.1809 0.2049",
    ...                     "point D 0.4 0"])
    >>> plan = make_plan(analyze(m))
    >>> print(stretch_text(plan, solve_cycle(plan, 8), "en"))  # doctest: +NORMALIZE_WHITESPACE
    Not a whole turn: the mechanism reaches from φ1 = -45.86°, a dead point of group II(2,3),
    to φ1 = 1.789°, a dead point of group II(2,3). The poses shown go from φ1 = -42.88° to
    φ1 = 0°.
    """
    first, last = (inputs_text(plan, row) for row in cycle.sweep.inputs[[0, -1]])
    ends = {}
    for side, limit in zip(("low", "high"), cycle.limits or (), strict=False):
        key = f"limit_{limit.stop.name.lower()}"
        ends[side] = say(lang, key, at=inputs_text(plan, limit.at), group=limit.group)
    turning = any(d.kind == "R" for d in plan.drivers)
    return say(lang, "partial" if turning else "stroke", start=first, end=last, **ends)
