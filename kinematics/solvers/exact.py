"""Exact velocities, accelerations and forces at the sketch pose, in one number field.

At the sketch every link is at ``q = 0``, so the pair Jacobians are built
from the sketch coordinates alone; when those are exact (decimals, fractions,
``0.2*sqrt(3)``) the group-by-group linear solves are exact too. The drivers'
speeds may stay symbols: ``symbolic=True`` gives ω3 = ω1/2 for the exam's
slotted link rather than a number.

Every number of the data (coordinates, the cosines and sines of the slide
angles, speeds, loads) is an element of one number field K — ``QQ``,
``QQ<sqrt(3)>``, ``QQ<sqrt(3) + sqrt(7)>`` — that sympy's
:func:`~sympy.polys.constructor.construct_domain` builds once; every solve is
a linear solve over K (sympy's ``DomainMatrix``), so no expression grows and
nothing is simplified: the answers come out in K's canonical form
(``-1/2 + 5*sqrt(3)/3``). Symbolic speeds are the generators of the
polynomial ring ``K[omega_1, epsilon_1]``.

The work has a time limit (``timeout`` seconds, :data:`EXACT_TIMEOUT` by
default): past it, :class:`~kinematics.errors.ExactTimeoutError` names what
was being worked on and how to raise the limit. The clock is read between
steps and, on the main thread where the platform has ``SIGALRM``, an alarm
also interrupts a step that runs long.

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

import contextlib
import math
import signal
import threading
import time
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy
from sympy.polys.constructor import construct_domain
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError

from structure.errors import MechanismError
from structure.expressions import exact_float, exact_value
from structure.model import Load, Mechanism

from ..errors import ExactTimeoutError, IndeterminateError, SingularPoseError
from ..kinetostatics.forces import ground_equations
from .equations import Equation, equation_point
from .plan import DriverStep, GroupStep, SolvePlan

__all__ = [
    "EXACT_TIMEOUT",
    "ExactForces",
    "ExactState",
    "ExactTimeoutError",
    "forces_exact",
    "solve_exact",
]

#: the default time limit of one exact answer, in seconds
EXACT_TIMEOUT = 60.0

#: the largest degree of the field of cos θ and sin θ kept exact for a slide angle that sympy
#: does not write in radicals (10° has 6; 5° has 12, and its field takes tens of seconds)
_TRIG_DEGREE = 6


@dataclass(frozen=True)
class ExactState:
    """Exact ``omega``/``epsilon`` per link and ``velocity``/``acceleration`` per point.

    Values are sympy expressions; ``drivers`` maps each driver to its speed
    and acceleration (numbers, or symbols ``omega_1``, ``epsilon_1``).
    ``approximations`` lists the data taken as the rationals of their
    floating-point values because they have no exact form here (a slide at
    70.89° or at 1°: its cosine and sine).
    """

    links: Mapping[str, Mapping[str, sympy.Expr]]
    points: Mapping[str, Mapping[str, tuple[sympy.Expr, sympy.Expr]]]
    drivers: Mapping[str, tuple[sympy.Expr, sympy.Expr]]
    q_dot: Mapping[str, sympy.Matrix]
    q_ddot: Mapping[str, sympy.Matrix]
    approximations: tuple[str, ...] = ()


@dataclass(frozen=True)
class ExactForces:
    """Exact reactions (point, links, kind, force on links[1] by links[0], couple) and balance."""

    reactions: tuple[tuple[str | None, tuple[str, str], str, tuple, sympy.Expr], ...]
    balancing_moment: Mapping[str, sympy.Expr]
    balancing_force: tuple[sympy.Expr, sympy.Expr] | None
    approximations: tuple[str, ...] = ()


# ------------------------------------------------------------------------------ the clock
class _Clock:
    """The time limit of one exact answer, and what the work is on (for the message)."""

    def __init__(self, timeout: float | None) -> None:
        if timeout is not None and not (math.isfinite(timeout) and timeout > 0):
            raise ValueError(f"the time limit must be a positive number of seconds, not {timeout}")
        self.timeout = timeout
        self.end = None if timeout is None else time.monotonic() + timeout
        self.stage = "the number field of the data"
        self.expired = False

    def at(self, stage: str) -> None:
        """Start on ``stage`` (when there is time left)."""
        self.stage = stage
        self.check()

    def check(self) -> None:
        """Raise :class:`ExactTimeoutError` when the time is up."""
        if self.expired or (self.end is not None and time.monotonic() >= self.end):
            self.expired = True
            raise self.error()

    def error(self) -> ExactTimeoutError:
        return ExactTimeoutError(
            f"the exact answer gave up after {self.timeout:g} s, working on {self.stage}; "
            "raise the limit with --exact-timeout SECONDS (timeout= in solve_exact and "
            "forces_exact), or leave out --exact for the numeric answer",
            self.stage,
            self.timeout or 0.0,
        )

    @contextlib.contextmanager
    def running(self) -> Iterator[None]:
        """Interrupt the work at the limit with ``SIGALRM`` where it can be used.

        That is on the main thread of a platform with ``setitimer`` while no
        other interval timer runs; elsewhere :meth:`check` between steps does.
        The alarm repeats every 0.2 s until the work ends, in case a library
        swallows the first exception.
        """
        usable = (
            self.end is not None
            and hasattr(signal, "setitimer")
            and threading.current_thread() is threading.main_thread()
            and signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
        )
        if not usable:
            yield
            return

        def ring(signum, frame) -> None:
            self.expired = True
            raise self.error()

        previous = signal.signal(signal.SIGALRM, ring)
        try:
            signal.setitimer(signal.ITIMER_REAL, max(self.end - time.monotonic(), 1e-3), 0.2)
            yield
        finally:
            try:
                signal.setitimer(signal.ITIMER_REAL, 0.0)
            finally:  # even when the last alarm rings here: the caller's handler back
                signal.signal(signal.SIGALRM, previous)


# ------------------------------------------------------------------------------ the data
def _exact_point(m: Mechanism, name: str | None) -> tuple[sympy.Expr, sympy.Expr]:
    p = m.points[name]  # type: ignore[index]
    x = exact_value(p.exact[0]) if p.exact[0] else exact_float(p.x)
    y = exact_value(p.exact[1]) if p.exact[1] else exact_float(p.y)
    return x, y


def _point_name(m: Mechanism, eq: Equation) -> str | None:
    """The point an equation's pair acts at (a compound hinge's for its canonical pair)."""
    name = equation_point(m, eq)
    if name is None and not eq.pair:
        raise ValueError(f"no compound hinge at {tuple(eq.point)}")
    return name


def _trig_degree(turns: Fraction) -> int:
    """The degree over Q of the field of cos 2πt and sin 2πt (t = ``turns``, in lowest terms)."""
    n = math.lcm(turns.denominator, 4)
    return int(sympy.totient(n)) // 2


def _unit(degrees: float | None, notes: list[str]) -> tuple[sympy.Expr, sympy.Expr]:
    """The exact unit vector of a slide direction.

    An angle of a whole number of degrees, or a simple fraction of one, gives
    radicals (cos 30° = √3/2) or, when sympy has none, cos and sin of a
    rational multiple of π of a small degree (cos 10°); any other angle (1°,
    70.89°) is taken as the exact rationals of its float cosine and sine, and
    a note says so in ``notes``.
    """
    value = exact_float(degrees or 0.0)
    if value.q <= 12:
        t = sympy.pi * value / 180
        c, s = sympy.cos(t), sympy.sin(t)
        radical = not (c.has(sympy.cos, sympy.sin) or s.has(sympy.cos, sympy.sin))
        if radical or _trig_degree(Fraction(int(value.p), 360 * int(value.q))) <= _TRIG_DEGREE:
            return c, s
    rad = math.radians(float(degrees or 0.0))
    note = (
        f"the slide angle {float(degrees or 0.0)!r}°: its cosine and sine are taken as the "
        "rationals of their floating-point values"
    )
    if note not in notes:
        notes.append(note)
    return exact_float(math.cos(rad)), exact_float(math.sin(rad))


class _Field:
    """The number field K of the data, and the ring of the answers (K, or K[speed symbols])."""

    def __init__(self, values: Sequence[sympy.Expr], symbols: Sequence[sympy.Symbol]) -> None:
        unique = list(dict.fromkeys([sympy.Integer(0), sympy.Integer(1), *values]))
        domain, elements = construct_domain(unique, field=True, extension=True)
        self.K = domain
        self.elements = dict(zip(unique, elements, strict=True))
        self.R = domain[tuple(symbols)] if symbols else domain

    def k(self, value: sympy.Expr):
        """``value`` (a number of the data) as an element of K."""
        found = self.elements.get(value)
        return found if found is not None else self.K.from_sympy(value)

    def lift(self, a):
        """An element of K as one of the ring of the answers."""
        return a if self.R is self.K else self.R.convert_from(a, self.K)

    def expr(self, a) -> sympy.Expr:
        """An answer as a sympy expression (a canonical form of K; simplified only in EX)."""
        out = self.R.to_sympy(a)
        return sympy.simplify(out) if self.K.is_EX else out


def _data_values(plan: SolvePlan, notes: list[str]) -> list[sympy.Expr]:
    """Every exact number of the plan's mechanism: coordinates, slide directions, loads."""
    m = plan.mechanism
    values: list[sympy.Expr] = []
    for name in m.points:
        values.extend(_exact_point(m, name))
    for pair in m.pairs:
        if pair.angle_deg is not None:
            values.extend(_unit(pair.angle_deg, notes))
    for load in m.loads:
        if load.kind == "balance":
            values.extend(_unit(load.values[0], notes))
        else:
            values.extend(_load_number(load, k) for k in range(len(load.values)))
    for d in plan.drivers:
        values.extend((exact_float(d.speed), exact_float(d.acceleration)))
    return values


