"""Function generation: exact at the precision points, its structural error by the solvers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics import make_plan, sweep
from kinematics.errors import SynthesisError
from kinematics.synthesis.formula import read_function
from kinematics.synthesis.function import (
    FunctionLinkage,
    FunctionProblem,
    chebyshev_points,
    synthesize_function,
)
from structure import analyze

LOG = FunctionProblem(read_function("log10(x)"), 1.0, 2.0, 60.0, 90.0)


def test_chebyshev_spacing_by_its_formula() -> None:
    # x_j = 1.5 − 0.5·cos((2j − 1)π/6): 1.5 ∓ 0.5·√3/2 and 1.5
    expected = [1.5 - 0.25 * math.sqrt(3), 1.5, 1.5 + 0.25 * math.sqrt(3)]
    np.testing.assert_allclose(chebyshev_points(1.0, 2.0, 3), expected, atol=1e-15)


def _rocker_angle(design, inputs_deg: np.ndarray) -> np.ndarray:
    """The rocker's angle ψ (of the signed rocker c, degrees) as the solvers find it.

    The sketch's ψ from its points C and D, plus the rotation the sweep finds.
    """
    m = design.mechanism
    c, d = m.points["C"], m.points["D"]
    sketch = math.degrees(math.atan2(c.y - d.y, c.x - d.x)) + (
        180 if design.lengths["c"] < 0 else 0
    )
    plan = make_plan(analyze(m))
    turned = sweep(plan, np.radians(inputs_deg), rates=False).links["3"]["angle"]
    return sketch + np.degrees(turned)


@pytest.mark.parametrize("points", [3, 4, 5])
def test_the_solvers_meet_each_precision_point(points: int) -> None:
    design = synthesize_function(FunctionProblem(LOG.function, 1.0, 2.0, 60.0, 90.0, points))
    inputs = np.array(design.precision_input) - design.input_start
    psi = _rocker_angle(design, np.concatenate([[0.0], inputs]))[1:]
    gap = np.angle(np.exp(1j * np.radians(psi - np.array(design.precision_output))))
    assert np.max(np.degrees(np.abs(gap))) <= 1e-9 * 90.0
    assert design.error_at_precision <= 1e-9 * math.log10(2)


def test_structural_error_of_the_three_point_log10_generator_by_the_solvers() -> None:
    design = synthesize_function(LOG)
    # Freudenstein's constants solved anew from the precision points (3×3, exact points)
    phi = np.radians(45 + (np.array(design.precision_x) - 1) * 60)
    psi = np.radians(135 + np.log10(design.precision_x) / math.log10(2) * 90)
    k = np.linalg.solve(np.column_stack([np.cos(psi), -np.cos(phi), np.ones(3)]), np.cos(phi - psi))
    assert design.lengths["a"] == pytest.approx(1 / k[0], rel=1e-12)
    assert design.lengths["c"] == pytest.approx(1 / k[1], rel=1e-12)
    # the generated y over the range by the solvers' sweep of the written mechanism
    x = design.x
    psi = _rocker_angle(design, (x - 1) * 60)
    psi = 135 + (psi - 135 + 180) % 360 - 180
    generated = (psi - 135) / 90 * math.log10(2)
    error = generated - np.log10(x)
    assert np.max(np.abs(error)) == pytest.approx(design.error_max, rel=1e-9)
    np.testing.assert_allclose(design.error, error, atol=1e-12)
    # three Chebyshev points: the error changes sign at each, so four extremes alternate
    signs = np.sign(error[np.abs(error) > 1e-6])
    assert np.count_nonzero(np.diff(signs)) == 3


def test_crank_slider_meets_its_precision_points() -> None:
    design = synthesize_function(
        FunctionProblem(LOG.function, 1.0, 2.0, 60.0, 0.1, linkage=FunctionLinkage.CRANK_SLIDER)
    )
    plan = make_plan(analyze(design.mechanism))
    inputs = np.radians(np.array(design.precision_input) - design.input_start)
    moved = sweep(plan, np.concatenate([[0.0], inputs]), rates=False)
    s = moved.points["P"]["position"][1:, 0]
    np.testing.assert_allclose(s, design.precision_output, atol=1e-9 * 0.1)


@pytest.mark.parametrize(
    "problem, message",
    [
        (FunctionProblem(read_function("log10(x)"), 0.0, 1.0, 60, 90), "not defined"),
        (FunctionProblem(read_function("sqrt(x)"), -1.0, 1.0, 60, 90), "not defined"),
        (FunctionProblem(read_function("x"), 1.0, 2.0, 60, 90, points=2), "at least 3"),
        (FunctionProblem(read_function("x"), 1.0, 1.0, 60, 90), "empty"),
        (FunctionProblem(read_function("x*x"), -1.0, 1.0, 60, 90), "f.x0. = f.x1."),
    ],
)
def test_bad_problems_are_named(problem: FunctionProblem, message: str) -> None:
    with pytest.raises(SynthesisError, match=message):
        synthesize_function(problem)


@pytest.mark.parametrize("text", ["__import__('os')", "x.real", "open(x)", "[x]", "x if x else 1"])
def test_the_function_reader_refuses_what_is_not_arithmetic(text: str) -> None:
    with pytest.raises(SynthesisError, match="cannot read the function"):
        read_function(text)


def test_the_function_reader_computes() -> None:
    f = read_function("2^3 + sqrt(x) * sin(pi/2) - log(e)")
    assert float(f(np.array([4.0]))[0]) == pytest.approx(9.0)
