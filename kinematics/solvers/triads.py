"""Class III triads of revolute pairs, reduced to one unknown: the base link's angle.

A class III triad is a ternary base link whose three pins P₁, P₂, P₃ each
carry a binary lead, the lead's other pin E₁, E₂, E₃ on a known link. The
general Newton (:mod:`kinematics.solvers.newton`) solves its twelve equations; with
every pair a revolute one unknown is enough. Turned by φ, the base's pin P₁
lies on the circle of radius l₁ about E₁ and on the circle of radius l₂
about C₂ = E₂ − R(φ)·d₁₂ (d₁ⱼ = Pⱼ − P₁ on the sketch), so it is a
circle–circle intersection, on the sketch's side; φ is then a root of

    f(φ) = |P₁(φ) + R(φ)·d₁₃ − E₃|² − l₃²

(:func:`angle_residual`, with f′ from the intersection's derivative).

Over a sweep the root is followed from the sketch (φ = 0): first at coarse
poses along the path, one after another, each Newton starting from an
extrapolation of the coarse roots before it; then at every pose at once, a
vectorised Newton starting from the coarse roots interpolated along the path
(:func:`triad_angles`). The pins' velocities and accelerations follow from
one 3×3 system per pose, ``uᵢ·(v_Pᵢ − v_Eᵢ) = 0`` (uᵢ = Pᵢ − Eᵢ) and its
derivative, in closed form (:func:`pin_rates`). Each link's motion is kept as
a :class:`~kinematics.solvers.frames.Frame`.

Where this does not apply, :func:`frame_triad` returns None and the general
Newton solves the group as before: a group that is not an RRR triad, inputs
that start away from the sketch or take steps longer than the continuation
step, inputs that all are the sketch (which the general Newton keeps exactly,
where this solve would land within rounding of it), a pose where the circle
intersection meets its tangency for every pair of leads (where its side
changes), or where Newton does not settle near its prediction.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan, solve_poses
>>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "1 3 R B", "3 2 R C", "2 4 R D",
...                     "4 0 R F", "2 5 R E", "5 0 R G", "point A 0 0", "point B 0 0.1",
...                     "point C 0.1 0.4", "point D 0.4 0.45", "point E 0.3 0.6",
...                     "point F 0.5 0.1", "point G 0.1 0.9"])
>>> plan = make_plan(analyze(m))
>>> triad = triad_of(plan.steps[0])
>>> triad.base, [(lead.link, lead.known) for lead in triad.leads]
('2', [('3', '1'), ('4', '0'), ('5', '0')])
>>> sorted(solve_poses(plan, np.linspace(0.0, 0.5, 21)[:, None]).frames)  # solved as frames
['1', '2', '3', '4', '5']
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .dyads import PinCache, known_frame, known_pin
from .frames import Frame
from .newton import CONTINUATION_STEP
from .plan import GroupStep, SolvePlan

__all__ = [
    "COARSE_STEP",
    "SUSPECT",
    "Lead",
    "Triad",
    "angle_residual",
    "frame_triad",
    "path_length",
    "pin_rates",
    "triad_angles",
    "triad_of",
]

#: input span (rad, or fraction of the sketch) between the coarse poses followed one by one
COARSE_STEP = 0.1
_COARSE_JUMP = 0.05  # rad: a coarse root this far from its extrapolation may be another mode
_FINE_JUMP = 0.05  # rad: a root this far from its interpolation may be another mode
#: f′ may change by this fraction of its value at the root between Newton's start and the
#: root: then the start lies well inside the root's basin (Kantorovich: |f″|·|δ|/|f′| ≤ ½),
#: closer to it than to a neighbouring root, such as the other one near a dead centre
_BASIN = 0.25
_SETTLED = 1e-9  # rad: a Newton step this small leaves an error of ~1e-18, below rounding
_ITERATIONS = 8  # Newton steps per pose at most (two or three are the rule)
_TANGENCY = 1e-8  # h²·D²/l₁²: the circle intersection this close to its tangency is given up
_CLOSED = 1e-11  # the distance |P₃E₃| − l₃ accepted, × the sketch's size
#: the triad's conditioning measure (:func:`pin_rates`) below which a pose is screened by the
#: group's full Jacobian, × (1 + the pins' distance from the origin / the sketch's size)²: on
#: random triads near their singular pose, the measure stays below 110·(1 + that)² times the
#: Jacobian's σ_min/σ_max (whose θ columns grow with the distance), so a pose with
#: σ_min/σ_max at DEAD_CENTRE = 1e-6 has a measure below 1.1e-4·(1 + that)²: 90 times less
SUSPECT = 1e-2


@dataclass(frozen=True)
class Lead:
    """A lead: ``link``, its outer pin ``outer`` on ``known``, its inner pin ``inner`` on the base.

    ``outer`` and ``inner`` are sketch coordinates.
    """

    link: str
    known: str
    outer: np.ndarray
    inner: np.ndarray

    @property
    def length(self) -> float:
        """The distance between the lead's pins (m)."""
        return float(np.hypot(*(self.inner - self.outer)))


