"""The motion laws against their textbook peak factors, derived here independently.

Peak factors (v_max = C_v·h/β, a_max = C_a·h/β², j_max = C_j·h/β³): Norton,
*Design of Machinery*, ch. 8 (table of the double-dwell laws); Rothbart, *Cam
Design Handbook*, ch. 2. Each expected value below is derived in the test: by
hand for the trigonometric laws, by integrating the piecewise accelerations of
the modified trapezoid and sine by hand (their lift fixes C_a), with sympy for
the extremes of the polynomials.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from kinematics.cams.laws import (
    MODIFIED_SINE_PEAK,
    MODIFIED_TRAPEZOID_PEAK,
    fit_polynomial,
    law_candidates,
    unit_law,
)
from structure.cams import MotionLaw

PI = math.pi
# modified trapezoid: a = C·sin(4πx) to 1/8, C to 3/8, ... By hand, the displacement at
# x = 1/2 of the unit-amplitude acceleration is 1/(8π) + 1/16, and y(1) = 2·y(1/2) = 1.
C_A_TRAPEZOID = 1.0 / (1.0 / (4 * PI) + 1.0 / 8.0)
# modified sine: a = C·sin(4πx) to 1/8, C·cos(4π/3·(x − 1/8)) to 7/8, ...; y(1/2) of the
# unit amplitude is 1/(8π) + 1/(2π²), so C_a = 1/(1/(4π) + 1/π²); v(1/2) = C/π.
C_A_SINE = 1.0 / (1.0 / (4 * PI) + 1.0 / PI**2)


def _polynomial_peaks(expr: sp.Expr) -> tuple[float, float, float]:
    """The largest |y'|, |y''|, |y'''| on [0, 1] of a polynomial, from its critical points."""
    x = sp.symbols("x")
    out = []
    for order in (1, 2, 3):
        d = sp.diff(expr, x, order)
        points = [0, 1] + [r for r in sp.solve(sp.diff(d, x), x) if r.is_real and 0 <= r <= 1]
        out.append(max(abs(float(d.subs(x, p))) for p in points))
    return tuple(out)


_X = sp.symbols("x")
PEAKS = {
    # law: (C_v, C_a, C_j) of the law's own interior (uniform and harmonic: their jumps at
    # the ends are the joins' business, see test_program)
    MotionLaw.UNIFORM: (1.0, 0.0, 0.0),
    MotionLaw.HARMONIC: (PI / 2, PI**2 / 2, PI**3 / 2),
    MotionLaw.CYCLOIDAL: (2.0, 2 * PI, 4 * PI**2),
    MotionLaw.MODIFIED_TRAPEZOID: (2.0, C_A_TRAPEZOID, 4 * PI * C_A_TRAPEZOID),
    MotionLaw.MODIFIED_SINE: (C_A_SINE / PI, C_A_SINE, 4 * PI * C_A_SINE),
    MotionLaw.POLY_345: _polynomial_peaks(10 * _X**3 - 15 * _X**4 + 6 * _X**5),
    MotionLaw.POLY_4567: _polynomial_peaks(35 * _X**4 - 84 * _X**5 + 70 * _X**6 - 20 * _X**7),
}


def test_the_independent_factors_are_the_printed_ones() -> None:
    """The derivations above give the textbook table (DESIGN.md): 4.888, 5.528, 7.513, ..."""
    assert PEAKS[MotionLaw.MODIFIED_TRAPEZOID][1] == pytest.approx(4.888, abs=5e-4)
    assert PEAKS[MotionLaw.MODIFIED_SINE][0] == pytest.approx(1.760, abs=5e-4)
    assert PEAKS[MotionLaw.MODIFIED_SINE][1] == pytest.approx(5.528, abs=5e-4)
    assert PEAKS[MotionLaw.POLY_345] == pytest.approx((1.875, 5.774, 60.0), abs=5e-4)
    assert PEAKS[MotionLaw.POLY_4567] == pytest.approx((2.1875, 7.513, 52.5), abs=5e-4)


@pytest.mark.parametrize("law", list(PEAKS))
def test_peak_factors(law: MotionLaw) -> None:
    """The law's peaks, at its own candidate points, are the factors derived above."""
    x = np.array(law_candidates(law))
    _, y1, y2, y3 = unit_law(law, x)
    found = (np.max(np.abs(y1)), np.max(np.abs(y2)), np.max(np.abs(y3)))
    assert found == pytest.approx(PEAKS[law], rel=1e-12, abs=1e-12)
    # and no sample of the whole interval beats them
    dense = np.linspace(0.0, 1.0, 20001)
    _, d1, d2, d3 = unit_law(law, dense)
    for k, d in enumerate((d1, d2, d3)):
        assert np.max(np.abs(d)) <= PEAKS[law][k] * (1 + 1e-12) + 1e-12


