"""The cycle's animation: an inline SVG of the mechanism, every pose's coordinates for the script.

:func:`animation_html` draws the mechanism at the sketch's pose of a
:class:`~kinematics.html.cycle.Cycle` as plain SVG elements (each link's
outline in its group's colour, pins, slider blocks, guides, the ground, the
paths of the points) and adds the coordinates of every element at every
pose as strict JSON. The page's script (``report.js``) sets those
coordinates when the slider moves or the play button runs: no library, no
drawing code in the browser. The SVG's y axis points down, so every y is
negated. A mechanism far from metres is written in a power of 1000 of the metre
(:func:`kinematics.figures.style.drawing_unit`): a browser draws SVG in single
precision, which holds neither 1e-302 nor 1e150.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from html import escape

import numpy as np
from matplotlib.colors import to_hex

from structure.model import Pair, PairKind
from structure.report import StructuralReport

from ..cams.contact import sketch_profile
from ..figures.style import OTHER_COLOUR, drawing_unit, palette, virtual_links
from ..solvers.plan import SolvePlan
from .cycle import Cycle, inputs_text
from .markup import element, json_script
from .phrases import say

__all__ = ["animation_html"]


@dataclass(frozen=True)
class _Body:
    """A link's outline: its sketch points in drawing order, its colour, dashed when virtual."""

    link: str
    points: np.ndarray  # (k, 2), sketch coordinates
    colour: str
    ring: bool
    virtual: bool


@dataclass(frozen=True)
class _Slider:
    """A prismatic pair: the block's link, the guide's link, the sketch point and the angle."""

    block: str
    guide: str
    at: np.ndarray
    angle: float


def _sketch_xy(plan: SolvePlan, name: str | None) -> np.ndarray | None:
    """The sketch coordinates of a point of the plan's mechanism (or of the plan's points)."""
    if name is None:
        return None
    xy = plan.mechanism.coordinates(name)
    if xy is None and name in plan.points:
        return np.asarray(plan.points[name][1], dtype=float)
    return None if xy is None else np.asarray(xy, dtype=float)


def _ring_order(points: list[np.ndarray]) -> list[np.ndarray]:
    """Points sorted by angle about their centroid: a ring's outline."""
    centre = np.mean(points, axis=0)
    return sorted(points, key=lambda p: math.atan2(p[1] - centre[1], p[0] - centre[0]))


def _bodies(report: StructuralReport, plan: SolvePlan, reach: float) -> list[_Body]:
    """Each moving link's outline through its pair points and markers (a wheel's spoke)."""
    m = plan.mechanism
    colour, _ = palette(report)
    virtual = virtual_links(report)
    out = []
    profiled = {cam.cam: cam for cam in plan.cams}
    for link in m.moving_links:
        if link in profiled:  # a designed cam: its profile, turning with it
            outline = sketch_profile(profiled[link], 120)
            out.append(_Body(link, outline, to_hex(colour.get(link, OTHER_COLOUR)), True, False))
            continue
        named: dict[str, np.ndarray] = {}
        for pair in m.pairs_of(link):
            if pair.kind is PairKind.P and link not in virtual and pair.other(link) in virtual:
                continue
            xy = _sketch_xy(plan, pair.point)
            if xy is not None:
                named.setdefault(pair.point or "", xy)
        for name, (owner, xy) in plan.points.items():
            if owner == link:
                named.setdefault(name, np.asarray(xy, dtype=float))
        points = list(named.values())
        slides = any(p.kind is PairKind.P for p in m.pairs_of(link))
        if len(points) == 1 and not slides:  # a wheel on its axle: a spoke shows it turning
            points.append(points[0] + np.array([0.12 * reach, 0.0]))
        if len(points) < 2:  # a block alone: its slider draws it
            continue
        ring = len(points) >= 3
        ordered = np.array(_ring_order(points) if ring else points)
        hexed = to_hex(colour.get(link, OTHER_COLOUR))
        out.append(_Body(link, ordered, hexed, ring, link in virtual))
    for cam in plan.cams:  # its roller, carried by the follower (the roller's spin is idle)
        radius = cam.design.layout.roller_radius
        axis = _sketch_xy(plan, cam.pair.center_of(cam.other)) if radius else None
        if axis is not None:
            turn = np.linspace(0.0, 2.0 * math.pi, 36, endpoint=False)
            ring = axis + radius * np.stack([np.cos(turn), np.sin(turn)], axis=1)
            out.append(_Body(cam.follower, ring, to_hex(colour.get(cam.follower, OTHER_COLOUR)),
                             True, False))  # fmt: skip
    return out