@dataclass(frozen=True)
class Triad:
    """An RRR class III triad: the ``base`` link and its three ``leads``."""

    base: str
    leads: tuple[Lead, Lead, Lead]

    @property
    def arms(self) -> tuple[np.ndarray, np.ndarray]:
        """d₁₂ and d₁₃: the base's second and third pins from its first, on the sketch."""
        first = self.leads[0].inner
        return self.leads[1].inner - first, self.leads[2].inner - first

    @cached_property
    def shape(self) -> tuple[float, ...]:
        """``(d₁₂x, d₁₂y, d₁₃x, d₁₃y, l₁, l₂, l₃)`` as floats, what the residual reads."""
        (d2x, d2y), (d3x, d3y) = self.arms
        return (float(d2x), float(d2y), float(d3x), float(d3y),
                *(lead.length for lead in self.leads))  # fmt: skip

    @property
    def side(self) -> float:
        """The side of the line E₁C₂ that P₁ takes on the sketch (+1 or −1; 0: on it)."""
        one, two = self.leads[0], self.leads[1]
        w = two.outer - self.arms[0] - one.outer
        u = one.inner - one.outer
        return float(np.sign(w[0] * u[1] - w[1] * u[0]))


def triad_of(step: GroupStep) -> Triad | None:
    """The step as an RRR class III triad, None if it is not one.

    The base is the link with three revolute pairs inside the group, to three
    distinct leads; each lead has one more revolute pair, to a known link.
    """
    group = step.group
    if group is None or step.unknowns or group.assur_class != 3 or len(step.links) != 4:
        return None
    if len(step.equations) != 6 or any(eq.kind != "HINGE" for eq in step.equations):
        return None
    links = set(step.links)
    inside = [eq for eq in step.equations if eq.a in links and eq.b in links]
    outside = [eq for eq in step.equations if (eq.a in links) != (eq.b in links)]
    if len(inside) != 3 or len(outside) != 3:
        return None
    counts = {link: sum(link in (eq.a, eq.b) for eq in inside) for link in links}
    bases = [link for link, k in counts.items() if k == 3]
    if len(bases) != 1:
        return None
    base = bases[0]
    leads = []
    for eq in inside:
        lead = eq.b if eq.a == base else eq.a
        (out,) = [e for e in outside if lead in (e.a, e.b)] or [None]
        if out is None or counts[lead] != 1:
            return None
        known = out.b if out.a == lead else out.a
        leads.append(Lead(lead, known, np.asarray(out.point, float), np.asarray(eq.point, float)))
    if len({lead.link for lead in leads}) != 3 or min(x.length for x in leads) <= 0.0:
        return None
    return Triad(base, (leads[0], leads[1], leads[2]))


def _rotations(triad: Triad, outer: list) -> list[tuple[Triad, list]]:
    """The triad with its leads taken in each cyclic order, the outer pins' motions alike.

    Each order intersects the circles of another pair of leads; the orders
    whose first two pins coincide on the base, or whose P₁ lies on the line
    E₁C₂ on the sketch, are left out.
    """
    out = []
    for k in range(3):
        turned = Triad(triad.base, triad.leads[k:] + triad.leads[:k])  # type: ignore[arg-type]
        if float(np.hypot(*turned.arms[0])) > 0.0 and turned.side != 0.0:
            out.append((turned, outer[k:] + outer[:k]))
    return out


# ---------------------------------------------------------------- the residual in φ


