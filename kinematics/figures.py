"""Figures: the mechanism, its kinematic graph, velocity, acceleration and force polygons, sweeps.

Everything is drawn on a :class:`matplotlib.figure.Figure` with the Agg canvas
(no pyplot, no global state). The artists keep what they show, so a figure
can be read back by their gids:

* :func:`draw_mechanism` — each link's outline is a ``Line2D`` (a link with
  three or more points also a filled ``Polygon``) with gid ``link:<name>``,
  dashed for the virtual links of a higher-pair replacement; pins are
  ``Circle`` patches (gid ``pin:<point>``), sliders ``Polygon`` blocks (gid
  ``slider:<pair id>``) on a dashed guide line (gid ``guide:<pair id>``); the
  ground is hatched (gid ``ground``). A higher pair is drawn as its contacting
  profiles (gid ``profile:<pair id>:<link>``: the osculating circles of the
  curved profiles, the flat face, the roller), a gear mesh as its pitch
  circles (gid ``pitch:<pair id>:<link>``), the contact as a dot (gid
  ``contact:<point>``). Markers are dots (gid ``marker:<name>``), the drivers
  carry an arrow of their motion (gid ``driver:<link>``). Labels are ``Text``
  objects with gid ``link:<name>`` and ``point:<name>``. The legend has one
  entry per Assur group (``"II(2,3) RRR, order 2"``) in the group's colour,
  then one per driver (``"driver 1"``) in black, then a dashed
  ``"virtual link"`` entry when higher pairs were replaced.
* :func:`draw_graph` — the kinematic graph: one node per link (``Circle``, the
  ground a hatched square, gid ``node:<link>``, coloured as in
  :func:`draw_mechanism`, drivers black, virtual links dashed), one edge per
  pair (``FancyArrowPatch``, gid ``edge:<pair id>``, parallel pairs bowed
  apart, the pairs of a replacement dashed) labelled with its kind and point.
* :func:`velocity_polygon`, :func:`acceleration_polygon` — the pole (``p``,
  ``π``) at the origin, each point's vector as an ``Annotation`` arrow with
  gid ``arrow:<name>`` (``.xyann`` the pole, ``.xy`` the tip, in drawing
  units), its lower-case label a ``Text`` with gid ``label:<name>``; the title
  states the scale, ``μ_v = 0.02 (m/s)/unit``. Each dyad's vector equations
  (:mod:`kinematics.polygons`) are drawn head to tail from the known points'
  images: relative velocities ``rel:v_CB``, ``rel:v_B3B2``; normal,
  tangential, Coriolis and relative accelerations ``comp:a^n_CB``,
  ``comp:a^t_CB``, ``comp:a^k_B3B2``, ``comp:a^r_B3B2`` (a zero one is a
  circle ``Line2D``), each labelled by a ``Text`` with the same gid; the
  point between two components is a dot ``node:n_CB`` or ``node:k_B3B2``.
* :func:`force_polygon` — for each Assur group (and each driver) the forces on
  it drawn head to tail, a closed polygon: ``Annotation`` arrows with gid
  ``force:<key>`` (``load:<link>:<point>``, ``weight:<link>``,
  ``inertia:<link>``, ``reaction:<from>-><on>:<point>``, ``balance:<link>``),
  the scale ``μ_F = 10 N/unit`` in the title; :func:`forces_sheet` also draws
  the applied forces on the mechanism (gid ``load:<link>:<point>``).
* :func:`sweep_figure` — point paths and ω, ε, \\|v\\|, \\|a\\|, transmission
  angle and balancing moment against the input, each a ``Line2D`` with gid
  ``path:<point>``, ``omega:<link>``, ``epsilon:<link>``, ``speed:<point>``,
  ``accel:<point>``, ``transmission:<group>``, ``balancing:<name>``.

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
>>> graph = draw_graph(report).axes[0]
>>> sorted(p.get_gid() for p in graph.patches if p.get_gid().startswith("node"))
['node:0', 'node:1', 'node:2', 'node:3']
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import networkx as nx
import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Arc, Circle, FancyArrowPatch, Polygon, Rectangle

from structure.model import Pair, PairKind
from structure.report import StructuralReport

from .forces import ForceSolution
from .plan import SolvePlan
from .polygons import Term, point_motion, vector_equations
from .solve import KinematicState, solve_pose
from .sweep import Sweep

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
_FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}

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


def _turn(poses: Poses, link: str) -> float:
    q = poses.get(link)
    return 0.0 if q is None else float(q[2])


def _state_poses(state: KinematicState) -> dict[str, np.ndarray]:
    return {name: np.asarray(ls.q, dtype=float) for name, ls in state.links.items()}


def _sketch(plan: SolvePlan, name: str | None) -> np.ndarray | None:
    if name is None:
        return None
    xy = plan.mechanism.coordinates(name)
    if xy is None and name in plan.points:
        return np.asarray(plan.points[name][1], dtype=float)
    return None if xy is None else np.asarray(xy, dtype=float)


def _virtual_links(report: StructuralReport) -> set[str]:
    return {r.virtual_link for r in report.replacements}


def _link_points(plan: SolvePlan, link: str, virtual: set[str]) -> dict[str, np.ndarray]:
    """The named sketch points of ``link``: its pair points and its markers.

    A real link leaves out the point of a virtual link's slide along its flat
    face (that point is on the slide line, not on the link's body).
    """
    m = plan.mechanism
    out: dict[str, np.ndarray] = {}
    for pair in m.pairs_of(link):
        if pair.kind is PairKind.P and link not in virtual and pair.other(link) in virtual:
            continue
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


# ---------------------------------------------------------------- the mechanism


class _Scene:
    """The artists of a mechanism drawing and the functions that move them with the links.

    ``anchors`` lists each link's sketch points (to bound a whole motion).
    """

    def __init__(self, size: float) -> None:
        self.size = size
        self.anchors: list[tuple[str, np.ndarray]] = []
        self.artists: list = []  # the artists that move, to redraw them alone
        self.virtual: dict[str, list] = {}  # the artists of each virtual link
        self._moves: list[Callable[[Poses], None]] = []

    def follow(self, move: Callable[[Poses], None], *artists) -> None:
        """Call ``move(poses)`` on every update; it moves ``artists``."""
        self._moves.append(move)
        self.artists.extend(artists)

    def update(self, poses: Poses) -> None:
        """Move every artist to the links' poses ``{link: (x, y, θ)}``."""
        for move in self._moves:
            move(poses)


@dataclass(frozen=True)
class _Profile:
    """A contact curve of a higher pair: whose profile, which link carries it, its shape."""

    pair: Pair
    link: str
    carrier: str
    kind: str  # 'roller', 'circle', 'arc', 'flat' or 'pitch'
    centre: np.ndarray  # sketch; the contact point for 'flat'
    radius: float
    angle: float  # 'flat': the face's direction; 'arc': from the centre to the contact (rad)


def _xy(mechanism, name: str | None) -> np.ndarray | None:
    xy = mechanism.coordinates(name) if name else None
    return None if xy is None else np.asarray(xy, dtype=float)


def _pitch_circles(mechanism, pair: Pair, contact: np.ndarray | None) -> list[_Profile]:
    """Pitch circles of a gear mesh: radius m·z/2 (``module=``), else the axis–contact distance."""
    out = []
    teeth = pair.teeth or (None, None)
    for link, z in zip((pair.a, pair.b), teeth, strict=True):
        known = pair.module * z / 2 if pair.module and z else None
        pins = [
            q
            for q in mechanism.pairs_of(link)
            if q.kind is PairKind.R and _xy(mechanism, q.point) is not None
        ]
        if not pins:
            continue
        if known is not None and contact is not None:
            axis = min(
                (_xy(mechanism, q.point) for q in pins),
                key=lambda c: abs(float(np.hypot(*(c - contact))) - known),
            )
        elif link == mechanism.ground:
            continue  # which of the frame's pivots is the gear's axis is not known
        else:
            to_ground = [q for q in pins if q.other(link) == mechanism.ground]
            axis = _xy(mechanism, (to_ground or pins)[0].point)
        radius = known
        if radius is None and contact is not None:
            radius = float(np.hypot(*(axis - contact)))
        if radius and radius > 0:
            out.append(_Profile(pair, link, link, "pitch", axis, radius, 0.0))
    return out


def _profiles(report: StructuralReport, size: float) -> list[_Profile]:
    """The contact curves of every replaced higher pair, at the sketch."""
    m = report.mechanism
    out: list[_Profile] = []
    for r in report.replacements:
        p = r.pair
        contact = _xy(m, p.point)
        if p.gear:
            out.extend(_pitch_circles(m, p, contact))
            continue
        if contact is None:
            continue
        for link in (p.a, p.b):
            if r.roller is not None and link == r.roller.roller:
                axis = _xy(m, r.roller.axis)
                if axis is not None:
                    radius = float(np.hypot(*(axis - contact)))
                    out.append(_Profile(p, link, r.roller.follower, "roller", axis, radius, 0.0))
                continue
            if p.flat == link:
                face = next((q.angle for q in r.new_pairs if q.kind is PairKind.P), None)
                if face is not None:
                    out.append(_Profile(p, link, link, "flat", contact, 0.0, face))
                continue
            centre = _xy(m, p.center_of(link))
            if centre is None:
                continue
            radius = float(np.hypot(*(centre - contact)))
            if radius <= 1e-9 * size:
                continue  # a knife edge: the contact dot is its profile
            toward = math.atan2(contact[1] - centre[1], contact[0] - centre[0])
            kind = "circle" if radius <= 1.5 * size else "arc"
            out.append(_Profile(p, link, link, kind, centre, radius, toward))
    return out


def _contact_carrier(plan: SolvePlan, pair: Pair) -> str:
    links = plan.mechanism.links
    return pair.a if pair.a in links else pair.b


def _draw_scene(
    report: StructuralReport, plan: SolvePlan, ax: Axes, poses: Poses
) -> tuple[_Scene, list[Line2D]]:
    """Draw the mechanism at ``poses`` on ``ax``; the scene moves it to other poses."""
    m = plan.mechanism
    ground = m.ground
    colour, handles = _palette(report)
    virtual = _virtual_links(report)
    bodies = {link: _link_points(plan, link, virtual) for link in m.moving_links}

    sketch_span = [xy for pts in bodies.values() for xy in pts.values()]
    sketch_span += [xy for pair in m.pairs if (xy := _sketch(plan, pair.point)) is not None]
    if sketch_span:
        world = np.array(
            [_place(poses, lk, xy) for lk, pts in bodies.items() for xy in pts.values()]
        )
        span = float(np.ptp(np.array(sketch_span), axis=0).max())
        if len(world):
            span = max(span, float(np.ptp(world, axis=0).max()))
        size = float(max(span, plan.length or 0.0, 1e-9))
    else:
        size = float(plan.length or 1.0)
    profiles = _profiles(report, size)
    for prof in profiles:
        if prof.kind == "flat" and prof.link in bodies and prof.pair.point:
            bodies[prof.link].setdefault(prof.pair.point, prof.centre)
    scene = _Scene(size)
    pin_r = 0.015 * size
    offset = 0.02 * size

    def tint(link: str) -> str:
        return colour.get(link, _DRIVER_COLOUR if link == ground else _OTHER_COLOUR)

    # links: outline, filled body of a ternary link, label
    for link, pts in bodies.items():
        if not pts:
            continue
        scene.anchors.append((link, np.array(list(pts.values()))))
        before = len(scene.artists)
        _draw_link(ax, scene, link, list(pts.values()), tint(link), link in virtual, offset)
        if link in virtual:
            scene.virtual.setdefault(link, []).extend(scene.artists[before:])

    # higher pairs: the contacting profiles, the contact point
    compass = np.array([[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]])
    for prof in profiles:
        _draw_profile(ax, scene, prof, tint(prof.carrier if prof.kind == "roller" else prof.link))
        if prof.kind != "flat":
            scene.anchors.append((prof.carrier, prof.centre + prof.radius * compass))
        if prof.kind == "roller":
            label = ax.text(
                0,
                0,
                prof.link,
                color=tint(prof.carrier),
                fontsize=10,
                fontweight="bold",
                ha="left",
                va="bottom",
                gid=f"link:{prof.link}",
                zorder=6,
            )
            scene.follow(_mover_text(label, prof.carrier, prof.centre, prof.radius * 0.75), label)
    for r in report.replacements:
        k = _xy(report.mechanism, r.pair.point)
        if k is None:
            continue
        # a gear mesh's contact stays at the pitch point as the gears roll
        carrier = ground if r.pair.gear else _contact_carrier(plan, r.pair)
        dot = Line2D(
            [k[0]],
            [k[1]],
            marker="o",
            ms=4,
            color="black",
            ls="none",
            gid=f"contact:{r.pair.point}",
            zorder=7,
        )
        ax.add_line(dot)
        scene.follow(_mover_dot(dot, carrier, k), dot)
        if r.pair.point not in plan.points:
            text = ax.text(
                0,
                0,
                r.pair.point,
                fontsize=9,
                ha="left",
                va="bottom",
                gid=f"point:{r.pair.point}",
                zorder=7,
            )
            scene.follow(_mover_text(text, carrier, k, offset), text)

    # sliders and their guides
    for pair in m.pairs:
        if pair.kind is not PairKind.P:
            continue
        at = _sketch(plan, pair.point)
        if at is None:
            continue
        block, guide = _slider_of(plan, pair)
        before = len(scene.artists)
        _draw_slider(ax, scene, pair, block, guide, at, tint, ground, virtual, size)
        for link in {block, guide} & virtual:
            scene.virtual.setdefault(link, []).extend(scene.artists[before:])

    # pins (R pairs), the ground's on a hatched base
    pins: dict[str, list[Pair]] = {}
    real_pins = {p.point for p in report.mechanism.pairs if p.kind is PairKind.R}
    for pair in m.pairs:
        if pair.kind is PairKind.R and pair.point is not None:
            pins.setdefault(pair.point, []).append(pair)
    for point, pairs in pins.items():
        at = _sketch(plan, point)
        if at is None:
            continue
        links = [lk for p in pairs for lk in p.links]
        only_virtual = point not in real_pins and all(
            p.a in virtual or p.b in virtual for p in pairs
        )
        if ground in links:
            dx, dy = 2.5 * pin_r, -3.5 * pin_r
            base = np.array([at, at + np.array([-dx, dy]), at + np.array([dx, dy])])
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
        pin = Circle(
            tuple(at),
            pin_r,
            facecolor="white",
            edgecolor="black",
            lw=1.2,
            ls="--" if only_virtual else "-",
            gid=f"pin:{point}",
            zorder=5,
        )
        ax.add_patch(pin)
        if ground not in links:
            carrier = next((lk for lk in links if lk not in virtual), links[0])
            scene.follow(_mover_centre(pin, carrier, at), pin)

    # named points and markers
    for name, (link, xy) in plan.points.items():
        if link in virtual:  # a pin of a virtual link: carried by the real link it joins
            link = next(
                (lk for p in m.pairs if p.point == name for lk in p.links if lk not in virtual),
                link,
            )
        xy = np.asarray(xy, dtype=float)
        text = ax.text(
            0, 0, name, fontsize=9, ha="left", va="bottom", gid=f"point:{name}", zorder=7
        )
        scene.follow(_mover_text(text, link, xy, offset), text)
        definition = m.points.get(name)
        if definition is not None and definition.on is not None:
            dot = Line2D(
                [xy[0]],
                [xy[1]],
                marker="o",
                ms=4,
                ls="none",
                color=tint(link),
                markeredgecolor="black",
                gid=f"marker:{name}",
                zorder=6,
            )
            ax.add_line(dot)
            scene.follow(_mover_dot(dot, link, xy), dot)

    # the drivers' motion
    for d in plan.drivers:
        _draw_driver(ax, scene, plan, d, bodies.get(d.link, {}), pin_r, size)

    scene.update(poses)
    return scene, handles


def _mover_text(text, link: str, xy: np.ndarray, nudge: float) -> Callable[[Poses], None]:
    """Move ``text`` to the point ``xy`` of ``link``, ``nudge`` up and right of it."""

    def move(poses: Poses) -> None:
        w = _place(poses, link, xy) + nudge
        text.set_position((float(w[0]), float(w[1])))

    return move


def _mover_dot(line: Line2D, link: str, xy: np.ndarray) -> Callable[[Poses], None]:
    def move(poses: Poses) -> None:
        w = _place(poses, link, xy)
        line.set_data([w[0]], [w[1]])

    return move


def _mover_centre(patch, link: str, xy: np.ndarray) -> Callable[[Poses], None]:
    def move(poses: Poses) -> None:
        patch.set_center(tuple(_place(poses, link, xy)))

    return move


def _draw_link(
    ax: Axes, scene: _Scene, link: str, pts: list, c: str, virtual: bool, offset: float
) -> None:
    ring = len(pts) >= 3
    sketch = np.array(_order(pts) if ring else pts)
    body = None
    if ring and not virtual:
        body = Polygon(
            sketch,
            closed=True,
            facecolor=c,
            alpha=0.25,
            edgecolor="none",
            gid=f"link:{link}",
            zorder=1,
        )
        ax.add_patch(body)
    line = Line2D(
        [],
        [],
        color=c,
        lw=1.6 if virtual else 3,
        ls="--" if virtual else "-",
        solid_capstyle="round",
        gid=f"link:{link}",
        zorder=2,
    )
    ax.add_line(line)
    label = ax.text(
        0,
        0,
        link,
        color=c,
        fontsize=10,
        fontweight="bold",
        ha="center",
        va="center",
        gid=f"link:{link}",
        zorder=6,
    )
    centre = sketch.mean(axis=0)

    def move(poses: Poses) -> None:
        w = _place(poses, link, sketch)
        if body is not None:
            body.set_xy(w)
        xy = np.vstack([w, w[:1]]) if ring else w
        line.set_data(xy[:, 0], xy[:, 1])
        at = _place(poses, link, centre)
        if len(w) == 2 and np.hypot(*(w[1] - w[0])) > 0:  # beside a bar, below or right of it
            d = (w[1] - w[0]) / np.hypot(*(w[1] - w[0]))
            side = np.array([d[1], -d[0]])
            if side[1] > 1e-9 or (abs(side[1]) <= 1e-9 and side[0] < 0):
                side = -side
            at = at + 1.6 * offset * side
        elif not ring:
            at = at - np.array([0.0, 1.6 * offset])
        label.set_position((float(at[0]), float(at[1])))

    scene.follow(move, *([body] if body is not None else []), line, label)


def _draw_profile(ax: Axes, scene: _Scene, prof: _Profile, c: str) -> None:
    gid = f"{'pitch' if prof.kind == 'pitch' else 'profile'}:{prof.pair.id}:{prof.link}"
    size = scene.size
    if prof.kind == "flat":
        u = np.array([math.cos(prof.angle), math.sin(prof.angle)])
        ends = np.array([prof.centre - 0.18 * size * u, prof.centre + 0.18 * size * u])
        face = Line2D([], [], color=c, lw=2.5, gid=gid, zorder=3)
        ax.add_line(face)

        def move(poses: Poses) -> None:
            w = _place(poses, prof.carrier, ends)
            face.set_data(w[:, 0], w[:, 1])

        scene.follow(move, face)
        return
    if prof.kind == "arc":
        span = min(300.0, math.degrees(1.2 * size / prof.radius))
        mid = math.degrees(prof.angle)
        patch = Arc(
            tuple(prof.centre),
            2 * prof.radius,
            2 * prof.radius,
            theta1=mid - span / 2,
            theta2=mid + span / 2,
            color=c,
            lw=2,
            gid=gid,
            zorder=3,
        )
    elif prof.kind == "pitch":
        patch = Circle(
            tuple(prof.centre),
            prof.radius,
            fill=False,
            edgecolor=c,
            lw=1.3,
            ls="-.",
            gid=gid,
            zorder=3,
        )
    else:  # a roller or the osculating circle of a cam
        patch = Circle(
            tuple(prof.centre),
            prof.radius,
            facecolor=to_rgba(c, 0.15 if prof.kind == "roller" else 0.07),
            edgecolor=c,
            lw=1.8,
            gid=gid,
            zorder=3,
        )
    ax.add_patch(patch)

    def move_curve(poses: Poses) -> None:
        patch.set_center(tuple(_place(poses, prof.carrier, prof.centre)))
        if isinstance(patch, Arc):
            patch.set_angle(math.degrees(_turn(poses, prof.carrier)))

    scene.follow(move_curve, patch)


def _draw_slider(
    ax: Axes,
    scene: _Scene,
    pair: Pair,
    block: str,
    guide: str,
    at: np.ndarray,
    tint: Callable[[str], str],
    ground: str,
    virtual: set[str],
    size: float,
) -> None:
    dashed = block in virtual or guide in virtual
    line = Line2D([], [], color=tint(guide), lw=1.2, ls="--", gid=f"guide:{pair.id}", zorder=1)
    ax.add_line(line)
    half = 0.35 * size
    if guide == ground:
        u = np.array([math.cos(pair.angle or 0.0), math.sin(pair.angle or 0.0)])
        n = np.array([-u[1], u[0]]) * 0.03 * size
        ends = np.array([at - half * u, at + half * u])
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
    bc = tint(block)
    box = Polygon(
        _rectangle(at, pair.angle or 0.0, 0.09 * size, 0.05 * size),
        closed=True,
        facecolor="none" if dashed else bc,
        alpha=None if dashed else 0.6,
        edgecolor=bc,
        lw=1.5,
        ls="--" if dashed else "-",
        gid=f"slider:{pair.id}",
        zorder=3,
    )
    ax.add_patch(box)

    def move(poses: Poses) -> None:
        theta = (pair.angle or 0.0) + _turn(poses, guide)
        on_guide = _place(poses, guide, at)
        u = np.array([math.cos(theta), math.sin(theta)])
        ends = np.array([on_guide - half * u, on_guide + half * u])
        line.set_data(ends[:, 0], ends[:, 1])
        box.set_xy(_rectangle(_place(poses, block, at), theta, 0.09 * size, 0.05 * size))

    scene.follow(move, line, box)


def _draw_driver(
    ax: Axes,
    scene: _Scene,
    plan: SolvePlan,
    d,
    body: Mapping[str, np.ndarray],
    pin_r: float,
    size: float,
) -> None:
    """An arc arrow of ω about a rotating driver's pivot, a straight one along a slide."""
    forward = d.speed >= 0
    if d.kind == "R":
        pivot = np.asarray(d.pivot, dtype=float)
        others = [xy for xy in body.values() if np.hypot(*(xy - pivot)) > 1e-9 * size]
        away = -math.pi / 2
        if others:
            arm = np.mean(others, axis=0) - pivot
            if np.hypot(*arm) > 1e-12:
                away = math.atan2(arm[1], arm[0]) + math.pi
        rho = 4.5 * pin_r
        ends = [
            pivot + rho * np.array([math.cos(a), math.sin(a)]) for a in (away - 0.9, away + 0.9)
        ]
        if not forward:
            ends.reverse()
        note = pivot + 2.0 * rho * np.array([math.cos(away), math.sin(away)])
        symbol = f"ω{d.link}"
    else:
        at = _sketch(plan, d.point)
        if at is None:
            at = np.mean(list(body.values()), axis=0) if body else np.zeros(2)
        u = np.asarray(d.direction, dtype=float) * (1.0 if forward else -1.0)
        n = np.array([-u[1], u[0]])
        base = at + 0.07 * size * n
        ends = [base - 0.08 * size * u, base + 0.08 * size * u]
        note = base + 0.03 * size * n
        symbol = f"v{d.link}"
    sketch = np.array(ends)
    arrow = FancyArrowPatch(
        tuple(sketch[0]),
        tuple(sketch[1]),
        arrowstyle="-|>",
        mutation_scale=12,
        connectionstyle="arc3,rad=0.35" if d.kind == "R" else "arc3,rad=0",
        color="black",
        lw=1.3,
        gid=f"driver:{d.link}",
        zorder=6,
    )
    ax.add_artist(arrow)
    text = ax.text(0, 0, symbol, fontsize=10, ha="center", va="center", gid=f"driver:{d.link}")

    def move(poses: Poses) -> None:
        w = _place(poses, d.link, sketch)
        arrow.set_positions(tuple(w[0]), tuple(w[1]))
        t = _place(poses, d.link, note)
        text.set_position((float(t[0]), float(t[1])))

    scene.follow(move, arrow, text)


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
        Its solve plan (:func:`kinematics.plan.make_plan`).
    state : KinematicState
        A solved pose (:func:`kinematics.solve.solve_pose`).
    ax : Axes, optional
        Draw on these axes instead of a new figure.

    Returns
    -------
    Figure
    """
    fig, ax = _axes(ax)
    _, handles = _draw_scene(report, plan, ax, _state_poses(state))
    ax.legend(handles=handles, loc="best", fontsize=8)
    ax.relim()
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.margins(0.1)
    ax.set_title(getattr(plan.mechanism, "name", "") or "")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return fig


# ---------------------------------------------------------------- the kinematic graph


def _graph_layout(graph: nx.MultiGraph, ground: str) -> dict[str, np.ndarray]:
    """Node positions (about [-1, 1]²), turned so that the ground is at the bottom."""
    simple = nx.Graph(graph)
    if simple.number_of_nodes() < 2:
        return {n: np.zeros(2) for n in simple}
    try:
        if simple.number_of_nodes() > 200:
            raise ImportError  # Kamada–Kawai is quadratic: springs for big graphs
        pos = nx.kamada_kawai_layout(simple)
    except ImportError:  # it needs scipy
        pos = nx.spring_layout(simple, seed=1)
    xy = {n: np.asarray(p, dtype=float) for n, p in pos.items()}
    centre = np.mean(list(xy.values()), axis=0)
    down = xy[ground] - centre if ground in xy else np.zeros(2)
    if np.hypot(*down) > 1e-9:
        turn = -math.pi / 2 - math.atan2(down[1], down[0])
        c, s = math.cos(turn), math.sin(turn)
        rot = np.array([[c, -s], [s, c]])
        xy = {n: rot @ (p - centre) for n, p in xy.items()}
    return xy


def draw_graph(report: StructuralReport, ax: Axes | None = None) -> Figure:
    """The kinematic graph: links as nodes, pairs as edges, coloured by Assur group.

    The nodes are coloured as in :func:`draw_mechanism` (the same legend), the
    drivers black, the ground a hatched square; each pair is an edge labelled
    with its kind and point (parallel pairs bowed apart). The virtual links of
    a higher-pair replacement and their two pairs are dashed, beside the
    higher pair they stand for.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis; no coordinates are needed.
    ax : Axes, optional
        Draw on these axes instead of a new figure.

    Returns
    -------
    Figure
    """
    fig, ax = _axes(ax, (6.5, 5.5))
    m = report.mechanism
    colour, handles = _palette(report)
    virtual = _virtual_links(report)
    drivers = set(report.drivers)
    edges = [(p, False) for p in m.pairs]
    edges += [(p, True) for r in report.replacements for p in r.new_pairs]
    graph = nx.MultiGraph()
    graph.add_nodes_from(m.links)
    graph.add_nodes_from(r.virtual_link for r in report.replacements)
    graph.add_edges_from((p.a, p.b, p.id) for p, _ in edges)
    pos = _graph_layout(graph, m.ground)
    rank = {n: i for i, n in enumerate(graph.nodes)}
    points = np.array(list(pos.values()))
    gaps = [
        float(np.hypot(*(points[i] - points[j])))
        for i in range(len(points))
        for j in range(i + 1, len(points))
    ]
    r = min(0.085, 0.3 * min(gaps)) if gaps else 0.085

    bundles: dict[tuple[str, str], list[tuple[Pair, bool]]] = {}
    for p, dashed in edges:
        a, b = sorted((p.a, p.b), key=rank.__getitem__)
        bundles.setdefault((a, b), []).append((p, dashed))
    spots = [*points]
    for (a, b), bundle in bundles.items():
        start, end = pos[a], pos[b]
        normal = np.array([end[1] - start[1], start[0] - end[0]])
        for i, (p, dashed) in enumerate(bundle):
            rad = 0.35 * (i - (len(bundle) - 1) / 2)
            ax.add_patch(
                FancyArrowPatch(
                    tuple(start),
                    tuple(end),
                    arrowstyle="-",
                    connectionstyle=f"arc3,rad={rad}",
                    color="0.45" if dashed else "0.15",
                    lw=1.4,
                    ls="--" if dashed else "-",
                    shrinkA=0,
                    shrinkB=0,
                    gid=f"edge:{p.id}",
                    zorder=1,
                )
            )
            mid = (start + end) / 2 + 0.5 * rad * normal
            spots.append(mid)
            ax.text(
                float(mid[0]),
                float(mid[1]),
                p.kind.value + (f" {p.point}" if p.point else ""),
                fontsize=7,
                ha="center",
                va="center",
                gid=f"edge:{p.id}",
                zorder=2,
                bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.85},
            )

    for n in graph.nodes:
        x, y = (float(v) for v in pos[n])
        c = colour.get(n, _OTHER_COLOUR)
        ink = "white"
        if n == m.ground:
            patch = Rectangle(
                (x - r, y - r),
                2 * r,
                2 * r,
                facecolor="white",
                edgecolor="black",
                hatch="////",
                lw=1.5,
                gid=f"node:{n}",
                zorder=3,
            )
            ink = "black"
        elif n in virtual:
            patch = Circle(
                (x, y),
                r,
                facecolor="white",
                edgecolor=c,
                lw=1.8,
                ls="--",
                gid=f"node:{n}",
                zorder=3,
            )
            ink = c
        else:
            patch = Circle(
                (x, y),
                r,
                facecolor=c,
                edgecolor="black",
                lw=2.5 if n in drivers else 1,
                gid=f"node:{n}",
                zorder=3,
            )
        ax.add_patch(patch)
        ax.text(
            x,
            y,
            n,
            color=ink,
            fontsize=9,
            fontweight="bold",
            ha="center",
            va="center",
            gid=f"node:{n}",
            zorder=4,
            bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none"}
            if ink == "black"
            else None,
        )

    spread = np.array(spots)
    lo, hi = spread.min(axis=0) - 2 * r, spread.max(axis=0) + 2 * r
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal", adjustable="box")
    ax.set_axis_off()
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.0, 1.0), fontsize=8)
    title = f"Kinematic graph of {m.name}" if m.name else "Kinematic graph"
    ax.set_title(f"{title}\n{report.formula}", fontsize=10)
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


@dataclass(frozen=True, eq=False)
class _Component:
    """A term of a dyad's vector equation drawn head to tail (physical units)."""

    gid: str  # 'rel:v_CB', 'comp:a^n_CB', 'comp:a^t_CB', 'comp:a^k_B3B2', 'comp:a^r_B3B2'
    text: str  # its label
    tail: np.ndarray
    vector: np.ndarray
    sup: str  # '', 'n', 'τ', 'k', 'r'


@dataclass
class _Construction:
    """What a polygon draws beyond the points' own vectors from the pole."""

    images: dict[str, np.ndarray] = field(default_factory=dict)  # points no plan point is
    components: list[_Component] = field(default_factory=list)
    nodes: list[tuple[str, str, np.ndarray]] = field(default_factory=list)  # gid, text, where
    links: list[tuple[str, list[np.ndarray]]] = field(default_factory=list)  # similar figures


_COMPONENT_STYLE = {  # colour, legend entry (plain text: mathtext is slow to lay out)
    "": ("tab:green", "relative velocity"),
    "n": ("tab:purple", "normal, ω²·l toward the pin"),
    "τ": ("tab:green", "tangential, ε·l"),
    "k": ("tab:orange", "Coriolis, 2·ω·v_rel"),
    "r": ("tab:brown", "relative, along the guide"),
}
_PLAIN_SUB = re.compile(r"[A-Za-z0-9()',.]+")


def _term_text(term: Term) -> str:
    """``$a^{\\tau}_{CB}$`` (mathtext); the plain ``a^τ_C*`` for names mathtext would misread."""
    if not _PLAIN_SUB.fullmatch(term.sub):
        return term.key
    sup = {"τ": r"\tau"}.get(term.sup, term.sup)
    top = f"^{{{sup}}}" if sup else ""
    return f"${term.letter}{top}_{{{term.sub}}}$"


def _term_gid(term: Term) -> str:
    prefix = "rel" if term.letter == "v" else "comp"
    return f"{prefix}:{term.key.replace('τ', 't')}"


def _construction(
    plan: SolvePlan, state: KinematicState, order: int, vectors: Mapping[str, np.ndarray]
) -> _Construction:
    """The dyads' relative terms head to tail, the points they need, the links' images."""
    out = _Construction()
    pts = {n: ps for n, ps in state.points.items() if n in vectors}
    size = max([1e-12] + [float(np.linalg.norm(ps.position)) for ps in pts.values()])
    speed = max([1e-12] + [float(np.linalg.norm(ps.velocity)) for ps in pts.values()])
    accel = max([1e-12] + [float(np.linalg.norm(ps.acceleration)) for ps in pts.values()])

    derived: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}  # where, v, a

    def image(label: str, link: str, where: np.ndarray) -> str:
        """The name of the point of ``link`` at ``where``: a plan point's, else ``label``."""
        v, a = point_motion(plan, state, link, where)

        def same(p: np.ndarray, pv: np.ndarray, pa: np.ndarray) -> bool:
            return bool(
                np.linalg.norm(p - where) <= 1e-9 * size
                and np.linalg.norm(pv - v) <= 1e-9 * speed
                and np.linalg.norm(pa - a) <= 1e-9 * accel
            )

        for name, ps in pts.items():
            if same(ps.position, ps.velocity, ps.acceleration):
                return name
        for name, known in derived.items():
            if same(*known):
                return name
        name = label
        while name in vectors or name in derived:
            name += "'"
        derived[name] = (where, v, a)
        out.images[name] = v if order == 1 else a
        return name

    for eq in vector_equations(plan, state, order):
        image(eq.x, eq.x_link, eq.dyad.where)
        for chain in eq.chains:
            image(chain.start, chain.start_link, chain.start_where)
            at = chain.origin
            small = 1e-9 * (speed if order == 1 else accel)
            nonzero = all(np.linalg.norm(t.vector) > small for t in chain.terms)
            for k, term in enumerate(chain.terms):
                out.components.append(
                    _Component(_term_gid(term), _term_text(term), at, term.vector, term.sup)
                )
                at = at + term.vector
                if k + 1 < len(chain.terms) and nonzero:
                    mark = "n" if term.sup == "n" else "k"
                    out.nodes.append((f"node:{mark}_{term.sub}", mark, at))

    # similar figures: the images of the points of each link that carries a marker
    m = plan.mechanism
    for link in m.moving_links:
        markers = [n for n, p in m.points.items() if p.on == link and n in pts]
        if not markers:
            continue
        pins = [p.point for p in m.pairs_of(link) if p.kind is PairKind.R and p.point in pts]
        names = list(dict.fromkeys([*pins, *markers]))
        corners = [point_motion(plan, state, link, pts[n].position)[order - 1] for n in names]
        if len(corners) >= 2:
            out.links.append((link, corners))
    return out


