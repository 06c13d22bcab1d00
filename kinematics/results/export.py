"""The solved mechanism out to CAD and data tools: the drawing at a pose as DXF, a sweep as Parquet.

:func:`mechanism_dxf` draws the mechanism at a solved pose with ezdxf (the
``dxf`` extra), one layer per Assur group so that a CAD user can show, hide or
colour each group:

* layer ``I(<driver>)`` for each driving link, ``II(2,3)``-style layers named
  as the structural formula names the groups, ``GROUND`` for the frame,
  ``OTHER`` for a link in no group, ``LABELS`` for the point names;
* a link with two points is a ``LINE``, with more a closed ``LWPOLYLINE``
  round its points (a virtual link that replaces a higher pair is dashed);
* each pin is a ``CIRCLE`` on the layer of the group that the pin attaches
  (the last solved of its links), a slider block a closed ``LWPOLYLINE``
  rectangle on its link's layer, its guide a ``LINE`` on the guide link's;
* the ground under a fixed pivot or along a fixed guide is a base ``LINE``
  with short hatch strokes (``LINE`` entities) on ``GROUND``;
* a gear mesh's pitch circles (radius m·z/2 with ``module=``, else the axis to
  the contact) are ``CIRCLE`` entities on ``PITCH_CIRCLES``, each gear's tooth
  number a ``TEXT`` (``z = 20``) on ``TOOTH_NUMBERS``;
* a cam's profile at the contact (its disc: the circle about its centre of
  curvature through the contact), a roller and a flat face are ``CIRCLE`` and
  ``LINE`` entities on ``CAM_PROFILES``;
* the mechanism's name is a ``TEXT`` above the drawing on ``LABELS``, and every
  named point not drawn otherwise a ``POINT`` with its name.

Coordinates are the pose's, in the units of the sketch (metres). A drawing holds
no loads, driver motion, friction or other physics (:data:`DXF_HOLDS`;
:func:`dxf_left_out` says what a mechanism loses, a line per kind). Files are
written whole or not at all (:mod:`structure.readwrite.atomic`).

:func:`write_parquet` writes a :class:`~kinematics.solvers.sweep.Sweep` as a Parquet
table (pyarrow, the ``parquet`` extra) with the columns of
:meth:`~kinematics.solvers.sweep.Sweep.as_dict`, as :meth:`~kinematics.solvers.sweep.Sweep.to_csv`
writes them to CSV.

This module draws without matplotlib: the figures of :mod:`kinematics.figures`
are for the eye, this is geometry for other programs.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from structure.errors import MechanismError
from structure.model import Mechanism, Pair, PairKind
from structure.readwrite.atomic import atomic_path
from structure.readwrite.omissions import Holds, left_out
from structure.report import StructuralReport

from ..solvers.plan import SolvePlan
from ..solvers.solve import KinematicState
from ..solvers.sweep import Sweep

try:  # the ``dxf`` extra
    import ezdxf
except ImportError:  # pragma: no cover - depends on the environment
    ezdxf = None
try:  # the ``parquet`` extra
    import pyarrow
    import pyarrow.parquet
except ImportError:  # pragma: no cover - depends on the environment
    pyarrow = None

__all__ = [
    "CAM_LAYER",
    "DRAWING_HOLDS",
    "DXF_HOLDS",
    "GROUND_LAYER",
    "LABEL_LAYER",
    "OTHER_LAYER",
    "PITCH_LAYER",
    "TEETH_LAYER",
    "drawing_left_out",
    "dxf_layers",
    "dxf_left_out",
    "mechanism_dxf",
    "write_dxf",
    "write_parquet",
]

GROUND_LAYER = "GROUND"
LABEL_LAYER = "LABELS"
OTHER_LAYER = "OTHER"
PITCH_LAYER = "PITCH_CIRCLES"
TEETH_LAYER = "TOOTH_NUMBERS"
CAM_LAYER = "CAM_PROFILES"

#: the pair options a drawing at a pose shows (the geometry); the others are physics
_DRAWN_OPTIONS = frozenset({"angle", "flat", "roller", "centers", "z", "module", "internal"})

#: what a DXF drawing keeps of a mechanism: its geometry at a pose, names and tooth numbers
DXF_HOLDS = Holds("DXF drawings", loads=False, motion=False, options=_DRAWN_OPTIONS)

#: what a figure (SVG, PNG, PDF) of the mechanism keeps: as DXF, but no tooth numbers
DRAWING_HOLDS = Holds(
    "SVG, PNG and PDF drawings", loads=False, motion=False, options=_DRAWN_OPTIONS - {"z"}
)


def dxf_left_out(mechanism: Mechanism) -> tuple[str, ...]:
    """What a DXF drawing of ``mechanism`` leaves out (loads, motion, physics), a line per kind.

    >>> from structure import parse_edgelist
    >>> dxf_left_out(parse_edgelist(["driver 1 omega=5", "0 1 R A", "point A 0 0"]))
    ('DXF drawings hold no driver motion: omega of driver 1 left out',)
    """
    return left_out(mechanism, DXF_HOLDS)


def drawing_left_out(mechanism: Mechanism) -> tuple[str, ...]:
    """What an SVG, PNG or PDF drawing of ``mechanism`` leaves out, a line per kind."""
    return left_out(mechanism, DRAWING_HOLDS)


_FORBIDDEN = re.compile(r'[<>/\\":;?*|=`]')
#: AutoCAD colour index of each group's layer, in solve order (drivers are white/black)
_COLOURS = (5, 30, 3, 1, 6, 42, 4, 2, 8)


def _layer_name(label: str) -> str:
    return _FORBIDDEN.sub("_", label)


def dxf_layers(report: StructuralReport) -> dict[str, str]:
    """Each link's layer: its group's label (``I(1)`` for a driver), ``GROUND``, or ``OTHER``.

    >>> from structure import parse_edgelist, analyze
    >>> m = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"])
    >>> dxf_layers(analyze(m))
    {'0': 'GROUND', '1': 'I(1)', '2': 'II(2,3)', '3': 'II(2,3)'}
    """
    mechanism = report.mechanism
    out = {mechanism.ground: GROUND_LAYER}
    for link in report.drivers:
        out[link] = _layer_name(f"I({link})")
    for group in report.groups:
        for link in group.links:
            out[link] = _layer_name(group.label)
    for link in (*mechanism.links, *(r.virtual_link for r in report.replacements)):
        out.setdefault(link, OTHER_LAYER)
    return out


# ------------------------------------------------------------ the geometry
class _Pose:
    """Sketch points placed where the pose puts their links."""

    def __init__(self, plan: SolvePlan, state: KinematicState):
        self.plan = plan
        self.q = {name: np.asarray(link.q, dtype=float) for name, link in state.links.items()}

    def place(self, link: str, xy: Any) -> np.ndarray:
        xy = np.asarray(xy, dtype=float)
        q = self.q.get(link)
        if q is None:
            return xy
        cos, sin = math.cos(q[2]), math.sin(q[2])
        return q[:2] + np.array([cos * xy[0] - sin * xy[1], sin * xy[0] + cos * xy[1]])

    def turn(self, link: str) -> float:
        q = self.q.get(link)
        return 0.0 if q is None else float(q[2])

    def sketch(self, name: str | None) -> np.ndarray | None:
        if name is None:
            return None
        xy = self.plan.mechanism.coordinates(name)
        if xy is None and name in self.plan.points:
            return np.asarray(self.plan.points[name][1], dtype=float)
        return None if xy is None else np.asarray(xy, dtype=float)


def _link_points(plan: SolvePlan, link: str) -> dict[str, np.ndarray]:
    """The named sketch points of ``link``: the points of its pairs and its markers."""
    m = plan.mechanism
    out: dict[str, np.ndarray] = {}
    for pair in m.pairs_of(link):
        xy = m.coordinates(pair.point) if pair.point else None
        if xy is not None:
            out.setdefault(pair.point, np.asarray(xy, dtype=float))  # type: ignore[arg-type]
    for name, (owner, xy) in plan.points.items():
        if owner == link:
            out.setdefault(name, np.asarray(xy, dtype=float))
    for name, point in m.points.items():
        if point.on == link:
            out.setdefault(name, np.array([point.x, point.y], dtype=float))
    return out


def _ring(points: list[np.ndarray]) -> list[np.ndarray]:
    centre = np.mean(points, axis=0)
    return sorted(points, key=lambda p: math.atan2(p[1] - centre[1], p[0] - centre[0]))


def _solve_order(report: StructuralReport) -> dict[str, int]:
    """Links by when they are known: the ground, the drivers, then the groups."""
    order = {report.mechanism.ground: -1}
    for k, link in enumerate(report.drivers):
        order[link] = k
    for k, group in enumerate(report.groups, start=len(report.drivers)):
        for link in group.links:
            order[link] = k
    return order


def _block_and_guide(plan: SolvePlan, pair: Pair) -> tuple[str, str]:
    """(block, guide) of a P pair: the ground guides; else the link pinned at the point slides."""
    m = plan.mechanism
    if m.ground in pair.links:
        return pair.other(m.ground), m.ground
    pinned = [
        link
        for link in pair.links
        if any(p.kind is PairKind.R and p.point == pair.point for p in m.pairs_of(link))
    ]
    if len(pinned) == 1:
        return pinned[0], pair.other(pinned[0])
    return pair.b, pair.a


# ----------------------------------------------------------------- drawing
class _Sheet:
    """The modelspace of a new drawing, its layers, and the size of the mechanism."""

    def __init__(self, report: StructuralReport, plan: SolvePlan):
        self.doc = ezdxf.new("R2010", setup=True)
        self.msp = self.doc.modelspace()
        self.layers = dxf_layers(report)
        self.virtual = {r.virtual_link for r in report.replacements}
        names = [GROUND_LAYER, *dict.fromkeys(self.layers.values()), LABEL_LAYER]
        for k, name in enumerate(dict.fromkeys(names)):
            colour = 7 if name in (GROUND_LAYER, LABEL_LAYER) or name.startswith("I(") else None
            colour = colour or _COLOURS[k % len(_COLOURS)]
            self.doc.layers.add(name, color=colour)
        self.size = float(plan.length or 1.0)
        self.low = np.array([math.inf, math.inf])
        self.high = -self.low

    def _extend(self, *points: Any) -> None:
        for point in points:
            xy = np.asarray(point, dtype=float)
            self.low, self.high = np.minimum(self.low, xy), np.maximum(self.high, xy)

    def layer(self, name: str, colour: int) -> str:
        """``name``, a layer added the first time it is used."""
        if name not in self.doc.layers:
            self.doc.layers.add(name, color=colour)
        return name

    def line(self, layer: str, start: np.ndarray, end: np.ndarray, dashed: bool = False) -> None:
        attribs = {"layer": layer, "linetype": "DASHED"} if dashed else {"layer": layer}
        self._extend(start, end)
        self.msp.add_line(tuple(map(float, start)), tuple(map(float, end)), dxfattribs=attribs)

    def circle(self, layer: str, centre: np.ndarray, radius: float, dashed: bool = False) -> None:
        attribs = {"layer": layer, "linetype": "DASHED"} if dashed else {"layer": layer}
        self._extend(centre - radius, centre + radius)
        self.msp.add_circle(tuple(map(float, centre)), float(radius), dxfattribs=attribs)

    def text(self, layer: str, text: str, at: np.ndarray, height: float) -> None:
        self._extend(at)
        self.msp.add_text(text, height=height, dxfattribs={"layer": layer}).set_placement(
            (float(at[0]), float(at[1]))
        )

    def ring(self, layer: str, points: list[np.ndarray], dashed: bool = False) -> None:
        attribs = {"layer": layer, "linetype": "DASHED"} if dashed else {"layer": layer}
        self._extend(*points)
        xy = [(float(p[0]), float(p[1])) for p in points]
        self.msp.add_lwpolyline(xy, close=True, dxfattribs=attribs)

    def hatch(self, start: np.ndarray, end: np.ndarray, below: np.ndarray) -> None:
        """The ground along ``start``–``end``: the line, strokes towards ``below``."""
        self.line(GROUND_LAYER, start, end)
        length = float(np.hypot(*(end - start)))
        strokes = max(2, round(length / (0.02 * self.size)))
        slant = below + (end - start) / length * float(np.hypot(*below)) * -0.8
        for t in np.linspace(0.0, 1.0, strokes):
            foot = start + t * (end - start)
            self.line(GROUND_LAYER, foot, foot + slant)


def _draw_links(sheet: _Sheet, plan: SolvePlan, pose: _Pose) -> None:
    for link in plan.mechanism.moving_links:
        points = [pose.place(link, xy) for xy in _link_points(plan, link).values()]
        dashed = link in sheet.virtual
        if len(points) == 2:
            sheet.line(sheet.layers.get(link, OTHER_LAYER), points[0], points[1], dashed)
        elif len(points) > 2:
            sheet.ring(sheet.layers.get(link, OTHER_LAYER), _ring(points), dashed)


def _draw_pins(
    sheet: _Sheet, report: StructuralReport, plan: SolvePlan, pose: _Pose
) -> dict[str, np.ndarray]:
    """A circle at each pin on the layer of the group it attaches; returns their centres."""
    m = plan.mechanism
    order = _solve_order(report)
    radius = 0.015 * sheet.size
    centres: dict[str, np.ndarray] = {}
    for hinge in m.hinges:
        at = pose.sketch(hinge.point)
        if at is None:
            continue
        last = max(hinge.links, key=lambda link: order.get(link, len(order)))
        carrier = m.ground if m.ground in hinge.links else last
        centre = pose.place(carrier, at)
        centres[hinge.point] = centre
        sheet.msp.add_circle(
            tuple(map(float, centre)), radius, dxfattribs={"layer": sheet.layers[last]}
        )
        if m.ground in hinge.links:
            drop = np.array([0.0, -3.5 * radius])
            span = np.array([2.5 * radius, 0.0])
            sheet.hatch(centre + drop - span, centre + drop + span, np.array([0.0, -radius]))
        sheet.msp.add_text(
            hinge.point, height=radius * 1.5, dxfattribs={"layer": LABEL_LAYER}
        ).set_placement((float(centre[0] + radius), float(centre[1] + radius)))
    return centres


def _draw_sliders(sheet: _Sheet, plan: SolvePlan, pose: _Pose) -> None:
    m = plan.mechanism
    for pair in m.pairs:
        at = pose.sketch(pair.point)
        if pair.kind is not PairKind.P or at is None:
            continue
        block, guide = _block_and_guide(plan, pair)
        theta = math.radians(pair.angle_deg or 0.0) + pose.turn(guide)
        along = np.array([math.cos(theta), math.sin(theta)])
        across = np.array([-along[1], along[0]])
        centre = pose.place(block, at)
        half, thick = 0.045 * sheet.size, 0.025 * sheet.size
        corners = [
            centre + sign_a * half * along + sign_b * thick * across
            for sign_a, sign_b in ((-1, -1), (1, -1), (1, 1), (-1, 1))
        ]
        sheet.ring(sheet.layers.get(block, OTHER_LAYER), corners, block in sheet.virtual)
        on_guide = pose.place(guide, at)
        reach = 0.35 * sheet.size * along
        layer = sheet.layers.get(guide, OTHER_LAYER)
        sheet.line(layer, on_guide - reach, on_guide + reach, guide in sheet.virtual)
        if guide == m.ground:
            below = -across * 0.03 * sheet.size
            sheet.hatch(on_guide - reach + below, on_guide + reach + below, below)


def _pin_axis(m: Mechanism, link: str, near: np.ndarray | None, radius: float | None):
    """The sketch point of ``link``'s axle: the pin to the ground (else its first), or the pin
    whose distance to the contact ``near`` is the pitch radius when that is known."""
    pins = [
        np.asarray(m.coordinates(q.point), dtype=float)
        for q in m.pairs_of(link)
        if q.kind is PairKind.R and q.point is not None and m.coordinates(q.point) is not None
    ]
    if not pins:
        return None
    if radius is not None and near is not None:
        return min(pins, key=lambda c: abs(float(np.hypot(*(c - near))) - radius))
    grounded = [
        np.asarray(m.coordinates(q.point), dtype=float)
        for q in m.pairs_of(link)
        if q.kind is PairKind.R and q.other(link) == m.ground and m.coordinates(q.point)
    ]
    return (grounded or pins)[0]


def _draw_gear(sheet: _Sheet, m: Mechanism, pair: Pair, pose: _Pose) -> None:
    """The pitch circle and tooth number of each gear of a mesh (not of the frame's)."""
    contact = pose.sketch(pair.point)
    teeth = pair.teeth or (None, None)
    pitch = sheet.layer(PITCH_LAYER, 4)
    numbers = sheet.layer(TEETH_LAYER, 7)
    for link, z in zip((pair.a, pair.b), teeth, strict=True):
        known = pair.module * z / 2 if pair.module and z else None
        if link == m.ground and known is None:
            continue  # which pivot of the frame is the gear's axle is not known
        axis = _pin_axis(m, link, contact, known)
        if axis is None:
            continue
        radius = (
            known
            if known is not None
            else (float(np.hypot(*(axis - contact))) if contact is not None else 0.0)
        )
        if not radius > 0:
            continue
        centre = pose.place(link, axis)
        sheet.circle(pitch, centre, radius, dashed=True)
        label = f"z = {'?' if z is None else z}"
        corner = centre + radius * np.array([math.sqrt(0.5), math.sqrt(0.5)])
        sheet.text(numbers, label, corner, 0.03 * sheet.size)


def _draw_cam(sheet: _Sheet, report: StructuralReport, pair: Pair, pose: _Pose) -> None:
    """A cam contact's profiles: the disc (a circle through the contact about its centre of
    curvature), the roller, the flat face."""
    contact = pose.sketch(pair.point)
    if contact is None:
        return
    layer = sheet.layer(CAM_LAYER, 6)
    found = next((r for r in report.replacements if r.pair.id == pair.id), None)
    for link in (pair.a, pair.b):
        if found is not None and found.roller is not None and link == found.roller.roller:
            axis = pose.sketch(found.roller.axis)
            if axis is not None:
                radius = float(np.hypot(*(axis - contact)))
                sheet.circle(layer, pose.place(found.roller.follower, axis), radius)
            continue
        if pair.flat == link:
            face = None
            if found is not None:
                face = next((q.angle for q in found.new_pairs if q.kind is PairKind.P), None)
            if face is None and pair.normal_deg is not None:
                face = math.radians(pair.normal_deg) + math.pi / 2
            if face is not None:
                along = 0.18 * sheet.size * np.array([math.cos(face), math.sin(face)])
                sheet.line(
                    layer, pose.place(link, contact - along), pose.place(link, contact + along)
                )
            continue
        centre = pose.sketch(pair.center_of(link))
        if centre is None:
            continue
        radius = float(np.hypot(*(centre - contact)))
        if radius > 1e-9 * sheet.size:  # a knife edge has no circle: the contact is its profile
            sheet.circle(layer, pose.place(link, centre), radius)


def _draw_higher_pairs(sheet: _Sheet, report: StructuralReport, pose: _Pose) -> None:
    m = report.mechanism
    for pair in m.pairs:
        if pair.kind is not PairKind.H:
            continue
        if pair.gear:
            _draw_gear(sheet, m, pair, pose)
        else:
            _draw_cam(sheet, report, pair, pose)


def mechanism_dxf(report: StructuralReport, plan: SolvePlan, state: KinematicState) -> Any:
    """The mechanism at ``state``'s pose as an ezdxf drawing (see the module for its layers).

    Raises
    ------
    MechanismError
        ezdxf is not installed.
    """
    if ezdxf is None:
        raise MechanismError("DXF export needs ezdxf: pip install 'assur[dxf]'")
    sheet = _Sheet(report, plan)
    pose = _Pose(plan, state)
    _draw_links(sheet, plan, pose)
    _draw_sliders(sheet, plan, pose)
    drawn = set(_draw_pins(sheet, report, plan, pose))
    _draw_higher_pairs(sheet, report, pose)
    mechanism = plan.mechanism
    height = 0.02 * sheet.size
    for name, point in state.points.items():
        definition = mechanism.points.get(name)
        if definition is not None and definition.on is not None:
            drawn.add(name)
            sheet.msp.add_point(
                tuple(map(float, point.position)), dxfattribs={"layer": sheet.layers[point.link]}
            )
            sheet.text(LABEL_LAYER, name, np.asarray(point.position, dtype=float), height)
    for name, definition in mechanism.points.items():
        if name in drawn:
            continue  # a pin's name is written by its circle, a marker's by its point
        link = definition.on or mechanism.ground
        at = pose.place(link, (definition.x, definition.y)) if link in pose.q else None
        if at is None:
            at = np.array([definition.x, definition.y])
        sheet.msp.add_point(tuple(map(float, at)), dxfattribs={"layer": LABEL_LAYER})
        sheet.text(LABEL_LAYER, name, at, height)
    if mechanism.name and np.all(np.isfinite(sheet.low)):
        top_left = np.array([sheet.low[0], sheet.high[1] + 0.08 * sheet.size])
        sheet.text(LABEL_LAYER, mechanism.name, top_left, 0.04 * sheet.size)
    return sheet.doc


def write_dxf(
    report: StructuralReport, plan: SolvePlan, state: KinematicState, path: str | os.PathLike[str]
) -> Path:
    """Write :func:`mechanism_dxf` to ``path``, whole or not at all.

    What the drawing leaves out of the mechanism is not said here: ask :func:`dxf_left_out`.

    Raises
    ------
    MechanismError
        ezdxf is not installed, or the file cannot be written.
    """
    doc = mechanism_dxf(report, plan, state)
    with atomic_path(path) as temporary:
        doc.saveas(temporary)
    return Path(path)


def write_parquet(result: Sweep, path: str | os.PathLike[str]) -> Path:
    """Write a sweep as a Parquet table: one row per pose, the columns of ``Sweep.as_dict``.

    The file is written whole or not at all.

    Raises
    ------
    MechanismError
        pyarrow is not installed, or the file cannot be written.
    """
    if pyarrow is None:
        raise MechanismError("Parquet export needs pyarrow: pip install 'assur[parquet]'")
    columns: Mapping[str, np.ndarray] = result.as_dict()
    table = pyarrow.table(
        {name: np.asarray(values, dtype=float) for name, values in columns.items()}
    )
    with atomic_path(path) as temporary:
        pyarrow.parquet.write_table(table, temporary)
    return Path(path)
