"""Figures: the mechanism, its kinematic graph, velocity, acceleration and force polygons, sweeps.

Everything is drawn on a :class:`matplotlib.figure.Figure` with the Agg canvas
(no pyplot, no global state). The artists keep what they show, so a figure
can be read back by their gids; each drawing lives in the module named after
it, which states its gids, and is re-exported here:

* :mod:`kinematics.figures.mechanism` — :func:`draw_mechanism` (its
  artists drawn by :mod:`kinematics.figures.scene`);
* :mod:`kinematics.figures.graph` — :func:`draw_graph`;
* :mod:`kinematics.figures.polygons` — :func:`velocity_polygon`,
  :func:`acceleration_polygon`;
* :mod:`kinematics.figures.forces` — :func:`force_polygon`;
* :mod:`kinematics.figures.sweep` — :func:`sweep_figure`;
* :mod:`kinematics.figures.style` — the colours, axes and scales they share.

This module puts them together on sheets (:func:`kinematics_sheet`,
:func:`structure_sheet`, :func:`forces_sheet`) and saves a figure
(:func:`save`). The animation of a motion is
:func:`kinematics.figures.animation.animate`, imported from its module.

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.solvers.plan import make_plan
>>> from kinematics.solvers.solve import solve_pose
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 1", "point C 2 1", "point D 2 0"])
>>> report = analyze(m)
>>> plan = make_plan(report)
>>> state = solve_pose(plan)
>>> fig = draw_mechanism(report, plan, state)
>>> [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
['II(2,3) RRR, order 2', 'driver 1']
>>> velocity_polygon(plan, state).axes[0].get_title()
'Velocity polygon, μ_v = 0.1 (m/s)/unit'
>>> graph = draw_graph(report).axes[0]
>>> sorted(p.get_gid() for p in graph.patches if p.get_gid().startswith("node"))
['node:0', 'node:1', 'node:2', 'node:3']
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from structure.report import StructuralReport

from ..kinetostatics.forces import ForceSolution
from ..solvers.plan import SolvePlan
from ..solvers.solve import KinematicState, solve_pose
from .forces import draw_loads, force_polygon, polygon_entries
from .graph import draw_graph
from .mechanism import draw_mechanism
from .polygons import acceleration_polygon, velocity_polygon
from .sweep import sweep_figure

__all__ = [
    "acceleration_polygon",
    "draw_graph",
    "draw_mechanism",
    "force_polygon",
    "forces_sheet",
    "kinematics_sheet",
    "save",
    "structure_sheet",
    "sweep_figure",
    "velocity_polygon",
]


_FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}


def save(fig: Figure, path: str | Path) -> Path:
    """Write ``fig`` to ``path`` as PNG, SVG or PDF (by the extension).

    Raises
    ------
    ValueError
        Another extension.
    """
    path = Path(path)
    fmt = _FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise ValueError(f"unsupported figure format {path.suffix!r}: use .png, .svg or .pdf")
    if fig.canvas is None or not hasattr(fig.canvas, "print_figure"):
        FigureCanvasAgg(fig)
    fig.savefig(path, format=fmt, bbox_inches="tight")
    return path


def kinematics_sheet(report: StructuralReport, plan: SolvePlan, state: KinematicState) -> Figure:
    """One figure with the mechanism at the pose and its velocity and acceleration polygons."""
    fig = Figure(figsize=(18.0, 6.0))
    FigureCanvasAgg(fig)
    left, middle, right = fig.subplots(1, 3)
    draw_mechanism(report, plan, state, ax=left)
    velocity_polygon(plan, state, ax=middle)
    acceleration_polygon(plan, state, ax=right)
    fig.tight_layout()
    return fig


def structure_sheet(
    report: StructuralReport, plan: SolvePlan | None = None, state: KinematicState | None = None
) -> Figure:
    """The kinematic graph, and beside it the mechanism when a solved pose is given.

    Parameters
    ----------
    report : StructuralReport
    plan, state : SolvePlan, KinematicState, optional
        A solved pose (the sketch's); without them, the graph alone.

    Returns
    -------
    Figure
    """
    if plan is None or state is None:
        return draw_graph(report)
    fig = Figure(figsize=(15.0, 6.0))
    FigureCanvasAgg(fig)
    left, right = fig.subplots(1, 2)
    draw_graph(report, ax=left)
    draw_mechanism(report, plan, state, ax=right)
    fig.tight_layout()
    return fig


def forces_sheet(
    report: StructuralReport,
    plan: SolvePlan,
    solution: ForceSolution,
    state: KinematicState | None = None,
) -> Figure:
    """The mechanism at the pose with its loads, then the force polygons (:func:`force_polygon`).

    Parameters
    ----------
    report : StructuralReport
    plan : SolvePlan
    solution : ForceSolution
        From :func:`kinematics.kinetostatics.forces.solve_forces` at the pose of ``state``.
    state : KinematicState, optional
        The pose (default: the sketch's).

    Returns
    -------
    Figure
    """
    state = solve_pose(plan) if state is None else state
    entries = polygon_entries(plan, solution)
    panels = 1 + len(entries)
    cols = min(panels, 3)
    rows = math.ceil(panels / cols)
    fig = Figure(figsize=(6.2 * cols, 5.2 * rows))
    FigureCanvasAgg(fig)
    axes = list(np.atleast_1d(fig.subplots(rows, cols)).ravel())
    for extra in axes[panels:]:
        fig.delaxes(extra)
    draw_mechanism(report, plan, state, ax=axes[0])
    draw_loads(axes[0], plan, state)
    for (label, _, _), ax in zip(entries, axes[1:], strict=False):
        force_polygon(plan, solution, label, ax=ax, state=state)
    fig.tight_layout()
    return fig
