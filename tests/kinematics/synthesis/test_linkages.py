"""Linkages as rows of numbers: their closed forms against the solvers, their six-bar kinds."""

from __future__ import annotations

import math
from collections import Counter

import numpy as np
import pytest

from kinematics import make_plan, sweep
from kinematics.synthesis.linkages import (
    PARAMETERS,
    Linkage,
    coupler_frame,
    design_mechanism,
    linkage_poses,
    place,
)
from structure import analyze

TURN = np.linspace(0.0, 2 * math.pi, 721)
SIXBARS = {
    # a crank–rocker (A (0, 0), D (4, 0), a 1, b 4, c 3) and a dyad that closes over the turn
    Linkage.WATT1: {"e": 3, "f": 3},
    Linkage.WATT2: {"ex": 1.5, "ey": 1, "gx": 5, "gy": 4, "e": 3, "f": 3},
    Linkage.STEPHENSON3: {},
}


def row(linkage: Linkage, **changes: float) -> np.ndarray:
    numbers = {"ax": 0, "ay": 0, "theta0": 0, "d": 4, "a": 1, "b": 4, "c": 3, "p": 1, "q": 0.5}
    numbers.update({"phi1": 0.3, "side": 1, "side2": 1, "ex": 2, "ey": 1, "gx": 2, "gy": 6})
    numbers.update({"hx": 1.5, "hy": -1, "e": 4, "f": 4, **changes})
    return np.array([numbers[n] for n in PARAMETERS[linkage]], dtype=float)


@pytest.mark.parametrize("linkage", [Linkage.FOURBAR, *SIXBARS])
def test_the_closed_forms_place_p_where_the_solvers_do(linkage: Linkage) -> None:
    x = row(linkage, **SIXBARS.get(linkage, {}))
    phi = x[PARAMETERS[linkage].index("phi1")] + TURN
    poses = linkage_poses(linkage, x[None], phi[None])
    assert all(h.min() > 0 for h in poses.heights)  # it closes over the whole turn
    solved = sweep(make_plan(analyze(design_mechanism(linkage, x))), TURN, rates=False)
    for name in ("P", "C", "F") if linkage is not Linkage.FOURBAR else ("P", "C"):
        np.testing.assert_allclose(
            solved.points[name]["position"], poses.points[name][0], atol=1e-12
        )


@pytest.mark.parametrize(
    "linkage, ground_ternary, ternaries_jointed",
    [
        (Linkage.WATT1, False, True),  # Watt's chain, a binary ground
        (Linkage.WATT2, True, True),  # Watt's chain, a ternary ground: four-bars in series
        (Linkage.STEPHENSON3, True, False),  # Stephenson's chain, a ternary ground
    ],
)
def test_the_six_bars_are_the_inversions_they_are_named(
    linkage: Linkage, ground_ternary: bool, ternaries_jointed: bool
) -> None:
    m = design_mechanism(linkage, row(linkage, **SIXBARS[linkage]))
    pairs = [(p.a, p.b) for p in m.pairs]
    degree = Counter(link for pair in pairs for link in pair)
    assert sorted(degree.values()) == [2, 2, 2, 2, 3, 3] and len(pairs) == 7
    ternary = {link for link, k in degree.items() if k == 3}
    assert ("0" in ternary) is ground_ternary
    assert any(set(pair) == ternary for pair in pairs) is ternaries_jointed
    assert m.points["P"].on == "4"


def test_a_similarity_moves_every_point_of_a_linkage() -> None:
    x = row(Linkage.STEPHENSON3)
    z, w = 0.5 * np.exp(0.7j), 3 - 2j
    moved = place(Linkage.STEPHENSON3, x[None], np.array([z]), np.array([w]))
    phi = np.array([[0.1, 1.0, 2.5]])
    before = linkage_poses(Linkage.STEPHENSON3, x[None], phi).points
    after = linkage_poses(Linkage.STEPHENSON3, moved, phi + np.angle(z)).points
    for name in ("A", "B", "C", "D", "E", "F", "G", "P"):
        u = before[name][0, :, 0] + 1j * before[name][0, :, 1]
        np.testing.assert_allclose(after[name][0, :, 0] + 1j * after[name][0, :, 1], z * u + w)


def test_p_is_fixed_in_the_frame_of_its_link() -> None:
    x = row(Linkage.WATT1, **SIXBARS[Linkage.WATT1])
    poses = linkage_poses(Linkage.WATT1, x[None], (0.3 + TURN)[None])
    origin, axis = coupler_frame(Linkage.WATT1, poses, x[None])
    np.testing.assert_allclose(np.abs(axis), 1.0)
    p = poses.points["P"][0, :, 0] + 1j * poses.points["P"][0, :, 1]
    np.testing.assert_allclose(origin[0] + axis[0] * (1 + 0.5j), p, atol=1e-12)
