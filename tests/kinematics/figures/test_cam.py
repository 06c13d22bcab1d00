"""The cam's figures: the SVAJ sheet, and a designed cam in the mechanism's scene."""

from __future__ import annotations

import math

import numpy as np

from kinematics import make_plan, solve_pose, solve_poses
from kinematics.cams.contact import sketch_profile
from kinematics.cams.design import make_design
from kinematics.cams.mechanism import cam_mechanism
from kinematics.figures import draw_mechanism
from kinematics.figures.cam import cam_sheet
from kinematics.figures.scene import draw_scene
from kinematics.figures.style import figure_axes
from structure import analyze
from structure.cams import cam_spec_from_dict

SPEC = cam_spec_from_dict(
    {"omega": 10.0, "base_radius": 0.04,
     "follower": {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
     "segments": [{"law": "harmonic", "lift": 0.02, "angle": 120}, {"law": "dwell", "angle": 60},
                  {"law": "cycloidal", "lift": -0.02, "angle": 120},
                  {"law": "dwell", "angle": 60}]}
)  # fmt: skip


def test_the_sheet_draws_svaj_and_marks_infinite_jerk() -> None:
    fig = cam_sheet(make_design(SPEC), 120)
    gids = {x.get_gid() for ax in fig.axes for x in [*ax.lines, *ax.patches] if x.get_gid()}
    assert {"svaj:s", "svaj:v", "svaj:a", "svaj:j", "profile", "pitch", "follower"} <= gids
    # harmonic beside dwells: the acceleration jumps at 0° and 120° (red lines on the jerk axes)
    jerk = fig.axes[3]
    red = [ln.get_xdata()[0] for ln in jerk.lines if ln.get_color() == "tab:red"]
    assert sorted(red) == [0.0, 120.0]


def test_the_scene_turns_the_profile_and_keeps_the_contact_on_it() -> None:
    design = make_design(SPEC)
    report = analyze(cam_mechanism(design))
    plan = make_plan(report)
    fig = draw_mechanism(report, plan, solve_pose(plan))
    patches = {p.get_gid(): p for p in fig.axes[0].patches if p.get_gid()}
    profile = patches["profile:4:1"]
    np.testing.assert_allclose(profile.get_xy()[:-1], sketch_profile(plan.cams[0]), atol=1e-15)
    _, ax = figure_axes(None)
    turned = math.radians(75.0)
    motion = solve_poses(plan, np.array([[turned]]))
    poses = {link: q[0] for link, q in motion.q.items()}
    draw_scene(report, plan, ax, poses)
    drawn = next(p for p in ax.patches if p.get_gid() == "profile:4:1").get_xy()[:-1]
    c, s = math.cos(turned), math.sin(turned)
    np.testing.assert_allclose(drawn, sketch_profile(plan.cams[0]) @ np.array([[c, s], [-s, c]]),
                               atol=1e-12)  # fmt: skip
    dot = next(ln for ln in ax.lines if ln.get_gid() == "contact:K")
    k = np.array([dot.get_xdata()[0], dot.get_ydata()[0]])
    # the contact lies on the turned profile (within its sampling) and R_f from the roller axis
    assert np.min(np.hypot(*(drawn - k).T)) < 2e-3
    axis = motion.point("2", np.array(plan.points["A"][1]))[0][0]
    assert np.hypot(*(axis - k)) == np.float64(0.01) or abs(np.hypot(*(axis - k)) - 0.01) < 1e-12
