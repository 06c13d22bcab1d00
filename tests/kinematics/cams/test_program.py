"""A follower program laid on the turn: values, peaks in time, continuity at the joins."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.cams.program import continuity, make_program, peaks, program_values, time_values
from structure.cams import cam_spec_from_dict
from structure.errors import CamProgramError

KNIFE = {"motion": "translating", "contact": "knife"}


def _spec(segments: list[dict], omega: float = 10.0, follower: dict | None = None):
    return cam_spec_from_dict(
        {"base_radius": 0.05, "omega": omega, "follower": follower or KNIFE, "segments": segments}
    )


def test_values_follow_each_segment_from_where_the_last_left_off() -> None:
    """Rise 20 mm cycloidal over 120°, dwell 60°, return harmonic 120°, dwell: s at hand-picked
    angles from the laws' formulas."""
    program = make_program(
        _spec(
            [
                {"law": "cycloidal", "lift": 0.02, "angle": 120},
                {"law": "dwell", "angle": 60},
                {"law": "harmonic", "lift": -0.02, "angle": 120},
                {"law": "dwell", "angle": 60},
            ]
        )
    )
    theta = np.radians([30.0, 150.0, 240.0, 330.0, 390.0])
    s, s1, s2, _ = program_values(program, theta)
    beta = math.radians(120)
    x = 0.25
    cyc = 0.02 * (x - math.sin(2 * math.pi * x) / (2 * math.pi))
    har = 0.02 - 0.02 * (1 - math.cos(math.pi * 0.5)) / 2
    assert s.tolist() == pytest.approx([cyc, 0.02, har, 0.0, cyc], abs=1e-15)
    assert s1[0] == pytest.approx(0.02 / beta * (1 - math.cos(2 * math.pi * x)), rel=1e-12)
    expected = -0.02 * math.pi**2 / 2 / beta**2 * math.cos(math.pi / 2)
    assert s2[2] == pytest.approx(expected, abs=1e-12)


@pytest.mark.parametrize(
    ("law", "cv", "ca"),
    [
        ("cycloidal", 2.0, 2 * math.pi),
        ("modified-trapezoid", 2.0, 1 / (1 / (4 * math.pi) + 1 / 8)),
        ("modified-sine", 1 / (1 / (4 * math.pi) + 1 / math.pi**2) / math.pi,
         1 / (1 / (4 * math.pi) + 1 / math.pi**2)),
        ("3-4-5", 1.875, 10 / math.sqrt(3)),
    ],
)  # fmt: skip
def test_peaks_in_time_are_the_factors_times_h_omega_over_beta(law, cv, ca) -> None:
    """v_max = C_v·h·ω/β, a_max = C_a·h·ω²/β² (Norton ch. 8), h = 15 mm, β = 100°, ω = 12."""
    h, beta, omega = 0.015, math.radians(100), 12.0
    program = make_program(
        _spec(
            [{"law": law, "lift": h, "angle": 100}, {"law": "dwell", "angle": 80},
             {"law": law, "lift": -h, "angle": 100}, {"law": "dwell", "angle": 80}],
            omega=omega,
        )
    )  # fmt: skip
    found = peaks(program, omega)
    assert abs(found["v"].value) == pytest.approx(cv * h * omega / beta, rel=1e-12)
    assert abs(found["a"].value) == pytest.approx(ca * h * omega**2 / beta**2, rel=1e-12)
    _, v, a, _ = time_values(program, np.radians(np.arange(0, 360, 0.05)), omega)
    assert np.max(np.abs(v)) <= abs(found["v"].value) * (1 + 1e-12)
    assert np.max(np.abs(a)) <= abs(found["a"].value) * (1 + 1e-12)