def _polygon(
    vectors: Mapping[str, np.ndarray],
    ax: Axes | None,
    scale: float | None,
    pole: str,
    symbol: str,
    unit: str,
    what: str,
    colour: str,
    extra: _Construction | None = None,
) -> Figure:
    fig, ax = _axes(ax, (6.0, 6.0))
    extra = extra or _Construction()
    vectors = {n: np.asarray(v, dtype=float) for n, v in vectors.items()}
    vectors.update({n: np.asarray(v, dtype=float) for n, v in extra.images.items()})
    derived = set(extra.images)
    corners_phys = [*vectors.values()]
    corners_phys += [c.tail + c.vector for c in extra.components] + [n[2] for n in extra.nodes]
    biggest = max((float(np.linalg.norm(v)) for v in corners_phys), default=0.0)
    absolute = max((float(np.linalg.norm(v)) for v in vectors.values()), default=0.0)
    shown = {
        n: v for n, v in vectors.items() if float(np.linalg.norm(v)) > 1e-9 * max(absolute, 1e-12)
    }
    if scale is None:
        scale = _nice(biggest / 100.0) if biggest > 0 else 1.0
    if not scale > 0:
        raise ValueError(f"scale must be positive, got {scale}")
    tips = {n: v / scale for n, v in shown.items()}
    extent = max((float(np.abs(v).max()) for v in corners_phys), default=0.0) / scale or 1.0
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
                "lw": 1.2 if name in derived else 2.2,
                "alpha": 0.75,
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

    corners = [np.zeros(2), *tips.values()]
    corners += _draw_components(ax, extra, scale, absolute, nudge)
    for link, images in extra.links:
        xy = np.array(images) / scale
        if len(xy) > 2:
            xy = np.vstack([xy, xy[:1]])
        ax.plot(xy[:, 0], xy[:, 1], ls=":", color="0.5", lw=1.0, zorder=1, gid=f"image:{link}")
    if extra.components:
        handles = [Line2D([], [], color=colour, lw=2.2, alpha=0.75, label=f"absolute, from {pole}")]
        kinds = dict.fromkeys(c.sup for c in extra.components)
        for sup in kinds:
            c, entry = _COMPONENT_STYLE[sup]
            handles.append(Line2D([], [], color=c, lw=1.2, label=entry))
        ax.legend(
            handles=handles,
            loc="upper center",
            bbox_to_anchor=(0.5, -0.05),
            ncol=2,
            fontsize=7,
            frameon=False,
        )

    corners_arr = np.array(corners)
    lo, hi = corners_arr.min(axis=0), corners_arr.max(axis=0)
    pad = 0.12 * max(float((hi - lo).max()), extent)
    lo, hi = lo - pad, hi + pad
    span = hi - lo
    grow = np.maximum(0.6 * span.max() - span, 0.0) / 2  # not a sliver: room for the labels
    lo, hi = lo - grow, hi + grow
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal", adjustable="box")
    ax.axhline(0.0, color="0.85", lw=0.6, zorder=0)
    ax.axvline(0.0, color="0.85", lw=0.6, zorder=0)
    ax.set_title(f"{what}, {symbol} = {scale:.6g} {unit}/unit")
    return fig


