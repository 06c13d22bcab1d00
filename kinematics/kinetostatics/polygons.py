"""The terms of a dyad's relative-motion vector equations, as numbers.

The textbook solves a class II group (dyad) through its common point X by two
vector equations, one per way of reaching X from a point already known:

* from a pin B of a link that turns about it: ``v_C = v_B + v_CB`` with
  ``v_CB ⊥ BC``, and ``a_C = a_B + a^n_CB + a^τ_CB`` with the normal term
  ``a^n_CB = ω²·l_BC`` pointing from C to B and the tangential one
  ``a^τ_CB = ε·l_BC ⊥ BC``;
* from the point of a guide under X, for X sliding along it:
  ``v_B3 = v_B2 + v_B3B2`` with the relative velocity ``∥`` the guide, and
  ``a_B3 = a_B2 + a^k_B3B2 + a^r_B3B2`` with the Coriolis term
  ``a^k = 2·ω_guide × v_rel`` (``v_rel`` turned 90° in the sense of the guide's
  ω, magnitude ``2·ω·v_rel``) and the relative ``a^r`` along the guide;
* along a guide on the ground X's own vector is ``∥`` the guide: no term.

:func:`dyad_of` finds, for an Assur group of a solved pose, its point X and
these ways (:class:`Side`); :func:`vector_equations` evaluates every term at
the pose (:class:`Chain`, :class:`Term`), for the velocity (``order=1``) or
the acceleration (``order=2``) polygon. Each chain starts at the known point's
absolute vector and its terms, added head to tail, end at X's: the polygon
closes. Groups that are not dyads (triads and higher) have no such equations.
The notation is :mod:`kinematics.explain`'s: the point of link 3 at B is
``B3`` (:func:`point_label`).

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan, solve_pose
>>> m = parse_edgelist(["driver 1 omega=20", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 0.1", "point C 0.4 0.1", "point D 0.4 -0.3"])
>>> plan = make_plan(analyze(m)); state = solve_pose(plan)
>>> (eq,) = vector_equations(plan, state, order=2)
>>> [(c.start, [(t.key, round(float(np.hypot(*t.vector)), 9)) for t in c.terms]) for c in eq.chains]
[('B', [('a^n_CB', 0.0), ('a^τ_CB', 30.0)]), ('D', [('a^n_CD', 10.0), ('a^τ_CD', 0.0)])]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from structure.assur import AssurGroup, GroupPair
from structure.model import PairKind

from ..results.state import KinematicState
from ..solvers.plan import SolvePlan
from ..solvers.planar import cross, norm, perpendicular, rotate, unit

__all__ = [
    "Chain",
    "Dyad",
    "Side",
    "Term",
    "VectorEquation",
    "coriolis",
    "dyad_of",
    "link_rates",
    "point_at",
    "point_label",
    "point_motion",
    "relative_label",
    "slide_angle",
    "slide_direction",
    "vector_equations",
]


# ---------------------------------------------------------------- motion of a link's points


def link_rates(
    plan: SolvePlan, state: KinematicState, link: str
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``q, q̇, q̈`` (each ``(x, y, θ)``) of a link; zeros for the ground or an unsolved link."""
    if link == plan.mechanism.ground or link not in state.links:
        z = np.zeros(3)
        return z, z, z
    s = state.links[link]
    return np.asarray(s.q, float), np.asarray(s.qd, float), np.asarray(s.qdd, float)


