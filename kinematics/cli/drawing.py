"""The figures the command line saves (imports matplotlib: load it through ``load_drawing``).

Each ``save_*`` function draws one sheet and writes it to the path; a path
matplotlib cannot write is a :class:`MechanismError`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from structure.errors import MechanismError
from structure.limits import check_size
from structure.readwrite.atomic import atomic_path

from .. import figures
from ..figures.animation import animate, there_and_back, turn_inputs
from ..figures.cam import cam_sheet
from ..figures.dynamics import balance_sheet, dynamics_sheet
from ..figures.synthesis import structural_error_figure, target_figure
from ..solvers.plan import make_plan
from ..solvers.solve import solve_pose
from ..solvers.sweep import BYTES_PER_POSE_ITEM

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from structure.report import StructuralReport

    from ..cams.design import CamDesign
    from ..dynamics.analysis import MachineDynamics
    from ..dynamics.balancing import Balanced
    from ..kinetostatics.forces import ForceSolution
    from ..solvers.plan import SolvePlan
    from ..solvers.solve import KinematicState
    from ..solvers.sweep import Sweep

__all__ = [
    "FRAME_BYTES",
    "animate",
    "check_frames",
    "save_balance_sheet",
    "save_cam_sheet",
    "save_dynamics_sheet",
    "save_forces_sheet",
    "save_kinematics_sheet",
    "save_mechanism_drawing",
    "save_structural_error",
    "save_structure_sheet",
    "save_sweep_figure",
    "save_target_figure",
    "there_and_back",
    "turn_inputs",
]


#: memory one frame of an animation takes until the file is written (measured: the peak of
#: ``assur animate`` on the four-bar grows 387 kB a frame from 36 to 360 and 720 frames,
#: 142, 268 and 407 MB: the frame's palette image, 480 x 400, and what Pillow keeps of it)
FRAME_BYTES = 400_000


def check_frames(frames: int, plan: SolvePlan) -> None:
    """Refuse an animation of more frames than fit in memory (``--steps``, an --inputs file).

    Raises
    ------
    SizeError
        Naming the memory the frames would take and how many fit.
    """
    items = len(plan.points) + len(plan.mechanism.moving_links)
    per_frame = FRAME_BYTES + BYTES_PER_POSE_ITEM * max(items, 1)
    check_size(
        frames,
        per_frame,
        f"an animation of {frames} frames",
        "ask for at most {fit} frames (--steps, or fewer lines in --inputs)",
    )


def _save(path: str, draw: Callable[[], object]) -> None:
    """Save the figure ``draw()`` makes to ``path`` whole or not at all (errors named).

    Raises
    ------
    MechanismError
        An unsupported format, or the file cannot be written.
    """
    try:
        figure = draw()
        with atomic_path(path) as temporary:
            figures.save(figure, temporary)
    except ValueError as exc:
        raise MechanismError(str(exc)) from exc


def save_cam_sheet(design: CamDesign, path: str, samples: int = 720) -> None:
    """A cam design's SVAJ diagrams beside its profile."""
    _save(path, lambda: cam_sheet(design, samples))


def save_structure_sheet(report: StructuralReport, path: str) -> None:
    """The kinematic graph, with the mechanism at its sketch pose when the file has one."""
    _save(path, lambda: figures.structure_sheet(report, *_sketch_pose(report)))


def _sketch_pose(report: StructuralReport) -> tuple[SolvePlan | None, KinematicState | None]:
    """The plan and the state at the sketch pose, or ``(None, None)`` for a graph alone."""
    if not report.mechanism.points:
        return None, None
    try:
        plan = make_plan(report)
        return plan, solve_pose(plan)
    except MechanismError:  # an incomplete sketch: the graph alone
        return None, None


def save_mechanism_drawing(
    report: StructuralReport, plan: SolvePlan, state: KinematicState, path: str
) -> None:
    """The mechanism alone at the pose of ``state``."""
    _save(path, lambda: figures.draw_mechanism(report, plan, state))


def save_kinematics_sheet(
    report: StructuralReport, plan: SolvePlan, state: KinematicState, path: str
) -> None:
    """The mechanism with its velocity and acceleration polygons."""
    _save(path, lambda: figures.kinematics_sheet(report, plan, state))


def save_forces_sheet(
    report: StructuralReport, plan: SolvePlan, forces: ForceSolution, path: str
) -> None:
    """The mechanism with the force polygon of each group and driver."""
    _save(path, lambda: figures.forces_sheet(report, plan, forces))


def save_sweep_figure(result: Sweep, plan: SolvePlan, path: str) -> None:
    """Paths, ω, ε, |v|, |a|, transmission angles and balancing over the sweep."""
    _save(path, lambda: figures.sweep_figure(result, plan))


def save_dynamics_sheet(result: MachineDynamics, path: str) -> None:
    """J_r(φ), M_r(φ), ω(φ), ω(t), the energy–inertia diagram and the shaking, on one sheet."""
    _save(path, lambda: dynamics_sheet(result))


def save_balance_sheet(result: Balanced, path: str) -> None:
    """The shaking force before and after a balance, and the driving torque."""
    _save(path, lambda: balance_sheet(result))


def save_target_figure(mechanism, path: str) -> None:
    """A synthesised design: its targets over the path of its marker P."""
    _save(path, lambda: target_figure(mechanism))


def save_structural_error(design, path: str) -> None:
    """A function generator's structural error over its range."""
    _save(path, lambda: structural_error_figure(design))