def _sliders(plan: SolvePlan) -> list[_Slider]:
    """Each prismatic pair with a point: the block is the link pinned at the slide's point."""
    m = plan.mechanism
    out = []
    for pair in m.pairs:
        at = _sketch_xy(plan, pair.point)
        if pair.kind is not PairKind.P or at is None:
            continue
        out.append(_Slider(*_block_and_guide(m, pair), at, pair.angle or 0.0))
    return out


def _block_and_guide(m, pair: Pair) -> tuple[str, str]:
    """(block, guide) of a P pair: the ground is a guide; else the link pinned there is a block."""
    if m.ground in (pair.a, pair.b):
        return (pair.b, pair.a) if pair.a == m.ground else (pair.a, pair.b)
    pinned = {
        link
        for link in pair.links
        for p in m.pairs_of(link)
        if p is not pair and p.kind is PairKind.R and p.point == pair.point
    }
    return (pair.a, pair.b) if pair.a in pinned and pair.b not in pinned else (pair.b, pair.a)


def _carried(poses: Mapping[str, np.ndarray], link: str, points: np.ndarray, n: int) -> np.ndarray:
    """World coordinates (n, k, 2) of sketch ``points`` (k, 2) carried by ``link`` at each pose."""
    q = poses.get(link)
    if q is None:  # the ground, or a virtual link the rolling gears do without
        return np.broadcast_to(points, (n, *points.shape)).copy()
    cos, sin = np.cos(q[:, 2])[:, None], np.sin(q[:, 2])[:, None]
    x = q[:, 0:1] + cos * points[:, 0] - sin * points[:, 1]
    y = q[:, 1:2] + sin * points[:, 0] + cos * points[:, 1]
    return np.stack([x, y], axis=-1)


def _pins(report: StructuralReport, plan: SolvePlan) -> list[tuple[str, str, np.ndarray, bool]]:
    """Each revolute pair's point once, then each other named point (a marker).

    Each is ``(name, the link that carries it, sketch xy, whether it is a marker)``.
    """
    m = plan.mechanism
    virtual = virtual_links(report)
    links_at: dict[str, list[str]] = {}
    for pair in m.pairs:
        if pair.kind is PairKind.R and pair.point is not None:
            links_at.setdefault(pair.point, []).extend(pair.links)
    out = []
    for point, links in links_at.items():
        xy = _sketch_xy(plan, point)
        if xy is None:
            continue
        carrier = m.ground if m.ground in links else None
        carrier = carrier or next((lk for lk in links if lk not in virtual), links[0])
        out.append((point, carrier, xy, False))
    pair_points = {p.point for p in m.pairs}
    for name, (owner, xy) in plan.points.items():
        if name not in pair_points and owner not in virtual:
            out.append((name, owner, np.asarray(xy, dtype=float), True))
    return out


