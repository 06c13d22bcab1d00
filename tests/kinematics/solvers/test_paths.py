"""Where a quantity sampled along a path of inputs may dip to zero unseen (solvers/paths.py).

The samples here are of known functions: (x − x₀)², which touches zero at x₀,
sampled along paths written in different ways. What the samples say must not
depend on how the path is written: repeated rows, a turn back, the order of
travel (issue 22, items 2 and 4).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematics.solvers.paths import Watch, suspect_steps


def squared_distance(x: np.ndarray, zero: float) -> np.ndarray:
    return (x[:, 0] - zero) ** 2


def test_a_touch_between_two_samples_is_suspect():
    x = np.linspace(0.0, 1.0, 11)[:, None]
    steps = suspect_steps(x, squared_distance(x, 0.55))
    assert set(steps) >= {5}  # the step from 0.5 to 0.6 holds the zero


def test_a_function_that_only_falls_or_rises_is_never_suspect():
    x = np.linspace(0.0, 1.0, 11)[:, None]
    assert len(suspect_steps(x, squared_distance(x, 1.7))) == 0
    assert len(suspect_steps(x, squared_distance(x, -0.7))) == 0


def test_repeated_rows_say_nothing_and_never_make_a_step_suspect():
    # a driver held still: every row the same (issue 22 item 2: this grew without bound)
    x = np.zeros((50, 1))
    assert len(suspect_steps(x, np.full(50, 0.3))) == 0
    # repeats inside a path: the same answer as the path written once
    once = np.linspace(0.0, 1.0, 11)[:, None]
    twice = np.repeat(once, 2, axis=0)
    values = squared_distance(once, 1.3)
    assert len(suspect_steps(twice, np.repeat(values, 2))) == 0


def test_a_dip_beside_a_repeated_row_is_still_found():
    x = np.array([[0.0], [0.1], [0.2], [0.2], [0.3], [0.4]])
    steps = suspect_steps(x, squared_distance(x, 0.25))
    assert 3 in steps  # the step from the (second) 0.2 to 0.3 holds the zero


def test_a_path_turning_back_near_a_zero_is_not_suspect_at_its_turn():
    # the zero at 0 lies beyond the turn at 0.1: the path never reaches it
    there = np.linspace(1.0, 0.1, 10)
    back = np.linspace(0.1, 1.0, 10)[1:]
    x = np.concatenate([there, back])[:, None]
    assert len(suspect_steps(x, squared_distance(x, 0.0))) == 0
    # the same path with the turn one step from the zero: still nothing to see
    x = np.array([[0.3], [0.2], [0.1], [0.105]])
    assert len(suspect_steps(x, squared_distance(x, 0.0))) == 0


def test_a_zero_just_before_a_turn_is_still_found():
    x = np.array([[0.0], [0.1], [0.2], [0.3], [0.25], [0.2]])
    steps = suspect_steps(x, squared_distance(x, 0.26))
    assert set(steps) & {2, 3}


def test_breaks_join_pieces_that_say_nothing_about_each_other():
    # two pieces far apart, each rising from its start: low at the join, but not between samples
    a = np.linspace(0.0, 0.1, 9)
    b = np.linspace(5.0, 5.1, 9)
    x = np.concatenate([a, b])[:, None]
    values = np.concatenate(
        [squared_distance(a[:, None], -0.01), squared_distance(b[:, None], 4.99)]
    )
    assert len(suspect_steps(x, values, np.array([8]))) == 0
    watch = Watch(np.array([8]))
    assert watch == [] and watch.breaks.tolist() == [8]


@settings(max_examples=60, deadline=None)
@given(
    zero=st.floats(-1.0, 2.0),
    start=st.floats(0.0, 1.0),
    stop=st.floats(0.0, 1.0),
    steps=st.integers(3, 60),
    repeat=st.integers(1, 3),
)
def test_the_same_steps_whichever_way_the_path_is_travelled(zero, start, stop, steps, repeat):
    forward = np.repeat(np.linspace(start, stop, steps), repeat)[:, None]
    backward = forward[::-1]
    ahead = suspect_steps(forward, squared_distance(forward, zero))
    behind = suspect_steps(backward, squared_distance(backward, zero))
    # step k forward is step n − 2 − k backward (between the same two rows)
    n = len(forward)
    assert sorted(ahead.tolist()) == sorted((n - 2 - behind).tolist())


@pytest.mark.parametrize("scale", [1e-300, 1.0, 1e150])
def test_the_samples_are_read_in_any_unit(scale):
    x = np.linspace(0.0, 1.0, 11)[:, None]
    assert set(suspect_steps(x, squared_distance(x, 0.55) * scale)) >= {5}


@settings(max_examples=80, deadline=None)
@given(
    zeros=st.lists(st.floats(-0.5, 1.5), min_size=1, max_size=3),
    steps=st.integers(3, 80),
    drivers=st.integers(1, 2),
    backward=st.booleans(),
)
def test_a_straight_path_is_looked_into_as_any_path_is(zeros, steps, drivers, backward):
    # a path of one run takes a shorter way (its minima only): the same steps come out
    t = np.linspace(0.0, 1.0, steps)
    if backward:
        t = t[::-1]
    path = np.column_stack([t] + [0.5 * t] * (drivers - 1))
    values = np.prod([(t - z) ** 2 + 1e-6 * k for k, z in enumerate(zeros)], axis=0)
    fast = suspect_steps(path, values)
    general = suspect_steps(path, values, np.array([-1]))  # a break that joins no rows
    assert fast.tolist() == general.tolist()
