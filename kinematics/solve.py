"""Positions, velocities and accelerations, group by group from the drivers, for many poses.

Each link's state is ``(x, y, θ)``: the displacement and rotation of its frame
from the sketch pose (where every link is at ``(0, 0, 0)``). For every pose
the drivers are placed from their input; then each Assur group, in solve
order, is

* positioned: RRR and RRP dyads in closed form, vectorised over all poses,
  with the sketch's assembly mode (the sign of the square root), other groups
  by Newton's method on their own equations, started from the previous pose
  (the sketch for the first);
* given its velocities from ``J_g·q̇_g = −J_k·q̇_k`` (``k``: the known links its
  external pairs touch) and its accelerations from
  ``J_g·q̈_g = −J_k·q̈_k − (dJ/dt)·q̇``, as batched linear solves.

A group that cannot be assembled raises :class:`AssemblyError`; one whose
Jacobian loses rank (a dead centre) raises :class:`SingularPoseError`. Both
name the group and the input; nothing is returned as NaN.

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.plan import make_plan
>>> m = parse_edgelist(["driver 1 omega=20", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 0.1", "point C 0.4 0.1", "point D 0.4 -0.3"])
>>> state = solve_pose(make_plan(analyze(m)))
>>> round(state.links["3"].omega, 12), abs(round(state.links["2"].omega, 12))
(5.0, 0.0)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from structure.errors import MechanismError
from structure.model import PairKind

from .equations import evaluate, rotate_many
from .frames import (
    GROUND_FRAME,
    Frame,
    LinkTable,
    frame_of_columns,
    unwrapped,
)
from .plan import GroupStep, SolvePlan

__all__ = [
    "AssemblyError",
    "KinematicState",
    "LinkState",
    "Motion",
    "PointState",
    "SingularPoseError",
    "solve_pose",
    "solve_poses",
]

_MAX_NEWTON = 60
_SINGULAR = 1e-6  # Newton stops within ~1e-7 of a double root, so test above that


class AssemblyError(MechanismError):
    """A group cannot be assembled at the requested input (it does not close)."""

    def __init__(self, message: str, group: str = "", pose: object = None):
        self.group = group
        self.pose = pose
        super().__init__(message)


class SingularPoseError(MechanismError):
    """A group's Jacobian loses rank at the pose (a dead centre)."""

    def __init__(self, message: str, group: str = "", pose: object = None):
        self.group = group
        self.pose = pose
        super().__init__(message)


