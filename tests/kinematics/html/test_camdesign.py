"""The report's cam section: the figure, the checks tied to assur cam --json, the worked steps."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from kinematics.cams.design import make_design
from kinematics.cams.summary import cam_report, cam_report_to_dict
from kinematics.html.contents import gather
from kinematics.html.page import report_page
from structure import read_edgelist

from .conftest import FIXTURES

EDGES = FIXTURES.parent / "examples" / "cams" / "offset_roller.edges"


def test_the_cam_section() -> None:
    """(The Vietnamese words are the worked solution's: tests/kinematics/explain/test_cam.py.)"""
    mechanism = read_edgelist(EDGES)
    page = report_page(gather(mechanism, 12), "vi")
    root = ET.fromstring(page.split("\n", 1)[1])
    (part,) = [e for e in root.iter() if e.get("id") == "cams"]
    assert [e for e in part.iter() if e.get("id") == "fig-cam-0"], "no SVAJ figure"
    tied = {e.get("data-path"): float(e.get("data-value")) for e in part.iter()
            if e.get("data-source") == "assur cam --json"}  # fmt: skip
    data = cam_report_to_dict(cam_report(make_design(mechanism.cams[0].spec), 360))
    for path, value in tied.items():
        here = data
        for key in path.split("/"):
            here = here[key]
        assert here == pytest.approx(value, rel=1e-12), path
    assert "pressure_angle/max_deg" in tied and "jump_speed" in tied
    assert [e for e in part.iter() if e.tag.endswith("math")], "no MathML in the worked solution"
    # the cycle's animation turns the cam's profile (issue 22, item 16) and the roller's circle
    (svg,) = [e for e in root.iter() if e.get("id") == "cycle-svg"]
    bodies = {e.get("data-name"): e.get("points").split() for e in svg.iter()
              if e.get("class") == "link" and e.get("points")}  # fmt: skip
    assert len(bodies["1"]) == 120


def test_a_mechanism_without_a_designed_cam_says_so() -> None:
    page = report_page(gather(read_edgelist(FIXTURES / "cam_roller_follower.edges"), 8))
    root = ET.fromstring(page.split("\n", 1)[1])
    (part,) = [e for e in root.iter() if e.get("id") == "cams"]
    assert {e.get("data-note") for e in part.iter() if e.get("class") == "note"} == {"no_cams"}
