"""Bevel differential with friction against Lê Hoàng Anh et al. (2016), LIFAN LF3070G1.

Printed in the paper: pinion torque M1 = 784.7202 N·m, F_t1 = 9895.6 N,
F_t2 = 14000 N; friction moments planet/cross-shaft 1.3 N·m, planet/thrust
washer 5.6132 N·m, their sum printed as M3ms = 7 N·m; side gear/case
M4ms = M5ms = 35.2304 N·m; rolling-resistance moments M_Ctr = M_Cph = 191.25;
F_t3 = 7099.5 N, F_t4 = 6900.5 N; M4 = 580.7405 N·m (left), M5 = 604.0195 N·m
(right). Not printed, inferred (see :mod:`kinematics.gears.differential`): the
side-gear radius r_s, the planet radius r_p and the case torque F_t2·r_s.

Inconsistencies in the printed values, tested below through the model:
1.3 + 5.6132 = 6.9132, not 7 (eq. (21) uses 7); 191.25 is G·f in newtons, the
wheel radius of eq. (22) is missing. M1 is the pinion torque, not the case
torque (1637.7208 N·m); the model has no pinion, so that is documented in
:mod:`kinematics.gears.differential`, not tested here.
"""

from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematics.gears.differential import DifferentialSplit, bevel_differential_split

# printed in the paper
F_T2 = 14000.0
M_PLANET_PIN = 1.3
M_PLANET_WASHER = 5.6132
M3MS_PRINTED = 7.0
M_SIDE_CASE = 35.2304
M_ROLL = 191.25
F_T3, F_T4 = 7099.5, 6900.5
M4, M5 = 580.7405, 604.0195

# inferred from the printed numbers
R_S = (M4 + M5 + 2 * M_ROLL + 2 * M_SIDE_CASE) / F_T2  # = 1637.7208 / 14000
M_CASE = F_T2 * R_S
R_P = M3MS_PRINTED * R_S / (M5 - M4)


def paper_split(**overrides) -> DifferentialSplit:
    kwargs = {
        "side_radius": R_S,
        "planet_radius": R_P,
        "planet_friction": M3MS_PRINTED,
        "side_friction": M_SIDE_CASE,
        "faster": "left",
        "resistance_torques": (M_ROLL, M_ROLL),
        "side_friction_model": "paper",
    }
    kwargs.update(overrides)
    case_torque = kwargs.pop("case_torque", M_CASE)
    return bevel_differential_split(case_torque, **kwargs)


# --------------------------------------------------------------------------- the paper


def test_inferred_inputs():
    # r_s and r_p are inferred from the printed torques (see kinematics.gears.differential);
    # through the model they must give back what the paper prints besides: the force
    # difference F_t3 − F_t4 = M3ms / r_p and the ratio of the torque difference to it,
    # (M5 − M4) / (F_t3 − F_t4) = 0.1169799 m = r_s, both to the printed precision
    assert round(R_S, 8) == 0.11698006
    assert round(R_P, 8) == 0.03517593
    s = paper_split()
    assert s.force_right - s.force_left == pytest.approx(F_T3 - F_T4, rel=2e-6)
    torque_over_force = (s.torque_right - s.torque_left) / (s.force_right - s.force_left)
    assert torque_over_force == pytest.approx((M5 - M4) / (F_T3 - F_T4), rel=2e-6)
    # the case torque F_t2·r_s is what the half-shafts, the rolling resistance and the
    # paper's side-gear friction (eq. (24)) take together
    taken = s.torque_left + s.torque_right + 2 * M_ROLL + 2 * M_SIDE_CASE
    assert taken == pytest.approx(1637.7208, abs=1e-9)


def test_paper_forces():
    s = paper_split()
    assert round(s.cross_shaft_force, 1) == F_T2
    assert round(s.force_right, 1) == F_T3  # paper's F_t3, right (slower) side
    assert round(s.force_left, 1) == F_T4  # paper's F_t4, left (faster) side
    assert s.force_left + s.force_right == pytest.approx(F_T2)


def test_paper_half_shaft_torques():
    s = paper_split()
    assert round(s.torque_left, 4) == M4
    assert round(s.torque_right, 4) == M5
    assert s.torque_fast == s.torque_left and s.torque_slow == s.torque_right
    assert s.bias_ratio == pytest.approx(M5 / M4)
    assert round(s.bias_ratio, 4) == 1.0401


def test_paper_planet_friction_sum_is_rounded():
    # printed "M3ms = 1.3 + 5.6132 = 7 N·m": the sum is 6.9132, and eq. (21) used 7
    derived = M_PLANET_PIN + M_PLANET_WASHER
    assert derived == pytest.approx(6.9132, abs=1e-12)
    assert round(derived) == M3MS_PRINTED
    s = paper_split(planet_friction=derived)
    assert round(s.force_right, 2) == 7098.27
    assert round(s.force_left, 2) == 6901.73
    assert round(s.torque_right, 4) == 603.8752
    assert round(s.torque_left, 4) == 580.8848


