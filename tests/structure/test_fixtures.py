"""The fixture table: every mechanism of the source's chapter 1 and the classic linkages.

The expected answers in fixtures/*.toml were derived by hand (counts, the W
formula, groups with hinges as points); where they depart from the printed
answer the table says why.
"""

from __future__ import annotations

import pytest

from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES, FORCES_TABLE, GEARS_TABLE, KINEMATICS_TABLE, expected_table

TABLE = expected_table()


def test_every_fixture_has_expected_answers():
    files = {p.stem for p in FIXTURES.glob("*.edges")}
    kinematic = set(expected_table((KINEMATICS_TABLE, FORCES_TABLE, GEARS_TABLE)))
    assert set(TABLE) <= files
    assert files == set(TABLE) | kinematic, files.symmetric_difference(set(TABLE) | kinematic)
    assert len([f for f in files if f.startswith("ch1_")]) == 17


@pytest.fixture(scope="module", params=sorted(TABLE))
def case(request):
    expected = TABLE[request.param]
    return expected, analyze(read_edgelist(FIXTURES / expected["file"]))


def test_counts_and_mobility(case):
    expected, report = case
    mob = report.mobility
    assert (mob.n, mob.P5, mob.P4) == (expected["n"], expected["P5"], expected["P4"])
    assert mob.r == expected["redundant"]
    assert mob.W_passive == expected["passive"]
    assert mob.W == expected["W"]
    assert mob.W == mob.W_topology + mob.r - mob.W_passive


def test_replacement_counts(case):
    expected, report = case
    rm = report.replaced_mobility
    assert {"n": rm.n, "P5": rm.P5, "P4": rm.P4} == expected["replaced"]
    assert rm.W == report.mobility.W  # replacement keeps the mobility


def test_drivers(case):
    expected, report = case
    assert sorted(report.drivers) == sorted(expected["drivers"])


def test_groups_and_class(case):
    expected, report = case
    got = sorted((sorted(g.links), g.assur_class, g.order, g.kind or "") for g in report.groups)
    want = sorted(
        (sorted(g["links"]), g["class"], g["order"], g.get("kind", "")) for g in expected["groups"]
    )
    assert got == want
    assert report.mechanism_class == expected["mechanism_class"]


def test_formula_lists_groups_in_solve_order(case):
    _, report = case
    known = set(report.drivers) | {report.replaced.ground}
    for group in report.groups:
        assert set(group.known_links) <= known, group
        known |= set(group.links)
    assert report.formula.count("→") == len(report.drivers) + len(report.groups) - 1
