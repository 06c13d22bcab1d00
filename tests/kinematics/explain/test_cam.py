"""The cam's worked solution: the numbers it puts into the formulas, in both languages."""

from __future__ import annotations

import math
import re

import pytest

from kinematics import make_plan, solve_pose
from kinematics.cams.design import make_design
from kinematics.cams.mechanism import cam_mechanism
from kinematics.cams.summary import cam_report
from kinematics.explain import explain_kinematics
from kinematics.explain.cam import CAM_PHRASES, explain_cam
from structure import analyze
from structure.cams import cam_spec_from_dict

SPEC = {
    "name": "harmonic rise",
    "omega": 10.0,
    "base_radius": 0.04,
    "follower_mass": 1.0,
    "spring": {"rate": 1000.0, "preload": 10.0},
    "follower": {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
    "segments": [
        {"law": "harmonic", "lift": 0.02, "angle": 180},
        {"law": "harmonic", "lift": -0.02, "angle": 180},
    ],
}


def test_both_languages_have_every_phrase() -> None:
    assert CAM_PHRASES["en"].keys() == CAM_PHRASES["vi"].keys()


def test_the_pressure_angle_is_worked_with_its_numbers() -> None:
    """Harmonic rise, radial roller: φ_max = asin(h/(2R_p + h)) = asin(1/6) (by hand)."""
    text = explain_cam(cam_report(make_design(cam_spec_from_dict(SPEC)), 360))
    expected = math.degrees(math.asin(1 / 6))
    found = re.search(r"⇒ φ = (-?[\d.]+)°", text)
    assert found and float(found.group(1)) == pytest.approx(expected, abs=1e-4)
    # the harmonic law's factor: C_v = π/2, printed in its step
    assert "v_max = C_v·h·ω/β = 1.5708·0.02·10/3.14159" in text
    # harmonic rise into harmonic return: a continuous at both joins, only j jumps
    assert "The fundamental law of cam design holds" in text


@pytest.mark.parametrize("lang", ["en", "vi"])
@pytest.mark.parametrize("fmt", ["text", "markdown", "latex", "html"])
def test_every_format_and_language(lang: str, fmt: str) -> None:
    for follower in (
        SPEC["follower"],
        {"motion": "oscillating", "contact": "flat", "pivot": [0.1, 0.02]},
        {"motion": "translating", "contact": "flat"},
    ):
        spec = dict(SPEC, follower=follower)
        if follower["motion"] == "oscillating":
            spec = dict(spec, follower_mass=0.0, follower_inertia=0.01,
                        segments=[{"law": "cycloidal", "lift": 10, "angle": 180},
                                  {"law": "cycloidal", "lift": -10, "angle": 180}])  # fmt: skip
        out = explain_cam(cam_report(make_design(cam_spec_from_dict(spec)), 72), lang, fmt)
        assert out and "nan" not in out.lower()


def test_the_cam_group_of_a_kinematics_solution_matches_the_law() -> None:
    """At 60° the follower's rate from the replacement equals the law's s'·ω = (h/2)·sin θ·ω."""
    design = make_design(cam_spec_from_dict(SPEC))
    report = analyze(cam_mechanism(design))
    plan = make_plan(report)
    state = solve_pose(plan, (math.radians(60.0),))
    text = explain_kinematics(report, plan, state)
    law = 0.01 * math.sin(math.radians(60.0)) * 10.0
    found = re.search(r"q̇ = (-?[\d.e-]+) m/s", text)
    assert found and float(found.group(1)) == pytest.approx(law, rel=1e-5)
    assert f"s'·θ̇ = {law:.6g} m/s" in text
    assert "v_C" not in text.split("2. Group")[0]  # the sketch's centre is no point of the cam


def test_the_forces_worked_solution_carries_the_contact_to_the_cam() -> None:
    """At 60° of the harmonic rise the balancing moment is the camshaft torque T = F_c·s'
    (power), F_c = m·s''·ω² + k·s + F_0 (the spring is not in the mechanism: F_c = m·s''·ω²)."""
    from kinematics import solve_forces
    from kinematics.explain import explain_forces

    design = make_design(cam_spec_from_dict(SPEC))
    report = analyze(cam_mechanism(design, at_deg=60.0))
    plan = make_plan(report)
    text = explain_forces(report, plan, solve_forces(plan))
    theta = math.radians(60.0)
    s1, s2 = 0.01 * math.sin(theta), 0.01 * math.cos(theta)
    torque = 1.0 * s2 * 100.0 * s1
    assert "Known loads on link 1: R_21" in text
    found = re.search(r"balancing moment M_cb = (-?[\d.e-]+) N·m", text)
    assert found and float(found.group(1)) == pytest.approx(torque, rel=1e-5)