def angle_residual(triad: Triad, known: tuple, c, s, side: float) -> tuple:
    """f(φ), f′(φ), the pin P₁, its rate dP₁/dφ and how far off the tangency, at ``cos φ = c``.

    ``s`` is sin φ; ``known`` holds the outer pins ``(e1x, e1y, e2x, e2y,
    e3x, e3y)``, floats or (N,) arrays alike (so that one pose and many share
    this code). P₁ is ``E₁ + a·w + h·J·w`` with ``w = C₂ − E₁``, on the
    ``side`` of w. Returns ``(f, f′, p1x, p1y, dp1x, dp1y, gap)``, ``gap`` =
    h²·|w|²/l₁², the squared sine of the angle between E₁P₁ and w: zero where
    the two circles touch.
    """
    e1x, e1y, e2x, e2y, e3x, e3y = known
    d2x, d2y, d3x, d3y, l1, l2, l3 = triad.shape
    r2x, r2y = c * d2x - s * d2y, s * d2x + c * d2y
    r3x, r3y = c * d3x - s * d3y, s * d3x + c * d3y
    wx, wy = e2x - r2x - e1x, e2y - r2y - e1y
    ww = wx * wx + wy * wy
    a = 0.5 + (0.5 * (l1 * l1 - l2 * l2)) / ww
    h2 = (l1 * l1) / ww - a * a
    h = side * abs(h2) ** 0.5
    u1x, u1y = a * wx - h * wy, a * wy + h * wx  # P₁ − E₁
    del a  # (each value let go once used: over many poses, fewer arrays live at once)
    # dP₁/dφ = k·J·u₁ keeps |P₁E₁| and moves P₁ with C₂ (dC₂/dφ = −J·R·d₁₂):
    # k = (u₂·dC₂/dφ)/(u₁ × u₂) with u₂ = P₁ − C₂ = u₁ − w, and u₁ × u₂ = h·|w|²
    k = ((u1x - wx) * r2y - (u1y - wy) * r2x) / (h * ww)
    del r2x, r2y, wx, wy, h
    dp1x, dp1y = -k * u1y, k * u1x
    del k
    p1x, p1y = e1x + u1x, e1y + u1y
    del u1x, u1y
    gx, gy = p1x + r3x - e3x, p1y + r3y - e3y
    f = gx * gx + gy * gy - l3 * l3
    df = 2.0 * (gx * (dp1x - r3y) + gy * (dp1y + r3x))
    del gx, gy, r3x, r3y
    return f, df, p1x, p1y, dp1x, dp1y, h2 * ww / (l1 * l1)


def _coarse_newton(triad: Triad, known: tuple, phi: float, side: float) -> tuple | None:
    """Newton on one pose from ``phi`` (floats); None if it does not settle off the tangency.

    Returns the root and how much f′ changed on the way from ``phi``, relative
    to f′ at the root (see :data:`_BASIN`).
    """
    first = None
    for _ in range(_ITERATIONS):
        try:
            f, df, *_, gap = angle_residual(triad, known, math.cos(phi), math.sin(phi), side)
        except ZeroDivisionError:  # on the tangency, or E₁ on C₂
            return None
        if df == 0.0:
            return None
        first = df if first is None else first
        step = -f / df
        phi += step
        if abs(step) <= _SETTLED:
            return (phi, abs(df - first) / abs(df)) if gap > _TANGENCY else None
    return None


def path_length(plan: SolvePlan, inputs: np.ndarray) -> np.ndarray | None:
    """Distance along the inputs from the sketch to each row, in units of scale.

    None when the path starts away from the sketch or takes a step longer than
    the continuation step (the poses in between would not be followed).
    """
    scaled = inputs / plan.driver_scale
    steps = np.empty(len(inputs))
    steps[0] = np.sqrt(np.sum(scaled[0] ** 2))
    steps[1:] = np.sqrt(np.sum(np.diff(scaled, axis=0) ** 2, axis=1))
    if float(np.max(steps)) > CONTINUATION_STEP * math.sqrt(inputs.shape[1]) * (1 + 1e-9):
        return None
    return np.cumsum(steps)


