"""The report's dynamics section: the numbers of ``assur dynamics --json``, or a line saying why."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from kinematics.html import gather
from kinematics.html.dynamics import dynamics_html
from structure.readwrite.edgelist import parse_edgelist, read_edgelist

from ...conftest import FIXTURES
from .conftest import cli_json, json_at
from .test_page import local, notes_in


def _part(mechanism, lang: str = "en") -> ET.Element:
    """The section's body alone, parsed (the page's other sections are test_page's)."""
    return ET.fromstring(f"<section>{dynamics_html(gather(mechanism, steps=4), lang)}</section>")


def _section(stem: str, lang: str = "en") -> ET.Element:
    return _part(read_edgelist(str(FIXTURES / f"{stem}.edges")), lang)


def test_a_machine_with_masses_has_its_numbers_figures_and_solution():
    part = _section("press_flywheel")
    tied = [e for e in part.iter() if e.get("data-source") == "dynamics"]
    paths = {e.get("data-path") for e in tied}
    assert {"steady/delta", "flywheel/J_exact", "flywheel/J_approx", "shaking/force_max"} <= paths
    data = cli_json("dynamics", "press_flywheel")
    for e in tied:
        assert float(e.get("data-value")) == json_at(data, e.get("data-path"))
    assert any(local(e.tag) == "svg" and e.get("id") == "fig-dynamics" for e in part.iter())
    assert any(e.get("class") == "worked-solution" for e in part.iter())
    assert any(local(e.tag) == "math" for e in part.iter())


def test_in_vietnamese():
    part = _section("press_flywheel", "vi")
    text = "".join(part.itertext())
    assert "bánh đà" in text and "Wittenbauer" in text and "hệ số chuyển động không đều" in text


def test_no_mass_data_is_one_line():
    part = _section("fourbar")
    assert notes_in(part) == {"no_masses"}
    assert len([e for e in part.iter() if e.get("class") == "note"]) == 1


def test_a_mechanism_without_dynamics_says_why():
    """Two drivers and a mass: the section is the one-line error of ``assur dynamics``."""
    lines = (FIXTURES / "fivebar_two_drivers.edges").read_text(encoding="utf-8").splitlines()
    part = _part(parse_edgelist([*lines, "mass 1 1 0.01 A"]))
    assert notes_in(part) == {"unsolved"} and "W = 2" in "".join(part.itertext())