def _motion(qd: np.ndarray, qdd: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Velocity and acceleration of a link's point at ``r`` (world axes) from the link's origin."""
    jr = perpendicular(r)
    return qd[:2] + qd[2] * jr, qdd[:2] + qdd[2] * jr - qd[2] ** 2 * r


def point_motion(
    plan: SolvePlan, state: KinematicState, link: str, p: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Velocity and acceleration of the point of ``link`` now at world position ``p``."""
    q, qd, qdd = link_rates(plan, state, link)
    return _motion(qd, qdd, np.asarray(p, float) - q[:2])


def point_at(
    plan: SolvePlan, state: KinematicState, link: str, name: str
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Position, velocity, acceleration of the point of ``link`` at sketch point ``name``."""
    q, qd, qdd = link_rates(plan, state, link)
    r = rotate(float(q[2]), np.array(plan.mechanism.coordinates(name), dtype=float))
    return (q[:2] + r, *_motion(qd, qdd, r))


def slide_angle(plan: SolvePlan, state: KinematicState, pair_id: int) -> float:
    """Angle (rad) of the slide of P pair ``pair_id`` at the pose: its ``angle=`` turned.

    The angle is the pair's ``angle=`` plus the turn of its moving link (of
    the first link when neither is the ground).

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan, solve_pose
    >>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "1 2 R B", "2 3 R C",
    ...                     "3 0 P C angle=30", "point A 0 0", "point B 0 0.1", "point C 0.3 0"])
    >>> plan = make_plan(analyze(m)); state = solve_pose(plan)
    >>> (pid,) = [p.id for p in m.pairs if p.kind.value == "P"]
    >>> import math
    >>> round(math.degrees(slide_angle(plan, state, pid)), 9), slide_direction(plan, state, pid)
    (30.0, array([0.8660254, 0.5      ]))
    """
    m = plan.mechanism
    pair = m.pair(pair_id)
    turned = pair.a if pair.a != m.ground else pair.b
    return float(link_rates(plan, state, turned)[0][2]) + (pair.angle or 0.0)


def slide_direction(plan: SolvePlan, state: KinematicState, pair_id: int) -> np.ndarray:
    """Unit direction of the slide of P pair ``pair_id`` at the pose (its ``angle=`` turned)."""
    theta = slide_angle(plan, state, pair_id)
    return unit(theta)


# ---------------------------------------------------------------- the dyad's ways to X


@dataclass(frozen=True)
class Side:
    """One way to reach the common point X of a dyad.

    ``kind`` ``'R'``: X of ``link`` turns about ``base``, a pin whose motion
    is known through link ``known``. ``'P'``: X of ``link`` slides along a
    guide of ``guide_link`` (pair ``pair``); the guide's point at X is known
    through ``known`` (the guide link itself, or the known link its pin at X
    joins). ``'G'``: the guide is the ground, so X of ``link`` just moves
    along it.
    """

    kind: str
    link: str
    known: str
    base: str = ""
    guide_link: str = ""
    pair: int = 0


@dataclass(frozen=True, eq=False)
class Dyad:
    """A dyad's common point X, the link in X's symbol, and its two sides.

    ``lhs_link`` is None when X is the pin common to both links (``v_C``);
    with a slide inside the dyad X is the pin of the block ``la`` and the
    equations are written for the point of the other link there (``v_B3``).
    """

    x: str
    where: np.ndarray  # X's position at the pose
    lhs_link: str | None
    sides: tuple[Side, ...]
    la: str = ""
    links: tuple[str, ...] = ()


def point_label(point: str, link: str | None = None) -> str:
    """``C``; ``B3`` for the point of link 3 at B; ``T4(5)``, ``B(v1)`` where that would blur.

    >>> point_label("B", "3"), point_label("T4", "5"), point_label("B", "v1")
    ('B3', 'T4(5)', 'B(v1)')
    """
    if link is None:
        return point
    if link.isdigit() and not point[-1:].isdigit():
        return point + link
    return f"{point}({link})"


def relative_label(d: Dyad, side: Side) -> str:
    """Subscript of a side's relative term: ``CB`` (X about B) or ``B3B2`` (X of 3 along 2)."""
    if side.kind == "R":
        return point_label(d.x, d.lhs_link) + side.base
    return point_label(d.x, side.link) + point_label(d.x, side.guide_link)


