"""Kinetostatics: reactions and balancing moment, by hand statics and by virtual power."""

from __future__ import annotations

import json
import math
import random

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from kinematics.cli.commands import main
from kinematics.kinetostatics.forces import IndeterminateError, forces_over, solve_forces
from kinematics.results.serialization import forces_to_dict
from kinematics.solvers.exact import forces_exact
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import SingularPoseError, solve_pose, solve_poses
from structure.errors import MechanismError
from structure.generators import random_mechanism
from structure.model import Load, PointDef
from structure.readwrite.edgelist import parse_edgelist, write_edgelist
from structure.report import analyze

from ..conftest import FIXTURES


def forces_of(text: str, **kw):
    return solve_forces(make_plan(analyze(parse_edgelist(text.strip().splitlines()))), **kw)


SQUARE = """
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0 0.1
point C 0.1 0.1
point D 0.1 0
point E 0.1 0.05 on=3
force 3 E 1000 0
"""


def reaction(result, point):
    (r,) = [x for x in result.reactions if x.point == point]
    return r


def test_square_four_bar_by_hand():
    # BC is a two-force member along x; moments about D on the rocker: 0.05·1000 = 0.1·F,
    # so the coupler pulls the rocker with 500 N toward −x, and the crank needs 0.1·500 = 50 N·m
    result = forces_of(SQUARE)
    assert result.balancing_moment["1"] == pytest.approx(50.0)
    c = reaction(result, "C")
    force_on_3 = c.force if c.links == ("2", "3") else -c.force
    np.testing.assert_allclose(force_on_3, [-500.0, 0.0], atol=1e-9)
    d = reaction(result, "D")
    force_on_ground = d.force if d.links == ("3", "0") else -d.force
    np.testing.assert_allclose(force_on_ground, [500.0, 0.0], atol=1e-9)
    assert result.power_residual < 1e-12
    assert result.order == ("II(2,3)", "I(1)")


def test_crank_slider_balancing_moment_by_hand():
    # crank AB = 0.1 along +y, rod BC = 0.2 to C = (√0.03, 0) on the slide y = 0. The rod is a
    # two-force member: to balance 100 N along −x on the slider it pushes the slider with
    # +100 N in x, so it pushes the crank at B with −100 N in x (and some y, through A's
    # height 0): moment about A = (0, 0.1) × (−100, F_y) = +10 N·m, so M_b = −10 N·m.
    cx = math.sqrt(0.03)
    text = f"""
driver 1 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0 0.1
point C {cx!r} 0
force 3 C -100 0
"""
    result = forces_of(text)
    assert result.balancing_moment["1"] == pytest.approx(-10.0, rel=1e-12)
    assert result.power_residual < 1e-12


def test_balancing_force_instead_of_a_moment():
    text = SQUARE + "balance 1 B angle=0\n"
    result = forces_of(text)
    assert result.balancing_moment == {}
    # the moment 50 N·m about A from a force at B (0, 0.1) along x: −0.1·F = 50
    np.testing.assert_allclose(result.balancing_force, [-500.0, 0.0], atol=1e-9)


def test_over_constrained_reactions_are_indeterminate():
    text = (FIXTURES / "parallelogram_redundant.edges").read_text()
    with pytest.raises(IndeterminateError, match="indeterminate"):
        forces_of(text + "\nforce 3 C 100 0\n")
    result = forces_of(text + "\nforce 3 C 100 0\n", minimum_norm=True)
    assert result.power_residual < 1e-9


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000), n=st.integers(3, 12))
def test_balancing_moment_equals_virtual_power(seed, n):
    """Random dyad mechanisms, random sketch, random loads: the group-by-group balancing
    moment equals the one from virtual power (Σ P·v + Σ M·ω + M_b·ω1 = 0)."""
    rng = random.Random(seed)
    m = random_mechanism(n, seed, kinds=("RRR", "RRP", "RPR", "PRP", "RPP"))
    names = {p.point for p in m.pairs if p.point}
    points = {x: PointDef(x, rng.uniform(-1, 1), rng.uniform(-1, 1)) for x in sorted(names)}
    loads = []
    for link in m.moving_links:
        pin = next(p.point for p in m.pairs_of(link) if p.point)
        loads.append(Load("force", link, pin, (rng.uniform(-100, 100), rng.uniform(-100, 100))))
        loads.append(Load("moment", link, None, (rng.uniform(-10, 10),)))
    text = write_edgelist(m.evolve(points=points, loads=tuple(loads)))
    text = text.replace("driver 1\n", "driver 1 omega=3\n")
    try:
        result = forces_of(text)
    except SingularPoseError:
        assume(False)
    assert result.power_residual < 1e-9