def _draw_components(
    ax: Axes, extra: _Construction, scale: float, absolute: float, nudge: float
) -> list[np.ndarray]:
    """Each term an arrow from its tail (a dot when zero) with its label; the corners drawn."""
    corners: list[np.ndarray] = []
    labels: list[np.ndarray] = []
    longest = max((float(np.linalg.norm(c.vector)) for c in extra.components), default=0.0)
    zero = 1e-9 * max(absolute, longest, 1e-12)

    def spot(anchor: np.ndarray, away: np.ndarray) -> np.ndarray:
        at = anchor + away
        while any(np.linalg.norm(at - q) < 1.2 * nudge for q in labels):
            at = at + away
        labels.append(at)
        return at

    for c in extra.components:
        colour = _COMPONENT_STYLE[c.sup][0]
        tail = c.tail / scale
        tip = (c.tail + c.vector) / scale
        corners += [tail, tip]
        if float(np.linalg.norm(c.vector)) <= zero:
            ax.plot([tail[0]], [tail[1]], "o", mfc="none", mec=colour, ms=5, gid=c.gid)
            at = spot(tail, np.array([1.2, -1.0]) * nudge)
            text = _zero_text(c.text)
            ax.text(*at, text, color=colour, fontsize=8, ha="left", va="center", gid=c.gid)
            continue
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(float(tail[0]), float(tail[1])),
            arrowprops={
                "arrowstyle": "-|>",
                "color": colour,
                "lw": 1.2,
                "shrinkA": 0,
                "shrinkB": 0,
            },
            gid=c.gid,
        )
        d = tip - tail
        normal = np.array([-d[1], d[0]]) / (float(np.hypot(*d)) or 1.0) * nudge
        at = spot((tail + tip) / 2, normal)
        ax.text(*at, c.text, color=colour, fontsize=9, ha="center", va="center", gid=c.gid)
    for gid, text, where in extra.nodes:
        xy = where / scale
        ax.plot([xy[0]], [xy[1]], "o", color="0.3", ms=3, gid=gid)
        at = spot(xy, np.array([-1.0, 1.0]) * 0.7 * nudge)
        ax.text(*at, text, color="0.3", fontsize=7, ha="center", va="center", gid=gid)
    return corners


