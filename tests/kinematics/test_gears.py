"""Gear trains: Willis relations from the graph, against hand derivations and the solver."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematics.gears.trains import (
    balancing_moment,
    meshes,
    reduced_inertia,
    speed_ratios,
    train_forces,
    train_losses,
)
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_pose
from structure.errors import MobilityError
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES, GEARS_TABLE, expected_table

TABLE = expected_table((GEARS_TABLE,))


@pytest.mark.parametrize("stem", sorted(TABLE))
def test_gear_trains_of_the_source(stem):
    expected = TABLE[stem]
    m = read_edgelist(FIXTURES / expected["file"])
    ratios = speed_ratios(m)
    assert ratios.dof == expected["dof"]
    for link, value in expected["ratios"].items():
        assert ratios.ratios[link] == sympy.Rational(value), link
    if "teeth_found" in expected:
        assert list(ratios.teeth_found.values()) == [expected["teeth_found"]]
    if "balancing_moment" in expected:
        assert balancing_moment(m, ratios) == sympy.Rational(expected["balancing_moment"])
    if "reduced_inertia" in expected:
        assert reduced_inertia(m, ratios) == sympy.Rational(expected["reduced_inertia"])


def test_carriers_are_found_from_the_pins():
    m = read_edgelist(FIXTURES / "exam_2_planetary.edges")
    assert {mesh.carrier for mesh in meshes(m)} == {"c"}
    m = read_edgelist(FIXTURES / "gear_pair.edges")
    assert [mesh.carrier for mesh in meshes(m)] == ["0"]


DIFFERENTIAL = """
name open differential (planar equivalent)
ground 0
driver c
0 c R O
0 3 R O
0 4 R O
c 2 R P
2 3 H gear z=10,20
2 4 H gear z=10,20 internal=4
"""


def test_differential_with_one_input_asks_for_a_second():
    # case c, side gears 3 and 4 (z = 20) and the planet 2 (z = 10) meshing with both; in the
    # planar equivalent of the bevel gears one side meshes internally, so that relative to the
    # case the two sides turn opposite ways. Two Willis relations for four speeds: DOF 2
    m = parse_edgelist(DIFFERENTIAL.strip().splitlines())
    with pytest.raises(MobilityError, match="2 degree"):
        speed_ratios(m)
    both = speed_ratios(m, ["c", "3"])
    w_c, w_3 = sympy.symbols("omega_c omega_3")
    # the side gears' mean speed is the case's: ω3 + ω4 = 2·ωc
    assert sympy.simplify(both.ratios["4"] - (2 * w_c - w_3)) == 0


def test_gear_pair_ratio_agrees_with_the_velocity_solver():
    # the velocity solver sees the mesh through its replacement (the four-bar O1–N1–N2–O2)
    m = read_edgelist(FIXTURES / "gear_pair.edges")
    ratio = speed_ratios(m).ratios["2"]
    state = solve_pose(make_plan(analyze(m)))
    assert state.links["2"].omega / state.links["1"].omega == pytest.approx(float(ratio), rel=1e-6)
    assert ratio == sympy.Rational(-1, 2)


def chain(teeth: list[int], module: float = 0.004, alpha: float = math.radians(20)) -> str:
    """A chain of gears on fixed axles along x, with exact involute geometry for the sketch."""
    lines = ["driver 1 omega=1", "ground 0"]
    x = 0.0
    centers = [0.0]
    for za, zb in itertools.pairwise(teeth):
        x += module * (za + zb) / 2
        centers.append(x)
    d = np.array([math.sin(alpha), math.cos(alpha)])  # the line of action
    for i in range(1, len(teeth) + 1):
        lines.append(f"0 {i} R O{i}")
        lines.append(f"point O{i} {centers[i - 1]!r} 0")
    for i, (za, zb) in enumerate(itertools.pairwise(teeth), start=1):
        k = np.array([centers[i - 1] + module * za / 2, 0.0])
        na = k + ((np.array([centers[i - 1], 0.0]) - k) @ d) * d
        nb = k + ((np.array([centers[i], 0.0]) - k) @ d) * d
        lines.append(f"{i} {i + 1} H K{i} gear z={za},{zb} centers=Na{i},Nb{i}")
        lines.append(f"point K{i} {float(k[0])!r} 0")
        lines.append(f"point Na{i} {float(na[0])!r} {float(na[1])!r}")
        lines.append(f"point Nb{i} {float(nb[0])!r} {float(nb[1])!r}")
    return "\n".join(lines)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.integers(12, 80), min_size=2, max_size=4))
def test_willis_ratios_agree_with_the_velocity_solver(teeth):
    m = parse_edgelist(chain(teeth).splitlines())
    ratios = speed_ratios(m)
    # an ordinary train: each mesh reverses, ω_k/ω_1 = (−1)^(k−1)·z1/z_k
    last = str(len(teeth))
    assert ratios.ratios[last] == sympy.Rational((-1) ** (len(teeth) - 1) * teeth[0], teeth[-1])
    state = solve_pose(make_plan(analyze(m)))
    for link, value in ratios.ratios.items():
        assert state.links[link].omega == pytest.approx(float(value), rel=1e-7, abs=1e-9)


@pytest.mark.parametrize(
    ("stem", "tangential"),
    [
        # 3.11: the sun's 100 N at r1 = 0.2 m and the ring's equal force give 200 N at the pin
        ("ch3_3_11_planetary", 200.0),
        # 3.12: the carrier's 56 N·m at the arm r_C = 5·(28 + 84)/2 mm = 0.28 m: 200 N
        ("ch3_3_12_planetary", 200.0),
    ],
)
def test_planet_force_balance_agrees_with_power(stem, tangential):
    m = read_edgelist(FIXTURES / TABLE[stem]["file"])
    ratios = speed_ratios(m)
    forces = train_forces(m, ratios)
    assert forces.balancing_moment == pytest.approx(float(balancing_moment(m, ratios)))
    ((_, pin_tangential),) = forces.pins.values()
    assert abs(pin_tangential) == pytest.approx(tangential)


def test_mesh_losses_of_problem_3_11():
    # ω_C = 1, ω1 = 4, ω2 = −2: each mesh carries 20 N·m at a relative speed of 3 rad/s
    # (sun: 4 − 1, planet: −2 − 1), so with η = 0.98 each loses 0.02·60 = 1.2 W per rad/s;
    # the sun drives (M1·ω1 = 80), the carrier receives 80 − 2.4 = 77.6: efficiency 0.97
    m = read_edgelist(FIXTURES / "ch3_3_11_planetary.edges")
    losses = train_losses(m, speed_ratios(m), 0.98)
    assert losses.lost_power == pytest.approx(2.4)
    assert losses.balancing_moment == pytest.approx(-77.6)
    assert losses.efficiency == pytest.approx(0.97)
    assert train_losses(m, speed_ratios(m), 1.0).balancing_moment == pytest.approx(-80.0)


def test_reduced_inertia_counts_the_orbiting_planet():
    # 3.11 with a 2 kg planet (J = 0.001) and the carrier input: the planet turns at ω2 = −2·ωC
    # and its centre orbits at R = 0.02·(20 + 20)/2 = 0.4 m: J_red = 0.001·4 + 2·0.4² = 0.324
    text = (FIXTURES / "ch3_3_11_planetary.edges").read_text() + "\nmass 2 2 0.001 B\n"
    m = parse_edgelist(text.splitlines())
    assert reduced_inertia(m, speed_ratios(m)) == sympy.Rational(324, 1000)
