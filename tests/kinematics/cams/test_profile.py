"""The pitch curve and the profile against closed forms and a second method.

Closed forms: the pressure angle of an offset translating roller follower,
``tan φ = (s' − ε)/(d + s)``, ``d = √(R_p² − ε²)`` (Norton, *Design of Machinery*,
§8.7, eq. 8.31), and the radius of curvature of its pitch curve, derived here
by hand with complex numbers: ``X = e^{−iθ}(ε + i(d + s))``,
``X' = e^{−iθ}((d + s) + i(s' − ε))``, ``X'' = e^{−iθ}((2s' − ε) + i(s'' − d − s))``, so

    ρ = ((d + s)² + (s' − ε)²)^{3/2} / ((d + s)² + (s' − ε)(2s' − ε) − s''·(d + s));

with ε = 0 this is the polar form ``(r² + r'²)^{3/2}/(r² + 2r'² − r·r'')``, r = R_p + s
(DESIGN.md). A harmonic rise h over 180° under a radial roller has
``tan φ = a·sin θ/(b − a·cos θ)``, a = h/2, b = R_p + h/2, largest where cos θ = a/b:
``φ_max = asin(h/(2R_p + h))``. A flat face: ``ρ = R_b + s + s''`` and the contact
``s'`` from the axis (Norton §8.8). The example cams are those of Norton's
ch. 8 double-dwell examples (a cycloidal and a harmonic rise, dwells,
returns), at our own dimensions. Every follower kind is also checked by a
second method: the normal against finite differences of the pitch curve, the
radius against the three-point curvature of the profile's own points, the
profile against the envelope of neighbouring follower positions.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.cams.design import make_design
from kinematics.cams.profile import cam_geometry
from kinematics.errors import BaseCircleError
from structure.cams import cam_spec_from_dict

DOUBLE_DWELL = [
    {"law": "cycloidal", "lift": 0.02, "angle": 120},
    {"law": "dwell", "angle": 60},
    {"law": "harmonic", "lift": -0.02, "angle": 120},
    {"law": "dwell", "angle": 60},
]
THETA = np.radians(np.arange(0.25, 360, 1.5))


def _design(follower: dict, omega: float = 10.0, base: float = 0.04, segments=None):
    return make_design(
        cam_spec_from_dict(
            {"base_radius": base, "omega": omega, "follower": follower,
             "segments": segments or DOUBLE_DWELL}
        )
    )  # fmt: skip


def _curvature(points: np.ndarray, step: float, sense: float) -> np.ndarray:
    """Three-point radius of curvature of a curve sampled at ``θ − step, θ, θ + step``."""
    behind, here, ahead = points
    d1 = (ahead - behind) / (2 * step)
    d2 = (ahead - 2 * here + behind) / step**2
    cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    return -sense * np.hypot(d1[:, 0], d1[:, 1]) ** 3 / cross


@pytest.mark.parametrize("omega", [10.0, -10.0])
@pytest.mark.parametrize("offset", [0.0, 0.006, -0.004])
def test_translating_roller_against_the_closed_forms(offset: float, omega: float) -> None:
    rf, base = 0.012, 0.04
    design = _design(
        {"motion": "translating", "contact": "roller", "offset": offset, "roller_radius": rf},
        omega,
    )
    g = cam_geometry(design, THETA)
    d = math.sqrt((base + rf) ** 2 - offset**2)
    s, s1, s2 = g.s, g.s1, g.s2
    np.testing.assert_allclose(g.pressure, np.arctan((s1 - offset) / (d + s)), atol=1e-14)
    rho = ((d + s) ** 2 + (s1 - offset) ** 2) ** 1.5 / (
        (d + s) ** 2 + (s1 - offset) * (2 * s1 - offset) - s2 * (d + s)
    )
    np.testing.assert_allclose(g.pitch_radius, rho, rtol=1e-12)
    np.testing.assert_allclose(g.profile_radius, rho - rf, rtol=1e-12, atol=1e-15)
    # the roller's centre in the fixed frame: on the axis x = ±ε (mirrored for a clockwise cam)
    np.testing.assert_allclose(g.point[:, 0], math.copysign(1, omega) * offset, atol=1e-15)
    np.testing.assert_allclose(g.point[:, 1], d + s, atol=1e-15)


def test_zero_offset_is_the_polar_form() -> None:
    rf = 0.01
    design = _design({"motion": "translating", "contact": "roller", "roller_radius": rf})
    g = cam_geometry(design, THETA)
    r, r1, r2 = 0.05 + g.s, g.s1, g.s2
    polar = (r**2 + r1**2) ** 1.5 / (r**2 + 2 * r1**2 - r * r2)
    np.testing.assert_allclose(g.pitch_radius, polar, rtol=1e-12)
    # the pitch curve is the polar curve r(θ) in the cam's frame, turned back by the cam's angle
    np.testing.assert_allclose(np.hypot(*g.pitch.T), r, rtol=1e-14)


def test_harmonic_rise_peak_pressure_angle_in_closed_form() -> None:
    h, rp = 0.02, 0.05
    design = _design(
        {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
        segments=[{"law": "harmonic", "lift": h, "angle": 180},
                  {"law": "harmonic", "lift": -h, "angle": 180}],
    )  # fmt: skip
    theta = np.radians(np.arange(0, 180, 0.001))
    g = cam_geometry(design, theta)
    assert np.max(g.pressure) == pytest.approx(math.asin(h / (2 * rp + h)), abs=1e-10)
    k = int(np.argmax(g.pressure))
    assert math.cos(theta[k]) == pytest.approx((h / 2) / (rp + h / 2), abs=1e-5)


@pytest.mark.parametrize(
    "follower",
    [
        {"motion": "translating", "contact": "roller", "offset": 0.005, "roller_radius": 0.01},
        {"motion": "translating", "contact": "knife", "offset": -0.01},
        {"motion": "oscillating", "contact": "roller", "pivot": [0.09, 0.03], "arm": 0.075,
         "roller_radius": 0.01},
        {"motion": "oscillating", "contact": "knife", "pivot": [-0.02, 0.1], "arm": 0.07},
    ],
)  # fmt: skip
@pytest.mark.parametrize("omega", [7.0, -7.0])
def test_pitch_curve_by_a_second_method(follower: dict, omega: float) -> None:
    """Normal ⟂ the pitch curve's finite-difference tangent; radius = its three-point curvature;
    the profile is R_f inside the pitch curve (every roller position touches it, none cuts it)."""
    if follower["motion"] == "oscillating":
        segments = [{"law": "cycloidal", "lift": 15, "angle": 120}, {"law": "dwell", "angle": 60},
                    {"law": "modified-sine", "lift": -15, "angle": 120},
                    {"law": "dwell", "angle": 60}]  # fmt: skip
    else:
        segments = None
    design = _design(follower, omega, segments=segments)
    step = 1e-4
    g = [cam_geometry(design, THETA + k * step) for k in (-1, 0, 1)]
    tangent = g[2].pitch - g[0].pitch
    # the normal turned into the cam's frame
    back = -design.layout.sense * THETA
    c, s = np.cos(back), np.sin(back)
    n = np.stack([c * g[1].normal[:, 0] - s * g[1].normal[:, 1],
                  s * g[1].normal[:, 0] + c * g[1].normal[:, 1]], axis=1)  # fmt: skip
    dot = np.einsum("ij,ij->i", n, tangent) / np.hypot(*tangent.T)
    assert np.max(np.abs(dot)) < 1e-8
    rho = _curvature([x.pitch for x in g], step, design.layout.sense)
    np.testing.assert_allclose(g[1].pitch_radius, rho, rtol=1e-5)
    rf = design.layout.roller_radius
    if rf == 0:  # a knife: the profile is the pitch curve
        np.testing.assert_array_equal(g[1].profile, g[1].pitch)
    dense = cam_geometry(design, np.linspace(0, 2 * math.pi, 20001)).pitch
    for point in g[1].profile[::10] if rf else ():
        distance = np.min(np.hypot(*(dense - point).T))
        assert distance == pytest.approx(rf, abs=2e-7)
    # the pressure angle: between the normal and the way the roller's centre moves as it rises
    way = g[1].way
    cosine = np.einsum("ij,ij->i", g[1].normal, way)
    np.testing.assert_allclose(np.cos(g[1].pressure), cosine, atol=1e-13)


def test_oscillating_roller_starts_on_the_prime_circle_and_rises_outward() -> None:
    design = _design(
        {"motion": "oscillating", "contact": "roller", "pivot": [0.1, 0.0], "arm": 0.08,
         "roller_radius": 0.01},
        segments=[{"law": "cycloidal", "lift": 10, "angle": 180},
                  {"law": "cycloidal", "lift": -10, "angle": 180}],
    )  # fmt: skip
    g = cam_geometry(design, np.radians([0.0, 180.0]))
    r = np.hypot(*g.point.T)
    assert r[0] == pytest.approx(0.05, rel=1e-14)
    assert r[1] > r[0]
    arm = np.hypot(*(g.point - [0.1, 0.0]).T)
    np.testing.assert_allclose(arm, 0.08, rtol=1e-14)
    turned = math.degrees(
        math.atan2(*(g.point[1] - [0.1, 0])[::-1]) - math.atan2(*(g.point[0] - [0.1, 0])[::-1])
    )
    assert abs(turned) == pytest.approx(10.0, rel=1e-12)


@pytest.mark.parametrize("omega", [5.0, -5.0])
def test_translating_flat_face_in_closed_form(omega: float) -> None:
    """ρ = R_b + s + s''; the contact s' from the cam's centre along the face; the profile point
    is where neighbouring faces meet (their envelope)."""
    base = 0.04
    design = _design({"motion": "translating", "contact": "flat", "offset": 0.003}, omega, base)
    g = cam_geometry(design, THETA)
    np.testing.assert_allclose(g.profile_radius, base + g.s + g.s2, rtol=1e-13)
    sense = math.copysign(1.0, omega)
    np.testing.assert_allclose(g.contact[:, 0], sense * g.s1, atol=1e-15)
    np.testing.assert_allclose(g.contact[:, 1], base + g.s, atol=1e-15)
    assert np.all(g.pressure == 0)
    _envelope_check(design)


def test_oscillating_flat_face_touches_the_base_circle_and_is_its_envelope() -> None:
    design = _design(
        {"motion": "oscillating", "contact": "flat", "pivot": [0.1, 0.02], "face_offset": 0.005},
        segments=[{"law": "3-4-5", "lift": 12, "angle": 150}, {"law": "dwell", "angle": 30},
                  {"law": "3-4-5", "lift": -12, "angle": 150}, {"law": "dwell", "angle": 30}],
    )  # fmt: skip
    g = cam_geometry(design, np.radians([0.0, 165.0]))
    np.testing.assert_allclose(np.einsum("ij,ij->i", g.contact, g.normal)[0], 0.04, rtol=1e-14)
    # the face passes face_offset from the pivot
    np.testing.assert_allclose(
        np.einsum("ij,ij->i", g.contact - [0.1, 0.02], g.normal), 0.005, atol=1e-15
    )
    _envelope_check(design)
    step = 1e-4
    h = [cam_geometry(design, THETA + k * step) for k in (-1, 0, 1)]
    rho = _curvature([x.profile for x in h], step, design.layout.sense)
    np.testing.assert_allclose(h[1].profile_radius, rho, rtol=1e-5)


def _envelope_check(design) -> None:
    """The contact is where the face lines at θ ± δ cross (cam frame): the envelope."""
    step = 1e-6
    lines = []
    for k in (-1, 1):
        g = cam_geometry(design, THETA + k * step)
        back = -design.layout.sense * (THETA + k * step)
        c, s = np.cos(back), np.sin(back)
        n = np.stack([c * g.normal[:, 0] - s * g.normal[:, 1],
                      s * g.normal[:, 0] + c * g.normal[:, 1]], axis=1)  # fmt: skip
        lines.append((n, np.einsum("ij,ij->i", g.profile, n)))
    (n1, h1), (n2, h2) = lines
    det = n1[:, 0] * n2[:, 1] - n1[:, 1] * n2[:, 0]
    x = (h1 * n2[:, 1] - h2 * n1[:, 1]) / det
    y = (n1[:, 0] * h2 - n2[:, 0] * h1) / det
    here = cam_geometry(design, THETA).profile
    np.testing.assert_allclose(np.stack([x, y], axis=1), here, atol=1e-7)


def test_a_follower_that_cannot_reach_the_cam_is_a_named_error() -> None:
    with pytest.raises(BaseCircleError, match=r"make the base circle larger than 0\.04"):
        _design({"motion": "translating", "contact": "roller", "offset": 0.05,
                 "roller_radius": 0.01}, base=0.03)  # fmt: skip
    with pytest.raises(BaseCircleError, match="prime circle must lie between"):
        _design({"motion": "oscillating", "contact": "roller", "pivot": [0.2, 0.0], "arm": 0.05,
                 "roller_radius": 0.01})  # fmt: skip
    with pytest.raises(BaseCircleError, match="pivot must be farther"):
        _design({"motion": "oscillating", "contact": "flat", "pivot": [0.01, 0.0]})


def test_a_program_that_takes_the_follower_past_the_centre_is_named() -> None:
    segments = [{"law": "cycloidal", "lift": -0.06, "angle": 180},
                {"law": "cycloidal", "lift": 0.06, "angle": 180}]  # fmt: skip
    with pytest.raises(BaseCircleError, match="past the cam's centre"):
        _design({"motion": "translating", "contact": "roller", "roller_radius": 0.01},
                segments=segments)  # fmt: skip
