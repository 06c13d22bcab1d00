"""The dynamics' figures: each curve drawn from the results, read back by its gid."""

from __future__ import annotations

import numpy as np
import pytest

from kinematics.dynamics.analysis import machine_dynamics
from kinematics.dynamics.balancing import balance
from kinematics.figures.dynamics import (
    balance_sheet,
    dynamics_sheet,
    energy_inertia_figure,
    shaking_figure,
)
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES


@pytest.fixture(scope="module")
def press():
    report = analyze(read_edgelist(FIXTURES / "press_flywheel.edges"))
    return machine_dynamics(report)


def _lines(fig) -> dict:
    return {line.get_gid(): line for ax in fig.axes for line in ax.get_lines() if line.get_gid()}


def test_the_sheet_draws_every_curve(press):
    lines = _lines(dynamics_sheet(press))
    expected = {
        "inertia:J", "inertia:dJ", "moment:total", "moment:drive", "moment:loads",
        "omega:steady", "omega:flywheel", "run:start-up", "run:run-down",
        "wittenbauer:curve", "tangent:max", "tangent:min", "wittenbauer:origin", "shaking:before",
    }  # fmt: skip
    assert expected <= set(lines)
    x, y = lines["inertia:J"].get_data()
    np.testing.assert_array_equal(y, press.machine.properties.inertia)
    np.testing.assert_allclose(x, np.degrees(press.machine.properties.phi))
    _, omega = lines["omega:steady"].get_data()
    np.testing.assert_array_equal(omega, press.steady.omega)


def test_the_tangents_meet_at_the_true_origin(press):
    wheel = press.flywheel
    lines = _lines(energy_inertia_figure(wheel))
    j0, e0 = wheel.origin
    for name, (slope, _, _) in zip(("max", "min"), wheel.tangents, strict=True):
        x, y = lines[f"tangent:{name}"].get_data()
        assert x[0] == pytest.approx(j0) and y[0] == pytest.approx(e0)
        assert (y[1] - y[0]) / (x[1] - x[0]) == pytest.approx(slope)


def test_the_polar_plot_is_the_force_s_tip(press):
    shaken = press.shaking
    lines = _lines(shaking_figure(shaken))
    angle, radius = lines["shaking:before"].get_data()
    np.testing.assert_allclose(radius * np.cos(angle), shaken.force[:, 0], atol=1e-9)
    np.testing.assert_allclose(radius * np.sin(angle), shaken.force[:, 1], atol=1e-9)


def test_the_balance_sheet():
    report = analyze(read_edgelist(FIXTURES / "fourbar_masses.edges"))
    lines = _lines(balance_sheet(balance(report)))
    assert {"shaking:before", "shaking:after", "torque:before", "torque:after"} <= set(lines)
    _, after = lines["shaking:after"].get_data()
    assert np.max(after) < 1e-9 * np.max(lines["shaking:before"].get_data()[1])