@dataclass(frozen=True)
class Motion:
    """Arrays over poses: ``q``, ``qd``, ``qdd`` per link (shape (N, 3)), and the inputs.

    ``frames`` holds the links solved in closed form as
    :class:`~kinematics.frames.Frame` s; their ``q`` (which needs the angle's
    ``arctan2``) is computed the first time it is read, and :meth:`point`
    uses the frame directly.
    """

    inputs: np.ndarray
    q: Mapping[str, np.ndarray]
    qd: Mapping[str, np.ndarray]
    qdd: Mapping[str, np.ndarray]
    frames: Mapping[str, Frame] = field(default_factory=dict)

    def point(self, link: str, c: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity, acceleration (each (N, 2)) of sketch point ``c`` on ``link``."""
        frame = self.frames.get(link)
        if frame is not None:
            n = self.inputs.shape[0]
            x, y, vx, vy, ax, ay = frame.point(c)
            return _pairs(x, y, n), _pairs(vx, vy, n), _pairs(ax, ay, n)
        q, v, a = self.q[link], self.qd[link], self.qdd[link]
        r = rotate_many(q[:, 2], c)
        jr = np.stack([-r[:, 1], r[:, 0]], axis=1)
        w, e = v[:, 2:3], a[:, 2:3]
        return q[:, :2] + r, v[:, :2] + w * jr, a[:, :2] + e * jr - w**2 * r


@dataclass(frozen=True)
class LinkState:
    """A link's pose (from the sketch), angular velocity and angular acceleration."""

    q: np.ndarray  # (x, y, θ)
    qd: np.ndarray
    qdd: np.ndarray

    @property
    def angle(self) -> float:
        """Rotation from the sketch pose, rad (counter-clockwise positive)."""
        return float(self.q[2])

    @property
    def omega(self) -> float:
        return float(self.qd[2])

    @property
    def epsilon(self) -> float:
        return float(self.qdd[2])


@dataclass(frozen=True)
class PointState:
    """Position, velocity and acceleration of a point, world frame, SI units."""

    link: str
    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray


@dataclass(frozen=True)
class KinematicState:
    """Every link's and every named point's motion at one pose."""

    links: Mapping[str, LinkState]
    points: Mapping[str, PointState]
    inputs: tuple[float, ...]


def _fmt(inputs: np.ndarray) -> str:
    return ", ".join(f"{x:.6g}" for x in np.atleast_1d(inputs))


def _norm(v: np.ndarray) -> np.ndarray:
    """Length of each row of an (N, 2) array (``np.hypot`` is several times slower)."""
    return np.sqrt(v[:, 0] * v[:, 0] + v[:, 1] * v[:, 1])


def _pairs(x, y, n: int) -> np.ndarray:
    """An (N, 2) array from two columns (arrays or floats)."""
    out = np.empty((n, 2))
    out[:, 0] = x
    out[:, 1] = y
    return out


def _place_drivers(
    plan: SolvePlan, inputs: np.ndarray, frames: dict[str, Frame], tables: tuple
) -> None:
    """Each driver's frame: a crank turned by its input about its pivot, a slider moved along."""
    for k, d in enumerate(plan.drivers):
        value = inputs[:, k]
        if d.kind == "R":
            px, py = float(d.pivot[0]), float(d.pivot[1])
            frames[d.link] = Frame(
                d.pivot.copy(), px, py, 0.0, 0.0, 0.0, 0.0,
                np.cos(value), np.sin(value), float(d.speed), float(d.acceleration), value,
            )  # fmt: skip
        else:
            ux, uy = float(d.direction[0]), float(d.direction[1])
            v, a = float(d.speed), float(d.acceleration)
            frames[d.link] = Frame(
                np.zeros(2), value * ux, value * uy, v * ux, v * uy, a * ux, a * uy,
                1.0, 0.0, 0.0, 0.0, 0.0,
            )  # fmt: skip
        for table in tables:
            table.declare(d.link)


def _known_frame(frames: dict[str, Frame], tables: tuple, link: str) -> Frame:
    """The frame of a link solved earlier (the ground's if it is not a moving link)."""
    frame = frames.get(link)
    if frame is not None:
        return frame
    q, qd, qdd = tables
    if link not in q:
        return GROUND_FRAME
    frame = frames[link] = frame_of_columns(q[link], qd[link], qdd[link])
    return frame


def _system(
    step: GroupStep, q: Mapping, v: Mapping, n: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Residual (N, m), group Jacobian (N, m, m), known-link terms J_k·v_k and (dJ/dt)·v."""
    index = {link: i for i, link in enumerate(step.links)}
    m = 3 * len(step.links)
    rows_total = sum(eq.size for eq in step.equations)
    zero = np.zeros((n, 3))
    phi = np.zeros((n, rows_total))
    jac = np.zeros((n, rows_total, m))
    known = np.zeros((n, rows_total))
    bias = np.zeros((n, rows_total))
    row = 0
    for eq in step.equations:
        if eq.kind == "GEAR":  # (θa − θc) + k·(θb − θc) = 0: linear, no bias term
            coefficients = ((eq.a, 1.0), (eq.b, eq.ratio), (eq.carrier, -1.0 - eq.ratio))
            for link, k in coefficients:
                phi[:, row] += k * q.get(link, zero)[:, 2]
                i = index.get(link)
                if i is None:
                    known[:, row] += k * v.get(link, zero)[:, 2]
                else:
                    jac[:, row, 3 * i + 2] += k
            row += 1
            continue
        qa, qb = q.get(eq.a, zero), q.get(eq.b, zero)
        va, vb = v.get(eq.a, zero), v.get(eq.b, zero)
        f, ja, jb, g = evaluate(eq, qa, qb, va, vb)
        rows = slice(row, row + eq.size)
        phi[:, rows] = f
        bias[:, rows] = g
        for link, part, vel in ((eq.a, ja, va), (eq.b, jb, vb)):
            k = index.get(link)
            if k is None:
                known[:, rows] += np.einsum("nij,nj->ni", part, vel)
            else:
                jac[:, rows, 3 * k : 3 * k + 3] += part
        row += eq.size
    return phi, jac, known, bias


def _scaled(jac: np.ndarray, length: float) -> np.ndarray:
    scaled = jac.copy()
    scaled[..., 2::3] /= length
    return scaled


def _newton(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray) -> None:
    """Newton on one pose (arrays of one row) from the current ``q`` of the group's links."""
    tol = 1e-13 * plan.length
    norm = math.inf
    for _ in range(_MAX_NEWTON):
        phi, jac, _, _ = _system(step, q, {}, 1)
        norm = float(np.linalg.norm(phi))
        if norm <= tol:
            return
        dz = np.linalg.lstsq(_scaled(jac, plan.length)[0], -phi[0], rcond=None)[0]
        dz[2::3] /= plan.length
        base = {link: q[link].copy() for link in step.links}
        step_size = 1.0
        while True:
            for i, link in enumerate(step.links):
                q[link] = base[link] + step_size * dz[3 * i : 3 * i + 3]
            trial = float(np.linalg.norm(_system(step, q, {}, 1)[0]))
            if trial < norm or step_size < 1e-6:
                break
            step_size /= 2
    if norm > 1e-9 * plan.length:
        raise AssemblyError(
            f"group {step.label} cannot be assembled at input {_fmt(inputs)}: its pairs do not "
            f"close (residual {norm:.3g} m after {_MAX_NEWTON} Newton steps)",
            step.label,
            tuple(np.atleast_1d(inputs)),
        )


def _external(step: GroupStep, link: str, kind: PairKind):
    pairs = step.group.external_pairs if step.group is not None else ()
    return [p for p in pairs if p.links[0] == link and p.kind is kind]


def _sketch_angle(v: np.ndarray) -> float:
    return math.atan2(float(v[1]), float(v[0]))


def _world(q: Mapping, link: str, c: np.ndarray, n: int) -> np.ndarray:
    if link not in q:
        return np.broadcast_to(c, (n, 2)).copy()
    frame = q.frame(link) if isinstance(q, LinkTable) else None
    if frame is not None:
        return _pairs(*frame.position(c), n)
    return q[link][:, :2] + rotate_many(q[link][:, 2], c)


def _not_assembled(step: GroupStep, inputs: np.ndarray, bad: np.ndarray) -> AssemblyError:
    k = int(np.argmax(bad))
    return AssemblyError(
        f"group {step.label} cannot be assembled at input {_fmt(inputs[k])}: "
        "the dyad cannot close (its links are too short for the distance to span)",
        step.label,
        tuple(np.atleast_1d(inputs[k])),
    )


def _direction(plan: SolvePlan, pair_id: int) -> np.ndarray | None:
    pair = plan.mechanism.pair(pair_id)
    if pair.angle is None:
        return None
    return np.array([math.cos(pair.angle), math.sin(pair.angle)])


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _angle_of(q: Mapping, link: str, n: int) -> np.ndarray:
    return q[link][:, 2] if link in q else np.zeros(n)


def _solve2(
    a: np.ndarray, b: np.ndarray, rhs: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Solve s·a + t·b = rhs for many poses (2-vectors); also the determinants."""
    det = _cross(a, b)
    safe = np.where(det == 0, 1.0, det)
    return _cross(rhs, b) / safe, _cross(a, rhs) / safe, det


def _closed_form(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray) -> bool:
    """Place a dyad for every pose at once; False when no closed form applies.

    The pairs fix the dyad as follows (``x_Y = x_X + s·R(θ_X)·u`` and
    ``θ_Y = θ_X`` for a prismatic pair, a common point for a revolute pair):
    (RRR and RRP are placed by :func:`_dyad_frames`.) RPR a circle in
    the slide offset, PRP and RPP a 2×2 linear system. The root is the one of
    the sketch (or the other, for a group in ``plan.flip``).
    """
    g = step.group
    if g is None or g.kind is None or len(step.links) != 2:
        return False
    m = plan.mechanism
    n = inputs.shape[0]
    flip = -1.0 if g.label in plan.flip else 1.0

    def point(name: str | None) -> np.ndarray | None:
        xy = m.coordinates(name) if name is not None else None
        return None if xy is None else np.array(xy, dtype=float)

    (mid,) = g.internal_pairs
    ext = {
        x: g_pairs
        for x in step.links
        if (g_pairs := [p for p in g.external_pairs if p.links[0] == x])
    }
    if len(ext) != 2 or any(len(v) != 1 for v in ext.values()):
        return False
    (l1, l2) = step.links
    e1, e2 = ext[l1][0], ext[l2][0]
    kinds = (e1.kind.value, mid.kind.value, e2.kind.value)
    if kinds in (("P", "R", "R"), ("P", "P", "R")):  # read it from the other end
        l1, l2, e1, e2 = l2, l1, e2, e1
        kinds = kinds[::-1]
    tol = 1e-12 * plan.length**2
    if kinds == ("R", "P", "R"):  # both links turn together; the slide spans the pins
        b, d, u0 = point(e1.point), point(e2.point), _direction(plan, mid.pair)
        if b is None or d is None or u0 is None:
            return False
        w = d - b
        sigma = flip * np.sign(u0 @ w)
        if sigma == 0:
            return False
        bw, dw = _world(q, e1.links[1], b, n), _world(q, e2.links[1], d, n)
        e = dw - bw
        uw = float(u0 @ w)
        disc = uw**2 - float(w @ w) + np.einsum("ij,ij->i", e, e)
        if (bad := disc < -tol).any():
            raise _not_assembled(step, inputs, bad)
        s = -uw + sigma * np.sqrt(np.maximum(disc, 0.0))
        span = w[None, :] + s[:, None] * u0[None, :]
        theta = np.arctan2(e[:, 1], e[:, 0]) - np.arctan2(span[:, 1], span[:, 0])
        theta = unwrapped((theta + math.pi) % (2 * math.pi) - math.pi)
        q[l1] = np.column_stack([bw - rotate_many(theta, b), theta])
        q[l2] = np.column_stack([dw - rotate_many(theta, d), theta])
        return True
    if kinds == ("P", "R", "P"):  # each slider keeps its guide's angle; the pin joins them
        c, u1, u2 = point(mid.point), _direction(plan, e1.pair), _direction(plan, e2.pair)
        if c is None or u1 is None or u2 is None:
            return False
        k1, k2 = e1.links[1], e2.links[1]
        t1, t2 = _angle_of(q, k1, n), _angle_of(q, k2, n)
        big_u1, big_u2 = rotate_many(t1, u1), rotate_many(t2, u2)
        gap = _world(q, k2, c, n) - _world(q, k1, c, n)
        s1, s2, det = _solve2(big_u1, -big_u2, gap)
        if (bad := np.abs(det) < 1e-12).any():
            raise _not_assembled(step, inputs, bad)
        x1 = (q[k1][:, :2] if k1 in q else 0.0) + s1[:, None] * big_u1
        x2 = (q[k2][:, :2] if k2 in q else 0.0) + s2[:, None] * big_u2
        q[l1] = np.column_stack([np.broadcast_to(x1, (n, 2)), t1])
        q[l2] = np.column_stack([np.broadcast_to(x2, (n, 2)), t2])
        return True
    if kinds == ("R", "P", "P"):  # the guides fix both angles; the pin fixes l1
        b, um, u2 = point(e1.point), _direction(plan, mid.pair), _direction(plan, e2.pair)
        if b is None or um is None or u2 is None:
            return False
        k2 = e2.links[1]
        theta = _angle_of(q, k2, n)
        bw = _world(q, e1.links[1], b, n)
        x1 = bw - rotate_many(theta, b)
        big_um, big_u2 = rotate_many(theta, um), rotate_many(theta, u2)
        xk2 = q[k2][:, :2] if k2 in q else np.zeros((n, 2))
        sm, _, det = _solve2(big_um, -big_u2, xk2 - x1)
        if (bad := np.abs(det) < 1e-12).any():
            raise _not_assembled(step, inputs, bad)
        q[l1] = np.column_stack([x1, theta])
        q[l2] = np.column_stack([x1 + sm[:, None] * big_um, theta])
        return True
    return False


def _dead_centre(step: GroupStep, inputs: np.ndarray, sine: np.ndarray) -> None:
    bad = np.abs(sine) <= _SINGULAR
    if bad.any():
        k = int(np.argmax(bad))
        raise SingularPoseError(
            f"group {step.label} is at a dead centre at input {_fmt(inputs[k])}: its "
            f"Jacobian loses rank (sine of the transmission angle {sine[k]:.2g}; "
            "transmission angle 0° or 180°)",
            step.label,
            tuple(inputs[k]),
        )


def _arrays(n: int, *values):
    """The values as (N,) arrays (a dyad between two ground pins has only floats)."""
    return tuple(v if isinstance(v, np.ndarray) else np.full(n, float(v)) for v in values)


def _pin(frames: dict[str, Frame], tables: tuple, pins: dict, link: str, point: np.ndarray):
    """``(x, y, vx, vy, ax, ay)`` of a pin on a known link, each computed once per solve."""
    key = (link, float(point[0]), float(point[1]))
    found = pins.get(key)
    if found is None:
        found = pins[key] = _known_frame(frames, tables, link).point(point)
    return found


def _circle_circle(
    step: GroupStep,
    inputs: np.ndarray,
    pin_b: tuple,
    pin_d: tuple,
    len1: float,
    len2: float,
    side: float,
    tol: float,
) -> tuple:
    """``(x, y, vx, vy, ax, ay)`` of an RRR dyad's joint C from its pins B and D.

    C is at distance √len1 from B and √len2 from D, on the ``side`` of BD;
    ``v_C = v_B + ω1·J·BC = v_D + ω2·J·DC`` and
    ``a_C = a_B + ε1·J·BC − ω1²·BC = a_D + ε2·J·DC − ω2²·DC`` by Cramer's
    rule. Written with in-place operations: at 10^5 poses, fresh temporaries
    cost more (in page faults) than the arithmetic.
    """
    bx, by, bvx, bvy, bax, bay = pin_b
    dx, dy, dvx, dvy, dax, day = pin_d
    n = inputs.shape[0]
    ex, ey = _arrays(n, dx - bx, dy - by)  # fresh arrays, free to overwrite
    d2 = ex * ex
    t = ey * ey
    d2 += t
    inv = np.sqrt(d2)
    np.reciprocal(inv, out=inv)
    along = d2
    along += len1 - len2
    along *= inv
    along *= 0.5
    h = np.multiply(along, along, out=t)
    np.subtract(len1, h, out=h)
    if (bad := h < -tol).any():
        raise _not_assembled(step, inputs, bad)
    np.maximum(h, 0.0, out=h)
    np.sqrt(h, out=h)
    h *= side
    h *= inv
    along *= inv
    r1x = along * ex  # C − B
    r1y = along * ey
    ey *= h
    ex *= h
    r1x -= ey
    r1y += ex
    cx, cy = bx + r1x, by + r1y
    r2x, r2y = cx - dx, cy - dy  # C − D
    cross = r1x * r2y
    t = np.multiply(r1y, r2x, out=ex)
    cross -= t
    _dead_centre(step, inputs, cross * (1.0 / math.sqrt(len1 * len2)))
    inv = np.reciprocal(cross, out=cross)
    gx, gy = dvx - bvx, dvy - bvy
    w1 = gx * r2x
    w1 += np.multiply(gy, r2y, out=t)
    w1 *= inv
    w2 = gx * r1x
    w2 += np.multiply(gy, r1y, out=t)
    w2 *= inv
    vcx = w1 * r1y
    np.subtract(bvx, vcx, out=vcx)
    vcy = w1 * r1x
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
    acx = e1 * r1y
    acx += np.multiply(w1, r1x, out=t)
    np.subtract(bax, acx, out=acx)
    acy = e1 * r1x
    acy -= np.multiply(w1, r1y, out=t)
    acy += bay
    return cx, cy, vcx, vcy, acx, acy


def _dyad_frames(
    step: GroupStep,
    plan: SolvePlan,
    frames: dict[str, Frame],
    tables: tuple,
    pins: dict,
    inputs: np.ndarray,
) -> bool:
    """Solve an RRR or RRP dyad for every pose in closed form, positions and rates at once.

    False when the group is not such a dyad (or its sketch does not fix the
    assembly mode); the general path solves it then. The pins' positions,
    velocities and accelerations come from the vector equations of the
    textbook, by Cramer's rule, and each link's motion is kept as a
    :class:`~kinematics.frames.Frame` (no ``arctan2``):

    * RRR (pins B, D on known links, joint C): C is the circle–circle
      intersection on the sketch's side; ``v_C = v_B + ω1·J·BC = v_D + ω2·J·DC``
      and ``a_C = a_B + ε1·J·BC − ω1²·BC = a_D + ε2·J·DC − ω2²·DC``.
    * RRP (rod from pin B to joint C, slider on the guide of a known link):
      C is the circle–line intersection; ``v_C = v_K + ṡ·u = v_B + ω1·J·BC``
      and ``a_C = a_K + s̈·u + 2·ω_g·ṡ·J·u = a_B + ε1·J·BC − ω1²·BC``, with
      K the guide's point under C and the Coriolis term ``2·ω_g·ṡ·J·u``.
    """
    g = step.group
    if g is None or g.kind not in ("RRR", "RRP") or len(step.links) != 2:
        return False
    m = plan.mechanism
    (mid,) = g.internal_pairs
    ext = {p.links[0]: p for p in g.external_pairs}
    if len(ext) != 2 or len(g.external_pairs) != 2:
        return False

    def point(name: str | None) -> np.ndarray | None:
        xy = m.coordinates(name) if name is not None else None
        return None if xy is None else np.array(xy, dtype=float)

    c = point(mid.point)
    if c is None:
        return False
    n = inputs.shape[0]
    flip = -1.0 if g.label in plan.flip else 1.0
    tol = 1e-12 * plan.length**2
    if g.kind == "RRR":
        l1, l2 = step.links
        e1, e2 = ext[l1], ext[l2]
        b, d = point(e1.point), point(e2.point)
        if b is None or d is None:
            return False
        side = flip * np.sign(_cross(d - b, c - b))
        if side == 0:
            return False
        pins_b = bx, by, bvx, bvy, bax, bay = _pin(frames, tables, pins, e1.links[1], b)
        pins_d = dx, dy, dvx, dvy, dax, day = _pin(frames, tables, pins, e2.links[1], d)
        s1, s2 = c - b, c - d
        joint = (c, *_circle_circle(step, inputs, pins_b, pins_d, float(s1 @ s1), float(s2 @ s2),
                                    side, tol))  # fmt: skip
        pins[(l1, *c)] = pins[(l2, *c)] = joint[1:]
        frames[l1] = Frame(b, bx, by, bvx, bvy, bax, bay, second=joint)
        frames[l2] = Frame(d, dx, dy, dvx, dvy, dax, day, second=joint)
    else:
        rod = next((x for x in step.links if ext[x].kind is PairKind.R), None)
        slider = next((x for x in step.links if ext[x].kind is PairKind.P), None)
        if rod is None or slider is None:
            return False
        b, u0 = point(ext[rod].point), _direction(plan, ext[slider].pair)
        if b is None or u0 is None:
            return False
        sigma = flip * np.sign(u0 @ (c - b))
        if sigma == 0:
            return False
        s1 = c - b
        len1 = float(s1 @ s1)
        fg = _known_frame(frames, tables, ext[slider].links[1])
        bx, by, bvx, bvy, bax, bay = _pin(frames, tables, pins, ext[rod].links[1], b)
        ox, oy, ovx, ovy, oax, oay = fg.point(c)  # the guide's point at C in the sketch
        ux = fg.cos * u0[0] - fg.sin * u0[1]
        uy = fg.sin * u0[0] + fg.cos * u0[1]
        wx, wy = _arrays(n, ox - bx, oy - by)
        uw = ux * wx + uy * wy
        disc = uw * uw - (wx * wx + wy * wy) + len1
        if (bad := disc < -tol).any():
            raise _not_assembled(step, inputs, bad)
        s = -uw + sigma * np.sqrt(np.maximum(disc, 0.0))
        r1x, r1y = wx + s * ux, wy + s * uy  # C − B
        cx, cy = bx + r1x, by + r1y
        wg, eg = fg.omega, fg.epsilon
        wgs = wg * wg
        kvx, kvy = ovx - wg * s * uy, ovy + wg * s * ux  # the guide's point K under C
        kax = oax - eg * s * uy - wgs * s * ux
        kay = oay + eg * s * ux - wgs * s * uy
        det = r1x * ux + r1y * uy
        _dead_centre(step, inputs, det / math.sqrt(len1))
        inv = 1.0 / det
        gx, gy = kvx - bvx, kvy - bvy
        w1 = (ux * gy - uy * gx) * inv
        sd = -(r1x * gx + r1y * gy) * inv
        w1s = w1 * w1
        coriolis = 2.0 * wg * sd
        gx = kax - coriolis * uy - bax + w1s * r1x
        gy = kay + coriolis * ux - bay + w1s * r1y
        e1_ = (ux * gy - uy * gx) * inv
        vcx, vcy = bvx - w1 * r1y, bvy + w1 * r1x
        acx, acy = bax - e1_ * r1y - w1s * r1x, bay + e1_ * r1x - w1s * r1y
        joint = (c, cx, cy, vcx, vcy, acx, acy)
        pins[(rod, *c)] = pins[(slider, *c)] = joint[1:]
        frames[rod] = Frame(b, bx, by, bvx, bvy, bax, bay, second=joint)
        frames[slider] = Frame(c, cx, cy, vcx, vcy, acx, acy, turns_with=fg)
    for link in step.links:
        for table in tables:
            table.declare(link)
    return True


_CHUNK_SPAN = 0.3  # input span (rad, or fraction of the sketch) of one batched Newton chunk
_CHUNK_MAX = 1024


def _sequential(
    step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray, k: int, start: dict
) -> dict[str, np.ndarray]:
    """Newton on pose ``k`` alone, from ``start`` (link -> (3,))."""
    one = {link: value[k : k + 1] for link, value in q.items()}
    for link in step.links:
        one[link] = start[link][None, :].copy()
    _newton(step, plan, one, inputs[k])
    return {link: one[link][0] for link in step.links}


def _follow(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray, start: dict) -> None:
    """Solve a Newton group for every pose, following the inputs in order.

    The first pose starts from ``start``; then chunks of poses start from a
    linear extrapolation of the last two solutions and run one batched Newton
    together. A chunk where any pose fails to converge, or lands farther from
    its prediction than the step between poses allows (another assembly mode),
    is redone pose by pose from the previous solution.
    """
    n = inputs.shape[0]
    links = step.links
    out = {link: np.zeros((n, 3)) for link in links}
    first = _sequential(step, plan, q, inputs, 0, start)
    for link in links:
        out[link][0] = first[link]
    k = 1
    tol = 1e-13 * plan.length
    scale = np.array([1.0 if d.kind == "R" else plan.length for d in plan.drivers])
    steps = np.max(np.abs(np.diff(inputs, axis=0)) / scale, axis=1) if n > 1 else np.zeros(1)
    typical = float(np.median(steps)) if len(steps) else 0.0
    size = int(np.clip(_CHUNK_SPAN / typical, 8, _CHUNK_MAX)) if typical > 0 else 8
    while k < n:
        stop = min(n, k + size)
        idx = np.arange(k, stop)
        last = {link: out[link][k - 1] for link in links}
        slope = (
            {link: out[link][k - 1] - out[link][k - 2] for link in links}
            if k >= 2
            else {link: np.zeros(3) for link in links}
        )
        step_in = np.linalg.norm(inputs[k - 1] - inputs[k - 2]) if k >= 2 else 0.0
        reach = np.linalg.norm(inputs[idx] - inputs[k - 1], axis=1)
        ratio = reach / step_in if step_in > 0 else np.zeros(len(idx))
        chunk = {name: value[idx] for name, value in q.items()}
        predicted = {link: last[link] + ratio[:, None] * slope[link] for link in links}
        for link in links:
            chunk[link] = predicted[link].copy()
        converged = False
        for _ in range(12):
            phi, jac, _, _ = _system(step, chunk, {}, len(idx))
            worst = float(np.max(np.abs(phi)))
            if worst <= tol:
                converged = True
                break
            try:
                dz = np.linalg.solve(_scaled(jac, plan.length), -phi[..., None])[..., 0]
            except np.linalg.LinAlgError:
                break
            dz[:, 2::3] /= plan.length
            for i, link in enumerate(links):
                chunk[link] = chunk[link] + dz[:, 3 * i : 3 * i + 3]
        jumps = max(float(np.max(np.abs(chunk[link] - predicted[link])[:, 2])) for link in links)
        if converged and jumps <= 0.2:
            for link in links:
                out[link][idx] = chunk[link]
        else:
            for j in idx:
                solved = _sequential(
                    step, plan, q, inputs, int(j), {link: out[link][j - 1] for link in links}
                )
                for link in links:
                    out[link][j] = solved[link]
        k = stop
    for link in links:
        q[link] = out[link]


_CONTINUATION_STEP = 0.05  # rad for a turning driver, fraction of the sketch for a sliding one


def _needs_continuation(plan: SolvePlan) -> bool:
    return any(step.group is None or step.group.kind is None for step in plan.steps)


def _densified(plan: SolvePlan, inputs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Inputs with intermediate rows from the sketch on, so Newton never jumps far."""
    scale = np.array([1.0 if d.kind == "R" else plan.length for d in plan.drivers])
    previous = np.vstack([np.zeros((1, inputs.shape[1])), inputs[:-1]])
    jump = np.max(np.abs(inputs - previous) / scale, axis=1) if len(scale) else np.zeros(0)
    pieces = np.maximum(1, np.ceil(jump / _CONTINUATION_STEP)).astype(int)
    picks = np.cumsum(pieces) - 1
    # row i's pieces: previous_i + (input_i − previous_i)·k/pieces_i, k = 1 … pieces_i
    owner = np.repeat(np.arange(len(inputs)), pieces)
    k = np.arange(len(owner)) - np.repeat(picks - pieces + 1, pieces) + 1
    fraction = (k / pieces[owner])[:, None]
    rows = previous[owner] + (inputs[owner] - previous[owner]) * fraction
    return rows, picks


def solve_poses(
    plan: SolvePlan,
    inputs: np.ndarray,
    guess: Mapping[str, np.ndarray] | None = None,
) -> Motion:
    """Positions, velocities and accelerations for every row of ``inputs`` (N, drivers).

    Rows are driver rotations (rad) or displacements (m) from the sketch.
    Groups solved by Newton follow the inputs from the sketch on, with
    intermediate poses where consecutive rows are far apart, so that they keep
    the sketch's assembly mode. ``guess`` holds link poses (3,) to start Newton
    from at the first row instead (no intermediate poses are added then).

    Raises
    ------
    AssemblyError
        A group does not close at some input (the first one is named).
    SingularPoseError
        A group is at a dead centre at some input.
    MechanismError
        Inputs away from the sketch for a mechanism with a cam (its replacement
        is instantaneous); gear meshes roll (``plan.rolling``).
    """
    inputs = np.atleast_2d(np.asarray(inputs, dtype=float))
    if inputs.shape[1] != len(plan.drivers):
        inputs = inputs.reshape(-1, len(plan.drivers))
    if plan.higher_pairs and np.any(inputs != 0):
        if plan.rolling is None:
            raise MechanismError(
                "the higher pair(s) "
                + ", ".join(plan.higher_pairs)
                + " are replaced by virtual links that hold at the sketch pose only; away "
                "from the sketch a cam needs its profile, which the format does not hold (a "
                "gear mesh needs z=za,zb and a carrier): solve at the sketch pose"
            )
        # gear meshes roll: their virtual links give way to the rolling constraints
        plan = dataclasses.replace(plan, steps=plan.rolling, higher_pairs=())
    if guess is None and _needs_continuation(plan):
        dense, picks = _densified(plan, inputs)
        if len(dense) > len(inputs):
            motion = _solve_poses(plan, dense, None)
            return Motion(
                inputs,
                MappingProxyType({k: v[picks] for k, v in motion.q.items()}),
                MappingProxyType({k: v[picks] for k, v in motion.qd.items()}),
                MappingProxyType({k: v[picks] for k, v in motion.qdd.items()}),
            )
    return _solve_poses(plan, inputs, guess)


def _solve_poses(
    plan: SolvePlan, inputs: np.ndarray, guess: Mapping[str, np.ndarray] | None
) -> Motion:
    n = inputs.shape[0]
    ground = plan.mechanism.ground
    frames: dict[str, Frame] = {}
    q, qd, qdd = tables = tuple(LinkTable(frames, order, n) for order in ("q", "qd", "qdd"))
    _place_drivers(plan, inputs, frames, tables)
    pins: dict = {}
    for step in plan.steps:
        if _dyad_frames(step, plan, frames, tables, pins, inputs):
            continue
        if not _closed_form(step, plan, q, inputs):
            start = {
                link: np.array(guess[link], dtype=float) if guess and link in guess else np.zeros(3)
                for link in step.links
            }
            _follow(step, plan, q, inputs, start)
        _, jac, known_v, _ = _system(step, q, qd, n)
        ratio = _conditioning(_scaled(jac, plan.length))
        if step.group is not None and (ratio <= _SINGULAR).any():
            k = int(np.argmax(ratio <= _SINGULAR))
            raise SingularPoseError(
                f"group {step.label} is at a dead centre at input {_fmt(inputs[k])}: its "
                f"Jacobian loses rank (σ_min/σ_max = {ratio[k]:.2g}; transmission angle "
                "0° or 180°)",
                step.label,
                tuple(inputs[k]),
            )
        solve = np.linalg.solve if jac.shape[1] == jac.shape[2] else _least_squares
        z_dot = solve(jac, -known_v[..., None])[..., 0]
        for i, link in enumerate(step.links):
            qd[link] = z_dot[:, 3 * i : 3 * i + 3]
        _, _, known_a, _ = _system(step, q, qdd, n)
        _, _, _, bias = _system(step, q, qd, n)
        z_ddot = solve(jac, (-known_a - bias)[..., None])[..., 0]
        for i, link in enumerate(step.links):
            qdd[link] = z_ddot[:, 3 * i : 3 * i + 3]
    zero = np.zeros((n, 3))
    for table in (q, qd, qdd):
        table.setdefault(ground, zero)
    return Motion(inputs, q, qd, qdd, MappingProxyType(frames))


def _conditioning(jac: np.ndarray) -> np.ndarray:
    """σ_min/σ_max of each pose's Jacobian (N, m, k).

    For square Jacobians ``1/(‖J‖_F·‖J⁻¹‖_F)`` is a lower bound of it, within a
    factor m: only the poses it flags get a singular value decomposition, which
    costs several times an inverse.
    """
    ratio = np.ones(jac.shape[0])
    suspect = np.ones(jac.shape[0], dtype=bool)
    if jac.shape[1] == jac.shape[2]:
        try:
            inv = np.linalg.inv(jac)
        except np.linalg.LinAlgError:  # some pose exactly singular
            inv = None
        if inv is not None:
            bound = 1.0 / (np.linalg.norm(jac, axis=(1, 2)) * np.linalg.norm(inv, axis=(1, 2)))
            suspect = ~(bound > _SINGULAR)  # NaN (an overflowed inverse) is suspect too
    if suspect.any():
        s = np.linalg.svd(jac[suspect], compute_uv=False)
        ratio[suspect] = s[:, -1] / s[:, 0]
    return ratio


def _least_squares(jac: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Batched least squares for the consistent, overdetermined rows of a redundant link."""
    return np.linalg.pinv(jac) @ rhs


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.flags.writeable = False
    return a


def solve_pose(
    plan: SolvePlan,
    inputs: tuple[float, ...] | None = None,
    guess: Mapping[str, np.ndarray] | None = None,
) -> KinematicState:
    """Positions, velocities and accelerations at one input (default: the sketch).

    Raises
    ------
    AssemblyError
        A group does not close at this input.
    SingularPoseError
        A group is at a dead centre.
    """
    inputs = tuple(0.0 for _ in plan.drivers) if inputs is None else tuple(inputs)
    motion = solve_poses(plan, np.array([inputs], dtype=float).reshape(1, -1), guess)
    m = plan.mechanism
    links = {
        link: LinkState(
            _frozen(motion.q[link][0]), _frozen(motion.qd[link][0]), _frozen(motion.qdd[link][0])
        )
        for link in m.moving_links
        if link in motion.q
    }
    points = {}
    for name, (link, c) in plan.points.items():
        if link not in motion.q:  # on a virtual link, which a rolling gear mesh does without
            continue
        x, v, a = motion.point(link, c)
        points[name] = PointState(link, _frozen(x[0]), _frozen(v[0]), _frozen(a[0]))
    return KinematicState(MappingProxyType(links), MappingProxyType(points), inputs)