def _load_number(load: Load, k: int) -> sympy.Expr:
    written = load.exact[k] if k < len(load.exact) else None
    return exact_value(written) if written else exact_float(load.values[k])


# ------------------------------------------------------------------------------ the algebra
class _Exact:
    """The exact data of a plan in one field, and its linear algebra there."""

    def __init__(self, plan: SolvePlan, clock: _Clock, symbols: Sequence[sympy.Symbol] = ()):
        self.plan = plan
        self.clock = clock
        self.notes: list[str] = []
        values = _data_values(plan, self.notes)
        clock.at("the number field of the data")
        self.field = _Field(values, symbols)
        self.zero3 = (self.field.R.zero,) * 3

    def point(self, name: str | None) -> tuple:
        """A named point's sketch coordinates in K (the origin for an unnamed one)."""
        m = self.plan.mechanism
        if name is None or name not in m.points:
            return (self.field.K.zero, self.field.K.zero)
        return tuple(self.field.k(v) for v in _exact_point(m, name))

    def unit(self, degrees: float | None) -> tuple:
        return tuple(self.field.k(v) for v in _unit(degrees, self.notes))

    def rows(self, equations: Sequence[Equation]) -> list:
        """(equation, partials of a, partials of b, point, normal) of each equation at q = 0."""
        m = self.plan.mechanism
        K = self.field.K
        zero, one = K.zero, K.one
        out = []
        for eq in equations:
            c = self.point(_point_name(m, eq))
            if eq.kind == "HINGE":
                ja = [[one, zero, -c[1]], [zero, one, c[0]]]
                out.append((eq, ja, [[-x for x in row] for row in ja], c, None))
            elif eq.kind == "ANGLE":
                out.append((eq, [[zero, zero, one]], [[zero, zero, -one]], c, None))
            else:
                pair = m.pair(eq.pair) if eq.pair else None
                u = self.unit(pair.angle_deg if pair is not None else None)
                n = (-u[1], u[0])
                lever = -n[0] * c[1] + n[1] * c[0]
                ja = [[-n[0], -n[1], -lever]]
                out.append((eq, ja, [[n[0], n[1], lever]], c, n))
        return out

    def times(self, part: list, v: tuple) -> list:
        """``part · v``: a block of partials (rows of K) times a link's 3-vector of the ring."""
        lift = self.field.lift
        return [sum((lift(a) * x for a, x in zip(row, v, strict=True)), self.field.R.zero)
                for row in part]  # fmt: skip

    def solver(self, matrix: list[list], label: str):
        """``b ↦ x`` with ``matrix · x = b`` (over the ring), one inverse for every ``b``.

        A square matrix must be regular; another (a redundant link's rows) is
        solved on a largest regular block, the other unknowns 0, and ``b``
        must be consistent.
        """
        K, R = self.field.K, self.field.R
        rows, cols = len(matrix), len(matrix[0]) if matrix else 0
        whole = DomainMatrix(matrix, (rows, cols), K)
        if rows == cols:
            keep_rows, keep_cols = list(range(rows)), list(range(cols))
        else:
            keep_cols = list(whole.rref()[1])
            keep_rows = list(whole.transpose().rref()[1])
        self.clock.check()
        block = DomainMatrix(
            [[matrix[i][j] for j in keep_cols] for i in keep_rows],
            (len(keep_rows), len(keep_cols)),
            K,
        )
        try:
            inverse = block.inv().convert_to(R) if keep_rows else None
        except DMNonInvertibleMatrixError:  # a dead centre, as the numeric solver says it
            raise SingularPoseError.at(
                label, np.zeros(len(self.plan.drivers)), "exactly singular", self.plan.driver_kinds
            ) from None
        full = whole.convert_to(R)

        def solve(b: list) -> list:
            x = [R.zero] * cols
            if inverse is not None:
                part = DomainMatrix([[b[i]] for i in keep_rows], (len(keep_rows), 1), R)
                for j, value in zip(keep_cols, (inverse * part).to_list_flat(), strict=True):
                    x[j] = value
            if rows != cols:
                check = full * DomainMatrix([[v] for v in x], (cols, 1), R)
                if check.to_list_flat() != list(b):
                    raise self.singular(label, "its velocity equations contradict each other")
            self.clock.check()
            return x

        return solve

    def singular(self, label: str, why: str) -> SingularPoseError:
        plan = self.plan
        return SingularPoseError.singular(
            label, np.zeros(len(plan.drivers)), why, plan.driver_kinds
        )


