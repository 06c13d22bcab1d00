"""Force closure against a hand-worked case.

The case is a classic exercise on cam dynamics (Shigley & Uicker, *Theory of Machines and
Mechanisms*, ch. "Cam dynamics", forced-closure exercise): a plate cam drives a radial
translating follower with cycloidal rise and return of 10 mm over 120° each, two equal dwells,
at 1000 rev/min; follower mass 1.8 kg; spring 15 N/mm compressed 2.5 mm at assembly. Worked
by hand at θ = 100° (x = 5/6 of the rise, sin 300° = −√3/2, cos 300° = 1/2):

    ω = 1000·2π/60 = 104.71976 rad/s, β = 2π/3
    s   = h·(x − sin 2πx/(2π))       = 0.01·(5/6 + √3/(4π))      = 9.71165 mm
    s'  = h/β·(1 − cos 2πx)          = 0.01·3/(2π)·(1/2)           = 2.38732 mm/rad
    s'' = 2πh/β²·sin 2πx             = −(0.09/(2π))·√3/2           = −12.4049 mm/rad²
    F_c = m·s''·ω² + k·s + F0        = −244.863 + 145.675 + 37.5   = −61.688 N
    T   = F_c·s'                     = −0.147269 N·m

F_c < 0: at 1000 rev/min the spring is too weak and the follower leaves the cam there.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.cams.closure import force_closure
from kinematics.cams.design import make_design
from kinematics.cams.program import program_values
from structure.cams import cam_spec_from_dict

OMEGA = 1000 * 2 * math.pi / 60


def _design(spring: dict | None = None, **more):
    return make_design(
        cam_spec_from_dict(
            {
                "base_radius": 0.03,
                "omega": OMEGA,
                "follower": {"motion": "translating", "contact": "flat"},
                "follower_mass": 1.8,
                "spring": spring or {"rate": 15000.0, "preload": 37.5},
                "segments": [
                    {"law": "cycloidal", "lift": 0.01, "angle": 120},
                    {"law": "dwell", "angle": 60},
                    {"law": "cycloidal", "lift": -0.01, "angle": 120},
                    {"law": "dwell", "angle": 60},
                ],
                **more,
            }
        )
    )


def test_the_hand_worked_point() -> None:
    closure = force_closure(_design(), 3600)
    k = 1000  # θ = 100°
    assert math.degrees(closure.theta[k]) == pytest.approx(100.0)
    assert closure.axial[k] == pytest.approx(-61.688, abs=1e-3)
    assert closure.contact[k] == pytest.approx(-61.688, abs=1e-3)  # flat face: φ = 0
    assert closure.torque[k] == pytest.approx(-0.147269, abs=1e-6)
    assert closure.contact_lost
    assert any(a <= 100.0 <= b for a, b in closure.lost_at)


def test_jump_speed_preload_and_rate_by_brute_force() -> None:
    """ω_jump² = min over s'' < 0 of (k·s + F0)/(−m·s''); the preload and rate that hold contact
    at 1000 rev/min from their definitions, on a fine sweep of their own."""
    design = _design()
    closure = force_closure(design, 36000)
    theta = np.radians(np.arange(36000) / 100)
    s, _, s2, _ = program_values(design.program, theta)
    m, k, f0 = 1.8, 15000.0, 37.5
    pulling = s2 < 0
    jump = math.sqrt(np.min((k * s[pulling] + f0) / (-m * s2[pulling])))
    assert closure.jump_speed == pytest.approx(jump, rel=1e-12)
    assert closure.jump_speed < OMEGA
    preload = np.max(-m * s2 * OMEGA**2 - k * s)
    assert closure.preload_needed == pytest.approx(preload, rel=1e-12)
    short = -m * s2 * OMEGA**2 - f0 > 0
    assert closure.rate_needed == pytest.approx(
        np.max((-m * s2[short] * OMEGA**2 - f0) / s[short]), rel=1e-12
    )
    # with that preload, contact holds all round at 1000 rev/min
    held = force_closure(_design({"rate": k, "preload": closure.preload_needed * (1 + 1e-9)}))
    assert not held.contact_lost
    assert held.jump_speed >= OMEGA * (1 - 1e-9)


def test_a_spring_that_cannot_hold_at_rest_and_one_that_never_lets_go() -> None:
    pulled = force_closure(_design({"rate": 1000.0, "preload": 0.0}, load=-20.0))
    assert pulled.jump_speed == 0.0  # the load pulls it off the base circle at any speed
    light = force_closure(_design(follower_mass=0.0))
    assert light.jump_speed is None


def test_the_camshaft_torque_balances_the_power() -> None:
    """T·ω = F_c·v at every angle (v = s'·ω), and the torque averages to zero over a turn
    of a conservative spring and no load (the work of the spring and inertia returns)."""
    closure = force_closure(_design(), 3600)
    design = _design()
    _, s1, _, _ = program_values(design.program, closure.theta)
    np.testing.assert_allclose(closure.torque * OMEGA, closure.axial * s1 * OMEGA, rtol=1e-14)
    assert abs(np.mean(closure.torque)) < 1e-9 * np.max(np.abs(closure.torque))


def test_an_oscillating_follower_contact_force_is_its_moment_over_the_normal_arm() -> None:
    design = make_design(
        cam_spec_from_dict(
            {"base_radius": 0.04, "omega": 20.0, "follower_inertia": 0.002,
             "spring": {"rate": 5.0, "preload": 0.5},
             "follower": {"motion": "oscillating", "contact": "roller", "pivot": [0.1, 0.02],
                          "arm": 0.08, "roller_radius": 0.01},
             "segments": [{"law": "cycloidal", "lift": 15, "angle": 180},
                          {"law": "cycloidal", "lift": -15, "angle": 180}]}
        )
    )  # fmt: skip
    closure = force_closure(design, 720)
    from kinematics.cams.profile import cam_geometry

    g = cam_geometry(design, closure.theta)
    moment = 0.002 * g.s2 * 400 + 5.0 * g.s + 0.5
    np.testing.assert_allclose(closure.axial, moment, rtol=1e-14)
    # the contact force along the normal through the roller's centre gives that moment
    arm = g.point - np.array([0.1, 0.02])
    torque_of_force = closure.contact * (arm[:, 0] * g.normal[:, 1] - arm[:, 1] * g.normal[:, 0])
    np.testing.assert_allclose(design.layout.swing * torque_of_force, moment, rtol=1e-12)