def test_cli_forces_json(capsys, tmp_path):
    path = tmp_path / "square.edges"
    path.write_text(SQUARE)
    assert main(["forces", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["balancing_moment"] == pytest.approx(50.0)
    assert data["inputs"] == [0.0] and "balancing_slide_force" not in data
    assert {"point", "links", "force", "magnitude"} <= set(data["reactions"][0])
    assert data["power_residual"] < 1e-12


def test_slide_friction_on_a_pushed_block():
    # a block pressed down with 100 N slides at 2 m/s on a guide with μ = 0.3: the drive must
    # overcome 30 N of friction, which dissipates 30·2 = 60 W
    text = """
driver 1 v=2
0 1 P S angle=0 friction=0.3
point S 0 0
force 1 S 0 -100
"""
    result = forces_of(text)
    assert result.balancing_moment["1"] == pytest.approx(30.0)
    assert result.friction_loss == pytest.approx(60.0)
    assert result.power_residual < 1e-12


def test_pin_friction_circle_on_a_crank():
    # a 0.1 m crank turning at 5 rad/s against 200 N at its tip: 20 N·m, plus the friction
    # circle 0.01 m times the 200 N pin reaction, 2 N·m; the loss is 2·5 = 10 W
    text = """
driver 1 omega=5
0 1 R A circle=0.01
point A 0 0
point B 0.1 0
force 1 B 0 -200
"""
    result = forces_of(text)
    assert result.balancing_moment["1"] == pytest.approx(22.0)
    assert result.friction_loss == pytest.approx(10.0)


OVERHUNG_BLOCK = """
driver 1 v=2
0 1 P S angle=0 span=0.1 friction=0.3
point S 0 0
point K {x} 0 on=1
force 1 K 0 -100
"""


def _contact_sizes(result, point):
    n1, n2 = reaction(result, point).contacts
    return sorted([float(np.hypot(*n1)), float(np.hypot(*n2))])


def test_slide_friction_counts_both_contacts_when_they_bear_on_opposite_faces():
    # issue 22, item 9. A block on a guide with two contacts at x = ∓0.05 (span 0.1), pressed
    # by 100 N at K, 0.1 m ahead of S, slides at 2 m/s. Net normal N = 100 up; the couple about
    # S is 0.1·100 = 10 N·m, so n1 + n2 = 100 and 0.05·(n2 − n1) = 10: n2 = 150, n1 = −50 (the
    # back contact bears on the other face). The friction is μ(|n1| + |n2|) = 0.3·200 = 60 N
    # (not μ|N| = 30 N); it acts along the guide's line through S, so it leaves the couple and
    # the contacts as they are. Balancing force 60 N, loss 60·2 = 120 W.
    result = forces_of(OVERHUNG_BLOCK.format(x=0.1))
    assert _contact_sizes(result, "S") == pytest.approx([50.0, 150.0])
    assert result.balancing_moment["1"] == pytest.approx(60.0)
    assert result.friction_loss == pytest.approx(120.0)
    assert result.power_residual < 1e-12
    # the load between the contacts (0.02 m ahead): 0.05·(n2 − n1) = 2, n = 30 and 70, both
    # on one face: the friction is μ·100 = 30 N either way
    result = forces_of(OVERHUNG_BLOCK.format(x=0.02))
    assert _contact_sizes(result, "S") == pytest.approx([30.0, 70.0])
    assert result.balancing_moment["1"] == pytest.approx(30.0)
    assert result.friction_loss == pytest.approx(60.0)


SINE_WITH_FRICTION = (
    (FIXTURES / "ch3_3_6_sine_mechanism.edges")
    .read_text()
    .replace("span=0.2", "span=0.2 friction=0.1")
)


def test_friction_of_a_yoke_held_by_a_couple_alone():
    # problem 3.6 (Scotch yoke) with μ = 0.1 in the yoke's guide, contacts ∓0.1 m (span 0.2).
    # The guide's net normal force is 0: it holds the yoke by a couple alone, C = (P + F)·h,
    # h = 0.05·√2 the height of the block B over the yoke's axis, F the friction. The
    # contacts carry ∓C/(2·0.1) and F = μ·|C|/0.1 = μ·h·(P + F)/0.1, so
    #   F = μ·h·P/(0.1 − μ·h) = 7.07107/0.0929289 = 76.0911 N
    # (it was 0: μ times the net normal force). The crank then pushes B with P + F along x:
    # M = (P + F)·h = (1000 + 76.0911)·0.0707107 = 76.0911 N·m, contacts ±380.456 N,
    # loss F·|v_yoke| = 76.0911·0.5·√2 = 53.8046 W.
    mu, h, half = 0.1, 0.05 * math.sqrt(2), 0.1
    friction = mu * h * 1000 / (half - mu * h)
    result = forces_of(SINE_WITH_FRICTION)
    couple = (1000 + friction) * h
    assert _contact_sizes(result, "S") == pytest.approx([couple / (2 * half)] * 2)
    assert result.balancing_moment["1"] == pytest.approx((1000 + friction) * h)
    assert result.friction_loss == pytest.approx(friction * 0.5 * math.sqrt(2))
    assert result.power_residual < 1e-12


def test_slide_friction_over_a_sweep_is_the_contacts_at_each_pose():
    # the vectorised sweep against the single poses' reported contacts: at every pose the loss
    # is μ(|N1| + |N2|)·|v| with the yoke's speed |v| = 0.1·10·|sin φ|
    plan = make_plan(analyze(parse_edgelist(SINE_WITH_FRICTION.strip().splitlines())))
    inputs = np.array([[0.3], [1.0], [2.0], [-0.7]])
    sweep = forces_over(plan, solve_poses(plan, inputs))
    for (turned,), loss in zip(inputs, sweep.friction_loss, strict=True):
        single = solve_forces(plan, (float(turned),))
        speed = 0.1 * 10 * abs(math.sin(math.radians(45) + turned))
        assert loss == pytest.approx(0.1 * sum(_contact_sizes(single, "S")) * speed, rel=1e-9)
        assert single.friction_loss == pytest.approx(loss, rel=1e-12)


def test_friction_of_a_bearing_inside_a_compound_hinge():
    # two cranks on one ground pin A: link 2 turns on link 1's pin (the pair 1–2 written with
    # circle=ρ), link 1 is held (ω1 = 0) and link 2 turns at 10 rad/s against 100 N at 0.1 m.
    # The solver joins both to the ground at A, so the pair 1–2 has no reaction of its own;
    # its bearing carries what the pin puts on link 2: |R| = 100 N. The friction moment
    # ρ·100 = 1 N·m brakes 2 (M2 = 10 + 1 = 11) and drags 1 (M1 = −1); loss 1·10 = 10 W.
    text = """
driver 1 omega=0
driver 2 omega=10
0 1 R A
1 2 R A circle=0.01
point A 0 0
point B 0.1 0 on=2
force 2 B 0 -100
"""
    result = forces_of(text)
    assert result.balancing_moment["2"] == pytest.approx(11.0)
    assert result.balancing_moment["1"] == pytest.approx(-1.0)
    assert result.friction_loss == pytest.approx(10.0)


def test_exact_reactions_refuse_friction():
    plan = make_plan(analyze(parse_edgelist(SINE_WITH_FRICTION.strip().splitlines())))
    with pytest.raises(MechanismError, match=r"3–0 P S.*drop --exact"):
        forces_exact(plan)


def test_friction_in_a_crank_slider_is_found_by_iteration():
    text = """
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0 friction=0.2
point A 0 0
point B 0.05 0.08660254037844387
point C 0.3438 0
force 3 C -500 0
"""
    smooth = forces_of(text.replace(" friction=0.2", ""))
    rough = forces_of(text)
    # the slider moves toward −x here, so the 500 N load helps; friction opposes the motion
    # and the drive must supply its loss: M_b·ω1 grows by exactly the dissipated power
    gain = (rough.balancing_moment["1"] - smooth.balancing_moment["1"]) * 10.0
    assert rough.friction_loss > 0
    assert gain == pytest.approx(rough.friction_loss, rel=1e-9)


def test_compound_pin_forces_balance_and_carry_the_load():
    # three links on one pin B: crank 1 drives two dyads through it (links 2 and 4);
    # the pin is massless, so the forces it exerts on 1, 2 and 4 add up to zero
    text = """
driver 1 omega=1
0 1 R A
1 2 R B
1 4 R B
2 3 R C
3 0 R D
4 5 R E
5 0 R F
point A 0 0
point B 0.1 0.1
point C 0.3 0.25
point D 0.4 0
point E 0.05 0.35
point F -0.2 0.1
force 3 C 100 0
force 5 E 0 -100
"""
    result = forces_of(text)
    forces = result.pin_forces["B"]
    assert set(forces) == {"1", "2", "4"}
    np.testing.assert_allclose(sum(forces.values()), [0.0, 0.0], atol=1e-9)
    # the pin pushes on the crank with the sum of what the two couplers push on the pin
    on_1 = forces["1"]
    assert np.hypot(*on_1) > 0
    assert result.power_residual < 1e-9


def test_solution_records_its_inputs_and_is_solved_there():
    # SQUARE turned 0.4 rad: by virtual power at that pose, M_b·ω1 + P3·v_E = 0, with v_E
    # from the kinematics alone (no force solve)
    plan = make_plan(analyze(parse_edgelist(SQUARE.strip().splitlines())))
    assert solve_forces(plan).inputs == (0.0,)
    result = solve_forces(plan, (0.4,))
    assert result.inputs == (0.4,)
    state = solve_pose(plan, (0.4,))
    m_b = -float(np.array([1000.0, 0.0]) @ state.points["E"].velocity) / 10.0
    assert result.balancing_moment["1"] == pytest.approx(m_b, rel=1e-9)
    assert abs(m_b - 50.0) > 1.0  # not the sketch's answer


def test_sliding_driver_balancing_is_a_force_along_its_slide():
    # the pushed block: 30 N along the slide (not a moment), kept under balancing_moment too
    result = forces_of("driver 1 v=2\n0 1 P S angle=0 friction=0.3\npoint S 0 0\nforce 1 S 0 -100")
    assert result.balancing_slide_force == {"1": pytest.approx(30.0)}
    assert result.balancing_moment["1"] == result.balancing_slide_force["1"]
    assert forces_to_dict(result)["balancing_slide_force"] == {"1": pytest.approx(30.0)}
    assert forces_of(SQUARE).balancing_slide_force == {}


def test_two_contacts_of_a_turning_guide_are_across_it_at_the_pose():
    # block 2 on crank pin B slides in the slot of rocker 3 (through B and C), contacts 0.05 m
    # apart; a load on the block off its pin makes a couple in the slot. Away from the sketch
    # the slot has turned: both contact forces are across it there, and with the contacts
    # ∓0.025 m along it they add up to the reaction and give its couple.
    text = """
driver 1 omega=1
0 1 R A
1 2 R B
2 3 P B angle=90 span=0.05
3 0 R C
point A 0 0
point B 0 0.1
point C 0 -0.2
point K 0.02 0.1 on=2
force 2 K 30 50
"""
    plan = make_plan(analyze(parse_edgelist(text.strip().splitlines())))
    result = solve_forces(plan, (0.6,))
    (slot,) = [r for r in result.reactions if r.contacts is not None]
    state = solve_pose(plan, (0.6,))
    u = state.points["B"].position - np.array([0.0, -0.2])
    u = u / np.hypot(*u)
    n1, n2 = slot.contacts
    assert abs(float(n1 @ u)) < 1e-9 and abs(float(n2 @ u)) < 1e-9
    np.testing.assert_allclose(n1 + n2, slot.force, atol=1e-9)
    half = 0.025
    couple = half * float(u[0] * (n2 - n1)[1] - u[1] * (n2 - n1)[0])
    assert couple == pytest.approx(slot.couple, rel=1e-9, abs=1e-9)
    assert abs(slot.couple) > 0.1


def _with_loads(name: str) -> list[str]:
    """A fixture's lines with a mass and a force at a pin of every moving link, and gravity."""
    lines = (FIXTURES / name).read_text().splitlines()
    mechanism = parse_edgelist(lines)
    extra = ["gravity 0 -9.81"]
    for k, link in enumerate(sorted(mechanism.moving_links)):
        point = next(p.point for p in mechanism.pairs_of(link) if p.point)
        extra.append(f"mass {link} {1.0 + 0.1 * k} {0.01 * (k + 1)} {point}")
        extra.append(f"force {link} {point} {10.0 * k} {-50.0 - k}")
    return lines + extra


@pytest.mark.parametrize(
    "name",
    [
        "fourbar.edges",
        "crank_slider.edges",
        "jansen.edges",
        "ch2_2_7_slotted_link.edges",  # an RRP dyad whose guide turns
        "ch3_3_7_sieve.edges",
        "quick_return_shaper.edges",
        "watt_sixbar.edges",
    ],
)
def test_closed_form_reactions_agree_with_the_dense_solve(name, monkeypatch):
    # the dyads' and cranks' closed forms give the dense solve's reactions and balancing
    plan = make_plan(analyze(parse_edgelist(_with_loads(name))))
    inputs = np.linspace(-0.2, 0.3, 11)[:, None]
    motion = solve_poses(plan, inputs)
    closed = forces_over(plan, motion)
    assert closed.power_residual.max() < 1e-9
    monkeypatch.setattr("kinematics.kinetostatics.forces._closed_dyad", lambda *args: None)
    monkeypatch.setattr("kinematics.kinetostatics.forces._crank_balance", lambda *args: None)
    dense = forces_over(plan, motion)
    assert closed.order == dense.order
    for ours, theirs in zip(closed.reactions, dense.reactions, strict=True):
        assert ours[:3] == theirs[:3]
        scale = 1.0 + float(np.max(np.abs(theirs[3])))
        np.testing.assert_allclose(ours[3], theirs[3], rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose(ours[4], theirs[4], rtol=0, atol=1e-12 * scale)
    for link, moment in dense.balancing_moment.items():
        scale = 1.0 + float(np.max(np.abs(moment)))
        np.testing.assert_allclose(closed.balancing_moment[link], moment, atol=1e-12 * scale)