def _side(plan: SolvePlan, link: str, gp: GroupPair) -> Side:
    other = gp.links[1]
    if gp.kind is PairKind.R:
        return Side("R", link, other, base=gp.point or "?")
    kind = "G" if other == plan.mechanism.ground else "P"
    return Side(kind, link, other, guide_link=other, pair=gp.pair)


def _arm(plan: SolvePlan, state: KinematicState, d: Dyad, side: Side) -> np.ndarray:
    """From a pin side's base to X (world)."""
    return d.where - point_at(plan, state, side.link, side.base)[0]


def dyad_of(plan: SolvePlan, state: KinematicState, group: AssurGroup | None) -> Dyad | None:
    """The dyad's two ways to its common point, or None for a group solved as a whole.

    None too for a dyad with a higher pair, a pair without coordinates, a
    virtual link the solve did not keep (a gear mesh followed by its rolling)
    or a pin side of zero length.
    """
    m = plan.mechanism
    if group is None or len(group.links) != 2 or len(group.internal_pairs) != 1:
        return None
    if any(link not in state.links for link in group.links):
        return None
    (mid,) = group.internal_pairs
    ext: dict[str, GroupPair] = {}
    for p in group.external_pairs:
        if p.links[0] in ext:
            return None
        ext[p.links[0]] = p
    if set(ext) != set(group.links) or any(
        p.kind is PairKind.H or p.point is None or m.coordinates(p.point) is None
        for p in group.pairs
    ):
        return None
    if mid.kind is PairKind.R:
        x = mid.point or "?"
        where = point_at(plan, state, group.links[0], x)[0]
        sides = tuple(_side(plan, link, ext[link]) for link in group.links)
        d = Dyad(x, where, None, sides, links=group.links)
    else:
        pinned = [link for link in group.links if ext[link].kind is PairKind.R]
        if not pinned:
            return None
        u = slide_direction(plan, state, mid.pair)
        s = point_at(plan, state, group.links[0], mid.point or "")[0]

        def off_line(link: str) -> float:
            pin = point_at(plan, state, ext[link].links[1], ext[link].point or "")[0]
            return abs(float(cross(u, pin - s)))

        la = min(pinned, key=off_line)  # the block: its pin on the slide line if either is
        lb = group.links[1] if la == group.links[0] else group.links[0]
        x = ext[la].point or "?"
        sides = (
            _side(plan, lb, ext[lb]),
            Side("P", lb, ext[la].links[1], guide_link=la, pair=mid.pair),
        )
        d = Dyad(x, point_at(plan, state, la, x)[0], lb, sides, la, group.links)
    tiny = 1e-12 * (plan.length or 1.0)  # an arm this short has no direction (any unit of length)
    if any(side.kind == "R" and norm(_arm(plan, state, d, side)) <= tiny for side in d.sides):
        return None
    return d


# ---------------------------------------------------------------- the terms


@dataclass(frozen=True, eq=False)
class Term:
    """One term of a vector equation: ``letter^sup_sub`` and its vector at the pose.

    ``sup`` is ``''`` for a relative velocity, ``'n'``, ``'τ'`` (normal and
    tangential, about a pin), ``'k'``, ``'r'`` (Coriolis and relative, along a
    guide).
    """

    letter: str
    sup: str
    sub: str
    vector: np.ndarray

    @property
    def key(self) -> str:
        """``v_CB``, ``a^n_CB``, ``a^τ_CB``, ``a^k_B3B2``, ``a^r_B3B2``."""
        return f"{self.letter}^{self.sup}_{self.sub}" if self.sup else f"{self.letter}_{self.sub}"


@dataclass(frozen=True, eq=False)
class Chain:
    """One side of the equation: a known point's absolute vector, then the terms to X.

    ``start`` names the known point (``B``, ``D``, the guide's ``B2``) of
    ``start_link`` at world position ``start_where``; ``origin`` is its
    velocity or acceleration. ``origin + Σ terms`` is X's.
    """

    side: Side
    start: str
    start_link: str
    start_where: np.ndarray
    origin: np.ndarray
    terms: tuple[Term, ...]

    @property
    def end(self) -> np.ndarray:
        return self.origin + sum((t.vector for t in self.terms), np.zeros(2))


