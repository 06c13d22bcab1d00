"""Constraint equations of the lower pairs, with their Jacobians and velocity terms.

Every link carries a frame that coincides with the world frame at the sketch
pose, so a point of the sketch at ``c`` sits at ``x_L + R(θ_L)·c`` when link
``L`` is at ``(x_L, y_L, θ_L)``; the sketch is ``q = 0`` for every link.

======  ====  ===============================================================
kind    rows  equation
======  ====  ===============================================================
HINGE   2     p_a − p_b = 0, p_L = x_L + R(θ_L)·c (the pin on both links)
ANGLE   1     θ_a − θ_b = 0 (a prismatic pair locks the relative rotation)
SLIDE   1     (R(θ_a)·n)·(p_b − p_a) = 0 (n ⊥ the slide direction at the sketch)
GEAR    1     (θ_a − θ_c) + k·(θ_b − θ_c) = 0: gears a, b rolling on each other,
              their axes on the carrier c; k = ±z_b/z_a (+ external, − internal)
======  ====  ===============================================================

A GEAR equation involves three links; :func:`group_system` handles it itself
(:func:`evaluate` covers the two-link pairs). :func:`group_system` stacks the
equations of a group into its residual, Jacobian and velocity terms;
:func:`group_residual` gives the residual alone, each link's rotation computed
once (what a Newton iteration with a kept Jacobian needs).

:func:`evaluate` gives, for many poses at once (arrays with a leading pose
axis), the residual Φ, the partial derivatives with respect to ``(x, y, θ)``
of each link, and the term ``(dJ/dt)·q̇`` of the acceleration equation
``J·q̈ = −(dJ/dt)·q̇``, which holds the centripetal and Coriolis parts.

>>> import numpy as np
>>> eq = Equation("HINGE", "1", "2", np.array([1.0, 0.0]))
>>> z = np.zeros((1, 3))
>>> phi, ja, jb, bias = evaluate(eq, z, z, z, z)
>>> phi.tolist(), (ja[0] + 0.0).tolist()
([[0.0, 0.0]], [[1.0, 0.0, 0.0], [0.0, 1.0, 1.0]])
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from structure.model import Mechanism

from .planar import dot, perpendicular, rotate, rotate_many

# rotate and rotate_many live in kinematics.solvers.planar; they stay importable from here
__all__ = [
    "Equation",
    "equation_point",
    "evaluate",
    "group_residual",
    "group_system",
    "rotate",
    "rotate_many",
    "slide_equations",
]


@dataclass(frozen=True)
class Equation:
    """One pair's equation between links ``a`` and ``b`` (``b`` may be the ground).

    ``point`` is the sketch location of the pin or of the slide's reference
    point; ``normal`` the unit normal of the slide at the sketch (SLIDE only).
    """

    kind: str
    a: str
    b: str
    point: np.ndarray = field(default_factory=lambda: np.zeros(2))
    normal: np.ndarray = field(default_factory=lambda: np.zeros(2))
    pair: int = 0  # the mechanism's pair it comes from (0: a compound hinge's canonical pair)
    carrier: str = ""  # GEAR: the link that carries both gears' axes
    ratio: float = 0.0  # GEAR: k = ±z_b/z_a

    @property
    def size(self) -> int:
        return 2 if self.kind == "HINGE" else 1


def slide_equations(
    a: str, b: str, point: np.ndarray, direction: np.ndarray, pair: int
) -> tuple[Equation, Equation]:
    """A prismatic pair's two equations: ANGLE, then SLIDE along ``direction`` (sketch, unit)."""
    return (
        Equation("ANGLE", a, b, pair=pair),
        Equation("SLIDE", a, b, point, perpendicular(direction), pair),
    )


def equation_point(mechanism: Mechanism, eq: Equation) -> str | None:
    """The name of the point where an equation's pair acts.

    That is its pair's point; for a compound hinge's canonical pair
    (``eq.pair`` 0) the hinge whose sketch point is the equation's, None if
    there is none.
    """
    if eq.pair:
        return mechanism.pair(eq.pair).point
    x, y = float(eq.point[0]), float(eq.point[1])
    for h in mechanism.compound_hinges.values():
        p = mechanism.points.get(h.point)
        if p is not None and (p.x, p.y) == (x, y):
            return h.point
    return None


