"""Shared style of the figures: group colours and legend, new axes, placing points, round scales.

The private helpers the figure modules (:mod:`kinematics.mechanism_figure`,
:mod:`kinematics.graph_figure`, :mod:`kinematics.polygon_figures`,
:mod:`kinematics.force_figures`, :mod:`kinematics.sweep_figure`) share: each
Assur group's colour (drivers black, other links grey) and the legend entries
(``"II(2,3) RRR, order 2"``, ``"driver 1"``, a dashed ``"virtual link"``), a
new Agg figure's axes, a link's sketch point placed at a pose, and the round
scale (1, 2, 2.5, 5 × 10ᵏ) of a polygon.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from structure.report import StructuralReport

from ..solve import KinematicState

__all__: list[str] = []  # private helpers of the figure modules


_GROUP_COLOURS = (
    "tab:blue",
    "tab:orange",
    "tab:green",
    "tab:red",
    "tab:purple",
    "tab:brown",
    "tab:pink",
    "tab:olive",
    "tab:cyan",
)
_DRIVER_COLOUR = "black"
_OTHER_COLOUR = "0.55"
_VIRTUAL_ENTRY = "virtual link (replaces a higher pair)"

Poses = Mapping[str, np.ndarray]


def _axes(ax: Axes | None, size: tuple[float, float] = (7.0, 6.0)) -> tuple[Figure, Axes]:
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=size)
    FigureCanvasAgg(fig)
    return fig, fig.add_subplot()


def _place(poses: Poses, link: str, c) -> np.ndarray:
    """World position of sketch point(s) ``c`` ((2,) or (k, 2)) carried by ``link``."""
    c = np.asarray(c, dtype=float)
    q = poses.get(link)
    if q is None:
        return c
    cos, sin = math.cos(float(q[2])), math.sin(float(q[2]))
    return np.asarray(q[:2], dtype=float) + c @ np.array([[cos, sin], [-sin, cos]])


def _state_poses(state: KinematicState) -> dict[str, np.ndarray]:
    return {name: np.asarray(ls.q, dtype=float) for name, ls in state.links.items()}


def _xy(mechanism, name: str | None) -> np.ndarray | None:
    xy = mechanism.coordinates(name) if name else None
    return None if xy is None else np.asarray(xy, dtype=float)


def _virtual_links(report: StructuralReport) -> set[str]:
    return {r.virtual_link for r in report.replacements}


def _group_entry(group) -> str:
    kind = f" {group.kind}" if group.kind else ""
    return f"{group.label}{kind}, order {group.order}"


def _palette(report: StructuralReport) -> tuple[dict[str, str], list[Line2D]]:
    """Each link's colour (its group's, drivers black) and the legend handles."""
    colour: dict[str, str] = {}
    handles: list[Line2D] = []
    for i, group in enumerate(report.groups):
        c = _GROUP_COLOURS[i % len(_GROUP_COLOURS)]
        for link in group.links:
            colour[link] = c
        handles.append(Line2D([], [], color=c, lw=3, label=_group_entry(group)))
    for link in report.drivers:
        colour[link] = _DRIVER_COLOUR
        handles.append(Line2D([], [], color=_DRIVER_COLOUR, lw=3, label=f"driver {link}"))
    if report.replacements:
        handles.append(Line2D([], [], color=_OTHER_COLOUR, lw=1.5, ls="--", label=_VIRTUAL_ENTRY))
    return colour, handles


def _nice(value: float) -> float:
    """The smallest of 1, 2, 2.5, 5 × 10ᵏ not below ``value``."""
    if value <= 0 or not math.isfinite(value):
        return 1.0
    k = math.floor(math.log10(value))
    for step in (1.0, 2.0, 2.5, 5.0, 10.0):
        nice = float(f"{step * 10.0**k:.12g}")
        if nice >= value * (1 - 1e-12):
            return nice
    return float(f"{10.0 ** (k + 1):.12g}")