def _coarse_roots(
    triad: Triad, known: tuple, distance: np.ndarray
) -> tuple[np.ndarray, np.ndarray] | None:
    """φ at coarse poses along the path, followed one by one from the sketch.

    Each coarse pose lies at most a stride further along the path than the
    last; Newton there starts from an extrapolation of the roots before it
    and must settle within :data:`_COARSE_JUMP` of it, inside the root's basin
    (:data:`_BASIN`). The stride starts at
    :data:`COARSE_STEP` / 8, is halved where Newton lands too far (or does
    not settle), doubled up to :data:`COARSE_STEP` where it lands close: a
    step-size control, so that the coarse poses are dense where the triad
    moves fast. Returns the coarse poses' distances along the path and their
    roots (the sketch first, at distance 0 and φ = 0), None where even the
    step to the next pose fails.
    """
    at, roots = [0.0], [0.0]
    last, stride, side = -1, COARSE_STEP / 8, triad.side
    while last < len(distance) - 1:
        j = max(last + 1, int(np.searchsorted(distance, at[-1] + stride, "right")) - 1)
        here = float(distance[j])
        if here == at[-1]:  # the same place on the path (a repeated input): the same root
            last = j
            continue
        pose = tuple(float(x[j]) if isinstance(x, np.ndarray) else x for x in known)
        guess = _extrapolated(at, roots, here)
        found = _coarse_newton(triad, pose, guess, side)
        phi, bend = found if found is not None else (guess, math.inf)
        if bend > _BASIN or abs(phi - guess) > _COARSE_JUMP:
            if j == last + 1:
                return None
            stride /= 2
            continue
        if bend < _BASIN / 4 and abs(phi - guess) < _COARSE_JUMP / 8:
            stride = min(2 * stride, COARSE_STEP)
        at.append(here)
        roots.append(phi)
        last = j
    return np.array(at), np.array(roots)


def _extrapolated(at: list[float], roots: list[float], x: float) -> float:
    """The root at ``x``: a parabola through the last three roots (a line, the last one)."""
    x0, y0 = at[-1], roots[-1]
    if len(at) == 1:
        return y0
    x1, y1 = at[-2], roots[-2]
    if len(at) == 2:
        return y0 + (y0 - y1) * (x - x0) / (x0 - x1)
    x2, y2 = at[-3], roots[-3]
    return (
        y0 * (x - x1) * (x - x2) / ((x0 - x1) * (x0 - x2))
        + y1 * (x - x0) * (x - x2) / ((x1 - x0) * (x1 - x2))
        + y2 * (x - x0) * (x - x1) / ((x2 - x0) * (x2 - x1))
    )


def _interpolated(at: np.ndarray, roots: np.ndarray, distance: np.ndarray) -> np.ndarray:
    """The coarse roots interpolated at ``distance``: a cubic through four nodes per interval.

    On the interval from node k to node k + 1, the cubic through nodes k − 1 …
    k + 2 (the first or last four at the ends), from its divided differences
    expanded about node k; with fewer than four nodes, a line.
    """
    m = len(at)
    if m < 4:
        return np.interp(distance, at, roots)
    k = np.arange(m - 1)
    low = np.clip(k - 1, 0, m - 4)
    xs = [at[low + i] - at[k] for i in range(4)]  # the four nodes, about node k
    ys = [roots[low + i] for i in range(4)]
    for order in range(1, 4):  # divided differences, in place: ys[i] = f[x_0 … x_i]
        for i in range(3, order - 1, -1):
            ys[i] = (ys[i] - ys[i - 1]) / (xs[i] - xs[i - order])
    coefficients = [ys[3]]
    for i in (2, 1, 0):  # p ← p·(t − x_i) + f[x_0 … x_i], coefficients of 1, t, t², …
        shifted = [np.zeros(m - 1), *coefficients]
        coefficients = [a - xs[i] * b for a, b in zip(shifted, [*coefficients, 0.0], strict=True)]
        coefficients[0] = coefficients[0] + ys[i]
    seg = np.clip(np.searchsorted(at, distance, side="right") - 1, 0, m - 2)
    t = distance - at[seg]
    c0, c1, c2, c3 = (c[seg] for c in coefficients)
    return ((c3 * t + c2) * t + c1) * t + c0


def _turned(c: np.ndarray, s: np.ndarray, phi: np.ndarray, step: np.ndarray) -> tuple:
    """cos φ and sin φ after the rotation by ``step`` (φ the new angle).

    For steps below 0.01 rad the rotation by ``step`` is applied with cos and
    sin of ``step`` by their series to the δ⁶ and δ⁷ terms (the next ones are
    below 3e-21): cheaper than two trigonometric functions, as exact.
    """
    if not np.all(np.abs(step) <= 1e-2):
        return np.cos(phi), np.sin(phi)
    d2 = step * step
    cos = 1.0 - d2 * (0.5 - d2 * (1.0 / 24.0 - d2 / 720.0))
    sin = step * (1.0 - d2 * (1.0 / 6.0 - d2 * (1.0 / 120.0 - d2 / 5040.0)))
    return c * cos - s * sin, s * cos + c * sin


