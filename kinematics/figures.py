"""Figures of a solved pose: the mechanism, its velocity and acceleration polygons.

Everything is drawn on a :class:`matplotlib.figure.Figure` with the Agg canvas
(no pyplot, no global state). The artists keep what they show, so a figure
can be read back:

* :func:`draw_mechanism` — each link's outline is a ``Line2D`` (a link with
  three or more points also a filled ``Polygon``) with gid ``link:<name>``;
  pins are ``Circle`` patches, sliders ``Polygon`` patches (gid
  ``slider:<pair id>``) on a dashed guide line (gid ``guide:<pair id>``); the
  ground's pins have a hatched base. Labels are ``Text`` objects with gid
  ``link:<name>`` (at the link's centroid) and ``point:<name>``. The legend
  has one entry per Assur group (``"II(2,3) RRR, order 2"``) in the group's
  colour, then one per driver (``"driver 1"``) in black.
* :func:`velocity_polygon`, :func:`acceleration_polygon` — the pole (``p``,
  ``π``) at the origin, each point's vector as an ``Annotation`` arrow with
  gid ``arrow:<name>`` (``.xyann`` the pole, ``.xy`` the tip, in drawing
  units), its lower-case label a ``Text`` with gid ``label:<name>``; the title
  states the scale, ``μ_v = 0.02 (m/s)/unit``.

>>> from structure.edgelist import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.plan import make_plan
>>> from kinematics.solve import solve_pose
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
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Circle, Polygon

from structure.model import PairKind
from structure.report import StructuralReport

from .plan import SolvePlan
from .solve import KinematicState

__all__ = [
    "acceleration_polygon",
    "draw_mechanism",
    "kinematics_sheet",
    "save",
    "velocity_polygon",
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
_DRIVER_COLOUR = "black"
_OTHER_COLOUR = "0.55"
_FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}


def _axes(ax: Axes | None, size: tuple[float, float] = (7.0, 6.0)) -> tuple[Figure, Axes]:
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=size)
    FigureCanvasAgg(fig)
    return fig, fig.add_subplot()


def _rot(theta: float) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s], [s, c]])


def _world(plan: SolvePlan, state: KinematicState, link: str, c) -> np.ndarray:
    """World position of sketch point ``c`` carried by ``link`` at the state's pose."""
    c = np.asarray(c, dtype=float)
    ls = state.links.get(link)
    if link == plan.mechanism.ground or ls is None:
        return c
    q = np.asarray(ls.q, dtype=float)
    return q[:2] + _rot(float(q[2])) @ c


def _angle(state: KinematicState, link: str) -> float:
    ls = state.links.get(link)
    return 0.0 if ls is None else float(np.asarray(ls.q)[2])


def _sketch(plan: SolvePlan, name: str | None) -> np.ndarray | None:
    if name is None:
        return None
    xy = plan.mechanism.coordinates(name)
    if xy is None and name in plan.points:
        return np.asarray(plan.points[name][1], dtype=float)
    return None if xy is None else np.asarray(xy, dtype=float)


def _link_points(plan: SolvePlan, link: str) -> dict[str, np.ndarray]:
    """The named sketch points of ``link``: its pair points and its markers."""
    m = plan.mechanism
    out: dict[str, np.ndarray] = {}
    for pair in m.pairs_of(link):
        xy = _sketch(plan, pair.point)
        if xy is not None and pair.point not in out:
            out[pair.point] = xy
    for name, (owner, xy) in plan.points.items():
        if owner == link and name not in out:
            out[name] = np.asarray(xy, dtype=float)
    for name, p in m.points.items():
        if p.on == link and name not in out:
            out[name] = np.array([p.x, p.y], dtype=float)
    return out


def _slider_of(plan: SolvePlan, pair) -> tuple[str, str]:
    """(block, guide) of a P pair: the block is the link pinned at the slide's point."""
    m = plan.mechanism
    if pair.a == m.ground:
        return pair.b, pair.a
    if pair.b == m.ground:
        return pair.a, pair.b

    def pinned(link: str) -> bool:
        return any(
            p.kind is PairKind.R and p.point == pair.point
            for p in m.pairs_of(link)
            if p is not pair
        )

    if pinned(pair.a) and not pinned(pair.b):
        return pair.a, pair.b
    return pair.b, pair.a


def _order(points: list[np.ndarray]) -> list[np.ndarray]:
    centre = np.mean(points, axis=0)
    return sorted(points, key=lambda p: math.atan2(p[1] - centre[1], p[0] - centre[0]))


