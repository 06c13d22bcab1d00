"""Reduced moment of inertia over a sweep, against a closed form."""

from __future__ import annotations

import math

import numpy as np

from kinematics.kinetostatics.inertia import reduced_inertia_over
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_poses
from structure.readwrite.edgelist import parse_edgelist
from structure.report import analyze


def test_crank_slider_reduced_inertia_follows_the_slider_speed_ratio():
    # crank r = 0.1 (J1 = 0.01 about A), rod l = 0.3 without mass, slider m3 = 2 kg:
    # J_red(φ) = J1 + m3·(dx_C/dφ)², dx_C/dφ = −r·sinφ − r²·sinφ·cosφ/√(l² − r²·sin²φ)
    text = """
driver 1 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0.1 0
point C 0.4 0
mass 1 0 0.01 A
mass 3 2 0 C
"""
    plan = make_plan(analyze(parse_edgelist(text.strip().splitlines())))
    phi = np.linspace(0, 2 * math.pi, 73)
    j = reduced_inertia_over(plan, solve_poses(plan, phi[:, None]))
    r, rod = 0.1, 0.3
    dx = -r * np.sin(phi) - r * r * np.sin(phi) * np.cos(phi) / np.sqrt(
        rod * rod - (r * np.sin(phi)) ** 2
    )
    np.testing.assert_allclose(j, 0.01 + 2.0 * dx * dx, rtol=1e-10, atol=1e-12)