def _bias(kind: str, c: tuple, n, va: tuple, vb: tuple, lift) -> list:
    """The ``(dJ/dt)·q̇`` terms of an equation at the sketch."""
    wa, wb = va[2], vb[2]
    if kind == "ANGLE":
        return [wa - wa]
    cx, cy = lift(c[0]), lift(c[1])
    if kind == "HINGE":
        k = wb**2 - wa**2
        return [k * cx, k * cy]
    nx, ny = lift(n[0]), lift(n[1])
    dx = vb[0] - wb * cy - va[0] + wa * cy
    dy = vb[1] + wb * cx - va[1] - wa * cx
    k = wa**2 - wb**2
    return [2 * wa * (-ny * dx + nx * dy) + k * (nx * cx + ny * cy)]


def _driver_motion(ex: _Exact, plan: SolvePlan, symbols: Sequence[sympy.Symbol]):
    """Each driver's (speed, acceleration) in the ring, and its links' q̇ and q̈."""
    F = ex.field
    R, lift = F.R, F.lift
    qd: dict[str, tuple] = {plan.mechanism.ground: ex.zero3}
    qdd: dict[str, tuple] = {plan.mechanism.ground: ex.zero3}
    motion: dict[str, tuple] = {}
    for k, d in enumerate(plan.drivers):
        if symbols:
            w, e = R.from_sympy(symbols[2 * k]), R.from_sympy(symbols[2 * k + 1])
        else:
            w, e = F.k(exact_float(d.speed)), F.k(exact_float(d.acceleration))
        motion[d.link] = (w, e)
        if d.kind == "R":
            px, py = (lift(v) for v in ex.point(d.point))
            qd[d.link] = (w * py, -w * px, w)  # −ω·J·p, ω
            qdd[d.link] = (e * py + w**2 * px, -e * px + w**2 * py, e)
        else:
            u = tuple(lift(v) for v in ex.unit(plan.mechanism.ground_joint(d.link).pair.angle_deg))
            qd[d.link] = (w * u[0], w * u[1], R.zero)
            qdd[d.link] = (e * u[0], e * u[1], R.zero)
    return motion, qd, qdd


