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
    balancing_moments,
    inertia_matrix,
    link_speeds,
    meshes,
    reduced_inertia,
    speed_ratios,
    speed_relations,
    train_forces,
    train_losses,
)
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_pose
from structure.errors import MechanismError, MobilityError
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
    # ω_C = 1, ω1 = 4, ω2 = −2, the ring fixed. In the carrier's frame the sun turns at 3 and
    # drives (its load M1 = 20 gives 60 W per rad/s of the carrier), the planet turns at −3 and
    # drives the ring. Torque method, η per mesh applied in the direction of flow:
    #   sun:    μ1 + 20 = 0                    → μ1 = −20 (moment of mesh 1 on the sun)
    #   planet: η·(z2/z1)·μ1 + μ2 = 0          → μ2 = 20η (moment of mesh 2 on the planet)
    #   ring:   ν2 = −η·(z3/z2)·μ2 = −60η²     (the ground takes it)
    #   carrier: M_C = −(sun + ring) = −(20 + 60η²) = −77.624 N·m at η = 0.98.
    # The first-order estimate −(80 − 2·0.02·60) = −77.6 was the old answer. The sun gives 80 W,
    # the carrier takes 77.624: loss 2.376 W, efficiency 0.25 + 0.75η² = 0.9703.
    m = read_edgelist(FIXTURES / "ch3_3_11_planetary.edges")
    losses = train_losses(m, speed_ratios(m), 0.98)
    assert losses.balancing_moment == pytest.approx(-(20 + 60 * 0.98**2), rel=1e-12)
    assert losses.lost_power == pytest.approx(80 - 77.624, rel=1e-9)
    assert losses.efficiency == pytest.approx(0.9703, rel=1e-12)
    # each mesh passes 60 W (sun side) and 58.8 W (planet side) and loses 2 % of it
    assert sorted(losses.mesh_power.values()) == pytest.approx([58.8, 60.0])
    assert sum(losses.mesh_loss.values()) == pytest.approx(losses.lost_power, rel=1e-12)
    assert train_losses(m, speed_ratios(m), 1.0).balancing_moment == pytest.approx(-80.0)


def test_mesh_losses_of_problem_3_12():
    # The sun 1 drives (ω1 = 1, ωC = −2/13), gear 3 is fixed; in the carrier's frame the sun
    # turns at 15/13 and drives the compound planet, which drives gear 3 (relative speed 2/13):
    # i_13^C = (z2/z1)(z3/z2') = 7.5. Torques: T3 = −7.5·η²·T1 (both meshes pass the power
    # from the sun's side), T1 + T3 + Mc = 0 with Mc = 56: T1 = 56/(7.5η² − 1).
    m = read_edgelist(FIXTURES / "ch3_3_12_planetary.edges")
    eta = 0.98
    losses = train_losses(m, speed_ratios(m), eta)
    expected = 56 / (7.5 * eta**2 - 1)  # 9.02789 N·m; first order gave 9.01302
    assert losses.balancing_moment == pytest.approx(expected, rel=1e-12)
    # power: the sun gives 9.0279 W per rad/s, the carrier's load takes 56·2/13
    assert losses.lost_power == pytest.approx(expected - 56 * 2 / 13, rel=1e-9)
    assert losses.efficiency == pytest.approx((56 * 2 / 13) / expected, rel=1e-12)


def test_mesh_loss_of_an_ordinary_pair_is_applied_once():
    # gear 1 (z = 20) at ω1 = 1 turns gear 2 (z = 40) at ω2 = −1/2; a moment +10 on gear 2
    # resists (power −5 W): lossless the input gives 5 N·m, with one mesh of efficiency η it
    # must give 5/η (the driven gear gets η of the moment ratio)
    lines = ["driver 1", "0 1 R A", "0 2 R B", "1 2 H gear z=20,40"]
    m = parse_edgelist([*lines, "moment 2 10"])
    losses = train_losses(m, speed_ratios(m), 0.9)
    assert losses.balancing_moment == pytest.approx(5 / 0.9, rel=1e-12)
    assert losses.efficiency == pytest.approx(0.9, rel=1e-12)
    # −10 drives gear 2 along its motion: gear 1 brakes and receives η of the 5 W
    m = parse_edgelist([*lines, "moment 2 -10"])
    losses = train_losses(m, speed_ratios(m), 0.9)
    assert losses.balancing_moment == pytest.approx(-5 * 0.9, rel=1e-12)
    assert losses.efficiency == pytest.approx(0.9, rel=1e-12)


@pytest.mark.parametrize("stem", ["ch3_3_11_planetary", "ch3_3_12_planetary"])
def test_the_lossless_torque_method_is_the_power_method(stem):
    # two independent routes: the moment balances of every link (η = 1) and virtual power
    m = read_edgelist(FIXTURES / f"{stem}.edges")
    ratios = speed_ratios(m)
    found = train_losses(m, ratios, 1.0)
    assert found.balancing_moment == pytest.approx(float(balancing_moment(m, ratios)))
    assert found.lost_power == pytest.approx(0.0, abs=1e-9)


