"""Positions, velocities and accelerations: closed forms and finite differences."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kinematics.solvers.equations import group_residual, group_system
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import AssemblyError, SingularPoseError, solve_pose, solve_poses
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze
from structure.rigidity.constraints import sketch_problems

from ..conftest import FIXTURES


def plan_of(text: str):
    return make_plan(analyze(parse_edgelist(text.strip().splitlines())))


# problem 2.4: ∠ABC = ∠BCD = 90°, 4·AB = BC = CD = 0.4 m, ω1 = 20 s⁻¹
FOURBAR_2_4 = """
driver 1 omega=20
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0 0.1
point C 0.4 0.1
point D 0.4 -0.3
"""


def test_fourbar_of_problem_2_4_by_the_vector_polygons():
    # v_B = ω1·AB = 2 m/s along −x; BC ⟂ CD makes v_C = v_B, so ω2 = 0 and ω3 = 2/0.4 = 5.
    # a_B = (0, −40); a_C = a_B + ε2 k×BC = ε3 k×DC − ω3²·DC gives ε3 = 0, ε2 = 75.
    state = solve_pose(plan_of(FOURBAR_2_4))
    assert state.links["2"].omega == pytest.approx(0.0, abs=1e-12)
    assert state.links["3"].omega == pytest.approx(5.0)
    assert state.links["2"].epsilon == pytest.approx(75.0)
    assert state.links["3"].epsilon == pytest.approx(0.0, abs=1e-9)
    np.testing.assert_allclose(state.points["C"].velocity, [-2.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(state.points["C"].acceleration, [0.0, -10.0], atol=1e-9)


def slider_closed_form(r: float, rod: float, e: float, phi: float, w: float) -> tuple:
    """Offset crank–slider: slider x, ẋ, ẍ for crank angle φ, constant ω."""
    s = r * math.sin(phi) - e
    root = math.sqrt(rod * rod - s * s)
    x = r * math.cos(phi) + root
    dx = -r * w * math.sin(phi) - s * r * w * math.cos(phi) / root
    # second derivative by differentiating dx once more (closed form)
    ds = r * w * math.cos(phi)
    dds = -r * w * w * math.sin(phi)
    droot = -s * ds / root
    ddx = -r * w * w * math.cos(phi) - ((ds * ds + s * dds) * root - s * ds * droot) / root**2
    return x, dx, ddx


@pytest.mark.parametrize("phi_deg", [20.0, 75.0, 160.0, 250.0])
def test_offset_crank_slider_against_its_closed_form(phi_deg):
    r, rod, e, w = 0.1, 0.35, 0.03, 15.0
    phi = math.radians(phi_deg)
    bx, by = r * math.cos(phi), r * math.sin(phi)
    x, dx, ddx = slider_closed_form(r, rod, e, phi, w)
    text = f"""
