"""What a report holds: every answer of the command line for one mechanism, or why it has none.

:func:`gather` runs the structural analysis and, as far as the file allows,
the kinematics and forces at the sketch pose, the cycle and the gear train.
The numbers the page shows are the very dicts the command line prints with
``--json`` (:func:`structure.report.report_to_dict`,
:func:`kinematics.results.serialization.state_to_dict`,
:func:`kinematics.results.serialization.forces_to_dict`), so the two agree by
construction. A part that does not apply is a :class:`Note` instead: no
coordinates, no loads, no gears, or the error that stopped it.

>>> from structure import parse_edgelist
>>> c = gather(parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]))
>>> c.structure["W"], c.notes["pose"].key, c.notes["gears"].key
(1, 'no_geometry', 'no_gears')
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, NamedTuple

from structure.errors import MechanismError
from structure.model import Mechanism
from structure.readwrite.reports import report_to_dict
from structure.report import StructuralReport, analyze

from ..kinetostatics.forces import ForceSolution, solve_forces
from ..results.serialization import forces_to_dict, state_to_dict
from ..results.state import KinematicState
from ..solvers.plan import SolvePlan, make_plan
from ..solvers.solve import solve_pose
from .cycle import Cycle, solve_cycle
from .gearing import TrainSummary, train_summary
from .markup import note
from .phrases import say

__all__ = ["APPLIED_LOADS", "Note", "ReportContents", "gather", "part_note"]

#: the load statements that make a force analysis worth showing (gravity alone moves no mass)
APPLIED_LOADS = ("force", "moment", "mass")


class Note(NamedTuple):
    """Why a part of the report does not apply: a phrase key and, for an error, its message."""

    key: str
    reason: str = ""


@dataclass(frozen=True)
class ReportContents:
    """The answers of one report; a part that does not apply is ``None`` with its note.

    ``notes`` maps ``"pose"`` (kinematics at the sketch), ``"forces"``, ``"cycle"``
    and ``"gears"`` to the :class:`Note` that replaces the part.
    """

    mechanism: Mechanism
    report: StructuralReport
    structure: Mapping[str, Any]
    plan: SolvePlan | None = None
    state: KinematicState | None = None
    kinematics: Mapping[str, Any] | None = None
    forces: ForceSolution | None = None
    forces_dict: Mapping[str, Any] | None = None
    cycle: Cycle | None = None
    train: TrainSummary | None = None
    notes: Mapping[str, Note] = field(default_factory=dict)


def _pose(report: StructuralReport, notes: dict[str, Note]) -> tuple[Any, Any]:
    """The plan and the solved sketch pose, or ``(None, None)`` with the pose's note."""
    if not report.mechanism.points:
        notes["pose"] = Note("no_geometry")
        return None, None
    try:
        plan = make_plan(report)
        return plan, solve_pose(plan)
    except MechanismError as exc:
        notes["pose"] = Note("unsolved", str(exc))
        return None, None


def _forces(plan: SolvePlan, notes: dict[str, Note]) -> ForceSolution | None:
    """The reactions at the sketch pose, or ``None`` with the note: no loads, or the error."""
    if not any(x.kind in APPLIED_LOADS for x in plan.mechanism.loads):
        notes["forces"] = Note("no_loads")
        return None
    try:
        return solve_forces(plan)
    except MechanismError as exc:
        notes["forces"] = Note("unsolved", str(exc))
        return None


def _cycle(plan: SolvePlan, steps: int, notes: dict[str, Note]) -> Cycle | None:
    """The cycle's poses, or ``None`` with the error that keeps the mechanism at the sketch."""
    try:
        return solve_cycle(plan, steps)
    except MechanismError as exc:
        notes["cycle"] = Note("unsolved", str(exc))
        return None


def _train(mechanism: Mechanism, notes: dict[str, Note]) -> TrainSummary | None:
    """The gear train's answers, or ``None`` with the note: no gears, or the error."""
    try:
        summary = train_summary(mechanism)
    except MechanismError as exc:
        notes["gears"] = Note("unsolved", str(exc))
        return None
    if summary is None:
        notes["gears"] = Note("no_gears")
    return summary


def gather(mechanism: Mechanism, steps: int = 120) -> ReportContents:
    """Every answer the report shows for ``mechanism``, with ``steps`` poses per turn.

    Raises
    ------
    MechanismError
        The structural analysis fails (a mobility error, links left undetermined):
        then there is nothing to report, as ``assur classify`` says.
    """
    report = analyze(mechanism)
    notes: dict[str, Note] = {}
    plan, state = _pose(report, notes)
    forces = cycle = None
    if plan is None:
        notes["forces"] = notes["cycle"] = notes["pose"]
    else:
        forces = _forces(plan, notes)
        cycle = _cycle(plan, steps, notes)
    return ReportContents(
        mechanism=mechanism,
        report=report,
        structure=report_to_dict(report),
        plan=plan,
        state=state,
        kinematics=None if state is None else state_to_dict(state),
        forces=forces,
        forces_dict=None if forces is None else forces_to_dict(forces),
        cycle=cycle,
        train=_train(mechanism, notes),
        notes=notes,
    )


def part_note(contents: ReportContents, part: str, lang: str) -> str:
    """The one-line note (``<p class="note" data-note="…">``) that stands for ``part``."""
    found = contents.notes[part]
    return note(say(lang, found.key, reason=found.reason), found.key)