def test_continuity_names_infinite_jerk_and_infinite_acceleration() -> None:
    """Harmonic beside a dwell: a jumps (C1, infinite jerk); cycloidal: only j jumps (C2);
    uniform: v jumps (C0); 4-5-6-7 beside dwells: s to j continuous (C3)."""
    program = make_program(
        _spec(
            [
                {"law": "harmonic", "lift": 0.01, "angle": 60},
                {"law": "dwell", "angle": 30},
                {"law": "cycloidal", "lift": 0.01, "angle": 60},
                {"law": "dwell", "angle": 30},
                {"law": "uniform", "lift": -0.01, "angle": 60},
                {"law": "dwell", "angle": 30},
                {"law": "4-5-6-7", "lift": -0.01, "angle": 60},
                {"law": "dwell", "angle": 30},
            ]
        )
    )
    joins = continuity(program)
    assert [(j.at_deg, j.name) for j in joins] == [
        (60.0, "C1"), (90.0, "C2"), (150.0, "C2"), (180.0, "C0"), (240.0, "C0"),
        (270.0, "C3"), (330.0, "C3"), (0.0, "C1"),
    ]  # fmt: skip
    assert [j.infinite_jerk for j in joins] == [True, False, False, True, True, False, False, True]


def test_a_polynomial_segment_fitted_to_time_conditions() -> None:
    """Norton's SVAJ method: a rise of 10 mm over 90° with v = a = 0 at both ends (given in
    m/s, m/s² at ω) is the 3-4-5; a return to 0 the same, so the joins are C2."""
    omega = 20.0
    program = make_program(
        _spec(
            [
                {"law": "polynomial", "angle": 90,
                 "bc": [{"at": 0, "s": 0, "v": 0, "a": 0}, {"at": 90, "s": 0.01, "v": 0, "a": 0}]},
                {"law": "dwell", "angle": 90},
                {"law": "3-4-5", "lift": -0.01, "angle": 90},
                {"law": "dwell", "angle": 90},
            ],
            omega=omega,
        )
    )  # fmt: skip
    x = np.linspace(0, 1, 7)
    s, *_ = program_values(program, x * math.pi / 2)
    np.testing.assert_allclose(s, 0.01 * (10 * x**3 - 15 * x**4 + 6 * x**5), atol=1e-15)
    assert [j.order for j in continuity(program)] == [2, 2, 2, 2]


def test_polynomial_conditions_on_velocity_are_time_rates() -> None:
    """A uniform rise written as a polynomial: s 0 → 0.02 m over 180° with v = 0.02/π·ω at
    both ends is s = 0.02·x (v given in m/s at ω = 5)."""
    omega, v = 5.0, 0.02 / math.pi * 5.0
    program = make_program(
        _spec(
            [{"law": "polynomial", "angle": 180,
              "bc": [{"at": 0, "s": 0, "v": v}, {"at": 180, "s": 0.02, "v": v}]},
             {"law": "uniform", "lift": -0.02, "angle": 180}],
            omega=omega,
        )
    )  # fmt: skip
    np.testing.assert_allclose(program.pieces[0].coefficients, [0, 0.02, 0, 0], atol=1e-15)


def test_conditions_that_fix_no_polynomial_are_a_named_error() -> None:
    spec = _spec(
        [{"law": "polynomial", "angle": 180,
          "bc": [{"at": 0, "s": 0}, {"at": 90, "v": 0.1}, {"at": 90, "a": 0}, {"at": 180, "s": 0}]},
         {"law": "dwell", "angle": 180}],
    )  # fmt: skip
    program = make_program(spec)  # four conditions: a cubic, and it exists
    assert len(program.pieces[0].coefficients) == 4
    bad = _spec(
        [{"law": "polynomial", "angle": 180,
          "bc": [{"at": 0, "s": 0, "a": 0}, {"at": 180, "s": 0, "a": 0}, {"at": 90, "j": 1}]},
         {"law": "dwell", "angle": 180}],
    )  # fmt: skip
    # s(0) = s(1) = 0, a(0) = a(1) = 0, j(1/2) = 1 over a quartic: the rows are singular
    with pytest.raises(CamProgramError, match=r"segments\[0\]: the boundary conditions"):
        make_program(bad)


def test_an_oscillating_program_is_in_radians_inside() -> None:
    follower = {"motion": "oscillating", "contact": "roller", "pivot": [0.1, 0.0], "arm": 0.08,
                "roller_radius": 0.01}  # fmt: skip
    program = make_program(
        _spec([{"law": "cycloidal", "lift": 20, "angle": 180},
               {"law": "cycloidal", "lift": -20, "angle": 180}], follower=follower)
    )  # fmt: skip
    s, *_ = program_values(program, np.array([math.pi]))
    assert s[0] == pytest.approx(math.radians(20), rel=1e-15)
    assert program.to_file_units(s)[0] == pytest.approx(20.0, rel=1e-15)
