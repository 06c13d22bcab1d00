"""Higher-pair replacement (THEORY.md §4)."""

from __future__ import annotations

import pytest

from structure.errors import EdgeListError
from structure.mobility import mobility
from structure.model import PairKind
from structure.readwrite.edgelist import parse_edgelist
from structure.replacement import replace_higher_pairs


def mech(text: str):
    return parse_edgelist(text.strip().splitlines())


def test_curve_curve_contact_becomes_rr_at_the_centres():
    m = mech("driver 1\n0 1 R O1\n1 2 H K centers=C1,C2\n2 0 R O2")
    r, (rep,) = replace_higher_pairs(m)
    assert rep.scheme == "R–R"
    assert [(p.kind, p.links, p.point) for p in rep.new_pairs] == [
        (PairKind.R, ("1", "v1"), "C1"),
        (PairKind.R, ("v1", "2"), "C2"),
    ]
    assert mobility(r).W == mobility(m).W == 1


def test_flat_face_becomes_r_plus_p_parallel_to_the_face():
    text = """
driver 1
0 1 R O
1 2 H K flat=2 centers=C1,
2 0 P S angle=90
point O 0 0
point C1 0.01 0
point K 0.01 0.03
point S 0.01 0.05
"""
    r, (rep,) = replace_higher_pairs(mech(text))
    rp, pp = rep.new_pairs
    assert (rp.kind, rp.links, rp.point) == (PairKind.R, ("1", "v1"), "C1")
    assert (pp.kind, pp.links) == (PairKind.P, ("v1", "2"))
    # normal C1→K points along +y, so the face (and the new slide) is along x: 180° ≡ 0°
    assert pp.angle_deg % 180 == pytest.approx(0)
    assert mobility(r).W == 1


def test_roller_is_removed_and_contact_moves_to_its_axis():
    m = mech("driver 1\n0 1 R O1\n1 2 H K roller=2 centers=C1,\n2 3 R B\n3 0 R O3")
    assert mobility(m).W_passive == 1
    r, (rep,) = replace_higher_pairs(m)
    assert "2" not in r.links
    assert rep.roller is not None and (rep.roller.follower, rep.roller.axis) == ("3", "B")
    assert [(p.links, p.point) for p in rep.new_pairs] == [(("1", "v1"), "C1"), (("v1", "3"), "B")]
    assert mobility(r).W == 1 and mobility(r).W_passive == 0


def test_virtual_link_names_avoid_existing_links():
    m = mech("driver 1\n0 1 R\n1 v1 H K\nv1 0 R")
    _, (rep,) = replace_higher_pairs(m)
    assert rep.virtual_link == "v1'"


def test_roller_must_be_binary():
    with pytest.raises(EdgeListError, match="roller 2"):
        replace_higher_pairs(mech("driver 1\n0 1 R\n1 2 H K roller=2\n2 3 R\n2 4 R\n3 0 R\n4 0 R"))


def test_lower_pairs_keep_their_ids():
    m = mech("driver 1\n0 1 R O1\n1 2 H K\n2 0 R O2")
    r, _ = replace_higher_pairs(m)
    assert {p.id for p in r.pairs if p.kind is PairKind.R and p.point in ("O1", "O2")} == {1, 3}
