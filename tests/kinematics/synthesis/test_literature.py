"""Standard four-bar path problems of the literature, rerun with a fixed seed (slow).

Problem data as the literature states them (see README, "Dimensional synthesis"):
five points on a vertical line with prescribed timing (Kunjur & Krishnamurty 1997,
Cabrera, Simon & Prado 2002), and ten points on an ellipse, x = 10 + 10·cos t,
y = 10 + 8·sin t, t = 0°, 40°, ..., 360° (Acharyya & Mandal 2009), here without
timing. Ours keeps the 30° transmission bound and the ground pivots free.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

from kinematics import make_plan, sweep
from kinematics.synthesis.path import PathProblem, synthesize_path
from structure import analyze

LINE = np.array([[20, 20], [20, 25], [20, 30], [20, 35], [20, 40]], dtype=float)
LINE_CRANK = np.degrees([math.pi / 6, math.pi / 4, math.pi / 3, 5 * math.pi / 12, math.pi / 2])
_T = np.radians(np.arange(0, 360, 40))
ELLIPSE = np.column_stack([10 + 10 * np.cos(_T), 10 + 8 * np.sin(_T)])


@pytest.mark.slow
@pytest.mark.parametrize(
    "problem, bound",
    [
        (PathProblem(LINE, LINE_CRANK, seed=0), 0.05),
        (PathProblem(ELLIPSE, None, seed=0, restarts=1, generations=150), 0.2),
    ],
    ids=["line-timed", "ellipse-untimed"],
)
def test_literature_problem(problem: PathProblem, bound: float) -> None:
    started = time.perf_counter()
    design = synthesize_path(problem)
    assert time.perf_counter() - started < 60
    assert design.error_max < bound
    plan = make_plan(analyze(design.mechanism))
    sweep(plan, np.linspace(0, 2 * math.pi, 1441), rates=False)  # the whole turn, one branch
