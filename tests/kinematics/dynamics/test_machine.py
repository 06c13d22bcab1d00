"""The machine reduced to its driver: J_r anywhere in the turn, M_r and its work, by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.dynamics.machine import reduced_machine
from kinematics.errors import DynamicsError
from kinematics.kinetostatics.forces import forces_over
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_poses
from structure.errors import MobilityError
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES
from . import fourbar_model


def _machine(*extra: str, **options):
    lines = [*fourbar_model.EDGES.splitlines(), *extra]
    return reduced_machine(analyze(parse_edgelist(lines)), **options)


def test_the_exam_s_planetary_train_has_its_reduced_inertia():
    """Exam problem 2: the carrier (J_c = 0.05) turns at 7/12 of the ring (Willis, by hand in
    fixtures/gears.toml): J = 0.05·(7/12)² = 49/2880 kg·m², constant over the turn."""
    machine = reduced_machine(analyze(read_edgelist(FIXTURES / "exam_2_planetary.edges")))
    np.testing.assert_allclose(machine.properties.inertia, 0.05 * (7 / 12) ** 2, rtol=1e-15)
    assert np.all(machine.properties.slope == 0)
    assert machine.driver == "3" and machine.massless == ("3", "2")


def test_problem_3_2_the_flywheel_s_inertia_torque():
    """Problem 3.2: J = 2 kg·m² started uniformly to 21 s⁻¹ in 3 s: ε = 7 rad/s², the inertia
    torque −J·ε = −14 N·m (the motor supplies 14 N·m, the kinetostatics' balancing moment)."""
    report = analyze(read_edgelist(FIXTURES / "ch3_3_2_flywheel.edges"))
    machine = reduced_machine(report)
    torque = machine.inertia_torque(0.0, 21 / 3)
    np.testing.assert_allclose(torque, -14.0, rtol=1e-15)
    plan = make_plan(report)
    balancing = forces_over(plan, solve_poses(plan, machine.properties.phi[:5, None]))
    np.testing.assert_allclose(balancing.balancing_moment["1"], 14.0, rtol=1e-14)


def test_the_series_reads_the_reduced_inertia_between_the_poses():
    model = fourbar_model.build()
    machine = _machine()
    phi = np.linspace(0.01, 2 * math.pi, 101) + 0.3
    values, slopes = machine.inertia(phi)
    np.testing.assert_allclose(values, model.reduced_inertia(phi), rtol=1e-11)
    scale = float(np.max(np.abs(slopes)))
    np.testing.assert_allclose(slopes, model.reduced_slope(phi), rtol=0, atol=1e-9 * scale)
    assert machine.accuracy < 1e-9


def test_work_of_a_force_is_the_change_of_its_point_s_coordinate():
    """A constant force along x on the rocker at C: W(φ) = F·(x_C(φ) − x_C(0)), the closed form's
    x_C; and a table moment on the crank: W = ∫ table, by trapezoids of the table by hand."""
    model = fourbar_model.build()
    machine = _machine(
        "cycle force 3 C angle=0 -300",
        "cycle moment 1 table=0:0,90:20,90:-10,270:-10,360:0",
        drive=None,
    )
    phi = np.radians([0.0, 45.0, 90.0, 180.0, 270.0, 360.0])
    work = machine.work(phi)
    x_c = _pin_c_x(model, phi)
    table = np.array([0.0, 0.5 * 10 * math.pi / 4, 0.5 * 20 * math.pi / 2, 0.0, 0.0, 0.0])
    table[3] = table[2] - 10 * math.pi / 2
    table[4] = table[3] - 10 * math.pi / 2
    table[5] = table[4] - 0.5 * 10 * math.pi / 2
    np.testing.assert_allclose(work, -300 * (x_c - x_c[0]) + table, rtol=0, atol=1e-9)


def _pin_c_x(model, phi: np.ndarray) -> np.ndarray:
    """x of the pin C from the rocker's angle: D + c·(cos θ3)."""
    c = math.hypot(fourbar_model.C[0] - fourbar_model.D[0], fourbar_model.C[1])
    return fourbar_model.D[0] + c * np.cos(np.array([model.angles(p)[2] for p in phi]))


def test_gravity_is_the_change_of_the_potential_energy():
    """With gravity the reduced moment's work is −Σ m·g·Δy_S (the closed form's centres)."""
    model = fourbar_model.build()
    machine = _machine("gravity 0 -9.81", drive=None)
    phi = np.linspace(0, 2 * math.pi, 9)
    heights = np.array([[y for _, y in model.centres(p)] for p in phi])
    masses = np.array([fourbar_model.M1, fourbar_model.M2, fourbar_model.M3])
    potential = 9.81 * heights @ masses
    np.testing.assert_allclose(machine.work(phi), -(potential - potential[0]), atol=1e-11)


def test_with_no_drive_the_loads_mean_is_assumed():
    machine = _machine("cycle moment 3 -2")
    assert machine.drive is not None
    # the rocker's moment −2 does no net work over a turn (the rocker swings back)
    assert machine.assumed_drive == pytest.approx(0.0, abs=1e-12)
    crank = _machine("cycle moment 1 formula=-2-sin(phi)")
    assert crank.assumed_drive == pytest.approx(2.0, rel=1e-12)


def test_the_reduced_moment_reads_its_laws():
    machine = _machine("drive 1 motor=40,100", "cycle moment 1 -5")
    np.testing.assert_allclose(machine.moment(np.array([0.1, 2.0]), 50.0), [15.0, 15.0])
    assert machine.at(2.0, 50.0)[2] == pytest.approx(15.0, rel=1e-14)
    assert machine.moment(np.array([2.0]), 50.0, drive=False)[0] == pytest.approx(-5.0)
    assert machine.uses_omega


@pytest.mark.parametrize(
    ("edges", "error", "said"),
    [
        ("fivebar_two_drivers.edges", MobilityError, "W = 2"),
        ("ch3_3_1_slider_power.edges", DynamicsError, "slides"),
        ("cam_flat_follower.edges", Exception, "sketch pose only"),
    ],
)
def test_what_has_no_cycle_is_named(edges: str, error: type, said: str):
    with pytest.raises(error, match=said):
        reduced_machine(analyze(read_edgelist(FIXTURES / edges)))


def test_a_formula_that_is_not_finite_is_named():
    with pytest.raises(DynamicsError, match="not finite at φ = 0°"):
        _machine("cycle moment 1 formula=1/phi", drive=None).moment(np.array([0.0]), 0.0)
