"""Dyads (class II groups) in closed form, vectorised over all poses.

The pairs fix a dyad as follows (``x_Y = x_X + s·R(θ_X)·u`` and ``θ_Y = θ_X``
for a prismatic pair, a common point for a revolute pair):

* RRR: C is the intersection of the circles about its pins B and D, on the
  sketch's side of BD; RRP: the intersection of the circle about B with the
  slide's line. :func:`frame_dyad` finds the pins' positions, velocities and
  accelerations at once from the vector equations of the textbook, by
  Cramer's rule, and keeps each link's motion as a
  :class:`~kinematics.solvers.frames.Frame` (no ``arctan2``):
  ``v_C = v_B + ω1·J·BC = v_D + ω2·J·DC`` and
  ``a_C = a_B + ε1·J·BC − ω1²·BC = a_D + ε2·J·DC − ω2²·DC`` (RRR);
  ``v_C = v_K + ṡ·u = v_B + ω1·J·BC`` and
  ``a_C = a_K + s̈·u + 2·ω_g·ṡ·J·u = a_B + ε1·J·BC − ω1²·BC`` (RRP, with K
  the guide's point under C and the Coriolis term ``2·ω_g·ṡ·J·u``).
* RPR: a circle in the slide offset; PRP and RPP: a 2×2 linear system.
  :func:`place_dyad` finds the links' poses ``(x, y, θ)``; their rates come
  from the group's Jacobian (:mod:`kinematics.solvers.solve`).

The root taken is the one of the sketch (or the other, for a group in
``plan.flip``). A dyad that does not close at some input raises
:class:`~kinematics.errors.AssemblyError`, one at a dead centre
:class:`~kinematics.errors.SingularPoseError`, both naming the first such input.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan, solve_poses
>>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 1", "point C 2 1", "point D 2 0"])
>>> motion = solve_poses(make_plan(analyze(m)), [[0.0], [0.1]])
>>> sorted(motion.frames)   # the crank, and both links of the RRR dyad as frames
['1', '2', '3']
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field

import numpy as np

from structure.assur import GroupPair
from structure.model import PairKind

from ..errors import DEAD_CENTRE, AssemblyError, SingularPoseError
from .frames import GROUND_FRAME, Frame, LinkTable, frame_of_columns, unwrapped
from .paths import Watch, suspect_steps
from .plan import GroupStep, SolvePlan
from .planar import cross, rotate_many, unit, vectors

__all__ = [
    "NOT_CLOSED",
    "PinCache",
    "PointLayout",
    "frame_dyad",
    "known_frame",
    "known_pin",
    "laid_out",
    "layout_discarded",
    "place_dyad",
]


@dataclass
class PointLayout:
    """Where a sweep wants the named points' values: rows of one block it returns.

    ``block`` has shape (points, 1 or 3, 2, poses) (positions; or positions,
    velocities, accelerations) for the poses of ``inputs``; ``rows`` maps a
    point's ``(link, x, y)`` (its link and sketch coordinates) to its row. The
    first solve started inside :func:`laid_out` over these very ``inputs``
    (``owner``, its :class:`PinCache`) writes each named pin and joint it finds
    straight into its row, and notes the row in ``filled``: the values are the
    same, and they need no copy nor memory of their own.
    """

    block: np.ndarray
    rows: dict[tuple, int]
    inputs: np.ndarray
    filled: set[int] = field(default_factory=set)
    owner: object = None


_LAYOUT: ContextVar[PointLayout | None] = ContextVar("point_layout", default=None)


@contextmanager
def laid_out(layout: PointLayout) -> Iterator[PointLayout]:
    """Solves started inside may write the named points into ``layout`` (:class:`PointLayout`)."""
    token = _LAYOUT.set(layout)
    try:
        yield layout
    finally:
        _LAYOUT.reset(token)
        layout.owner = None  # the owner refers to the layout: no cycle to wait for the collector


def layout_discarded() -> None:
    """Forget what a solve that failed wrote into the current layout (its rows are free again).

    A solve that writes the named points into a sweep's layout and then fails
    (a change point found after the poses were solved) leaves rows that the
    solve the sweep goes on with, in pieces, must not take for its own.
    """
    layout = _LAYOUT.get()
    if layout is not None:
        layout.filled.clear()
        layout.owner = None


class PinCache(dict):
    """``(link, x, y) -> (x, y, vx, vy, ax, ay)``: the pins a solve has found, each once.

    ``joints`` holds the keys of the dyads' joints, which the closed forms find
    themselves; every other entry is its link's frame's :meth:`Frame.point`
    (or :meth:`Frame.position`, the rates None), as any point of that link is.
    Inside :func:`laid_out`, :meth:`targets` hands out the layout's rows.
    """

    def __init__(self) -> None:
        super().__init__()
        self.joints: set = set()
        self.layout = _LAYOUT.get()

    def on_frames(self) -> dict:
        """The entries that come from a link's frame (not the dyads' joints)."""
        return {k: v for k, v in self.items() if k not in self.joints}

    def targets(self, keys: tuple, inputs: np.ndarray, rates: bool) -> tuple | None:
        """The arrays to write the point at any of ``keys`` into: its layout row, or None.

        Two arrays (x, y) for positions, six with ``rates``; None when there
        is no layout, the point has no row (or it is filled already), or the
        solve is not the sweep's (other inputs or rates, or another solve
        has taken the layout).
        """
        layout = self.layout
        if layout is None or inputs is not layout.inputs:
            return None
        if layout.block.shape[1] != (3 if rates else 1) or layout.owner not in (None, self):
            return None
        row = next((layout.rows[k] for k in keys if k in layout.rows), None)
        if row is None or row in layout.filled:
            return None
        layout.owner = self
        layout.filled.add(row)
        rows = layout.block[row]
        return tuple(rows[k // 2, k % 2] for k in range(6 if rates else 2))


# ---------------------------------------------------------------- shared pieces


def known_frame(frames: dict[str, Frame], tables: tuple, link: str) -> Frame:
    """The frame of a link solved earlier (the ground's if it is not a moving link).

    ``tables`` are the solve's ``(q, qd, qdd)`` tables; a link solved without a
    frame gets one from its columns, kept in ``frames``.
    """
    frame = frames.get(link)
    if frame is not None:
        return frame
    q, qd, qdd = tables
    if link not in q:
        return GROUND_FRAME
    if link in qd:
        frame = frames[link] = frame_of_columns(q[link], qd[link], qdd[link])
    else:  # solved for positions only
        frame = frames[link] = frame_of_columns(q[link], None, None)
    return frame


def _sketch_point(plan: SolvePlan, name: str | None) -> np.ndarray | None:
    xy = plan.mechanism.coordinates(name) if name is not None else None
    return None if xy is None else np.array(xy, dtype=float)


def _direction(plan: SolvePlan, pair_id: int) -> np.ndarray | None:
    """The sketch direction of a prismatic pair's slide (None without ``angle=``)."""
    pair = plan.mechanism.pair(pair_id)
    if pair.angle is None:
        return None
    return unit(pair.angle)


def _flip(step: GroupStep, plan: SolvePlan) -> float:
    """−1 for a dyad to assemble in the other mode than the sketch's, else 1."""
    return -1.0 if step.group.label in plan.flip else 1.0  # type: ignore[union-attr]


def _tolerance(plan: SolvePlan) -> float:
    """How far below zero a squared length may fall from rounding (m²)."""
    return 1e-12 * plan.length**2


#: why a dyad does not close, as the errors say it
NOT_CLOSED = "the dyad cannot close (its links are too short for the distance to span)"


def _not_assembled(
    step: GroupStep, plan: SolvePlan, inputs: np.ndarray, bad: np.ndarray
) -> AssemblyError:
    """The error at the first pose of ``bad``; it keeps the rows of all of them (``indices``)."""
    k = int(np.argmax(bad))
    error = AssemblyError.at(step.label, inputs[k], NOT_CLOSED, plan.driver_kinds)
    error.indices = np.flatnonzero(bad)
    return error


def _dead_centre(step: GroupStep, plan: SolvePlan, inputs: np.ndarray, sine: np.ndarray) -> None:
    bad = np.abs(sine) <= DEAD_CENTRE
    if bad.any():
        k = int(np.argmax(bad))
        error = SingularPoseError.at(
            step.label,
            inputs[k],
            f"sine of the transmission angle {sine[k]:.2g}",
            plan.driver_kinds,
        )
        error.indices = np.flatnonzero(bad)
        raise error


def _watch_dips(solve: _FrameSolve, h2) -> None:
    """Note the steps where ``h2``, sampled at the poses, may dip to zero between them.

    ``h2`` is the square of what keeps a dyad's two assembly modes apart (the
    distance of its joint from the line of its roots; for an RRR dyad with
    equal links also the distance between its outer pins). It is smooth along
    the inputs while both modes exist, and touches zero where they meet (a
    change point) or dips below where the dyad cannot close. The steps
    :func:`~kinematics.solvers.paths.suspect_steps` finds, measured in the
    sketch's size (so in any unit of length), are appended to
    ``solve.watch`` for the solve to look into with finer steps
    (:mod:`kinematics.solvers.branches`).
    """
    if solve.watch is None or not isinstance(h2, np.ndarray) or len(h2) < 3:
        return
    plan = solve.plan
    watch = solve.watch if isinstance(solve.watch, Watch) else None
    steps = suspect_steps(
        solve.inputs,
        h2,
        None if watch is None else watch.breaks,
        path_scale=plan.driver_scale,
        value_scale=plan.length**2,
        watch=watch,
    )
    if len(steps):
        solve.watch.append((solve.step.label, steps))


def _arrays(n: int, *values):
    """The values as (N,) arrays (a dyad between two ground pins has only floats)."""
    return tuple(v if isinstance(v, np.ndarray) else np.full(n, float(v)) for v in values)


def known_pin(
    frames: dict[str, Frame],
    tables: tuple,
    pins: dict,
    link: str,
    point: np.ndarray,
    rates: bool,
    inputs: np.ndarray,
    also: tuple[str, ...] = (),
):
    """``(x, y, vx, vy, ax, ay)`` of a pin on a known link, each computed once per solve.

    Without ``rates``, the rates are None. A named pin of a sweep's layout
    is written into its row (:meth:`PinCache.targets`), whether the layout
    names it under ``link`` or under one of the links ``also`` jointed there.
    """
    key = (link, float(point[0]), float(point[1]))
    found = pins.get(key)
    if found is None:
        frame = known_frame(frames, tables, link)
        targets = None
        if isinstance(pins, PinCache) and frame is not GROUND_FRAME:
            keys = (key, *((other, key[1], key[2]) for other in also))
            targets = pins.targets(keys, inputs, rates)
        if targets is not None:
            frame.point_into(point, targets)
            found = targets if rates else (*targets, None, None, None, None)
        elif rates:
            found = frame.point(point)
        else:
            found = (*frame.position(point), None, None, None, None)
        pins[key] = found
    return found


# ---------------------------------------------------------------- RRR and RRP, as frames


@dataclass(frozen=True)
class _FrameSolve:
    """What an RRR or RRP dyad's closed form reads and writes during one solve."""

    step: GroupStep
    plan: SolvePlan
    frames: dict[str, Frame]
    tables: tuple
    pins: dict
    inputs: np.ndarray
    rates: bool = True
    watch: list | None = None

    def pin(self, link: str, point: np.ndarray) -> tuple:
        return known_pin(self.frames, self.tables, self.pins, link, point, self.rates, self.inputs)

    def targets(self, links: tuple, point: np.ndarray) -> tuple | None:
        """Where to write point ``point`` (sketch) of any of ``links``: its layout row, or None."""
        if not isinstance(self.pins, PinCache):
            return None
        keys = tuple((link, float(point[0]), float(point[1])) for link in links)
        return self.pins.targets(keys, self.inputs, self.rates)


def frame_dyad(
    step: GroupStep,
    plan: SolvePlan,
    frames: dict[str, Frame],
    tables: tuple,
    pins: dict,
    inputs: np.ndarray,
    rates: bool = True,
    watch: list | None = None,
) -> bool:
    """Solve an RRR or RRP dyad for every pose in closed form, positions and rates at once.

    False when the group is not such a dyad (or its sketch does not fix the
    assembly mode); the general path solves it then. Each link's motion is
    added to ``frames`` and declared in the ``(q, qd, qdd)`` ``tables``;
    ``pins`` caches the motion of the pins on known links. With ``rates``
    false only the positions are found (the frames' rates are None). The
    steps between poses where the dyad may have changed its assembly mode are
    appended to ``watch`` as ``(label, step indices)`` (see :func:`_watch_dips`).

    Raises
    ------
    AssemblyError
        The dyad does not close at some input (``indices``: every such row).
    SingularPoseError
        The dyad is at a dead centre at some input, or its outer pins coincide.
    """
    g = step.group
    if g is None or g.kind not in ("RRR", "RRP") or len(step.links) != 2:
        return False
    (mid,) = g.internal_pairs
    ext = {p.links[0]: p for p in g.external_pairs}
    if len(ext) != 2 or len(g.external_pairs) != 2:
        return False
    c = _sketch_point(plan, mid.point)
    if c is None:
        return False
    solve = _FrameSolve(step, plan, frames, tables, pins, inputs, rates, watch)
    placed = _frame_rrr(solve, ext, c) if g.kind == "RRR" else _frame_rrp(solve, ext, c)
    if not placed:
        return False
    for link in step.links:
        for table in tables:
            table.declare(link)
    return True


def _frame_rrr(solve: _FrameSolve, ext: Mapping[str, GroupPair], c: np.ndarray) -> bool:
    """RRR: links l1 (pin B) and l2 (pin D) meet at C on the sketch's side of BD."""
    step, plan = solve.step, solve.plan
    l1, l2 = step.links
    e1, e2 = ext[l1], ext[l2]
    b, d = _sketch_point(plan, e1.point), _sketch_point(plan, e2.point)
    if b is None or d is None:
        return False
    side = _flip(step, plan) * np.sign(cross(d - b, c - b))
    if side == 0:
        return False
    pins_b = bx, by, bvx, bvy, bax, bay = solve.pin(e1.links[1], b)
    pins_d = dx, dy, dvx, dvy, dax, day = solve.pin(e2.links[1], d)
    s1, s2 = c - b, c - d
    len1, len2 = float(s1 @ s1), float(s2 @ s2)
    _check_coincident(solve, pins_b, pins_d, len1, len2, (e1.point, e2.point))
    out = solve.targets((l1, l2), c)
    joint = (c, *_circle_circle(solve, pins_b, pins_d, len1, len2, side, out))
    solve.frames[l1] = Frame(b, bx, by, bvx, bvy, bax, bay, second=joint)
    solve.frames[l2] = Frame(d, dx, dy, dvx, dvy, dax, day, second=joint)
    return True


def _joint(solve: _FrameSolve, key1: tuple, key2: tuple, values: tuple) -> None:
    """Keep a dyad's joint in the solve's pins, under both of its links."""
    solve.pins[key1] = solve.pins[key2] = values
    if isinstance(solve.pins, PinCache):
        solve.pins.joints.update((key1, key2))


def _check_coincident(
    solve: _FrameSolve, pin_b: tuple, pin_d: tuple, len1: float, len2: float, names: tuple
) -> None:
    """Refuse the poses where an RRR dyad's outer pins coincide and its links are equal.

    C may then be anywhere on a circle (a deltoid folded onto itself): a
    singular pose, not links too short.
    """
    tol = _tolerance(solve.plan)
    if abs(len1 - len2) > tol * 1e3:  # unequal links: coinciding pins cannot close
        return
    ex, ey = pin_d[0] - pin_b[0], pin_d[1] - pin_b[1]
    gap = ex * ex + ey * ey
    _watch_dips(solve, gap)
    near = np.atleast_1d(gap <= tol)
    if near.any():
        k = int(np.argmax(near)) if near.shape[0] > 1 else 0
        error = SingularPoseError.singular(
            solve.step.label,
            solve.inputs[k],
            f"its outer pins {names[0]} and {names[1]} coincide and its links are equal, so "
            "the pin between them may be anywhere on a circle (its position is indeterminate)",
            solve.plan.driver_kinds,
        )
        error.indices = np.flatnonzero(near)
        raise error


def _circle_circle(
    solve: _FrameSolve,
    pin_b: tuple,
    pin_d: tuple,
    len1: float,
    len2: float,
    side: float,
    out: tuple | None = None,
) -> tuple:
    """``(x, y, vx, vy, ax, ay)`` of an RRR dyad's joint C from its pins B and D.

    C is at distance √len1 from B and √len2 from D, on the ``side`` of BD;
    its rates follow by :func:`_rrr_rates` (None for positions only). The
    values are written into ``out`` (two or six arrays) when given.
    Written with in-place operations on a few arrays: at 10^5 poses, fresh
    temporaries cost more (in page faults and cache misses) than the arithmetic.
    """
    step, inputs, tol = solve.step, solve.inputs, _tolerance(solve.plan)
    bx, by = pin_b[:2]
    dx, dy = pin_d[:2]
    n = inputs.shape[0]
    ex, ey = _arrays(n, dx - bx, dy - by)  # fresh arrays, free to overwrite
    d2 = ex * ex
    t = ey * ey
    d2 += t
    inv = np.sqrt(d2)
    with np.errstate(divide="ignore", invalid="ignore"):  # pins that meet: refused just below
        np.reciprocal(inv, out=inv)
    along = d2
    along += len1 - len2
    along *= inv
    along *= 0.5
    with np.errstate(invalid="ignore"):
        h = np.multiply(along, along, out=t)
        np.subtract(len1, h, out=h)
    low = h.min()
    if not low >= -tol:  # NaN too: pins that coincide with unequal links
        raise _not_assembled(step, solve.plan, inputs, ~(h >= -tol))
    if low < 0.0:
        np.maximum(h, 0.0, out=h)
    _watch_dips(solve, h)
    np.sqrt(h, out=h)
    if not solve.rates:  # |C − B|·|C − D|·sine = |BD|·h: the dead centres from h alone
        _dead_height(solve, h, inv, len1, len2)
    h *= inv
    along *= inv
    r1y = np.multiply(along, ey, out=inv)  # C − B, the side's sign taken by adding or not
    r1x = np.multiply(along, ex, out=along)
    ey *= h
    ex *= h
    if side > 0:
        r1x -= ey
        r1y += ex
    else:
        r1x += ey
        r1y -= ex
    free = ex, ey  # scratch once C is written elsewhere
    if out is None:
        out, free = (ex, ey, None, None, None, None), (None, None)
    cx, cy = np.add(bx, r1x, out=out[0]), np.add(by, r1y, out=out[1])
    if not solve.rates:
        return cx, cy, None, None, None, None
    r2x, r2y = np.subtract(cx, dx, out=free[0]), np.subtract(cy, dy, out=free[1])  # C − D
    det = np.multiply(r1x, r2y, out=h)
    t = np.multiply(r1y, r2x)
    det -= t
    scale = _inverse_lengths(len1, len2)
    if np.abs(det).min() * scale <= DEAD_CENTRE:
        _dead_centre(step, solve.plan, inputs, det * scale)
    return (cx, cy, *_rrr_rates(pin_b, pin_d, (r1x, r1y, r2x, r2y), det, t, out[2:]))


def _inverse_lengths(len1: float, len2: float) -> float:
    """1/(|BC|·|CD|) from the squared lengths, without their product over- or underflowing."""
    return 1.0 / (math.sqrt(len1) * math.sqrt(len2))


def _dead_height(solve: _FrameSolve, h: np.ndarray, inv, len1: float, len2: float) -> None:
    """The dead-centre check of an RRR dyad from C's height ``h`` over BD (``inv`` = 1/|BD|).

    The sine of the transmission angle is |BD|·h/(|BC|·|CD|); the smallest
    height over the largest ``inv`` bounds it from below, so most sweeps need
    no pass for the quotient.
    """
    scale = _inverse_lengths(len1, len2)
    if h.min() / inv.max() * scale > DEAD_CENTRE:
        return
    sine = h / inv
    if sine.min() * scale <= DEAD_CENTRE:
        _dead_centre(solve.step, solve.plan, solve.inputs, sine * scale)


def _rrr_rates(
    pin_b: tuple, pin_d: tuple, arms: tuple, det: np.ndarray, t: np.ndarray, out: tuple
) -> tuple:
    """``(vx, vy, ax, ay)`` of an RRR dyad's joint C, by Cramer's rule.

    ``v_C = v_B + ω1·J·BC = v_D + ω2·J·DC`` and
    ``a_C = a_B + ε1·J·BC − ω1²·BC = a_D + ε2·J·DC − ω2²·DC``, with ``arms``
    ``(r1x, r1y, r2x, r2y)``: ``r1 = C − B``, ``r2 = C − D``, and ``det = r1 × r2``
    (overwritten, as is the scratch array ``t``). The values are written
    into the four arrays of ``out`` (fresh ones where they are None).
    """
    r1x, r1y, r2x, r2y = arms
    bvx, bvy, bax, bay = pin_b[2:]
    dvx, dvy, dax, day = pin_d[2:]
    inv = np.reciprocal(det, out=det)
    gx, gy = dvx - bvx, dvy - bvy
    w1 = gx * r2x
    w1 += np.multiply(gy, r2y, out=t)
    w1 *= inv
    w2 = gx * r1x
    w2 += np.multiply(gy, r1y, out=t)
    w2 *= inv
    vcx = np.multiply(w1, r1y, out=out[0])
    np.subtract(bvx, vcx, out=vcx)
    vcy = np.multiply(w1, r1x, out=out[1])
    vcy += bvy
    w1 *= w1  # from here on ω1² and ω2²
    w2 *= w2
    gx = w1 * r1x
    gx -= np.multiply(w2, r2x, out=t)
    gx += dax
    gx -= bax
    gy = w1 * r1y
    gy -= np.multiply(w2, r2y, out=t)
    gy += day
    gy -= bay
    e1 = np.multiply(gx, r2x, out=gx)
    e1 += np.multiply(gy, r2y, out=t)
    e1 *= inv
    acx = np.multiply(e1, r1y, out=out[2])
    acx += np.multiply(w1, r1x, out=t)
    np.subtract(bax, acx, out=acx)
    acy = np.multiply(e1, r1x, out=out[3])
    acy -= np.multiply(w1, r1y, out=t)
    acy += bay
    return vcx, vcy, acx, acy


def _frame_rrp(solve: _FrameSolve, ext: Mapping[str, GroupPair], c: np.ndarray) -> bool:
    """RRP: a rod from pin B to joint C, and a slider at C on the guide of a known link."""
    step, plan = solve.step, solve.plan
    rod = next((x for x in step.links if ext[x].kind is PairKind.R), None)
    slider = next((x for x in step.links if ext[x].kind is PairKind.P), None)
    if rod is None or slider is None:
        return False
    b, u0 = _sketch_point(plan, ext[rod].point), _direction(plan, ext[slider].pair)
    if b is None or u0 is None:
        return False
    sigma = _flip(step, plan) * np.sign(u0 @ (c - b))
    if sigma == 0:
        return False
    s1 = c - b
    len1 = float(s1 @ s1)
    guide = known_frame(solve.frames, solve.tables, ext[slider].links[1])
    pin_b = bx, by, bvx, bvy, bax, bay = solve.pin(ext[rod].links[1], b)
    # the guide's point at C in the sketch
    origin = guide.point(c) if solve.rates else (*guide.position(c), None, None, None, None)
    ux = guide.cos * u0[0] - guide.sin * u0[1]  # the slide's direction at every pose
    uy = guide.sin * u0[0] + guide.cos * u0[1]
    s, r1x, r1y = _circle_line(solve, pin_b, origin, (ux, uy), len1, sigma)
    cx, cy = bx + r1x, by + r1y
    if solve.rates:
        rates = _rrp_rates(solve, pin_b, guide, origin, (ux, uy), s, (r1x, r1y), len1)
    else:
        _dead_centre(solve.step, plan, solve.inputs, (r1x * ux + r1y * uy) / math.sqrt(len1))
        rates = (None, None, None, None)
    joint = (c, cx, cy, *rates)
    _joint(solve, (rod, *c), (slider, *c), joint[1:])
    solve.frames[rod] = Frame(b, bx, by, bvx, bvy, bax, bay, second=joint)
    solve.frames[slider] = Frame(c, *joint[1:], turns_with=guide)
    return True


def _circle_line(
    solve: _FrameSolve,
    pin_b: tuple,
    origin: tuple,
    direction: tuple,
    len1: float,
    sigma: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(s, C − B)`` of an RRP dyad: C at √len1 from B and at ``s`` along the slide from O.

    O (``origin``) is the guide's point at C in the sketch, ``direction`` the
    slide's; the root is the one on the ``sigma`` side (the sketch's, or the
    other when flipped).
    """
    n = solve.inputs.shape[0]
    bx, by = pin_b[:2]
    ox, oy = origin[:2]
    ux, uy = direction
    wx, wy = _arrays(n, ox - bx, oy - by)
    uw = ux * wx + uy * wy
    disc = uw * uw - (wx * wx + wy * wy) + len1
    if (bad := disc < -_tolerance(solve.plan)).any():
        raise _not_assembled(solve.step, solve.plan, solve.inputs, bad)
    root = np.maximum(disc, 0.0)
    _watch_dips(solve, root)
    s = -uw + sigma * np.sqrt(root)
    return s, wx + s * ux, wy + s * uy


def _rrp_rates(
    solve: _FrameSolve,
    pin_b: tuple,
    guide: Frame,
    origin: tuple,
    direction: tuple,
    s: np.ndarray,
    rod: tuple,
    len1: float,
) -> tuple:
    """``(vx, vy, ax, ay)`` of an RRP dyad's joint C, by Cramer's rule.

    ``v_C = v_K + ṡ·u = v_B + ω1·J·BC`` and
    ``a_C = a_K + s̈·u + 2·ω_g·ṡ·J·u = a_B + ε1·J·BC − ω1²·BC``, with K the
    guide's point under C (``s`` along the slide from ``origin``, the guide's
    point at C in the sketch), ``u`` the slide's ``direction`` and ``rod`` = C − B.
    """
    _, _, bvx, bvy, bax, bay = pin_b
    _, _, ovx, ovy, oax, oay = origin
    ux, uy = direction
    r1x, r1y = rod
    wg, eg = guide.omega, guide.epsilon
    wgs = wg * wg
    kvx, kvy = ovx - wg * s * uy, ovy + wg * s * ux  # the guide's point K under C
    kax = oax - eg * s * uy - wgs * s * ux
    kay = oay + eg * s * ux - wgs * s * uy
    det = r1x * ux + r1y * uy
    _dead_centre(solve.step, solve.plan, solve.inputs, det / math.sqrt(len1))
    inv = 1.0 / det
    gx, gy = kvx - bvx, kvy - bvy
    w1 = (ux * gy - uy * gx) * inv
    sd = -(r1x * gx + r1y * gy) * inv
    w1s = w1 * w1
    coriolis = 2.0 * wg * sd
    gx = kax - coriolis * uy - bax + w1s * r1x
    gy = kay + coriolis * ux - bay + w1s * r1y
    e1 = (ux * gy - uy * gx) * inv
    vcx, vcy = bvx - w1 * r1y, bvy + w1 * r1x
    return vcx, vcy, bax - e1 * r1y - w1s * r1x, bay + e1 * r1x - w1s * r1y


# ---------------------------------------------------------------- RPR, PRP, RPP, as poses


@dataclass(frozen=True)
class _Dyad:
    """A dyad read from one end: link ``first`` (outer pair ``outer_first``), the middle pair,
    link ``second`` (outer pair ``outer_second``)."""

    first: str
    second: str
    outer_first: GroupPair
    middle: GroupPair
    outer_second: GroupPair

    @property
    def kinds(self) -> tuple[PairKind, PairKind, PairKind]:
        return (self.outer_first.kind, self.middle.kind, self.outer_second.kind)


def _read_dyad(step: GroupStep) -> _Dyad | None:
    """The dyad's links and pairs, read from the end that puts a revolute pair first if any."""
    g = step.group
    if g is None or g.kind is None or len(step.links) != 2:
        return None
    (mid,) = g.internal_pairs
    ext = {
        x: g_pairs
        for x in step.links
        if (g_pairs := [p for p in g.external_pairs if p.links[0] == x])
    }
    if len(ext) != 2 or any(len(v) != 1 for v in ext.values()):
        return None
    l1, l2 = step.links
    dyad = _Dyad(l1, l2, ext[l1][0], mid, ext[l2][0])
    if dyad.kinds in (
        (PairKind.P, PairKind.R, PairKind.R),
        (PairKind.P, PairKind.P, PairKind.R),
    ):  # read it from the other end
        dyad = _Dyad(l2, l1, ext[l2][0], mid, ext[l1][0])
    return dyad