def _group_entry(group) -> str:
    kind = f" {group.kind}" if group.kind else ""
    return f"{group.label}{kind}, order {group.order}"


def _rectangle(centre: np.ndarray, angle: float, length: float, width: float) -> np.ndarray:
    u = np.array([math.cos(angle), math.sin(angle)])
    n = np.array([-u[1], u[0]])
    h, w = length / 2, width / 2
    return np.array(
        [
            centre - h * u - w * n,
            centre + h * u - w * n,
            centre + h * u + w * n,
            centre - h * u + w * n,
        ]
    )


def draw_mechanism(
    report: StructuralReport, plan: SolvePlan, state: KinematicState, ax: Axes | None = None
) -> Figure:
    """The mechanism at the state's pose, its Assur groups in colour, drivers in black."""
    fig, ax = _axes(ax)
    m = plan.mechanism
    ground = m.ground

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

    world = {
        link: {n: _world(plan, state, link, xy) for n, xy in _link_points(plan, link).items()}
        for link in (*m.moving_links, ground)
    }
    every = [xy for pts in world.values() for xy in pts.values()]
    if every:
        span = np.ptp(np.array(every), axis=0)
        size = float(max(span.max(), getattr(plan, "length", 0.0) or 0.0, 1e-9))
    else:
        size = 1.0
    pin_r = 0.015 * size
    offset = np.array([0.02, 0.02]) * size

    # links
    for link in m.moving_links:
        c = colour.get(link, _OTHER_COLOUR)
        pts = list(world[link].values())
        if not pts:
            continue
        if len(pts) >= 3:
            ring = _order(pts)
            ax.add_patch(
                Polygon(
                    np.array(ring),
                    closed=True,
                    facecolor=c,
                    alpha=0.25,
                    edgecolor="none",
                    gid=f"link:{link}",
                    zorder=1,
                )
            )
            xy = np.array([*ring, ring[0]])
        else:
            xy = np.array(pts)
        ax.add_line(
            Line2D(
                xy[:, 0],
                xy[:, 1],
                color=c,
                lw=3,
                solid_capstyle="round",
                gid=f"link:{link}",
                zorder=2,
            )
        )
        centre = np.mean(pts, axis=0)
        ax.text(
            centre[0],
            centre[1] - offset[1],
            link,
            color=c,
            fontsize=10,
            fontweight="bold",
            ha="center",
            va="top",
            gid=f"link:{link}",
            zorder=6,
        )

    # sliders and their guides
    for pair in m.pairs:
        if pair.kind is not PairKind.P:
            continue
        block, guide = _slider_of(plan, pair)
        at = _sketch(plan, pair.point)
        if at is None:
            continue
        theta = (pair.angle or 0.0) + _angle(state, guide)
        on_guide = _world(plan, state, guide, at)
        u = np.array([math.cos(theta), math.sin(theta)])
        ends = np.array([on_guide - 0.35 * size * u, on_guide + 0.35 * size * u])
        gc = colour.get(guide, _DRIVER_COLOUR if guide == ground else _OTHER_COLOUR)
        ax.add_line(
            Line2D(
                ends[:, 0], ends[:, 1], color=gc, lw=1.2, ls="--", gid=f"guide:{pair.id}", zorder=1
            )
        )
        if guide == ground:
            n = np.array([-u[1], u[0]]) * 0.03 * size
            strip = np.array([ends[0], ends[1], ends[1] - n, ends[0] - n])
            ax.add_patch(
                Polygon(
                    strip,
                    closed=True,
                    facecolor="none",
                    edgecolor="0.3",
                    hatch="////",
                    lw=0,
                    gid="ground",
                    zorder=0,
                )
            )
        bc = colour.get(block, _OTHER_COLOUR)
        box = _rectangle(_world(plan, state, block, at), theta, 0.09 * size, 0.05 * size)
        ax.add_patch(
            Polygon(
                box,
                closed=True,
                facecolor=bc,
                alpha=0.6,
                edgecolor=bc,
                lw=1.5,
                gid=f"slider:{pair.id}",
                zorder=3,
            )
        )

    # pins (R pairs), the ground's hatched
    seen: set[tuple[float, float]] = set()
    for pair in m.pairs:
        if pair.kind is not PairKind.R:
            continue
        at = _sketch(plan, pair.point)
        if at is None:
            continue
        moving = pair.b if pair.a == ground else pair.a
        xy = _world(plan, state, moving, at)
        key = (round(float(xy[0]) / size, 9), round(float(xy[1]) / size, 9))
        if ground in (pair.a, pair.b) and (*key, 1.0) not in seen:
            seen.add((*key, 1.0))
            dx, dy = 2.5 * pin_r, -3.5 * pin_r
            base = np.array([xy, xy + np.array([-dx, dy]), xy + np.array([dx, dy])])
            ax.add_patch(
                Polygon(
                    base,
                    closed=True,
                    facecolor="white",
                    edgecolor="black",
                    hatch="////",
                    lw=1,
                    gid="ground",
                    zorder=0,
                )
            )
        if key in seen:
            continue
        seen.add(key)
        ax.add_patch(
            Circle(
                tuple(xy),
                pin_r,
                facecolor="white",
                edgecolor="black",
                lw=1.2,
                gid=f"pin:{pair.point}",
                zorder=5,
            )
        )

    # named points
    for name, (link, xy) in plan.points.items():
        w = _world(plan, state, link, xy)
        ax.text(
            w[0] + offset[0],
            w[1] + offset[1],
            name,
            fontsize=9,
            ha="left",
            va="bottom",
            gid=f"point:{name}",
            zorder=7,
        )

    ax.legend(handles=handles, loc="best", fontsize=8)
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.margins(0.1)
    title = getattr(m, "name", "") or ""
    ax.set_title(title)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return fig


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


