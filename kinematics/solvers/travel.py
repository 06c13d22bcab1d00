"""How far the drivers take a mechanism from its sketch: its cycle, or the stretch it can reach.

The drivers move together along a line of inputs, ``inputs = t·rates``
(:func:`driver_rates`): at the ratio of the speeds the file gives them
(``omega=``, ``v=`` on each driver line) when it gives every one, else each
turning driver one turn alike. A turning driver's cycle is a whole number of
turns (:func:`cycle_span`): the poses come back. A sliding driver has no
cycle: it travels its stroke, as far as the mechanism lets it go each way
from the sketch.

:func:`cycle_inputs` gives the inputs of one cycle (a sliding driver's
stroke); :func:`travel` solves them and, when the mechanism cannot make the
whole cycle, gives the stretch of it the mechanism reaches from the sketch,
each end with what stops it there (:class:`Limit`): a dead point, where a
group can be assembled no further; a change point, where two assembly modes
of a group meet and the linkage may go on in either; another singular pose;
or nothing within the search, for a slider the mechanism does not stop. A
driver that cannot move at all from the sketch is a :class:`TravelError`.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 3", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 P C angle=0",
...                     "point A 0 0", "point B 0 0.1", "point C 0.1732 0"])
>>> way = travel(make_plan(analyze(m)), 40)       # the slider block drives the crank
>>> way.complete, [limit.stop.value for limit in way.limits]
(False, ['dead point', 'dead point'])
>>> [round(float(limit.at[0]), 4) for limit in way.limits]   # |AC| from 0.2 − 0.1 to 0.2 + 0.1
[-0.0732, 0.1268]
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum
from fractions import Fraction

import numpy as np

from ..errors import AssemblyError, BranchChangeError, SingularPoseError, TravelError
from .memory import check_poses
from .plan import SolvePlan
from .solve import solve_poses

__all__ = [
    "Limit",
    "Stop",
    "Travel",
    "cycle_inputs",
    "cycle_span",
    "driver_rates",
    "reach",
    "travel",
]

#: a sliding driver's stroke is looked for up to this many sketch sizes each way; a slider
#: that goes that far unhindered travels :data:`FREE_TRAVEL` sketch sizes each way
SEARCH = 4.0
FREE_TRAVEL = 1.0
#: the most turns of its fastest turning driver a cycle takes (a ratio of speeds that needs
#: more, or that no fraction with a denominator up to this gives, is one turn of the slowest,
#: at most this many of the fastest)
MOST_TURNS = 12
_BISECTIONS = 24  # halvings of the step in which a limit lies: 6e-8 of it
_COARSE = 24  # poses of the first look along a search, at least
_COARSE_MOST = 1024  # and at most


class Stop(Enum):
    """What ends a stretch of travel."""

    DEAD_POINT = "dead point"  # a group cannot be assembled any further
    CHANGE_POINT = "change point"  # two assembly modes of a group meet
    SINGULAR = "singular pose"  # a group's position is indeterminate there
    FREE = "free"  # nothing within the search: a slider the mechanism does not stop


@dataclass(frozen=True)
class Limit:
    """One end of a stretch: the inputs of the last pose reached, what stops it there.

    ``group`` is the group that stops it (empty for a free slide), ``reason``
    the error a little beyond.
    """

    at: np.ndarray
    stop: Stop
    reason: str
    group: str = ""


@dataclass(frozen=True)
class Travel:
    """The poses a mechanism goes through from its sketch.

    ``inputs`` (poses, drivers) in increasing order along the drivers' line,
    ``sketch`` the row of the sketch (all inputs 0); ``complete`` is true for
    a whole cycle (the poses come back to the first), false for a stretch,
    whose two ends (backward, forward) ``limits`` gives.
    """

    inputs: np.ndarray
    sketch: int
    complete: bool
    limits: tuple[Limit, Limit] | None = None


def driver_rates(plan: SolvePlan) -> np.ndarray:
    """Each driver's input per unit of the path's parameter: how the drivers move together.

    With every driver's speed in the file (and one of them not 0), the speeds
    divided by the largest turning one's (by the largest sliding one's when
    none turns), signed so that the first moving driver goes forward; else 1
    for each turning driver, and for a sliding one 1 when it is the only
    driver, 0 (held at the sketch) when there are others.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan
    >>> m = parse_edgelist(["driver 1 omega=10", "driver 4 omega=-5", "0 1 R A", "1 2 R B",
    ...                     "2 3 R C", "3 4 R D", "4 0 R E", "point A 0 0", "point B 0 1",
    ...                     "point C 1 2", "point D 2 1", "point E 2 0"])
    >>> driver_rates(make_plan(analyze(m))).tolist()
    [1.0, -0.5]
    """
    speeds = np.array([d.speed for d in plan.drivers], dtype=float)
    turning = np.array([d.kind == "R" for d in plan.drivers])
    if all(d.speed_given for d in plan.drivers) and np.any(speeds != 0.0):
        pool = speeds[turning] if np.any(speeds[turning] != 0.0) else speeds
        rates = speeds / float(np.max(np.abs(pool)))
        return rates * math.copysign(1.0, rates[np.flatnonzero(rates)[0]])
    if len(plan.drivers) == 1:
        return np.ones(1)
    return np.where(turning, 1.0, 0.0)


def cycle_span(plan: SolvePlan, rates: np.ndarray) -> float | None:
    """The parameter's span of one cycle: each turning driver a whole number of turns.

    None when no turning driver moves (a slider has a stroke, not a cycle).
    """
    moving = [abs(r) for d, r in zip(plan.drivers, rates, strict=True) if d.kind == "R" and r]
    if not moving:
        return None
    fractions = [Fraction(r).limit_denominator(MOST_TURNS) for r in moving]
    exact = all(abs(float(f) - r) <= 1e-9 * r for f, r in zip(fractions, moving, strict=True))
    turns = math.lcm(*(f.denominator for f in fractions)) if exact else MOST_TURNS + 1
    if turns > MOST_TURNS:  # one turn of the slowest, at most MOST_TURNS of the fastest
        turns = min(math.ceil(1.0 / min(moving)), MOST_TURNS)
    return 2.0 * math.pi * turns


def cycle_inputs(plan: SolvePlan, steps: int) -> np.ndarray:
    """The inputs (steps, drivers) of one cycle, from the sketch (its end left out).

    A sliding driver alone travels its stroke instead (:func:`travel`, which
    solves the mechanism to find it), its ends left a little short of the
    dead points, where the mechanism's speeds are infinite.

    Raises
    ------
    TravelError
        A sliding driver that cannot move from the sketch.
    """
    rates = driver_rates(plan)
    span = cycle_span(plan, rates)
    if span is None:
        return travel(plan, steps).inputs
    return np.linspace(0.0, span, steps, endpoint=False)[:, None] * rates[None, :] + 0.0


def travel(plan: SolvePlan, steps: int) -> Travel:
    """The cycle of ``steps`` poses when the mechanism makes it, else the stretch it reaches.

    The stretch runs from the sketch backward and forward along the drivers'
    line to the first pose each way that cannot be solved (:func:`reach`),
    at most one cycle each way, in ``steps`` poses at equal steps, the first
    and last half a step short of the limits, and the one nearest the sketch
    moved onto it.

    Raises
    ------
    TravelError
        The drivers cannot move from the sketch either way.
    SweepSizeError
        ``steps`` poses would not fit in the memory a sweep may take.
    MechanismError
        The sketch itself cannot be solved (or a cam's profile is missing).
    """
    check_poses(plan, steps, rates=True)
    rates = driver_rates(plan)
    span = cycle_span(plan, rates)
    if span is not None:
        rows = np.linspace(0.0, span, steps, endpoint=False)[:, None] * rates[None, :] + 0.0
        if _failure(plan, rows) is None:
            return Travel(rows, 0, True)
        search = span
    else:
        search = SEARCH * plan.length * plan.unit / float(np.max(np.abs(rates)))
    back, ahead = reach(plan, rates, -search, steps), reach(plan, rates, search, steps)
    limits = tuple(_free_travel(plan, rates, limit) for limit in (back, ahead))
    low, high = (_parameter(limit.at, rates) for limit in limits)
    if high - low <= 0.0:
        raise TravelError(_nowhere(plan, limits))
    t = low + (np.arange(steps) + 0.5) * ((high - low) / steps)
    sketch = int(np.argmin(np.abs(t)))
    t[sketch] = 0.0  # the sketch among them (its neighbours half a step to one and a half away)
    rows = t[:, None] * rates[None, :] + 0.0  # (no −0 for a driver turning back)
    return Travel(rows, sketch, False, limits)  # type: ignore[arg-type]


def reach(plan: SolvePlan, rates: np.ndarray, span: float, steps: int = _COARSE) -> Limit:
    """How far along ``t·rates`` (t from 0 to ``span``, either sign) the mechanism goes.

    The path is looked along in ``steps`` poses (from 24 to 1024);
    the first pose that cannot be solved is closed in on by halving, from
    the last one that can, to within 6e-8 of a step. What stops it there is
    told by the error a little further on (:class:`Stop`).
    """
    n = min(max(steps, _COARSE), _COARSE_MOST)
    t = np.linspace(0.0, span, n + 1)[1:]
    error = _failure(plan, t[:, None] * rates[None, :])
    if error is None:
        return Limit(span * rates, Stop.FREE, "")
    k = _first_failing(t, rates, error)
    good, bad = (t[k - 1] if k else 0.0), float(t[k])
    if k and _failure(plan, _path(good, rates)) is not None:
        good = 0.0
    if good == 0.0:  # blocked right at the sketch? then no halving is needed
        nudge = bad * 2.0**-_BISECTIONS
        failed = _failure(plan, _path(nudge, rates))
        if failed is not None:
            return Limit(0.0 * rates, _stop_of(failed), str(failed), getattr(failed, "group", ""))
    for _ in range(_BISECTIONS):
        middle = 0.5 * (good + bad)
        if middle in (good, bad):
            break
        failed = _failure(plan, _path(middle, rates))
        if failed is None:
            good = middle
        else:
            bad, error = middle, failed
    beyond = _failure(plan, _path(good + 1e-6 * (span / n), rates))
    if beyond is not None:
        error = beyond
    return Limit(good * rates, _stop_of(error), str(error), getattr(error, "group", ""))


def _path(t: float, rates: np.ndarray) -> np.ndarray:
    """The two rows from the sketch to ``t·rates`` (the solve follows the way between)."""
    return np.vstack([np.zeros(len(rates)), t * rates])


def _failure(plan: SolvePlan, rows: np.ndarray) -> Exception | None:
    """The error of solving the path of ``rows`` from the sketch, None when it solves."""
    try:
        solve_poses(plan, rows)
    except (AssemblyError, SingularPoseError) as exc:
        return exc
    return None


def _first_failing(t: np.ndarray, rates: np.ndarray, error: Exception) -> int:
    """The first row at or beyond the pose ``error`` names (the first row when it names none)."""
    pose = getattr(error, "pose", None)
    if pose is None:
        return 0
    where = abs(_parameter(np.asarray(pose, dtype=float), rates))
    return min(int(np.searchsorted(np.abs(t), where * (1.0 - 1e-12))), len(t) - 1)


def _parameter(inputs: np.ndarray, rates: np.ndarray) -> float:
    """The parameter t of the inputs ``t·rates`` (least squares over the moving drivers)."""
    return float(inputs @ rates / (rates @ rates))


def _stop_of(error: Exception) -> Stop:
    if isinstance(error, BranchChangeError):
        return Stop.CHANGE_POINT
    if isinstance(error, AssemblyError):
        return Stop.DEAD_POINT
    if isinstance(error, SingularPoseError) and not error.dead_centre:
        return Stop.SINGULAR
    return Stop.DEAD_POINT  # a dead centre that cannot be passed: the end of the way


def _free_travel(plan: SolvePlan, rates: np.ndarray, limit: Limit) -> Limit:
    """A limit that nothing stops moved in to :data:`FREE_TRAVEL` sketch sizes (a free slider)."""
    if limit.stop is not Stop.FREE or cycle_span(plan, rates) is not None:
        return limit
    size = FREE_TRAVEL * plan.length * plan.unit / float(np.max(np.abs(rates)))
    t = math.copysign(size, _parameter(limit.at, rates))
    reason = f"the mechanism does not stop the slide within {SEARCH:g} sketch sizes"
    return Limit(t * rates, Stop.FREE, reason)


def _nowhere(plan: SolvePlan, limits) -> str:
    """The message for drivers that cannot move from the sketch either way."""
    who = ", ".join(d.link for d in plan.drivers)
    why = "; ".join(dict.fromkeys(limit.reason for limit in limits if limit.reason))
    return (
        f"driver {who} cannot move from the sketch either way, so there is nothing to sweep: {why}"
    )
