"""Shared style of the figures: group colours and legend, new axes, placing points, round scales.

What the figure modules (:mod:`kinematics.figures.scene`,
:mod:`kinematics.figures.mechanism`, :mod:`kinematics.figures.graph`,
:mod:`kinematics.figures.polygons`, :mod:`kinematics.figures.forces`) share:
each Assur group's colour (drivers black, other links grey) and the legend
entries (``"II(2,3) RRR, order 2"``, ``"driver 1"``, a dashed ``"virtual
link"``), a new Agg figure's axes, a link's sketch point placed at a pose,
and the round scale (1, 2, 2.5, 5 × 10ᵏ) of a polygon.

>>> nice_scale(0.3)
0.5
>>> place({"1": np.array([1.0, 0.0, math.pi / 2])}, "1", [1.0, 0.0]).round(12).tolist()
[1.0, 1.0]
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

from ..solvers.solve import KinematicState

__all__ = [
    "DRIVER_COLOUR",
    "OTHER_COLOUR",
    "PLAIN_SPANS",
    "Poses",
    "drawing_unit",
    "figure_axes",
    "length",
    "nice_scale",
    "palette",
    "place",
    "point_xy",
    "state_poses",
    "unit_text",
    "virtual_links",
]


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
DRIVER_COLOUR = "black"
"""The colour of the drivers (and of the ground)."""
OTHER_COLOUR = "0.55"
"""The colour of a link in no group (a virtual link's guide, an idle link)."""
_VIRTUAL_ENTRY = "virtual link (replaces a higher pair)"

Poses = Mapping[str, np.ndarray]
"""Each link's pose ``{link: (x, y, θ)}`` (m, m, rad); a link not in it stays at the sketch."""


def figure_axes(ax: Axes | None, size: tuple[float, float] = (7.0, 6.0)) -> tuple[Figure, Axes]:
    """``ax`` and its figure, or a new Agg figure of ``size`` (inches) with one axes."""
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=size)
    FigureCanvasAgg(fig)
    return fig, fig.add_subplot()


def place(poses: Poses, link: str, c) -> np.ndarray:
    """World position of sketch point(s) ``c`` ((2,) or (k, 2)) carried by ``link``."""
    c = np.asarray(c, dtype=float)
    q = poses.get(link)
    if q is None:
        return c
    cos, sin = math.cos(float(q[2])), math.sin(float(q[2]))
    return np.asarray(q[:2], dtype=float) + c @ np.array([[cos, sin], [-sin, cos]])


def state_poses(state: KinematicState) -> dict[str, np.ndarray]:
    """Each link's pose ``(x, y, θ)`` in a solved state."""
    return {name: np.asarray(ls.q, dtype=float) for name, ls in state.links.items()}


def point_xy(mechanism, name: str | None) -> np.ndarray | None:
    """The sketch coordinates of point ``name`` of ``mechanism`` (None: no name or no point)."""
    xy = mechanism.coordinates(name) if name else None
    return None if xy is None else np.asarray(xy, dtype=float)


def virtual_links(report: StructuralReport) -> set[str]:
    """The links that replace higher pairs (drawn dashed)."""
    return {r.virtual_link for r in report.replacements}


def _group_entry(group) -> str:
    kind = f" {group.kind}" if group.kind else ""
    return f"{group.label}{kind}, order {group.order}"


def palette(report: StructuralReport) -> tuple[dict[str, str], list[Line2D]]:
    """Each link's colour (its group's, drivers black) and the legend handles."""
    colour: dict[str, str] = {}
    handles: list[Line2D] = []
    for i, group in enumerate(report.groups):
        c = _GROUP_COLOURS[i % len(_GROUP_COLOURS)]
        for link in group.links:
            colour[link] = c
        handles.append(Line2D([], [], color=c, lw=3, label=_group_entry(group)))
    for link in report.drivers:
        colour[link] = DRIVER_COLOUR
        handles.append(Line2D([], [], color=DRIVER_COLOUR, lw=3, label=f"driver {link}"))
    if report.replacements:
        handles.append(Line2D([], [], color=OTHER_COLOUR, lw=1.5, ls="--", label=_VIRTUAL_ENTRY))
    return colour, handles


def length(v) -> float:
    """The length of a 2-D vector, by ``hypot``: no square under- or overflows at any scale.

    >>> length([3e-300, 4e-300]), length([3e200, 4e200]) > 4.99e200
    (5e-300, True)
    """
    return float(np.hypot(v[0], v[1]))


#: the spans drawn in plain metres; a span outside is drawn in a power of 1000 of the metre
PLAIN_SPANS = (1e-9, 1e9)


def drawing_unit(span: float) -> float:
    """The unit the figures draw lengths in: 1 (m), or 10³ᵏ m for a span far from metres.

    matplotlib cannot draw axes whose limits are below about 1e-287 (it widens them
    to ±0.05), and a browser draws an SVG in single precision, so a mechanism
    1e-302 m across is drawn in units of 10⁻³⁰³ m, numbers from 1 to 1000.

    >>> drawing_unit(0.4), drawing_unit(4e-302), drawing_unit(3e150)
    (1.0, 1e-303, 1e+150)
    """
    if not (math.isfinite(span) and span > 0) or PLAIN_SPANS[0] <= span <= PLAIN_SPANS[1]:
        return 1.0
    return float(f"1e{3 * math.floor(math.log10(span) / 3)}")


def unit_text(unit: float, what: str = "m") -> str:
    """The unit of an axis label: ``m``, or ``10⁻³⁰³ m`` for a drawing unit.

    >>> unit_text(1.0), unit_text(1e-303), unit_text(1e150, "m/s")
    ('m', '10⁻³⁰³ m', '10¹⁵⁰ m/s')
    """
    if unit == 1.0:
        return what
    power = str(round(math.log10(unit))).translate(_SUPERSCRIPT)
    return f"10{power} {what}"


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def nice_scale(value: float) -> float:
    """The smallest of 1, 2, 2.5, 5 × 10ᵏ not below ``value``."""
    if value <= 0 or not math.isfinite(value):
        return 1.0
    k = math.floor(math.log10(value))
    for step in (1.0, 2.0, 2.5, 5.0, 10.0):
        nice = float(f"{step * 10.0**k:.12g}")
        if nice >= value * (1 - 1e-12):
            return nice
    return float(f"{10.0 ** (k + 1):.12g}")