def _zero_text(text: str) -> str:
    """``$v_{CB}$`` → ``$v_{CB} = 0$``."""
    return text[:-1] + " = 0$" if text.endswith("$") else text + " = 0"


def velocity_polygon(
    plan: SolvePlan, state: KinematicState, ax: Axes | None = None, scale: float | None = None
) -> Figure:
    """Velocity polygon: pole p, each point's vector, each dyad's relative velocities.

    Parameters
    ----------
    plan : SolvePlan
    state : KinematicState
        A solved pose of ``plan``.
    ax : Axes, optional
        Draw on it (default: a new figure).
    scale : float, optional
        μ_v in (m/s) per drawing unit (default: a round number, ~100 units for
        the longest vector).

    Returns
    -------
    Figure

    Notes
    -----
    Each moving point's velocity is an arrow p→x (gid ``arrow:<name>``, label
    ``label:<name>``). For each dyad (class II group) the terms of its vector
    equation (:mod:`kinematics.polygons`) are drawn from the known point's
    image to X's: for an RRR dyad B–C–D the arrows b→c (``rel:v_CB``, ⊥BC) and
    d→c (``rel:v_CD``, ⊥CD); for a slider, the relative sliding velocity from
    the guide point's image (``rel:v_B3B2``, ∥ the guide). The point of a
    guide or of a slotted link under X (``B3``) that no named point stands
    for is added, with its arrow from p. A zero term is a circle, its label
    ``v_CB = 0``; every label is a ``Text`` with the arrow's gid. The images
    of the points of a link with markers are joined by a dotted line (gid
    ``image:<link>``): the figure similar to the link. Triads and higher
    groups are solved as a whole: only their points' vectors are drawn.
    """
    vectors = {n: state.points[n].velocity for n in plan.points if n in state.points}
    extra = _construction(plan, state, 1, vectors)
    return _polygon(vectors, ax, scale, "p", "μ_v", "(m/s)", "Velocity polygon", "tab:blue", extra)