def _kinematics(ex: _Exact, symbols: Sequence[sympy.Symbol] = ()):
    """q̇ and q̈ of every link (in the ring), group by group, and the drivers' motion."""
    plan = ex.plan
    R = ex.field.R
    motion, qd, qdd = _driver_motion(ex, plan, symbols)
    zero = ex.zero3
    for step in plan.steps:
        ex.clock.at(f"group {step.label}")
        index = {link: i for i, link in enumerate(step.links)}
        rows = ex.rows(step.equations)
        size = sum(eq.size for eq, *_ in rows)
        jac = [[ex.field.K.zero] * (3 * len(index)) for _ in range(size)]
        rhs_v: list = []
        rhs_a: list = []
        r = 0
        for eq, ja, jb, _, _ in rows:
            known_v = [R.zero] * eq.size
            known_a = [R.zero] * eq.size
            for link, part in ((eq.a, ja), (eq.b, jb)):
                if link in index:
                    for i, row in enumerate(part):
                        jac[r + i][3 * index[link] : 3 * index[link] + 3] = row
                else:
                    known_v = [x + y for x, y in zip(known_v, ex.times(part, qd.get(link, zero)),
                                                     strict=True)]  # fmt: skip
                    known_a = [x + y for x, y in zip(known_a, ex.times(part, qdd.get(link, zero)),
                                                     strict=True)]  # fmt: skip
            rhs_v.extend(-x for x in known_v)
            rhs_a.extend(-x for x in known_a)
            r += eq.size
        solve = ex.solver(jac, step.label)
        z_dot = solve(rhs_v)
        for link, i in index.items():
            qd[link] = tuple(z_dot[3 * i : 3 * i + 3])
        r = 0
        for eq, _, _, c, n in rows:
            bias = _bias(eq.kind, c, n, qd.get(eq.a, zero), qd.get(eq.b, zero), ex.field.lift)
            for i, value in enumerate(bias):
                rhs_a[r + i] -= value
            r += eq.size
        z_ddot = solve(rhs_a)
        for link, i in index.items():
            qdd[link] = tuple(z_ddot[3 * i : 3 * i + 3])
    return motion, qd, qdd


