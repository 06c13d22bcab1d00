"""The report's cycle (kinematics.html.cycle): issue 22, item 16.

No animation was made for the five-bar with two drivers, the parallelogram
with a redundant crank, or a double-rocker driven as a crank; the two-driver
one turned both inputs alike. The limits of a stretch are worked out by hand
from the link lengths.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.html.cycle import solve_cycle, stretch_text
from kinematics.solvers.plan import make_plan
from kinematics.solvers.travel import Stop
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES


def fixture_plan(stem: str):
    return make_plan(analyze(read_edgelist(str(FIXTURES / f"{stem}.edges"))))


def test_a_two_driver_cycle_follows_the_ratio_of_the_drivers_omega():
    plan = fixture_plan("fivebar_two_drivers")  # ω1 = 10, ω4 = −5
    cycle = solve_cycle(plan, 24)
    inputs = cycle.sweep.inputs
    np.testing.assert_allclose(inputs[:, 1], -0.5 * inputs[:, 0], atol=1e-15)
    assert inputs[cycle.sketch].tolist() == [0.0, 0.0]
    # the five-bar cannot close all the way round: a stretch between two dead points, where
    # B, C and D come into line (|BD| = |BC| + |CD|)
    assert not cycle.complete
    assert [limit.stop for limit in cycle.limits] == [Stop.DEAD_POINT, Stop.DEAD_POINT]
    m = read_edgelist(str(FIXTURES / "fivebar_two_drivers.edges"))
    reach = math.dist(m.coordinates("B"), m.coordinates("C"))
    reach += math.dist(m.coordinates("C"), m.coordinates("D"))
    for limit in cycle.limits:
        phi1, phi4 = (float(x) for x in limit.at)
        b = np.array(m.coordinates("B")) @ rotation(phi1).T
        d = (
            np.array(m.coordinates("E"))
            + (np.subtract(m.coordinates("D"), m.coordinates("E"))) @ rotation(phi4).T
        )
        assert np.linalg.norm(d - b) == pytest.approx(reach, rel=1e-7)


def rotation(phi: float) -> np.ndarray:
    return np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])


def test_a_parallelogram_with_a_third_crank_loops_a_whole_turn():
    cycle = solve_cycle(fixture_plan("parallelogram_redundant"), 24)
    assert cycle.complete and cycle.sketch == 0 and cycle.limits is None
    assert cycle.poses["2"][:, 2] == pytest.approx(np.zeros(24), abs=1e-9)  # the coupler translates


def test_a_double_rocker_shows_its_stretch_between_dead_points_in_both_languages():
    plan = fixture_plan("double_rocker")
    cycle = solve_cycle(plan, 24)
    assert not cycle.complete
    # |BD|² = 0.25² + 0.4² − 0.2·cos φ between 0.2² and 0.4²: cos φ from 0.3125 to 0.9125,
    # the crank starting at atan2(B)
    bx, by = read_edgelist(str(FIXTURES / "double_rocker.edges")).coordinates("B")
    start = math.degrees(math.atan2(by, bx))
    low, high = (math.degrees(math.acos(c)) - start for c in (0.9125, 0.3125))
    assert [math.degrees(float(limit.at[0])) for limit in cycle.limits] == pytest.approx(
        [low, high], abs=1e-5
    )
    english = stretch_text(plan, cycle, "en")
    assert "a dead point of group II(2,3)" in english and "change point" not in english
    assert f"φ1 = {low:.4g}°" in english and f"φ1 = {high:.4g}°" in english
    assert "điểm chết" in stretch_text(plan, cycle, "vi")


def test_a_slider_driver_shows_its_stroke():
    text = [
        "driver 3 v=1",
        "0 1 R A",
        "1 2 R B",
        "2 3 R C",
        "3 0 P C angle=0",
        "point A 0 0",
        "point B 0 0.1",
        "point C 0.1732 0",
    ]
    plan = make_plan(analyze(parse_edgelist(text)))
    cycle = solve_cycle(plan, 12)
    assert stretch_text(plan, cycle, "en").startswith(
        "The stroke of the sliding driver: from s3 = "
    )