def test_paper_rolling_resistance_lowers_each_half_shaft_torque():
    # M_C = G·f·r_b with G = 2550/2 kg · 10 m/s², f = 0.015 and the wheel radius r_b left out
    # (= 1 m): each half-shaft torque is that much lower than without rolling resistance,
    # and the forces, set by the case torque and the friction, do not change
    g_f_rb = 2550 / 2 * 10 * 0.015 * 1.0
    free = paper_split(resistance_torques=(0.0, 0.0))
    loaded = paper_split()
    assert free.torque_left - loaded.torque_left == pytest.approx(g_f_rb)
    assert free.torque_right - loaded.torque_right == pytest.approx(g_f_rb)
    assert (loaded.force_left, loaded.force_right) == (free.force_left, free.force_right)


def test_four_planets_with_load_shared_friction_match_the_lumped_paper_model():
    lumped = paper_split()
    four = paper_split(n_planets=4, planet_friction=M3MS_PRINTED / 4)
    for field in ("cross_shaft_force", "force_left", "force_right", "torque_left", "torque_right"):
        assert getattr(four, field) == pytest.approx(getattr(lumped, field), rel=1e-12)


def test_paper_data_in_the_relative_model():
    # the slower side gear is dragged forward by the case, not braked
    s = paper_split(side_friction_model="relative")
    assert s.torque_left == pytest.approx(M4)
    assert s.torque_right == pytest.approx(M5 + 2 * M_SIDE_CASE)
    assert s.torque_left + s.torque_right == pytest.approx(M_CASE - 2 * M_ROLL)


# --------------------------------------------------------------------------- independent checks


@pytest.mark.parametrize("model", ["relative", "paper"])
@pytest.mark.parametrize("faster", ["left", "right"])
@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_no_friction_splits_evenly(model, faster, n):
    s = bevel_differential_split(
        1234.5,
        side_radius=0.06,
        planet_radius=0.03,
        planet_friction=0.0,
        side_friction=0.0,
        faster=faster,
        n_planets=n,
        side_friction_model=model,
    )
    assert s.force_left == s.force_right == pytest.approx(1234.5 / 0.06 / 2)
    assert s.torque_left == s.torque_right == pytest.approx(1234.5 / 2)
    assert s.bias_ratio == pytest.approx(1.0)


def test_mirror_symmetry():
    left = paper_split(faster="left", side_friction_model="relative")
    right = paper_split(faster="right", side_friction_model="relative")
    assert (right.force_left, right.force_right) == (left.force_right, left.force_left)
    assert (right.torque_left, right.torque_right) == (left.torque_right, left.torque_left)
    assert right.bias_ratio == left.bias_ratio
    assert right.torque_fast == right.torque_right


def test_bias_ratio_closed_form():
    m, r_s, r_p, m_p, m_sc, n = 900.0, 0.07, 0.028, 3.0, 20.0, 4
    s = bevel_differential_split(
        m,
        side_radius=r_s,
        planet_radius=r_p,
        planet_friction=m_p,
        side_friction=m_sc,
        faster="right",
        n_planets=n,
    )
    loss = n * m_p * r_s / (2 * r_p) + m_sc  # torque moved from fast to slow side
    assert s.torque_right == pytest.approx(m / 2 - loss)
    assert s.torque_left == pytest.approx(m / 2 + loss)
    assert s.bias_ratio == pytest.approx((m / 2 + loss) / (m / 2 - loss))


finite = st.floats(-5000, 5000, allow_nan=False)
radius = st.floats(0.01, 0.2)
friction = st.floats(0.0, 50.0)


@settings(max_examples=200, deadline=None)
@given(
    m=finite,
    r_s=radius,
    r_p=radius,
    m_p=friction,
    m_sc=friction,
    n=st.integers(1, 6),
    faster=st.sampled_from(["left", "right"]),
    mc_l=st.floats(0, 300),
    mc_r=st.floats(0, 300),
)
def test_sum_of_half_shaft_torques(m, r_s, r_p, m_p, m_sc, n, faster, mc_l, mc_r):
    common = {
        "side_radius": r_s,
        "planet_radius": r_p,
        "planet_friction": m_p,
        "side_friction": m_sc,
        "faster": faster,
        "n_planets": n,
        "resistance_torques": (mc_l, mc_r),
    }
    rel = bevel_differential_split(m, side_friction_model="relative", **common)
    pap = bevel_differential_split(m, side_friction_model="paper", **common)
    tol = 1e-9 * (abs(m) + 1e4)
    # friction internal (planet friction acts about axes perpendicular to the axle)
    assert rel.torque_left + rel.torque_right == pytest.approx(m - mc_l - mc_r, abs=tol)
    # the paper's eq. (24) loses 2·M_sc on top
    assert pap.torque_left + pap.torque_right == pytest.approx(m - 2 * m_sc - mc_l - mc_r, abs=tol)
    mc_fast, mc_slow = (mc_l, mc_r) if faster == "left" else (mc_r, mc_l)
    shaft_fast, shaft_slow = rel.torque_fast + mc_fast, rel.torque_slow + mc_slow
    assert shaft_slow >= shaft_fast - tol  # friction moves torque to the slower side
    assert shaft_slow - shaft_fast == pytest.approx(n * m_p * r_s / r_p + 2 * m_sc, abs=tol)