def test_moment_lines_on_one_link_add_up():
    # two `moment 1 20` lines are 40 N·m on the sun: by power −160, by the force balance the
    # same (the force balance used to keep only the last line)
    text = (FIXTURES / "ch3_3_11_planetary.edges").read_text() + "\nmoment 1 20\n"
    m = parse_edgelist(text.splitlines())
    ratios = speed_ratios(m)
    assert balancing_moment(m, ratios) == -160
    assert train_forces(m, ratios).balancing_moment == pytest.approx(-160.0)
    assert train_losses(m, ratios, 1.0).balancing_moment == pytest.approx(-160.0)


def test_reduced_inertia_counts_the_orbiting_planet():
    # 3.11 with a 2 kg planet (J = 0.001) and the carrier input: the planet turns at ω2 = −2·ωC
    # and its centre orbits at R = 0.02·(20 + 20)/2 = 0.4 m: J_red = 0.001·4 + 2·0.4² = 0.324
    text = (FIXTURES / "ch3_3_11_planetary.edges").read_text() + "\nmass 2 2 0.001 B\n"
    m = parse_edgelist(text.splitlines())
    assert reduced_inertia(m, speed_ratios(m)) == sympy.Rational(324, 1000)


TWO_INPUTS = DIFFERENTIAL.replace("driver c", "driver c omega=10\ndriver 3 omega=4")


def test_a_differential_has_relations_in_its_two_inputs():
    # the planet 2 (z = 10) meshes externally with 3 and internally with 4 (z = 20), carrier c:
    #   10(ω2 − ωc) = −20(ω3 − ωc) → ω2 = 3ωc − 2ω3
    #   10(ω2 − ωc) = +20(ω4 − ωc) → ω4 = ωc + (ω2 − ωc)/2 = 2ωc − ω3
    m = parse_edgelist(TWO_INPUTS.strip().splitlines())
    ratios = speed_ratios(m)
    relations = speed_relations(ratios)
    assert relations["2"] == {"c": 3, "3": -2}
    assert relations["4"] == {"c": 2, "3": -1}
    # at ωc = 10, ω3 = 4: ω2 = 30 − 8 = 22, ω4 = 20 − 4 = 16
    assert link_speeds(ratios, {"c": 10, "3": 4}) == {"c": 10, "3": 4, "4": 16, "2": 22}


def test_a_differential_has_a_balancing_moment_per_input():
    # virtual power with a load M4 on 4: M_c·ωc + M_3·ω3 + M4·(2ωc − ω3) = 0 for all ωc, ω3,
    # so M_c = −2·M4 and M_3 = M4; a load on the input 3 itself is balanced there alone
    lines = TWO_INPUTS.strip().splitlines()
    m = parse_edgelist([*lines, "moment 4 -20"])
    assert balancing_moments(m, speed_ratios(m)) == {"c": 40, "3": -20}
    m = parse_edgelist([*lines, "moment 3 20"])
    assert balancing_moments(m, speed_ratios(m)) == {"c": 0, "3": -20}
    with pytest.raises(MobilityError, match="one per input"):
        balancing_moment(m, speed_ratios(m))


def test_a_differential_with_modules_balances_by_forces_too():
    # a buildable two-input train: sun 3 (z = 20), planet 2 (z = 10), ring 4 (z = 40), module
    # 1 mm, both arms 15 mm. 10(ω2 − ωc) = −20(ω3 − ωc), 10(ω2 − ωc) = 40(ω4 − ωc):
    # ω4 = 1.5ωc − 0.5ω3; a load M4 = −20 asks M_c = 30 and M_3 = −10 by power, and the
    # planets' force balance with one balancing moment per input must agree
    m = parse_edgelist(
        [
            "driver c",
            "driver 3",
            "0 c R O",
            "0 3 R O",
            "0 4 R O",
            "c 2 R P",
            "2 3 H gear z=10,20 module=0.001",
            "2 4 H gear z=10,40 internal=4 module=0.001",
            "moment 4 -20",
        ]
    )
    ratios = speed_ratios(m)
    assert balancing_moments(m, ratios) == {"c": 30, "3": -10}
    forces = train_forces(m, ratios)
    assert forces.balancing_moments == pytest.approx({"c": 30.0, "3": -10.0})
    with pytest.raises(MobilityError, match="one balancing moment per input"):
        _ = forces.balancing_moment