def _speed_symbols(plan: SolvePlan) -> list[sympy.Symbol]:
    """``omega_k, epsilon_k`` (a turning driver) or ``v_k, a_k`` (a sliding one), k from 1."""
    out = []
    for k, d in enumerate(plan.drivers, start=1):
        names = ("omega", "epsilon") if d.kind == "R" else ("v", "a")
        out.extend((sympy.Symbol(f"{names[0]}_{k}"), sympy.Symbol(f"{names[1]}_{k}")))
    return out


def _check_sketch_pose(plan: SolvePlan) -> None:
    """Exact values are at the sketch's pose: a plan that flips a dyad is not at it."""
    if plan.flip:
        raise ValueError(
            "exact values are at the sketch's assembly: the plan flips "
            f"{', '.join(sorted(plan.flip))} (make the plan without flip=)"
        )


def _no_designed_cam(plan: SolvePlan) -> None:
    """Refuse a designed cam by name: its motion has no exact form here."""
    if plan.cams:
        raise MechanismError(
            f"{plan.cams[0].label} has the profile of its program: its curvature and motion are "
            "computed in floating point, with no exact form here; solve without --exact"
        )


def _no_friction(plan: SolvePlan) -> None:
    """Refuse rough pairs by name: the exact reactions leave friction out."""
    rough = [p.label for p in plan.mechanism.pairs if p.friction or p.circle]
    if rough:
        raise MechanismError(
            f"the exact reactions leave friction out, and pair(s) {', '.join(rough)} have it "
            "(friction= or circle=): drop --exact for the reactions with friction"
        )


def solve_exact(
    plan: SolvePlan, symbolic: bool = False, timeout: float | None = EXACT_TIMEOUT
) -> ExactState:
    """Exact ω, ε of every link and v, a of every named point at the sketch pose.

    Parameters
    ----------
    plan : SolvePlan
        The plan of a mechanism whose sketch is the pose (no ``flip``).
    symbolic : bool
        Keep each driver's speed and acceleration as symbols (``omega_1``,
        ``epsilon_1``; ``v_1``, ``a_1`` for a sliding driver).
    timeout : float or None
        The time limit in seconds (None: none).

    Raises
    ------
    ExactTimeoutError
        Past ``timeout``: it names the group being solved.
    SingularPoseError
        A group's Jacobian is singular at the sketch.
    ValueError
        A plan with ``flip`` (the sketch is not its pose).
    """
    _no_designed_cam(plan)
    _check_sketch_pose(plan)
    clock = _Clock(timeout)
    with clock.running():
        symbols = _speed_symbols(plan) if symbolic else []
        ex = _Exact(plan, clock, symbols)
        motion, qd, qdd = _kinematics(ex, symbols)
        clock.at("writing the answers")
        return _state(ex, motion, qd, qdd)


