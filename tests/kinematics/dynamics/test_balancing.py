"""Balancing: counterweights by hand, Berkof–Lowen's complete balance, a crank–slider."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.dynamics.balancing import balance, counterweight
from kinematics.errors import DynamicsError
from structure.readwrite.edgelist import parse_edgelist, write_edgelist
from structure.report import analyze

from . import fourbar_model as fb

OMEGA = 10.0


def test_the_four_bar_is_completely_balanced():
    """Berkof–Lowen by hand for this four-bar, whose coupler's centre is its midpoint: the crank
    must carry −m2·a1/2 = −0.1 kg·m and has m1·0.05 = 0.05, so 1.5 kg at 0.1 m opposite B;
    the rocker must carry −m2·a3/2 = −0.2062 and has m3·a3/2 = 0.1546, so 1.75 kg at a3
    opposite C."""
    report = analyze(parse_edgelist(fb.EDGES.splitlines()))
    result = balance(report, omega=OMEGA)
    assert result.method == "complete"
    crank, rocker = result.counterweights
    assert (crank.link, rocker.link) == ("1", "3")
    assert crank.mass == pytest.approx(1.5, rel=1e-12)
    np.testing.assert_allclose(crank.position, (-0.1, 0.0), atol=1e-15)
    assert rocker.mass == pytest.approx(1.75, rel=1e-12)
    np.testing.assert_allclose(rocker.position, (0.25, -0.2), atol=1e-15)
    assert result.after.force_max <= 1e-9 * result.before.force_max
    # the counterweights move the rocker's inertia: the shaking moment and the torque change
    assert result.after.moment_max != pytest.approx(result.before.moment_max)


def test_the_balanced_file_reads_back_with_its_counterweights():
    report = analyze(parse_edgelist(fb.EDGES.splitlines()))
    result = balance(report, omega=OMEGA)
    text = write_edgelist(result.mechanism)
    assert "point CW1 -0.1 0 on=1" in text and "mass 1 1.5 0 CW1" in text
    again = balance(analyze(parse_edgelist(text.splitlines())), omega=OMEGA)
    assert again.before.force_max <= 1e-9 * result.before.force_max
    assert again.counterweights == ()


def test_the_driving_torque_is_the_kinetostatics_balancing_moment():
    """Before and after: ½·J_r'·ω² at constant speed equals the balancing moment of the
    kinetostatics, group by group (checked here on the balanced four-bar's file)."""
    import dataclasses

    from kinematics.kinetostatics.forces import forces_over
    from kinematics.solvers.plan import make_plan
    from kinematics.solvers.solve import solve_poses

    report = analyze(parse_edgelist(fb.EDGES.splitlines()))
    result = balance(report, omega=OMEGA)
    for mechanism, torque in ((report.mechanism, result.torque_before),
                              (result.mechanism, result.torque_after)):  # fmt: skip
        plan = make_plan(analyze(mechanism))
        driver = dataclasses.replace(plan.drivers[0], speed=OMEGA, acceleration=0.0)
        plan = dataclasses.replace(plan, drivers=(driver,))
        phi = result.before.phi[::15]
        kinetostatic = forces_over(plan, solve_poses(plan, phi[:, None])).balancing_moment["1"]
        np.testing.assert_allclose(torque[::15], kinetostatic, atol=1e-9 * np.max(np.abs(torque)))


SLIDER = """driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0.1 0
point C 0.4 0
mass 3 2 0 C
mass 1 0 0.01 A
""".splitlines()


def _closed_form_harmonics(r: float, rod: float, m: float, omega: float) -> tuple[float, float]:
    """The first two harmonics of −m·ẍ_C for x = r·cos φ + √(l² − r²·sin² φ), by FFT of the
    closed form's second derivative (written out by hand)."""
    phi = np.linspace(0, 2 * math.pi, 720, endpoint=False)
    s, c = np.sin(phi), np.cos(phi)
    root = np.sqrt(rod**2 - (r * s) ** 2)
    x2 = -r * c - (r * r * (c * c - s * s)) / root - (r**4 * s * s * c * c) / root**3
    spectrum = np.fft.rfft(-m * x2 * omega**2) / len(phi) * 2
    return abs(spectrum[1]), abs(spectrum[2])


@pytest.mark.parametrize("fraction", [0.0, 0.5, 1.0])
def test_a_crank_slider_is_balanced_in_its_primary_force(fraction: float):
    report = analyze(parse_edgelist(SLIDER))
    result = balance(report, fraction=fraction)
    assert result.method == "primary"
    primary, secondary = _closed_form_harmonics(0.1, 0.3, 2.0, OMEGA)
    assert primary == pytest.approx(2 * 0.1 * OMEGA**2, rel=1e-12)  # exactly m·r·ω²
    h = result.harmonics
    assert h.primary == pytest.approx(primary, rel=1e-9)
    assert h.secondary == pytest.approx(secondary, rel=1e-9)
    assert h.reciprocating == 2.0 and h.crank == pytest.approx(0.1)
    assert result.harmonics_after.primary == pytest.approx((1 - fraction) * primary, abs=1e-9)
    assert result.harmonics_after.secondary == pytest.approx(secondary, rel=1e-9)
    # what the counterweight takes off along the slide it puts across it
    across = result.after.force[:, 1]
    spectrum = np.fft.rfft(across[:-1]) / (len(across) - 1) * 2
    assert abs(spectrum[1]) == pytest.approx(fraction * primary, abs=1e-9)
    assert h.lanchester == pytest.approx(secondary / (8 * OMEGA**2))
    assert "Lanchester" in result.notes[0]


def test_static_balance_of_one_link():
    m = parse_edgelist(["0 1 R A", "point A 0 0", "point S 0.1 0.1", "mass 1 2 0 S"])
    w = counterweight(m, "1", "A", radius=0.2)
    assert w.mass == pytest.approx(2 * math.sqrt(0.02) / 0.2)
    np.testing.assert_allclose(w.position, (-0.2 / math.sqrt(2), -0.2 / math.sqrt(2)))


def test_without_masses_there_is_nothing_to_balance():
    lines = [line for line in fb.EDGES.splitlines() if not line.startswith("mass")]
    with pytest.raises(DynamicsError, match="no mass data"):
        balance(analyze(parse_edgelist(lines)))
    with pytest.raises(DynamicsError, match="for a four-bar"):
        balance(analyze(parse_edgelist(SLIDER)), method="complete")
