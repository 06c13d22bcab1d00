"""Positions, velocities and accelerations at a pose, group by group from the drivers.

Each link's state is ``(x, y, θ)``: the displacement and rotation of its frame
from the sketch pose (where every link is at ``(0, 0, 0)``). The drivers are
placed from their input; then each Assur group, in solve order, is

* positioned by Newton's method on its own equations, started from the
  previous pose (the sketch by default), which keeps the sketch's assembly
  mode;
* given its velocities from ``J_g·q̇_g = −J_k·q̇_k`` (``k``: the known links its
  external pairs touch);
* given its accelerations from ``J_g·q̈_g = −J_k·q̈_k − (dJ/dt)·q̇``.

A group that cannot be assembled raises :class:`AssemblyError`; one whose
Jacobian loses rank (a dead centre) raises :class:`SingularPoseError`. Both
name the group and the input; nothing is returned as NaN.

>>> from structure.edgelist import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.plan import make_plan
>>> m = parse_edgelist(["driver 1 omega=20", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 0.1", "point C 0.4 0.1", "point D 0.4 -0.3"])
>>> state = solve_pose(make_plan(analyze(m)))
>>> round(state.links["3"].omega, 12), round(state.links["2"].omega, 12)
(5.0, 0.0)
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from structure.errors import MechanismError

from .equations import evaluate, rotate
from .plan import GroupStep, SolvePlan

__all__ = [
    "AssemblyError",
    "KinematicState",
    "LinkState",
    "PointState",
    "SingularPoseError",
    "solve_pose",
]

_J = np.array([[0.0, -1.0], [1.0, 0.0]])
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


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.flags.writeable = False
    return a


def _place_drivers(
    plan: SolvePlan, inputs: tuple[float, ...], q: dict, qd: dict, qdd: dict
) -> None:
    for d, value in zip(plan.drivers, inputs, strict=True):
        if d.kind == "R":
            # turn by `value` about the pivot: x = c − R(φ)·c keeps the pivot in place
            q[d.link] = np.array([*(d.pivot - rotate(value, d.pivot)), value])
            r = rotate(value, d.pivot)
            qd[d.link] = np.array([*(-d.speed * (_J @ r)), d.speed])
            qdd[d.link] = np.array([*(-d.acceleration * (_J @ r) + d.speed**2 * r), d.acceleration])
        else:
            q[d.link] = np.array([*(value * d.direction), 0.0])
            qd[d.link] = np.array([*(d.speed * d.direction), 0.0])
            qdd[d.link] = np.array([*(d.acceleration * d.direction), 0.0])


def _system(
    step: GroupStep,
    q: dict,
    qd: dict,
    index: dict[str, int],
    zero: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Residual, group Jacobian, known-link velocity terms and (dJ/dt)·q̇ of a group."""
    n = 3 * len(step.links)
    phi = np.zeros(n)
    jac = np.zeros((n, n))
    known = np.zeros(n)
    bias = np.zeros(n)
    row = 0
    for eq in step.equations:
        qa, qb = q.get(eq.a, zero), q.get(eq.b, zero)
        va, vb = qd.get(eq.a, zero), qd.get(eq.b, zero)
        f, ja, jb, g = evaluate(eq, qa, qb, va, vb)
        rows = slice(row, row + eq.size)
        phi[rows] = f
        bias[rows] = g
        for link, part, v in ((eq.a, ja, va), (eq.b, jb, vb)):
            k = index.get(link)
            if k is None:
                known[rows] += part @ v
            else:
                jac[rows, 3 * k : 3 * k + 3] += part
        row += eq.size
    return phi, jac, known, bias


def _scaled(jac: np.ndarray, length: float) -> np.ndarray:
    scaled = jac.copy()
    scaled[:, 2::3] /= length
    return scaled