def acceleration_polygon(
    plan: SolvePlan, state: KinematicState, ax: Axes | None = None, scale: float | None = None
) -> Figure:
    """Acceleration polygon: pole π, each point's vector, each dyad's components head to tail.

    Parameters
    ----------
    plan : SolvePlan
    state : KinematicState
        A solved pose of ``plan``.
    ax : Axes, optional
        Draw on it (default: a new figure).
    scale : float, optional
        μ_a in (m/s²) per drawing unit (default: a round number).

    Returns
    -------
    Figure

    Notes
    -----
    Each moving point's acceleration is an arrow π→x' (gid ``arrow:<name>``).
    For each dyad, from the image of a pin B that X turns about: the normal
    component (gid ``comp:a^n_CB``, ∥CB from C to B, ω²·l_BC) to the
    intermediate point n_CB (gid ``node:n_CB``), then the tangential one
    (``comp:a^t_CB``, ⊥BC, ε·l_BC) to x'; from the image of a guide's point
    under X: the Coriolis component (``comp:a^k_B3B2``, 2·ω_guide·v_rel, the
    relative velocity turned 90° in the sense of the guide's ω) to k_B3B2,
    then the relative one (``comp:a^r_B3B2``, ∥ the guide). A zero component
    is a circle at its tail, labelled ``a^n_CB = 0``; labels are ``Text`` s
    with the arrow's gid. Triads and higher groups are solved as a whole:
    only their points' vectors are drawn.
    """
    vectors = {n: state.points[n].acceleration for n in plan.points if n in state.points}
    extra = _construction(plan, state, 2, vectors)
    return _polygon(
        vectors, ax, scale, "π", "μ_a", "(m/s²)", "Acceleration polygon", "tab:red", extra
    )