def _power_terms(s: DifferentialSplit, m, r_s, r_p, w_case, w_fast, resist):
    w_slow = 2 * w_case - w_fast
    w_left, w_right = (w_fast, w_slow) if s.faster == "left" else (w_slow, w_fast)
    w_planet = (w_fast - w_case) * r_s / r_p  # planet spin on the cross-shaft
    p_in = m * w_case
    p_out = (s.torque_left + resist[0]) * w_left + (s.torque_right + resist[1]) * w_right
    return p_in, p_out, w_planet


@settings(max_examples=200, deadline=None)
@given(
    m=st.floats(0, 5000),
    r_s=radius,
    r_p=radius,
    m_p=friction,
    m_sc=friction,
    n=st.integers(1, 6),
    faster=st.sampled_from(["left", "right"]),
    w_case=st.floats(0.1, 100),
    dw=st.floats(0.0, 50),
    mc=st.floats(0, 300),
)
def test_power_balance(m, r_s, r_p, m_p, m_sc, n, faster, w_case, dw, mc):
    w_fast = w_case + dw
    common = {
        "side_radius": r_s,
        "planet_radius": r_p,
        "planet_friction": m_p,
        "side_friction": m_sc,
        "faster": faster,
        "n_planets": n,
        "resistance_torques": (mc, 0.5 * mc),
    }
    tol = 1e-9 * (abs(m) + 1e4) * (w_case + dw + 1)

    rel = bevel_differential_split(m, side_friction_model="relative", **common)
    p_in, p_out, w_p = _power_terms(rel, m, r_s, r_p, w_case, w_fast, (mc, 0.5 * mc))
    loss = n * m_p * w_p + 2 * m_sc * (w_fast - w_case)
    assert loss >= 0
    assert p_in == pytest.approx(p_out + loss, abs=tol)

    pap = bevel_differential_split(m, side_friction_model="paper", **common)
    p_in, p_out, w_p = _power_terms(pap, m, r_s, r_p, w_case, w_fast, (mc, 0.5 * mc))
    # side-gear friction as if against a fixed housing: dissipates even when dw = 0
    assert p_in == pytest.approx(p_out + n * m_p * w_p + 2 * m_sc * w_case, abs=tol)


def test_paper_power_balance_at_a_turn():
    # case at 30 rad/s, left (outer) wheel at 33 rad/s
    w_case, w_fast = 30.0, 33.0
    s = paper_split(side_friction_model="relative")
    p_in, p_out, w_p = _power_terms(s, M_CASE, R_S, R_P, w_case, w_fast, (M_ROLL, M_ROLL))
    assert w_p == pytest.approx(3.0 * R_S / R_P)
    assert p_in - p_out == pytest.approx(M3MS_PRINTED * w_p + 2 * M_SIDE_CASE * 3.0)
    assert round(p_in - p_out, 2) == 281.22


# --------------------------------------------------------------------------- API


def test_result_is_frozen():
    s = paper_split()
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.torque_left = 0.0  # type: ignore[misc]


def test_zero_fast_torque_gives_infinite_bias():
    s = bevel_differential_split(
        1.0,
        side_radius=0.1,
        planet_radius=0.05,
        planet_friction=0.5,
        side_friction=0.0,
        faster="left",
    )
    assert s.torque_left == pytest.approx(0.0)
    assert s.bias_ratio == math.inf


@pytest.mark.parametrize(
    "overrides",
    [
        {"side_radius": 0.0},
        {"planet_radius": -0.01},
        {"planet_friction": -1.0},
        {"side_friction": math.nan},
        {"case_torque": math.inf},
        {"n_planets": 0},
        {"n_planets": 2.0},
        {"n_planets": True},
        {"faster": "both"},
        {"side_friction_model": "absolute"},
        {"resistance_torques": (1.0,)},
        {"resistance_torques": (1.0, math.nan)},
    ],
)
def test_rejects_bad_inputs(overrides):
    with pytest.raises(ValueError):
        paper_split(**overrides)
