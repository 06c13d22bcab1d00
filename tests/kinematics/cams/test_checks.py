"""The checks over the cycle and the design in reverse, against closed forms and brute force."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from kinematics.cams.checks import check_cam, smallest_base_circle
from kinematics.cams.design import make_design
from kinematics.cams.profile import cam_geometry
from kinematics.cams.program import program_values
from structure.cams import cam_spec_from_dict

RISE_RETURN = [
    {"law": "cycloidal", "lift": 0.02, "angle": 100},
    {"law": "dwell", "angle": 80},
    {"law": "harmonic", "lift": -0.02, "angle": 120},
    {"law": "dwell", "angle": 60},
]


def _spec(follower: dict, base: float = 0.04, segments=None, **more):
    data = {"base_radius": base, "omega": 10.0, "follower": follower,
            "segments": segments or RISE_RETURN, **more}  # fmt: skip
    return cam_spec_from_dict(data)


def test_the_largest_pressure_angle_is_the_closed_form() -> None:
    """Harmonic rise h over 180°, radial roller: φ_max = asin(h/(2R_p + h)) at cos θ = a/b."""
    h, rp = 0.02, 0.05
    spec = _spec(
        {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
        segments=[{"law": "harmonic", "lift": h, "angle": 180},
                  {"law": "harmonic", "lift": -h, "angle": 180}],
    )  # fmt: skip
    checks = check_cam(make_design(spec), 360)
    largest = math.degrees(math.asin(h / (2 * rp + h)))
    assert abs(checks.pressure.value) == pytest.approx(largest, abs=1e-8)
    at = math.radians(checks.pressure.at_deg)
    where = math.degrees(math.acos((h / 2) / (rp + h / 2)))
    at_deg = checks.pressure.at_deg
    assert min(at_deg, 360 - at_deg) == pytest.approx(where, abs=1e-3)
    assert math.sin(at) != 0
    assert checks.pressure_ok and checks.limit == 30.0


def test_the_smallest_radii_are_those_of_the_closed_form_over_a_fine_sweep() -> None:
    """The pitch curve's radius from the hand-derived formula (see test_profile) at 0.001°."""
    eps, rf, base = 0.004, 0.008, 0.035
    spec = _spec(
        {"motion": "translating", "contact": "roller", "offset": eps, "roller_radius": rf}, base
    )
    design = make_design(spec)
    checks = check_cam(design, 720)
    theta = np.radians(np.arange(0, 360, 0.001))
    s, s1, s2, _ = program_values(design.program, theta)
    d = math.sqrt((base + rf) ** 2 - eps**2)
    rho = ((d + s) ** 2 + (s1 - eps) ** 2) ** 1.5 / (
        (d + s) ** 2 + (s1 - eps) * (2 * s1 - eps) - s2 * (d + s)
    )
    convex = rho[rho > 0]
    assert checks.pitch_min.value == pytest.approx(convex.min(), rel=1e-8)
    assert checks.profile_min.value == pytest.approx(convex.min() - rf, rel=1e-7)
    where = theta[rho == convex.min()][0]
    assert math.radians(checks.pitch_min.at_deg) == pytest.approx(where, abs=2e-5)
    if (rho < 0).any():
        assert checks.pitch_concave.value == pytest.approx(np.min(-rho[rho < 0]), rel=1e-8)
    assert not checks.undercut


def test_undercut_where_the_roller_exceeds_the_convex_radius() -> None:
    """A sharp nose (30 mm in 50°, then back): its smallest convex radius is below the prime
    circle's; a roller 1.2 times that radius on the same pitch curve loops there."""
    sharp = [
        {"law": "cycloidal", "lift": 0.03, "angle": 50},
        {"law": "dwell", "angle": 10},
        {"law": "cycloidal", "lift": -0.03, "angle": 50},
        {"law": "dwell", "angle": 250},
    ]
    small = make_design(
        _spec({"motion": "translating", "contact": "roller", "roller_radius": 0.002}, 0.02,
              segments=sharp)
    )  # fmt: skip
    found = check_cam(small, 720)
    rho_min = found.pitch_min.value
    assert rho_min * 1.2 < small.layout.prime
    big = dataclasses.replace(
        small.spec, follower=dataclasses.replace(small.spec.follower, roller_radius=rho_min * 1.2)
    )
    big = dataclasses.replace(big, base_radius=small.layout.prime - rho_min * 1.2)
    checks = check_cam(make_design(big), 720)  # the same pitch curve, a larger roller
    assert checks.pitch_min.value == pytest.approx(rho_min, rel=1e-9)
    assert checks.undercut
    assert any(a <= checks.pitch_min.at_deg <= b for a, b in checks.undercut_at)
    assert not found.undercut