class _Frames:
    """Every element's coordinates at every pose, in the SVG's axes (y down), rounded.

    They are computed in metres (``size`` too) and written in ``unit`` metres.
    """

    def __init__(self, report: StructuralReport, plan: SolvePlan, cycle: Cycle) -> None:
        self.count = len(cycle.sweep.inputs)
        sketch_span = np.array([p[1] for p in plan.points.values()] or [[0.0, 0.0]])
        reach = float(max(np.ptp(sketch_span, axis=0).max(), plan.length or 0.0) or 1.0)
        self.bodies = _bodies(report, plan, reach)
        self.sliders = _sliders(plan)
        self.pins = _pins(report, plan)
        poses, n = cycle.poses, self.count
        self.links = [_carried(poses, b.link, b.points, n) for b in self.bodies]
        self.pin_xy = [_carried(poses, link, xy[None, :], n)[:, 0] for _, link, xy, _ in self.pins]
        self.block_xy = [_carried(poses, s.block, s.at[None, :], n)[:, 0] for s in self.sliders]
        self.turns = [
            poses[s.guide][:, 2] if s.guide in poses else np.zeros(n) for s in self.sliders
        ]
        self.guide_xy = [_carried(poses, s.guide, s.at[None, :], n)[:, 0] for s in self.sliders]
        everything = [a.reshape(-1, 2) for a in (*self.links, *self.pin_xy, *self.block_xy)]
        stacked = np.concatenate(everything) if everything else np.zeros((1, 2))
        low, high = stacked.min(axis=0), stacked.max(axis=0)
        self.size = float(max((high - low).max(), reach * 0.2))
        self.unit = drawing_unit(self.size)
        margin = 0.12 * self.size
        box = (low[0] - margin, -high[1] - margin, *(high - low + 2 * margin))
        self.box = tuple(float(v) / self.unit for v in box)
        self.decimals = max(0, 4 - math.floor(math.log10(self.size / self.unit)))

    def flat(self, xy: np.ndarray) -> list[float]:
        """(…, 2) world coordinates as a flat list of SVG coordinates (y negated), rounded."""
        svg = np.array(xy, dtype=float) / self.unit
        svg[..., 1] *= -1.0
        return [round(float(v), self.decimals) for v in svg.ravel()]

    def guide_ends(self, k: int, frame: int) -> list[float]:
        """The two ends of slider ``k``'s guide line at ``frame`` (x1, y1, x2, y2)."""
        theta = self.sliders[k].angle + float(self.turns[k][frame])
        u = np.array([math.cos(theta), math.sin(theta)]) * 0.35 * self.size
        centre = self.guide_xy[k][frame]
        return self.flat(np.array([centre - u, centre + u]))

    def slider_place(self, k: int, frame: int) -> list[float]:
        """Slider ``k``'s block at ``frame``: centre x, y (SVG) and its turn in SVG degrees."""
        theta = self.sliders[k].angle + float(self.turns[k][frame])
        x, y = self.flat(self.block_xy[k][frame])
        return [x, y, round(-math.degrees(theta), 3)]

    def data(self, readout: list[str], sketch: int, loop: bool) -> dict:
        """The script's JSON: per element, its coordinates at every pose."""
        frames = range(self.count)
        return {
            "count": self.count,
            "sketch": sketch,
            "loop": loop,
            "readout": readout,
            "links": [[self.flat(xy[f]) for f in frames] for xy in self.links],
            "pins": [self.flat(xy) for xy in self.pin_xy],
            "sliders": [
                [v for f in frames for v in self.slider_place(k, f)]
                for k in range(len(self.sliders))
            ],
            "guides": [
                [v for f in frames for v in self.guide_ends(k, f)] for k in range(len(self.sliders))
            ],
        }


def _points_attribute(flat: list[float]) -> str:
    """An SVG ``points`` attribute from a flat coordinate list."""
    return " ".join(f"{flat[i]:g},{flat[i + 1]:g}" for i in range(0, len(flat), 2))