def _solve_group(step: GroupStep, plan: SolvePlan, q: dict, inputs: tuple[float, ...]) -> None:
    index = {link: i for i, link in enumerate(step.links)}
    zero = np.zeros(3)
    tol = 1e-13 * plan.length
    for _ in range(_MAX_NEWTON):
        phi, jac, _, _ = _system(step, q, {}, index, zero)
        norm = float(np.linalg.norm(phi))
        if norm <= tol:
            break
        try:
            dz = np.linalg.lstsq(_scaled(jac, plan.length), -phi, rcond=None)[0]
        except np.linalg.LinAlgError as exc:  # pragma: no cover - lstsq rarely fails
            raise AssemblyError(str(exc), step.label, inputs) from exc
        dz[2::3] /= plan.length
        step_size = 1.0
        base = {link: q[link].copy() for link in step.links}
        while True:
            for link, i in index.items():
                q[link] = base[link] + step_size * dz[3 * i : 3 * i + 3]
            trial = float(np.linalg.norm(_system(step, q, {}, index, zero)[0]))
            if trial < norm or step_size < 1e-6:
                break
            step_size /= 2
    else:
        raise AssemblyError(
            f"group {step.label} cannot be assembled at input {_fmt(inputs)}: its pairs do not "
            f"close (residual {norm:.3g} m after {_MAX_NEWTON} Newton steps)",
            step.label,
            inputs,
        )
    phi, jac, _, _ = _system(step, q, {}, index, zero)
    if float(np.linalg.norm(phi)) > 1e-9 * plan.length:
        raise AssemblyError(
            f"group {step.label} cannot be assembled at input {_fmt(inputs)}",
            step.label,
            inputs,
        )
    s = np.linalg.svd(_scaled(jac, plan.length), compute_uv=False)
    if s[-1] <= _SINGULAR * s[0]:
        raise SingularPoseError(
            f"group {step.label} is at a dead centre at input {_fmt(inputs)}: its Jacobian "
            f"loses rank (σ_min/σ_max = {s[-1] / s[0]:.2g}; transmission angle 0° or 180°)",
            step.label,
            inputs,
        )


def _fmt(inputs: tuple[float, ...]) -> str:
    return ", ".join(f"{x:.6g}" for x in inputs)


def solve_pose(
    plan: SolvePlan,
    inputs: tuple[float, ...] | None = None,
    guess: Mapping[str, np.ndarray] | None = None,
) -> KinematicState:
    """Positions, velocities and accelerations at one input.

    ``inputs`` holds one value per driver: its rotation (rad) or displacement
    (m) from the sketch pose; default the sketch itself. ``guess`` holds link
    poses to start Newton from (a previous pose in a sweep).

    Raises
    ------
    AssemblyError
        A group does not close at this input.
    SingularPoseError
        A group is at a dead centre.
    """
    inputs = tuple(0.0 for _ in plan.drivers) if inputs is None else tuple(inputs)
    m = plan.mechanism
    zero = np.zeros(3)
    q: dict[str, np.ndarray] = {m.ground: zero}
    qd: dict[str, np.ndarray] = {m.ground: zero}
    qdd: dict[str, np.ndarray] = {m.ground: zero}
    _place_drivers(plan, inputs, q, qd, qdd)
    for step in plan.steps:
        for link in step.links:
            q[link] = np.array(guess[link], dtype=float) if guess and link in guess else zero.copy()
        _solve_group(step, plan, q, inputs)
        index = {link: i for i, link in enumerate(step.links)}
        _, jac, known_v, _ = _system(step, q, qd, index, zero)
        z_dot = np.linalg.solve(jac, -known_v)
        for link, i in index.items():
            qd[link] = z_dot[3 * i : 3 * i + 3]
        _, _, known_a, _ = _system(step, q, qdd, index, zero)
        _, _, _, bias = _system(step, q, qd, index, zero)
        z_ddot = np.linalg.solve(jac, -known_a - bias)
        for link, i in index.items():
            qdd[link] = z_ddot[3 * i : 3 * i + 3]
    links = {
        link: LinkState(_frozen(q[link]), _frozen(qd[link]), _frozen(qdd[link]))
        for link in m.moving_links
        if link in q
    }
    points = {}
    for name, (link, c) in plan.points.items():
        x, v, a = q.get(link, zero), qd.get(link, zero), qdd.get(link, zero)
        r = rotate(x[2], c)
        points[name] = PointState(
            link,
            _frozen(x[:2] + r),
            _frozen(v[:2] + v[2] * (_J @ r)),
            _frozen(a[:2] + a[2] * (_J @ r) - v[2] ** 2 * r),
        )
    return KinematicState(MappingProxyType(links), MappingProxyType(points), inputs)