def _state(ex: _Exact, motion: Mapping, qd: Mapping, qdd: Mapping) -> ExactState:
    """The answers as sympy expressions."""
    m = ex.plan.mechanism
    F = ex.field
    expr, lift = F.expr, F.lift
    links = {
        name: {"omega": expr(qd[name][2]), "epsilon": expr(qdd[name][2])}
        for name in m.moving_links
        if name in qd
    }
    points = {}
    for name, (link, _) in ex.plan.points.items():
        cx, cy = (lift(v) for v in ex.point(name))
        v, a = qd.get(link, ex.zero3), qdd.get(link, ex.zero3)
        vel = (v[0] - v[2] * cy, v[1] + v[2] * cx)
        acc = (a[0] - a[2] * cy - v[2] ** 2 * cx, a[1] + a[2] * cx - v[2] ** 2 * cy)
        points[name] = {
            "velocity": (expr(vel[0]), expr(vel[1])),
            "acceleration": (expr(acc[0]), expr(acc[1])),
        }
    drivers = {link: (expr(w), expr(e)) for link, (w, e) in motion.items()}
    q_dot = {link: sympy.Matrix([expr(x) for x in q]) for link, q in qd.items()}
    q_ddot = {link: sympy.Matrix([expr(x) for x in q]) for link, q in qdd.items()}
    return ExactState(links, points, drivers, q_dot, q_ddot, tuple(ex.notes))


# ------------------------------------------------------------------------------ forces
def _exact_loads(ex: _Exact, qd: Mapping, qdd: Mapping) -> dict[str, list]:
    """Exact generalized loads (Fx, Fy, moment about the world origin) per link at the sketch."""
    m = ex.plan.mechanism
    F = ex.field
    out: dict[str, list] = {}
    gravity = (F.K.zero, F.K.zero)

    def number(load: Load, k: int):
        return F.k(_load_number(load, k))

    for load in m.loads:
        if load.kind == "gravity":
            gravity = (number(load, 0), number(load, 1))

    def add(link: str, value: Sequence) -> None:
        total = out.get(link, [F.K.zero] * 3)
        out[link] = [x + y for x, y in zip(total, value, strict=True)]

    for load in m.loads:
        if load.kind == "force":
            cx, cy = ex.point(load.point)
            fx, fy = number(load, 0), number(load, 1)
            add(load.link, (fx, fy, cx * fy - cy * fx))
        elif load.kind == "moment":
            add(load.link, (F.K.zero, F.K.zero, number(load, 0)))
        elif load.kind == "mass":
            mass, inertia = number(load, 0), number(load, 1)
            cx, cy = ex.point(load.point)
            v, a = qd[load.link], qdd[load.link]
            ax = a[0] - a[2] * cy - v[2] ** 2 * cx
            ay = a[1] + a[2] * cx - v[2] ** 2 * cy
            fx, fy = mass * (gravity[0] - ax), mass * (gravity[1] - ay)
            add(load.link, (fx, fy, cx * fy - cy * fx - inertia * a[2]))
    return out


def _reactions(ex: _Exact, rows: list, lam: Sequence) -> list:
    """Each pair's reaction on its link b from the multipliers ``lam`` of its rows."""
    expr = ex.field.expr
    out = []
    couple = ex.field.K.zero
    r = 0
    for eq, _, jb, _, _ in rows:
        value = lam[r : r + eq.size]
        r += eq.size
        on_b = [sum((jb[i][j] * value[i] for i in range(eq.size)), ex.field.K.zero)
                for j in range(3)]  # fmt: skip
        if eq.kind == "HINGE":
            out.append((eq, (eq.a, eq.b), "R", (expr(on_b[0]), expr(on_b[1])), sympy.Integer(0)))
        elif eq.kind == "ANGLE":
            couple = on_b[2]
        else:
            out.append((eq, (eq.a, eq.b), "P", (expr(on_b[0]), expr(on_b[1])), expr(couple)))
            couple = ex.field.K.zero
    return out


