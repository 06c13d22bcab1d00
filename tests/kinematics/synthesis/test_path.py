"""Path generation: answers the solvers confirm, reproducible, refusing what cannot be built."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from kinematics import make_plan, sweep
from kinematics.cli.commands import main
from kinematics.errors import InfeasibleDesignError, SynthesisError
from kinematics.synthesis.linkages import (
    PARAMETERS,
    Linkage,
    coupler_frame,
    is_crank,
    linkage_poses,
)
from kinematics.synthesis.path import (
    PathProblem,
    _fit,
    _fourbar_worst,
    _Placement,
    _scale,
    synthesize_path,
)
from structure import analyze, read_edgelist

from .test_linkages import SIXBARS
from .test_linkages import row as sixbar_row

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
    # the targets were drawn by a crank–rocker the constraints admit: it is found again
    assert timed.error_max < 1e-8


def test_the_design_sweeps_its_whole_turn_on_one_branch(timed) -> None:
    plan = make_plan(analyze(timed.mechanism))
    turn = sweep(plan, np.linspace(0, 2 * math.pi, 721), rates=False)  # raises on a defect
    mu = np.degrees(np.concatenate([v for v in turn.transmission.values()]))
    assert mu.min() >= 30 - 1e-6 and mu.max() <= 150 + 1e-6
    assert timed.grashof in ("crank-rocker", "double-crank")


def test_without_timing_p_meets_the_targets_in_order_on_one_branch() -> None:
    design = synthesize_path(PathProblem(TARGETS, None, seed=7, **QUICK))
    assert design.error_max < 1e-8 and design.in_order
    steps = np.diff(design.inputs_deg)
    assert (np.all(steps > 0) or np.all(steps < 0)) and abs(design.inputs_deg[-1]) < 360
    plan = make_plan(analyze(design.mechanism))
    moved = sweep(plan, np.radians(np.abs(design.inputs_deg)) * np.sign(steps[0]), rates=False)
    gaps = np.linalg.norm(moved.points["P"]["position"] - TARGETS, axis=1)
    np.testing.assert_allclose(gaps, design.errors, atol=1e-9)


def test_crank_angles_from_a_fixed_ground_line() -> None:
    # a frame fixed at A (0, 0) along +x and the crank's angles measured from it
    shifted = KNOWN.copy()
    shifted[9] = math.radians(25.0)
    crank = 25.0 + CRANK
    phi = np.radians(crank)[None]
    targets = linkage_poses(Linkage.FOURBAR, shifted[None], phi).points["P"][0]
    problem = PathProblem(
        targets,
        crank,
        seed=3,
        fixed={"ax": 0.0, "ay": 0.0, "theta0": 0.0},
        crank_from_ground=True,
        **QUICK,
    )
    design = synthesize_path(problem)
    p = design.parameters
    assert (p["ax"], p["ay"], p["theta0"]) == (0.0, 0.0, 0.0)
    assert p["phi1"] == pytest.approx(math.radians(25.0), abs=1e-12)
    assert design.error_max < 1e-8


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


def test_crank_angles_from_the_ground_need_timing() -> None:
    with pytest.raises(SynthesisError, match="need targets with timing"):
        synthesize_path(PathProblem(TARGETS, None, crank_from_ground=True, **QUICK))


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


# ------------------------------------------------------------------ the closed forms of the search
def _frame(angles: np.ndarray):
    """The frame P is fixed in, of the known four-bar at ``angles``."""
    x = KNOWN.copy()[None]
    return coupler_frame(Linkage.FOURBAR, linkage_poses(Linkage.FOURBAR, x, angles[None]), x)


@pytest.mark.parametrize("mode", [_Placement.FREE, _Placement.SIZE])
def test_the_placement_and_p_are_fitted_exactly(mode) -> None:
    s, _, _ = _scale(PathProblem(TARGETS, CRANK))
    o, u = _frame(0.3 + np.radians(CRANK))
    anchor = np.array([0.7 - 0.2j])
    pq = 1.3 - 0.4j
    if mode is _Placement.FREE:
        z, w = 0.6 * np.exp(2.1j), -1.5 + 0.25j
    else:  # a growth about A
        z, w = 1.7 + 0j, anchor[0] * (1 - 1.7)
    targets = z * (o[0] + u[0] * pq) + w
    fz, fw, fpq = _fit(s, mode, o, u, np.array([0j]), targets, anchor)
    np.testing.assert_allclose([fz[0], fw[0], fpq[0]], [z, w, pq], atol=1e-12)


def test_the_four_bars_least_transmission_angle_is_exact() -> None:
    s, _, _ = _scale(PathProblem(TARGETS, CRANK))
    rng = np.random.default_rng(1)
    x = np.repeat(KNOWN[None], 60, axis=0)
    k = [PARAMETERS[Linkage.FOURBAR].index(n) for n in ("d", "a", "b", "c")]
    x[:, k] *= rng.uniform(0.8, 1.25, size=(60, 4))
    x = x[is_crank(*x[:, k].T)]
    turn = np.linspace(0.0, 2 * math.pi, 8001)
    mu = linkage_poses(Linkage.FOURBAR, x, x[:, [9]] + turn).transmission[0]
    sampled = np.minimum(mu, np.pi - mu).min(axis=1)
    exact = _fourbar_worst(s, x)
    assert np.all(exact <= sampled + 1e-12)
    np.testing.assert_allclose(exact, sampled, atol=1e-6)


# ------------------------------------------------------------------ six-bars, end to end
SIXBAR_CRANK = np.arange(8) * 40.0


def _sixbar_targets(linkage: Linkage) -> np.ndarray:
    x = sixbar_row(linkage, **SIXBARS[linkage])
    phi = x[PARAMETERS[linkage].index("phi1")] + np.radians(SIXBAR_CRANK)
    return linkage_poses(linkage, x[None], phi[None]).points["P"][0]


def _check_sixbar(design, targets: np.ndarray, share: float) -> None:
    size = np.max(np.linalg.norm(targets - targets.mean(axis=0), axis=1))
    assert design.error_max < share * size
    plan = make_plan(analyze(design.mechanism))
    inputs = np.radians(np.concatenate([[0.0], SIXBAR_CRANK[1:]]))
    moved = sweep(plan, inputs, rates=False)
    gaps = np.linalg.norm(moved.points["P"]["position"] - targets, axis=1)
    np.testing.assert_allclose(gaps, design.errors, atol=1e-9)
    turn = sweep(plan, np.linspace(0, 2 * math.pi, 721), rates=False)  # one branch, all of it
    mu = np.degrees(np.concatenate([v for v in turn.transmission.values()]))
    assert mu.min() >= 30 - 1e-6 and mu.max() <= 150 + 1e-6


@pytest.mark.parametrize("linkage", list(SIXBARS))
def test_a_six_bar_path_generator_the_solvers_confirm(linkage: Linkage) -> None:
    targets = _sixbar_targets(linkage)
    design = synthesize_path(PathProblem(targets, SIXBAR_CRANK, linkage, seed=0, **QUICK))
    _check_sixbar(design, targets, 0.1)


@pytest.mark.slow
@pytest.mark.parametrize("linkage", list(SIXBARS))
def test_a_six_bar_nearly_finds_the_one_that_drew_the_targets(linkage: Linkage) -> None:
    targets = _sixbar_targets(linkage)
    design = synthesize_path(PathProblem(targets, SIXBAR_CRANK, linkage, seed=0), jobs=2)
    _check_sixbar(design, targets, 0.01)
