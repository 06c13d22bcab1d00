"""Exact answers at the sketch pose: the same numbers as the hand derivations, as radicals."""

from __future__ import annotations

import pytest
import sympy

from kinematics.solvers.exact import solve_exact
from kinematics.solvers.plan import make_plan
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES, KINEMATICS_TABLE, expected_table

TABLE = expected_table((KINEMATICS_TABLE,))


def exact_of(name: str, symbolic: bool = False):
    return solve_exact(make_plan(analyze(read_edgelist(FIXTURES / name))), symbolic=symbolic)


@pytest.mark.parametrize("stem", sorted(TABLE))
def test_exact_values_match_the_hand_derivations(stem):
    expected = TABLE[stem]
    state = exact_of(expected["file"])
    for name, values in expected["links"].items():
        assert float(state.links[name]["omega"]) == pytest.approx(values["omega"], abs=1e-8)
        assert float(state.links[name]["epsilon"]) == pytest.approx(values["epsilon"], abs=1e-6)
    for name, values in expected["points"].items():
        got = state.points[name]
        assert [float(x) for x in got["velocity"]] == pytest.approx(values["velocity"], abs=1e-9)
        assert [float(x) for x in got["acceleration"]] == pytest.approx(
            values["acceleration"], abs=1e-6
        )


def test_problem_2_2_angular_acceleration_is_fifty_root_three():
    state = exact_of("ch2_2_2_slotted_link.edges")
    assert sympy.simplify(state.links["3"]["epsilon"] - 50 * sympy.sqrt(3)) == 0
    assert state.links["3"]["omega"] == 5


def test_exam_slotted_link_turns_at_half_the_crank_speed():
    state = exact_of("exam_1_slotted_link.edges", symbolic=True)
    omega = sympy.Symbol("omega_1")
    assert sympy.simplify(state.links["3"]["omega"] - omega / 2) == 0
    # with a uniform crank the slotted link has no angular acceleration (AC = AB)
    epsilon = sympy.Symbol("epsilon_1")
    assert sympy.simplify(state.links["3"]["epsilon"].subs(epsilon, 0)) == 0


def sketch_fixtures():
    from structure.rigidity.constraints import sketch_problems

    out = []
    for path in sorted(FIXTURES.glob("*.edges")):
        m = read_edgelist(path)
        if m.points and not sketch_problems(m):
            out.append(path.name)
    return out


@pytest.mark.parametrize("name", sketch_fixtures())
def test_exact_and_numeric_solvers_agree_at_the_sketch(name):
    from kinematics.solvers.solve import solve_pose

    plan = make_plan(analyze(read_edgelist(FIXTURES / name)))
    numeric = solve_pose(plan)
    exact = solve_exact(plan)
    for link, state in numeric.links.items():
        assert float(exact.links[link]["omega"]) == pytest.approx(state.omega, abs=1e-9)
        assert float(exact.links[link]["epsilon"]) == pytest.approx(state.epsilon, abs=1e-7)
    for point, state in numeric.points.items():
        v = [float(x) for x in exact.points[point]["velocity"]]
        assert v == pytest.approx(state.velocity.tolist(), abs=1e-9)