def forces_exact(plan: SolvePlan, timeout: float | None = EXACT_TIMEOUT) -> ExactForces:
    """Exact reactions and balancing moment at the sketch pose.

    See :mod:`kinematics.kinetostatics.forces`; ``timeout`` as in :func:`solve_exact`.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan
    >>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0",
    ...                     "point B 0.1 0.1", "force 1 B 0 -100"])
    >>> forces_exact(make_plan(analyze(m))).balancing_moment["1"]
    10

    Raises
    ------
    MechanismError
        A redundant link: the reactions are indeterminate (an
        :class:`IndeterminateError`); a pair with friction, which the exact
        solution does not take; the others of :func:`solve_exact`.
    """
    if any(s.group is None for s in plan.steps):
        raise IndeterminateError("the mechanism is over-constrained: reactions are indeterminate")
    _no_designed_cam(plan)
    _no_friction(plan)
    _check_sketch_pose(plan)
    clock = _Clock(timeout)
    with clock.running():
        ex = _Exact(plan, clock)
        _, qd, qdd = _kinematics(ex)
        clock.at("the loads")
        loads = _exact_loads(ex, qd, qdd)
        carried: dict[str, list] = {}
        reactions = []
        for step in reversed(plan.steps):
            clock.at(f"the reactions of group {step.label}")
            reactions.extend(_group_reactions(ex, step, loads, carried))
        moments: dict[str, sympy.Expr] = {}
        balancing_force = None
        balance = {x.link: x for x in plan.mechanism.loads if x.kind == "balance"}
        for d in plan.drivers:
            clock.at(f"the balance of driver {d.link}")
            load = balance.get(d.link)
            rows, lam, direction = _driver_balance(ex, d, load, loads, carried)
            reactions.extend(_reactions(ex, rows, lam[:-1]))
            if direction is not None:
                balancing_force = (
                    ex.field.expr(lam[-1] * direction[0]),
                    ex.field.expr(lam[-1] * direction[1]),
                )
            else:
                moments[d.link] = ex.field.expr(lam[-1])
        m = plan.mechanism
        out = tuple(
            (_point_name(m, eq), links, kind, force, couple)
            for eq, links, kind, force, couple in reactions
        )
        return ExactForces(out, moments, balancing_force, tuple(ex.notes))


def _group_reactions(
    ex: _Exact, step: GroupStep, loads: Mapping[str, list], carried: dict[str, list]
) -> list:
    """A group's exact reactions, ``Jᵀ·λ = −Q``; its reactions on known links go to ``carried``."""
    K = ex.field.K
    rows = ex.rows(step.equations)
    index = {link: i for i, link in enumerate(step.links)}
    size = sum(eq.size for eq, *_ in rows)
    jt = [[K.zero] * size for _ in range(3 * len(index))]
    r = 0
    for eq, ja, jb, _, _ in rows:
        for link, part in ((eq.a, ja), (eq.b, jb)):
            if link in index:
                for i, row in enumerate(part):
                    for j, value in enumerate(row):
                        jt[3 * index[link] + j][r + i] = value
        r += eq.size
    rhs = []
    for link in index:
        total = _sum3(K, loads.get(link), carried.get(link))
        rhs.extend(-x for x in total)
    lam = ex.solver(jt, step.label)(rhs)
    r = 0
    for eq, ja, jb, _, _ in rows:
        value = lam[r : r + eq.size]
        for link, part in ((eq.a, ja), (eq.b, jb)):
            if link not in index:
                force = [sum((part[i][j] * value[i] for i in range(eq.size)), K.zero)
                         for j in range(3)]  # fmt: skip
                carried[link] = _sum3(K, carried.get(link), force)
        r += eq.size
    return _reactions(ex, rows, lam)


def _sum3(K, *vectors: Sequence | None) -> list:
    out = [K.zero] * 3
    for v in vectors:
        if v is not None:
            out = [x + y for x, y in zip(out, v, strict=True)]
    return out


def _driver_balance(
    ex: _Exact,
    driver: DriverStep,
    load: Load | None,
    loads: Mapping[str, list],
    carried: Mapping[str, list],
) -> tuple[list, list, tuple | None]:
    """A driver's exact equilibrium: its ground pair's rows, the multipliers (balancing load
    last) and the direction of a ``balance`` statement's force (None for the motor's)."""
    K = ex.field.K
    m = ex.plan.mechanism
    rows = ex.rows(ground_equations(ex.plan, driver.link))
    columns = [list(row) for _, ja, _, _, _ in rows for row in ja]  # the columns of Jᵀ
    u = None
    if load is not None:
        u = ex.unit(load.values[0])
        cx, cy = ex.point(load.point)
        drive = [u[0], u[1], cx * u[1] - cy * u[0]]
    elif driver.kind == "R":
        drive = [K.zero, K.zero, K.one]
    else:
        slide = ex.unit(m.ground_joint(driver.link).pair.angle_deg)
        drive = [slide[0], slide[1], K.zero]
    columns.append(drive)
    jt = [[col[i] for col in columns] for i in range(3)]
    total = _sum3(K, loads.get(driver.link), carried.get(driver.link))
    lam = ex.solver(jt, f"I({driver.link})")([-x for x in total])
    return rows, lam, u
