"""A design checked by the group-by-group solvers: its targets met in order, on one branch.

Every answer of the synthesis goes through here before it is returned. The
mechanism (with its marker ``P`` and its targets, each with the driver's
input ``input=`` from the sketch) is swept by :func:`kinematics.solvers.sweep.sweep`
from its first target's input to its last, through every target in order
and with :data:`STEPS_BETWEEN` poses between two targets: the sweep keeps the
sketch's assembly mode by continuity, looks into every step where a dyad's
two modes may meet, and stops at a dead point or where a group does not
close. So:

* a **branch defect** (a dead point, or a stretch that cannot be assembled,
  between two targets) is the sweep's error;
* a **circuit defect** (a target reached only in the other assembly mode) is
  a target the sweep passes at its input but not at its place;
* an **order defect** (targets reached out of sequence) is a run of inputs
  that does not go one way: the inputs must rise (or fall) from target to
  target, within one turn for a crank.

:func:`whole_cycle` sweeps a crank's whole turn (or a rocker's range between
its first and last target) the same way: a returned design must pass it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from structure.errors import MechanismError
from structure.model import Mechanism
from structure.report import analyze

from ..solvers.plan import SolvePlan, make_plan
from ..solvers.sweep import Sweep, sweep

__all__ = ["STEPS_BETWEEN", "Defects", "check_targets", "points_at", "whole_cycle"]

#: poses swept between two targets (the sweep looks finer where a dyad's modes may meet)
STEPS_BETWEEN = 24


@dataclass(frozen=True)
class Defects:
    """What the solvers found along a design's targets.

    ``branch``, ``circuit``, ``order``: the defects found (see the module's
    text), ``reason`` what the solver said; ``distance`` the largest distance
    from ``P`` to its target (metres), ``angle`` the largest error of ``P``'s
    link's rotation between targets (degrees; 0 without angles).
    """

    branch: bool = False
    circuit: bool = False
    order: bool = False
    reason: str = ""
    distance: float = 0.0
    angle: float = 0.0

    @property
    def ok(self) -> bool:
        """Free of defects."""
        return not (self.branch or self.circuit or self.order)

    def names(self) -> list[str]:
        """The defects found, by name."""
        return [n for n in ("circuit", "branch", "order") if getattr(self, n)]


def _plan(mechanism: Mechanism) -> SolvePlan:
    return make_plan(analyze(mechanism))


def _path_inputs(inputs: np.ndarray, steps: int) -> tuple[np.ndarray, np.ndarray]:
    """Rows from each input to the next in ``steps`` steps, and the row of each input."""
    rows = [inputs[:1]]
    where = [0]
    for k in range(1, len(inputs)):
        piece = np.linspace(inputs[k - 1], inputs[k], steps + 1)[1:]
        rows.append(piece)
        where.append(where[-1] + steps)
    return np.concatenate(rows), np.array(where)


def check_targets(mechanism: Mechanism, tolerance: float, *, steps: int = STEPS_BETWEEN) -> Defects:
    """Sweep ``mechanism`` through its targets in order and say what went wrong, if anything.

    ``tolerance`` is the distance (metres) within which ``P`` counts as at a
    target; a target further away at its input is a circuit defect. Targets
    without an input are reached at the input of the closest pose of ``P``
    on the swept path from the first timed target (none: the whole turn).
    """
    targets = mechanism.targets
    if not targets or "P" not in mechanism.points:
        return Defects(reason="no targets or no marker P")
    inputs = np.array([t.input_deg or 0.0 for t in targets], dtype=float)
    steps_ = np.diff(inputs)
    if len(steps_) and not (np.all(steps_ > 0) or np.all(steps_ < 0)):
        return Defects(order=True, reason="the targets' inputs do not go one way")
    if np.ptp(inputs) >= 360.0 + 1e-9:
        return Defects(order=True, reason="the targets' inputs span more than one turn")
    try:
        plan = _plan(mechanism)
        rows, where = _path_inputs(np.radians(inputs), steps)
        result = sweep(plan, rows, rates=False)
    except MechanismError as exc:
        return Defects(branch=True, reason=str(exc))
    return _measured(mechanism, result, where)


def _measured(mechanism: Mechanism, result: Sweep, where: np.ndarray) -> Defects:
    """Distances of ``P`` from its targets at their rows; angle errors of its link."""
    targets = mechanism.targets
    p = result.points["P"]["position"][where]
    xy = np.array([(t.x, t.y) for t in targets])
    distance = float(np.max(np.linalg.norm(p - xy, axis=1)))
    angle = 0.0
    angles = [t.angle_deg for t in targets]
    if all(a is not None for a in angles):
        link = mechanism.points["P"].on
        turned = result.links[link]["angle"][where] if link in result.links else None
        if turned is not None:
            wanted = np.radians(np.array(angles, dtype=float) - angles[0])
            gap = np.angle(np.exp(1j * (turned - turned[0] - wanted)))
            angle = float(np.degrees(np.max(np.abs(gap))))
    return Defects(distance=distance, angle=angle)


def whole_cycle(mechanism: Mechanism, crank: bool, steps: int = 720) -> Sweep:
    """The sweep of a crank's whole turn from the sketch, or of the targets' input range.

    Raises
    ------
    MechanismError
        Where the solvers stop: a group that does not close, a dead point, a
        change of assembly branch.
    """
    plan = _plan(mechanism)
    if crank:
        rows = np.linspace(0.0, 2 * math.pi, steps + 1)
    else:
        inputs = np.radians([t.input_deg or 0.0 for t in mechanism.targets])
        rows = np.linspace(float(inputs.min()), float(inputs.max()), steps + 1)
    return sweep(plan, rows, rates=False)


def points_at(mechanism: Mechanism, inputs: np.ndarray, crank: bool) -> np.ndarray:
    """``P`` as the solvers place it at the driver's ``inputs`` (rad from the sketch).

    The inputs are swept in increasing order (a crank's within one turn), so
    the sketch's assembly mode is carried to each by continuity.

    Raises
    ------
    MechanismError
        Where the solvers stop.
    """
    rows = np.mod(inputs, 2 * math.pi) if crank else np.asarray(inputs, dtype=float)
    # each input once, from the sketch (whose mode it carries): the sweep is given no
    # repeated row (a repeated row at a dyad's low point sends its branch watch into
    # ever finer copies of a step of length zero; see the report of this branch)
    swept, where = np.unique(np.concatenate([[0.0], rows]), return_inverse=True)
    result = sweep(_plan(mechanism), swept, rates=False)
    return result.points["P"]["position"][where[1:]]
