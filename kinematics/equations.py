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
======  ====  ===============================================================

For each equation :func:`evaluate` gives the residual Φ, the partial
derivatives with respect to ``(x, y, θ)`` of each link, and the term
``(dJ/dt)·q̇`` of the acceleration equation ``J·q̈ = −(dJ/dt)·q̇``, which holds
the centripetal and Coriolis parts.

>>> import numpy as np
>>> eq = Equation("HINGE", "1", "2", np.array([1.0, 0.0]))
>>> phi, ja, jb, bias = evaluate(eq, np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3))
>>> phi.tolist(), ja.tolist()
([0.0, 0.0], [[1.0, 0.0, 0.0], [0.0, 1.0, 1.0]])
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Equation", "evaluate", "rotate"]

_J = np.array([[0.0, -1.0], [1.0, 0.0]])


def rotate(theta: float, v: np.ndarray) -> np.ndarray:
    """``R(θ)·v``."""
    c, s = math.cos(theta), math.sin(theta)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


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

    @property
    def size(self) -> int:
        return 2 if self.kind == "HINGE" else 1


def evaluate(
    eq: Equation, qa: np.ndarray, qb: np.ndarray, va: np.ndarray, vb: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(Φ, ∂Φ/∂q_a, ∂Φ/∂q_b, (dJ/dt)·q̇)`` at poses ``qa, qb`` and velocities ``va, vb``."""
    c = eq.point
    if eq.kind == "ANGLE":
        phi = np.array([qa[2] - qb[2]])
        return phi, np.array([[0.0, 0.0, 1.0]]), np.array([[0.0, 0.0, -1.0]]), np.zeros(1)
    ra = rotate(qa[2], c)
    rb = rotate(qb[2], c)
    pa = qa[:2] + ra
    pb = qb[:2] + rb
    if eq.kind == "HINGE":
        phi = pa - pb
        ja = np.column_stack([np.eye(2), _J @ ra])
        jb = -np.column_stack([np.eye(2), _J @ rb])
        bias = -(va[2] ** 2) * ra + vb[2] ** 2 * rb
        return phi, ja, jb, bias
    # SLIDE: the guide turns with link a
    n = rotate(qa[2], eq.normal)
    jn = _J @ n
    d = pb - pa
    phi = np.array([n @ d])
    ja = np.array([[-n[0], -n[1], jn @ d - n @ (_J @ ra)]])
    jb = np.array([[n[0], n[1], n @ (_J @ rb)]])
    d_dot = vb[:2] + vb[2] * (_J @ rb) - va[:2] - va[2] * (_J @ ra)
    bias = np.array(
        [
            -(va[2] ** 2) * (n @ d)
            + 2.0 * va[2] * (jn @ d_dot)
            + n @ (-(vb[2] ** 2) * rb + va[2] ** 2 * ra)
        ]
    )
    return phi, ja, jb, bias
