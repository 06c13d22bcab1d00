"""Exact velocities and accelerations at the sketch pose, with sympy.

At the sketch every link is at ``q = 0``, so the pair Jacobians are built
from the sketch coordinates alone; when those are exact (decimals, fractions,
``0.2*sqrt(3)``) the group-by-group linear solves are exact too. The drivers'
speeds may stay symbols: ``symbolic=True`` gives ω3 = ω1/2 for the exam's
slotted link rather than a number.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 1 omega=20", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 0.1", "point C 0.4 0.1", "point D 0.4 -0.3"])
>>> e = solve_exact(make_plan(analyze(m)))
>>> e.links["3"]["omega"], e.links["2"]["epsilon"]
(5, 75)
>>> solve_exact(make_plan(analyze(m)), symbolic=True).links["3"]["omega"]
omega_1/4
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy
from sympy.matrices.exceptions import NonInvertibleMatrixError

from structure.errors import MechanismError
from structure.expressions import exact_float, exact_value
from structure.model import Load, Mechanism

from ..errors import IndeterminateError, SingularPoseError
from ..kinetostatics.forces import ground_equations
from .equations import Equation, equation_point
from .plan import DriverStep, GroupStep, SolvePlan

__all__ = ["ExactForces", "ExactState", "forces_exact", "solve_exact"]


@dataclass(frozen=True)
class ExactState:
    """Exact ``omega``/``epsilon`` per link and ``velocity``/``acceleration`` per point.

    Values are sympy expressions; ``drivers`` maps each driver to its speed
    and acceleration (numbers, or symbols ``omega_1``, ``epsilon_1``).
    """

    links: Mapping[str, Mapping[str, sympy.Expr]]
    points: Mapping[str, Mapping[str, tuple[sympy.Expr, sympy.Expr]]]
    drivers: Mapping[str, tuple[sympy.Expr, sympy.Expr]]
    q_dot: Mapping[str, sympy.Matrix]
    q_ddot: Mapping[str, sympy.Matrix]


def _exact_point(m: Mechanism, name: str | None) -> sympy.Matrix:
    p = m.points[name]  # type: ignore[index]
    x = exact_value(p.exact[0]) if p.exact[0] else exact_float(p.x)
    y = exact_value(p.exact[1]) if p.exact[1] else exact_float(p.y)
    return sympy.Matrix([x, y])


def _point_name(m: Mechanism, eq: Equation) -> str | None:
    """The point an equation's pair acts at (a compound hinge's for its canonical pair)."""
    name = equation_point(m, eq)
    if name is None and not eq.pair:
        raise ValueError(f"no compound hinge at {tuple(eq.point)}")
    return name


def _unit(degrees: float | None) -> sympy.Matrix:
    """Exact unit vector of a slide direction.

    Angles that are a whole number of degrees, or a simple fraction of one,
    give radicals (cos 30° = √3/2); any other angle is taken as the exact
    rational of its float cosine and sine (the data are not exact then anyway).
    """
    value = exact_float(degrees or 0.0)
    if value.q <= 12:
        t = sympy.pi * value / 180
        return sympy.Matrix([sympy.cos(t), sympy.sin(t)])
    rad = math.radians(float(degrees or 0.0))
    return sympy.Matrix([exact_float(math.cos(rad)), exact_float(math.sin(rad))])


def _perp(v: sympy.Matrix) -> sympy.Matrix:
    """``J·v`` for an exact vector (what :func:`~.planar.perpendicular` does to arrays)."""
    return sympy.Matrix([-v[1], v[0]])


def _cross(a: sympy.Matrix, b: sympy.Matrix) -> sympy.Expr:
    """``a × b`` (z) for exact vectors (what :func:`~.planar.cross` does to arrays)."""
    return a[0] * b[1] - a[1] * b[0]


def _rows(equations, plan: SolvePlan):
    """Exact (equation, partials of a, partials of b, point, normal) of each equation at q = 0."""
    m = plan.mechanism
    out = []
    for eq in equations:
        pair = m.pair(eq.pair) if eq.pair else None
        c = _exact_point(m, _point_name(m, eq))
        if eq.kind == "HINGE":
            ja = sympy.Matrix.hstack(sympy.eye(2), _perp(c))
            out.append((eq, ja, -ja, c, None))
        elif eq.kind == "ANGLE":
            out.append((eq, sympy.Matrix([[0, 0, 1]]), sympy.Matrix([[0, 0, -1]]), c, None))
        else:
            u = _unit(pair.angle_deg if pair is not None else None)
            n = _perp(u)
            lever = (n.T * _perp(c))[0]
            ja = sympy.Matrix([[-n[0], -n[1], -lever]])
            jb = sympy.Matrix([[n[0], n[1], lever]])
            out.append((eq, ja, jb, c, n))
    return out


def _bias(kind: str, c: sympy.Matrix, n, va: sympy.Matrix, vb: sympy.Matrix) -> sympy.Matrix:
    wa, wb = va[2], vb[2]
    if kind == "ANGLE":
        return sympy.Matrix([0])
    if kind == "HINGE":
        return -(wa**2) * c + wb**2 * c
    d_dot = vb[:2, 0] + wb * _perp(c) - va[:2, 0] - wa * _perp(c)
    return sympy.Matrix([2 * wa * (_perp(n).T * d_dot)[0] + (n.T * (-(wb**2) * c + wa**2 * c))[0]])


def _no_designed_cam(plan: SolvePlan) -> None:
    """Refuse a designed cam by name: its motion has no exact form here."""
    if plan.cams:
        raise MechanismError(
            f"{plan.cams[0].label} has the profile of its program: its curvature and motion are "
            "computed in floating point, with no exact form here; solve without --exact"
        )


def solve_exact(plan: SolvePlan, symbolic: bool = False) -> ExactState:
    """Exact ω, ε of every link and v, a of every named point at the sketch pose.

    ``symbolic`` keeps each driver's speed and acceleration as symbols.

    Raises
    ------
    MechanismError
        The mechanism has a designed cam (a ``cam`` statement): its profile
        comes from its program in floating point, with no exact form here.
    """
    _no_designed_cam(plan)
    m = plan.mechanism
    zero = sympy.zeros(3, 1)
    qd: dict[str, sympy.Matrix] = {m.ground: zero}
    qdd: dict[str, sympy.Matrix] = {m.ground: zero}
    drivers: dict[str, tuple[sympy.Expr, sympy.Expr]] = {}
    for k, d in enumerate(plan.drivers, start=1):
        if symbolic:
            names = ("omega", "epsilon") if d.kind == "R" else ("v", "a")
            w, e = sympy.Symbol(f"{names[0]}_{k}"), sympy.Symbol(f"{names[1]}_{k}")
        else:
            w, e = exact_float(d.speed), exact_float(d.acceleration)
        drivers[d.link] = (w, e)
        if d.kind == "R":
            pivot = _exact_point(m, d.point)
            qd[d.link] = sympy.Matrix([*(-w * _perp(pivot)), w])
            qdd[d.link] = sympy.Matrix([*(-e * _perp(pivot) + w**2 * pivot), e])
        else:
            slide = m.ground_joint(d.link).pair
            u = _unit(slide.angle_deg)
            qd[d.link] = sympy.Matrix([*(w * u), 0])
            qdd[d.link] = sympy.Matrix([*(e * u), 0])
    for step in plan.steps:
        links = step.links
        index = {link: i for i, link in enumerate(links)}
        rows = _rows(step.equations, plan)
        size = sum(eq.size for eq, *_ in rows)
        jac = sympy.zeros(size, 3 * len(links))
        rhs_v = sympy.zeros(size, 1)
        r = 0
        for eq, ja, jb, _, _ in rows:
            for link, part in ((eq.a, ja), (eq.b, jb)):
                if link in index:
                    jac[r : r + eq.size, 3 * index[link] : 3 * index[link] + 3] = part
                else:
                    rhs_v[r : r + eq.size, 0] -= part * qd.get(link, zero)
            r += eq.size
        z_dot = _solve(jac, rhs_v, plan, step)
        for link, i in index.items():
            qd[link] = z_dot[3 * i : 3 * i + 3, 0]
        rhs_a = sympy.zeros(size, 1)
        r = 0
        for eq, ja, jb, c, n in rows:
            for link, part in ((eq.a, ja), (eq.b, jb)):
                if link not in index:
                    rhs_a[r : r + eq.size, 0] -= part * qdd.get(link, zero)
            va, vb = qd.get(eq.a, zero), qd.get(eq.b, zero)
            rhs_a[r : r + eq.size, 0] -= _bias(eq.kind, c, n, va, vb)
            r += eq.size
        z_ddot = _solve(jac, rhs_a, plan, step)
        for link, i in index.items():
            qdd[link] = z_ddot[3 * i : 3 * i + 3, 0]
    links = {
        name: {"omega": sympy.simplify(qd[name][2]), "epsilon": sympy.simplify(qdd[name][2])}
        for name in m.moving_links
        if name in qd
    }
    points = {}
    for name, (link, _) in plan.points.items():
        c = _exact_point(m, name) if name in m.points else sympy.zeros(2, 1)
        v, a = qd.get(link, zero), qdd.get(link, zero)
        vel = v[:2, 0] + v[2] * _perp(c)
        acc = a[:2, 0] + a[2] * _perp(c) - v[2] ** 2 * c
        points[name] = {
            "velocity": (sympy.simplify(vel[0]), sympy.simplify(vel[1])),
            "acceleration": (sympy.simplify(acc[0]), sympy.simplify(acc[1])),
        }
    return ExactState(links, points, drivers, qd, qdd)


@dataclass(frozen=True)
class ExactForces:
    """Exact reactions (point, links, kind, force on links[1] by links[0], couple) and balance."""

    reactions: tuple[tuple[str | None, tuple[str, str], str, tuple, sympy.Expr], ...]
    balancing_moment: Mapping[str, sympy.Expr]
    balancing_force: tuple[sympy.Expr, sympy.Expr] | None


def _exact_loads(plan: SolvePlan, kin: ExactState) -> dict[str, sympy.Matrix]:
    """Exact generalized loads (Fx, Fy, moment about the world origin) per link at the sketch."""
    m = plan.mechanism
    out: dict[str, sympy.Matrix] = {}
    gravity = sympy.zeros(2, 1)

    def number(load, k: int) -> sympy.Expr:
        written = load.exact[k] if k < len(load.exact) else None
        return exact_value(written) if written else exact_float(load.values[k])

    for load in m.loads:
        if load.kind == "gravity":
            gravity = sympy.Matrix([number(load, 0), number(load, 1)])

    def add(link: str, value: sympy.Matrix) -> None:
        out[link] = out.get(link, sympy.zeros(3, 1)) + value

    for load in m.loads:
        if load.kind == "force":
            c = _exact_point(m, load.point)
            f = sympy.Matrix([number(load, 0), number(load, 1)])
            add(load.link, sympy.Matrix([f[0], f[1], _cross(c, f)]))
        elif load.kind == "moment":
            add(load.link, sympy.Matrix([0, 0, number(load, 0)]))
        elif load.kind == "mass":
            mass, inertia = number(load, 0), number(load, 1)
            c = _exact_point(m, load.point)
            v, a = kin.q_dot[load.link], kin.q_ddot[load.link]
            a_s = a[:2, 0] + a[2] * _perp(c) - v[2] ** 2 * c
            f = mass * (gravity - a_s)
            add(load.link, sympy.Matrix([f[0], f[1], _cross(c, f) - inertia * a[2]]))
    return out


def _exact_reactions(rows, lam: sympy.Matrix) -> list:
    out = []
    couple = sympy.Integer(0)
    r = 0
    for eq, _, jb, _c, _ in rows:
        value = lam[r : r + eq.size, 0]
        r += eq.size
        on_b = jb.T * value
        if eq.kind == "HINGE":
            out.append(
                (eq, (eq.a, eq.b), "R", (sympy.simplify(on_b[0]), sympy.simplify(on_b[1])), 0)
            )
        elif eq.kind == "ANGLE":
            couple = sympy.simplify(on_b[2])
        else:
            force = (sympy.simplify(on_b[0]), sympy.simplify(on_b[1]))
            out.append((eq, (eq.a, eq.b), "P", force, couple))
            couple = sympy.Integer(0)
    return out


def forces_exact(plan: SolvePlan) -> ExactForces:
    """Exact reactions and balancing moment at the sketch pose.

    See :mod:`kinematics.kinetostatics.forces`.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan
    >>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0",
    ...                     "point B 0.1 0.1", "force 1 B 0 -100"])
    >>> forces_exact(make_plan(analyze(m))).balancing_moment["1"]
    10

    Raises
    ------
    MechanismError
        A redundant link: the reactions are indeterminate; or a pair with
        friction, which the exact solution does not take.
    """
    _no_designed_cam(plan)
    if any(s.group is None for s in plan.steps):
        raise IndeterminateError("the mechanism is over-constrained: reactions are indeterminate")
    m = plan.mechanism
    rough = [p.label for p in m.pairs if p.friction or p.circle]
    if rough:
        raise MechanismError(
            f"the exact reactions leave friction out, and pair(s) {', '.join(rough)} have it "
            "(friction= or circle=): drop --exact for the reactions with friction"
        )
    kin = solve_exact(plan)
    loads = _exact_loads(plan, kin)
    carried: dict[str, sympy.Matrix] = {}
    reactions = []
    for step in reversed(plan.steps):
        reactions.extend(_exact_group_reactions(plan, step, loads, carried))
    moments: dict[str, sympy.Expr] = {}
    balancing_force = None
    balance = {x.link: x for x in m.loads if x.kind == "balance"}
    for d in plan.drivers:
        load = balance.get(d.link)
        rows, lam, direction = _exact_driver_balance(plan, d, load, loads, carried)
        reactions.extend(_exact_reactions(rows, lam[:-1, 0]))
        if load is not None:
            balancing_force = (
                sympy.simplify(lam[-1] * direction[0]),
                sympy.simplify(lam[-1] * direction[1]),
            )
        else:
            moments[d.link] = sympy.simplify(lam[-1])
    out = tuple(
        (_point_name(m, eq), links, kind, force, couple)
        for eq, links, kind, force, couple in reactions
    )
    return ExactForces(out, moments, balancing_force)


def _exact_group_reactions(
    plan: SolvePlan,
    step: GroupStep,
    loads: Mapping[str, sympy.Matrix],
    carried: dict[str, sympy.Matrix],
) -> list:
    """A group's exact reactions, ``Jᵀ·λ = −Q``; its reactions on known links go to ``carried``."""
    rows = _rows(step.equations, plan)
    index = {link: i for i, link in enumerate(step.links)}
    size = sum(eq.size for eq, *_ in rows)
    jt = sympy.zeros(3 * len(index), size)
    r = 0
    for eq, ja, jb, _, _ in rows:
        for link, part in ((eq.a, ja), (eq.b, jb)):
            if link in index:
                jt[3 * index[link] : 3 * index[link] + 3, r : r + eq.size] = part.T
        r += eq.size
    rhs = sympy.Matrix.vstack(
        *[-(loads.get(x, sympy.zeros(3, 1)) + carried.get(x, sympy.zeros(3, 1))) for x in index]
    )
    lam = _solve(jt, rhs, plan, step)
    r = 0
    for eq, ja, jb, _, _ in rows:
        value = lam[r : r + eq.size, 0]
        for link, part in ((eq.a, ja), (eq.b, jb)):
            if link not in index:
                carried[link] = carried.get(link, sympy.zeros(3, 1)) + part.T * value
        r += eq.size
    return _exact_reactions(rows, lam)


