"""Mobility with its corrections, against hand counts (THEORY.md §3)."""

from __future__ import annotations

import pytest

from structure.errors import MobilityError
from structure.mobility import mobility
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES


def mech(text: str):
    return parse_edgelist(text.strip().splitlines())


FOURBAR = """
0 1 R A
1 2 R B
2 3 R C
3 0 R D
"""

PARALLELOGRAM = """
driver 1
0 1 R A
1 2 R B
2 3 R C
3 0 R D
0 4 R E
4 2 R F
point A 0 0
point B 0 1
point C 2 1
point D 2 0
point E 1 0
point F {fx} 1
"""


@pytest.mark.parametrize(
    ("text", "n", "p5", "p4", "r", "passive", "w"),
    [
        # every pair kind appears: R, P, H
        (FOURBAR, 3, 4, 0, 0, 0, 1),
        ("0 1 R\n1 2 R\n2 3 R\n3 0 P C angle=0", 3, 4, 0, 0, 0, 1),
        ("0 1 R\n1 2 H K\n2 0 R", 2, 2, 1, 0, 0, 1),  # cam with oscillating follower
        # a loop of three prismatic pairs: the angle constraints repeat (r = 1, W = 1)
        ("0 1 P X angle=0\n1 2 P Y angle=90\n2 0 P Z angle=45", 2, 3, 0, 1, 0, 1),
        # two links joined by two pins: one constraint is redundant (3 - 4 + 1 = ... W = 1)
        ("0 1 R O\n1 2 R p\n1 2 R q", 2, 3, 0, 1, 0, 1),
        # roller follower: 3·3 − (2·3 + 1) = 2, the roller's spin is passive
        ("0 1 R O1\n1 2 H K roller=2\n2 3 R B\n3 0 R O3", 3, 3, 1, 0, 1, 1),
        # a triangle is a structure
        ("0 1 R\n1 2 R\n2 0 R", 2, 3, 0, 0, 0, 0),
        # five-bar: two degrees of freedom
        ("0 1 R\n1 2 R\n2 3 R\n3 4 R\n4 0 R", 4, 5, 0, 0, 0, 2),
    ],
)
def test_structural_mobility(text, n, p5, p4, r, passive, w):
    mob = mobility(mech(text))
    assert (mob.n, mob.P5, mob.P4) == (n, p5, p4)
    assert (mob.r, mob.W_passive, mob.W) == (r, passive, w)
    assert mob.W_topology == 3 * n - (2 * p5 + p4)


def test_compound_hinge_counts_k_minus_one_pairs():
    # links 1, 3, 5 on one pin B: two pairs, whichever two are listed
    for listing in (("1 3 R B", "1 5 R B"), ("1 3 R B", "3 5 R B"), ("5 1 R B", "3 5 R B")):
        text = "\n".join(["0 1 R A", *listing, "3 0 R C", "5 0 R D"])
        mob = mobility(mech(text))
        assert mob.P5 == 5
        # 1 and 3 form a rigid triangle with the ground; 5 is then pinned at D and B:
        # W_topology = 3·3 − 2·5 = −1, one constraint repeats, W = 0
        assert (mob.W_topology, mob.r, mob.W) == (-1, 1, 0)


def test_redundant_pair_is_named():
    mob = mobility(mech("0 1 R O\n1 2 R p\n1 2 R q"))
    assert [(x.label, x.constraints, x.source) for x in mob.redundant] == [
        ("1–2 R q", 1, "structural")
    ]


def test_parallelogram_third_crank_is_geometrically_redundant():
    m = mech(PARALLELOGRAM.format(fx=1))
    mob = mobility(m)
    assert mob.W_topology == 0
    assert (mob.r, mob.W) == (1, 1)
    assert [(x.label, x.source) for x in mob.redundant] == [("4–2 R F", "geometric")]
    report = analyze(m)
    assert report.decomposition.removed_links == ("4",)
    assert [g.links for g in report.groups] == [("2", "3")]