def evaluate(
    eq: Equation, qa: np.ndarray, qb: np.ndarray, va: np.ndarray, vb: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(Φ, ∂Φ/∂q_a, ∂Φ/∂q_b, (dJ/dt)·q̇)`` for poses ``qa, qb`` (N, 3), velocities ``va, vb``.

    Shapes: Φ and the bias (N, size), the partials (N, size, 3).
    """
    n = qa.shape[0]
    if eq.kind == "GEAR":
        raise ValueError("a GEAR equation involves three links: see group_system")
    if eq.kind == "ANGLE":
        phi = (qa[:, 2] - qb[:, 2])[:, None]
        ja = np.broadcast_to(np.array([[[0.0, 0.0, 1.0]]]), (n, 1, 3))
        jb = np.broadcast_to(np.array([[[0.0, 0.0, -1.0]]]), (n, 1, 3))
        return phi, ja, jb, np.zeros((n, 1))
    ra = rotate_many(qa[:, 2], eq.point)
    rb = rotate_many(qb[:, 2], eq.point)
    pa = qa[:, :2] + ra
    pb = qb[:, :2] + rb
    wa, wb = va[:, 2:3], vb[:, 2:3]
    if eq.kind == "HINGE":
        eye = np.broadcast_to(np.eye(2), (n, 2, 2))
        ja = np.concatenate([eye, perpendicular(ra)[:, :, None]], axis=2)
        jb = -np.concatenate([eye, perpendicular(rb)[:, :, None]], axis=2)
        bias = -(wa**2) * ra + wb**2 * rb
        return pa - pb, ja, jb, bias
    # SLIDE: the guide turns with link a
    nrm = rotate_many(qa[:, 2], eq.normal)
    jn = perpendicular(nrm)
    d = pb - pa
    phi = dot(nrm, d)[:, None]
    lever_a = dot(jn, d) - dot(nrm, perpendicular(ra))
    ja = np.stack([-nrm[:, 0], -nrm[:, 1], lever_a], axis=1)[:, None]
    jb = np.stack([nrm[:, 0], nrm[:, 1], dot(nrm, perpendicular(rb))], axis=1)[:, None]
    d_dot = vb[:, :2] + wb * perpendicular(rb) - va[:, :2] - wa * perpendicular(ra)
    w_a, w_b = wa[:, 0], wb[:, 0]
    bias = (
        -(w_a**2) * dot(nrm, d)
        + 2.0 * w_a * dot(jn, d_dot)
        + dot(nrm, -(w_b[:, None] ** 2) * rb + (w_a[:, None] ** 2) * ra)
    )[:, None]
    return phi, ja, jb, bias


def group_system(
    links: tuple[str, ...],
    equations: tuple[Equation, ...],
    q: Mapping[str, np.ndarray],
    v: Mapping[str, np.ndarray],
    n: int,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A group's residual (N, m), Jacobian (N, m, 3·links), known-link terms J_k·v_k, (dJ/dt)·v.

    ``links`` are the group's unknown links (their columns of the Jacobian, in
    order); the other links an equation touches are known: their poses ``q``
    and rates ``v`` (absent: the ground, at rest) give the known terms.
    """
    index = {link: i for i, link in enumerate(links)}
    m = 3 * len(links)
    rows_total = sum(eq.size for eq in equations)
    zero = np.zeros((n, 3))
    phi = np.zeros((n, rows_total))
    jac = np.zeros((n, rows_total, m))
    known = np.zeros((n, rows_total))
    bias = np.zeros((n, rows_total))
    row = 0
    for eq in equations:
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


def group_residual(
    equations: tuple[Equation, ...], q: Mapping[str, np.ndarray], n: int
) -> np.ndarray:
    """A group's residual Φ (N, rows) alone, the same equations as :func:`group_system`."""
    turns: dict[str, tuple] = {}

    def turn(link: str) -> tuple:
        found = turns.get(link)
        if found is None:
            pose = q.get(link)
            if pose is None:  # the ground, at rest
                found = turns[link] = (None, 1.0, 0.0)
            else:
                found = turns[link] = (pose, np.cos(pose[:, 2]), np.sin(pose[:, 2]))
        return found

    def place(link: str, c: np.ndarray) -> tuple:
        pose, cos, sin = turn(link)
        cx, cy = float(c[0]), float(c[1])
        if pose is None:
            return cx, cy
        return pose[:, 0] + (cos * cx - sin * cy), pose[:, 1] + (sin * cx + cos * cy)

    rows = sum(eq.size for eq in equations)
    phi = np.zeros((n, rows))
    row = 0
    for eq in equations:
        if eq.kind == "GEAR":
            coefficients = ((eq.a, 1.0), (eq.b, eq.ratio), (eq.carrier, -1.0 - eq.ratio))
            for link, k in coefficients:
                if link in q:
                    phi[:, row] += k * q[link][:, 2]
        elif eq.kind == "ANGLE":
            phi[:, row] = q[eq.a][:, 2] if eq.a in q else 0.0
            if eq.b in q:
                phi[:, row] -= q[eq.b][:, 2]
        elif eq.kind == "HINGE":
            ax, ay = place(eq.a, eq.point)
            bx, by = place(eq.b, eq.point)
            phi[:, row] = ax - bx
            phi[:, row + 1] = ay - by
        else:  # SLIDE: (R(θa)·n)·(p_b − p_a)
            _, cos, sin = turn(eq.a)
            nx, ny = float(eq.normal[0]), float(eq.normal[1])
            ax, ay = place(eq.a, eq.point)
            bx, by = place(eq.b, eq.point)
            phi[:, row] = (cos * nx - sin * ny) * (bx - ax) + (sin * nx + cos * ny) * (by - ay)
        row += eq.size
    return phi
