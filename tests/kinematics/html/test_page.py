"""The report page without a browser: it parses, holds every section, says what does not apply.

Every fixture's report is read as XML (the page is well-formed XML as well as
HTML5); its numbers are checked against the command line's ``--json`` answers,
its embedded data against strict JSON, its references against the network.
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from matplotlib.figure import Figure

from kinematics.html import SECTIONS, gather, report_page
from kinematics.html.cycle import solve_cycle
from kinematics.html.markup import format_number
from kinematics.html.phrases import PHRASES
from kinematics.html.svg import figure_svg
from kinematics.solvers.plan import make_plan
from structure.meshes import meshes
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES, sampled
from .conftest import SECTION_IDS, SKETCHED, STEMS, STEPS, cli_json, json_at

#: the namespaces a page may name (they are identifiers, never fetched)
NAMESPACES = {
    "http://www.w3.org/2000/svg",
    "http://www.w3.org/1999/xlink",
    "http://www.w3.org/1998/Math/MathML",
}


def parse(page: str) -> ET.Element:
    """The page as XML: everything after the ``<!DOCTYPE html>`` line."""
    doctype, rest = page.split("\n", 1)
    assert doctype == "<!DOCTYPE html>"
    return ET.fromstring(rest)


def local(tag: str) -> str:
    """A tag without its namespace."""
    return tag.rsplit("}", 1)[-1]


def section(root: ET.Element, sid: str) -> ET.Element:
    (found,) = [e for e in root.iter() if local(e.tag) == "section" and e.get("id") == sid]
    return found


def notes_in(element: ET.Element) -> set[str]:
    return {e.get("data-note") for e in element.iter() if e.get("class") == "note"}


def mechanism(stem: str):
    return read_edgelist(str(FIXTURES / f"{stem}.edges"))


# ------------------------------------------------------------------ every fixture
@pytest.mark.parametrize("stem", sampled(STEMS))
def test_every_fixture_makes_a_whole_report(all_reports, stem):
    """Each fixture's page parses, has its sections in order, unique ids, no network."""
    page = all_reports.page(stem)
    root = parse(page)
    assert root.get("lang") == "en"
    sections = [e.get("id") for e in root.iter() if e.get("class") == "part"]
    assert sections == SECTION_IDS == [sid for sid, _, _ in SECTIONS]
    ids = [e.get("id") for e in root.iter() if e.get("id")]
    assert len(ids) == len(set(ids)), "an id is used twice"
    for tag in ("link", "img", "iframe", "object", "embed"):
        assert not [e for e in root.iter() if local(e.tag) == tag], f"a <{tag}> in the page"
    urls = set(re.findall(r"""https?://[^\s"'<>)]+""", page))
    assert urls <= NAMESPACES, f"addresses in the page: {urls - NAMESPACES}"
    assert not [e for e in root.iter() if e.get("src")], "an external source"
    links = {e.get("href") for e in root.iter() if e.get("href")}
    assert all(href.startswith("#") for href in links), f"a link out of the page: {links}"


@pytest.mark.parametrize("stem", sampled(STEMS))
def test_a_part_that_does_not_apply_says_so_in_one_line(all_reports, stem):
    """No coordinates, no loads, no gears: the section holds the note instead of vanishing."""
    root = parse(all_reports.page(stem))
    m = mechanism(stem)
    if not m.points:
        for sid in ("kinematics", "forces", "cycle"):
            assert notes_in(section(root, sid)) == {"no_geometry"}, sid
        assert "no_geometry" in notes_in(section(root, "mechanism"))
    elif not any(x.kind in ("force", "moment", "mass") for x in m.loads):
        assert notes_in(section(root, "forces")) == {"no_loads"}
    gears = section(root, "gears")
    if meshes(m):
        assert "no_gears" not in notes_in(gears)
        assert [e for e in gears.iter() if local(e.tag) == "math"], "no Willis relation"
    else:
        assert notes_in(gears) == {"no_gears"}
    for note in (e for e in root.iter() if e.get("class") == "note"):
        assert "\n" not in "".join(note.itertext()), "a note of more than one line"


@pytest.mark.parametrize("stem", sampled(STEMS))
def test_the_numbers_are_the_command_lines(all_reports, stem):
    """Every number tied to a JSON path holds that value and shows it to six digits."""
    root = parse(all_reports.page(stem))
    tied = [e for e in root.iter() if e.get("data-source")]
    assert tied, "no number tied to the JSON"
    for e in tied:
        data = cli_json(e.get("data-source"), stem)
        expected = json_at(data, e.get("data-path"))
        value = e.get("data-value")
        if isinstance(expected, float):
            assert float(value) == expected, e.get("data-path")
            if e.tag == "td":
                assert "".join(e.itertext()) == format_number(expected)
        elif value is not None:
            assert value == str(expected), e.get("data-path")
        if e.get("data-source") == "gears" and e.get("data-path").endswith("/exact"):
            assert "".join(e.itertext()) == expected


