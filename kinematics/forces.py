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
the moment the motor applies to the driver, counter-clockwise positive.

Every solution comes with the virtual-power check: the power of every load,
inertia load and the balancing moment must add up to zero; its residual is
reported relative to the largest term.

>>> from structure.edgelist import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.plan import make_plan
>>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0", "point B 0.1 0",
...                     "force 1 B 0 -100"])
>>> r = solve_forces(make_plan(analyze(m)))
>>> round(r.balancing_moment["1"], 9), r.power_residual < 1e-12
(10.0, True)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from structure.errors import MechanismError

from .equations import Equation, evaluate
from .plan import SolvePlan
from .solve import KinematicState, solve_pose

__all__ = ["ForceSolution", "IndeterminateError", "Reaction", "ground_equations", "solve_forces"]


class IndeterminateError(MechanismError):
    """Reactions of an over-constrained mechanism (r > 0) are statically indeterminate."""


@dataclass(frozen=True)
class Reaction:
    """The force (and for a prismatic pair the couple) ``links[0]`` exerts on ``links[1]``."""

    point: str | None
    links: tuple[str, str]
    kind: str  # 'R' or 'P'
    force: np.ndarray
    couple: float = 0.0

    @property
    def magnitude(self) -> float:
        return float(np.hypot(*self.force))


@dataclass(frozen=True)
class ForceSolution:
    """Reactions in the order solved, the balancing moment(s) or force, the power check."""

    reactions: tuple[Reaction, ...]
    balancing_moment: Mapping[str, float]
    balancing_force: np.ndarray | None
    power_residual: float
    order: tuple[str, ...]


def _applied(plan: SolvePlan, state: KinematicState) -> dict[str, np.ndarray]:
    """Generalized applied and inertia forces (Fx, Fy, moment about the frame origin) per link."""
    m = plan.mechanism
    q: dict[str, np.ndarray] = {}
    gravity = np.zeros(2)
    for load in m.loads:
        if load.kind == "gravity":
            gravity = np.array(load.values)

    def at(link: str, point: str | None) -> np.ndarray:
        if point is None or m.coordinates(point) is None:
            raise MechanismError(f"point {point} of a load on link {link} needs coordinates")
        c = np.array(m.coordinates(point), dtype=float)
        x = state.links[link].q if link in state.links else np.zeros(3)
        cs, sn = math.cos(x[2]), math.sin(x[2])
        return np.array([cs * c[0] - sn * c[1], sn * c[0] + cs * c[1]])

    def add(link: str, value: np.ndarray) -> None:
        q[link] = q.get(link, np.zeros(3)) + value

    for load in m.loads:
        if load.kind == "force":
            r = at(load.link, load.point)
            f = np.array(load.values)
            add(load.link, np.array([f[0], f[1], r[0] * f[1] - r[1] * f[0]]))
        elif load.kind == "moment":
            add(load.link, np.array([0.0, 0.0, load.values[0]]))
        elif load.kind == "mass":
            mass, inertia = load.values
            link = load.link
            r = at(link, load.point)
            st = state.links[link]
            w, e = st.qd[2], st.qdd[2]
            jr = np.array([-r[1], r[0]])
            a_s = st.qdd[:2] + e * jr - w * w * r
            f = mass * (gravity - a_s)
            add(link, np.array([f[0], f[1], r[0] * f[1] - r[1] * f[0] - inertia * e]))
    return q


def _parts(eq: Equation, state: KinematicState) -> tuple[np.ndarray, np.ndarray]:
    zero = np.zeros((1, 3))

    def pose(link: str) -> np.ndarray:
        return state.links[link].q[None, :] if link in state.links else zero

    _, ja, jb, _ = evaluate(eq, pose(eq.a), pose(eq.b), zero, zero)
    return ja[0], jb[0]