# ---------------------------------------------------------------- force polygons


@dataclass(frozen=True)
class _Force:
    key: str  # the arrow's gid is 'force:<key>'
    label: str
    vector: np.ndarray
    kind: str  # 'load', 'weight', 'inertia', 'reaction', 'balance' or 'rest'


_FORCE_COLOURS = {
    "load": "tab:red",
    "weight": "tab:green",
    "inertia": "tab:orange",
    "reaction": "tab:blue",
    "balance": "black",
    "rest": "0.5",
}


def _pair_label(a: str, b: str) -> str:
    return f"R{a}{b}" if len(a) == 1 and len(b) == 1 else f"R{a},{b}"


def _forces_on(
    plan: SolvePlan,
    solution: ForceSolution,
    links: set[str],
    state: KinematicState | None,
    with_balance: bool,
) -> list[_Force]:
    """The external forces on the set ``links``: loads, inertia, reactions (and balancing force).

    A reaction counts when it joins a link of the set to one outside it; what
    the outside link exerts on the set is ``force`` or ``−force`` by the
    reaction's orientation. A higher pair's contact force is carried by its
    virtual link's pairs, so its own entry is skipped; the labels name the
    real links in contact.
    """
    m = plan.mechanism
    out: list[_Force] = []
    keys: set[str] = set()

    def add(key: str, label: str, vector, kind: str) -> None:
        base, k = key, 1
        while key in keys:
            k += 1
            key = f"{base}#{k}"
        keys.add(key)
        out.append(_Force(key, label, np.asarray(vector, dtype=float), kind))

    gravity = np.zeros(2)
    for load in m.loads:
        if load.kind == "gravity":
            gravity = np.array(load.values, dtype=float)
    for load in m.loads:
        if load.link not in links:
            continue
        if load.kind == "force":
            add(f"load:{load.link}:{load.point}", f"P{load.link}", load.values, "load")
        elif load.kind == "mass":
            mass = load.values[0]
            if np.any(gravity):
                add(f"weight:{load.link}", f"G{load.link}", mass * gravity, "weight")
            if state is None:
                state = solve_pose(plan)
            ls = state.links.get(load.link)
            c = _xy(m, load.point)
            if ls is None or c is None:
                continue
            theta, omega, eps = float(ls.q[2]), float(ls.qd[2]), float(ls.qdd[2])
            rc = _place({load.link: np.array([0.0, 0.0, theta])}, load.link, c)
            a_s = np.asarray(ls.qdd[:2], dtype=float) + eps * np.array([-rc[1], rc[0]])
            a_s = a_s - omega**2 * rc
            add(f"inertia:{load.link}", f"Φ{load.link}", -mass * a_s, "inertia")

    contact = {v: (a, b) for v, a, b, _ in plan.contacts}

    def real(name: str, partner: str) -> str:
        if name in contact:
            a, b = contact[name]
            return b if partner == a else a
        return name

    for r in solution.reactions:
        if r.kind == "H":
            continue
        a, b = r.links
        if (a in links) == (b in links):
            continue
        if b in links:
            source, target, force = a, b, np.asarray(r.force, dtype=float)
        else:
            source, target, force = b, a, -np.asarray(r.force, dtype=float)
        label = _pair_label(real(source, target), real(target, source))
        add(f"reaction:{source}->{target}:{r.point}", label, force, "reaction")
    if with_balance and solution.balancing_force is not None:
        balance = next((x for x in m.loads if x.kind == "balance"), None)
        if balance is not None and balance.link in links:
            add(f"balance:{balance.link}", "P_cb", solution.balancing_force, "balance")
    if with_balance:  # a sliding driver's balancing "moment" is a force along its slide
        for d in plan.drivers:
            if d.kind == "P" and d.link in links and d.link in solution.balancing_moment:
                push = solution.balancing_moment[d.link] * np.asarray(d.direction, dtype=float)
                add(f"balance:{d.link}", "P_cb", push, "balance")
    total = sum((f.vector for f in out), np.zeros(2))
    biggest = max((float(np.hypot(*f.vector)) for f in out), default=0.0)
    if float(np.hypot(*total)) > 1e-7 * max(biggest, 1e-12):
        add("rest", "rest (friction)", -total, "rest")
    return out


