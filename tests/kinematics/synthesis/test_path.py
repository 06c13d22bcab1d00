"""Path generation: answers the solvers confirm, reproducible, refusing what cannot be built."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from kinematics import make_plan, sweep
from kinematics.cli.main import main
from kinematics.errors import InfeasibleDesignError, SynthesisError
from kinematics.synthesis.linkages import Linkage, linkage_poses
from kinematics.synthesis.path import PathProblem, synthesize_path
from structure import analyze, read_edgelist

# targets traced by a known crank–rocker (A (0, 0), d 4, a 1, b 4, c 3, P (2, 1) on the coupler)
KNOWN = np.array([0, 0, 0, 4, 1, 4, 3, 2, 1, 0.3, 1.0])
CRANK = np.array([0.0, 40.0, 80.0, 120.0, 160.0, 200.0])
TARGETS = linkage_poses(Linkage.FOURBAR, KNOWN[None], (0.3 + np.radians(CRANK))[None]).points["P"][
    0
]
QUICK = {"generations": 40, "population": 12, "restarts": 1}


@pytest.fixture(scope="module")
def timed():
    return synthesize_path(PathProblem(TARGETS, CRANK, seed=7, **QUICK))


def test_the_errors_are_those_the_solvers_give(timed) -> None:
    m = timed.mechanism
    plan = make_plan(analyze(m))
    result = sweep(plan, np.radians(np.concatenate([[0.0], CRANK[1:] - CRANK[0]])), rates=False)
    gaps = np.linalg.norm(result.points["P"]["position"] - TARGETS, axis=1)
    np.testing.assert_allclose(gaps, timed.errors, atol=1e-9)
    assert timed.error_max == pytest.approx(gaps.max(), abs=1e-9)
    assert timed.error_max < 0.2 * 4  # well inside the targets' size after 40 generations


def test_the_design_sweeps_its_whole_turn_on_one_branch(timed) -> None:
    plan = make_plan(analyze(timed.mechanism))
    turn = sweep(plan, np.linspace(0, 2 * math.pi, 721), rates=False)  # raises on a defect
    mu = np.degrees(np.concatenate([v for v in turn.transmission.values()]))
    assert mu.min() >= 30 - 1e-6 and mu.max() <= 150 + 1e-6
    assert timed.grashof in ("crank-rocker", "double-crank")


def test_a_seed_reproduces_its_answer(timed) -> None:
    again = synthesize_path(PathProblem(TARGETS, CRANK, seed=7, **QUICK))
    np.testing.assert_array_equal(again.x, timed.x)


def test_the_answer_does_not_depend_on_the_unit_of_length(timed) -> None:
    mm = synthesize_path(PathProblem(TARGETS * 1000, CRANK, seed=7, **QUICK))
    # the same search in other units: the same design to round-off (1e-6 of the targets' size)
    assert abs(mm.error_max / 1000 - timed.error_max) <= 1e-6 * 4
    np.testing.assert_allclose(mm.x[3:7] / 1000, timed.x[3:7], rtol=1e-5)


@pytest.mark.parametrize(
    "targets, crank, message",
    [
        (TARGETS[:2], None, "at least 3"),
        (np.zeros((101, 2)) + np.arange(101)[:, None], None, "at most 100"),
        (np.array([[0, 0], [1, 0], [2, 0], [0, 0]], float), None, "straight line"),
        (np.array([[0, 0], [1, 0], [2, 0]], float), np.array([0, 200, 400.0]), "straight line"),
        (TARGETS[:3], np.array([0, 50, 20.0]), "rise"),
    ],
)
def test_bad_targets_are_named(targets, crank, message) -> None:
    with pytest.raises(SynthesisError, match=message):
        synthesize_path(PathProblem(targets, crank, **QUICK))


def test_no_feasible_design_names_the_constraint_that_refused_most() -> None:
    with pytest.raises(InfeasibleDesignError, match="transmission angle constraint") as info:
        synthesize_path(
            PathProblem(
                TARGETS, CRANK, transmission_min=89.9, generations=3, population=5, restarts=1
            )
        )
    assert max(info.value.rejections, key=info.value.rejections.get) == "transmission angle"


def test_cli_contract(tmp_path, capsys) -> None:
    csv = tmp_path / "targets.csv"
    csv.write_text(
        "x,y,crank_deg\n"
        + "\n".join(f"{x},{y},{c}" for (x, y), c in zip(TARGETS, CRANK, strict=True))
    )
    out = tmp_path / "design.edges"
    code = main(
        [
            "synthesize",
            "path",
            str(csv),
            "--linkage",
            "fourbar",
            "--timing",
            "--seed",
            "7",
            "--generations",
            "40",
            "--population",
            "12",
            "--restarts",
            "1",
            "-o",
            str(out),
            "--json",
        ]
    )
    assert code == 0
    answer = json.loads(capsys.readouterr().out, parse_constant=lambda c: 1 / 0)
    for key in (
        "error_max",
        "error_rms",
        "transmission_deg",
        "grashof",
        "seed",
        "evaluations",
        "seconds",
    ):
        assert key in answer
    m = read_edgelist(out)
    assert m.points["P"].on == "2" and len(m.targets) == len(TARGETS)
    assert main(["classify", str(out)]) == 0
