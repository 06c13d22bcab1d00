"""The RRR class III triad through its base's angle, against independent derivations.

The general Newton on the group's twelve equations (the path the triad took
before, switched back on here by turning the closed form off), the pair
constraints themselves (each lead's length, the base's rigid triangle), and
finite differences of the positions along the inputs for the rates.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.solvers import triads
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import SingularPoseError, solve_pose, solve_poses
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES


def _plan(name: str):
    return make_plan(analyze(read_edgelist(FIXTURES / f"{name}.edges")))


def _by_newton(monkeypatch, plan, inputs, **kwargs):
    """The general Newton's solve of the same poses (the closed form turned off)."""
    with monkeypatch.context() as m:
        m.setattr(triads, "frame_triad", lambda *args, **kw: None)
        return solve_poses(plan, inputs, **kwargs)


def _points(plan, motion, names):
    """Position, velocity, acceleration (N, 2) of each named point."""
    return {name: motion.point(*plan.points[name]) for name in names}


def test_the_eight_bars_triad_is_read_as_base_and_leads():
    triad = triads.triad_of(_plan("eightbar_triad").steps[-1])
    assert triad.base == "5"
    assert {lead.link: lead.known for lead in triad.leads} == {"4": "2", "6": "0", "7": "3"}
    # lengths from the file's comments (measured on the sketch)
    lengths = {lead.link: lead.length for lead in triad.leads}
    np.testing.assert_allclose(
        [lengths["4"], lengths["6"], lengths["7"]], [0.296788228, 0.240416306, 0.342923264],
        atol=1e-9,
    )  # fmt: skip


def test_other_groups_are_not_rrr_triads():
    assert triads.triad_of(_plan("class4_group").steps[-1]) is None
    assert all(triads.triad_of(step) is None for step in _plan("jansen").steps)


@pytest.mark.parametrize("name", ["eightbar_triad", "stephenson_sixbar"])
def test_the_closed_form_lands_where_the_general_newton_does(monkeypatch, name):
    plan = _plan(name)
    inputs = np.linspace(0.0, 2 * math.pi, 1500, endpoint=False)[:, None]
    fast = solve_poses(plan, inputs)
    assert set(plan.steps[-1].links) <= set(fast.frames)  # solved in closed form
    slow = _by_newton(monkeypatch, plan, inputs)
    assert not set(plan.steps[-1].links) & set(slow.frames)
    for link in plan.steps[-1].links:
        for got, want in ((fast.q, slow.q), (fast.qd, slow.qd), (fast.qdd, slow.qdd)):
            scale = float(np.max(np.abs(want[link])))
            np.testing.assert_allclose(got[link], want[link], rtol=0, atol=1e-10 * scale)


def test_pins_keep_the_leads_lengths_and_the_bases_triangle():
    plan = _plan("eightbar_triad")
    triad = triads.triad_of(plan.steps[-1])
    motion = solve_poses(plan, np.linspace(0.0, 2 * math.pi, 3000, endpoint=False)[:, None])
    size = plan.length
    inner = []
    for lead in triad.leads:
        on_lead = motion.point(lead.link, lead.inner)[0]
        on_base = motion.point(triad.base, lead.inner)[0]
        outer = motion.point(lead.link, lead.outer)[0]
        on_known = (
            motion.point(lead.known, lead.outer)[0]
            if lead.known != plan.mechanism.ground
            else np.broadcast_to(lead.outer, outer.shape)
        )
        np.testing.assert_allclose(on_lead, on_base, rtol=0, atol=1e-12 * size)
        np.testing.assert_allclose(outer, on_known, rtol=0, atol=1e-12 * size)
        np.testing.assert_allclose(
            np.hypot(*(on_base - on_known).T), lead.length, rtol=1e-12, atol=0
        )
        inner.append(on_base)
    for i, j in ((0, 1), (1, 2), (0, 2)):
        sketch = float(np.hypot(*(triad.leads[j].inner - triad.leads[i].inner)))
        np.testing.assert_allclose(np.hypot(*(inner[j] - inner[i]).T), sketch, rtol=1e-12)


def test_rates_are_the_derivatives_of_the_positions():
    # the crank turns at ω = 10 rad/s, ε = 0: d/dt = 10·d/dφ; central differences, h = 1e-5
    plan = _plan("eightbar_triad")
    omega, h = plan.drivers[0].speed, 1e-5
    phi = np.linspace(0.0, 2 * math.pi, 97, endpoint=False)
    rows = np.column_stack([phi - h, phi, phi + h]).ravel()[:, None]
    motion = solve_poses(plan, np.vstack([np.zeros((1, 1)), rows]))
    names = ("T45", "T56", "T57")
    for x, v, a in _points(plan, motion, names).values():
        x, v, a = (value[1:].reshape(-1, 3, 2) for value in (x, v, a))
        fd_v = (x[:, 2] - x[:, 0]) / (2 * h) * omega
        fd_a = (v[:, 2] - v[:, 0]) / (2 * h) * omega
        np.testing.assert_allclose(v[:, 1], fd_v, rtol=0, atol=1e-7 * np.max(np.abs(fd_v)))
        np.testing.assert_allclose(a[:, 1], fd_a, rtol=0, atol=1e-7 * np.max(np.abs(fd_a)))
    for link in plan.steps[-1].links:
        theta = np.unwrap(motion.q[link][1:, 2].reshape(-1, 3), axis=1)
        w = motion.qd[link][1:, 2].reshape(-1, 3)
        np.testing.assert_allclose(
            w[:, 1], (theta[:, 2] - theta[:, 0]) / (2 * h) * omega, rtol=0, atol=1e-6
        )