def _exact_driver_balance(
    plan: SolvePlan,
    driver: DriverStep,
    load: Load | None,
    loads: Mapping[str, sympy.Matrix],
    carried: Mapping[str, sympy.Matrix],
) -> tuple[list, sympy.Matrix, sympy.Matrix | None]:
    """A driver's exact equilibrium: its ground pair's rows, the multipliers (balancing load
    last) and the direction of a ``balance`` statement's force (None for the motor's)."""
    m = plan.mechanism
    rows = _rows(ground_equations(plan, driver.link), plan)
    cols = [ja.T for _, ja, _, _, _ in rows]
    u = None
    if load is not None:
        u = _unit(load.values[0])
        c = _exact_point(m, load.point)
        drive = sympy.Matrix([u[0], u[1], _cross(c, u)])
    elif driver.kind == "R":
        drive = sympy.Matrix([0, 0, 1])
    else:
        drive = sympy.Matrix([*_unit(m.ground_joint(driver.link).pair.angle_deg), 0])
    jt = sympy.Matrix.hstack(*cols, drive)
    total = loads.get(driver.link, sympy.zeros(3, 1)) + carried.get(driver.link, sympy.zeros(3, 1))
    return rows, jt.LUsolve(-total), u


def _solve(jac: sympy.Matrix, rhs: sympy.Matrix, plan: SolvePlan, step: GroupStep) -> sympy.Matrix:
    """``jac·x = rhs`` for a group at the sketch.

    Raises
    ------
    SingularPoseError
        The group's Jacobian is singular at the sketch (a dead point).
    """
    try:
        if jac.rows == jac.cols:
            return jac.LUsolve(rhs)
        solution, params = jac.gauss_jordan_solve(rhs)  # a redundant link: consistent rows
    except NonInvertibleMatrixError:
        raise SingularPoseError.at(
            step.label, np.zeros(len(plan.drivers)), "exactly singular", plan.driver_kinds
        ) from None
    return solution.subs({p: 0 for p in params})
