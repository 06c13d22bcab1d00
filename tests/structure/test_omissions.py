"""What a format leaves out, said in words (structure.readwrite.omissions), issue 22, item 11.

For every fixture pyslvs can hold, the warnings cover every difference between the
mechanism and what comes back from its Pyslvs-UI project.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from structure.errors import EdgeListError
from structure.readwrite.edgelist import read_edgelist
from structure.readwrite.formats import mechanism_left_out, mechanism_text, parse_mechanism
from structure.readwrite.pyslvs import pyslvs_left_out

from ..conftest import FIXTURES

FIXTURE_FILES = sorted(FIXTURES.glob("*.edges"))


def test_the_issues_example():
    m = parse_mechanism(
        "driver 1 omega=10\n0 1 R A\n1 2 R B\n2 3 R C\n3 0 R D\n"
        "point A 0 0\npoint B 0 1\npoint C 2 1\npoint D 2 0\n"
        "force 2 B 1 0\nforce 3 C 0 1\nmass 2 1 0.1 B\n",
        ".edges",
        "fourbar.edges",
    )
    lines = pyslvs_left_out(m)
    assert "pyslvs projects hold no loads: 2 force and 1 mass statements left out" in lines
    assert "pyslvs projects hold no driver motion: omega of driver 1 left out" in lines


def test_the_edge_list_and_json_leave_nothing_out():
    for path in FIXTURE_FILES:
        m = read_edgelist(path)
        assert mechanism_left_out(m, ".edges") == mechanism_left_out(m, ".json") == ()


@pytest.mark.parametrize("path", FIXTURE_FILES, ids=lambda p: p.stem)
def test_every_loss_of_a_pyslvs_project_is_named(path: Path):
    original = read_edgelist(path)
    try:
        text = mechanism_text(original, ".pyslvs")
    except EdgeListError:
        return  # a higher pair: pyslvs cannot hold it, and says so
    back = parse_mechanism(text, ".pyslvs", "back.pyslvs")
    said = " ".join(pyslvs_left_out(original))
    if original.name and original.name != back.name:
        assert "have no title" in said
    if original.loads:
        assert "hold no loads" in said
    if any(d.motion for d in original.drivers):
        assert "hold no driver motion" in said
    if len(back.drivers) < len(original.drivers):
        assert "drive by turning" in said
    for p in original.pairs_with_options():
        for key, value in (("span", p.span), ("friction", p.friction), ("circle", p.circle)):
            if value is not None:
                assert f"{key}= of pair" in said
    if any(e for point in original.points.values() for e in point.exact):
        assert "hold decimals only" in said
    if len(back.points) < len(original.points):
        assert "hold joints only" in said
    if set(original.links) != set(back.links) or set(original.points) != set(back.points):
        assert "name things their own way" in said