def test_a_single_pose_and_a_guess_agree_with_the_sweep():
    plan = _plan("eightbar_triad")
    phi = np.linspace(0.0, 2 * math.pi, 801)
    motion = solve_poses(plan, phi[:, None])
    for k in (0, 333, 800):
        alone = solve_pose(plan, (float(phi[k]),))
        guessed = solve_pose(plan, (float(phi[k]),), guess={x: motion.q[x][k] for x in motion.q})
        for state in (alone, guessed):
            for link, s in state.links.items():
                np.testing.assert_allclose(s.q, motion.q[link][k], atol=1e-10)
                np.testing.assert_allclose(s.qd, motion.qd[link][k], atol=1e-8)


def test_inputs_that_jump_or_start_away_from_the_sketch_go_the_general_way():
    plan = _plan("eightbar_triad")
    assert triads.path_length(plan, np.array([[0.0], [0.2]])) is None
    assert triads.path_length(plan, np.array([[1.0], [1.01]])) is None
    np.testing.assert_allclose(
        triads.path_length(plan, np.array([[0.03], [0.0], [0.04]])), [0.03, 0.06, 0.10]
    )


def test_screening_every_pose_by_the_full_jacobian_changes_nothing(monkeypatch):
    plan = _plan("eightbar_triad")
    inputs = np.linspace(0.0, 2 * math.pi, 300, endpoint=False)[:, None]
    plain = solve_poses(plan, inputs)
    monkeypatch.setattr(triads, "SUSPECT", math.inf)
    screened = solve_poses(plan, inputs)
    for link in plain.q:
        np.testing.assert_array_equal(plain.qd[link], screened.qd[link])


def test_a_dead_centre_is_reported_as_the_general_newton_reports_it(monkeypatch):
    # the Stephenson chain driven at link 1 (a rocker when driven at link 4): θ1's largest
    # value over the dyads' turn is a dead centre of the triad; just past it, the triad cannot
    # be assembled. Both solves must say the same.
    text = (FIXTURES / "stephenson_sixbar_dyads.edges").read_text()
    dyads = make_plan(analyze(parse_edgelist(text.splitlines())))
    phi = np.linspace(0.0, 2 * math.pi, 20001)
    theta1 = solve_poses(dyads, phi[:, None]).q["1"][:, 2]
    top = float(np.max(theta1))
    lines = text.replace("driver 4 omega=10", "driver 1 omega=1").splitlines()
    triad = make_plan(analyze(parse_edgelist(lines)))
    path = np.linspace(0.0, top + 1e-3, 400)[:, None]
    errors = []
    for solve in (solve_poses, lambda *a: _by_newton(monkeypatch, *a)):
        with pytest.raises(Exception) as caught:
            solve(triad, path)
        errors.append((type(caught.value), str(caught.value)))
    assert errors[0] == errors[1]
    assert issubclass(errors[0][0], SingularPoseError) or "cannot be assembled" in errors[0][1]


# a triad sketched near a dead centre (found by a random search): its two assembly modes lie
# close together there, and a coarse step from the sketch once landed in the other one
NEAR_DEAD_CENTRE = """
driver 1 omega=10
0 1 R A
1 3 R B
3 2 R C
2 4 R D
4 0 R F
2 5 R E
5 0 R G
point A 0.361579328894 0.421676859047
point B 0.271452229441 0.357337678308
point C 0.00230028586295 -0.462384834363
point D -0.39755868862 0.0239233948746
point E 0.356008304611 -0.0673654392883
point F -0.496270637714 -0.287696893805
point G 0.25997041822 -0.34158201147
"""


def test_near_a_dead_centre_the_sketchs_mode_is_kept(monkeypatch):
    plan = make_plan(analyze(parse_edgelist(NEAR_DEAD_CENTRE.strip().splitlines())))
    inputs = np.linspace(0.0, 0.3, 400)[:, None]
    fast = solve_poses(plan, inputs)
    slow = _by_newton(monkeypatch, plan, inputs)
    for link in plan.steps[-1].links:
        np.testing.assert_allclose(fast.q[link], slow.q[link], rtol=0, atol=1e-10)
    # the sketch's own rates: θ3 leaves the sketch the way ω3 turns it (the other mode: back)
    omega3 = solve_pose(plan).links["3"].omega
    assert np.sign(fast.q["3"][1, 2]) == np.sign(omega3) != 0
