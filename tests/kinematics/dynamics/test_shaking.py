"""The shaking force and moment on the frame, against closed forms and the kinetostatics."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from kinematics.dynamics.reduced import reduced_properties
from kinematics.dynamics.shaking import shaking
from kinematics.kinetostatics.forces import forces_over
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_poses
from structure.readwrite.edgelist import parse_edgelist
from structure.report import analyze

from . import fourbar_model

OMEGA = 12.0


def _fourbar():
    mechanism = parse_edgelist(fourbar_model.EDGES.splitlines())
    plan = make_plan(analyze(mechanism))
    phi = np.linspace(0, 2 * math.pi, 24, endpoint=False)
    return mechanism, plan, phi, shaking(reduced_properties(plan, phi), mechanism, OMEGA)


def test_the_four_bar_s_shaking_is_minus_the_mass_times_acceleration():
    """F = −Σ m·S''·ω², M_A = −Σ (J·θk''·ω² + S × m·S''·ω²), from the closed-form four-bar."""
    _, _, phi, found = _fourbar()
    model = fourbar_model.build()
    parts = model.rates(phi)
    masses = (fourbar_model.M1, fourbar_model.M2, fourbar_model.M3)
    inertias = (fourbar_model.J1, fourbar_model.J2, fourbar_model.J3)
    force = -sum(m * x[2] for m, x in zip(masses, parts, strict=True)).T * OMEGA**2
    moment = -sum(
        (j * x[5] + m * (x[0][0] * x[2][1] - x[0][1] * x[2][0])) * OMEGA**2
        for m, j, x in zip(masses, inertias, parts, strict=True)
    )
    np.testing.assert_allclose(found.force, force, atol=1e-10 * np.max(np.abs(force)))
    np.testing.assert_allclose(found.moment, moment, atol=1e-10 * np.max(np.abs(moment)))
    assert found.about == (0.0, 0.0) and found.about_name == "A"
    assert found.force_max == pytest.approx(np.max(np.hypot(*force.T)))


def test_the_shaking_force_is_what_the_frame_s_pins_carry():
    """The kinetostatics, group by group at the same constant speed: the forces the links exert
    on the frame at its pins add up to the shaking force (no loads, no gravity)."""
    _, plan, phi, found = _fourbar()
    driver = dataclasses.replace(plan.drivers[0], speed=OMEGA, acceleration=0.0)
    running = dataclasses.replace(plan, drivers=(driver,))
    reactions = forces_over(running, solve_poses(running, phi[:, None])).reactions
    ground = plan.mechanism.ground
    on_frame = np.zeros((len(phi), 2))
    for _, (a, b), _, force, _ in reactions:
        if b == ground:
            on_frame += force
        elif a == ground:
            on_frame -= force
    np.testing.assert_allclose(found.force, on_frame, atol=1e-9 * found.force_max)


def test_the_moment_is_taken_about_the_point_asked_for():
    mechanism, plan, phi, found = _fourbar()
    about_d = shaking(reduced_properties(plan, phi), mechanism, OMEGA, about="D")
    # M_D = M_A + (A − D) × F
    d = np.array(fourbar_model.D)
    shifted = found.moment + (-d[0]) * found.force[:, 1] - (-d[1]) * found.force[:, 0]
    np.testing.assert_allclose(about_d.moment, shifted, atol=1e-10 * found.moment_max)
    np.testing.assert_allclose(about_d.force, found.force)
