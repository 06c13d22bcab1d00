"""Kinetostatics: joint reactions and the balancing moment, from the farthest group back.

With the motion known at a pose, every moving link is in equilibrium under
its loads, its d'Alembert inertia loads (−m·a_S, −J_S·ε) and the reactions of
its pairs. Writing the reactions as the multipliers λ of the pair equations,
``Jᵀ·λ = −Q``; ``Jᵀ`` is block triangular in the group order, so the groups
are solved from the last one back, exactly as the textbook detaches them, and
the drivers last, from their own equilibrium, which gives the balancing
moment (or the balancing force of a ``balance`` statement).

Sign conventions: a reaction is reported as the force that ``links[0]``
exerts on ``links[1]`` (N, world frame); a prismatic pair also carries the
couple that ``links[0]`` exerts on ``links[1]`` (N·m). The balancing moment is
the moment the motor applies to the driver, counter-clockwise positive; for a
sliding driver it is the force the motor applies along the slide (N, positive
along the driver's direction), also given as ``balancing_slide_force``.

Every solution comes with the virtual-power check: the power of every load,
inertia load and the balancing moment must add up to zero; its residual is
reported relative to the largest term.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0", "point B 0.1 0",
...                     "force 1 B 0 -100"])
>>> r = solve_forces(make_plan(analyze(m)))
>>> round(r.balancing_moment["1"], 9), r.power_residual < 1e-12
(10.0, True)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from structure.errors import MechanismError
from structure.model import Load, Mechanism, PairKind

from ..cams.contact import cam_pose, cam_reactions
from ..errors import IndeterminateError
from ..results.state import Motion
from ..solvers.equations import Equation, equation_point, evaluate, slide_equations
from ..solvers.plan import DriverStep, GroupStep, SolvePlan
from ..solvers.planar import cross, norm, perpendicular, rotate_many, unit, unit_from_degrees
from ..solvers.solve import solve_poses

# IndeterminateError is defined in kinematics.errors; it stays importable from here
__all__ = [
    "ForceSolution",
    "ForceSweep",
    "IndeterminateError",
    "Reaction",
    "forces_over",
    "ground_equations",
    "solve_forces",
]


@dataclass(frozen=True)
class Reaction:
    """The force (and for a prismatic pair the couple) ``links[0]`` exerts on ``links[1]``.

    At a pin the force acts at the pin. At a slide it acts through the pair's
    point as fixed to ``links[1]``, with ``couple`` besides (away from the
    sketch the point of that name on ``links[0]`` has moved along the guide).
    """

    point: str | None
    links: tuple[str, str]
    kind: str  # 'R' or 'P'
    force: np.ndarray
    couple: float = 0.0
    contacts: tuple[np.ndarray, np.ndarray] | None = None

    @property
    def magnitude(self) -> float:
        return float(norm(self.force))


@dataclass(frozen=True)
class ForceSolution:
    """Reactions in the order solved, the balancing moment(s) or force, the power check, the pose.

    Attributes
    ----------
    reactions : tuple of Reaction
        In the order solved, from the farthest group to the drivers.
    balancing_moment : Mapping[str, float]
        For each driver without a ``balance`` statement, what the motor applies
        to it: for a rotating driver the moment (N·m, counter-clockwise
        positive); for a sliding driver, under the same key for the callers
        that read it, the force along its slide (N, positive along the
        driver's direction), which :attr:`balancing_slide_force` also holds.
    balancing_force : numpy.ndarray or None
        The balancing force of a ``balance`` statement (N, world frame).
    power_residual : float
        The virtual-power check: the sum of the powers relative to the largest.
    order : tuple of str
        The labels of the steps, in the order solved.
    friction_loss : float or None
        The power friction dissipates (W), when a pair has friction.
    pin_forces : Mapping[str, Mapping[str, numpy.ndarray]]
        At each compound hinge, the force its pin exerts on each of its links.
    inputs : tuple of float
        The driver inputs the solution is at (rad or m from the sketch, in the
        order of the plan's drivers); ``()``, the default, stands for the
        sketch (all zeros).
    balancing_slide_force : Mapping[str, float]
        For each sliding driver, the balancing force along its slide (N,
        positive along the driver's direction).
    """

    reactions: tuple[Reaction, ...]
    balancing_moment: Mapping[str, float]
    balancing_force: np.ndarray | None
    power_residual: float
    order: tuple[str, ...]
    friction_loss: float | None = None
    pin_forces: Mapping[str, Mapping[str, np.ndarray]] = field(default_factory=dict)
    inputs: tuple[float, ...] = ()
    balancing_slide_force: Mapping[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class ForceSweep:
    """Reactions and balancing over many poses: arrays with a leading pose axis.

    As in :class:`ForceSolution`, ``balancing_moment`` holds for a sliding
    driver the balancing force along its slide (N), not a moment.
    """

    inputs: np.ndarray
    reactions: tuple[tuple[str | None, tuple[str, str], str, np.ndarray, np.ndarray], ...]
    balancing_moment: Mapping[str, np.ndarray]
    balancing_force: np.ndarray | None
    power_residual: np.ndarray
    order: tuple[str, ...]
    friction_loss: np.ndarray | None = None


def _applied(plan: SolvePlan, where: _Where) -> dict[str, np.ndarray]:
    """Generalized applied and inertia loads (Fx, Fy, moment about the frame origin), (N, 3)."""
    m = plan.mechanism
    motion = where.motion
    n = motion.inputs.shape[0]
    out: dict[str, np.ndarray] = {}
    gravity = np.zeros(2)
    for load in m.loads:
        if load.kind == "gravity":
            gravity = np.array(load.values)
    for load in m.loads:
        if load.kind not in ("force", "moment", "mass"):
            continue
        link = load.link
        if link not in out:
            out[link] = _load_columns(n)
        total = out[link]
        if load.kind == "moment":
            total[:, 2] += load.values[0]
            continue
        c = _load_point(m, load)
        ox, oy = where.position(link, _ORIGIN)
        if load.kind == "force":
            sx, sy = where.position(link, c)
            fx, fy = float(load.values[0]), float(load.values[1])
            total[:, 0] += fx
            total[:, 1] += fy
            total[:, 2] += (sx - ox) * fy - (sy - oy) * fx
            continue
        mass, inertia = load.values
        sx, sy, ax, ay, epsilon = _point_acceleration(motion, m.ground, link, c)
        fx = mass * (gravity[0] - ax)
        fy = mass * (gravity[1] - ay)
        total[:, 0] += fx
        total[:, 1] += fy
        total[:, 2] += (sx - ox) * fy - (sy - oy) * fx - inertia * epsilon
    return out


def _load_point(m: Mechanism, load: Load) -> np.ndarray:
    """The sketch coordinates of a load's point."""
    if load.point is None or m.coordinates(load.point) is None:
        raise MechanismError(f"point {load.point} of a load on link {load.link} needs coordinates")
    return np.array(m.coordinates(load.point), dtype=float)


def _point_acceleration(motion: Motion, ground: str, link: str, c: np.ndarray) -> tuple:
    """``(x, y, ax, ay, ε)`` of sketch point ``c`` on ``link`` and the link's ε."""
    frame = motion.frames.get(link)
    if frame is not None:
        found = motion.pins.get((link, float(c[0]), float(c[1])))
        x, y, _, _, ax, ay = found if found is not None else frame.point(c)
        return x, y, ax, ay, frame.epsilon
    x, _, a = motion.point(link, c)
    return x[:, 0], x[:, 1], a[:, 0], a[:, 1], motion.qdd[link][:, 2]


def _parts(eq: Equation, motion: Motion) -> tuple[np.ndarray, np.ndarray]:
    n = motion.inputs.shape[0]
    zero = np.zeros((n, 3))
    _, ja, jb, _ = evaluate(eq, motion.q.get(eq.a, zero), motion.q.get(eq.b, zero), zero, zero)
    return ja, jb


def _reactions(parts, lam: np.ndarray, m) -> list:
    """Reactions from the multipliers: what eq.a exerts on eq.b is ∂Φ/∂q_bᵀ·λ.

    A prismatic pair's ANGLE row (a couple) is reported with its SLIDE row.
    """
    out = []
    n = lam.shape[0]
    couple = np.zeros(n)
    for eq, _, jb, r0 in parts:
        value = lam[:, r0 : r0 + eq.size]
        on_b = np.einsum("nij,ni->nj", jb, value)
        point = equation_point(m, eq)
        if eq.kind == "HINGE":
            out.append((point, (eq.a, eq.b), "R", on_b[:, :2].copy(), np.zeros(n)))
        elif eq.kind == "ANGLE":
            couple = on_b[:, 2].copy()
        else:
            out.append((point, (eq.a, eq.b), "P", on_b[:, :2].copy(), couple))
            couple = np.zeros(n)
    return out


def forces_over(plan: SolvePlan, motion: Motion, minimum_norm: bool = False) -> ForceSweep:
    """Reactions and balancing moment at every pose of a solved motion, vectorised.

    Pairs with Coulomb friction (``friction=μ`` on a slide, ``circle=ρ`` on a
    pin) are solved by fixed-point iteration: the friction loads of the last
    reactions are added to the loads until the reactions stop changing; the
    power the friction dissipates is reported as ``friction_loss`` (W).

    Raises
    ------
    IndeterminateError
        The mechanism has redundant constraints and ``minimum_norm`` is false.
    MechanismError
        The friction iteration does not settle (friction too large: self-locking).
    """
    rough = [p for p in plan.mechanism.pairs if p.friction or p.circle]
    result = _forces_once(plan, motion, minimum_norm, {})
    if not rough:
        return result
    for _ in range(200):
        extra, loss = _friction_loads(plan, motion, result, rough)
        new = _forces_once(plan, motion, minimum_norm, extra)
        old_b = np.concatenate([*result.balancing_moment.values(), np.zeros(1)])
        new_b = np.concatenate([*new.balancing_moment.values(), np.zeros(1)])
        scale = 1.0 + float(np.max(np.abs(new_b)))
        result = new
        if float(np.max(np.abs(new_b - old_b))) <= 1e-12 * scale:
            break
    else:
        raise MechanismError(
            "the friction iteration does not settle: the friction is large enough to lock "
            "the mechanism (self-locking) at some pose"
        )
    _, loss = _friction_loads(plan, motion, result, rough)
    return ForceSweep(
        result.inputs,
        result.reactions,
        result.balancing_moment,
        result.balancing_force,
        result.power_residual,
        result.order,
        loss,
    )


def _friction_loads(
    plan: SolvePlan, motion: Motion, result: ForceSweep, rough: list
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Generalized friction loads per link from the reactions, and the power they dissipate.

    A pin (``circle=ρ``) resists the relative turn of its links with ρ·|F|; a
    slide (``friction=μ``) resists the slip with μ·|N|, or with a ``span`` its
    two contacts each with μ·|N_k| (they can push on opposite sides of the
    guide, so the sum is not the net normal force: see :func:`_contact_normals`).

    Raises
    ------
    MechanismError
        A rough pair whose force the solution does not determine.
    """
    m = plan.mechanism
    n = motion.inputs.shape[0]
    loads: dict[str, np.ndarray] = {}
    loss = np.zeros(n)

    def add(link: str, value: np.ndarray) -> None:
        if link != m.ground:
            loads[link] = loads.get(link, np.zeros((n, 3))) + value

    for pair in rough:
        if pair.kind is PairKind.R:
            x, y, force = _pin_pair_force(m, result.reactions, pair)
            size = norm(force)
            wx, wy = motion.qd[x][:, 2], motion.qd[y][:, 2]
            spin = np.sign(wy - wx)
            moment = -(pair.circle or 0.0) * size * spin
            add(y, np.column_stack([np.zeros(n), np.zeros(n), moment]))
            add(x, np.column_stack([np.zeros(n), np.zeros(n), -moment]))
            loss += (pair.circle or 0.0) * size * np.abs(wy - wx)
            continue
        found = _reaction_of(result.reactions, pair)
        if found is None:
            raise MechanismError(
                f"the friction of pair {pair.label} needs the force in it, which the solution "
                "does not determine"
            )
        _, (x, y), _, force, couple = found
        c = np.array(m.coordinates(pair.point), dtype=float)  # type: ignore[arg-type]
        p_world, v_y, _ = motion.point(y, c)
        _, v_x, _ = motion.point(x, c)
        u = rotate_many(_turning(motion, x, y), unit(pair.angle))
        if pair.span:
            n1, n2 = _contact_normals(force, couple, u, pair.span / 2)
            size = np.abs(n1) + np.abs(n2)
        else:
            size = norm(force)
        slip = np.einsum("ni,ni->n", v_y - v_x, u)
        # the contacts lie on the slide's line through its point: their friction acts along it
        f = -(pair.friction or 0.0) * size[:, None] * np.sign(slip)[:, None] * u
        for link, sign in ((y, 1.0), (x, -1.0)):
            r = p_world - motion.q[link][:, :2]
            g = sign * f
            add(link, np.column_stack([g, cross(r, g)]))
        loss += (pair.friction or 0.0) * size * np.abs(slip)
    return loads, loss


def _turning(motion: Motion, x: str, y: str) -> np.ndarray:
    """The angle the links of a slide have turned (they turn together), at every pose."""
    link = x if x in motion.q else y
    return motion.q[link][:, 2]


def _reaction_of(reactions: tuple, pair) -> tuple | None:
    """The reaction the solution gives for ``pair`` (its links, kind and point), if any."""
    kind = pair.kind.value
    return next(
        (
            r
            for r in reactions
            if r[2] == kind and set(r[1]) == set(pair.links) and r[0] == pair.point
        ),
        None,
    )


def _pin_pair_force(m: Mechanism, reactions: tuple, pair) -> tuple[str, str, np.ndarray]:
    """``(a, b, force)``: the force (N, 2) that link ``a`` of a pin ``pair`` exerts on ``b``.

    At a compound hinge the solution gives the force the pin puts on each link,
    not the force between two of them; the hinge's pairs as written form a
    tree of bearings, and the bearing ``pair`` carries what the pin puts on
    the links on ``b``'s side of it.

    Raises
    ------
    MechanismError
        No reaction for the pair, or a compound hinge whose pairs do not join
        its links as a tree.
    """
    found = _reaction_of(reactions, pair)
    if found is not None:
        _, (x, y), _, force, _ = found
        return x, y, force
    hinge = m.compound_hinges.get(pair.point) if pair.point else None
    side = _hinge_side(m, hinge, pair) if hinge is not None else None
    if side is None:
        raise MechanismError(
            f"the friction of pair {pair.label} needs the force in it, which the solution "
            "does not determine"
        )
    total = None
    for point, (a, b), kind, force, _ in reactions:
        if point != pair.point or kind != "R":
            continue
        # what the reaction's a exerts on its b: the b side receives it, the a side gives it
        share = (b in side) - (a in side)
        if share:
            total = share * force if total is None else total + share * force
    if total is None:
        raise MechanismError(f"no reaction at the compound hinge {pair.point}")
    return pair.a, pair.b, total


def _hinge_side(m: Mechanism, hinge, pair) -> set[str] | None:
    """The links of ``hinge`` on ``pair.b``'s side of ``pair`` in the tree of its pairs."""
    edges = [m.pair(pid).links for pid in hinge.pairs if pid != pair.id]
    if pair.id not in hinge.pairs or len(edges) != len(hinge.links) - 2:
        return None
    side = {pair.b}
    grown = True
    while grown:
        grown = False
        for a, b in edges:
            if (a in side) != (b in side):
                side.update((a, b))
                grown = True
    return None if pair.a in side else side


def _contact_normals(
    force: np.ndarray, couple: np.ndarray | float, u: np.ndarray, half: float
) -> tuple[np.ndarray, np.ndarray]:
    """The normal forces of a slide's two contacts at ∓``half`` along ``u``, signed along u⊥.

    With N = u × F the slide's net normal force and C its couple about the
    pair's point, the contacts carry n1 = (N − C/half)/2 and n2 = (N + C/half)/2
    (n1 + n2 = N, half·(n2 − n1) = C). They can have opposite signs: the block
    then bears on both faces of the guide, and its friction is μ·(|n1| + |n2|).
    Arrays over the poses (``force`` and ``u`` (N, 2)).

    >>> n1, n2 = _contact_normals(np.array([[0.0, 0.0]]), 10.0, np.array([[1.0, 0.0]]), 0.5)
    >>> n1.tolist(), n2.tolist()
    ([-10.0], [10.0])
    """
    normal = cross(u, force)
    lever = np.asarray(couple, dtype=float) / half
    return (normal - lever) / 2, (normal + lever) / 2


def _forces_once(
    plan: SolvePlan, motion: Motion, minimum_norm: bool, extra: Mapping[str, np.ndarray]
) -> ForceSweep:
    """One kinetostatic pass: groups from the last back, then the drivers; ``extra`` loads added."""
    redundant = [s.redundant_link for s in plan.steps if s.group is None]
    if redundant and not minimum_norm:
        raise IndeterminateError(
            f"the mechanism is over-constrained (redundant link(s) {', '.join(redundant)}): its "
            "reactions are statically indeterminate; ask for the minimum-norm solution"
        )
    m = plan.mechanism
    n = motion.inputs.shape[0]
    where = _Where.of(motion, m.ground)
    applied = _applied(plan, where)
    for link, value in extra.items():
        applied[link] = applied.get(link, np.zeros((n, 3))) + value
    carried: dict[str, np.ndarray] = {}
    reactions: list = []
    order: list[str] = []
    for step in reversed(plan.steps):
        reactions.extend(_group_reactions(step, where, applied, carried, m))
        order.append(step.label)
    moments: dict[str, np.ndarray] = {}
    balancing_force = None
    balance = {x.link: x for x in m.loads if x.kind == "balance"}
    power = [_power(where, link, value) for link, value in applied.items()]
    for d in plan.drivers:
        load = balance.get(d.link)
        crank = _crank_balance(plan, where, d, load, applied, carried)
        if crank is not None:
            reaction, moment = crank
            reactions.append(reaction)
            moments[d.link] = moment
            power.append(moment * motion.qd[d.link][:, 2])
            order.append(f"I({d.link})")
            continue
        parts, lam, drive = _driver_balance(plan, motion, d, load, applied, carried)
        reactions.extend(_reactions(parts, lam[:, :-1], m))
        if load is not None:
            balancing_force = lam[:, -1:] * unit_from_degrees(load.values[0])[None, :]
        else:
            moments[d.link] = lam[:, -1].copy()
        power.append(lam[:, -1] * np.einsum("ni,ni->n", drive, motion.qd[d.link]))
        order.append(f"I({d.link})")
    reactions.extend(_contact_forces(plan, reactions))
    return ForceSweep(
        motion.inputs, tuple(reactions), moments, balancing_force, _residual(power, n), tuple(order)
    )


def _group_reactions(
    step: GroupStep,
    where: _Where,
    applied: Mapping[str, np.ndarray],
    carried: dict[str, np.ndarray],
    m: Mechanism,
) -> list:
    """A group's reactions from its links' equilibrium, ``Jᵀ·λ = −Q``, at every pose.

    ``Q`` holds the applied and inertia loads and what the groups solved before
    (farther from the drivers) pass on; the group's reactions on its known
    links are added to ``carried`` for the groups solved after it.
    """
    if step.cam is not None:
        return _cam_step_reactions(step, where, applied, carried, m)
    closed = _closed_dyad(step, where, applied, carried, m)
    if closed is not None:
        return closed
    motion = where.motion
    n = motion.inputs.shape[0]
    zero3 = np.zeros((n, 3))
    links = step.links
    index = {link: i for i, link in enumerate(links)}
    rows = sum(eq.size for eq in step.equations)
    jt = np.zeros((n, 3 * len(links), rows))
    parts = []
    r = 0
    for eq in step.equations:
        ja, jb = _parts(eq, motion)
        parts.append((eq, ja, jb, r))
        for link, part in ((eq.a, ja), (eq.b, jb)):
            if link in index:
                k = 3 * index[link]
                jt[:, k : k + 3, r : r + eq.size] += np.transpose(part, (0, 2, 1))
        r += eq.size
    rhs = np.concatenate([-(applied.get(x, zero3) + carried.get(x, zero3)) for x in links], axis=1)
    if jt.shape[1] == jt.shape[2]:
        lam = np.linalg.solve(jt, rhs[..., None])[..., 0]
    else:
        lam = (np.linalg.pinv(jt) @ rhs[..., None])[..., 0]
    for eq, ja, jb, r0 in parts:
        value = lam[:, r0 : r0 + eq.size]
        for link, part in ((eq.a, ja), (eq.b, jb)):
            if link not in index:
                carried[link] = carried.get(link, zero3) + np.einsum("nij,ni->nj", part, value)
    return _reactions(parts, lam, m)


def _cam_step_reactions(
    step: GroupStep,
    where: _Where,
    applied: Mapping[str, np.ndarray],
    carried: dict,
    m: Mechanism,
) -> list:
    """A designed cam's follower: the contact force along the common normal at the pose (the
    replacement rebuilt there) and its guide's or pivot's reaction; the cam takes the first."""
    cam = step.cam
    n = where.motion.inputs.shape[0]
    pose = cam_pose(cam, where.motion.q[cam.cam][:, 2])
    point = pose.contact if cam.design.layout.flat else pose.point
    px, py = point[:, 0], point[:, 1]
    total = _total(applied.get(cam.follower), carried.get(cam.follower), n)
    guide = cam.guide
    # a slide's force acts through its point as fixed to links[1]; a pivot's at the pivot
    on = guide.b if guide.kind is PairKind.P else m.ground
    sx, sy = where.position(on, np.asarray(m.coordinates(guide.point) or (0.0, 0.0), float))
    at = np.empty((n, 2))
    at[:, 0], at[:, 1] = sx, sy
    load = _load_about(where, cam.follower, total, px, py)
    push, force, couple, on_cam = cam_reactions(cam, pose, load, at)
    # the cam takes −push through the contact: carried as that force at its centre and the
    # contact's moment about it (exactly 0 where the normal passes through the centre)
    ox, oy = float(cam.origin[0]), float(cam.origin[1])
    _carry(where, carried, cam.cam, push[:, 0], push[:, 1], ox, oy, on_cam)
    sign = 1.0 if guide.b == cam.follower else -1.0
    return [
        (cam.contact_point, (cam.cam, cam.follower), "H", push, np.zeros(n)),
        (guide.point, (guide.a, guide.b), guide.kind.value, sign * force, sign * couple),
    ]


@dataclass(frozen=True)
class _Where:
    """Where the links' points are over a solved motion, each point found once per pass.

    ``found`` maps ``(link, x, y)`` (sketch) to world ``(x, y)``; it starts
    from the pins the solve found (:attr:`Motion.pins`).
    """

    motion: Motion
    ground: str
    found: dict = field(default_factory=dict)

    @classmethod
    def of(cls, motion: Motion, ground: str) -> _Where:
        return cls(motion, ground, {k: v[:2] for k, v in motion.pins.items()})

    def position(self, link: str, c: np.ndarray) -> tuple:
        """World ``(x, y)`` of sketch point ``c`` on ``link`` (arrays (N,) or floats)."""
        cx, cy = float(c[0]), float(c[1])
        if link == self.ground:
            return cx, cy
        key = (link, cx, cy)
        value = self.found.get(key)
        if value is None:
            value = self.found[key] = self._solved(link, c)
        return value

    def _solved(self, link: str, c: np.ndarray) -> tuple:
        frame = self.motion.frames.get(link)
        if frame is not None:
            if float(frame.ref[0]) == float(c[0]) and float(frame.ref[1]) == float(c[1]):
                return frame.x, frame.y
            return frame.position(c)
        q = self.motion.q[link]
        cos, sin = np.cos(q[:, 2]), np.sin(q[:, 2])
        cx, cy = float(c[0]), float(c[1])
        return q[:, 0] + cos * cx - sin * cy, q[:, 1] + sin * cx + cos * cy

    def turning(self, link: str) -> tuple:
        """The cosine and sine of ``link``'s rotation from the sketch."""
        if link == self.ground:
            return 1.0, 0.0
        frame = self.motion.frames.get(link)
        if frame is not None:
            return frame.cos, frame.sin
        theta = self.motion.q[link][:, 2]
        return np.cos(theta), np.sin(theta)


_ORIGIN = np.zeros(2)


def _power(where: _Where, link: str, value: np.ndarray) -> np.ndarray:
    """The power of a generalized load ``value`` (Fx, Fy, M about the frame origin) on a link.

    For a link with a frame, ``v_O = v_R + ω·J·(O − R)`` (R the frame's
    reference point) gives ``P = F·v_R + ω·(M + (O − R) × F)``: no (N, 3)
    velocity columns and no rotation needed.
    """
    frame = where.motion.frames.get(link)
    if frame is None or frame.vx is None:
        return np.einsum("ni,ni->n", value, where.motion.qd[link])
    ox, oy = where.position(link, _ORIGIN)
    fx, fy = value[:, 0], value[:, 1]
    arm = np.subtract(ox, frame.x) * fy
    arm -= np.subtract(oy, frame.y) * fx
    arm += value[:, 2]
    arm *= frame.omega
    out = fx * frame.vx
    out += fy * frame.vy
    out += arm
    return out


def _load_columns(n: int) -> np.ndarray:
    """A zero generalized load (N, 3) whose columns Fx, Fy, M are each contiguous."""
    return np.zeros((3, n)).T


def _load_about(where: _Where, link: str, total: np.ndarray, px, py) -> tuple:
    """A link's generalized load (about its frame origin) as ``(Fx, Fy, M about (px, py))``."""
    ox, oy = where.position(link, _ORIGIN)
    fx, fy = total[:, 0], total[:, 1]
    return fx, fy, total[:, 2] + (ox - px) * fy - (oy - py) * fx


def _carry(where: _Where, carried: dict, link: str, fx, fy, px, py, couple=0.0) -> None:
    """Add the force ``−(fx, fy)`` at ``(px, py)`` (and ``couple``) on a known link to ``carried``.

    The force is the reaction on the group's link; its known link takes the
    opposite one. Worked out as the sum of the negated force's moment and the
    couple, to the last bit, without making the negated arrays.
    """
    if link == where.ground:
        return
    ox, oy = where.position(link, _ORIGIN)
    arm = np.subtract(px, ox)
    arm *= fy
    moment = np.subtract(py, oy)
    moment *= fx
    moment -= arm  # (py − oy)·fx − (px − ox)·fy: the moment of −(fx, fy)
    moment += couple
    value = carried.get(link)  # the pass's own arrays: added to in place
    if value is None:
        value = carried[link] = _load_columns(where.motion.inputs.shape[0])
    value[:, 0] -= fx
    value[:, 1] -= fy
    value[:, 2] += moment


def _total(applied: np.ndarray | None, carried: np.ndarray | None, n: int) -> np.ndarray:
    """A link's applied and carried loads together (either may be absent), not to be written."""
    if applied is None or carried is None:
        found = applied if carried is None else carried
        return np.zeros((n, 3)) if found is None else found
    return applied + carried


def _closed_dyad(
    step: GroupStep,
    where: _Where,
    applied: Mapping[str, np.ndarray],
    carried: dict[str, np.ndarray],
    m: Mechanism,
) -> list | None:
    """An RRR or RRP dyad's reactions in closed form, vectorised; None for any other group.

    The same equilibrium as the dense solve, ``Jᵀ·λ = −Q``, worked out by hand:
    the moments about the inner pin of one link and the forces on both give
    the outer reactions by a 2×2 Cramer rule (RRR) or the slide's normal force
    by one division (RRP). The reactions come in the order of the equations.
    An unloaded dyad is left to the dense solve (whose zeros carry the signs
    the reports have always printed).
    """
    if step.kind not in ("RRR", "RRP") or len(step.links) != 2:
        return None
    links = step.links
    inner = [eq for eq in step.equations if eq.a in links and eq.b in links]
    if len(inner) != 1 or inner[0].kind != "HINGE":
        return None
    n = where.motion.inputs.shape[0]
    total = {x: _total(applied.get(x), carried.get(x), n) for x in links}
    if not any(value.any() for value in total.values()):
        return None  # unloaded: the dense solve's zeros, signs and all, as printed before
    solve = _rrr_forces if step.kind == "RRR" else _rrp_forces
    forces = solve(step, where, total, carried, m, inner[0])
    if forces is None:
        return None
    out = []
    for eq in step.equations:
        if eq.kind == "ANGLE":
            continue
        fx, fy, couple = forces[id(eq)]
        value = np.empty((n, 2))
        value[:, 0] = fx
        value[:, 1] = fy
        kind = "R" if eq.kind == "HINGE" else "P"
        if isinstance(couple, float) and couple == 0.0 and math.copysign(1.0, couple) > 0:
            couples = np.zeros(n)  # left untouched until read
        else:
            couples = np.broadcast_to(np.asarray(couple, dtype=float), (n,)).copy()
        out.append((equation_point(m, eq), (eq.a, eq.b), kind, value, couples))
    return out


def _outer(step: GroupStep, inner: Equation, link: str, kind: str) -> Equation | None:
    """The equation of ``link``'s outer pair of ``kind`` (HINGE or SLIDE), if it has one."""
    found = [
        eq for eq in step.equations if eq is not inner and link in (eq.a, eq.b) and eq.kind == kind
    ]
    return found[0] if len(found) == 1 else None


def _rrr_forces(step, where, total, carried, m, inner) -> dict | None:
    """RRR: the force on each link at its outer pin from ``u × R_A = a``, ``w × R_A = b``."""
    l1, l2 = step.links
    ea, ec = _outer(step, inner, l1, "HINGE"), _outer(step, inner, l2, "HINGE")
    if ea is None or ec is None or len(step.equations) != 3:
        return None
    bx, by = where.position(l1, inner.point)
    ax, ay = where.position(l1, ea.point)
    cx, cy = where.position(l2, ec.point)
    f1x, f1y, m1 = _load_about(where, l1, total[l1], bx, by)
    f2x, f2y, m2 = _load_about(where, l2, total[l2], bx, by)
    ux, uy, wx, wy = ax - bx, ay - by, cx - bx, cy - by
    fx, fy = f1x + f2x, f1y + f2y
    # in place on the arrays made here (the same arithmetic, fewer fresh arrays)
    rhs_a = np.negative(m1, out=m1)
    t = wx * fy
    t -= (s := wy * fx)
    rhs_b = np.subtract(m2, t, out=m2)  # m2 − (w × f)
    det = np.multiply(ux, wy, out=t)
    det -= np.multiply(uy, wx, out=s)
    rax = rhs_a * wx  # on l1 from its known link, at A: (rhs_a·wx − ux·rhs_b)/det
    rax -= np.multiply(ux, rhs_b, out=s)
    rax /= det
    ray = wy * rhs_a  # (wy·rhs_a − uy·rhs_b)/det
    ray -= np.multiply(uy, rhs_b, out=s)
    ray /= det
    rcx = np.negative(fx, out=fx)  # on l2 from its known link, at C: −f − r_A
    rcx -= rax
    rcy = np.negative(fy, out=fy)
    rcy -= ray
    rbx, rby = np.negative(f1x), np.negative(f1y)  # on l1 from l2, at B: −f1 − r_A
    rbx -= rax
    rby -= ray
    out = {}
    for eq, link, (gx, gy), (px, py) in (
        (ea, l1, (rax, ray), (ax, ay)),
        (ec, l2, (rcx, rcy), (cx, cy)),
    ):
        other = eq.b if eq.a == link else eq.a
        _carry(where, carried, other, gx, gy, px, py)
        out[id(eq)] = (gx, gy, 0.0) if eq.b == link else (-gx, -gy, 0.0)
    out[id(inner)] = (rbx, rby, 0.0) if inner.b == l1 else (-rbx, -rby, 0.0)
    return out


def _rrp_forces(step, where, total, carried, m, inner) -> dict | None:
    """RRP: the slide's normal force from the rod's moments about the inner pin, then the rest."""
    rod = next((x for x in step.links if _outer(step, inner, x, "HINGE") is not None), None)
    slider = next((x for x in step.links if _outer(step, inner, x, "SLIDE") is not None), None)
    if rod is None or slider is None or rod == slider or len(step.equations) != 4:
        return None
    er, es = _outer(step, inner, rod, "HINGE"), _outer(step, inner, slider, "SLIDE")
    angle = next((eq for eq in step.equations if eq.kind == "ANGLE"), None)
    if angle is None or {angle.a, angle.b} != {es.a, es.b}:
        return None
    cx, cy = where.position(rod, inner.point)
    bx, by = where.position(rod, er.point)
    sx, sy = where.position(es.b, es.point)  # the slide's force acts at p_b
    cos, sin = where.turning(slider)
    nx = cos * float(es.normal[0]) - sin * float(es.normal[1])
    ny = sin * float(es.normal[0]) + cos * float(es.normal[1])
    frx, fry, mr = _load_about(where, rod, total[rod], cx, cy)
    fsx, fsy, ms = _load_about(where, slider, total[slider], cx, cy)
    ux, uy = bx - cx, by - cy
    fx, fy = frx + fsx, fry + fsy
    normal = (mr - (ux * fy - uy * fx)) / (ux * ny - uy * nx)  # on the slider, along n
    rbx, rby = -fx - normal * nx, -fy - normal * ny  # on the rod from its known link, at B
    rcx, rcy = -frx - rbx, -fry - rby  # on the rod from the slider, at C
    gx, gy = normal * nx, normal * ny
    couple = -ms - ((sx - cx) * gy - (sy - cy) * gx)  # on the slider, besides
    guide = es.a if es.b == slider else es.b
    _carry(where, carried, guide, gx, gy, sx, sy, -couple)
    other = er.b if er.a == rod else er.a
    _carry(where, carried, other, rbx, rby, bx, by)
    return {
        id(er): (rbx, rby, 0.0) if er.b == rod else (-rbx, -rby, 0.0),
        id(inner): (rcx, rcy, 0.0) if inner.b == rod else (-rcx, -rcy, 0.0),
        id(es): (gx, gy, couple) if es.b == slider else (-gx, -gy, -couple),
    }


def _crank_balance(
    plan: SolvePlan,
    where: _Where,
    driver: DriverStep,
    load: Load | None,
    applied: Mapping[str, np.ndarray],
    carried: Mapping[str, np.ndarray],
) -> tuple[tuple, np.ndarray] | None:
    """A crank pinned to the ground, balanced by its motor: its reaction and moment, closed form.

    The pin takes the whole force on the crank, the motor the whole moment
    about the pin. None for any other driver (a slide, a ``balance`` load)
    and for an unloaded crank.
    """
    if driver.kind != "R" or load is not None:
        return None
    equations = ground_equations(plan, driver.link)
    eq = equations[0]
    if len(equations) != 1 or eq.kind != "HINGE" or eq.a != driver.link:
        return None
    m = plan.mechanism
    n = where.motion.inputs.shape[0]
    total = _total(applied.get(driver.link), carried.get(driver.link), n)
    if not total.any():
        return None  # unloaded: the dense solve's zeros, signs and all, as printed before
    px, py = float(eq.point[0]), float(eq.point[1])
    fx, fy, about_pin = _load_about(where, driver.link, total, px, py)
    force = np.empty((n, 2))
    force[:, 0] = fx  # what the crank exerts on the ground
    force[:, 1] = fy
    reaction = (equation_point(m, eq), (eq.a, eq.b), "R", force, np.zeros(n))
    return reaction, -about_pin


def _driver_balance(
    plan: SolvePlan,
    motion: Motion,
    driver: DriverStep,
    load: Load | None,
    applied: Mapping[str, np.ndarray],
    carried: Mapping[str, np.ndarray],
) -> tuple[list, np.ndarray, np.ndarray]:
    """A driver's equilibrium: its ground pair's multipliers and the balancing load, last.

    The balancing load is the motor's moment (or force along the slide), or
    the force of a ``balance`` statement ``load`` along its direction.
    Returns the equation parts, the multipliers (N, rows + 1) and the
    generalized direction of the balancing load (N, 3).
    """
    m = plan.mechanism
    n = motion.inputs.shape[0]
    link = driver.link
    zero3 = np.zeros((n, 3))
    total = applied.get(link, zero3) + carried.get(link, zero3)
    parts = []
    cols = []
    r0 = 0
    for eq in ground_equations(plan, link):
        ja, jb = _parts(eq, motion)
        parts.append((eq, ja, jb, r0))
        cols.append(np.transpose(ja, (0, 2, 1)))
        r0 += eq.size
    if load is not None:
        u = unit_from_degrees(load.values[0])
        if m.coordinates(load.point) is None:  # type: ignore[arg-type]
            raise MechanismError(f"point {load.point} of the balance on {link} needs coordinates")
        c = np.array(m.coordinates(load.point), dtype=float)  # type: ignore[arg-type]
        rp = rotate_many(motion.q[link][:, 2], c)
        drive = np.stack([np.full(n, u[0]), np.full(n, u[1]), cross(rp, u)], axis=1)
    elif driver.kind == "R":
        drive = np.tile([0.0, 0.0, 1.0], (n, 1))
    else:
        drive = np.tile([driver.direction[0], driver.direction[1], 0.0], (n, 1))
    jt = np.concatenate([*cols, drive[:, :, None]], axis=2)
    lam = np.linalg.solve(jt, -total[..., None])[..., 0]
    return parts, lam, drive


def _residual(power: list[np.ndarray], n: int) -> np.ndarray:
    """The virtual-power check: |Σ powers| relative to the largest term, at every pose."""
    if not power:
        return np.zeros(n)
    # term by term, in order (as a sum over the stacked terms adds them), on two arrays
    total_power = np.array(power[0], dtype=float)
    scale = np.abs(total_power)
    for term in power[1:]:
        total_power += term
        np.maximum(scale, np.abs(term), out=scale)  # the largest |term|
    np.abs(total_power, out=total_power)
    return np.where(scale > 0, total_power / np.where(scale > 0, scale, 1.0), 0.0)


def solve_forces(
    plan: SolvePlan,
    inputs: tuple[float, ...] | None = None,
    minimum_norm: bool = False,
) -> ForceSolution:
    """Reactions and balancing moment at one input (default: the sketch pose).

    The solution records the input in its ``inputs``.

    Raises
    ------
    IndeterminateError
        The mechanism has redundant constraints; with ``minimum_norm`` the
        minimum-norm reactions are returned instead.
    """
    inputs = tuple(0.0 for _ in plan.drivers) if inputs is None else tuple(inputs)
    motion = solve_poses(plan, np.array([inputs], dtype=float).reshape(1, -1))
    sweep = forces_over(plan, motion, minimum_norm)
    reactions = tuple(
        Reaction(
            point,
            links,
            kind,
            force[0],
            float(couple[0]),
            _two_contacts(plan, point, links, kind, force[0], float(couple[0]), motion),
        )
        for point, links, kind, force, couple in sweep.reactions
    )
    balancing = {k: float(v[0]) for k, v in sweep.balancing_moment.items()}
    return ForceSolution(
        reactions,
        balancing,
        None if sweep.balancing_force is None else sweep.balancing_force[0],
        float(sweep.power_residual[0]),
        sweep.order,
        None if sweep.friction_loss is None else float(sweep.friction_loss[0]),
        _pin_forces(plan.mechanism, reactions),
        inputs,
        {d.link: balancing[d.link] for d in plan.drivers if d.kind == "P" and d.link in balancing},
    )


def _pin_forces(m, reactions) -> dict[str, dict[str, np.ndarray]]:
    """At each compound hinge, the force its pin exerts on every link that meets there.

    With the pin massless these forces add up to zero; they are what a compound hinge
    determines (forces "between" two of its links are not: any split of the pin's
    load among them balances). Found from the tree of pairs the groups used.
    """
    out: dict[str, dict[str, np.ndarray]] = {}
    for point, hinge in m.compound_hinges.items():
        forces = {link: np.zeros(2) for link in hinge.links}
        for r in reactions:
            if r.point != point or r.kind != "R":
                continue
            a, b = r.links
            forces[b] = forces[b] + r.force
            forces[a] = forces[a] - r.force
        out[point] = forces
    return out


def ground_equations(plan: SolvePlan, link: str) -> list[Equation]:
    """The equations of a driver's pair with the ground."""
    m = plan.mechanism
    for p in m.pairs_of(link):
        if p.other(link) != m.ground:
            continue
        c = np.array(m.coordinates(p.point), dtype=float) if p.point else np.zeros(2)
        if p.kind is PairKind.R:
            return [Equation("HINGE", link, m.ground, c, pair=p.id)]
        if p.kind is PairKind.P and p.angle is not None:
            return list(slide_equations(link, m.ground, c, unit(p.angle), p.id))
    for h in m.compound_hinges.values():
        if link in h.links and m.ground in h.links:
            c = np.array(m.coordinates(h.point), dtype=float)
            return [Equation("HINGE", link, m.ground, c)]
    raise MechanismError(f"driver {link} has no pair with the ground to take its reactions")


def _two_contacts(
    plan: SolvePlan,
    point: str | None,
    links: tuple[str, str],
    kind: str,
    force: np.ndarray,
    couple: float,
    motion: Motion,
) -> tuple[np.ndarray, np.ndarray] | None:
    """A slide with two contact points ``span`` apart: the two normal forces.

    With N the normal force and C its moment about the pair's point, the
    contacts at ∓span/2 along the slide carry (N ∓ C/(span/2))/2 each. The
    slide's direction is taken at the pose of ``motion`` (its first row).
    """
    if kind != "P":
        return None
    pair = next(
        (
            p
            for p in plan.mechanism.pairs
            if p.kind is PairKind.P and set(p.links) == set(links) and p.point == point
        ),
        None,
    )
    if pair is None or pair.span is None:
        return None
    turned = next((x for x in pair.links if x in motion.q), None)  # the links keep one angle
    t = (pair.angle or 0.0) + (float(motion.q[turned][0, 2]) if turned is not None else 0.0)
    u = unit(t)
    size = float(norm(force))
    half = pair.span / 2
    if size <= 1e-9 * (1.0 + abs(couple) / half):  # a pure couple: no direction of its own
        size, direction = 0.0, perpendicular(u)
    else:
        direction = force / size
    side = float(cross(u, direction))  # ±1: u × direction
    # signed along u⊥ (u × direction = side): back along the direction of the net force
    n1, n2 = _contact_normals((side * size * perpendicular(u))[None, :], couple, u[None, :], half)
    return side * float(n1[0]) * direction, side * float(n2[0]) * direction


def _contact_forces(plan: SolvePlan, reactions: list) -> list:
    """Each higher pair's contact force, carried by its virtual link (a two-force member).

    What link ``a`` exerts on the virtual link passes on unchanged to link ``b``.
    """
    out = []
    for virtual, a, b, point in plan.contacts:
        for _, links, _, force, _ in reactions:
            if set(links) == {a, virtual}:
                on_virtual = force if links == (a, virtual) else -force
                out.append((point, (a, b), "H", on_virtual.copy(), np.zeros(force.shape[0])))
                break
    return out