def test_parallelogram_with_a_skew_third_link_is_a_structure():
    m = mech(PARALLELOGRAM.format(fx=1.3))
    mob = mobility(m)
    assert (mob.r, mob.W) == (0, 0)
    with pytest.raises(MobilityError, match="W = 0"):
        analyze(m)


def test_parallelogram_without_coordinates_counts_topology_only():
    text = "\n".join(line for line in PARALLELOGRAM.splitlines() if not line.startswith("point"))
    mob = mobility(mech(text))
    assert (mob.r, mob.W, mob.geometric) == (0, 0, False)


def test_slider_in_two_coaxial_guides():
    base = "0 1 R A\n1 2 R B\n2 3 R C\n3 0 P C angle=0\n3 0 P G angle={a}\n"
    pts = "point A 0 0\npoint B 0.1 0.1\npoint C 0.3 0\npoint G 0.5 {gy}\n"
    coaxial = mobility(mech(base.format(a=0) + pts.format(gy=0)))
    # two P pairs between the same links: 4 constraints on 3 freedoms (r ≥ 1); coaxial: r = 2
    assert coaxial.r == 2
    assert coaxial.W == 1
    # without coordinates only the structural redundancy is seen (W = 3·3 − 2·5 + 1 = 0)
    structural = mobility(mech(base.format(a=0)))
    assert (structural.r, structural.W) == (1, 0)


def test_geometric_passive_roller_not_declared():
    # contact normal C1→B passes through the roller's centre B: its spin moves nothing else
    text = """
driver 1
0 1 R O1
1 2 H K centers=C1,B
2 3 R B
3 0 R O3
point O1 0 0
point C1 0.01 0
point K 0.05 0
point B 0.07 0
point O3 0.07 0.2
"""
    mob = mobility(mech(text))
    assert [(p.link, p.dof, p.source) for p in mob.passive] == [("2", 1, "geometric")]
    assert mob.W == 1


def test_w_formula_text():
    mob = mobility(mech(FOURBAR))
    assert mob.formula == "W = 3·3 − (2·4 + 0) + 0 − 0 = 1"


def test_w_different_from_drivers_is_a_diagnostic():
    with pytest.raises(MobilityError, match="W = 1 but 2 driver"):
        analyze(mech(FOURBAR), drivers=["1", "3"])
    with pytest.raises(MobilityError) as info:
        analyze(mech("0 1 R\n1 2 R\n2 0 R"))
    assert info.value.mobility.W == 0


def test_drivers_are_chosen_when_none_named():
    report = analyze(mech("0 1 R\n1 2 R\n2 3 R\n3 4 R\n4 0 R"))
    assert report.drivers_chosen
    assert report.drivers == ("1", "4")


FLAT_PARALLELOGRAM = [
    "driver 1",
    "0 1 R A",
    "1 2 R B",
    "2 3 R C",
    "3 0 R D",
    "point A 0 0",
    "point B 1 0",
    "point C 3 0",
    "point D 2 0",
]


def test_a_sketch_at_a_singular_pose_is_not_taken_for_redundancy():
    # AB = CD = 1, BC = AD = 2 drawn folded flat: at that pose the pairs'
    # Jacobian loses a rank (8 rows, rank 7), yet the linkage moves with
    # W = 3·3 − 2·4 = 1 and no redundancy; a nearby regular pose shows it.
    mob = mobility(parse_edgelist(FLAT_PARALLELOGRAM))
    assert (mob.r, mob.W) == (0, 1)
    assert any("singular pose" in note for note in mob.notes)


def test_a_true_geometric_redundancy_survives_the_regularity_check():
    # The third parallel crank stays redundant at every pose of the parallelogram.
    mob = mobility(read_edgelist(FIXTURES / "parallelogram_redundant.edges"))
    assert (mob.r, mob.W) == (1, 1)
    assert not any("singular pose" in note for note in mob.notes)