def test_mesh_losses_of_a_differential_at_its_given_speeds():
    # ωc = 10, ω3 = 4, so ω4 = 16, ω2 = 22; in the carrier's frame ω2 − ωc = 12,
    # ω3 − ωc = −6, ω4 − ωc = 6. Lossless, with M4 = −20: μ2 = −10 on the planet from
    # mesh 2–4, μ1 = 10 from mesh 2–3; mesh 2–3 takes power from 3 (μ1·12 > 0: 3 drives the
    # planet, ν = (2/η)·μ), mesh 2–4 gives it to 4 (ν = −2η·μ). Then
    #   4:       −2η·μ2 − 20 = 0          → μ2 = −10/η
    #   planet:  μ1 + μ2 = 0              → μ1 = 10/η
    #   3:       (2/η)·μ1 + M3 = 0        → M3 = −20/η²
    #   carrier: −(1 + 2/η)·μ1 − (1 − 2η)·μ2 + Mc = 0 → Mc = 20 + 20/η²
    eta = 0.98
    m = parse_edgelist([*TWO_INPUTS.strip().splitlines(), "moment 4 -20"])
    ratios = speed_ratios(m)
    losses = train_losses(m, ratios, eta, {"c": 10.0, "3": 4.0})
    assert losses.balancing_moments["c"] == pytest.approx(20 + 20 / eta**2, rel=1e-12)
    assert losses.balancing_moments["3"] == pytest.approx(-20 / eta**2, rel=1e-12)
    given = 10 * (20 + 20 / eta**2)  # the carrier gives; 3 and 4 take
    taken = 4 * 20 / eta**2 + 16 * 20
    assert losses.lost_power == pytest.approx(given - taken, rel=1e-9)
    assert losses.efficiency == pytest.approx(taken / given, rel=1e-12)
    with pytest.raises(MechanismError, match="omega= on every driver"):
        train_losses(m, ratios, eta)


def test_a_differential_has_an_inertia_matrix():
    # J4 = 0.5 on ω4 = 2ωc − ω3 and Jc = 0.1 on ωc: T = ½(0.1ωc² + 0.5(2ωc − ω3)²), so
    # J = [[0.1 + 2, −1], [−1, 0.5]]
    lines = TWO_INPUTS.strip().splitlines()
    m = parse_edgelist([*lines, "mass 4 0 0.5 O", "mass c 0 0.1 O"])
    matrix = inertia_matrix(m, speed_ratios(m))
    assert matrix.tolist() == [[sympy.Rational(21, 10), -1], [-1, sympy.Rational(1, 2)]]


def test_losses_through_three_meshes_with_two_planets_in_a_row():
    # sun 1 (z = 20) – planet 2 (10) – planet 3 (10) – fixed ring (50), carrier c. Willis:
    # ω3 − ωc = −5ωc, ω2 − ωc = 5ωc, ω1 − ωc = −2.5ωc, so ω1 = 1 gives ωc = −2/3. The load
    # −5 N·m on c drives (power 10/3): lossless the sun brakes with −10/3 N·m. In the carrier's
    # frame the ring (relative speed 2/3) gives power to the sun (5/3) through three meshes:
    # −T1·5/3 = η³·T0·2/3 with T0 = 5 − T1 (moments about the axis balance), so
    # T1 = −5η³/(2.5 − η³).
    text = """
driver 1
0 1 R O
0 c R O
c 2 R P
c 3 R Q
1 2 H gear z=20,10 module=0.001
2 3 H gear z=10,10 module=0.001
3 0 H gear z=10,50 internal=0 module=0.001
moment c -5
"""
    m = parse_edgelist(text.strip().splitlines())
    ratios = speed_ratios(m)
    assert balancing_moment(m, ratios) == sympy.Rational(-10, 3)
    eta = 0.95
    losses = train_losses(m, ratios, eta)
    assert losses.balancing_moment == pytest.approx(-5 * eta**3 / (2.5 - eta**3), rel=1e-12)
    # the planets' force balance does not cover a mesh between two planets: refused, not guessed
    with pytest.raises(MechanismError, match="between two planets"):
        train_forces(m, ratios)


@settings(max_examples=20, deadline=None)
@given(st.lists(st.integers(12, 80), min_size=2, max_size=5), st.floats(0.8, 1.0))
def test_an_ordinary_train_passes_eta_to_the_power_of_its_meshes(teeth, eta):
    # gears on fixed axes in a row, the last one loaded against its motion: the power goes
    # through every mesh once, so the input gives P/η^(meshes), P the load's (lossless) power
    lines = chain(teeth).splitlines()
    last = str(len(teeth))
    m = parse_edgelist(lines)
    ratio = speed_ratios(m).ratios[last]  # ω_last/ω_1
    m = parse_edgelist([*lines, f"moment {last} {-1.0 if ratio > 0 else 1.0}"])
    ratios = speed_ratios(m)
    lossless = float(balancing_moment(m, ratios))  # = |ratio| > 0: the input drives
    losses = train_losses(m, ratios, eta)
    assert losses.balancing_moment == pytest.approx(lossless / eta ** (len(teeth) - 1), rel=1e-9)
    assert losses.efficiency == pytest.approx(eta ** (len(teeth) - 1), rel=1e-9)
