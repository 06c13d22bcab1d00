"""The equation of motion: start-up, run-down and steady running, against hand-worked motions."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.dynamics.loads import parse_drive
from kinematics.dynamics.machine import reduced_machine
from kinematics.dynamics.motion import Limits, run_down, start_up, steady_running
from kinematics.errors import DynamicsError, IntegrationError, NoSteadyRunningError, StallError
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES
from . import fourbar_model

#: a crank press: crank 0.1 m with a flywheel of 20 kg·m², rod 0.4 m (3 kg), ram 10 kg; the
#: working stroke pushes back with 5000 N from 100° to 170° of the crank
PRESS = """name crank press
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0.1 0
point C 0.5 0
point S2 0.3 0
mass 1 0 20 A
mass 2 3 0.04 S2
mass 3 10 0 C
cycle force 3 C angle=0 table=0:0,100:0,100:5000,170:5000,170:0,360:0
""".splitlines()


def _press(drive: str | None = None):
    lines = PRESS + ([f"drive 1 {drive}"] if drive else [])
    return reduced_machine(analyze(parse_edgelist(lines)))


def _press_mean_load() -> float:
    """The working stroke's mean torque on the crank, by hand: F·|Δx|/2π, with the ram at
    x = r·cos φ + √(l² − r²·sin² φ)."""
    r, rod = 0.1, 0.4

    def x(deg: float) -> float:
        p = math.radians(deg)
        return r * math.cos(p) + math.sqrt(rod * rod - (r * math.sin(p)) ** 2)

    return 5000 * (x(100) - x(170)) / (2 * math.pi)


def test_a_free_run_keeps_its_kinetic_energy():
    machine = reduced_machine(analyze(parse_edgelist(fourbar_model.EDGES.splitlines())), drive=None)
    run = run_down(machine, 10.0, limits=Limits(turns=10))
    assert run.ending == "turns" and len(run.turns) == 10
    inertia, _ = machine.inertia(run.phi)
    energy = 0.5 * inertia * run.omega**2
    assert np.max(np.abs(energy / energy[0] - 1)) < 1e-9
    assert np.ptp(run.omega) > 1.0  # the speed swings as J_r does: the energy does not


@pytest.mark.slow
def test_a_free_run_keeps_its_kinetic_energy_over_100_turns():
    machine = reduced_machine(analyze(parse_edgelist(fourbar_model.EDGES.splitlines())), drive=None)
    run = run_down(machine, 10.0, limits=Limits(turns=100))
    assert len(run.turns) == 100
    inertia, _ = machine.inertia(run.phi)
    energy = 0.5 * inertia * run.omega**2
    assert np.max(np.abs(energy / energy[0] - 1)) < 1e-8


def test_problem_3_2_the_flywheel_started_by_its_torque():
    """Problem 3.2: J = 2 kg·m² under the motor's 14 N·m from rest: ε = 7 rad/s², so ω = 21 s⁻¹
    after 3 s, and turn k ends at t_k = √(2·2πk/7)."""
    report = analyze(read_edgelist(FIXTURES / "ch3_3_2_flywheel.edges"))
    machine = reduced_machine(report, drive=parse_drive("14"))
    run = start_up(machine, dense=True, limits=Limits(turns=6))
    k = np.arange(1, 7)
    np.testing.assert_allclose(run.turns, np.sqrt(4 * math.pi * k / 7), rtol=1e-10)
    phi, omega = run.at(3.0)
    assert omega[0] == pytest.approx(21.0, rel=1e-10)
    assert phi[0] == pytest.approx(0.5 * 7 * 9, rel=1e-10)


def test_a_constant_brake_stops_a_flywheel_where_its_energy_runs_out():
    """J = 2 at 20 rad/s against −4 N·m: it stops after ½·J·ω²/|M| = 100 rad, in J·ω/|M| = 10 s."""
    lines = [*(FIXTURES / "ch3_3_2_flywheel.edges").read_text().splitlines(), "cycle moment 1 -4"]
    machine = reduced_machine(analyze(parse_edgelist(lines)), drive=None)
    run = run_down(machine, 20.0)
    assert run.ending == "stopped"
    assert run.phi[-1] == pytest.approx(100.0, rel=1e-9)
    assert run.duration == pytest.approx(10.0, rel=1e-9)
    assert len(run.turns) == int(100 // (2 * math.pi))


def test_khurmi_s_three_crank_engine():
    """Khurmi & Gupta, *Theory of Machines*, ch. 16 (turning moment diagrams and flywheel): a
    three-crank engine T = 25 − 7.5·sin 3θ kN·m drives a machine that resists with
    Tr = 25 + 3.6·sin θ kN·m; flywheel 360 kg·m², mean speed 450 rpm. By hand: the excess energy
    ∫(T − Tr) dθ = 2.5·cos 3θ + 3.6·cos θ + C kN·m swings from 6.1 (θ = 0) to −6.1 (θ = π), so
    ΔE = 12.2 kN·m; with a constant inertia ½·J·(ω_max² − ω_min²) = ΔE and ω_m = (ω_max +
    ω_min)/2 give δ = ΔE/(J·ω_m²) = 0.01526 exactly (the book: 1.53 %)."""
    omega = 450 * 2 * math.pi / 60
    lines = [
        "name three-crank engine",
        f"driver 1 omega={omega!r}",
        "0 1 R O",
        "point O 0 0",
        "mass 1 0 360 O",
        "drive 1 formula=25000-7500*sin(3*phi)",
        "cycle moment 1 formula=-25000-3600*sin(phi)",
    ]
    machine = reduced_machine(analyze(parse_edgelist(lines)))
    steady = steady_running(machine)
    assert steady.method == "energy"
    assert steady.omega_mean == pytest.approx(omega, rel=1e-12)
    assert steady.delta == pytest.approx(12200 / (360 * omega**2), rel=1e-9)
    assert steady.delta == pytest.approx(0.01526, abs=5e-6)
    assert np.argmax(steady.omega) == 0 and steady.phi[np.argmin(steady.omega)] == pytest.approx(
        math.pi
    )


def test_steady_running_is_where_a_long_start_up_goes():
    machine = _press("motor=1100,10.5")
    steady = steady_running(machine)
    assert steady.method == "shooting"
    run = start_up(machine, limits=Limits(turns=20))  # 20 turns ≈ 65 time constants J/(M0/W0)
    assert run.ending == "turns"
    assert run.omega[-1] == pytest.approx(steady.omega[0], rel=1e-8)
    assert steady.omega[-1] == pytest.approx(steady.omega[0], rel=1e-9)  # periodic
    assert steady.period == pytest.approx(run.turns[-1] - run.turns[-2], rel=1e-7)
    # the mean speed is where the motor's mean torque meets the loads' (to first order in δ)
    balanced = 10.5 * (1 - _press_mean_load() / 1100)
    assert steady.omega_time_mean == pytest.approx(balanced, rel=0.01)
    # and started with the steady running in view, the start-up ends there
    done = start_up(machine, steady=steady)
    assert done.ending == "steady" and len(done.turns) < 20


def test_a_weak_drive_stalls_and_says_where_and_by_how_much():
    machine = _press("motor=40,10.5")
    with pytest.raises(StallError) as info:
        steady_running(machine)
    shortfall = _press_mean_load() - 40
    assert info.value.shortfall == pytest.approx(shortfall, rel=1e-6)
    message = str(info.value)
    assert "stops at φ = " in message and "short by" in message
    assert f"{shortfall:.6g} N·m on average" in message
    # where: in the working stroke, 100°–170° of the turn
    assert 100 <= math.degrees(info.value.phi) % 360 <= 170
    with pytest.raises(StallError):
        start_up(machine)


def test_a_drive_that_outruns_the_loads_has_no_steady_running():
    machine = _press("100")
    with pytest.raises(NoSteadyRunningError, match="speeds up without end") as info:
        steady_running(machine)
    assert f"a constant drive of {_press_mean_load():.6g} N·m balances" in str(info.value)


def test_with_no_drive_the_mean_load_drives_it_at_the_file_s_speed():
    machine = _press()
    assert machine.assumed_drive == pytest.approx(_press_mean_load(), rel=1e-9)
    steady = steady_running(machine)
    assert steady.omega_mean == pytest.approx(10.0, rel=1e-12)
    assert steady_running(machine, speed=5.0).omega_mean == pytest.approx(5.0, rel=1e-12)


@pytest.mark.parametrize(
    ("lines", "said"),
    [
        (["driver 1", "0 1 R O", "point O 0 0", "mass 1 0 1 O", "drive 1 2"], "give it"),
        (["driver 1 omega=3", "0 1 R O", "point O 0 0", "drive 1 0"], "no mass"),
        (["driver 1 omega=-3", "0 1 R O", "point O 0 0", "mass 1 0 1 O", "drive 1 0"], "clockwise"),
    ],
)
def test_what_cannot_run_steadily_is_named(lines: list[str], said: str):
    with pytest.raises(DynamicsError, match=said):
        steady_running(reduced_machine(analyze(parse_edgelist(lines))))


def test_the_inertia_must_not_vanish():
    """A crank–slider whose only mass is the ram: J_r = 0 at the dead centres."""
    lines = [*PRESS[:9], "mass 3 10 0 C"]
    machine = reduced_machine(analyze(parse_edgelist(lines)), drive=None)
    with pytest.raises(DynamicsError, match="vanishes at φ = 0°"):
        run_down(machine, 10.0)


def test_every_run_is_bounded():
    machine = _press("motor=1100,10.5")
    with pytest.raises(IntegrationError, match="more than 300 evaluations"):
        start_up(machine, limits=Limits(evaluations=300))
    with pytest.raises(IntegrationError, match="more than 300 evaluations"):
        steady_running(machine, limits=Limits(evaluations=300))


def test_a_run_down_that_never_quite_stops():
    """J = 0.01 kg·m² against −ω³ N·m from 10 rad/s: dω/dt = −ω³/J, so 1/ω² = 1/ω0² + 2t/J and
    ω falls to ω0/1000 at t = J·(10⁶ − 1)/(2·ω0²) = 49.99995 s, after φ = J·(1000 − 1)/ω0 rad."""
    lines = [
        "driver 1",
        "0 1 R O",
        "point O 0 0",
        "mass 1 0 0.01 O",
        "cycle moment 1 formula=-omega^3",
    ]
    machine = reduced_machine(analyze(parse_edgelist(lines)), drive=None)
    run = run_down(machine, 10.0)
    assert run.ending == "slowed"
    assert run.duration == pytest.approx(0.01 * (1e6 - 1) / 200, rel=1e-6)
    assert run.phi[-1] == pytest.approx(0.01 * 999 / 10, rel=1e-6)


def test_a_stiff_start_up_goes_on_with_a_stiff_method():
    """J = 0.01 kg·m², drive 1000 N·m against −ω³: steady at ω = 10 rad/s exactly (1000 = ω³),
    where the load's slope 3ω²/J = 30,000 s⁻¹ would take explicit steps of 0.1 ms, tens of
    thousands of evaluations a turn; the switch to LSODA keeps the run within 30,000."""
    lines = ["driver 1 omega=10", "0 1 R O", "point O 0 0", "mass 1 0 0.01 O", "drive 1 1000",
             "cycle moment 1 formula=-omega^3"]  # fmt: skip
    machine = reduced_machine(analyze(parse_edgelist(lines)))
    steady = steady_running(machine)
    assert steady.omega_mean == pytest.approx(10.0, rel=1e-9) and steady.delta < 1e-9
    run = start_up(machine, steady=steady, limits=Limits(evaluations=30_000))
    assert run.ending == "steady" and run.omega[-1] == pytest.approx(10.0, rel=1e-3)