driver 1 omega={w}
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B {bx!r} {by!r}
point C {x!r} {e!r}
"""
    state = solve_pose(plan_of(text))
    c = state.points["C"]
    np.testing.assert_allclose(c.velocity, [dx, 0.0], atol=1e-10)
    np.testing.assert_allclose(c.acceleration, [ddx, 0.0], atol=1e-8)
    assert state.links["3"].omega == 0.0 or abs(state.links["3"].omega) < 1e-12


def fixtures_with_sketch(moving: bool = True):
    """Fixtures with a complete sketch; ``moving``: only those that can leave their sketch.

    A higher pair's replacement holds at the sketch pose only, so cams and gears stay there.
    """
    out = []
    for path in sorted(FIXTURES.glob("*.edges")):
        m = read_edgelist(path)
        if m.points and not sketch_problems(m):
            if moving and any(p.kind.value == "H" for p in m.pairs):
                continue
            out.append(path.name)
    return out


@pytest.mark.parametrize("name", fixtures_with_sketch())
def test_velocities_and_accelerations_match_finite_differences(name):
    plan = make_plan(analyze(read_edgelist(FIXTURES / name)))
    speeds = [d.speed if d.speed_given else 1.0 for d in plan.drivers]
    accels = [d.acceleration for d in plan.drivers]
    drivers = [
        d.__class__(d.link, d.kind, d.pivot, d.direction, s, a, True)
        for d, s, a in zip(plan.drivers, speeds, accels, strict=True)
    ]
    plan = plan.__class__(plan.mechanism, tuple(drivers), plan.steps, plan.points, plan.length)
    base = solve_pose(plan)
    h = 1e-4 / max(1.0, max(abs(s) for s in speeds))

    def at(t: float):
        inputs = tuple(s * t + 0.5 * a * t * t for s, a in zip(speeds, accels, strict=True))
        return solve_pose(plan, inputs, {k: v.q for k, v in base.links.items()})

    ahead, behind = at(h), at(-h)
    for link, st in base.links.items():
        dq = (ahead.links[link].q - behind.links[link].q) / (2 * h)
        ddq = (ahead.links[link].q - 2 * st.q + behind.links[link].q) / h**2
        scale = 1.0 + float(np.abs(st.qdd).max())
        np.testing.assert_allclose(st.qd, dq, atol=1e-6 * (1 + float(np.abs(st.qd).max())))
        np.testing.assert_allclose(st.qdd, ddq, atol=2e-3 * scale)
    for point, ps in base.points.items():
        dp = (ahead.points[point].position - behind.points[point].position) / (2 * h)
        np.testing.assert_allclose(ps.velocity, dp, atol=1e-6 * (1 + float(np.abs(dp).max())))


def test_higher_pairs_are_solved_at_the_sketch_only():
    from structure.errors import MechanismError

    plan = make_plan(analyze(read_edgelist(FIXTURES / "cam_roller_follower.edges")))
    state = solve_pose(plan)
    assert state.links
    with pytest.raises(MechanismError, match="sketch pose only"):
        solve_pose(plan, (0.1,))


def _planetary(epsilon: float) -> str:
    """Sun 1 (z 20), planet 2 (z 20) on carrier C, fixed ring (z 60), module 0.02 m.

    Each mesh's centres of curvature are the feet of the perpendiculars from
    the gear centres onto the line of action (20° from the common tangent).
    """
    d = (math.sin(math.radians(20)), math.cos(math.radians(20)))

    def foot(centre, pitch):
        t = (centre[0] - pitch[0]) * d[0] + (centre[1] - pitch[1]) * d[1]
        return f"{pitch[0] + t * d[0]:.15g} {pitch[1] + t * d[1]:.15g}"

    o, b, k1, k2 = (0.0, 0.0), (0.4, 0.0), (0.2, 0.0), (0.6, 0.0)
    return f"""
driver C omega=2 epsilon={epsilon}
0 C R O
0 1 R O
C 2 R B
1 2 H K1 gear z=20,20 centers=N1,N2
2 0 H K2 gear z=20,60 internal=0 centers=N3,N4
point O 0 0
point B 0.4 0
point K1 0.2 0
point K2 0.6 0
point N1 {foot(o, k1)}
point N2 {foot(b, k1)}
point N3 {foot(b, k2)}
point N4 {foot(o, k2)}
"""


def test_gear_meshes_roll_over_a_whole_cycle():
    # Willis with the ring fixed: (ω1 − ωC)/(0 − ωC) = −z3/z1 = −3, so ω1 = 4·ωC;
    # (ω2 − ωC)/(0 − ωC) = z3/z2 = 3 (internal), so ω2 = −2·ωC. Angles alike.
    plan = plan_of(_planetary(epsilon=0.5))
    phi = np.linspace(0.0, 2 * math.pi, 25)
    motion = solve_poses(plan, phi[:, None])
    np.testing.assert_allclose(motion.q["1"][:, 2], 4 * phi, atol=1e-9)
    np.testing.assert_allclose(motion.q["2"][:, 2], -2 * phi, atol=1e-9)
    np.testing.assert_allclose(motion.qd["1"][:, 2], 8.0, atol=1e-9)
    np.testing.assert_allclose(motion.qd["2"][:, 2], -4.0, atol=1e-9)
    np.testing.assert_allclose(motion.qdd["1"][:, 2], 2.0, atol=1e-9)
    np.testing.assert_allclose(motion.qdd["2"][:, 2], -1.0, atol=1e-9)
    x, v, a = motion.point("C", np.array([0.4, 0.0]))  # the planet's centre B on the carrier
    r = 0.4 * np.column_stack([np.cos(phi), np.sin(phi)])
    jr = np.column_stack([-r[:, 1], r[:, 0]])
    np.testing.assert_allclose(x, r, atol=1e-12)
    np.testing.assert_allclose(v, 2.0 * jr, atol=1e-12)
    np.testing.assert_allclose(a, 0.5 * jr - 4.0 * r, atol=1e-12)
    assert "v1" not in motion.q  # the virtual links hold at the sketch only


def test_rolling_gears_agree_with_the_virtual_links_at_the_sketch():
    # At the sketch the replacement by virtual links (centres of curvature) is
    # exact to second order: velocities and accelerations as by rolling.
    plan = plan_of(_planetary(epsilon=0.5))
    by_links = solve_pose(plan)
    rolled = solve_poses(plan, np.array([[0.0], [1e-3]]))
    for link in ("1", "2", "C"):
        assert by_links.links[link].omega == pytest.approx(rolled.qd[link][0, 2], abs=1e-9)
        assert by_links.links[link].epsilon == pytest.approx(rolled.qdd[link][0, 2], abs=1e-9)


def test_a_pose_that_cannot_be_assembled_is_named():
    # crank 0.1, coupler √0.05 ≈ 0.224, rocker √0.02 ≈ 0.141 on a 0.4 base: turned by half a
    # turn the crank pin is 0.5 from D, beyond the reach 0.365 of the dyad
    text = """