def _draw_forces(ax: Axes, forces: list[_Force], scale: float | None, what: str, note: str) -> None:
    biggest = max((float(np.hypot(*f.vector)) for f in forces), default=0.0)
    shown = [f for f in forces if float(np.hypot(*f.vector)) > 1e-9 * max(biggest, 1e-12)]
    if scale is None:
        scale = _nice(biggest / 100.0) if biggest > 0 else 1.0
    if not scale > 0:
        raise ValueError(f"scale must be positive, got {scale}")
    tail = np.zeros(2)
    corners = [tail]
    extent = biggest / scale or 1.0
    for f in shown:
        tip = tail + f.vector / scale
        c = _FORCE_COLOURS[f.kind]
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(float(tail[0]), float(tail[1])),
            arrowprops={"arrowstyle": "-|>", "color": c, "lw": 1.6, "shrinkA": 0, "shrinkB": 0},
            gid=f"force:{f.key}",
        )
        d = tip - tail
        n = np.array([-d[1], d[0]]) / (np.hypot(*d) or 1.0) * 0.04 * extent
        mid = (tail + tip) / 2 + n
        ax.text(
            float(mid[0]),
            float(mid[1]),
            f.label,
            color=c,
            fontsize=10,
            ha="center",
            va="center",
            gid=f"label:{f.key}",
        )
        tail = tip
        corners.append(tip)
    ax.plot([0.0], [0.0], "o", color="black", ms=4, gid="start")
    sizes = [f"{f.label} = {float(np.hypot(*f.vector)):.4g} N" for f in shown]
    rows = [", ".join(sizes[i : i + 3]) for i in range(0, len(sizes), 3)]
    ax.set_xlabel("\n".join(rows), fontsize=9)
    ax.xaxis.label.set_gid("table")
    pts = np.array(corners)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.12 * max(float((hi - lo).max()), extent)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.axhline(0.0, color="0.85", lw=0.6, zorder=0)
    ax.axvline(0.0, color="0.85", lw=0.6, zorder=0)
    title = f"Forces on {what}, μ_F = {scale:.6g} N/unit"
    ax.set_title(title + (f"\n{note}" if note else ""), fontsize=10)


def _polygon_entries(plan: SolvePlan, solution: ForceSolution) -> list[tuple[str, set[str], str]]:
    """(label, links, note) of each group in solve order, then of each driver."""
    entries = [(s.label, set(s.links), "") for s in plan.steps if s.group is not None]
    for d in plan.drivers:
        note = ""
        if d.link in solution.balancing_moment and d.kind == "P":
            value = solution.balancing_moment[d.link]
            note = f"balancing force P_cb = {value:.6g} N along the slide"
        elif d.link in solution.balancing_moment:
            note = f"balancing moment M_cb = {solution.balancing_moment[d.link]:.6g} N·m"
        elif solution.balancing_force is not None:
            note = f"balancing force P_cb = {float(np.hypot(*solution.balancing_force)):.6g} N"
        entries.append((f"I({d.link})", {d.link}, note))
    return entries


def force_polygon(
    plan: SolvePlan,
    solution: ForceSolution,
    group_label: str | None = None,
    *,
    ax: Axes | None = None,
    scale: float | None = None,
    state: KinematicState | None = None,
) -> Figure:
    """Force polygon of each Assur group and of each driver, to scale.

    For a group: its applied loads, its inertia loads (−m·a_S, with the weight
    m·g apart) and the reactions at its outer pairs (including those of the
    groups attached to it), head to tail from the origin; they add up to
    zero, so the polygon closes. For a driver (``'I(1)'``): the same with the
    reaction of the frame and the balancing force, the balancing moment in
    the title.

    Parameters
    ----------
    plan : SolvePlan
    solution : ForceSolution
        From :func:`kinematics.forces.solve_forces` at the sketch pose (or at
        the pose of ``state``).
    group_label : str, optional
        One group (``'II(2,3)'``) or driver (``'I(1)'``); all of them by default.
    ax : Axes, optional
        Draw one polygon on these axes (``group_label`` is then required
        unless there is only one).
    scale : float, optional
        μ_F in N per drawing unit; a round number by default.
    state : KinematicState, optional
        The pose of ``solution`` for inertia loads (default: the sketch pose).

    Returns
    -------
    Figure

    Raises
    ------
    ValueError
        ``group_label`` names no group or driver, or ``scale`` is not positive.

    Examples
    --------
    >>> from structure.edgelist import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.plan import make_plan
    >>> from kinematics.forces import solve_forces
    >>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0", "point B 0.1 0",
    ...                     "force 1 B 0 -100"])
    >>> plan = make_plan(analyze(m))
    >>> ax = force_polygon(plan, solve_forces(plan), "I(1)").axes[0]
    >>> ax.get_title().splitlines()
    ['Forces on driver 1, μ_F = 1 N/unit', 'balancing moment M_cb = 10 N·m']
    """
    entries = _polygon_entries(plan, solution)
    if group_label is not None:
        entries = [e for e in entries if e[0] == group_label]
        if not entries:
            known = ", ".join(e[0] for e in _polygon_entries(plan, solution))
            raise ValueError(f"no group or driver {group_label!r}: they are {known}")
    if ax is not None and len(entries) != 1:
        raise ValueError("drawing on given axes needs one group_label")
    if ax is not None:
        fig, axes = ax.figure, [ax]
    else:
        cols = min(len(entries), 3)
        rows = math.ceil(len(entries) / cols)
        fig = Figure(figsize=(6.2 * cols, 5.0 * rows))
        FigureCanvasAgg(fig)
        axes = list(np.atleast_1d(fig.subplots(rows, cols)).ravel())
        for extra in axes[len(entries) :]:
            fig.delaxes(extra)
    for (label, links, note), target in zip(entries, axes, strict=False):
        is_driver = label.startswith("I(")
        forces = _forces_on(plan, solution, links, state, with_balance=is_driver)
        what = f"driver {label[2:-1]}" if is_driver else label
        _draw_forces(target, forces, scale, what, note)
    if ax is None:
        fig.tight_layout()
    return fig


