"""Chapter 2 of the source and the exam's problem 1, against hand derivations.

The expected values in fixtures/kinematics.toml were derived by hand (closed
forms differentiated exactly, checked against the relative-velocity and
-acceleration polygons); the table notes where the printed answers are wrong.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_pose
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES, KINEMATICS_TABLE, expected_table

TABLE = expected_table((KINEMATICS_TABLE,))


@pytest.fixture(scope="module", params=sorted(TABLE))
def case(request):
    expected = TABLE[request.param]
    plan = make_plan(analyze(read_edgelist(FIXTURES / expected["file"])))
    return expected, solve_pose(plan)


def test_every_problem_is_covered():
    problems = {entry["problem"] for entry in TABLE.values()}
    assert {"2.2", "2.3", "2.4", "2.5", "2.6", "2.7", "2.9", "2.10"} <= problems
    assert any(p.startswith("2.8") for p in problems)
    assert any("exam" in p.lower() or p.startswith("1") for p in problems) or any(
        name.startswith("exam") for name in TABLE
    )


def test_angular_velocities_and_accelerations(case):
    expected, state = case
    for name, values in expected["links"].items():
        link = state.links[name]
        assert link.omega == pytest.approx(values["omega"], abs=1e-8), name
        assert link.epsilon == pytest.approx(values["epsilon"], abs=1e-6), name


def test_point_velocities_and_accelerations(case):
    expected, state = case
    for name, values in expected["points"].items():
        point = state.points[name]
        np.testing.assert_allclose(point.velocity, values["velocity"], atol=1e-9, err_msg=name)
        np.testing.assert_allclose(
            point.acceleration, values["acceleration"], atol=1e-6, err_msg=name
        )


def test_exam_answers_in_closed_form():
    # AB = a, CB = a√2, CD = 2a, crank ω: ω3 = ω/2, v_D = a·ω, Coriolis a·ω²/√2, ε3 = 0
    (name,) = [n for n in TABLE if n.startswith("exam")]
    state = solve_pose(make_plan(analyze(read_edgelist(FIXTURES / TABLE[name]["file"]))))
    omega = max(abs(link.omega) for link in state.links.values())
    slotted = [link for link in state.links.values() if math.isclose(abs(link.omega), omega / 2)]
    assert slotted, "no link turns at ω/2"
    assert all(abs(link.epsilon) < 1e-9 for link in slotted)