def triad_angles(triad: Triad, known: tuple, distance: np.ndarray) -> tuple | None:
    """The base's angle at every pose, its cosine and sine, and the pin P₁; None to give up.

    ``distance`` is :func:`path_length`'s. The coarse roots, interpolated
    along the path, start one Newton over all the poses, which must settle at
    every pose within :data:`_FINE_JUMP` of the interpolation, off the
    tangency, with P₃ at its lead's length from E₃. The last Newton step
    (below 1e-9 rad) moves the rotation and P₁ to first order: what that
    leaves out is below rounding. Returns ``(φ, cos φ, sin φ, p1x, p1y)``.
    """
    coarse = _coarse_roots(triad, known, distance)
    if coarse is None:
        return None
    start = _interpolated(*coarse, distance)
    phi, first = start, None
    c, s = np.cos(phi), np.sin(phi)
    for _ in range(_ITERATIONS):
        f = df = p1x = p1y = dp1x = dp1y = gap = None  # the last pass's, let go before the next
        with np.errstate(divide="ignore", invalid="ignore"):
            f, df, p1x, p1y, dp1x, dp1y, gap = angle_residual(triad, known, c, s, triad.side)
            step = -f / df
        first = df if first is None else first
        phi = phi + step
        if np.all(np.abs(step) <= _SETTLED):
            break
        c, s = _turned(c, s, phi, step)
    else:
        return None
    if not (np.all(gap > _TANGENCY) and np.all(np.abs(df - first) <= _BASIN * np.abs(df))):
        return None
    c, s = c - s * step, s + c * step
    p1x, p1y = p1x + dp1x * step, p1y + dp1y * step
    d3x, d3y = triad.arms[1]
    gx, gy = p1x + (c * d3x - s * d3y) - known[4], p1y + (s * d3x + c * d3y) - known[5]
    miss = np.abs(np.sqrt(gx * gx + gy * gy) - triad.leads[2].length)
    size = max(lead.length for lead in triad.leads)
    if not (np.all(np.abs(phi - start) <= _FINE_JUMP) and np.all(miss <= _CLOSED * size)):
        return None
    return phi, c, s, p1x, p1y


# ---------------------------------------------------------------- rates and frames