# ---------------------------------------------------------------- sweeps


def _input_axis(result: Sweep, plan: SolvePlan | None) -> tuple[np.ndarray, str]:
    """The first input in degrees (a rotation) or metres (a slide), and its axis label."""
    x = np.asarray(result.inputs[:, 0], dtype=float)
    name = plan.drivers[0].link if plan is not None and plan.drivers else "1"
    if plan is not None and plan.drivers and plan.drivers[0].kind == "P":
        return x, f"driver {name}: displacement from the sketch (m)"
    return np.degrees(x), f"driver {name}: rotation from the sketch (°)"


def sweep_figure(result: Sweep, plan: SolvePlan | None = None) -> Figure:
    """The sweep's curves against the input: paths, ω, ε, \\|v\\|, \\|a\\|, μ, balancing.

    Panels: the points' paths in the plane (coupler curves; the fixed points
    as dots), each link's ω and ε, each moving point's speed and acceleration
    magnitude, each dyad's transmission angle (degrees) and, when the file has
    loads, the balancing moment (or force), all against the first input in
    degrees (metres for a sliding driver, when ``plan`` says so).

    Parameters
    ----------
    result : Sweep
        From :func:`kinematics.sweep.sweep`.
    plan : SolvePlan, optional
        Names the driver and tells a rotation from a slide.

    Returns
    -------
    Figure

    Examples
    --------
    >>> from structure.edgelist import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.plan import make_plan
    >>> from kinematics.sweep import sweep
    >>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
    ...                     "point A 0 0", "point B 0.1 0", "point C 0.3 0.3", "point D 0.4 0"])
    >>> fig = sweep_figure(sweep(make_plan(analyze(m)), steps=12))
    >>> sorted(ln.get_gid() for ln in fig.axes[1].lines)
    ['omega:1', 'omega:2', 'omega:3']
    """
    x, xlabel = _input_axis(result, plan)
    panels = 7 if result.balancing else 6
    cols = 4 if result.balancing else 3
    fig = Figure(figsize=(4.6 * cols, 8.0))
    FigureCanvasAgg(fig)
    axes = list(fig.subplots(2, cols).ravel())
    for extra in axes[panels:]:
        fig.delaxes(extra)
    paths, omega, epsilon, speed, accel, trans = axes[:6]

    positions = {n: np.asarray(v["position"], dtype=float) for n, v in result.points.items()}
    reach = np.array([p for v in positions.values() for p in v]) if positions else np.zeros((1, 2))
    size = float(np.ptp(reach, axis=0).max()) or 1.0
    moving = [n for n, p in positions.items() if float(np.ptp(p, axis=0).max()) > 1e-9 * size]
    for name in moving:
        p = positions[name]
        paths.plot(p[:, 0], p[:, 1], lw=1.3, label=name, gid=f"path:{name}")
    for name, p in positions.items():
        if name not in moving:
            paths.plot(p[:1, 0], p[:1, 1], "k^", ms=5, gid=f"fixed:{name}")
            paths.annotate(name, (float(p[0, 0]), float(p[0, 1])), fontsize=7)
    paths.set_aspect("equal", adjustable="datalim")
    paths.set_title("Paths of the points (coupler curves)", fontsize=10)
    paths.set_xlabel("x (m)")
    paths.set_ylabel("y (m)")

    for name, values in result.links.items():
        omega.plot(x, values["omega"], lw=1.3, label=name, gid=f"omega:{name}")
        epsilon.plot(x, values["epsilon"], lw=1.3, label=name, gid=f"epsilon:{name}")
    omega.set_title("Angular velocity ω", fontsize=10)
    omega.set_ylabel("ω (rad/s)")
    epsilon.set_title("Angular acceleration ε", fontsize=10)
    epsilon.set_ylabel("ε (rad/s²)")
    for name in moving:
        v = np.asarray(result.points[name]["velocity"], dtype=float)
        a = np.asarray(result.points[name]["acceleration"], dtype=float)
        speed.plot(x, np.hypot(v[:, 0], v[:, 1]), lw=1.3, label=name, gid=f"speed:{name}")
        accel.plot(x, np.hypot(a[:, 0], a[:, 1]), lw=1.3, label=name, gid=f"accel:{name}")
    speed.set_title("Speed |v| of the points", fontsize=10)
    speed.set_ylabel("|v| (m/s)")
    accel.set_title("Acceleration |a| of the points", fontsize=10)
    accel.set_ylabel("|a| (m/s²)")
    for label, mu in result.transmission.items():
        trans.plot(x, np.degrees(mu), lw=1.3, label=label, gid=f"transmission:{label}")
    if not result.transmission:
        trans.text(
            0.5,
            0.5,
            "no dyad with a transmission angle",
            ha="center",
            va="center",
            transform=trans.transAxes,
            fontsize=9,
        )
    trans.set_title("Transmission angle μ", fontsize=10)
    trans.set_ylabel("μ (°)")
    chosen = [omega, epsilon, speed, accel, trans]
    if result.balancing:
        bal = axes[6]
        for name, values in result.balancing.items():
            bal.plot(x, values, lw=1.3, label=name, gid=f"balancing:{name}")
        bal.set_title("Balancing moment (force)", fontsize=10)
        bal.set_ylabel("M_cb (N·m) or P_cb (N)")
        chosen.append(bal)
    for ax in chosen:
        ax.set_xlabel(xlabel, fontsize=8)
        ax.grid(True, lw=0.4, alpha=0.6)
        if ax.lines:
            ax.legend(fontsize=7, ncol=2 if len(ax.lines) > 6 else 1)
    if paths.lines and moving:
        paths.legend(fontsize=7, ncol=2 if len(moving) > 6 else 1)
    fig.tight_layout()
    return fig


# ---------------------------------------------------------------- sheets


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
        From :func:`kinematics.forces.solve_forces` at the pose of ``state``.
    state : KinematicState, optional
        The pose (default: the sketch's).

    Returns
    -------
    Figure
    """
    state = solve_pose(plan) if state is None else state
    entries = _polygon_entries(plan, solution)
    panels = 1 + len(entries)
    cols = min(panels, 3)
    rows = math.ceil(panels / cols)
    fig = Figure(figsize=(6.2 * cols, 5.2 * rows))
    FigureCanvasAgg(fig)
    axes = list(np.atleast_1d(fig.subplots(rows, cols)).ravel())
    for extra in axes[panels:]:
        fig.delaxes(extra)
    draw_mechanism(report, plan, state, ax=axes[0])
    _draw_loads(axes[0], plan, state)
    for (label, _, _), ax in zip(entries, axes[1:], strict=False):
        force_polygon(plan, solution, label, ax=ax, state=state)
    fig.tight_layout()
    return fig


def _draw_loads(ax: Axes, plan: SolvePlan, state: KinematicState) -> None:
    """The applied forces on the mechanism: an arrow ending at each load's point (gid ``load:``)."""
    m = plan.mechanism
    poses = _state_poses(state)
    forces = [x for x in m.loads if x.kind == "force" and _xy(m, x.point) is not None]
    biggest = max((float(np.hypot(*x.values)) for x in forces), default=0.0)
    if biggest <= 0:
        return
    reach = 0.25 * (plan.length or 1.0)
    for load in forces:
        tip = _place(poses, load.link, _xy(m, load.point))
        tail = tip - np.asarray(load.values, dtype=float) / biggest * reach
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(float(tail[0]), float(tail[1])),
            arrowprops={"arrowstyle": "-|>", "color": _FORCE_COLOURS["load"], "lw": 1.8},
            gid=f"load:{load.link}:{load.point}",
            zorder=8,
        )
        ax.text(
            float(tail[0]),
            float(tail[1]),
            f"P{load.link}",
            color=_FORCE_COLOURS["load"],
            fontsize=10,
            ha="center",
            va="bottom",
            gid=f"load:{load.link}:{load.point}",
        )
