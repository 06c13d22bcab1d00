"""Branch tracking over a sweep: no false change, none missed, in any order and unit (issue 22).

Item 4's reproducers: pyslvs's "Parallel Linkage" swept through −89° then
−88.5° raised a BranchChangeError that the other order did not; Jansen's
linkage at 1e100 m reported a false branch change; the four-bar at 1e-300 m
gave NaN transmission angles. Item 16: the parallelogram held by a third
parallel crank goes on through its change points. The answers expected come
from the unscaled mechanism (scaled by hand) and from the parallelogram's
geometry (the coupler translates, every crank turns with the driver).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematics.errors import BranchChangeError
from kinematics.solvers import branches
from kinematics.solvers.plan import make_plan
from kinematics.solvers.sweep import sweep
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.readwrite.pyslvs import mechanism_from_expression
from structure.report import analyze

from ...conftest import FIXTURES


def scaled(mechanism, k: float):
    """The mechanism with every coordinate multiplied by ``k`` (its unit of length divided)."""
    points = {n: dataclasses.replace(p, x=p.x * k, y=p.y * k) for n, p in mechanism.points.items()}
    return dataclasses.replace(mechanism, points=points)


def fixture(stem: str):
    return read_edgelist(str(FIXTURES / f"{stem}.edges"))


def test_pyslvs_parallel_linkage_near_its_change_point_in_either_order(pyslvs_sdist):
    example = pyslvs_sdist.examples["Parallel Linkage"]
    m = mechanism_from_expression(example.expression, "Parallel Linkage", example.inputs)
    plan = make_plan(analyze(m))
    rows = np.radians([[-89.0], [-88.5]])
    ahead = sweep(plan, rows)
    behind = sweep(plan, rows[::-1])
    for name in ahead.points:
        np.testing.assert_allclose(
            ahead.points[name]["position"], behind.points[name]["position"][::-1], atol=1e-12
        )
    # a parallelogram: the coupler link_2 keeps its direction, the rocker turns with the crank
    assert ahead.links["link_2"]["angle"] == pytest.approx([0.0, 0.0], abs=1e-12)
    assert ahead.links["link_3"]["angle"] == pytest.approx(rows[:, 0], abs=1e-12)


SQUARE = """
driver 1 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0 1
point C 1 1
point D 1 0
"""


@settings(max_examples=30, deadline=None)
@given(a=st.floats(0.01, 3.0), b=st.floats(0.01, 3.0), side=st.sampled_from([-1.0, 1.0]))
def test_two_poses_short_of_a_change_point_solve_in_either_order(a, b, side):
    # a square parallelogram sketched with its crank upright: change points at ±90°, where
    # the crank lies along the frame; rows a° and b° short of −90° (or +90°) never cross it
    plan = make_plan(analyze(parse_edgelist(SQUARE.strip().splitlines())))
    rows = np.radians([[side * (90.0 - a)], [side * (90.0 - b)]])
    ahead, behind = sweep(plan, rows), sweep(plan, rows[::-1])
    np.testing.assert_allclose(ahead.links["3"]["angle"], rows[:, 0], atol=1e-9)
    np.testing.assert_allclose(behind.links["3"]["angle"], rows[::-1, 0], atol=1e-9)


def test_jansen_at_1e100_m_is_jansen_at_1_m_scaled_with_no_branch_check(monkeypatch):
    looked = []
    monkeypatch.setattr(branches, "confirm_branches", lambda *a: looked.append(a))
    m = fixture("jansen")
    plain = sweep(make_plan(analyze(m)), steps=72)
    huge = sweep(make_plan(analyze(scaled(m, 1e100))), steps=72)
    assert not looked  # the false change point came from a dip the unit of length made
    for name in plain.points:
        np.testing.assert_allclose(
            huge.points[name]["position"] / 1e100,
            plain.points[name]["position"],
            rtol=1e-12,
            atol=1e-13,
        )
    for name in plain.links:
        np.testing.assert_allclose(
            huge.links[name]["omega"], plain.links[name]["omega"], rtol=1e-10
        )


@pytest.mark.parametrize("k", [1e-300, 2.0**-1000, 1e150])
def test_the_four_bar_at_an_extreme_unit_has_finite_transmission_angles(k):
    m = fixture("fourbar")
    plain = sweep(make_plan(analyze(m)), steps=4)
    far = sweep(make_plan(analyze(scaled(m, k))), steps=4)
    mu = far.transmission["II(2,3)"]
    assert np.all(np.isfinite(mu))
    np.testing.assert_allclose(mu, plain.transmission["II(2,3)"], rtol=0, atol=1e-12)
    # at 1e-300 m and four poses, the rocker's pin stood still at its sketch place
    np.testing.assert_allclose(
        far.points["C"]["position"] / k, plain.points["C"]["position"], rtol=1e-12
    )


@pytest.mark.parametrize(
    "steps",
    [7, 72, pytest.param(360, marks=pytest.mark.slow), pytest.param(1000, marks=pytest.mark.slow)],
)
def test_a_parallelogram_held_by_a_third_crank_makes_the_whole_turn(steps):
    plan = make_plan(analyze(fixture("parallelogram_redundant")))
    result = sweep(plan, steps=steps)  # through both change points, at 126.87° and 306.87°
    assert len(result.inputs) == steps
    b, c, f = (result.points[p]["position"] for p in "BCF")
    np.testing.assert_allclose(c - b, [[0.3, 0.0]] * steps, atol=1e-12)  # the coupler translates
    np.testing.assert_allclose(f - b, [[0.15, 0.0]] * steps, atol=1e-12)
    for link in ("3", "4"):  # each crank turns with the driver, ω = 10
        np.testing.assert_allclose(result.links[link]["omega"], 10.0, rtol=0, atol=1e-7)
    np.testing.assert_allclose(result.links["2"]["omega"], 0.0, atol=1e-7)


def test_a_parallelogram_without_the_third_crank_still_stops_at_its_change_point():
    text = (FIXTURES / "parallelogram_redundant.edges").read_text().splitlines()
    text = [line for line in text if "third crank" not in line and "point E" not in line]
    text = [line for line in text if "point F" not in line]
    plan = make_plan(analyze(parse_edgelist(text)))
    with pytest.raises(BranchChangeError, match=r"at input 126\.87°"):
        sweep(plan, steps=360)


def test_a_sweep_that_starts_past_a_change_point_is_looked_into_from_the_sketch():
    # a parallelogram sketched with its crank at 179°, 1° short of lying along the frame (a
    # change point); rows at 1.5° and 2° are one small step from the sketch, past it
    b = (0.2 * math.cos(math.radians(179)), 0.2 * math.sin(math.radians(179)))
    text = f"""
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B {b[0]!r} {b[1]!r}
point C {b[0] + 0.5!r} {b[1]!r}
point D 0.5 0
"""
    plan = make_plan(analyze(parse_edgelist(text.strip().splitlines())))
    with pytest.raises(BranchChangeError) as err:
        sweep(plan, np.radians([[1.5], [2.0]]))
    assert err.value.group == "II(2,3)"
    assert math.degrees(err.value.pose[0]) == pytest.approx(1.0, abs=1e-4)
    before = sweep(plan, np.radians([[0.5], [0.9]]))  # short of it: the parallelogram's motion
    np.testing.assert_allclose(before.links["3"]["omega"], 10.0, atol=1e-6)
