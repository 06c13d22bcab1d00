"""The motion laws of a cam follower, for a unit lift over a unit interval, in closed form.

Each law is ``y(x)`` on ``x ∈ [0, 1]`` with ``y(0) = 0`` and ``y(1) = 1``, and its
first three derivatives by ``x``; a segment of lift ``h`` over ``β`` radians of cam
turn is ``s = h·y(x)``, ``s' = h·y'/β``, ``s'' = h·y''/β²``, ``s''' = h·y'''/β³``.

==================  ===============================================  ======  =======  =======
law                 y(x)                                               C_v     C_a      C_j
==================  ===============================================  ======  =======  =======
uniform             x                                                  1       ∞ ends   ∞
harmonic            (1 − cos πx)/2                                      π/2     π²/2     ∞ ends
cycloidal           x − sin(2πx)/(2π)                                  2       2π       4π²
modified-trapezoid  a: sine quarter (1/8), constant, sine half, …      2       4.888    61.4
modified-sine       a: sine quarter (1/8), sine 3/4-period, quarter    1.760   5.528    69.5
3-4-5               10x³ − 15x⁴ + 6x⁵                                   1.875   5.774    60
4-5-6-7             35x⁴ − 84x⁵ + 70x⁶ − 20x⁷                          2.1875  7.513    52.5
==================  ===============================================  ======  =======  =======

The modified trapezoid and modified sine are built from their acceleration,
integrated piece by piece in closed form (the constants of integration are
carried from piece to piece), then scaled so that ``y(1) = 1``.
:func:`fit_polynomial` fits a polynomial to boundary conditions (Norton's
SVAJ method). :func:`law_candidates` gives, for each law, the points of
``[0, 1]`` where its velocity, acceleration and jerk reach their extremes,
so that peaks are found exactly, not by sampling.

>>> import numpy as np
>>> y, y1, y2, y3 = unit_law(MotionLaw.CYCLOIDAL, np.array([0.5]))
>>> float(y[0]), float(y1[0]), round(float(y2[0]), 12), float(y3[0])
(0.5, 2.0, 0.0, -39.47841760435743)

References
----------
.. [1] R. L. Norton, *Design of Machinery*, ch. 8 (cam design, SVAJ diagrams).
.. [2] H. A. Rothbart, *Cam Design Handbook*, ch. 2–3 (the modified trapezoid and sine).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from structure.cams import MotionLaw

__all__ = [
    "MODIFIED_SINE_PEAK",
    "MODIFIED_TRAPEZOID_PEAK",
    "fit_polynomial",
    "law_candidates",
    "polynomial_derivatives",
    "unit_law",
]

_PI = math.pi
Values = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


def _uniform(x: np.ndarray) -> Values:
    zero = np.zeros_like(x)
    return x.copy(), np.ones_like(x), zero, zero.copy()


def _harmonic(x: np.ndarray) -> Values:
    c, s = np.cos(_PI * x), np.sin(_PI * x)
    return (1.0 - c) / 2.0, _PI / 2.0 * s, _PI**2 / 2.0 * c, -(_PI**3) / 2.0 * s


def _cycloidal(x: np.ndarray) -> Values:
    c, s = np.cos(2 * _PI * x), np.sin(2 * _PI * x)
    return x - s / (2 * _PI), 1.0 - c, 2 * _PI * s, 4 * _PI**2 * c


# ------------------------------------------------------------------ piecewise laws
# Each piece: (start, end, a(u), its integral v-part and double integral s-part), u = x − start.
# The acceleration of a piece is amplitude·f(k·u + phase) for f = sin or cos, or a constant;
# written as (kind, k, sign) and integrated in closed form below.


def _piece_values(kind: str, k: float, sign: float, u: np.ndarray) -> Values:
    """``(∫∫a, ∫a, a, a')`` of a piece's unit acceleration from its start (zero constants)."""
    if kind == "const":
        zero = np.zeros_like(u)
        return sign * u**2 / 2.0, sign * u, sign * np.ones_like(u), zero
    if kind == "sin":  # a = sign·sin(k·u)
        s, c = np.sin(k * u), np.cos(k * u)
        return sign * (u / k - s / k**2), sign * (1.0 - c) / k, sign * s, sign * k * c
    # "cos": a = sign·cos(k·u)
    s, c = np.sin(k * u), np.cos(k * u)
    return sign * (1.0 - c) / k**2, sign * s / k, sign * c, -sign * k * s


class _Piecewise:
    """A law given by its acceleration's pieces, integrated and scaled to a unit lift."""

    def __init__(self, pieces: tuple[tuple[float, float, str, float, float], ...]) -> None:
        self.pieces = pieces
        starts = []
        s0 = v0 = 0.0
        for start, end, kind, k, sign in pieces:
            starts.append((s0, v0))
            y, y1, _, _ = _piece_values(kind, k, sign, np.array([end - start]))
            s0, v0 = s0 + v0 * (end - start) + float(y[0]), v0 + float(y1[0])
        self.starts = tuple(starts)
        self.scale = 1.0 / s0
        self.end_velocity = v0 * self.scale

    def __call__(self, x: np.ndarray) -> Values:
        out = [np.zeros_like(x) for _ in range(4)]
        last = len(self.pieces) - 1
        for i, ((start, end, kind, k, sign), (s0, v0)) in enumerate(
            zip(self.pieces, self.starts, strict=True)
        ):
            inside = (x >= start) & ((x < end) if i < last else (x <= end))
            if not inside.any():
                continue
            u = x[inside] - start
            y, y1, y2, y3 = _piece_values(kind, k, sign, u)
            out[0][inside] = s0 + v0 * u + y
            out[1][inside] = v0 + y1
            out[2][inside] = y2
            out[3][inside] = y3
        return tuple(o * self.scale for o in out)  # type: ignore[return-value]


_K4 = 4 * _PI
#: the modified trapezoid: acceleration a sine quarter over 1/8, constant over 1/4, a sine half
#: over 1/4 (through zero at 1/2), constant over 1/4, a sine quarter back to zero over 1/8
_MODIFIED_TRAPEZOID = _Piecewise(
    (
        (0.0, 0.125, "sin", _K4, 1.0),
        (0.125, 0.375, "const", 0.0, 1.0),
        (0.375, 0.625, "cos", _K4, 1.0),
        (0.625, 0.875, "const", 0.0, -1.0),
        (0.875, 1.0, "cos", _K4, -1.0),
    )
)
#: the modified sine: a sine quarter over 1/8, three quarters of a slower sine over 3/4
#: (through zero at 1/2), a sine quarter back to zero over 1/8
_MODIFIED_SINE = _Piecewise(
    (
        (0.0, 0.125, "sin", _K4, 1.0),
        (0.125, 0.875, "cos", _K4 / 3.0, 1.0),
        (0.875, 1.0, "cos", _K4, -1.0),
    )
)

#: the peak acceleration factors C_a of the two piecewise laws (y'' at x = 1/8)
MODIFIED_TRAPEZOID_PEAK = _MODIFIED_TRAPEZOID.scale
MODIFIED_SINE_PEAK = _MODIFIED_SINE.scale

_POLY_345 = np.array([0.0, 0.0, 0.0, 10.0, -15.0, 6.0])
_POLY_4567 = np.array([0.0, 0.0, 0.0, 0.0, 35.0, -84.0, 70.0, -20.0])


def polynomial_derivatives(coefficients: np.ndarray, x: np.ndarray) -> Values:
    """``(y, y', y'', y''')`` of the polynomial ``Σ c_k·x^k`` (coefficients from the constant).

    >>> [float(v[0]) for v in polynomial_derivatives(np.array([1.0, 2.0, 3.0]), np.array([2.0]))]
    [17.0, 14.0, 6.0, 0.0]
    """
    c = np.asarray(coefficients, dtype=float)
    x = np.asarray(x, dtype=float)
    out = []
    for _ in range(4):
        value = np.full(x.shape, c[-1])
        for coefficient in c[-2::-1]:  # Horner
            value = value * x + coefficient
        out.append(value)
        c = c[1:] * np.arange(1, len(c)) if len(c) > 1 else np.zeros(1)
    return tuple(out)  # type: ignore[return-value]


def _polynomial(coefficients: np.ndarray) -> Callable[[np.ndarray], Values]:
    return lambda x: polynomial_derivatives(coefficients, x)


_LAWS: dict[MotionLaw, Callable[[np.ndarray], Values]] = {
    MotionLaw.UNIFORM: _uniform,
    MotionLaw.HARMONIC: _harmonic,
    MotionLaw.CYCLOIDAL: _cycloidal,
    MotionLaw.MODIFIED_TRAPEZOID: _MODIFIED_TRAPEZOID,
    MotionLaw.MODIFIED_SINE: _MODIFIED_SINE,
    MotionLaw.POLY_345: _polynomial(_POLY_345),
    MotionLaw.POLY_4567: _polynomial(_POLY_4567),
}


def unit_law(law: MotionLaw, x: np.ndarray) -> Values:
    """``(y, y', y'', y''')`` of ``law`` for a unit lift at ``x`` in [0, 1] (derivatives by x).

    A dwell is ``y = 0``. The fitted polynomial has no unit form (see
    :func:`fit_polynomial`).

    Raises
    ------
    ValueError
        ``law`` is the fitted polynomial.
    """
    x = np.asarray(x, dtype=float)
    if law is MotionLaw.DWELL:
        zero = np.zeros_like(x)
        return zero, zero.copy(), zero.copy(), zero.copy()
    if law is MotionLaw.POLYNOMIAL:
        raise ValueError("a fitted polynomial has no unit form: fit it with fit_polynomial")
    return _LAWS[law](x)


def _roots_in_unit(p: np.polynomial.Polynomial) -> list[float]:
    if p.degree() < 1 or not np.any(p.coef):
        return []
    roots = p.roots()
    real = roots[np.abs(roots.imag) <= 1e-9 * (1.0 + np.abs(roots.real))].real
    return [float(r) for r in real if -1e-12 <= r <= 1.0 + 1e-12]


def polynomial_candidates(coefficients: np.ndarray) -> tuple[float, ...]:
    """The ends and the points of [0, 1] where y', y'' or y''' of a polynomial is extreme."""
    p = np.polynomial.Polynomial(coefficients)
    found = {0.0, 1.0}
    for order in (2, 3, 4):
        found.update(min(1.0, max(0.0, r)) for r in _roots_in_unit(p.deriv(order)))
    return tuple(sorted(found))


_CANDIDATES: dict[MotionLaw, tuple[float, ...]] = {
    MotionLaw.DWELL: (0.0, 1.0),
    MotionLaw.UNIFORM: (0.0, 0.5, 1.0),
    MotionLaw.HARMONIC: (0.0, 0.5, 1.0),
    MotionLaw.CYCLOIDAL: (0.0, 0.25, 0.5, 0.75, 1.0),
    MotionLaw.MODIFIED_TRAPEZOID: tuple(k / 8 for k in range(9)),
    MotionLaw.MODIFIED_SINE: (0.0, 0.125, 0.5, 0.875, 1.0),
    MotionLaw.POLY_345: polynomial_candidates(_POLY_345),
    MotionLaw.POLY_4567: polynomial_candidates(_POLY_4567),
}


def law_candidates(law: MotionLaw) -> tuple[float, ...]:
    """Points of [0, 1] that hold every extreme of the law's y', y'' and y''' (and the ends).

    >>> law_candidates(MotionLaw.CYCLOIDAL)
    (0.0, 0.25, 0.5, 0.75, 1.0)
    """
    return _CANDIDATES[law]


def fit_polynomial(
    conditions: list[tuple[float, int, float]], duration: float
) -> np.ndarray | None:
    """The polynomial ``Σ c_k·x^k`` (x in [0, 1]) meeting the conditions; None if none or many.

    ``conditions`` are ``(x, order, value)``: the ``order``-th derivative of the
    displacement by the cam angle (per radian^order) at ``x`` of a segment of
    ``duration`` radians. With n conditions the polynomial has degree n − 1
    (Norton's SVAJ method).

    >>> c = fit_polynomial([(0, 0, 0.0), (0, 1, 0.0), (0, 2, 0.0), (1, 0, 1.0), (1, 1, 0.0),
    ...                     (1, 2, 0.0)], 1.0)
    >>> np.round(c, 9).tolist()
    [0.0, 0.0, 0.0, 10.0, -15.0, 6.0]
    """
    n = len(conditions)
    rows = np.zeros((n, n))
    rhs = np.zeros(n)
    for i, (x, order, value) in enumerate(conditions):
        for k in range(order, n):
            rows[i, k] = math.factorial(k) / math.factorial(k - order) * x ** (k - order)
        rhs[i] = value * duration**order
    try:
        coefficients = np.linalg.solve(rows, rhs)
    except np.linalg.LinAlgError:
        return None
    s = np.linalg.svd(rows, compute_uv=False)
    if s[-1] <= 1e-12 * s[0] or not np.all(np.isfinite(coefficients)):
        return None
    return coefficients