def pin_rates(
    triad: Triad,
    rotated: tuple,
    offsets: tuple,
    outer: tuple,
    length: float,
    out: tuple = (None, None, None),
) -> tuple:
    """The base's ω, ε and its pins' velocities and accelerations, at every pose.

    ``rotated`` is ``(R·d₁₂, R·d₁₃)``, ``offsets`` the three uᵢ = Pᵢ − Eᵢ,
    ``outer`` each outer pin's ``(x, y, vx, vy, ax, ay)``. The unknowns
    ``(v_P₁, ω)`` solve the rows ``uᵢ·(v_P₁ + ω·J·R·d₁ᵢ) = uᵢ·v_Eᵢ`` (each lead
    keeps its length); ``(a_P₁, ε)`` the same rows, right-hand sides
    ``uᵢ·a_Eᵢ + ω²·uᵢ·R·d₁ᵢ − |v_Pᵢ − v_Eᵢ|²``: Cramer's rule, the adjugate
    shared. P₂ and P₃ then move as points of the base with P₁ (the
    arithmetic of the base's :class:`~kinematics.solvers.frames.Frame`). Each pin's
    ``(vx, vy, ax, ay)`` is written into its entry of ``out`` (four arrays;
    fresh ones where it is None). Returns ``(ω, ε, velocities,
    accelerations, measure)``, the pins' rates as ``(x, y)`` pairs and
    ``measure`` = |det| over the product of the rows' norms (θ column ×
    1/``length``): zero where the leads' lines meet in one point, the triad's
    singular pose. In-place operations on a few arrays: at 10^4 poses and
    more, fresh temporaries cost more (in page faults) than the arithmetic.
    """
    (u1x, u1y), (u2x, u2y), (u3x, u3y) = offsets
    scratch = np.empty(np.shape(u1x))
    t2 = _difference(rotated[0][0], u2y, rotated[0][1], u2x, scratch)  # uᵢ·(J·R·d₁ᵢ)
    t3 = _difference(rotated[1][0], u3y, rotated[1][1], u3x, scratch)
    adj = _adjugate(offsets, t2, t3, scratch)
    det = u1x * adj[0][0]
    det += np.multiply(u1y, adj[1][0], out=scratch)
    inverse = np.divide(1.0, det)
    measure = _measure(triad, det, t2, t3, length, scratch)
    del det, t2, t3
    # every pin's four arrays (fresh where ``out`` has none), the accelerations' ones
    # holding the right-hand sides until the accelerations are written
    (v1x, v1y, a1x, a1y), (v2x, v2y, a2x, a2y), (v3x, v3y, a3x, a3y) = (
        pin if pin is not None else tuple(np.empty(scratch.shape) for _ in range(4)) for pin in out
    )
    rhs = [
        _dot(u, e[2], e[3], scratch, spare)
        for u, e, spare in zip(offsets, outer, (a1x, a1y, a2x), strict=True)
    ]
    _, _, omega = _solved(adj, rhs, inverse, scratch, (v1x, v1y))
    velocities = _on_base(omega, rotated, ((v1x, v1y), (v2x, v2y), (v3x, v3y)), scratch)
    w2 = omega * omega
    arms = ((0.0, 0.0), *rotated)
    rhs = [
        _acceleration_rhs(u, e, v, arm, w2, scratch, (spare, a3y))
        for u, e, v, arm, spare in zip(offsets, outer, velocities, arms, (a2x, a2y, a3x),
                                       strict=True)
    ]  # fmt: skip
    _, _, epsilon = _solved(adj, rhs, inverse, scratch, (a1x, a1y))
    del adj, rhs, inverse
    accelerations = _accelerated(epsilon, w2, rotated, ((a1x, a1y), (a2x, a2y), (a3x, a3y)),
                                 scratch)  # fmt: skip
    return omega, epsilon, velocities, accelerations, measure


def _measure(triad: Triad, det, t2, t3, length: float, scratch: np.ndarray) -> np.ndarray:
    """|det| over the product of the rows' norms; ``det``, ``t2`` and ``t3`` overwritten."""
    l1, l2, l3 = (lead.length for lead in triad.leads)
    k = 1.0 / (length * length)
    for t, lead_length in ((t2, l2), (t3, l3)):  # lᵢ² + k·tᵢ², in place
        np.multiply(k, t, out=scratch)
        np.multiply(scratch, t, out=t)
        t += lead_length * lead_length
    norms = np.multiply(t2, t3, out=t2)
    np.sqrt(norms, out=norms)
    np.multiply(l1, norms, out=norms)
    np.multiply(length, norms, out=norms)
    measure = np.abs(det, out=det)
    measure /= norms
    return measure


def _difference(a, b, c, d, scratch: np.ndarray) -> np.ndarray:
    """``a·b − c·d`` in a fresh array, ``scratch`` overwritten."""
    out = np.multiply(a, b)
    out -= np.multiply(c, d, out=scratch)
    return out


def _adjugate(offsets: tuple, t2: np.ndarray, t3: np.ndarray, scratch: np.ndarray) -> tuple:
    """The adjugate of the rows ``(uᵢx, uᵢy, tᵢ)`` (t₁ = 0), by rows of the inverse."""
    (u1x, u1y), (u2x, u2y), (u3x, u3y) = offsets
    minus_u1y_t3 = np.multiply(u1y, t3)
    np.negative(minus_u1y_t3, out=minus_u1y_t3)  # (−u₁y)·t₃, as exact
    minus_u1x_t2 = np.multiply(u1x, t2)
    np.negative(minus_u1x_t2, out=minus_u1x_t2)
    return (
        (_difference(u2y, t3, t2, u3y, scratch), minus_u1y_t3, u1y * t2),
        (_difference(t2, u3x, u2x, t3, scratch), u1x * t3, minus_u1x_t2),
        (
            _difference(u2x, u3y, u2y, u3x, scratch),
            _difference(u1y, u3x, u1x, u3y, scratch),
            _difference(u1x, u2y, u1y, u2x, scratch),
        ),
    )


