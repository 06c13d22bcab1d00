"""2-D vector helpers, written once: rotations, the +90° turn, cross and dot products, unit vectors.

Vectors are numpy arrays whose last axis holds ``(x, y)``: one vector has
shape (2,), many have shape (N, 2) (or any leading axes). Angles are in
radians, counter-clockwise positive, except where a name says degrees.

>>> import numpy as np
>>> rotate(math.pi / 2, np.array([1.0, 0.0])).round(12).tolist()
[0.0, 1.0]
>>> perpendicular(np.array([[1.0, 2.0], [3.0, 4.0]])).tolist()
[[-2.0, 1.0], [-4.0, 3.0]]
>>> float(cross(np.array([1.0, 0.0]), np.array([0.0, 2.0])))
2.0
>>> unit_from_degrees(90).round(12).tolist()
[0.0, 1.0]
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "cross",
    "dot",
    "norm",
    "perpendicular",
    "rotate",
    "rotate_many",
    "unit",
    "unit_from_degrees",
    "units",
    "vectors",
]


def rotate(theta: float, v: np.ndarray) -> np.ndarray:
    """``R(θ)·v`` for one angle and one vector (shape (2,))."""
    c, s = math.cos(theta), math.sin(theta)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def rotate_many(theta: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``R(θ_k)·v`` for an array of angles (shape (N,)); ``v`` shape (2,) or (N, 2)."""
    c, s = np.cos(theta), np.sin(theta)
    vx, vy = (v[..., 0], v[..., 1])
    return np.stack([c * vx - s * vy, s * vx + c * vy], axis=-1)


def perpendicular(v: np.ndarray) -> np.ndarray:
    """``J·v``: ``v`` turned by +90° (``(x, y) -> (−y, x)``), for one vector or many."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The z component of ``a × b`` (``a_x·b_y − a_y·b_x``), for one pair of vectors or many."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a·b`` along the last axis, for one pair of vectors or many."""
    return np.einsum("...i,...i->...", a, b)


def norm(v: np.ndarray) -> np.ndarray:
    """Length of a vector (or of each of many), by ``np.hypot``."""
    return np.hypot(v[..., 0], v[..., 1])


def unit(angle: float) -> np.ndarray:
    """The unit vector at ``angle`` (rad) from the x axis: ``(cos, sin)``."""
    return np.array([math.cos(angle), math.sin(angle)])


def unit_from_degrees(degrees: float | None) -> np.ndarray:
    """The unit vector at ``degrees`` from the x axis (None: the x axis itself)."""
    return unit(math.radians(degrees or 0.0))


def units(angles: np.ndarray) -> np.ndarray:
    """Unit vectors (N, 2) at each of the angles (N,) (rad)."""
    return np.stack([np.cos(angles), np.sin(angles)], axis=1)


def vectors(x, y, n: int) -> np.ndarray:
    """An (N, 2) array from its two columns (arrays of shape (N,) or floats)."""
    out = np.empty((n, 2))
    out[:, 0] = x
    out[:, 1] = y
    return out
