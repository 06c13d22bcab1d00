"""Synthesis figures: the targets over the coupler curve, and a function generator's error.

:func:`target_figure` draws the mechanism at its sketch pose (its Assur
groups in colour), the path of its marker ``P`` over the whole motion the
solvers sweep (a crank's turn, or the targets' input range) and the targets
(crosses, gid ``target:T1``, ...), with P at each target's input (dots,
gid ``reached:T1``) where the targets are timed. The curve's gid is
``path:P``. :func:`structural_error_figure` plots ``y_generated − f(x)``
over the range (gid ``error``) with the precision points (gid ``precision``).
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure

from structure.errors import MechanismError
from structure.model import Mechanism
from structure.report import analyze

from ..solvers.plan import make_plan
from ..solvers.solve import solve_pose
from ..solvers.sweep import sweep
from ..synthesis.function import FunctionDesign
from .scene import draw_scene
from .style import figure_axes, state_poses

__all__ = ["coupler_curve", "structural_error_figure", "target_figure"]


def coupler_curve(mechanism: Mechanism, steps: int = 360) -> tuple[np.ndarray, np.ndarray]:
    """The inputs (rad from the sketch) and P's positions over the motion the solvers allow.

    A whole turn when the solvers go round; else the targets' input range; else
    nothing (empty arrays).
    """
    plan = make_plan(analyze(mechanism))
    turn = np.linspace(0.0, 2 * math.pi, steps + 1)
    try:
        result = sweep(plan, turn, rates=False)
        return turn, result.points["P"]["position"]
    except MechanismError:
        pass
    inputs = [t.input_deg for t in mechanism.targets if t.input_deg is not None]
    if len(inputs) >= 2:
        rows = np.radians(np.linspace(min(inputs), max(inputs), steps + 1))
        try:
            result = sweep(plan, rows, rates=False)
            return rows, result.points["P"]["position"]
        except MechanismError:
            pass
    return np.zeros(0), np.zeros((0, 2))


def target_figure(mechanism: Mechanism) -> Figure:
    """The targets over the path of P, the mechanism at its sketch pose beneath.

    >>> from kinematics.synthesis.linkages import Linkage, design_mechanism, target_records
    >>> x = np.array([0, 0, 0, 4, 1, 4, 3, 2, 1, 0, 1], dtype=float)
    >>> m = design_mechanism(Linkage.FOURBAR, x, target_records(np.array([[4.0, 2.0]])))
    >>> ax = target_figure(m).axes[0]
    >>> sorted(g for g in (ln.get_gid() for ln in ax.lines) if g and g[:5] in ("path:", "targe"))
    ['path:P', 'target:T1']
    """
    fig, ax = figure_axes(None)
    report = analyze(mechanism)
    plan = make_plan(report)
    _, handles = draw_scene(report, plan, ax, state_poses(solve_pose(plan)))
    inputs, curve = coupler_curve(mechanism)
    if len(curve):
        ax.plot(curve[:, 0], curve[:, 1], "-", color="tab:purple", lw=1.4, gid="path:P")
    for t in mechanism.targets:
        ax.plot([t.x], [t.y], "x", color="crimson", ms=9, mew=2, gid=f"target:{t.name}")
        ax.annotate(t.name, (t.x, t.y), textcoords="offset points", xytext=(5, 5), fontsize=8)
    timed = [t for t in mechanism.targets if t.input_deg is not None]
    if timed and len(curve):
        at = np.radians([t.input_deg for t in timed])
        reached = np.column_stack(
            [np.interp(at % (2 * math.pi), inputs, curve[:, k]) for k in (0, 1)]
        )
        if inputs[-1] - inputs[0] < 2 * math.pi - 1e-9:
            reached = np.column_stack([np.interp(at, inputs, curve[:, k]) for k in (0, 1)])
        for t, (px, py) in zip(timed, reached, strict=True):
            ax.plot([px], [py], "o", color="tab:purple", ms=4, gid=f"reached:{t.name}")
    ax.legend(handles=handles, loc="best", fontsize=8)
    ax.relim()
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.margins(0.1)
    ax.set_title(f"{mechanism.name or 'design'}: targets (×) over the path of P")
    return fig


def structural_error_figure(design: FunctionDesign) -> Figure:
    """The structural error over the range, the precision points marked."""
    fig, ax = figure_axes(None)
    ax.plot(design.x, design.error, "-", color="tab:blue", gid="error")
    px = np.array(design.precision_x)
    ax.plot(px, np.zeros_like(px), "o", color="crimson", gid="precision")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("x")
    ax.set_ylabel("y generated − f(x)")
    ax.set_title(f"structural error of {design.mechanism.name}: largest {design.error_max:.3g}")
    ax.grid(True, alpha=0.3)
    return fig
