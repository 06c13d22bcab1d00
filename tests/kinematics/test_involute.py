"""Involute spur gear geometry against numbers worked out by hand.

Hand constants used below (4-figure tables / a calculator, 7 decimals):
cos 20° = 0.9396926, sin 20° = 0.3420201, tan 20° = 0.3639702,
20° = 0.3490659 rad, so inv 20° = 0.3639702 − 0.3490659 = 0.0149043.
Lengths are written in millimetres and multiplied by ``MM``; the module works in metres.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.gears.involute import (
    base_radius,
    center_distance,
    contact_ratio,
    inverse_involute,
    involute,
    pitch_radius,
    root_radius,
    tip_radius,
    tooth_thickness,
    tooth_thickness_at,
    working_center_distance,
    working_pressure_angle,
)

MM = 1e-3
M = 4 * MM  # module 4 mm
ALPHA = math.radians(20)


def mm(value: float, rel: float = 1e-6):
    """``value`` millimetres, as metres, with a relative tolerance."""
    return pytest.approx(value * MM, rel=rel)


# --------------------------------------------------------------------------- radii


def test_radii_of_a_standard_20_tooth_gear():
    # r = m z / 2 = 4·20/2 = 40 mm
    assert pitch_radius(M, 20) == mm(40.0)
    # r_b = r cos α = 40 · 0.9396926 = 37.58770 mm
    assert base_radius(M, 20, ALPHA) == mm(37.58770)
    assert base_radius(M, 20) == mm(37.58770)  # 20° is the default
    # r_a = r + m h_a* = 40 + 4·1 = 44 mm
    assert tip_radius(M, 20) == mm(44.0)
    # r_f = r − m h_f* = 40 − 4·1.25 = 35 mm
    assert root_radius(M, 20) == mm(35.0)


def test_radii_with_profile_shift():
    # ξ = 0.5: r_a = 40 + 4(1 + 0.5) = 46 mm; r_f = 40 − 4(1.25 − 0.5) = 37 mm
    assert tip_radius(M, 20, shift=0.5) == mm(46.0)
    assert root_radius(M, 20, shift=0.5) == mm(37.0)
    # ξ = −0.3: r_a = 40 + 4·0.7 = 42.8 mm; r_f = 40 − 4·1.55 = 33.8 mm
    assert tip_radius(M, 20, shift=-0.3) == mm(42.8)
    assert root_radius(M, 20, shift=-0.3) == mm(33.8)
    # stub tooth h_a* = 0.8, h_f* = 1.0: r_a = 40 + 3.2 = 43.2 mm, r_f = 40 − 4 = 36 mm
    assert tip_radius(M, 20, addendum=0.8) == mm(43.2)
    assert root_radius(M, 20, dedendum=1.0) == mm(36.0)


def test_radii_of_an_internal_gear():
    # z = 60: r = 4·60/2 = 120 mm; tips point inwards: r_a = 120 − 4 = 116 mm,
    # r_f = 120 + 4·1.25 = 125 mm
    assert tip_radius(M, 60, internal=True) == mm(116.0)
    assert root_radius(M, 60, internal=True) == mm(125.0)
    # ξ = 0.5 moves the profile outwards: r_a = 120 − 4(1 − 0.5) = 118 mm,
    # r_f = 120 + 4(1.25 + 0.5) = 127 mm
    assert tip_radius(M, 60, shift=0.5, internal=True) == mm(118.0)
    assert root_radius(M, 60, shift=0.5, internal=True) == mm(127.0)


# --------------------------------------------------------------------------- centre distance


def test_center_distance_external_and_internal():
    # a = m(z1 + z2)/2 = 4·60/2 = 120 mm
    assert center_distance(M, 20, 40) == mm(120.0)
    # internal: a = m(z2 − z1)/2 = 4·40/2 = 80 mm
    assert center_distance(M, 20, 60, internal=True) == mm(80.0)


def test_center_distance_of_the_exam_planetary_train():
    # Problem 2 of the exam: coaxial condition A12 = A2'3 with z1 = 60, z2 = 20, z2' = 25,
    # z3 = z1 + z2 + z2' = 105: m(60 + 20)/2 = 40 m = m(105 − 25)/2
    m = 2 * MM
    assert center_distance(m, 60, 20) == pytest.approx(40 * m)
    assert center_distance(m, 25, 105, internal=True) == pytest.approx(40 * m)


# --------------------------------------------------------------------------- involute function


def test_involute_function_table_values():
    # inv 20° = tan 20° − 20° = 0.3639702 − 0.3490659 = 0.0149043 (table: 0.014904)
    assert involute(ALPHA) == pytest.approx(0.014904, abs=5e-7)
    # inv 25° = 0.4663077 − 0.4363323 = 0.0299754 (table: 0.029975)
    assert involute(math.radians(25)) == pytest.approx(0.029975, abs=5e-7)
    assert involute(0.0) == 0.0


@pytest.mark.parametrize("degrees", [0.5, 5, 14.5, 20, 25, 30, 45, 70, 85, 89.9])
def test_inverse_involute_round_trip(degrees):
    alpha = math.radians(degrees)
    assert inverse_involute(involute(alpha)) == pytest.approx(alpha, rel=1e-12)


def test_inverse_involute_of_the_table_value():
    # the table value 0.014904 gives back 20° to about 0.0002°
    assert math.degrees(inverse_involute(0.014904)) == pytest.approx(20.0, abs=5e-4)
    assert inverse_involute(0.0) == 0.0


# --------------------------------------------------------------------------- working pressure angle


@pytest.mark.parametrize("x1, x2", [(0.0, 0.0), (0.5, -0.5), (-0.3, 0.3)])
def test_working_pressure_angle_is_alpha_when_the_shifts_cancel(x1, x2):
    # x1 + x2 = 0: inv α_w = inv α + 0, so α_w = α and a_w = a
    assert working_pressure_angle(20, 40, x1, x2, ALPHA) == pytest.approx(ALPHA, rel=1e-14)
    assert working_center_distance(M, 20, 40, x1, x2, ALPHA) == mm(120.0)


def test_working_pressure_angle_is_alpha_for_an_internal_pair_with_equal_shifts():
    # internal: inv α_w = inv α + 2 tan α (x2 − x1)/(z2 − z1) = inv α when x1 = x2
    assert working_pressure_angle(20, 60, 0.4, 0.4, ALPHA, internal=True) == pytest.approx(ALPHA)
    assert working_center_distance(M, 20, 60, 0.4, 0.4, internal=True) == mm(80.0)


def test_working_pressure_angle_of_a_positive_pair():
    # z1 = 20, z2 = 40, x1 = x2 = 0.5:
    # inv α_w = 0.0149043 + 2·0.3639702·1.0/60 = 0.0149043 + 0.0121323 = 0.0270366
    # inv 24.2° = tan 24.2° − 0.4223697 = 0.4494178 − 0.4223697 = 0.0270481, 0.0000115 too big;
    # d(inv α)/dα = tan² α = 0.2020, so α_w = 24.2° − 0.0000115/0.2020 rad = 24.2° − 0.0033°
    # = 24.1967°
    alpha_w = working_pressure_angle(20, 40, 0.5, 0.5, ALPHA)
    assert involute(alpha_w) == pytest.approx(0.0270366, abs=2e-7)
    assert math.degrees(alpha_w) == pytest.approx(24.197, abs=1e-3)
    # a_w = a cos α / cos α_w = 120·0.9396926/0.912143 = 112.7631/0.912143 = 123.624 mm
    assert working_center_distance(M, 20, 40, 0.5, 0.5) == mm(123.624, rel=1e-5)


def test_working_pressure_angle_of_an_internal_pair():
    # z1 = 20, z2 = 60, x1 = 0, x2 = 0.5:
    # inv α_w = 0.0149043 + 2·0.3639702·0.5/40 = 0.0149043 + 0.0090993 = 0.0240036
    alpha_w = working_pressure_angle(20, 60, 0.0, 0.5, ALPHA, internal=True)
    assert involute(alpha_w) == pytest.approx(0.0240036, abs=2e-7)


# --------------------------------------------------------------------------- contact ratio


def test_contact_ratio_of_a_standard_external_pair():
    # m = 4 mm, z1 = 20, z2 = 40, α = 20°, no shift, a_w = a = 120 mm, α_w = α:
    # r_a1 = 44, r_b1 = 37.58770: √(44² − 37.58770²) = √(1936 − 1412.8352) = √523.1648 = 22.87279
    # r_a2 = 84, r_b2 = 80·0.9396926 = 75.17541:
    #     √(84² − 75.17541²) = √(7056 − 5651.3423) = √1404.6577 = 37.47876
    # a sin α = 120·0.3420201 = 41.04241
    # p_b = π m cos α = π·4·0.9396926 = 11.80855
    # ε = (22.87279 + 37.47876 − 41.04241)/11.80855 = 19.30914/11.80855 = 1.63519
    assert contact_ratio(M, 20, 40) == pytest.approx(1.63519, abs=1e-4)
    assert contact_ratio(M, 20, 40, 0.0, 0.0, ALPHA) == pytest.approx(1.63519, abs=1e-4)


def test_contact_ratio_does_not_depend_on_the_module():
    # every length in ε scales with m, so ε does not
    assert contact_ratio(10 * MM, 20, 40) == pytest.approx(contact_ratio(M, 20, 40), rel=1e-12)


def test_contact_ratio_of_a_standard_internal_pair():
    # m = 4 mm, z1 = 20 (pinion), z2 = 60 (internal), a = 80 mm:
    # pinion term as above: 22.87279
    # ring: r_a2 = 116, r_b2 = 120·0.9396926 = 112.76311:
    #     √(116² − 112.76311²) = √(13456 − 12715.5190) = √740.4810 = 27.21178
    # a sin α = 80·0.3420201 = 27.36161
    # ε = (22.87279 − 27.21178 + 27.36161)/11.80855 = 23.02262/11.80855 = 1.94966
    assert contact_ratio(M, 20, 60, internal=True) == pytest.approx(1.94966, abs=1e-4)


def test_contact_ratio_of_a_shifted_pair():
    # z1 = 20, z2 = 40, x1 = x2 = 0.5: r_a1 = 46, r_a2 = 86, α_w = 24.197°, a_w = 123.624 mm
    # √(46² − 37.58770²) = √(2116 − 1412.8352) = √703.1648 = 26.51726
    # √(86² − 75.17541²) = √(7396 − 5651.3423) = √1744.6577 = 41.76910
    # a_w sin α_w = 123.6243·0.409871 = 50.67006
    # ε = (26.51726 + 41.76910 − 50.67006)/11.80855 = 17.61630/11.80855 = 1.49183
    # (smaller than the standard pair's 1.635: the bigger α_w shortens the path of contact)
    assert contact_ratio(M, 20, 40, 0.5, 0.5) == pytest.approx(1.49183, abs=1e-4)


# --------------------------------------------------------------------------- tooth thickness


def test_tooth_thickness_unshifted_is_half_the_pitch():
    # S = π m / 2 = 3.1415927·4/2 = 6.283185 mm
    assert tooth_thickness(M) == mm(6.283185)
    assert tooth_thickness(M, 0.0, ALPHA) == mm(6.283185)


def test_tooth_thickness_with_profile_shift():
    # ξ = 0.5:  S = 4(π/2 + 2·0.5·0.3639702) = 4(1.5707963 + 0.3639702) = 4·1.9347665 = 7.739066
    assert tooth_thickness(M, 0.5, ALPHA) == mm(7.739066)
    # ξ = −0.5: S = 4(1.5707963 − 0.3639702) = 4·1.2068261 = 4.827304 mm
    assert tooth_thickness(M, -0.5, ALPHA) == mm(4.827304)
    # internal gear, ξ = 0.5: S = m(π/2 − 2ξ tan α) = 4.827304 mm
    assert tooth_thickness(M, 0.5, ALPHA, internal=True) == mm(4.827304)


@pytest.mark.parametrize("xi", [-0.5, 0.0, 0.25, 0.5, 1.0])
@pytest.mark.parametrize("m_t", [1 * MM, 2.5 * MM, 4 * MM])
def test_tooth_thickness_is_the_space_of_the_generating_rack(xi, m_t):
    # Exam problem 3: the rack rolls without backlash on the blank's pitch circle, so
    # S = W_t = t_t/2 + 2δ tan α_t with t_t = π m_t and δ = ξ m_t.
    t_t, delta = math.pi * m_t, xi * m_t
    assert tooth_thickness(m_t, xi, ALPHA) == pytest.approx(t_t / 2 + 2 * delta * math.tan(ALPHA))


def test_tooth_thickness_at_the_pitch_circle_is_s():
    r = pitch_radius(M, 20)
    assert tooth_thickness_at(r, M, 20, 0.0, ALPHA) == mm(6.283185)
    assert tooth_thickness_at(r, M, 20, 0.5, ALPHA) == mm(7.739066)


def test_tooth_thickness_on_the_base_circle_matches_the_textbook_formula():
    # s_b = r_b (S/r + 2 inv α); m = 4 mm, z = 20, r = 40, r_b = 37.58770 mm
    rb = base_radius(M, 20, ALPHA)
    # ξ = 0:   37.58770(6.283185/40 + 2·0.0149043) = 37.58770(0.1570796 + 0.0298087)
    #        = 37.58770·0.1868883 = 7.024706 mm
    assert tooth_thickness_at(rb, M, 20, 0.0, ALPHA) == mm(7.024706, rel=1e-5)
    # ξ = 0.5: 37.58770(7.739066/40 + 0.0298087) = 37.58770·0.2232854 = 8.392786 mm
    assert tooth_thickness_at(rb, M, 20, 0.5, ALPHA) == mm(8.392786, rel=1e-5)
    # the same formula written out, for several gears and shifts
    for z, xi in [(12, 0.6), (20, -0.2), (57, 0.0), (100, 1.0)]:
        r, rb = pitch_radius(M, z), base_radius(M, z, ALPHA)
        s = tooth_thickness(M, xi, ALPHA)
        textbook = rb * (s / r + 2 * (math.tan(ALPHA) - ALPHA))
        assert tooth_thickness_at(rb, M, z, xi, ALPHA) == pytest.approx(textbook, rel=1e-12)


def test_tooth_thickness_on_the_tip_circle():
    # m = 4 mm, z = 20, ξ = 0, r_a = 44 mm: tan α_a = √(44² − r_b²)/r_b = 22.87279/37.58770
    # = 0.608518, α_a = 0.546659 rad (31.321°), inv α_a = 0.608518 − 0.546659 = 0.061859
    # s_a = 44(0.1570796 − 2(0.061859 − 0.0149043)) = 44(0.1570796 − 0.0939094)
    #     = 44·0.0631702 = 2.77949 mm  (≈ 0.69 m, a healthy tip)
    assert tooth_thickness_at(tip_radius(M, 20), M, 20, 0.0, ALPHA) == mm(2.7795, rel=1e-4)


def test_tooth_thickness_of_an_internal_gear_on_its_base_circle():
    # internal: s_b = r_b (S/r − 2 inv α); z = 60, r = 120, r_b = 112.76311 mm, ξ = 0:
    # 112.76311(6.283185/120 − 0.0298087) = 112.76311(0.0523599 − 0.0298087)
    #     = 112.76311·0.0225512 = 2.542945 mm
    rb = base_radius(M, 60, ALPHA)
    assert tooth_thickness_at(rb, M, 60, internal=True) == mm(2.542945, rel=1e-5)


@pytest.mark.parametrize(
    "z1, z2, x1, x2, internal",
    [
        (20, 40, 0.5, 0.5, False),
        (12, 30, 0.6, 0.2, False),
        (17, 51, 0.3, -0.1, False),
        (20, 60, 0.0, 0.5, True),
        (18, 72, 0.2, 0.7, True),
    ],
)
def test_shifted_pair_meshes_without_backlash_on_the_working_circles(z1, z2, x1, x2, internal):
    # On the working circles the two teeth fill one working pitch:
    # s_w1 + s_w2 = 2π r_w1/z1, r_w = r cos α / cos α_w (for an internal pair s_w2 is the
    # ring's tooth, which fills the pinion's space there just the same).
    alpha_w = working_pressure_angle(z1, z2, x1, x2, ALPHA, internal)
    ratio = math.cos(ALPHA) / math.cos(alpha_w)
    rw1, rw2 = pitch_radius(M, z1) * ratio, pitch_radius(M, z2) * ratio
    s1 = tooth_thickness_at(rw1, M, z1, x1, ALPHA)
    s2 = tooth_thickness_at(rw2, M, z2, x2, ALPHA, internal=internal)
    assert s1 + s2 == pytest.approx(2 * math.pi * rw1 / z1, rel=1e-12)
    # and the working centre distance is the sum (difference) of the working radii
    a_w = working_center_distance(M, z1, z2, x1, x2, ALPHA, internal)
    assert a_w == pytest.approx(rw2 - rw1 if internal else rw1 + rw2, rel=1e-12)


# --------------------------------------------------------------------------- validation


def test_numpy_integers_are_accepted_as_teeth():
    assert pitch_radius(M, np.int64(20)) == mm(40.0)


@pytest.mark.parametrize("module", [0, -4e-3, math.nan, math.inf, True, "4"])
def test_bad_module_is_rejected(module):
    with pytest.raises(ValueError, match="module"):
        pitch_radius(module, 20)


@pytest.mark.parametrize("teeth", [0, -3, 20.5, 20.0, True, "20"])
def test_bad_teeth_are_rejected(teeth):
    with pytest.raises(ValueError, match="teeth must be an integer"):
        pitch_radius(M, teeth)


@pytest.mark.parametrize("shift", [2.5, -3.0, math.nan])
def test_unreasonable_shift_is_rejected(shift):
    with pytest.raises(ValueError, match="shift"):
        tip_radius(M, 20, shift=shift)
    with pytest.raises(ValueError, match="shift"):
        tooth_thickness(M, shift)


def test_pressure_angle_in_degrees_is_rejected_with_a_hint():
    with pytest.raises(ValueError, match=r"radians.*math\.radians\(20\)"):
        base_radius(M, 20, 20)
    with pytest.raises(ValueError, match="radians"):
        contact_ratio(M, 20, 40, pressure_angle=0.0)


def test_internal_pair_needs_the_bigger_ring():
    with pytest.raises(ValueError, match="internal gear z2 larger"):
        center_distance(M, 40, 20, internal=True)
    with pytest.raises(ValueError, match="internal gear z2 larger"):
        contact_ratio(M, 30, 30, internal=True)


def test_radius_inside_the_base_circle_is_rejected():
    with pytest.raises(ValueError, match="base radius"):
        tooth_thickness_at(30 * MM, M, 20)


def test_negative_coefficients_and_involutes_are_rejected():
    with pytest.raises(ValueError, match="addendum"):
        tip_radius(M, 20, addendum=-1.0)
    with pytest.raises(ValueError, match="dedendum"):
        root_radius(M, 20, dedendum=-0.1)
    with pytest.raises(ValueError, match="inv"):
        inverse_involute(-0.01)
    with pytest.raises(ValueError, match="alpha"):
        involute(math.pi / 2)


def test_too_negative_shifts_have_no_working_pressure_angle():
    # inv α_w = 0.0149043 + 2·0.3639702·(−4)/20 = 0.0149043 − 0.1455881 < 0
    with pytest.raises(ValueError, match="no working"):
        working_pressure_angle(10, 10, -2.0, -2.0, ALPHA)


def test_ring_tip_inside_its_base_circle_is_rejected():
    # z2 = 25 internal, 20°: r = 50, r_b = 50·0.9396926 = 46.98463, r_a = 50 − 4 = 46 < r_b
    with pytest.raises(ValueError, match="base circle"):
        contact_ratio(M, 10, 25, internal=True)