def _drawing(
    frames: _Frames, report: StructuralReport, plan: SolvePlan, cycle: Cycle, label: str
) -> str:
    """The SVG at the sketch's pose: traces, ground, guides, links, sliders, pins, labels."""
    s, f = frames.size, cycle.sketch
    drawn = s / frames.unit  # the size in the SVG's unit
    parts = []
    for name, values in cycle.sweep.points.items():
        path = values["position"]
        if len(path) > 1 and float(np.ptp(path, axis=0).max()) > 1e-9 * s:
            if cycle.complete:  # a whole turn: the path closes
                path = np.vstack([path, path[:1]])
            pts = _points_attribute(frames.flat(path))
            parts.append(f'<polyline class="trace" data-point="{escape(name)}" points="{pts}"/>')
    for _, link, xy, _ in frames.pins:
        if link == plan.mechanism.ground:
            x, y = frames.flat(xy)
            d = 0.035 * drawn
            parts.append(
                f'<path class="ground" d="M{x:g},{y:g} l{-d:g},{1.6 * d:g} h{2 * d:g} z"/>'
            )
    for k in range(len(frames.sliders)):
        x1, y1, x2, y2 = frames.guide_ends(k, f)
        parts.append(
            f'<line class="guide" data-guide="{k}" '
            f'x1="{x1:g}" y1="{y1:g}" x2="{x2:g}" y2="{y2:g}"/>'
        )
    for k, body in enumerate(frames.bodies):
        tag = "polygon" if body.ring else "polyline"
        kind = "link virtual" if body.virtual else "link"
        pts = _points_attribute(frames.flat(frames.links[k][f]))
        parts.append(
            f'<{tag} class="{kind}" data-link="{k}" data-name="{escape(body.link)}" '
            f'style="stroke: {body.colour}; fill: {body.colour}" points="{pts}"/>'
        )
    w, h = 0.09 * drawn, 0.05 * drawn
    colour, _ = palette(report)
    for k, slider in enumerate(frames.sliders):
        x, y, deg = frames.slider_place(k, f)
        tint = to_hex(colour.get(slider.block, OTHER_COLOUR))
        parts.append(
            f'<rect class="slider" data-slider="{k}" x="{-w / 2:g}" y="{-h / 2:g}" '
            f'width="{w:g}" height="{h:g}" style="fill: {tint}; stroke: {tint}" '
            f'transform="translate({x:g} {y:g}) rotate({deg:g})"/>'
        )
    r = 0.014 * drawn
    for k, (name, _, _, marker) in enumerate(frames.pins):
        x, y = frames.flat(frames.pin_xy[k][f])
        kind, size = ("marker", 0.5 * r) if marker else ("pin", r)
        parts.append(f'<circle class="{kind}" data-pin="{k}" cx="{x:g}" cy="{y:g}" r="{size:g}"/>')
        parts.append(
            f'<text class="pin-label" data-pin="{k}" x="{x + 1.5 * r:g}" y="{y - 1.5 * r:g}" '
            f'font-size="{0.045 * drawn:g}">{escape(name)}</text>'
        )
    box = " ".join(f"{v:g}" for v in frames.box)
    return (
        f'<svg class="cycle" id="cycle-svg" viewBox="{box}" role="img" '
        f'aria-label="{escape(label)}" xmlns="http://www.w3.org/2000/svg">'
        + "".join(parts)
        + "</svg>"
    )


def animation_html(report: StructuralReport, plan: SolvePlan, cycle: Cycle, lang: str) -> str:
    """The animation: the SVG at the sketch's pose, the slider, the play button, the data.

    Parameters
    ----------
    report : StructuralReport
        Its groups colour the links.
    plan : SolvePlan
        The mechanism and its points.
    cycle : Cycle
        The poses to scrub through.
    lang : {"en", "vi"}
        The language of the controls.

    Returns
    -------
    str
        A ``<figure class="animation">`` with the SVG (``#cycle-svg``), the controls
        (``#cycle-play``, ``#cycle-slider``, ``#cycle-readout``) and the JSON
        (``#cycle-data``) the page's script reads.
    """
    frames = _Frames(report, plan, cycle)
    readout = [inputs_text(plan, row) for row in cycle.sweep.inputs]
    drawing = _drawing(frames, report, plan, cycle, say(lang, "h_animation"))
    play = element(
        "button",
        escape(say(lang, "play")),
        type="button",
        id="cycle-play",
        data_play=say(lang, "play"),
        data_pause=say(lang, "pause"),
    )
    slider = (
        f'<input type="range" id="cycle-slider" min="0" max="{frames.count - 1}" step="1" '
        f'value="{cycle.sketch}" aria-label="{escape(say(lang, "pose_slider"))}"/>'
    )
    output = element("output", escape(readout[cycle.sketch]), id="cycle-readout")
    controls = element("div", play + slider + output, class_="controls")
    data = json_script("cycle-data", frames.data(readout, cycle.sketch, cycle.complete))
    return element("figure", drawing + controls, class_="animation") + data
