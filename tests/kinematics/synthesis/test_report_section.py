"""The report's synthesis section: the targets drawn and listed, or its one-line note."""

from __future__ import annotations

import numpy as np

from kinematics.html.contents import gather
from kinematics.html.synthesis import synthesis_html
from kinematics.synthesis.linkages import Linkage, design_mechanism, linkage_poses, target_records
from structure import read_edgelist

X = np.array([0, 0, 0, 4, 1, 4, 3, 2, 1, 0.3, 1.0])


def test_a_design_shows_its_targets_at_distance_zero() -> None:
    inputs = np.array([0.0, 90.0, 180.0])
    p = linkage_poses(Linkage.FOURBAR, X[None], (0.3 + np.radians(inputs))[None]).points["P"][0]
    m = design_mechanism(Linkage.FOURBAR, X, target_records(p, inputs))
    html = synthesis_html(gather(m, steps=12), "en")
    assert 'id="fig-targets"' in html and html.count("<tr>") == 4  # heading and three rows
    assert html.count("<td>0</td></tr>") == 3  # P reaches each target (round-off shown as 0)


def test_a_file_without_targets_says_so() -> None:
    html = synthesis_html(gather(read_edgelist("fixtures/fourbar.edges"), steps=12), "en")
    assert "no design targets" in html
