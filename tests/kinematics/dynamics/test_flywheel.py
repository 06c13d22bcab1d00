"""The flywheel for a coefficient of speed fluctuation: Wittenbauer's and the approximate one."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.dynamics.flywheel import flywheel
from kinematics.dynamics.machine import reduced_machine
from kinematics.dynamics.motion import Limits, run_down
from kinematics.errors import DynamicsError
from structure.readwrite.edgelist import parse_edgelist
from structure.report import analyze

from . import fourbar_model
from .test_motion import PRESS

OMEGA = 450 * 2 * math.pi / 60  # 450 rpm


def _engine(crank_inertia: float):
    """Khurmi & Gupta's three-crank engine (see test_motion), its crank's own inertia given."""
    lines = [
        f"driver 1 omega={OMEGA!r}",
        "0 1 R O",
        "point O 0 0",
        f"mass 1 0 {crank_inertia} O",
        "drive 1 formula=25000-7500*sin(3*phi)",
        "cycle moment 1 formula=-25000-3600*sin(phi)",
    ]
    return reduced_machine(analyze(parse_edgelist(lines)))


def test_khurmi_s_engine_needs_its_360_kg_m2():
    """ΔE = 12.2 kN·m by hand (test_motion); the flywheel for δ = ΔE/(360·ω²) is 360 kg·m² by
    both methods when the crank has no inertia of its own."""
    delta = 12200 / (360 * OMEGA**2)
    result = flywheel(_engine(0.0), delta)
    assert result.energy_swing == pytest.approx(12200, rel=1e-12)
    assert result.approximate == pytest.approx(360, rel=1e-12)
    assert result.exact == pytest.approx(360, rel=1e-9)
    assert result.steady.delta == pytest.approx(delta, rel=1e-9)


def test_with_a_constant_inertia_the_exact_flywheel_is_the_approximate_less_it():
    delta = 0.01
    result = flywheel(_engine(40.0), delta)
    expected = 12200 / (delta * OMEGA**2) - 40.0
    assert result.exact == pytest.approx(expected, rel=1e-9)
    assert result.approximate_less_mean == pytest.approx(expected, rel=1e-12)
    assert result.steady.delta == pytest.approx(delta, rel=1e-9)


def test_a_free_four_bar_needs_a_flywheel_the_approximate_formula_misses():
    """No load: ΔE = 0, so ΔE/(δ·ω²) is 0; yet J_r(φ) alone makes the speed swing. The exact
    flywheel is checked by integrating one free turn in time with it: δ at the goal."""
    machine = reduced_machine(analyze(parse_edgelist(fourbar_model.EDGES.splitlines())), drive=None)
    result = flywheel(machine, 0.02)
    assert result.approximate == 0 and result.needed and result.exact > 0
    steady = result.steady
    run = run_down(
        machine, float(steady.omega[0]), flywheel=result.exact, limits=Limits(turns=1), dense=True
    )
    _, omega = run.at(np.linspace(0, run.duration, 20001))
    high, low = np.max(omega), np.min(omega)
    assert (high - low) / ((high + low) / 2) == pytest.approx(0.02, rel=1e-5)
    assert (high + low) / 2 == pytest.approx(10.0, rel=1e-5)


def test_a_machine_heavy_enough_needs_none():
    lines = [*fourbar_model.EDGES.splitlines(), "mass 1 0 50 A"]
    machine = reduced_machine(analyze(parse_edgelist(lines)), drive=None)
    result = flywheel(machine, 0.02)
    assert not result.needed and result.exact == 0
    assert result.steady.delta < 0.02


def test_a_motor_driven_press_holds_its_delta():
    machine = reduced_machine(analyze(parse_edgelist([*PRESS, "drive 1 motor=1100,10.5"])))
    result = flywheel(machine, 0.02)
    assert result.steady.delta == pytest.approx(0.02, rel=1e-5)
    assert result.exact > 0 and result.approximate > result.approximate_less_mean


@pytest.mark.parametrize("delta", [0.0, -0.1, 2.0, math.nan])
def test_a_delta_out_of_range_is_named(delta: float):
    with pytest.raises(DynamicsError, match="coefficient of speed fluctuation"):
        flywheel(_engine(0.0), delta)