def test_the_piecewise_peaks_are_exported() -> None:
    assert MODIFIED_TRAPEZOID_PEAK == pytest.approx(C_A_TRAPEZOID, rel=1e-14)
    assert MODIFIED_SINE_PEAK == pytest.approx(C_A_SINE, rel=1e-14)


@pytest.mark.parametrize("law", list(PEAKS))
def test_each_law_is_a_unit_lift_and_its_derivatives_are_its_own(law: MotionLaw) -> None:
    """y(0) = 0, y(1) = 1, and each derivative is the next one's integral (finite differences)."""
    y, y1, _, _ = unit_law(law, np.array([0.0, 1.0]))
    assert y.tolist() == pytest.approx([0.0, 1.0], abs=1e-15)
    if law is not MotionLaw.UNIFORM:
        assert y1.tolist() == pytest.approx([0.0, 0.0], abs=1e-12)
    x = np.linspace(0.01, 0.99, 99)
    h = 1e-6
    for k in range(3):
        ahead = unit_law(law, x + h)[k]
        behind = unit_law(law, x - h)[k]
        slope = (ahead - behind) / (2 * h)
        np.testing.assert_allclose(slope, unit_law(law, x)[k + 1], atol=1e-6 * (1 + 60))


def test_piecewise_laws_are_continuous_in_acceleration_at_their_knots() -> None:
    """The modified trapezoid and sine: s, v, a continuous where their pieces meet."""
    for law, knots in (
        (MotionLaw.MODIFIED_TRAPEZOID, (0.125, 0.375, 0.625, 0.875)),
        (MotionLaw.MODIFIED_SINE, (0.125, 0.875)),
    ):
        for knot in knots:
            left = unit_law(law, np.array([np.nextafter(knot, 0.0)]))
            right = unit_law(law, np.array([knot]))
            for k in range(3):
                assert left[k][0] == pytest.approx(right[k][0], abs=1e-12)


def test_fit_polynomial_gives_the_3_4_5_and_a_single_dwell_polynomial() -> None:
    """s, v, a zero at both ends of a unit rise: 10x³ − 15x⁴ + 6x⁵ (Norton §8.3); the symmetric
    rise-fall of one segment with s(1/2) = 1 and s, v, a zero at both ends: 64x³(1 − x)³
    (Norton's single-dwell polynomial, ex. 8-8), whatever the segment's length."""
    c = fit_polynomial(
        [(0, 0, 0.0), (0, 1, 0.0), (0, 2, 0.0), (1, 0, 1.0), (1, 1, 0.0), (1, 2, 0.0)], 2.0
    )
    np.testing.assert_allclose(c, [0, 0, 0, 10, -15, 6], atol=1e-9)
    c = fit_polynomial(
        [(0, 0, 0.0), (0, 1, 0.0), (0, 2, 0.0), (0.5, 0, 1.0), (1, 0, 0.0), (1, 1, 0.0),
         (1, 2, 0.0)],
        math.pi,
    )  # fmt: skip
    np.testing.assert_allclose(c, [0, 0, 0, 64, -192, 192, -64], atol=1e-8)


def test_fit_polynomial_refuses_conditions_that_fix_none() -> None:
    assert fit_polynomial([(0, 0, 0.0), (0, 0, 1.0)], 1.0) is None
    assert fit_polynomial([(0.5, 1, 0.0), (0.5, 1, 0.0), (1, 0, 1.0)], 1.0) is None


def test_the_fitted_law_has_no_unit_form() -> None:
    with pytest.raises(ValueError, match="fit_polynomial"):
        unit_law(MotionLaw.POLYNOMIAL, np.array([0.5]))