@dataclass(frozen=True, eq=False)
class VectorEquation:
    """A dyad's velocity (``order`` 1) or acceleration (2) equation at the pose.

    ``x`` labels the common point (``C``, ``B3``), a point of ``x_link``;
    ``value`` is its velocity or acceleration. A side along a guide on the
    ground has no chain (X's own vector is ``∥`` the guide).
    """

    label: str
    dyad: Dyad
    order: int
    x: str
    x_link: str
    value: np.ndarray
    chains: tuple[Chain, ...]


def coriolis(
    plan: SolvePlan, state: KinematicState, d: Dyad, side: Side
) -> tuple[float, np.ndarray, np.ndarray]:
    """ω of the guide, the relative velocity, the Coriolis acceleration ``2·ω×v_rel``."""
    wg = float(link_rates(plan, state, side.guide_link)[1][2])
    vrel = (
        point_motion(plan, state, side.link, d.where)[0]
        - point_motion(plan, state, side.guide_link, d.where)[0]
    )
    return wg, vrel, 2.0 * wg * perpendicular(vrel)


def _chain(plan: SolvePlan, state: KinematicState, d: Dyad, side: Side, order: int) -> Chain:
    sub = relative_label(d, side)
    if side.kind == "R":
        where = point_at(plan, state, side.link, side.base)[0]
        origin = point_motion(plan, state, side.link, where)[order - 1]
        r = d.where - where
        _, qd, qdd = link_rates(plan, state, side.link)
        w, e = float(qd[2]), float(qdd[2])
        if order == 1:
            terms = (Term("v", "", sub, w * perpendicular(r)),)
        else:
            terms = (Term("a", "n", sub, -w * w * r), Term("a", "τ", sub, e * perpendicular(r)))
        return Chain(side, side.base, side.link, where, origin, terms)
    own = point_motion(plan, state, side.link, d.where)[order - 1]
    origin = point_motion(plan, state, side.guide_link, d.where)[order - 1]
    start = point_label(d.x, side.guide_link)
    if order == 1:
        terms = (Term("v", "", sub, own - origin),)
    else:
        ak = coriolis(plan, state, d, side)[2]
        terms = (Term("a", "k", sub, ak), Term("a", "r", sub, own - origin - ak))
    return Chain(side, start, side.guide_link, d.where.copy(), origin, terms)


def vector_equations(
    plan: SolvePlan, state: KinematicState, order: int = 1
) -> list[VectorEquation]:
    """The velocity (``order=1``) or acceleration (``order=2``) equation of every dyad.

    Parameters
    ----------
    plan : SolvePlan
        From :func:`kinematics.solvers.plan.make_plan`.
    state : KinematicState
        A solved pose of ``plan``.
    order : {1, 2}
        Velocities or accelerations.

    Returns
    -------
    list of VectorEquation
        In solve order; groups that are not dyads (and the dyads
        :func:`dyad_of` leaves out) have none.

    Raises
    ------
    ValueError
        ``order`` other than 1 or 2.
    """
    if order not in (1, 2):
        raise ValueError(f"order must be 1 (velocity) or 2 (acceleration), got {order!r}")
    out: list[VectorEquation] = []
    for step in plan.steps:
        d = dyad_of(plan, state, step.group)
        if d is None:
            continue
        x_link = d.lhs_link or d.links[0]
        value = point_motion(plan, state, x_link, d.where)[order - 1]
        chains = tuple(_chain(plan, state, d, s, order) for s in d.sides if s.kind != "G")
        out.append(
            VectorEquation(
                step.label, d, order, point_label(d.x, d.lhs_link), x_link, value, chains
            )
        )
    return out