def _polygon(
    vectors: Mapping[str, np.ndarray],
    ax: Axes | None,
    scale: float | None,
    pole: str,
    symbol: str,
    unit: str,
    what: str,
    colour: str,
) -> Figure:
    fig, ax = _axes(ax, (6.0, 6.0))
    vectors = {n: np.asarray(v, dtype=float) for n, v in vectors.items()}
    biggest = max((float(np.linalg.norm(v)) for v in vectors.values()), default=0.0)
    shown = {
        n: v for n, v in vectors.items() if float(np.linalg.norm(v)) > 1e-9 * max(biggest, 1e-12)
    }
    if scale is None:
        scale = _nice(biggest / 100.0) if biggest > 0 else 1.0
    if not scale > 0:
        raise ValueError(f"scale must be positive, got {scale}")
    tips = {n: v / scale for n, v in shown.items()}
    extent = max((float(np.abs(t).max()) for t in tips.values()), default=1.0) or 1.0
    nudge = 0.03 * extent

    ax.plot([0.0], [0.0], "o", color="black", ms=4, gid="pole")
    ax.text(-nudge, -nudge, pole, fontsize=11, ha="right", va="top", gid="label:pole")
    placed: list[np.ndarray] = []
    for name, tip in tips.items():
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(0.0, 0.0),
            arrowprops={
                "arrowstyle": "-|>",
                "color": colour,
                "lw": 1.5,
                "shrinkA": 0,
                "shrinkB": 0,
            },
            gid=f"arrow:{name}",
        )
        same = sum(1 for t in placed if np.linalg.norm(t - tip) <= 1e-6 * extent)
        placed.append(tip)
        d = tip / (np.linalg.norm(tip) or 1.0) * nudge * (1 + 1.5 * same)  # coincident tips
        ax.text(
            tip[0] + d[0],
            tip[1] + d[1],
            name.lower(),
            fontsize=10,
            ha="center",
            va="center",
            gid=f"label:{name}",
        )

    corners = np.array([[0.0, 0.0], *tips.values()])
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    pad = 0.12 * max(float((hi - lo).max()), extent)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.axhline(0.0, color="0.85", lw=0.6, zorder=0)
    ax.axvline(0.0, color="0.85", lw=0.6, zorder=0)
    ax.set_title(f"{what}, {symbol} = {scale:.6g} {unit}/unit")
    return fig


def velocity_polygon(
    plan: SolvePlan, state: KinematicState, ax: Axes | None = None, scale: float | None = None
) -> Figure:
    """Velocity polygon: pole p, an arrow p→x per moving point, ``scale`` (m/s)/unit."""
    vectors = {n: state.points[n].velocity for n in plan.points if n in state.points}
    return _polygon(vectors, ax, scale, "p", "μ_v", "(m/s)", "Velocity polygon", "tab:blue")


def acceleration_polygon(
    plan: SolvePlan, state: KinematicState, ax: Axes | None = None, scale: float | None = None
) -> Figure:
    """Acceleration polygon: pole π, an arrow π→x per point, ``scale`` (m/s²)/unit."""
    vectors = {n: state.points[n].acceleration for n in plan.points if n in state.points}
    return _polygon(vectors, ax, scale, "π", "μ_a", "(m/s²)", "Acceleration polygon", "tab:red")


def save(fig: Figure, path: str | Path) -> Path:
    """Write ``fig`` to ``path`` as PNG, SVG or PDF (by the extension)."""
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
