"""Mobility with its corrections, against hand counts (THEORY.md §3)."""

from __future__ import annotations

import math

import pytest

from structure.errors import DecompositionError, MobilityError
from structure.mobility import mobility
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import all_driver_choices, analyze

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


# ------------------------------------------------------------ a sketch at a singular pose
# Issue 22, item 13. The four-bar AB = 0.1, BC = 0.2, CD = 0.2, AD = √0.13 drawn with the
# crank and the coupler in line (A, B, C on the x axis; D above C). Counted by hand:
# W = 3·3 − 2·4 = 1; generically the 8 pair rows and the driver's row are independent, so
# r = 0 and nothing is passive, whichever link drives.
# * the rocker 3 driving: with C held, the dyad (1, 2) spans A–C with |AB| + |BC| = |AC|: the
#   two circles about A and C touch at B, so B can move across AC to first order and the
#   dyad's Jacobian loses a rank (a dead point). The sketch then shows the driver's row as
#   dependent on the pairs' (once "the motion of driver 3 is already fixed"); a pose a small
#   turn away is regular, and the answer is the generic one: I(3) → II(1,2), II(1,2) singular
#   at the sketch.
# * the crank 1 driving: the dyad (2, 3) joins B and D with BC along x and CD along y, not
#   in line: regular, no warning (the rocker is at a limit: ω3 = 0, kinematics test below).
TOGGLE = """
name four-bar with the crank and the coupler in line
driver {driver}
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0.1 0
point C 0.3 0
point D 0.3 0.2
"""


def _counts(report):
    mob = report.mobility
    return mob.W, mob.r, mob.W_passive, report.formula


def test_a_toggle_sketch_is_classified_as_the_generic_four_bar():
    report = analyze(mech(TOGGLE.format(driver="3")))
    assert _counts(report) == (1, 0, 0, "I(3) → II(1,2)")
    assert [report.groups[k].label for k in report.singular] == ["II(1,2)"]
    (warning,) = report.warnings
    assert "group II(1,2) is at a singular pose in the sketch" in warning
    assert any("singular pose" in note for note in report.mobility.notes)
    # the same four-bar drawn at a regular pose gives the same answer: the crank at 60°,
    # B = (0.05, 0.05·√3), C where the circles of radius 0.2 about B and D meet (the nearer
    # to the x axis): |BD| = 0.274516, C = midpoint ± 0.136·⊥ = (0.235089, 0.010827)
    regular = TOGGLE.format(driver="3").replace("point B 0.1 0", "point B 0.05 0.05*sqrt(3)")
    regular = analyze(mech(regular.replace("point C 0.3 0", "point C 0.235089176 0.010826575")))
    assert _counts(regular) == _counts(report)
    assert regular.singular == () and regular.warnings == ()


def test_a_limit_position_of_the_rocker_is_not_a_singular_pose():
    report = analyze(mech(TOGGLE.format(driver="1")))
    assert _counts(report) == (1, 0, 0, "I(1) → II(2,3)")
    assert report.singular == () and report.warnings == ()
    assert not any("singular pose" in note for note in report.mobility.notes)


def test_coupler_and_rocker_in_line_is_a_dead_point_of_the_crank_driven_dyad():
    # B(0, 0.1), C(0.2, 0.1), D(0.3, 0.1): with B held, C can move across BD to first order
    text = TOGGLE.format(driver="1")
    for old, new in (("B 0.1 0", "B 0 0.1"), ("C 0.3 0", "C 0.2 0.1"), ("D 0.3 0.2", "D 0.3 0.1")):
        text = text.replace(f"point {old}", f"point {new}")
    report = analyze(mech(text))
    assert _counts(report) == (1, 0, 0, "I(1) → II(2,3)")
    assert [report.groups[k].label for k in report.singular] == ["II(2,3)"]


def test_a_flat_parallelogram_is_a_generic_four_bar_with_its_dyad_singular():
    # folded flat, B, C and D are in line: the dyad (2, 3) is singular at the sketch
    report = analyze(parse_edgelist(FLAT_PARALLELOGRAM))
    assert _counts(report) == (1, 0, 0, "I(1) → II(2,3)")
    assert [report.groups[k].label for k in report.singular] == ["II(2,3)"]


def test_a_true_geometric_redundancy_is_no_singular_sketch():
    # the third parallel crank is redundant at every pose: r = 1, set aside, no warning
    report = analyze(read_edgelist(FIXTURES / "parallelogram_redundant.edges"))
    assert (report.mobility.r, report.mobility.W) == (1, 1)
    assert [(x.label, x.source) for x in report.mobility.redundant] == [("4–2 R F", "geometric")]
    assert report.decomposition.removed_links == ("4",)
    assert report.singular == () and report.warnings == ()


def test_passive_freedoms_of_the_cam_roller_are_still_found():
    # the roller's spin (declared): W = 3·3 − (2·3 + 1) − 1 = 1; undeclared, the sketch shows
    # it (the contact normal passes through the roller's axis) and the error says so
    report = analyze(read_edgelist(FIXTURES / "cam_roller_follower.edges"))
    assert [(p.link, p.dof, p.source) for p in report.mobility.passive] == [("3", 1, "roller")]
    assert report.mobility.W == 1 and report.warnings == ()
    text = (FIXTURES / "cam_roller_follower.edges").read_text().replace(" roller=3", "")
    m = parse_edgelist(text.splitlines())
    assert [(p.link, p.source) for p in mobility(m).passive] == [("3", "geometric")]
    with pytest.raises(DecompositionError, match=r"link\(s\) 3 can move alone.*roller=LINK"):
        analyze(m)


def test_every_driver_choice_of_a_toggle_sketch_is_listed():
    # all_driver_choices decomposes each choice at the sketch: the rocker's choice used to be
    # dropped there as "already fixed"
    report = analyze(mech(TOGGLE.format(driver="1")))
    assert [c.drivers for c in all_driver_choices(report)] == [("1",), ("3",)]


def test_a_cam_roller_drawn_at_a_dead_point_keeps_its_passive_roller():
    # the cam fixture's disc (centre C1) and roller (axis R0, contact K on C1–R0) with the arm
    # Q–R0 drawn in line with C1–R0 (all at 60° from C1): once replaced, the dyad (v1, 2) has
    # its links in line, a dead point; the roller's spin is still the one passive freedom
    # (W = 3·3 − (2·3 + 1) − 1 = 1)
    c1x, c1y, c, s = 0.017320508, 0.01, 0.5, math.sqrt(3) / 2
    point = {
        "K": (c1x + 0.05 * c, c1y + 0.05 * s),
        "R0": (c1x + 0.065 * c, c1y + 0.065 * s),
        "Q": (c1x + 0.165 * c, c1y + 0.165 * s),
    }
    text = """
driver 1 omega=10
0 1 R O
0 2 R Q
2 3 R R0
1 3 H K roller=3 centers=C1,R0
point O 0 0
point C1 0.017320508 0.01
"""
    lines = [*text.strip().splitlines(), *(f"point {k} {x!r} {y!r}" for k, (x, y) in point.items())]
    report = analyze(parse_edgelist(lines))
    assert [(p.link, p.source) for p in report.mobility.passive] == [("3", "roller")]
    assert _counts(report) == (1, 0, 1, "I(1) → II(2,v1)")
    assert [report.groups[k].label for k in report.singular] == ["II(2,v1)"]
