"""A designed cam run through its whole cycle as a mechanism.

The follower's motion that the sweep computes (positions from the program, velocities and
accelerations from the higher-pair replacement rebuilt at each pose from the profile's
curvature) must equal the law: s(θ), v = s'·ω, a = s''·ω², to 1e-9 of the lift. The contact
force the kinetostatics finds (the follower's equilibrium, group by group) must equal the
force closure's, found apart (F_c/cos φ, or the moment over the normal's arm), and the
balancing moment the camshaft torque F_c·s' (power).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from kinematics import make_plan, solve_pose, solve_poses, sweep
from kinematics.cams.closure import force_closure
from kinematics.cams.design import make_design
from kinematics.cams.mechanism import cam_mechanism
from kinematics.cams.program import time_values
from kinematics.errors import CamGeometryError, UndercutError
from kinematics.kinetostatics.forces import forces_over, solve_forces
from structure import analyze, mechanism_from_json, mechanism_to_json, parse_edgelist
from structure.cams import cam_spec_from_dict, cam_spec_to_dict
from structure.errors import EdgeListError, MechanismError

LINEAR = [
    {"law": "cycloidal", "lift": 0.02, "angle": 120},
    {"law": "dwell", "angle": 60},
    {"law": "modified-sine", "lift": -0.02, "angle": 120},
    {"law": "dwell", "angle": 60},
]
SWING = [
    {"law": "cycloidal", "lift": 15, "angle": 120},
    {"law": "dwell", "angle": 60},
    {"law": "4-5-6-7", "lift": -15, "angle": 120},
    {"law": "dwell", "angle": 60},
]
FOLLOWERS = [
    {"motion": "translating", "contact": "roller", "offset": 0.005, "roller_radius": 0.01},
    {"motion": "translating", "contact": "knife", "offset": -0.003},
    {"motion": "translating", "contact": "flat", "offset": 0.002},
    {"motion": "oscillating", "contact": "roller", "pivot": [0.09, 0.03], "arm": 0.075,
     "roller_radius": 0.01},
    {"motion": "oscillating", "contact": "knife", "pivot": [-0.02, 0.1], "arm": 0.08},
    {"motion": "oscillating", "contact": "flat", "pivot": [0.1, 0.02], "face_offset": 0.005},
]  # fmt: skip


def _spec(follower: dict, omega: float = 10.0, **more):
    swinging = follower["motion"] == "oscillating"
    data = {
        "omega": omega,
        "follower": follower,
        "base_radius": 0.04,
        "segments": SWING if swinging else LINEAR,
        "follower_inertia" if swinging else "follower_mass": 0.4,
        "load": 20.0,
        **more,
    }
    return cam_spec_from_dict(data)


@pytest.mark.parametrize("omega", [10.0, -7.0])
@pytest.mark.parametrize("at", [0.0, 137.0])
@pytest.mark.parametrize("follower", FOLLOWERS)
def test_the_swept_follower_moves_as_the_law(follower: dict, at: float, omega: float) -> None:
    design = make_design(_spec(follower, omega))
    plan = make_plan(analyze(cam_mechanism(design, at_deg=at)))
    result = sweep(plan, steps=180)
    turned = result.inputs[:, 0]
    theta = math.radians(at) + math.copysign(1.0, omega) * turned
    s, v, a, _ = time_values(design.program, theta, omega)
    s0 = time_values(design.program, np.array([math.radians(at)]), omega)[0][0]
    lift = design.program.scale
    if follower["motion"] == "oscillating":
        link, swing = result.links["2"], design.layout.swing
        got = (swing * link["angle"], swing * link["omega"], swing * link["epsilon"])
    else:
        name = "A" if follower["contact"] == "roller" else "F"
        point = result.points[name]
        y0 = plan.mechanism.points[name].y
        got = (point["position"][:, 1] - y0, point["velocity"][:, 1],
               point["acceleration"][:, 1])  # fmt: skip
        np.testing.assert_array_equal(point["velocity"][:, 0], 0.0)
    omega_size = abs(omega)
    np.testing.assert_allclose(got[0], s - s0, rtol=0, atol=1e-9 * lift)
    np.testing.assert_allclose(got[1], v, rtol=0, atol=1e-9 * lift * omega_size)
    np.testing.assert_allclose(got[2], a, rtol=0, atol=1e-9 * lift * omega_size**2)


def test_an_accelerating_cam_adds_s_prime_times_epsilon() -> None:
    """With the driver's ε: a = s''·ω² + s'·ε (the replacement's Coriolis-free part)."""
    design = make_design(_spec(FOLLOWERS[0]))
    m = cam_mechanism(design)
    data = json.loads(mechanism_to_json(m))
    data["drivers"] = [{"link": "1", "omega": 10.0, "epsilon": 30.0}]
    plan = make_plan(analyze(mechanism_from_json(json.dumps(data))))
    motion = solve_poses(plan, np.radians([[30.0], [200.0], [250.0]]))
    _, s1, s2, _ = time_values(design.program, np.radians([30.0, 200.0, 250.0]), 1.0)
    a = motion.qdd["2"][:, 1]
    np.testing.assert_allclose(a, s2 * 100.0 + s1 * 30.0, rtol=0, atol=1e-12)


@pytest.mark.parametrize("follower", FOLLOWERS)
def test_contact_force_and_balancing_moment_are_the_force_closure(follower: dict) -> None:
    design = make_design(_spec(follower))
    plan = make_plan(analyze(cam_mechanism(design)))
    inputs = np.radians(np.arange(0.0, 360.0, 2.0))[:, None]
    forces = forces_over(plan, solve_poses(plan, inputs))
    closure = force_closure(design, 180)
    contact = next(r for r in forces.reactions if r[2] == "H")
    assert contact[1] == ("1", "2")
    np.testing.assert_allclose(np.hypot(*contact[3].T), np.abs(closure.contact), atol=1e-9)
    np.testing.assert_allclose(forces.balancing_moment["1"], closure.torque, atol=1e-12)
    assert np.max(forces.power_residual) < 1e-12
    # the contact force acts along the common normal, out of the cam
    single = solve_forces(plan)
    h = next(r for r in single.reactions if r.kind == "H")
    assert h.force == pytest.approx(contact[3][0], abs=1e-12)


def test_the_edge_list_refers_to_a_program_file(tmp_path) -> None:
    design = make_design(_spec(FOLLOWERS[0]))
    (tmp_path / "disc.json").write_text(json.dumps(cam_spec_to_dict(design.spec)))
    m = cam_mechanism(design, program="disc.json")
    from structure import write_edgelist

    text = write_edgelist(m)
    assert "cam 1 3 disc.json" in text
    path = tmp_path / "cam.edges"
    path.write_text(text)
    from structure import read_edgelist

    again = read_edgelist(path)
    assert again.cams[0].spec == design.spec and again.cams[0].path == "disc.json"
    plan = make_plan(analyze(again))
    assert solve_pose(plan, (1.0,)).points["A"].velocity[1] == pytest.approx(
        time_values(design.program, np.array([1.0]), 10.0)[1][0], abs=1e-15
    )


def test_an_inline_program_cannot_go_to_an_edge_list() -> None:
    from structure import write_edgelist

    m = cam_mechanism(make_design(_spec(FOLLOWERS[0])))
    with pytest.raises(EdgeListError, match="held inline"):
        write_edgelist(m)


def _roller_text(y_axis: float = 0.049749371855331, at: str = "") -> list[str]:
    return [
        "driver 1 omega=10",
        "0 1 R O",
        "0 2 P F angle=90",
        "2 3 R A",
        "1 3 H K roller=3 centers=C,A",
        f"cam 1 3 disc.json{at}",
        "point O 0 0",
        "point F 0.005 0.08",
        f"point A 0.005 {y_axis}",
        "point K 0.004 0.0397994974842648",
        "point C 0 0",
    ]


def test_a_sketch_that_disagrees_with_the_program_is_named(tmp_path) -> None:
    design = make_design(_spec(FOLLOWERS[0]))
    (tmp_path / "disc.json").write_text(json.dumps(cam_spec_to_dict(design.spec)))
    good = parse_edgelist(_roller_text(), source=str(tmp_path / "m.edges"))
    make_plan(analyze(good))
    bad = parse_edgelist(_roller_text(0.051), source=str(tmp_path / "m.edges"))
    with pytest.raises(CamGeometryError, match=r"point A \(the roller's axis\) is at"):
        make_plan(analyze(bad))
    shifted = parse_edgelist(_roller_text(at=" at=30"), source=str(tmp_path / "m.edges"))
    with pytest.raises(CamGeometryError, match="disagrees with the program at 30°"):
        make_plan(analyze(shifted))


def test_the_cam_statement_is_checked_against_the_pair(tmp_path) -> None:
    design = make_design(_spec(FOLLOWERS[0]))
    (tmp_path / "disc.json").write_text(json.dumps(cam_spec_to_dict(design.spec)))
    source = str(tmp_path / "m.edges")
    lines = _roller_text()
    with pytest.raises(EdgeListError, match="needs roller=3"):
        parse_edgelist([*lines[:4], "1 3 H K centers=C,A", *lines[5:]], source=source)
    with pytest.raises(EdgeListError, match="cam 1 must turn about a pivot on the ground"):
        parse_edgelist([lines[0], "0 1 P O angle=0", *lines[2:]], source=source)
    with pytest.raises(EdgeListError, match=r"cam program nosuch.json: .*cannot read"):
        parse_edgelist([*lines[:5], "cam 1 3 nosuch.json"], source=source)
    with pytest.raises(EdgeListError, match=r"expected 'cam CAM LINK FILE \[at=DEG\]'"):
        parse_edgelist([*lines[:5], "cam 1 3"], source=source)
    (tmp_path / "bad.json").write_text('{"base_radius": 0.04, "segments": []}')
    with pytest.raises(EdgeListError, match=r"cam program bad.json: .*segments: must be"):
        parse_edgelist([*lines[:5], "cam 1 3 bad.json"], source=source)


def test_an_undercut_cam_is_refused_with_the_radius_to_use() -> None:
    spec = cam_spec_from_dict(
        {"omega": 10, "base_radius": 0.012, "follower": {"motion": "translating",
         "contact": "roller", "roller_radius": 0.015},
         "segments": [{"law": "cycloidal", "lift": 0.03, "angle": 50},
                      {"law": "dwell", "angle": 10},
                      {"law": "cycloidal", "lift": -0.03, "angle": 50},
                      {"law": "dwell", "angle": 250}]}
    )  # fmt: skip
    m = cam_mechanism(make_design(spec))
    with pytest.raises(UndercutError, match=r"too large for the pitch curve.*use a roller smaller"):
        make_plan(analyze(m))


def test_cams_without_a_profile_work_as_before(fixtures_dir) -> None:
    """The fixtures' cams hold at the sketch and refuse to sweep, with the message naming the
    cam statement that would give them a profile."""
    from structure import read_edgelist

    for name in ("cam_roller_follower.edges", "cam_flat_follower.edges"):
        plan = make_plan(analyze(read_edgelist(fixtures_dir / name)))
        assert plan.cams == () and plan.higher_pairs
        solve_pose(plan)
        with pytest.raises(MechanismError, match="'cam CAM LINK FILE' statement"):
            sweep(plan, steps=4)


def test_the_json_form_holds_the_program_inline() -> None:
    m = cam_mechanism(make_design(_spec(FOLLOWERS[3])))
    again = mechanism_from_json(mechanism_to_json(m))
    assert again.cams == m.cams and again.pairs == m.pairs
    data = json.loads(mechanism_to_json(m))
    assert data["cams"][0]["links"] == ["1", "3"]
    assert data["cams"][0]["spec"]["follower"]["motion"] == "oscillating"


def test_the_translating_follower_is_in_equilibrium() -> None:
    """Contact force + guide force + load − m·a = 0 on the follower, the guide's force normal
    to it, and the guide's couple balancing that force's moment about the roller's centre."""
    design = make_design(_spec(FOLLOWERS[0]))
    plan = make_plan(analyze(cam_mechanism(design)))
    inputs = np.radians(np.arange(0.0, 360.0, 5.0))[:, None]
    motion = solve_poses(plan, inputs)
    forces = forces_over(plan, motion)
    push = next(r for r in forces.reactions if r[2] == "H")[3]
    point, links, _, guide, couple = next(r for r in forces.reactions if r[2] == "P")
    assert (point, links) == ("F", ("0", "2"))
    x, _, a = motion.point("2", np.array([0.005, 0.049749371855331]))
    applied = np.array([0.0, -20.0]) - 0.4 * a
    np.testing.assert_allclose(push + guide + applied, 0.0, atol=1e-12)
    np.testing.assert_allclose(guide[:, 1], 0.0, atol=1e-12)
    s, _, _ = motion.point("2", np.array(plan.mechanism.coordinates("F")))
    arm = s - x
    np.testing.assert_allclose(couple, -(arm[:, 0] * guide[:, 1] - arm[:, 1] * guide[:, 0]),
                               atol=1e-12)  # fmt: skip


def test_exact_values_refuse_a_designed_cam_by_name() -> None:
    from kinematics.solvers.exact import forces_exact, solve_exact

    plan = make_plan(analyze(cam_mechanism(make_design(_spec(FOLLOWERS[0])))))
    for solve in (solve_exact, forces_exact):
        with pytest.raises(MechanismError, match="no exact form here"):
            solve(plan)


def test_the_follower_drives_the_rest_of_the_mechanism() -> None:
    """A rocker hung on the follower (a dyad II(4,5) after the cam's): its links keep their
    lengths over the cycle, and its point's velocity is the derivative of its path (central
    differences over the sweep: an independent check of the rates passed on)."""
    from structure import Mechanism
    from structure.model import make_pair, make_point

    design = make_design(_spec(FOLLOWERS[0]))
    m = cam_mechanism(design)
    extra = [make_pair(5, "R", "2", "4", "G"), make_pair(6, "R", "4", "5", "H"),
             make_pair(7, "R", "5", "0", "I")]  # fmt: skip
    points = dict(m.points)
    for name, xy in (("G", (0.005, 0.09)), ("H", (0.06, 0.11)), ("I", (0.09, 0.05))):
        points[name] = make_point(name, *xy)
    bigger = Mechanism(m.pairs + tuple(extra), m.ground, m.drivers, points, m.name, m.source,
                       m.loads, m.cams)  # fmt: skip
    plan = make_plan(analyze(bigger))
    assert [s.label for s in plan.steps] == ["II(2,v1)", "II(4,5)"]
    result = sweep(plan, steps=720)
    g, h = result.points["G"]["position"], result.points["H"]["position"]
    np.testing.assert_allclose(np.hypot(*(h - g).T), math.hypot(0.055, 0.02), rtol=1e-12)
    i = np.array([0.09, 0.05])
    np.testing.assert_allclose(np.hypot(*(h - i).T), math.hypot(0.03, 0.06), rtol=1e-12)
    dt = 2 * math.pi / 720 / 10.0
    velocity = (np.roll(h, -1, axis=0) - np.roll(h, 1, axis=0)) / (2 * dt)
    np.testing.assert_allclose(velocity, result.points["H"]["velocity"], atol=2e-4)