@pytest.mark.parametrize("margin", [0.005, -0.002])
def test_a_flat_face_has_a_cusp_where_base_plus_s_plus_s2_is_not_positive(margin: float) -> None:
    theta = np.radians(np.arange(360000) / 1000)
    plain = make_design(_spec({"motion": "translating", "contact": "flat"}))
    s, s1, s2, _ = program_values(plain.program, theta)
    base = float(np.max(-(s + s2))) + margin
    design = make_design(
        _spec({"motion": "translating", "contact": "flat", "offset": 0.002}, base=base)
    )
    checks = check_cam(design, 3600)
    rho = base + s + s2
    assert checks.undercut == (margin < 0)
    if margin > 0:
        assert checks.profile_min.value == pytest.approx(rho.min(), rel=1e-8)
    # the face: the contact sits s' from the cam's centre, so from the axis (offset 2 mm) at s' − ε
    assert checks.face == pytest.approx((s1.min() - 0.002, s1.max() - 0.002), rel=1e-6)
    assert checks.face_width == pytest.approx(s1.max() - s1.min(), rel=1e-6)
    assert checks.pitch_min is None


def _pressure_max(s, s1, rp: float, eps: float) -> float:
    d = math.sqrt(rp**2 - eps**2)
    return float(np.max(np.abs(np.arctan((s1 - eps) / (d + s)))))


def test_smallest_base_circle_for_a_translating_roller() -> None:
    """At the answer the largest pressure angle is the limit; any smaller base circle exceeds
    it (Norton's formula evaluated on its own); the best offset beats a brute-force scan."""
    rf, eps = 0.01, 0.003
    design = make_design(
        _spec({"motion": "translating", "contact": "roller", "offset": eps, "roller_radius": rf},
              max_pressure_angle=25)
    )  # fmt: skip
    answer = smallest_base_circle(design, 3600)
    theta = np.radians(np.arange(3600) / 10)
    s, s1, *_ = program_values(design.program, theta)
    limit = math.radians(25)
    assert answer.bound == "pressure angle"
    assert _pressure_max(s, s1, answer.base_radius + rf, eps) <= limit + 1e-12
    assert _pressure_max(s, s1, answer.base_radius * (1 - 1e-6) + rf, eps) > limit
    best = answer.best_base_radius + rf
    for trial in np.linspace(-0.02, 0.02, 81):
        low, high = abs(trial) + 1e-9, 1.0
        for _ in range(60):
            mid = (low + high) / 2
            if _pressure_max(s, s1, mid, trial) <= limit:
                high = mid
            else:
                low = mid
        assert best <= high * (1 + 1e-6)
    assert _pressure_max(s, s1, best, answer.best_offset) <= limit + 1e-9


def test_smallest_base_circle_of_a_flat_face_is_minus_the_least_s_plus_s2() -> None:
    design = make_design(_spec({"motion": "translating", "contact": "flat"}))
    answer = smallest_base_circle(design, 3600)
    s, _, s2, _ = program_values(design.program, np.radians(np.arange(3600) / 10))
    assert answer.base_radius == pytest.approx(float(np.max(-(s + s2))), rel=1e-8)
    assert answer.bound == "undercut"


def test_smallest_base_circle_with_undercut_as_the_bound() -> None:
    """A large roller: the pressure limit alone would allow a base circle whose pitch curve is
    sharper than the roller; the answer is where the smallest convex radius reaches it."""
    design = make_design(
        _spec({"motion": "translating", "contact": "roller", "roller_radius": 0.03},
              max_pressure_angle=45)
    )  # fmt: skip
    answer = smallest_base_circle(design, 1440)
    assert answer.bound == "undercut"
    at = dataclasses.replace(design.spec, base_radius=answer.base_radius)
    assert not check_cam(make_design(at), 1440).undercut
    below = dataclasses.replace(design.spec, base_radius=answer.base_radius * (1 - 1e-5))
    assert check_cam(make_design(below), 1440).undercut


def test_smallest_base_circle_of_an_oscillating_roller_by_bisection() -> None:
    segments = [
        {"law": "cycloidal", "lift": 20, "angle": 120},
        {"law": "dwell", "angle": 60},
        {"law": "cycloidal", "lift": -20, "angle": 120},
        {"law": "dwell", "angle": 60},
    ]
    design = make_design(
        _spec({"motion": "oscillating", "contact": "roller", "pivot": [0.12, 0.0], "arm": 0.1,
               "roller_radius": 0.01}, segments=segments)
    )  # fmt: skip
    answer = smallest_base_circle(design, 720)
    assert answer.base_radius is not None
    theta = np.radians(np.arange(720) / 2)
    fits = dataclasses.replace(design.spec, base_radius=answer.base_radius)
    g = cam_geometry(make_design(fits), theta)
    assert np.degrees(np.max(np.abs(g.pressure))) <= 35.0 + 1e-9
    smaller = dataclasses.replace(design.spec, base_radius=answer.base_radius * (1 - 1e-6))
    g = cam_geometry(make_design(smaller), theta)
    assert np.degrees(np.max(np.abs(g.pressure))) > 35.0 or answer.bound != "pressure angle"