def place_dyad(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray) -> bool:
    """Place an RPR, PRP or RPP dyad for every pose at once; False when no closed form applies.

    The links' poses ``(x, y, θ)`` (N, 3) are stored in ``q``.

    Raises
    ------
    AssemblyError
        The dyad does not close at some input.
    """
    dyad = _read_dyad(step)
    if dyad is None:
        return False
    place = _PLACE_BY_KINDS.get(dyad.kinds)
    return place is not None and place(step, plan, q, inputs, dyad)


def _world(q: Mapping, link: str, c: np.ndarray, n: int) -> np.ndarray:
    """World positions (N, 2) of sketch point ``c`` of ``link`` (fixed for the ground)."""
    if link not in q:
        return np.broadcast_to(c, (n, 2)).copy()
    frame = q.frame(link) if isinstance(q, LinkTable) else None
    if frame is not None:
        return vectors(*frame.position(c), n)
    return q[link][:, :2] + rotate_many(q[link][:, 2], c)


def _angle_of(q: Mapping, link: str, n: int) -> np.ndarray:
    return q[link][:, 2] if link in q else np.zeros(n)


def _solve2(
    a: np.ndarray, b: np.ndarray, rhs: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Solve s·a + t·b = rhs for many poses (2-vectors); also the determinants."""
    det = cross(a, b)
    safe = np.where(det == 0, 1.0, det)
    return cross(rhs, b) / safe, cross(a, rhs) / safe, det


def _place_rpr(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray, dyad: _Dyad) -> bool:
    """RPR: both links turn together; the slide spans the pins."""
    b, d = _sketch_point(plan, dyad.outer_first.point), _sketch_point(plan, dyad.outer_second.point)
    u0 = _direction(plan, dyad.middle.pair)
    if b is None or d is None or u0 is None:
        return False
    w = d - b
    sigma = _flip(step, plan) * np.sign(u0 @ w)
    if sigma == 0:
        return False
    n = inputs.shape[0]
    bw = _world(q, dyad.outer_first.links[1], b, n)
    dw = _world(q, dyad.outer_second.links[1], d, n)
    e = dw - bw
    uw = float(u0 @ w)
    disc = uw**2 - float(w @ w) + np.einsum("ij,ij->i", e, e)
    if (bad := disc < -_tolerance(plan)).any():
        raise _not_assembled(step, plan, inputs, bad)
    s = -uw + sigma * np.sqrt(np.maximum(disc, 0.0))
    span = w[None, :] + s[:, None] * u0[None, :]
    theta = np.arctan2(e[:, 1], e[:, 0]) - np.arctan2(span[:, 1], span[:, 0])
    theta = unwrapped((theta + math.pi) % (2 * math.pi) - math.pi)
    q[dyad.first] = np.column_stack([bw - rotate_many(theta, b), theta])
    q[dyad.second] = np.column_stack([dw - rotate_many(theta, d), theta])
    return True


def _parallel_slides(step: GroupStep, plan: SolvePlan, inputs: np.ndarray, det: np.ndarray) -> None:
    """Refuse the poses where a dyad's two slides are parallel (``det``: the sine between them).

    The slides then meet nowhere, or everywhere along them: a singular pose.
    """
    if (bad := np.abs(det) < 1e-12).any():
        k = int(np.argmax(bad))
        error = SingularPoseError.singular(
            step.label,
            inputs[k],
            "its two slides are parallel, so they meet nowhere (or anywhere along them)",
            plan.driver_kinds,
        )
        error.indices = np.flatnonzero(bad)
        raise error


def _place_prp(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray, dyad: _Dyad) -> bool:
    """PRP: each slider keeps its guide's angle; the pin joins them."""
    c = _sketch_point(plan, dyad.middle.point)
    u1, u2 = _direction(plan, dyad.outer_first.pair), _direction(plan, dyad.outer_second.pair)
    if c is None or u1 is None or u2 is None:
        return False
    n = inputs.shape[0]
    k1, k2 = dyad.outer_first.links[1], dyad.outer_second.links[1]
    t1, t2 = _angle_of(q, k1, n), _angle_of(q, k2, n)
    big_u1, big_u2 = rotate_many(t1, u1), rotate_many(t2, u2)
    gap = _world(q, k2, c, n) - _world(q, k1, c, n)
    s1, s2, det = _solve2(big_u1, -big_u2, gap)
    _parallel_slides(step, plan, inputs, det)
    x1 = (q[k1][:, :2] if k1 in q else 0.0) + s1[:, None] * big_u1
    x2 = (q[k2][:, :2] if k2 in q else 0.0) + s2[:, None] * big_u2
    q[dyad.first] = np.column_stack([np.broadcast_to(x1, (n, 2)), t1])
    q[dyad.second] = np.column_stack([np.broadcast_to(x2, (n, 2)), t2])
    return True


def _place_rpp(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray, dyad: _Dyad) -> bool:
    """RPP: the guides fix both angles; the pin fixes the first link."""
    b = _sketch_point(plan, dyad.outer_first.point)
    um, u2 = _direction(plan, dyad.middle.pair), _direction(plan, dyad.outer_second.pair)
    if b is None or um is None or u2 is None:
        return False
    n = inputs.shape[0]
    k2 = dyad.outer_second.links[1]
    theta = _angle_of(q, k2, n)
    bw = _world(q, dyad.outer_first.links[1], b, n)
    x1 = bw - rotate_many(theta, b)
    big_um, big_u2 = rotate_many(theta, um), rotate_many(theta, u2)
    xk2 = q[k2][:, :2] if k2 in q else np.zeros((n, 2))
    sm, _, det = _solve2(big_um, -big_u2, xk2 - x1)
    _parallel_slides(step, plan, inputs, det)
    q[dyad.first] = np.column_stack([x1, theta])
    q[dyad.second] = np.column_stack([x1 + sm[:, None] * big_um, theta])
    return True


_PLACE_BY_KINDS: dict[tuple[PairKind, PairKind, PairKind], Callable[..., bool]] = {
    (PairKind.R, PairKind.P, PairKind.R): _place_rpr,
    (PairKind.P, PairKind.R, PairKind.P): _place_prp,
    (PairKind.R, PairKind.P, PairKind.P): _place_rpp,
}
