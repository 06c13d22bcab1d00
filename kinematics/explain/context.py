"""What a worked solution knows of the mechanism at its pose, and 2-D vector helpers.

:class:`SolutionContext` holds the document being written, the plan and the
motion at the pose, and the lookups the notation needs: each link's pivot or
slide on the ground, the step that solved each link, where a slide's
reaction acts, the name of a guide (``BC``, ``x``, ``(30°)``).
:class:`NamedPoint` is a point as the solution writes it and where it is.

>>> from structure import parse_edgelist
>>> from structure.explain.document import Doc
>>> from structure.report import analyze
>>> from kinematics.solvers.plan import make_plan
>>> from kinematics.solvers.solve import solve_pose
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C",
...                     "3 0 P C angle=0", "point A 0 0", "point B 0 0.1", "point C 0.2 0"])
>>> plan = make_plan(analyze(m))
>>> ctx = SolutionContext.at_pose(Doc({}, "en"), plan, solve_pose(plan))
>>> ctx.pivot, ctx.solved_in["3"], ctx.guide(ctx.slide["3"])[1]
({'1': 'A'}, 'II(2,3)', 'AC')
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from structure.explain.document import Doc
from structure.model import Mechanism, PairKind

from ..kinetostatics.polygons import link_rates, point_at, point_label, slide_angle, slide_direction
from ..solvers.plan import SolvePlan
from ..solvers.solve import KinematicState
from .notation import direction_text, segment_name

__all__ = [
    "NamedPoint",
    "SolutionContext",
    "cross",
    "turned_left",
    "turning_rates",
    "vector_length",
]


def vector_length(v: np.ndarray) -> float:
    """The length of a 2-D vector."""
    return float(np.hypot(v[0], v[1]))


def cross(a: np.ndarray, b: np.ndarray) -> float:
    """The z component of ``a × b`` (2-D vectors)."""
    return float(a[0] * b[1] - a[1] * b[0])


def turned_left(v: np.ndarray) -> np.ndarray:
    """``v`` turned by +90°."""
    return np.array([-v[1], v[0]])


@dataclass(frozen=True)
class NamedPoint:
    """A point as the explanation writes it, and where it is at the pose."""

    name: str
    xy: np.ndarray


@dataclass(frozen=True)
class SolutionContext:
    """The mechanism, the motion at the pose, and the lookups the notation needs.

    Build it with :meth:`at_pose`; ``doc`` is the document being written.
    """

    doc: Doc
    plan: SolvePlan
    state: KinematicState
    pivot: Mapping[str, str]  # link -> its pivot on the ground
    slide: Mapping[str, int]  # link -> its P pair with the ground
    solved_in: Mapping[str, str]  # link -> label of the step that solved it
    slide_on: Mapping[int, str]  # P pair -> the link its reaction acts on

    @classmethod
    def at_pose(cls, doc: Doc, plan: SolvePlan, state: KinematicState) -> SolutionContext:
        """The context of a solution written into ``doc`` for ``plan`` at ``state``."""
        pivot, slide = _ground_pairs(plan.mechanism)
        solved_in = {d.link: f"I({d.link})" for d in plan.drivers}
        slide_on: dict[int, str] = {}
        for step in plan.steps:
            for x in step.links:
                solved_in[x] = step.label
            for eq in step.equations:
                if eq.kind == "SLIDE":
                    slide_on[eq.pair] = eq.b  # the reaction is (eq.a, eq.b), as in forces
        return cls(doc, plan, state, pivot, slide, solved_in, slide_on)

    @property
    def mechanism(self) -> Mechanism:
        """The mechanism of the plan."""
        return self.plan.mechanism

    @property
    def ground(self) -> str:
        """The ground link."""
        return self.plan.mechanism.ground

    def pin(self, name: str) -> NamedPoint:
        """A pin (or another named point) where the solve put it."""
        return NamedPoint(name, np.asarray(self.state.points[name].position))

    def slide_point(self, name: str, link: str) -> NamedPoint:
        """The point ``name`` of ``link``: where a slide's reaction on ``link`` acts.

        Once the slide has moved from the sketch, its point on ``link`` has parted from
        the one named ``name``; it is written ``E3`` (the point of link 3 at E) then.
        """
        xy = point_at(self.plan, self.state, link, name)[0]
        named = self.state.points.get(name)
        if named is None:
            return NamedPoint(name, xy)
        parted = vector_length(np.asarray(named.position) - xy) > 1e-9 * (1.0 + vector_length(xy))
        return NamedPoint(point_label(name, link) if parted else name, xy)

    def slide_at(self, pair_id: int) -> NamedPoint:
        """Where the reaction of slide ``pair_id`` acts (see :meth:`slide_point`)."""
        pair = self.mechanism.pair(pair_id)
        return self.slide_point(pair.point or "?", self.slide_on.get(pair_id, pair.b))

    def distance(self, link: str, a: str, b: str) -> float:
        """Distance between the points ``a`` and ``b`` of ``link``."""
        pa, pb = (point_at(self.plan, self.state, link, x)[0] for x in (a, b))
        return vector_length(pa - pb)

    def points_of(self, link: str) -> list[str]:
        """Named points fixed to ``link``: its pairs' points and its markers."""
        out: list[str] = []
        # a designed cam's centre of curvature at the sketch is no point of the cam elsewhere
        hidden = {cam.pair.center_of(cam.cam) for cam in self.plan.cams}
        for p in self.mechanism.pairs_of(link):
            if (
                p.point
                and p.kind is not PairKind.H
                and p.point not in hidden
                and self.mechanism.coordinates(p.point) is not None
            ):
                out.append(p.point)
        for h in self.mechanism.compound_hinges.values():
            if link in h.links and self.mechanism.coordinates(h.point) is not None:
                out.append(h.point)
        out += [p.name for p in self.mechanism.points.values() if p.on == link]
        return list(dict.fromkeys(out))

    def guide(self, pair_id: int) -> tuple[np.ndarray, str]:
        """Unit direction of a slide at the pose and its name: ``BC``, ``x``, ``(30°)``."""
        pair = self.mechanism.pair(pair_id)
        u = slide_direction(self.plan, self.state, pair_id)
        if pair.point is not None and self.mechanism.coordinates(pair.point) is not None:
            turned = pair.a if pair.a != self.ground else pair.b
            s = point_at(self.plan, self.state, turned, pair.point)[0]
            for link in pair.links:
                for q in self.points_of(link):
                    d = point_at(self.plan, self.state, link, q)[0] - s
                    size = vector_length(d)
                    if q != pair.point and size > 1e-9 and abs(cross(u, d)) <= 1e-9 * size:
                        return u, segment_name(pair.point, q)
        folded = math.degrees(slide_angle(self.plan, self.state, pair_id)) % 180.0
        if min(folded, 180.0 - folded) <= 1e-6:
            return u, "x"
        if abs(folded - 90.0) <= 1e-6:
            return u, "y"
        return u, f"({direction_text(u)}°)"

    def sense(self, value: float) -> str:
        """`` (counter-clockwise)`` or `` (clockwise)`` for a non-zero rate."""
        if abs(value) <= 1e-9:
            return ""
        return " (" + self.doc.word("ccw" if value > 0 else "cw") + ")"


def _ground_pairs(m: Mechanism) -> tuple[dict[str, str], dict[str, int]]:
    """Each link's pivot (R pair or compound hinge) and slide (P pair) on the ground."""
    pivot: dict[str, str] = {}
    slide: dict[str, int] = {}
    for p in m.pairs:
        if m.ground not in p.links:
            continue
        other = p.other(m.ground)
        if p.kind is PairKind.R and p.point:
            pivot.setdefault(other, p.point)
        elif p.kind is PairKind.P:
            slide.setdefault(other, p.id)
    for h in m.compound_hinges.values():
        if m.ground in h.links:
            for x in h.links:
                if x != m.ground:
                    pivot.setdefault(x, h.point)
    return pivot, slide


def turning_rates(ctx: SolutionContext, link: str) -> tuple[float, float]:
    """ω and ε of a link (zeros for the ground)."""
    _, qd, qdd = link_rates(ctx.plan, ctx.state, link)
    return float(qd[2]), float(qdd[2])
