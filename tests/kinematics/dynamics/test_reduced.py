"""Reduced moment of inertia and its slope over a turn, against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.dynamics.reduced import reduced_inertia_over, reduced_properties
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_poses
from structure.errors import MobilityError
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES
from . import fourbar_model

CRANK_SLIDER = """
driver 1 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0.1 0
point C 0.4 0
mass 1 0 0.01 A
mass 3 2 0 C
"""


def test_crank_slider_reduced_inertia_follows_the_slider_speed_ratio():
    # crank r = 0.1 (J1 = 0.01 about A), rod l = 0.3 without mass, slider m3 = 2 kg:
    # J_red(φ) = J1 + m3·(dx_C/dφ)², dx_C/dφ = −r·sinφ − r²·sinφ·cosφ/√(l² − r²·sin²φ)
    plan = make_plan(analyze(parse_edgelist(CRANK_SLIDER.strip().splitlines())))
    phi = np.linspace(0, 2 * math.pi, 73)
    j = reduced_inertia_over(plan, solve_poses(plan, phi[:, None]))
    r, rod = 0.1, 0.3
    dx = -r * np.sin(phi) - r * r * np.sin(phi) * np.cos(phi) / np.sqrt(
        rod * rod - (r * np.sin(phi)) ** 2
    )
    np.testing.assert_allclose(j, 0.01 + 2.0 * dx * dx, rtol=1e-10, atol=1e-12)


def test_the_slope_is_the_closed_form_s_derivative():
    """dJ_r/dφ from the accelerations against the closed form's derivative (central differences
    of J_r(φ) written out by hand: an independent derivation)."""
    r, rod, j1, m3 = 0.1, 0.3, 0.01, 2.0

    def closed(phi):
        dx = -r * np.sin(phi) - r * r * np.sin(phi) * np.cos(phi) / np.sqrt(
            rod * rod - (r * np.sin(phi)) ** 2
        )
        return j1 + m3 * dx * dx

    text = CRANK_SLIDER.strip().splitlines()
    phi = np.linspace(0, 2 * math.pi, 37)
    props = reduced_properties(make_plan(analyze(parse_edgelist(text))), phi)
    h = 1e-5
    expected = (closed(phi + h) - closed(phi - h)) / (2 * h)
    np.testing.assert_allclose(props.slope, expected, rtol=0, atol=1e-8)
    assert props.massless == ("2",)


def test_the_four_bar_against_its_closed_form():
    model = fourbar_model.build()
    plan = make_plan(analyze(parse_edgelist(fourbar_model.EDGES.splitlines())))
    phi = np.linspace(0, 2 * math.pi, 25)
    props = reduced_properties(plan, phi)
    np.testing.assert_allclose(props.inertia, model.reduced_inertia(phi), rtol=1e-11)
    scale = float(np.max(np.abs(props.slope)))
    np.testing.assert_allclose(props.slope, model.reduced_slope(phi), rtol=0, atol=1e-11 * scale)
    assert set(props.shares) == {"1", "2", "3"}
    np.testing.assert_allclose(sum(props.shares.values()), props.inertia, rtol=1e-14)


def test_the_readme_s_sweep_goes_in_as_it_is():
    """Issue 22, item 17: ``reduced_inertia_over(plan, sweep(plan))`` raised AttributeError."""
    import kinematics

    plan = kinematics.make_plan(analyze(parse_edgelist(CRANK_SLIDER.strip().splitlines())))
    turn = kinematics.sweep(plan, steps=360)
    j = kinematics.reduced_inertia_over(plan, turn)
    expected = reduced_properties(plan, turn.inputs[:, 0]).inertia
    assert j.shape == (360,)
    np.testing.assert_array_equal(j, expected)
    # a driver standing still in the file (omega=0, as problem 3.2's) is no obstacle
    still = kinematics.make_plan(analyze(read_edgelist(FIXTURES / "ch3_3_2_flywheel.edges")))
    assert (
        kinematics.reduced_inertia_over(still, kinematics.sweep(still, steps=4)).tolist()
        == [2.0] * 4
    )


def test_the_old_module_path_still_imports():
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        from kinematics.kinetostatics.inertia import reduced_inertia_over as old
    assert old is reduced_inertia_over
    assert caught and caught[0].category is DeprecationWarning


def test_two_drivers_are_refused():
    plan = make_plan(analyze(read_edgelist(FIXTURES / "fivebar_two_drivers.edges")))
    with pytest.raises(MobilityError, match="one driver; this mechanism has 2"):
        reduced_properties(plan)
