"""Assur decomposition and classification (THEORY.md §1–2)."""

from __future__ import annotations

import pytest

from structure.assur import classify_group, decompose, roman
from structure.errors import DecompositionError
from structure.readwrite.edgelist import parse_edgelist
from structure.report import all_driver_choices, analyze


def mech(text: str):
    return parse_edgelist(text.strip().splitlines())


STEPHENSON = """
ground F
F C R
C L1 R
L1 B R
B L2 R
B L3 R
L2 F R
L3 F R
"""


def groups_of(decomposition):
    return sorted((sorted(g.links), g.assur_class, g.order) for g in decomposition.groups)


def test_driver_choice_changes_the_class():
    m = mech(STEPHENSON)
    triad = decompose(m, ["C"])
    assert groups_of(triad) == [(["B", "L1", "L2", "L3"], 3, 3)]
    dyads = decompose(m, ["L2"])
    assert groups_of(dyads) == [(["B", "L3"], 2, 2), (["C", "L1"], 2, 2)]
    # B–L3 hangs on the driver and the frame; C–L1 needs B known: solve order says so
    assert [g.links for g in dyads.groups] == [("B", "L3"), ("C", "L1")]
    assert list(dyads.dag.edges) == [(0, 1)]


def test_all_driver_choices_show_each_class():
    report = analyze(mech(STEPHENSON), ["C"])
    by_driver = {c.drivers: c.decomposition.mechanism_class for c in all_driver_choices(report)}
    assert by_driver == {("C",): 3, ("L2",): 2, ("L3",): 2}


@pytest.mark.parametrize(
    ("listing"),
    [
        ("1 2 R B", "1 5 R B"),
        ("1 2 R B", "2 5 R B"),
        ("5 2 R B", "5 1 R B"),
    ],
)
def test_peaucellier_pins_as_points_gives_three_dyads(listing):
    # printed: one class IV group (contour BDCE); with pins as points A and B are known,
    # so (AD, BD) fixes D, (AE, BE) fixes E, then (DC, CE) fixes C
    lines = [
        "driver 1",
        "0 1 R F",
        *listing,
        "2 3 R D",
        "2 6 R D",
        "3 4 R C",
        "4 5 R E",
        "4 7 R E",
        "0 6 R A",
        "0 7 R A",
    ]
    d = decompose(parse_edgelist(lines))
    assert groups_of(d) == [(["2", "6"], 2, 2), (["3", "4"], 2, 2), (["5", "7"], 2, 2)]
    assert all(g.kind == "RRR" for g in d.groups)


def test_class_five_group_from_its_contour():
    # pentagon A-B-C-D-E plus F joined to A and C: 6 links, 7 internal + 2 external pairs;
    # largest contour A-F-C-D-E (5 joints), so class V, order 2
    text = """
driver 1
0 1 R
A B R
B C R
C D R
D E R
E A R
F A R
F C R
B 0 R
E 1 R
"""
    d = decompose(mech(text))
    assert groups_of(d) == [(["A", "B", "C", "D", "E", "F"], 5, 2)]


@pytest.mark.parametrize(
    ("links", "joints", "expected"),
    [
        (["2", "3"], [("2", "3")], 2),
        (["b", "x", "y", "z"], [("b", "x"), ("b", "y"), ("b", "z")], 3),  # triad: base link
        (list("abcd"), [("a", "b"), ("b", "c"), ("c", "d"), ("d", "a")], 4),  # contour of 4
        # two base links (order 4 triad variant): class III
        (list("bBxyz"), [("b", "B"), ("b", "x"), ("b", "y"), ("B", "z")], 3),
        # a compound internal hinge joining three links counts once on a contour
        (list("abc"), [("a", "b", "c")], 2),
        (list("abcde"), [("a", "b"), ("b", "c"), ("c", "d"), ("d", "e"), ("e", "a")], 5),
    ],
)
def test_classify_group(links, joints, expected):
    assert classify_group(links, joints) == expected


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("driver 1\n0 1 R\n1 2 R\n2 3 R\n3 0 R", "RRR"),
        ("driver 1\n0 1 R\n1 2 R\n2 3 R\n3 0 P S angle=0", "RRP"),
        ("driver 1\n0 1 R\n1 2 R\n2 3 P S angle=0\n3 0 R", "RPR"),
        ("driver 1\n0 1 R\n1 2 P S angle=0\n2 3 R\n3 0 P T angle=90", "PRP"),
        ("driver 1\n0 1 R\n1 2 R\n2 3 P S angle=0\n3 0 P T angle=90", "RPP"),
        ("driver 1\n0 1 R\n1 2 P S angle=0\n2 3 P T angle=90\n3 0 R", "RPP"),
    ],
)
def test_dyad_kinds(text, kind):
    (group,) = decompose(mech(text)).groups
    assert (group.assur_class, group.order, group.kind) == (2, 2, kind)
    assert 3 * len(group.links) == 2 * len(group.pairs)


def test_textbook_formula_and_detach_order():
    report = analyze(mech("driver 1\n0 1 R\n1 2 R\n2 3 R\n3 0 R\n3 4 R\n4 5 R\n5 0 R"))
    assert report.formula == "I(1) → II(2,3) → II(4,5)"
    assert report.textbook_formula == "1 = 1 + 0 + 0"
    assert [g.links for g in report.detach_order] == [("4", "5"), ("2", "3")]


def test_higher_pairs_must_be_replaced_first():
    with pytest.raises(DecompositionError, match="replace"):
        decompose(mech("driver 1\n0 1 R\n1 2 H K\n2 0 R"))


def test_roman():
    assert [roman(k) for k in (1, 2, 3, 4, 9, 14)] == ["I", "II", "III", "IV", "IX", "XIV"]


def test_driver_pinned_to_the_ground_through_a_compound_hinge():
    # links 0, 1, 3 share pin A; listing 3–1 and 3–0 instead of 0–1 is the same four-bar
    d = decompose(mech("driver 1\n3 1 R A\n1 2 R B\n2 3 R C\n3 0 R A"))
    assert groups_of(d) == [(["2", "3"], 2, 2)]


def test_rpp_dyad_next_to_an_rrr_dyad_stays_two_groups():
    # the guides fix the RPP dyad's middle angle early; the pair must not be split
    text = """
driver 1
0 1 R A
1 2 R B
2 3 P C angle=10
3 0 P D angle=80
2 4 R E
4 5 R F
5 0 R G
"""
    d = decompose(mech(text))
    assert sorted((sorted(g.links), g.kind) for g in d.groups) == [
        (["2", "3"], "RPP"),
        (["4", "5"], "RRR"),
    ]
