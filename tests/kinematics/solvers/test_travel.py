"""How far the drivers take a mechanism: cycles, strokes, stretches (solvers/travel.py).

Issue 22, item 2: a crank–slider driven at its slider block grew without bound
(1.4 GB) and pyslvs's "Slider lifter" to 3.9 GB; a sliding driver now sweeps
its stroke, found from the mechanism, in metres. Item 16: a double-rocker
driven as a crank reaches a stretch between two dead points; two drivers
turn at the ratio of their ω. Every limit below is worked out by hand from
the link lengths (circle and line intersections), not by the code.
"""

from __future__ import annotations

import math
import tracemalloc

import numpy as np
import pytest

from kinematics.errors import TravelError
from kinematics.solvers.plan import make_plan
from kinematics.solvers.sweep import sweep
from kinematics.solvers.travel import Stop, cycle_inputs, cycle_span, driver_rates, travel
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.readwrite.pyslvs import mechanism_from_expression
from structure.report import analyze

from ...conftest import FIXTURES

#: issue 22 item 2's reproducer: the slider block 3 drives the crank 1 through the rod 2
SLIDER_DRIVEN = """
driver 3
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0 0.1
point C 0.1732 0
"""
CRANK, ROD = 0.1, math.hypot(0.1732, 0.1)
# C stays on the x axis right of A, at |AC| from ROD − CRANK (folded) to ROD + CRANK (stretched)
STROKE = (ROD - CRANK - 0.1732, ROD + CRANK - 0.1732)


def plan_of(text: str):
    return make_plan(analyze(parse_edgelist(text.strip().splitlines())))


def fixture_plan(stem: str):
    return make_plan(analyze(read_edgelist(str(FIXTURES / f"{stem}.edges"))))


# ------------------------------------------------------------------ a sliding driver's stroke
def test_a_slider_block_driving_a_crank_travels_between_its_dead_points():
    way = travel(plan_of(SLIDER_DRIVEN), 60)
    assert not way.complete
    (low, high) = way.limits
    assert low.stop is Stop.DEAD_POINT and high.stop is Stop.DEAD_POINT
    assert low.group == high.group == "II(1,2)"
    assert float(low.at[0]) == pytest.approx(STROKE[0], abs=1e-7)
    assert float(high.at[0]) == pytest.approx(STROKE[1], abs=1e-7)
    s = way.inputs[:, 0]
    assert np.all(np.diff(s) > 0) and s[way.sketch] == 0.0
    assert STROKE[0] < s[0] < s[-1] < STROKE[1]  # a little short of the dead points


def test_the_default_sweep_of_a_slider_driver_is_its_stroke_in_bounded_memory():
    plan = plan_of(SLIDER_DRIVEN)
    tracemalloc.start()
    try:
        result = sweep(plan, steps=360)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 64e6  # it reached 1.4 GB
    s = result.inputs[:, 0]
    assert len(s) == 360 and STROKE[0] < s.min() and s.max() < STROKE[1]
    assert s.max() - s.min() == pytest.approx(STROKE[1] - STROKE[0], rel=1 / 300)
    # the crank pin keeps the crank's length and the rod's at every pose
    b, c = result.points["B"]["position"], result.points["C"]["position"]
    np.testing.assert_allclose(np.hypot(*b.T), CRANK, rtol=1e-12)
    np.testing.assert_allclose(np.hypot(*(c - b).T), ROD, rtol=1e-12)
    np.testing.assert_allclose(c[:, 0], 0.1732 + s, rtol=0, atol=1e-15)


def test_a_slider_held_still_sweeps_the_same_pose_without_growing():
    plan = plan_of(SLIDER_DRIVEN)
    tracemalloc.start()
    try:
        result = sweep(plan, np.zeros((2000, 1)))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 64e6
    np.testing.assert_allclose(result.points["B"]["position"], [[0.0, 0.1]] * 2000, atol=1e-15)


