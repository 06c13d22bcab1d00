"""Continuation checks over a sweep: no silent change of assembly branch, and where a group stops.

A dyad solved in closed form keeps the sketch's assembly mode by the sign of a
square root at every pose, each on its own; nothing there ties one pose to the
next. Between two poses far apart the linkage may go through a change point
(the dyad's two circle intersections meet, as a parallelogram's do with all
links in line) or over a stretch where it cannot be assembled at all, and the
fixed sign then lands in the other mode without a word. The dyads note the
steps where their joint moves as far as the other mode lies
(:func:`kinematics.solvers.dyads.frame_dyad`); :func:`confirm_branches` looks into
each such step with finer steps, until it is clear (the same mode all along)
or the change point is found, where it raises :class:`BranchChangeError`.

A group that cannot be assembled over part of a sweep is reported by
:func:`unassembled_range`: the whole stretch of inputs and its ends, the dead
points, in the units of the files (degrees for a turning driver).

The solves are handed in as ``solve(rows, watch, groups)``: positions of the
plan at the driver inputs ``rows`` (N, drivers), appending watched steps to
``watch``, solving the groups up to the last of ``groups`` (all if None).

>>> import dataclasses

import numpy as np
>>> subdivided(np.array([[0.0]]), np.array([[0.8]]), 4).ravel().round(6).tolist()
[0.0, 0.2, 0.4, 0.6, 0.8]
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from ..errors import AssemblyError, BranchChangeError, SingularPoseError, inputs_text
from .dyads import NOT_CLOSED
from .newton import CONTINUATION_STEP
from .paths import Watch
from .plan import SolvePlan

__all__ = [
    "change_point",
    "confirm_branches",
    "either_mode",
    "is_change_point",
    "split_at",
    "subdivided",
    "unassembled_range",
]

Solver = Callable[..., object]

_SUBSTEPS = 8  # finer steps per watched step, at each level
_LEVELS = 16  # 8^16: far below the resolution of the inputs
_LEVEL_STEPS = 256  # watched steps looked into at once
_BUDGET = 2**20  # rows solved in all by one look into the watched steps
_BOUNDARY_SPLITS = 64  # rows per round when closing in on a dead point
_BOUNDARY_ROUNDS = 7  # 64^7 ≈ 4e12

#: change points this close (rad, or sketch sizes) are one: a dead centre is found where the
#: transmission angle's sine falls to DEAD_CENTRE (1e-6), about that far from the point itself
_SAME_POINT = 1e-5

#: what the error says happens at a change point
MODES_MEET = (
    "its two assembly modes meet there (its joint comes into line with its outer pins: a "
    "change point of the linkage), and the linkage may go on in either; the sweep stops "
    "rather than pick one (sweep up to that input, or solve each mode with inputs of its own)"
)


def subdivided(starts: np.ndarray, ends: np.ndarray, pieces: int = _SUBSTEPS) -> np.ndarray:
    """Rows from each start to its end in ``pieces`` equal steps, ends included, one after another.

    Each of the m steps gives ``pieces + 1`` rows: shape (m·(pieces + 1), drivers).
    """
    fractions = np.linspace(0.0, 1.0, pieces + 1)[None, :, None]
    rows = starts[:, None, :] + (ends - starts)[:, None, :] * fractions
    return rows.reshape(-1, starts.shape[1])


def change_point(plan: SolvePlan, group: str, inputs: np.ndarray) -> BranchChangeError:
    """The error for a change point of ``group`` at the driver ``inputs``."""
    return BranchChangeError.at(group, inputs, MODES_MEET, plan.driver_kinds)


def is_change_point(inputs: np.ndarray, k: int) -> bool:
    """Whether row ``k`` is inside the rows, the inputs going on the same way through it."""
    if not 0 < k < len(inputs) - 1:
        return False
    before, after = inputs[k] - inputs[k - 1], inputs[k + 1] - inputs[k]
    return float(before @ after) > 0.0


def confirm_branches(plan: SolvePlan, inputs: np.ndarray, watch: list, solve: Solver) -> None:
    """Look into the watched steps with finer ones; raise at a change of assembly mode.

    ``watch`` holds ``(group label, step indices)`` from the solve of ``inputs``
    (step k goes from row k to row k + 1). Each level solves the watched
    steps cut into :data:`_SUBSTEPS` pieces, as one path whose pieces are
    joined by breaks (:class:`~kinematics.solvers.paths.Watch`), and keeps the
    pieces where the dyads still see a dip. At most :data:`_LEVEL_STEPS` steps
    are looked into at once (the first along the path; the others wait their
    turn), and at most :data:`_BUDGET` rows are solved in all: samples that
    keep dipping beyond that (a group lying along its change point, within
    rounding) stop the sweep at the first of them, as a change point.

    Raises
    ------
    BranchChangeError
        At the change point, where the group's two assembly modes meet.
    SingularPoseError
        At a singular pose found on the way (outer pins that coincide).
    AssemblyError
        A stretch between two poses cannot be assembled (its range is named).
    """
    steps = np.array(sorted({int(k) for _, ks in watch for k in ks}))
    groups = {g for g, _ in watch}
    pending = [(inputs[steps], inputs[steps + 1], watch[0][0], 0)]
    solved = 0
    while pending:
        starts, ends, label, level = pending.pop(0)
        if len(starts) > _LEVEL_STEPS:  # the first ones now, the others after them
            pending.insert(0, (starts[_LEVEL_STEPS:], ends[_LEVEL_STEPS:], label, level))
            starts, ends = starts[:_LEVEL_STEPS], ends[:_LEVEL_STEPS]
        if level == _LEVELS or solved > _BUDGET:
            raise change_point(plan, label, (starts[0] + ends[0]) / 2)
        rows = subdivided(starts, ends)
        solved += len(rows)
        found = Watch(np.arange(_SUBSTEPS, len(rows) - 1, _SUBSTEPS + 1))
        try:
            solve(rows, found, groups)
        except SingularPoseError as exc:
            if getattr(exc, "dead_centre", False) and exc.indices is not None:
                k = int(exc.indices[0])
                raise change_point(plan, exc.group, rows[k]) from None
            raise
        except AssemblyError as exc:
            if exc.indices is None or type(exc) is not AssemblyError:
                raise
            piece = int(exc.indices[0]) // (_SUBSTEPS + 1)
            path = rows[piece * (_SUBSTEPS + 1) : (piece + 1) * (_SUBSTEPS + 1)]
            raise _range_of(plan, path, exc.group, solve) from None
        inner = sorted(
            {int(k) for _, ks in found for k in ks if int(k) % (_SUBSTEPS + 1) != _SUBSTEPS}
        )
        if inner:
            first = next(g for g, ks in found if int(inner[0]) in {int(k) for k in ks})
            index = np.array(inner)
            pending.insert(0, (rows[index], rows[index + 1], first, level + 1))


def _range_of(plan: SolvePlan, path: np.ndarray, group: str, solve: Solver) -> AssemblyError:
    """The range error of ``group`` along ``path``, solved again on its own."""
    try:
        solve(path, None, {group})
    except AssemblyError as exc:
        if exc.indices is not None and exc.group == group:
            return unassembled_range(plan, path, exc, solve)
        return exc
    return AssemblyError.at(group, path[-1], NOT_CLOSED, plan.driver_kinds)


def _run_end(indices: np.ndarray) -> int:
    """The last index of the run of consecutive indices that starts at ``indices[0]``."""
    gaps = np.flatnonzero(np.diff(indices) != 1)
    return int(indices[gaps[0]]) if len(gaps) else int(indices[-1])


def _dead_point(group: str, good: np.ndarray, bad: np.ndarray, solve: Solver) -> np.ndarray:
    """The last input from ``good`` towards ``bad`` at which ``group`` still assembles."""
    for _ in range(_BOUNDARY_ROUNDS):
        rows = good + (bad - good) * np.linspace(0.0, 1.0, _BOUNDARY_SPLITS + 1)[:, None]
        try:
            solve(rows, None, {group})
        except SingularPoseError as exc:  # a row right at the dead point
            if exc.group == group and exc.indices is not None:
                return rows[int(exc.indices[0])]
            return good
        except AssemblyError as exc:
            if exc.group != group or exc.indices is None or int(exc.indices[0]) == 0:
                return good
            j = int(exc.indices[0])
            good, bad = rows[j - 1], rows[j]
            continue
        return good
    return good


def unassembled_range(
    plan: SolvePlan, inputs: np.ndarray, error: AssemblyError, solve: Solver
) -> AssemblyError:
    """The error naming the whole stretch of ``inputs`` where a group cannot be assembled.

    ``error`` is the closed form's, with ``indices`` the rows that cannot be
    assembled; the first run of them is the stretch. Its ends are closed in on
    from the poses on either side, to the dead points where the group just
    assembles.
    """
    bad = np.asarray(error.indices)
    first, last = int(bad[0]), _run_end(bad)
    kinds = plan.driver_kinds
    low = _dead_point(error.group, inputs[first - 1], inputs[first], solve) if first else None
    high = (
        _dead_point(error.group, inputs[last + 1], inputs[last], solve)
        if last < len(inputs) - 1
        else None
    )

    def text(x: np.ndarray) -> str:
        return inputs_text(x, kinds) if len(kinds) == 1 else f"({inputs_text(x, kinds)})"

    if low is not None and high is not None:
        where = f"between inputs {text(low)} and {text(high)}, the dead points at its ends"
    elif low is not None:
        where = f"from input {text(low)}, a dead point, to the last input {text(inputs[last])}"
    elif high is not None:
        where = f"from the first input {text(inputs[first])} to input {text(high)}, a dead point"
    else:
        where = f"at any input from {text(inputs[first])} to {text(inputs[last])}"
    out = AssemblyError(
        f"group {error.group} cannot be assembled {where}: {NOT_CLOSED}",
        error.group,
        error.pose,
        error.indices,
    )
    return out


def either_mode(plan: SolvePlan, group: str) -> list[SolvePlan]:
    """``plan`` with the dyad ``group`` in its assembly mode, and in the other one.

    Empty when ``group`` is not a dyad the closed forms assemble by mode (a
    change point of another group cannot be gone past by choosing its mode).
    """
    dyads = {s.label for s in plan.steps if s.group is not None and s.group.kind is not None}
    if group not in dyads:
        return []
    return [plan, dataclasses.replace(plan, flip=plan.flip ^ {group})]


def split_at(
    plan: SolvePlan, inputs: np.ndarray, origin: np.ndarray | None, error: BranchChangeError
) -> tuple[int, np.ndarray, np.ndarray] | None:
    """Where the path of ``inputs`` (from ``origin``, else the sketch) meets a change point.

    Returns ``(k, point, ahead)``: the change point lies on the step into row
    ``k`` (from row k − 1, or from the origin for k = 0); ``point`` is it (the
    pose ``error`` names), and
    ``ahead`` a few poses from it toward row k, no farther than one
    continuation step, to try the ways on. None when the error names no pose
    on the path, or a row lies on the change point itself.
    """
    if error.pose is None:
        return None
    point = np.asarray(error.pose, dtype=float)
    scale = plan.driver_scale
    start = np.zeros(inputs.shape[1]) if origin is None else np.asarray(origin, dtype=float)
    ends = inputs / scale
    begins = np.vstack([start[None, :] / scale, ends[:-1]])
    step = ends - begins
    length2 = np.einsum("ij,ij->i", step, step)
    along = np.einsum("ij,ij->i", point / scale - begins, step) / np.where(length2 > 0, length2, 1)
    off = point / scale - (begins + np.clip(along, 0.0, 1.0)[:, None] * step)
    near = np.sqrt(np.einsum("ij,ij->i", off, off)) <= 1e-9 * (1.0 + np.sqrt(length2))
    on = near & (length2 > 0)
    if origin is not None:  # the origin is a change point itself: one found there is that one
        on[0] &= along[0] * np.sqrt(length2[0]) > _SAME_POINT
    if not on.any():
        return None
    k = int(np.argmax(on))
    if not 1e-12 < along[k] < 1.0 - 1e-12:  # a row (or the origin) on the change point itself
        return None
    toward = inputs[k] - point
    span = float(np.max(np.abs(toward) / scale))
    if span <= 0.0:
        return None
    reach = min(1.0, CONTINUATION_STEP / span)
    ahead = point + np.array([0.25, 0.5, 0.75, 1.0])[:, None] * reach * toward
    return k, point, ahead
