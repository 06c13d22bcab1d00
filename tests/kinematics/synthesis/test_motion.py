"""Motion generation: the design passes through the poses (1e-9), in order, on one branch."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from kinematics import make_plan, sweep
from kinematics.errors import SynthesisError
from kinematics.synthesis.motion import burmester_points, pole, synthesize_motion
from structure import analyze

POSES = [
    [[0, 0, 0], [1, 0.5, 30]],
    [[0, 0, 0], [1, 0.5, 30], [2, 0.6, 70]],
    [[0, 0, 0], [1, 0.5, 30], [2, 0.6, 70], [2.8, 0.2, 100]],
    [[0, 0, 0], [1, 0.5, 30], [2, 0.6, 70], [2.8, 0.2, 100], [3.2, -0.5, 120]],
]


def test_pole_of_a_quarter_turn_about_the_origin() -> None:
    p = pole(np.array([2.0, 0.0, 0.3]), np.array([0.0, 2.0, 0.3 + math.pi / 2]))
    np.testing.assert_allclose(p, [0.0, 0.0], atol=1e-12)


@pytest.mark.parametrize("poses", POSES, ids=["2", "3", "4", "5"])
def test_the_chosen_design_carries_the_body_through_the_poses(poses) -> None:
    design = synthesize_motion(np.array(poses, dtype=float))[0]
    assert design.defects.ok and design.checked
    # swept anew, in order through the crank's inputs, with steps between the poses
    m = design.mechanism
    inputs = np.radians(design.inputs_deg)
    rows = np.concatenate(
        [np.linspace(a, b, 20, endpoint=False) for a, b in itertools.pairwise(inputs)]
        + [inputs[-1:]]
    )
    result = sweep(make_plan(analyze(m)), rows, rates=False)
    at = np.arange(len(poses)) * 20
    p = result.points["P"]["position"][at]
    np.testing.assert_allclose(p, np.array(poses)[:, :2], atol=1e-9)
    # the coupler turns as the body does
    turned = np.degrees(result.links["2"]["angle"][at])
    wanted = np.array(poses)[:, 2] - poses[0][2]
    np.testing.assert_allclose(np.angle(np.exp(1j * np.radians(turned - wanted))), 0, atol=1e-9)


def test_burmester_points_lie_on_both_circle_point_curves() -> None:
    poses = np.array(POSES[3], dtype=float)
    poses[:, 2] = np.radians(poses[:, 2])
    found = burmester_points(poses, 1.0)
    assert 1 <= len(found) <= 4
    for m in found:
        if True:
            z = np.array(
                [
                    p[:2]
                    + np.array(
                        [[math.cos(p[2]), -math.sin(p[2])], [math.sin(p[2]), math.cos(p[2])]]
                    )
                    @ m
                    for p in poses
                ]
            )
        # all five positions on one circle: equal distances from their circumcentre
        a = 2 * np.array([z[1] - z[0], z[2] - z[0]])
        c = np.linalg.solve(a, [z[1] @ z[1] - z[0] @ z[0], z[2] @ z[2] - z[0] @ z[0]])
        r = np.linalg.norm(z - c, axis=1)
        np.testing.assert_allclose(r, r[0], rtol=1e-8)


@pytest.mark.parametrize(
    "poses, message",
    [
        ([[0, 0, 0]], "2 to 5"),
        ([[0, 0, 0]] * 2 + [[1, 1, 1]] * 4, "2 to 5"),
        ([[0, 0, 0], [0, 0, 0]], "coincide"),
    ],
)
def test_bad_poses_are_named(poses, message) -> None:
    with pytest.raises(SynthesisError, match=message):
        synthesize_motion(np.array(poses, dtype=float))
