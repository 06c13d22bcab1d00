"""The mechanism drawn at a pose: links, pins, sliders, higher pairs, markers and drivers.

:func:`draw_mechanism` — the scene of :func:`kinematics.figures.scene.draw_scene`
(whose module lists the artists' gids: ``link:<name>``, ``pin:<point>``,
``slider:<pair id>``, ``guide:<pair id>``, ``ground``,
``profile:<pair id>:<link>``, ``pitch:<pair id>:<link>``,
``contact:<point>``, ``marker:<name>``, ``driver:<link>``, ``point:<name>``)
at the state's pose, fitted to the axes with equal scales, titled with the
mechanism's name. The legend has one entry per Assur group
(``"II(2,3) RRR, order 2"``) in the group's colour, then one per driver
(``"driver 1"``) in black, then a dashed ``"virtual link"`` entry when
higher pairs were replaced. A mechanism far from metres is drawn in a power of
1000 of the metre, named on the axes (``x (10⁻³⁰³ m)``).
"""

from __future__ import annotations

from matplotlib.axes import Axes
from matplotlib.figure import Figure

from structure.report import StructuralReport

from ..solvers.plan import SolvePlan
from ..solvers.solve import KinematicState
from .scene import draw_scene
from .style import figure_axes, state_poses, unit_text

__all__ = ["draw_mechanism"]


def draw_mechanism(
    report: StructuralReport, plan: SolvePlan, state: KinematicState, ax: Axes | None = None
) -> Figure:
    """The mechanism at the state's pose, its Assur groups in colour, drivers in black.

    Higher pairs are drawn as their contacting profiles (gear meshes as pitch
    circles) and the virtual links that replace them dashed.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis (groups, drivers, replacements).
    plan : SolvePlan
        Its solve plan (:func:`kinematics.solvers.plan.make_plan`).
    state : KinematicState
        A solved pose (:func:`kinematics.solvers.solve.solve_pose`).
    ax : Axes, optional
        Draw on these axes instead of a new figure.

    Returns
    -------
    Figure
    """
    fig, ax = figure_axes(ax)
    scene, handles = draw_scene(report, plan, ax, state_poses(state))
    ax.legend(handles=handles, loc="best", fontsize=8)
    ax.relim()
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.margins(0.1)
    ax.set_title(getattr(plan.mechanism, "name", "") or "")
    ax.set_xlabel(f"x ({unit_text(scene.unit)})")
    ax.set_ylabel(f"y ({unit_text(scene.unit)})")
    return fig
