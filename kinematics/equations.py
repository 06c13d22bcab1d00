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

A GEAR equation involves three links; the group solver handles it itself
(:func:`evaluate` covers the two-link pairs).

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

import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Equation", "evaluate", "rotate", "rotate_many"]


def rotate(theta: float, v: np.ndarray) -> np.ndarray:
    """``R(θ)·v`` for one angle."""
    c, s = math.cos(theta), math.sin(theta)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def rotate_many(theta: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``R(θ_k)·v`` for an array of angles (shape (N,)); ``v`` shape (2,) or (N, 2)."""
    c, s = np.cos(theta), np.sin(theta)
    vx, vy = (v[..., 0], v[..., 1])
    return np.stack([c * vx - s * vy, s * vx + c * vy], axis=-1)


def _perp(v: np.ndarray) -> np.ndarray:
    """``J·v``: v turned by +90°."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.einsum("...i,...i->...", a, b)


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


def evaluate(
    eq: Equation, qa: np.ndarray, qb: np.ndarray, va: np.ndarray, vb: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(Φ, ∂Φ/∂q_a, ∂Φ/∂q_b, (dJ/dt)·q̇)`` for poses ``qa, qb`` (N, 3), velocities ``va, vb``.

    Shapes: Φ and the bias (N, size), the partials (N, size, 3).
    """
    n = qa.shape[0]
    if eq.kind == "GEAR":
        raise ValueError("a GEAR equation involves three links: see kinematics.solve._system")
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
        ja = np.concatenate([eye, _perp(ra)[:, :, None]], axis=2)
        jb = -np.concatenate([eye, _perp(rb)[:, :, None]], axis=2)
        bias = -(wa**2) * ra + wb**2 * rb
        return pa - pb, ja, jb, bias
    # SLIDE: the guide turns with link a
    nrm = rotate_many(qa[:, 2], eq.normal)
    jn = _perp(nrm)
    d = pb - pa
    phi = _dot(nrm, d)[:, None]
    ja = np.stack([-nrm[:, 0], -nrm[:, 1], _dot(jn, d) - _dot(nrm, _perp(ra))], axis=1)[:, None]
    jb = np.stack([nrm[:, 0], nrm[:, 1], _dot(nrm, _perp(rb))], axis=1)[:, None]
    d_dot = vb[:, :2] + wb * _perp(rb) - va[:, :2] - wa * _perp(ra)
    w_a, w_b = wa[:, 0], wb[:, 0]
    bias = (
        -(w_a**2) * _dot(nrm, d)
        + 2.0 * w_a * _dot(jn, d_dot)
        + _dot(nrm, -(w_b[:, None] ** 2) * rb + (w_a[:, None] ** 2) * ra)
    )[:, None]
    return phi, ja, jb, bias