def _dot(u: tuple, x, y, scratch: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """``u·(x, y)``, in ``out`` (a fresh array if None)."""
    out = np.multiply(u[0], x, out=out)
    out += np.multiply(u[1], y, out=scratch)
    return out


def _solved(adj: tuple, rhs: list, inverse: np.ndarray, scratch: np.ndarray, out: tuple) -> list:
    """The unknowns for the right-hand sides ``rhs``: the first two in ``out``, the third fresh."""
    solution = []
    for row, target in zip(adj, (*out, None), strict=True):
        value = np.multiply(row[0], rhs[0], out=target)
        value += np.multiply(row[1], rhs[1], out=scratch)
        value += np.multiply(row[2], rhs[2], out=scratch)
        value *= inverse
        solution.append(value)
    return solution


def _on_base(omega, rotated: tuple, pins: tuple, scratch: np.ndarray) -> tuple:
    """The pins' velocities, in ``pins``: P₁'s (solved, there) + ω·J·0, P₂'s and P₃'s from it."""
    x, y = pins[0]
    np.subtract(x, np.multiply(omega, 0.0, out=scratch), out=x)
    np.add(y, np.multiply(omega, 0.0, out=scratch), out=y)
    for (rx, ry), (px, py) in zip(rotated, pins[1:], strict=True):
        np.subtract(x, np.multiply(omega, ry, out=scratch), out=px)
        np.add(y, np.multiply(omega, rx, out=scratch), out=py)
    return pins


def _accelerated(epsilon, w2, rotated: tuple, pins: tuple, scratch: np.ndarray) -> tuple:
    """The pins' accelerations, in ``pins``: P₁'s (solved, there), P₂'s and P₃'s from it."""
    x, y = pins[0]
    np.subtract(x, np.multiply(epsilon, 0.0, out=scratch), out=x)
    x -= np.multiply(w2, 0.0, out=scratch)
    np.add(y, np.multiply(epsilon, 0.0, out=scratch), out=y)
    y -= np.multiply(w2, 0.0, out=scratch)
    for (rx, ry), (px, py) in zip(rotated, pins[1:], strict=True):
        np.subtract(x, np.multiply(w2, rx, out=scratch), out=px)
        px -= np.multiply(epsilon, ry, out=scratch)
        np.subtract(y, np.multiply(w2, ry, out=scratch), out=py)
        py += np.multiply(epsilon, rx, out=scratch)
    return pins


def _acceleration_rhs(
    u: tuple, e: tuple, v: tuple, arm: tuple, w2, scratch: np.ndarray, out: tuple
) -> np.ndarray:
    """``u·a_E + ω²·u·R·d − |v_P − v_E|²`` of one lead, in ``out[0]`` (``out[1]`` overwritten)."""
    value = _dot(u, e[4], e[5], scratch, out[0])
    along = _dot(u, arm[0], arm[1], scratch, out[1])
    along *= w2
    value += along
    for k in (0, 1):
        gap = np.subtract(v[k], e[2 + k], out=along)
        gap *= gap
        value -= gap
    return value


def _in_some_order(triad: Triad, outer: list, distance: np.ndarray) -> tuple | None:
    """:func:`triad_angles` with the leads in the first cyclic order that solves every pose.

    Returns that order's triad, its outer pins' motions and the solution; None
    if no order does (each pair of leads meets its tangency somewhere).
    """
    for turned, moved in _rotations(triad, outer):
        solved = triad_angles(turned, tuple(value for pin in moved for value in pin[:2]), distance)
        if solved is not None:
            return turned, moved, solved
    return None


def _reach(triad: Triad) -> float:
    """How far the triad's pins lie from the origin on the sketch (which the θ columns weigh)."""
    return max(float(np.hypot(*p)) for lead in triad.leads for p in (lead.inner, lead.outer))


def _outer_position(frames: dict[str, Frame], tables: tuple, pins: dict, lead: Lead) -> tuple:
    """``(x, y)`` of a lead's outer pin: the solve's, or from its known link's frame."""
    found = pins.get((lead.known, float(lead.outer[0]), float(lead.outer[1])))
    if found is not None:
        return found[:2]
    return known_frame(frames, tables, lead.known).position(lead.outer)


def _outer_pin(
    frames: dict[str, Frame], tables: tuple, pins: dict, lead: Lead, rates: bool, inputs
) -> tuple:
    """``(x, y, vx, vy, ax, ay)`` of a lead's outer pin (:func:`~.dyads.known_pin`).

    Written into its row of a sweep's layout when the layout names it under
    the known link or the lead; without ``rates`` only ``(x, y)``.
    """
    found = known_pin(frames, tables, pins, lead.known, lead.outer, rates, inputs, (lead.link,))
    return found if rates else found[:2]


def _base_rows(pins: dict, triad: Triad, inputs: np.ndarray, rates: bool) -> tuple:
    """Each base pin's row of a sweep's layout (under the base or its lead), or None."""
    if not isinstance(pins, PinCache):
        return (None, None, None)
    keys = (
        ((triad.base, float(x), float(y)), (lead.link, float(x), float(y)))
        for lead in triad.leads
        for x, y in (lead.inner,)
    )
    return tuple(pins.targets(pair, inputs, rates) for pair in keys)


def _placed(p1: tuple, arm: tuple | None, row: tuple | None) -> tuple:
    """A base pin's position: P₁ (``arm`` None) or P₁ + R·d₁ᵢ, written into ``row`` if given."""
    if arm is None:
        if row is None:
            return p1
        row[0][...] = p1[0]
        row[1][...] = p1[1]
        return row[0], row[1]
    return (np.add(p1[0], arm[0], out=None if row is None else row[0]),
            np.add(p1[1], arm[1], out=None if row is None else row[1]))  # fmt: skip


def frame_triad(
    step: GroupStep,
    plan: SolvePlan,
    frames: dict[str, Frame],
    tables: tuple,
    pins: dict,
    inputs: np.ndarray,
    rates: bool = True,
) -> np.ndarray | None:
    """Solve an RRR class III triad for every pose through its base's angle, as frames.

    None when it does not apply (see the module's notes): the general Newton
    solves the group then. Otherwise each link's motion is added to
    ``frames`` and declared in the ``(q, qd, qdd)`` ``tables``, the motions of
    the pins on known links kept in ``pins``, and the poses
    whose conditioning measure (:func:`pin_rates`) is below :data:`SUSPECT`
    are returned (a boolean mask; none without ``rates``), for the caller to
    screen with the group's full Jacobian.
    """
    triad = triad_of(step)
    distance = path_length(plan, inputs) if triad is not None else None
    if triad is None or distance is None or distance[-1] == 0.0:
        return None  # (every pose the sketch: the sketch is the answer, which Newton keeps exactly)
    where = [_outer_position(frames, tables, pins, lead) for lead in triad.leads]
    found = _in_some_order(triad, where, distance)
    del where, distance
    if found is None:
        return None
    triad, (phi, c, s, p1x, p1y) = found[0], found[2]
    del found  # (and with it the outer pins' positions the solve used)
    outer = [_outer_pin(frames, tables, pins, lead, rates, inputs) for lead in triad.leads]
    rows = _base_rows(pins, triad, inputs, rates)
    rotated = tuple((c * dx - s * dy, s * dx + c * dy) for dx, dy in triad.arms)
    p1 = _placed((p1x, p1y), None, rows[0])
    del p1x, p1y
    pins = (p1, *(_placed(p1, arm, row) for arm, row in zip(rotated, rows[1:], strict=True)))
    suspect = np.zeros(len(inputs), dtype=bool)
    omega = epsilon = None
    velocities = accelerations = ((None, None),) * 3
    if rates:
        offsets = tuple((p[0] - e[0], p[1] - e[1]) for p, e in zip(pins, outer, strict=True))
        targets = tuple(None if row is None else row[2:] for row in rows)
        omega, epsilon, velocities, accelerations, measure = pin_rates(
            triad, rotated, offsets, tuple(outer), plan.length, targets
        )
        del offsets, rotated
        suspect = ~(measure > SUSPECT * (1.0 + _reach(triad) / plan.length) ** 2)
    frames[triad.base] = Frame(
        triad.leads[0].inner, *pins[0], *velocities[0], *accelerations[0],
        c, s, omega, epsilon, phi,
    )  # fmt: skip
    for lead, pin, e, v, a in zip(triad.leads, pins, outer, velocities, accelerations, strict=True):
        ends = e if rates else (*e, None, None, None, None)
        frames[lead.link] = Frame(lead.outer, *ends, second=(lead.inner, *pin, *v, *a))
    for link in step.links:
        for table in tables:
            table.declare(link)
    return suspect
