"""The mechanism's artists at a pose, one drawing function per element, moved with the links.

:func:`draw_scene` draws a mechanism on given axes and returns the
:class:`Scene` that moves its artists to other poses (which
:func:`kinematics.figures.mechanism.draw_mechanism` draws once and
:func:`kinematics.figures.animation.animate` moves for each frame). Each
link's outline is a ``Line2D`` (a link with three or more points also a
filled ``Polygon``) with gid ``link:<name>``, dashed for the virtual links of
a higher-pair replacement; pins are ``Circle`` patches (gid ``pin:<point>``),
sliders ``Polygon`` blocks (gid ``slider:<pair id>``) on a dashed guide line
(gid ``guide:<pair id>``); the ground is hatched (gid ``ground``). A higher
pair is drawn as its contacting profiles (gid ``profile:<pair id>:<link>``:
the osculating circles of the curved profiles, the flat face, the roller), a
gear mesh as its pitch circles (gid ``pitch:<pair id>:<link>``), the contact
as a dot (gid ``contact:<point>``). Markers are dots (gid
``marker:<name>``), the drivers carry an arrow of their motion (gid
``driver:<link>``). Labels are ``Text`` objects with gid ``link:<name>`` and
``point:<name>``. The legend handles are one entry per Assur group
(``"II(2,3) RRR, order 2"``) in the group's colour, then one per driver
(``"driver 1"``) in black, then a dashed ``"virtual link"`` entry when
higher pairs were replaced (:func:`kinematics.figures.style.palette`).

The scene draws in the drawing unit of :func:`kinematics.figures.style.drawing_unit`
(``Scene.unit`` metres: 1 for any ordinary mechanism, 10⁻³⁰³ for one 1e-302 m
across, which matplotlib could not draw in metres); :meth:`Scene.update` takes
the poses in metres.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
from matplotlib.axes import Axes
from matplotlib.colors import to_rgba
from matplotlib.lines import Line2D
from matplotlib.patches import Arc, Circle, FancyArrowPatch, Polygon

from structure.model import Pair, PairKind
from structure.report import StructuralReport

from ..cams.contact import contact_at, sketch_profile
from ..solvers.plan import SolvePlan
from .style import (
    DRIVER_COLOUR,
    OTHER_COLOUR,
    Poses,
    drawing_unit,
    length,
    palette,
    place,
    virtual_links,
)

__all__ = ["Scene", "draw_scene"]


def _turn(poses: Poses, link: str) -> float:
    """The angle (rad) ``link`` has turned from the sketch (0 when not posed)."""
    q = poses.get(link)
    return 0.0 if q is None else float(q[2])


@dataclass(frozen=True)
class _Sketch:
    """The named points of the sketch in drawing units (``unit`` metres each)."""

    unit: float
    xy: Mapping[str, np.ndarray]

    def at(self, name: str | None) -> np.ndarray | None:
        """Point ``name`` in drawing units (None: no name, or no coordinates)."""
        return None if name is None else self.xy.get(name)


def _sketch_in_units(report: StructuralReport, plan: SolvePlan, unit: float) -> _Sketch:
    """Every named point of the plan's and the report's mechanisms and of the plan, in units."""
    xy: dict[str, np.ndarray] = {}
    for m in (report.mechanism, plan.mechanism):
        for name, p in m.points.items():
            xy.setdefault(name, np.array([p.x, p.y], dtype=float) / unit)
    for name, (_, c) in plan.points.items():
        xy.setdefault(name, np.asarray(c, dtype=float) / unit)
    return _Sketch(unit, MappingProxyType(xy))


def _link_points(
    plan: SolvePlan, sketch: _Sketch, link: str, virtual: set[str]
) -> dict[str, np.ndarray]:
    """The named sketch points of ``link`` (drawing units): its pair points and its markers.

    A real link leaves out the point of a virtual link's slide along its flat
    face (that point is on the slide line, not on the link's body).
    """
    m = plan.mechanism
    out: dict[str, np.ndarray] = {}
    for pair in m.pairs_of(link):
        if pair.kind is PairKind.P and link not in virtual and pair.other(link) in virtual:
            continue
        xy = sketch.at(pair.point)
        if xy is not None and pair.point not in out:
            out[pair.point] = xy
    for name, (owner, _) in plan.points.items():
        if owner == link and name not in out:
            out[name] = sketch.xy[name]
    for name, p in m.points.items():
        if p.on == link and name not in out:
            out[name] = sketch.xy[name]
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
    """Points sorted by angle about their centroid (a ring's outline)."""
    centre = np.mean(points, axis=0)
    return sorted(points, key=lambda p: math.atan2(p[1] - centre[1], p[0] - centre[0]))


def _rectangle(centre: np.ndarray, angle: float, length: float, width: float) -> np.ndarray:
    """Corners of a ``length`` × ``width`` rectangle at ``centre`` turned by ``angle``."""
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


class Scene:
    """The artists of a mechanism drawing and the functions that move them with the links.

    Attributes
    ----------
    unit : float
        The drawing unit in metres (1 unless the mechanism is far from metres).
    size : float
        The mechanism's size in drawing units: the scale of pins, sliders and arrows.
    anchors : list of (str, ndarray)
        Each link's sketch points in drawing units (to bound a whole motion).
    artists : list
        The artists that move, to redraw them alone.
    virtual : dict of str to list
        The artists of each virtual link.
    """

    def __init__(self, size: float, unit: float = 1.0) -> None:
        self.unit = unit
        self.size = size
        self.anchors: list[tuple[str, np.ndarray]] = []
        self.artists: list = []
        self.virtual: dict[str, list] = {}
        self._moves: list[Callable[[Poses], None]] = []

    def drawn(self, poses: Poses) -> dict[str, np.ndarray]:
        """Poses ``{link: (x, y, θ)}`` in metres as poses in drawing units."""
        return {
            link: np.array([q[0] / self.unit, q[1] / self.unit, q[2]], dtype=float)
            for link, q in poses.items()
        }

    def follow(self, move: Callable[[Poses], None], *artists) -> None:
        """Call ``move(poses)`` on every update; it moves ``artists``."""
        self._moves.append(move)
        self.artists.extend(artists)

    def update(self, poses: Poses) -> None:
        """Move every artist to the links' poses ``{link: (x, y, θ)}`` (metres, radians)."""
        if self.unit != 1.0:
            poses = self.drawn(poses)
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


def _pitch_circles(
    mechanism, sketch: _Sketch, pair: Pair, contact: np.ndarray | None
) -> list[_Profile]:
    """Pitch circles of a gear mesh: radius m·z/2 (``module=``), else the axis–contact distance."""
    out = []
    teeth = pair.teeth or (None, None)
    for link, z in zip((pair.a, pair.b), teeth, strict=True):
        known = pair.module * z / 2 / sketch.unit if pair.module and z else None
        pins = [
            q
            for q in mechanism.pairs_of(link)
            if q.kind is PairKind.R and sketch.at(q.point) is not None
        ]
        if not pins:
            continue
        if known is not None and contact is not None:
            axis = min(
                (sketch.at(q.point) for q in pins),
                key=lambda c: abs(length(c - contact) - known),
            )
        elif link == mechanism.ground:
            continue  # which of the frame's pivots is the gear's axis is not known
        else:
            to_ground = [q for q in pins if q.other(link) == mechanism.ground]
            axis = sketch.at((to_ground or pins)[0].point)
        radius = known
        if radius is None and contact is not None:
            radius = length(axis - contact)
        if radius and radius > 0:
            out.append(_Profile(pair, link, link, "pitch", axis, radius, 0.0))
    return out


def _profiles(report: StructuralReport, sketch: _Sketch, size: float) -> list[_Profile]:
    """The contact curves of every replaced higher pair, at the sketch (drawing units)."""
    m = report.mechanism
    out: list[_Profile] = []
    for r in report.replacements:
        p = r.pair
        contact = sketch.at(p.point)
        if p.gear:
            out.extend(_pitch_circles(m, sketch, p, contact))
            continue
        if contact is None:
            continue
        for link in (p.a, p.b):
            if r.roller is not None and link == r.roller.roller:
                axis = sketch.at(r.roller.axis)
                if axis is not None:
                    radius = length(axis - contact)
                    out.append(_Profile(p, link, r.roller.follower, "roller", axis, radius, 0.0))
                continue
            if p.flat == link:
                face = next((q.angle for q in r.new_pairs if q.kind is PairKind.P), None)
                if face is not None:
                    out.append(_Profile(p, link, link, "flat", contact, 0.0, face))
                continue
            centre = sketch.at(p.center_of(link))
            if centre is None:
                continue
            radius = length(centre - contact)
            if radius <= 1e-9 * size:
                continue  # a knife edge: the contact dot is its profile
            toward = math.atan2(contact[1] - centre[1], contact[0] - centre[0])
            kind = "circle" if radius <= 1.5 * size else "arc"
            out.append(_Profile(p, link, link, kind, centre, radius, toward))
    return out


def _contact_carrier(plan: SolvePlan, pair: Pair) -> str:
    """The real link of a higher pair that carries its contact point."""
    links = plan.mechanism.links
    return pair.a if pair.a in links else pair.b


@dataclass(frozen=True)
class _SceneStyle:
    """What every element of a scene is drawn with: the links' colours and the scene's size."""

    colour: Mapping[str, str]  # each link's group colour (drivers black)
    ground: str
    virtual: set[str]
    size: float  # drawing units
    sketch: _Sketch

    @property
    def pin_radius(self) -> float:
        """The radius of a pin's circle."""
        return 0.015 * self.size

    @property
    def offset(self) -> float:
        """How far a label sits from its point."""
        return 0.02 * self.size

    def tint(self, link: str) -> str:
        """The colour of ``link``: its group's, black for the ground, grey otherwise."""
        return self.colour.get(link, DRIVER_COLOUR if link == self.ground else OTHER_COLOUR)


def draw_scene(
    report: StructuralReport, plan: SolvePlan, ax: Axes, poses: Poses
) -> tuple[Scene, list[Line2D]]:
    """Draw the mechanism at ``poses`` on ``ax``; the scene moves it to other poses.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis (group colours, drivers, replacements).
    plan : SolvePlan
        Its solve plan.
    ax : Axes
        Where to draw; its limits and legend are left to the caller.
    poses : Poses
        Each link's pose ``{link: (x, y, θ)}``.

    Returns
    -------
    Scene
        The artists drawn and how they move (:meth:`Scene.update`).
    list of Line2D
        The legend handles: the groups, the drivers, the virtual links.
    """
    m = plan.mechanism
    colour, handles = palette(report)
    virtual = virtual_links(report)
    sketch = _sketch_in_units(report, plan, drawing_unit(plan.length))
    bodies = {link: _link_points(plan, sketch, link, virtual) for link in m.moving_links}
    scene = Scene(1.0, sketch.unit)
    size = _scene_size(plan, sketch, bodies, scene.drawn(poses))
    scene.size = size
    designed = {(c.pair.id, c.cam) for c in plan.cams}  # drawn from their programs below
    profiles = [p for p in _profiles(report, sketch, size) if (p.pair.id, p.link) not in designed]
    for prof in profiles:
        if prof.kind == "flat" and prof.link in bodies and prof.pair.point:
            bodies[prof.link].setdefault(prof.pair.point, prof.centre)
    style = _SceneStyle(colour, m.ground, virtual, size, sketch)
    _draw_links(ax, scene, bodies, style)
    _draw_profiles(ax, scene, profiles, style)
    _draw_cams(ax, scene, plan, style)
    _draw_contacts(ax, scene, report, plan, style)
    _draw_sliders(ax, scene, plan, style)
    _draw_pins(ax, scene, report, plan, style)
    _draw_points(ax, scene, plan, style)
    for d in plan.drivers:
        _draw_driver(ax, scene, plan, d, bodies.get(d.link, {}), style)
    scene.update(poses)
    return scene, handles


def _scene_size(
    plan: SolvePlan,
    sketch: _Sketch,
    bodies: Mapping[str, Mapping[str, np.ndarray]],
    poses: Poses,
) -> float:
    """The larger span of the sketch and of the pose, at least the plan's length (drawing units).

    ``poses`` are in drawing units too.
    """
    reach = (plan.length or 0.0) / sketch.unit
    sketch_span = [xy for pts in bodies.values() for xy in pts.values()]
    sketch_span += [
        xy for pair in plan.mechanism.pairs if (xy := sketch.at(pair.point)) is not None
    ]
    if not sketch_span:
        return float(reach or 1.0)
    world = np.array([place(poses, lk, xy) for lk, pts in bodies.items() for xy in pts.values()])
    span = float(np.ptp(np.array(sketch_span), axis=0).max())
    if len(world):
        span = max(span, float(np.ptp(world, axis=0).max()))
    return float(max(span, reach) or 1.0)


def _draw_links(
    ax: Axes, scene: Scene, bodies: Mapping[str, Mapping[str, np.ndarray]], style: _SceneStyle
) -> None:
    """Each link's outline, filled body (a ternary link) and label; the virtual ones dashed."""
    for link, pts in bodies.items():
        if not pts:
            continue
        scene.anchors.append((link, np.array(list(pts.values()))))
        before = len(scene.artists)
        is_virtual = link in style.virtual
        _draw_link(ax, scene, link, list(pts.values()), style.tint(link), is_virtual, style.offset)
        if is_virtual:
            scene.virtual.setdefault(link, []).extend(scene.artists[before:])


def _draw_profiles(ax: Axes, scene: Scene, profiles: list[_Profile], style: _SceneStyle) -> None:
    """The contacting profiles of the higher pairs; a roller carries its link's label."""
    compass = np.array([[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]])
    for prof in profiles:
        owner = prof.carrier if prof.kind == "roller" else prof.link
        _draw_profile(ax, scene, prof, style.tint(owner))
        if prof.kind != "flat":
            scene.anchors.append((prof.carrier, prof.centre + prof.radius * compass))
        if prof.kind == "roller":
            label = ax.text(
                0,
                0,
                prof.link,
                color=style.tint(prof.carrier),
                fontsize=10,
                fontweight="bold",
                ha="left",
                va="bottom",
                gid=f"link:{prof.link}",
                zorder=6,
            )
            scene.follow(_mover_text(label, prof.carrier, prof.centre, prof.radius * 0.75), label)


def _draw_cams(ax: Axes, scene: Scene, plan: SolvePlan, style: _SceneStyle) -> None:
    """Each designed cam's profile (gid ``profile:<pair id>:<cam>``), turning with the cam, and
    its contact (gid ``contact:<point>``), which runs along the profile as it turns."""
    for cam in plan.cams:
        outline = sketch_profile(cam) / scene.unit
        c = style.tint(cam.cam)
        patch = Polygon(
            outline, closed=True, facecolor=to_rgba(c, 0.08), edgecolor=c, lw=1.8,
            gid=f"profile:{cam.pair.id}:{cam.cam}", zorder=3,
        )  # fmt: skip
        ax.add_patch(patch)
        dot = Line2D([], [], marker="o", ms=4, color="black", ls="none",
                     gid=f"contact:{cam.contact_point}", zorder=7)  # fmt: skip
        ax.add_line(dot)
        scene.anchors.append((cam.cam, outline))

        def move(poses: Poses, cam=cam, outline=outline, patch=patch, dot=dot) -> None:
            patch.set_xy(place(poses, cam.cam, outline))
            turned = float(poses[cam.cam][2]) if cam.cam in poses else 0.0
            k = contact_at(cam, np.array([turned]))[0] / scene.unit
            dot.set_data([k[0]], [k[1]])

        scene.follow(move, patch, dot)


def _draw_contacts(
    ax: Axes, scene: Scene, report: StructuralReport, plan: SolvePlan, style: _SceneStyle
) -> None:
    """The contact point of each higher pair: a dot, and its name unless a plan point has it."""
    designed = {c.pair.id for c in plan.cams}
    for r in report.replacements:
        k = style.sketch.at(r.pair.point)
        if k is None or r.pair.id in designed:  # a designed cam's contact moves on its profile
            continue
        # a gear mesh's contact stays at the pitch point as the gears roll
        carrier = style.ground if r.pair.gear else _contact_carrier(plan, r.pair)
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
            scene.follow(_mover_text(text, carrier, k, style.offset), text)


def _draw_sliders(ax: Axes, scene: Scene, plan: SolvePlan, style: _SceneStyle) -> None:
    """Each P pair's block on its guide line."""
    for pair in plan.mechanism.pairs:
        if pair.kind is not PairKind.P:
            continue
        at = style.sketch.at(pair.point)
        if at is None:
            continue
        block, guide = _slider_of(plan, pair)
        before = len(scene.artists)
        _draw_slider(ax, scene, pair, block, guide, at, style)
        for link in {block, guide} & style.virtual:
            scene.virtual.setdefault(link, []).extend(scene.artists[before:])


def _draw_pins(
    ax: Axes, scene: Scene, report: StructuralReport, plan: SolvePlan, style: _SceneStyle
) -> None:
    """A circle at each R pair's point (dashed when only virtual links meet there).

    A pin of the ground sits on a hatched base and stays; another pin moves
    with a real link it joins.
    """
    m = plan.mechanism
    pins: dict[str, list[Pair]] = {}
    real_pins = {p.point for p in report.mechanism.pairs if p.kind is PairKind.R}
    for pair in m.pairs:
        if pair.kind is PairKind.R and pair.point is not None:
            pins.setdefault(pair.point, []).append(pair)
    for point, pairs in pins.items():
        at = style.sketch.at(point)
        if at is None:
            continue
        links = [lk for p in pairs for lk in p.links]
        only_virtual = point not in real_pins and all(
            p.a in style.virtual or p.b in style.virtual for p in pairs
        )
        if style.ground in links:
            _draw_ground_base(ax, at, style.pin_radius)
        pin = Circle(
            tuple(at),
            style.pin_radius,
            facecolor="white",
            edgecolor="black",
            lw=1.2,
            ls="--" if only_virtual else "-",
            gid=f"pin:{point}",
            zorder=5,
        )
        ax.add_patch(pin)
        if style.ground not in links:
            carrier = next((lk for lk in links if lk not in style.virtual), links[0])
            scene.follow(_mover_centre(pin, carrier, at), pin)


def _draw_ground_base(ax: Axes, at: np.ndarray, pin_r: float) -> None:
    """The hatched triangle under a pin of the ground."""
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


def _draw_ground_strip(ax: Axes, ends: np.ndarray, normal: np.ndarray) -> None:
    """The hatched strip along a guide of the ground, ``normal`` deep."""
    strip = np.array([ends[0], ends[1], ends[1] - normal, ends[0] - normal])
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


def _point_carrier(plan: SolvePlan, name: str, link: str, virtual: set[str]) -> str:
    """The link that carries point ``name``: a virtual link's pin goes with the real link."""
    if link not in virtual:
        return link
    joined = (lk for p in plan.mechanism.pairs if p.point == name for lk in p.links)
    return next((lk for lk in joined if lk not in virtual), link)


def _draw_points(ax: Axes, scene: Scene, plan: SolvePlan, style: _SceneStyle) -> None:
    """Each named point's label, and a dot for a marker (a point defined ``on`` a link)."""
    m = plan.mechanism
    for name, (owner, _) in plan.points.items():
        link = _point_carrier(plan, name, owner, style.virtual)
        xy = style.sketch.xy[name]
        text = ax.text(
            0, 0, name, fontsize=9, ha="left", va="bottom", gid=f"point:{name}", zorder=7
        )
        scene.follow(_mover_text(text, link, xy, style.offset), text)
        definition = m.points.get(name)
        if definition is not None and definition.on is not None:
            _draw_marker(ax, scene, name, link, xy, style.tint(link))


def _draw_marker(ax: Axes, scene: Scene, name: str, link: str, xy: np.ndarray, colour: str) -> None:
    """A dot in the colour of ``link`` at its point ``xy``."""
    dot = Line2D(
        [xy[0]],
        [xy[1]],
        marker="o",
        ms=4,
        ls="none",
        color=colour,
        markeredgecolor="black",
        gid=f"marker:{name}",
        zorder=6,
    )
    ax.add_line(dot)
    scene.follow(_mover_dot(dot, link, xy), dot)


def _mover_text(text, link: str, xy: np.ndarray, nudge: float) -> Callable[[Poses], None]:
    """Move ``text`` to the point ``xy`` of ``link``, ``nudge`` up and right of it."""

    def move(poses: Poses) -> None:
        w = place(poses, link, xy) + nudge
        text.set_position((float(w[0]), float(w[1])))

    return move


def _mover_dot(line: Line2D, link: str, xy: np.ndarray) -> Callable[[Poses], None]:
    """Move the one-point ``line`` to the point ``xy`` of ``link``."""

    def move(poses: Poses) -> None:
        w = place(poses, link, xy)
        line.set_data([w[0]], [w[1]])

    return move


def _mover_centre(patch, link: str, xy: np.ndarray) -> Callable[[Poses], None]:
    """Move the centre of ``patch`` to the point ``xy`` of ``link``."""

    def move(poses: Poses) -> None:
        patch.set_center(tuple(place(poses, link, xy)))

    return move


def _draw_link(
    ax: Axes, scene: Scene, link: str, pts: list, c: str, virtual: bool, offset: float
) -> None:
    """A link's outline (a ring from three points, filled unless virtual) and its label."""
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
        w = place(poses, link, sketch)
        if body is not None:
            body.set_xy(w)
        xy = np.vstack([w, w[:1]]) if ring else w
        line.set_data(xy[:, 0], xy[:, 1])
        at = place(poses, link, centre)
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


def _draw_profile(ax: Axes, scene: Scene, prof: _Profile, c: str) -> None:
    """A higher pair's profile: a flat face, an arc, a pitch circle, a roller or cam circle."""
    gid = f"{'pitch' if prof.kind == 'pitch' else 'profile'}:{prof.pair.id}:{prof.link}"
    size = scene.size
    if prof.kind == "flat":
        u = np.array([math.cos(prof.angle), math.sin(prof.angle)])
        ends = np.array([prof.centre - 0.18 * size * u, prof.centre + 0.18 * size * u])
        face = Line2D([], [], color=c, lw=2.5, gid=gid, zorder=3)
        ax.add_line(face)

        def move(poses: Poses) -> None:
            w = place(poses, prof.carrier, ends)
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
        patch.set_center(tuple(place(poses, prof.carrier, prof.centre)))
        if isinstance(patch, Arc):
            patch.set_angle(math.degrees(_turn(poses, prof.carrier)))

    scene.follow(move_curve, patch)


def _draw_slider(
    ax: Axes,
    scene: Scene,
    pair: Pair,
    block: str,
    guide: str,
    at: np.ndarray,
    style: _SceneStyle,
) -> None:
    """The block of ``pair`` at ``at`` on a dashed guide line (hatched when the ground's)."""
    size = style.size
    dashed = block in style.virtual or guide in style.virtual
    line = Line2D(
        [], [], color=style.tint(guide), lw=1.2, ls="--", gid=f"guide:{pair.id}", zorder=1
    )
    ax.add_line(line)
    half = 0.35 * size
    if guide == style.ground:
        u = np.array([math.cos(pair.angle or 0.0), math.sin(pair.angle or 0.0)])
        n = np.array([-u[1], u[0]]) * 0.03 * size
        _draw_ground_strip(ax, np.array([at - half * u, at + half * u]), n)
    bc = style.tint(block)
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
        on_guide = place(poses, guide, at)
        u = np.array([math.cos(theta), math.sin(theta)])
        ends = np.array([on_guide - half * u, on_guide + half * u])
        line.set_data(ends[:, 0], ends[:, 1])
        box.set_xy(_rectangle(place(poses, block, at), theta, 0.09 * size, 0.05 * size))

    scene.follow(move, line, box)


def _draw_driver(
    ax: Axes,
    scene: Scene,
    plan: SolvePlan,
    d,
    body: Mapping[str, np.ndarray],
    style: _SceneStyle,
) -> None:
    """An arc arrow of ω about a rotating driver's pivot, a straight one along a slide."""
    pin_r, size = style.pin_radius, style.size
    forward = d.speed >= 0
    if d.kind == "R":
        pivot = style.sketch.at(d.point)
        if pivot is None:
            pivot = np.asarray(d.pivot, dtype=float) / style.sketch.unit
        others = [xy for xy in body.values() if length(xy - pivot) > 1e-9 * size]
        away = -math.pi / 2
        if others:
            arm = np.mean(others, axis=0) - pivot
            if length(arm) > 1e-9 * size:
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
        at = style.sketch.at(d.point)
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
        w = place(poses, d.link, sketch)
        arrow.set_positions(tuple(w[0]), tuple(w[1]))
        t = place(poses, d.link, note)
        text.set_position((float(t[0]), float(t[1])))

    scene.follow(move, arrow, text)