def test_pyslvs_slider_lifter_travels_from_its_dead_point_to_where_its_pins_meet(pyslvs_sdist):
    example = pyslvs_sdist.examples["Slider lifter"]
    m = mechanism_from_expression(example.expression, "Slider lifter", example.inputs)
    plan = make_plan(analyze(m))
    tracemalloc.start()
    try:
        way = travel(plan, 120)
        result = sweep(plan, steps=120)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 64e6  # it reached 3.9 GB and was killed
    # J0 slides on the x axis from x = 0; L2 (J0–J2) and L1 (J1–J2) are both √(25² + 27²)
    # long, J1 = (50, 0): the dyad stretches out at x = 50 − 2·√(25² + 27²) and folds onto
    # itself (J0 on J1, a singular pose) at x = 50
    low, high = way.limits
    assert float(low.at[0]) == pytest.approx(50 - 2 * math.hypot(25, 27), abs=1e-5)
    assert low.stop is Stop.DEAD_POINT
    assert float(high.at[0]) == pytest.approx(50.0, abs=1e-3)
    assert high.stop is Stop.SINGULAR
    np.testing.assert_array_equal(result.inputs, way.inputs)


def test_a_slider_the_mechanism_does_not_stop_travels_a_sketch_size_each_way():
    plan = fixture_plan("ch3_3_1_slider_power")  # a block on a guide, nothing else
    way = travel(plan, 10)
    assert [limit.stop for limit in way.limits] == [Stop.FREE, Stop.FREE]
    size = plan.length
    assert [float(limit.at[0]) for limit in way.limits] == [-size, size]


def test_a_driver_that_cannot_move_either_way_is_a_named_error():
    # crank 0.1, coupler 0.2, rocker 0.3 stretched out along a frame 0.6 long: rigid
    text = """
driver 1
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0.1 0
point C 0.3 0
point D 0.6 0
"""
    with pytest.raises(TravelError, match="driver 1 cannot move from the sketch either way"):
        travel(plan_of(text), 12)


# ------------------------------------------------------------------ a turning driver's stretch
def test_a_double_rocker_driven_as_a_crank_reaches_between_two_dead_points():
    way = travel(fixture_plan("double_rocker"), 48)
    assert not way.complete
    # |BD|² = 0.25² + 0.4² − 2·0.25·0.4·cos φ must lie in [(0.3 − 0.1)², (0.3 + 0.1)²]:
    # cos φ from 0.3125 to 0.9125; the crank starts at atan2 of B
    bx, by = read_edgelist(str(FIXTURES / "double_rocker.edges")).coordinates("B")
    start = math.degrees(math.atan2(by, bx))
    low = math.degrees(math.acos(0.9125)) - start
    high = math.degrees(math.acos(0.3125)) - start
    limits = [math.degrees(float(limit.at[0])) for limit in way.limits]
    assert limits == pytest.approx([low, high], abs=1e-5)
    assert [limit.stop for limit in way.limits] == [Stop.DEAD_POINT, Stop.DEAD_POINT]


def test_a_mechanism_that_makes_the_turn_is_a_whole_cycle():
    way = travel(fixture_plan("fourbar"), 24)
    assert way.complete and way.sketch == 0 and way.limits is None
    np.testing.assert_allclose(way.inputs[:, 0], np.linspace(0, 2 * math.pi, 24, endpoint=False))


# ------------------------------------------------------------------ several drivers
def test_two_drivers_turn_at_the_ratio_of_their_omega():
    plan = fixture_plan("fivebar_two_drivers")  # ω1 = 10, ω4 = −5
    rates = driver_rates(plan)
    assert rates.tolist() == [1.0, -0.5]
    assert cycle_span(plan, rates) == pytest.approx(4 * math.pi)  # two turns of 1, one of 4
    rows = cycle_inputs(plan, 36)
    np.testing.assert_allclose(rows[:, 1], -0.5 * rows[:, 0])
    way = travel(plan, 36)
    np.testing.assert_allclose(way.inputs[:, 1], -0.5 * way.inputs[:, 0], atol=1e-15)


def test_drivers_without_their_speeds_turn_alike():
    text = (FIXTURES / "fivebar_two_drivers.edges").read_text()
    text = text.replace("driver 1 omega=10", "driver 1").replace("driver 4 omega=-5", "driver 4")
    plan = make_plan(analyze(parse_edgelist(text.splitlines())))
    assert driver_rates(plan).tolist() == [1.0, 1.0]
    assert cycle_span(plan, driver_rates(plan)) == pytest.approx(2 * math.pi)