def solve_forces(
    plan: SolvePlan,
    inputs: tuple[float, ...] | None = None,
    state: KinematicState | None = None,
    minimum_norm: bool = False,
) -> ForceSolution:
    """Reactions and balancing moment at one input (default: the sketch pose).

    Raises
    ------
    IndeterminateError
        The mechanism has redundant constraints; with ``minimum_norm`` the
        minimum-norm reactions are returned instead.
    """
    if state is None:
        state = solve_pose(plan, inputs)
    redundant = [s.redundant_link for s in plan.steps if s.group is None]
    if redundant and not minimum_norm:
        raise IndeterminateError(
            f"the mechanism is over-constrained (redundant link(s) {', '.join(redundant)}): its "
            "reactions are statically indeterminate; ask for the minimum-norm solution"
        )
    m = plan.mechanism
    applied = _applied(plan, state)
    # generalized force on each link from the pairs already solved (later groups)
    carried: dict[str, np.ndarray] = {}
    reactions: list[Reaction] = []
    order: list[str] = []
    for step in reversed(plan.steps):
        links = step.links
        index = {link: i for i, link in enumerate(links)}
        rows = sum(eq.size for eq in step.equations)
        jt = np.zeros((3 * len(links), rows))
        parts = []
        r = 0
        for eq in step.equations:
            ja, jb = _parts(eq, state)
            parts.append((eq, ja, jb, r))
            for link, part in ((eq.a, ja), (eq.b, jb)):
                if link in index:
                    jt[3 * index[link] : 3 * index[link] + 3, r : r + eq.size] += part.T
            r += eq.size
        rhs = np.concatenate(
            [-(applied.get(x, np.zeros(3)) + carried.get(x, np.zeros(3))) for x in links]
        )
        if jt.shape[0] == jt.shape[1]:
            lam = np.linalg.solve(jt, rhs)
        else:
            lam = np.linalg.lstsq(jt, rhs, rcond=None)[0]
        for eq, ja, jb, r0 in parts:
            value = lam[r0 : r0 + eq.size]
            for link, part in ((eq.a, ja), (eq.b, jb)):
                if link not in index:
                    carried[link] = carried.get(link, np.zeros(3)) + part.T @ value
        reactions.extend(_reactions(parts, lam, m))
        order.append(step.label)
    balancing: dict[str, float] = {}
    balance = [x for x in m.loads if x.kind == "balance"]
    balancing_force = None
    power = []
    for d in plan.drivers:
        link = d.link
        st = state.links[link]
        total = applied.get(link, np.zeros(3)) + carried.get(link, np.zeros(3))
        ground_eqs = ground_equations(plan, link)
        cols = []
        ground_parts = []
        r0 = 0
        for eq in ground_eqs:
            ja, jb = _parts(eq, state)
            cols.append(ja.T)
            ground_parts.append((eq, ja, jb, r0))
            r0 += eq.size
        load = next((x for x in balance if x.link == link), None)
        if load is not None:
            t = math.radians(load.values[0])
            u = np.array([math.cos(t), math.sin(t)])
            c = np.array(m.coordinates(load.point), dtype=float)  # type: ignore[arg-type]
            cs, sn = math.cos(st.q[2]), math.sin(st.q[2])
            rp = np.array([cs * c[0] - sn * c[1], sn * c[0] + cs * c[1]])
            drive = np.array([[u[0]], [u[1]], [rp[0] * u[1] - rp[1] * u[0]]])
        elif d.kind == "R":
            drive = np.array([[0.0], [0.0], [1.0]])
        else:
            drive = np.array([[d.direction[0]], [d.direction[1]], [0.0]])
        jt = np.hstack([*cols, drive])
        lam = np.linalg.solve(jt, -total)
        reactions.extend(_reactions(ground_parts, lam[:-1], m))
        if load is not None:
            balancing_force = lam[-1] * u
        else:
            balancing[link] = float(lam[-1])
        power.append(float(lam[-1] * (drive[:, 0] @ st.qd)))
        order.append(f"I({link})")
    for link, value in applied.items():
        if link in state.links:
            power.append(float(value @ state.links[link].qd))
    scale = max((abs(p) for p in power), default=0.0)
    residual = abs(sum(power)) / scale if scale > 0 else 0.0
    return ForceSolution(tuple(reactions), balancing, balancing_force, residual, tuple(order))


def ground_equations(plan: SolvePlan, link: str) -> list[Equation]:
    """The equations of a driver's pair with the ground."""
    m = plan.mechanism
    for p in m.pairs_of(link):
        if p.other(link) != m.ground:
            continue
        c = np.array(m.coordinates(p.point), dtype=float) if p.point else np.zeros(2)
        if p.kind.value == "R":
            return [Equation("HINGE", link, m.ground, c, pair=p.id)]
        if p.kind.value == "P" and p.angle is not None:
            u = np.array([math.cos(p.angle), math.sin(p.angle)])
            return [
                Equation("ANGLE", link, m.ground, pair=p.id),
                Equation("SLIDE", link, m.ground, c, np.array([-u[1], u[0]]), p.id),
            ]
    for h in m.compound_hinges.values():
        if link in h.links and m.ground in h.links:
            c = np.array(m.coordinates(h.point), dtype=float)
            return [Equation("HINGE", link, m.ground, c)]
    raise MechanismError(f"driver {link} has no pair with the ground to take its reactions")


def _reactions(parts, lam: np.ndarray, m) -> list[Reaction]:
    """Reactions from the multipliers: what eq.a exerts on eq.b is ∂Φ/∂q_bᵀ·λ.

    A prismatic pair's ANGLE row (a couple) is reported with its SLIDE row.
    """
    out: list[Reaction] = []
    couple = 0.0
    for eq, _, jb, r0 in parts:
        value = lam[r0 : r0 + eq.size]
        on_b = jb.T @ value
        point = m.pair(eq.pair).point if eq.pair else _hinge_at(m, eq.point)
        if eq.kind == "HINGE":
            out.append(Reaction(point, (eq.a, eq.b), "R", on_b[:2].copy()))
        elif eq.kind == "ANGLE":
            couple = float(on_b[2])
        else:
            out.append(Reaction(point, (eq.a, eq.b), "P", on_b[:2].copy(), couple))
            couple = 0.0
    return out


def _hinge_at(m, xy) -> str | None:
    for h in m.compound_hinges.values():
        p = m.points.get(h.point)
        if p is not None and (p.x, p.y) == (float(xy[0]), float(xy[1])):
            return h.point
    return None