driver 1 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0.1 0
point C 0.3 0.1
point D 0.4 0
"""
    plan = plan_of(text)
    with pytest.raises(AssemblyError, match=r"II\(2,3\).*cannot be assembled"):
        solve_pose(plan, (math.pi,))


def test_a_dead_centre_is_named():
    # BC = 0.3, CD = 0.2, D at 0.4: turned by half a turn the crank pin B is 0.5 from D,
    # so B, C, D are collinear (coupler and rocker stretched): the dyad's Jacobian loses rank
    cx = 1 / 3
    cy = math.sqrt(0.09 - (cx - 0.1) ** 2)
    text = f"""
driver 1 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0.1 0
point C {cx!r} {cy!r}
point D 0.4 0
"""
    plan = plan_of(text)
    solve_pose(plan, (math.pi - 0.01,))  # close to it the group still assembles
    with pytest.raises(SingularPoseError, match=r"II\(2,3\).*dead centre"):
        solve_pose(plan, (math.pi,))


@pytest.mark.parametrize("name", fixtures_with_sketch())
def test_closed_form_dyads_agree_with_newton(name, monkeypatch):
    import kinematics.solvers.solve as solve_module

    plan = make_plan(analyze(read_edgelist(FIXTURES / name)))
    inputs = np.array([[0.1] * len(plan.drivers), [-0.1] * len(plan.drivers)])
    try:
        closed = solve_module.solve_poses(plan, inputs)
    except AssemblyError:
        pytest.skip("this linkage does not reach ±0.1 rad from its sketch")
    monkeypatch.setattr("kinematics.solvers.dyads.place_dyad", lambda *args: False)
    monkeypatch.setattr("kinematics.solvers.dyads.frame_dyad", lambda *args: False)
    newton = solve_module.solve_poses(plan, inputs)
    for link in closed.q:
        np.testing.assert_allclose(closed.q[link], newton.q[link], atol=1e-10)
        np.testing.assert_allclose(closed.qd[link], newton.qd[link], atol=1e-8)
        np.testing.assert_allclose(closed.qdd[link], newton.qdd[link], atol=1e-6)


@pytest.mark.parametrize("name", ["fourbar.edges", "jansen.edges", "crank_slider.edges"])
def test_frames_over_a_whole_turn_agree_with_newton_and_the_jacobian(name, monkeypatch):
    # The closed-form dyads keep each link as a frame (pins, lazy angle); the
    # general path solves the same groups by Newton and J·q̇ = −J_k·q̇_k.
    import kinematics.solvers.solve as solve_module

    plan = make_plan(analyze(read_edgelist(FIXTURES / name)))
    inputs = np.linspace(0.0, 2 * math.pi, 73)[:, None]
    closed = solve_module.solve_poses(plan, inputs)
    drivers = {d.link for d in plan.drivers}
    assert set(closed.frames) > drivers  # the dyads were solved in closed form
    monkeypatch.setattr("kinematics.solvers.dyads.frame_dyad", lambda *args: False)
    newton = solve_module.solve_poses(plan, inputs)
    assert set(newton.frames) <= drivers
    for link in newton.q:
        np.testing.assert_allclose(closed.q[link], newton.q[link], atol=1e-10)
        np.testing.assert_allclose(closed.qd[link], newton.qd[link], atol=1e-8)
        np.testing.assert_allclose(closed.qdd[link], newton.qdd[link], atol=1e-6)
    for point, (link, c) in plan.points.items():
        for got, want in zip(closed.point(link, c), newton.point(link, c), strict=True):
            np.testing.assert_allclose(got, want, atol=1e-8, err_msg=point)


def test_flipping_a_dyad_assembles_its_mirror_image():
    plan = make_plan(analyze(parse_edgelist(FOURBAR_2_4.strip().splitlines())), flip=["II(2,3)"])
    c = solve_pose(plan).points["C"].position
    # mirror of C = (0.4, 0.1) across the line B(0, 0.1)–D(0.4, −0.3)
    b, d, c0 = np.array([0.0, 0.1]), np.array([0.4, -0.3]), np.array([0.4, 0.1])
    u = (d - b) / np.linalg.norm(d - b)
    mirror = b + 2 * ((c0 - b) @ u) * u - (c0 - b)
    np.testing.assert_allclose(c, mirror, atol=1e-12)
    with pytest.raises(ValueError, match="cannot flip"):
        make_plan(analyze(parse_edgelist(FOURBAR_2_4.strip().splitlines())), flip=["II(9,9)"])


def test_far_input_is_reached_by_continuation_in_the_sketch_mode():
    # the triad is solved by Newton: one pose half a turn away must match the sweep's pose
    plan = make_plan(analyze(read_edgelist(FIXTURES / "eightbar_triad.edges")))
    direct = solve_pose(plan, (math.pi / 2,))
    swept = solve_poses(plan, np.linspace(0, math.pi / 2, 200)[:, None])
    for link, state in direct.links.items():
        np.testing.assert_allclose(state.q, swept.q[link][-1], atol=1e-10)


def test_batched_newton_follows_the_same_branch_as_pose_by_pose():
    plan = make_plan(analyze(read_edgelist(FIXTURES / "eightbar_triad.edges")))
    angles = np.linspace(0, 2 * math.pi, 400, endpoint=False)
    batched = solve_poses(plan, angles[:, None])
    previous = None
    for k in range(0, 400, 37):
        one = solve_poses(plan, angles[k : k + 1, None], previous)
        previous = {link: value[0] for link, value in one.q.items()}
        for link in batched.q:
            np.testing.assert_allclose(batched.q[link][k], one.q[link][0], atol=1e-9)


def test_stephenson_triad_retraces_the_same_chain_driven_as_two_dyads():
    # One Stephenson chain, two drivers: driven at link 4 it is two RRR dyads
    # (closed form); driven at link 1 it is a class III triad (Newton). Feeding
    # the triad the crank angles θ1(φ) the dyads give must bring back φ, and the
    # speed ratios must be the reciprocal ones. Link 1 is a rocker: where θ1
    # turns back the triad is at a dead centre, so only the stretch from the
    # sketch to just before the first turn is retraced.
    text = (FIXTURES / "stephenson_sixbar_dyads.edges").read_text()
    dyads = plan_of(text)
    phi = np.linspace(0.0, 2 * math.pi, 721)
    by_dyads = solve_poses(dyads, phi[:, None])
    w1 = by_dyads.qd["1"][:, 2]
    turn = int(np.argmax(np.sign(w1) != np.sign(w1[0])))
    assert turn > 20
    phi = phi[: turn - 5]
    by_dyads = solve_poses(dyads, phi[:, None])
    triad_text = text.replace("driver 4 omega=10", "driver 1 omega=1")
    triad = plan_of(triad_text)
    assert [s.group.assur_class for s in triad.steps] == [3]
    theta1 = by_dyads.q["1"][:, 2]
    by_triad = solve_poses(triad, theta1[:, None])
    w1 = by_dyads.qd["1"][:, 2]
    for link in ("2", "3", "4", "5"):
        np.testing.assert_allclose(by_triad.q[link], by_dyads.q[link], atol=1e-10)
        np.testing.assert_allclose(
            by_triad.qd[link][:, 2], by_dyads.qd[link][:, 2] / w1, rtol=1e-8, atol=1e-9
        )


@pytest.mark.parametrize("name", ["eightbar_triad.edges", "crank_slider.edges", "jansen.edges"])
def test_group_residual_is_group_systems_residual(name):
    plan = make_plan(analyze(read_edgelist(FIXTURES / name)))
    rng = np.random.default_rng(7)
    for step in plan.steps:
        links = {x for eq in step.equations for x in (eq.a, eq.b)} - {plan.mechanism.ground}
        q = {link: rng.normal(size=(4, 3)) for link in links}
        phi = group_system(step.links, step.equations, q, {}, 4)[0]
        np.testing.assert_array_equal(group_residual(step.equations, q, 4), phi)


def test_a_newton_triad_over_a_fine_turn_agrees_with_single_poses():
    # the batched Newton (quadratic predictor, kept Jacobian) lands where Newton on each pose does
    plan = make_plan(analyze(read_edgelist(FIXTURES / "eightbar_triad.edges")))
    phi = np.linspace(0.0, 2 * math.pi, 2001)
    motion = solve_poses(plan, phi[:, None])
    for k in (1, 137, 1000, 1999):
        one = solve_pose(plan, (float(phi[k]),), guess={x: motion.q[x][k] for x in motion.q})
        for link, state in one.links.items():
            np.testing.assert_allclose(state.q, motion.q[link][k], atol=1e-10)
            np.testing.assert_allclose(state.qd, motion.qd[link][k], atol=1e-8)
            np.testing.assert_allclose(state.qdd, motion.qdd[link][k], atol=1e-6)