@pytest.mark.parametrize("stem", sampled(SKETCHED))
def test_the_cycle_data_is_strict_json(all_reports, stem):
    """The animation's data parses as strict JSON and has a pose for every frame."""
    root = parse(all_reports.page(stem))
    scripts = [e for e in root.iter() if e.get("id") == "cycle-data"]
    if not scripts:
        assert notes_in(section(root, "cycle")) == {"unsolved"}
        return
    (script,) = scripts

    def refuse(constant: str) -> None:
        raise ValueError(f"{constant} in the page's JSON")

    data = json.loads(script.text, parse_constant=refuse)
    count = data["count"]
    assert 0 <= data["sketch"] < count == len(data["readout"])
    assert all(len(link) == count for link in data["links"])
    assert all(len(pin) == 2 * count for pin in data["pins"])
    assert all(len(s) == 3 * count for s in data["sliders"])


# ------------------------------------------------------------------ particular pages
def test_the_sections_and_notes_in_vietnamese(reports):
    root = parse(reports.page("ch1_1_1a_valve_gear", "vi"))
    assert root.get("lang") == "vi"
    titles = ["".join(e.itertext()) for e in root.iter() if local(e.tag) == "h2"]
    for key in ("s_mechanism", "s_structure", "s_kinematics", "s_cycle", "s_worked"):
        assert PHRASES["vi"][key] in titles
    notes = ["".join(e.itertext()) for e in root.iter() if e.get("class") == "note"]
    assert PHRASES["vi"]["no_geometry"] in notes
    assert PHRASES["vi"]["no_gears"] in notes
    assert "Công thức cấu tạo" in "".join(root.itertext())


def test_a_mechanism_that_cannot_turn_shows_the_stretch_it_reaches():
    """The tangent mechanism closes only over part of the turn: both ends, and why it stops."""
    plan = make_plan(analyze(mechanism("ch2_2_3_tangent")))
    cycle = solve_cycle(plan, 24)
    assert not cycle.complete
    assert cycle.stop.startswith("group II(2,3) ")  # the error that stops it names the group
    inputs = cycle.sweep.inputs[:, 0]
    assert inputs[0] < 0 < inputs[-1]
    assert inputs[cycle.sketch] == 0.0
    assert np.all(np.diff(inputs) > 0)
    assert cycle.poses["2"].shape == (len(inputs), 3)


def test_a_whole_turn_loops():
    plan = make_plan(analyze(mechanism("fourbar")))
    cycle = solve_cycle(plan, 24)
    assert cycle.complete and cycle.sketch == 0 and cycle.stop == ""
    assert len(cycle.sweep.inputs) == 24


def test_a_cam_has_no_cycle_and_says_why(all_reports):
    root = parse(all_reports.page("cam_roller_follower"))
    cycle = section(root, "cycle")
    assert notes_in(cycle) == {"unsolved"}
    assert "hold at the sketch pose only" in "".join(cycle.itertext())


def test_the_structure_section_holds_w_the_groups_and_the_formula(all_reports):
    root = parse(all_reports.page("ch1_1_4a_oxygen_pump"))
    structure = section(root, "structure")
    text = "".join(structure.itertext())
    data = cli_json("classify", "ch1_1_4a_oxygen_pump")
    assert data["formula"] in text and data["textbook_formula"] in text
    for group in analyze(mechanism("ch1_1_4a_oxygen_pump")).groups:
        assert group.label in text
    maths = [e for e in structure.iter() if local(e.tag) == "math"]
    assert maths, "W with the numbers put in is a formula"
    assert "".join(maths[0].itertext()).endswith(f"={data['W']}")


def test_the_report_in_python_equals_the_command_line(reports):
    """``report_page(gather(...))`` is what ``assur report`` writes (same steps)."""
    page = report_page(gather(mechanism("crank_slider"), steps=STEPS), "en")
    assert page == reports.page("crank_slider")


def test_an_unknown_language_is_refused():
    with pytest.raises(ValueError, match="unknown language"):
        report_page(gather(mechanism("ch1_1_2a_mechanical_press")), "fr")


# ------------------------------------------------------------------ the inline SVG
def test_two_figures_never_share_an_id():
    figures = []
    for prefix in ("one", "two"):
        fig = Figure(figsize=(2, 1))
        ax = fig.add_subplot()
        ax.plot([0, 1], [1, 0], gid="line")
        ax.plot([0, 1], [0, 1], gid="line")  # matplotlib repeats a gid as is
        ax.fill_between([0, 1], [0, 1], hatch="//")  # a pattern referred to by url(#...)
        figures.append(figure_svg(fig, prefix, "a test figure"))
    ids = [i for svg in figures for i in re.findall(r'\bid="([^"]+)"', svg)]
    assert len(ids) == len(set(ids))
    for svg, prefix in zip(figures, ("one", "two"), strict=True):
        ET.fromstring(svg)  # well-formed XML, no prologue
        assert not svg.startswith("<?xml")
        for target in re.findall(r'(?:url\(#|href="#)([^)"]+)', svg):
            assert target.startswith(f"{prefix}-") and f'id="{target}"' in svg
