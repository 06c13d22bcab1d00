"""The compact Pair record and the Mechanism's link tables behave as the plain ones did.

A Pair keeps its rarely given options in one field and a Mechanism groups the
pairs of each link in flat tables (issue 11); these tests pin what callers
see: every option readable, equality and hashing over all of them,
``dataclasses.replace`` and pickling, and ``pairs_of`` / ``connected_to_ground``
answers worked out by hand.
"""

from __future__ import annotations

import dataclasses
import pickle

import pytest

from structure.errors import EdgeListError
from structure.model import Mechanism, Pair, PairKind, make_pair
from structure.readwrite.edgelist import parse_edgelist

OPTIONS = {
    "flat": "2",
    "roller": "1",
    "centers": ("O1", None),
    "normal_deg": 30.0,
    "span": 0.1,
    "friction": 0.2,
    "circle": 0.01,
    "gear": True,
    "teeth": (20, None),
    "internal": "2",
    "module": 0.002,
}
DEFAULTS = dict.fromkeys(OPTIONS) | {"gear": False}


def test_every_option_reads_back_and_defaults_hold() -> None:
    plain = Pair(1, PairKind.R, "1", "2", "A", line_no=4)
    assert {key: getattr(plain, key) for key in OPTIONS} == DEFAULTS
    for key, value in OPTIONS.items():
        pair = Pair(1, PairKind.H, "1", "2", "K", **{key: value})
        assert getattr(pair, key) == value
        assert {k: getattr(pair, k) for k in OPTIONS if k != key} == {
            k: v for k, v in DEFAULTS.items() if k != key
        }


def test_positional_fields_keep_their_order() -> None:
    pair = Pair(3, PairKind.P, "3", "0", "C", 30.0, None, None, None, None, 7, 0.5)
    assert (pair.id, pair.angle_deg, pair.line_no, pair.span) == (3, 30.0, 7, 0.5)


def test_equality_and_hash_see_each_option_but_not_the_line() -> None:
    base = Pair(1, PairKind.H, "1", "2", "K", line_no=3)
    assert base == Pair(1, PairKind.H, "1", "2", "K", line_no=99)
    assert hash(base) == hash(Pair(1, PairKind.H, "1", "2", "K"))
    for key, value in OPTIONS.items():
        assert Pair(1, PairKind.H, "1", "2", "K", **{key: value}) != base
    both = Pair(1, PairKind.H, "1", "2", "K", flat="2", normal_deg=30.0)
    again = Pair(1, PairKind.H, "1", "2", "K", normal_deg=30.0, flat="2", line_no=5)
    assert both == again and hash(both) == hash(again)


def test_plain_builds_the_same_record() -> None:
    built = Pair.plain(2, PairKind.P, "3", "0", "C", 45.0, 6)
    assert built == Pair(2, PairKind.P, "3", "0", "C", 45.0, line_no=6)
    assert built.line_no == 6 and built.gear is False and built.flat is None


def test_replace_and_pickle_keep_every_option() -> None:
    pair = make_pair(4, "H", "1", "2", "K", gear=True, z=(20, 60), module=0.002, line_no=8)
    moved = dataclasses.replace(pair, module=0.004)
    assert (moved.teeth, moved.gear, moved.module, moved.line_no) == ((20, 60), True, 0.004, 8)
    assert moved.statement == "1 2 H K gear z=20,60 module=0.004"
    back = pickle.loads(pickle.dumps(pair))
    assert back == pair and back.line_no == 8 and back.statement == pair.statement


def test_a_pair_stays_frozen() -> None:
    pair = Pair(1, PairKind.R, "1", "2")
    with pytest.raises(dataclasses.FrozenInstanceError):
        pair.flat = "1"  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        pair.a = "3"  # type: ignore[misc]


def test_pairs_of_in_file_order_with_ids_that_are_not_positions() -> None:
    pairs = [
        Pair(10, PairKind.R, "0", "1", "A"),
        Pair(20, PairKind.R, "1", "2", "B"),
        Pair(30, PairKind.R, "2", "0", "C"),
        Pair(40, PairKind.R, "1", "0", "D"),
    ]
    m = Mechanism(tuple(pairs))
    assert m.links == ("0", "1", "2")
    assert [p.id for p in m.pairs_of("0")] == [10, 30, 40]
    assert [p.id for p in m.pairs_of("1")] == [10, 20, 40]
    assert [p.id for p in m.pairs_of("2")] == [20, 30]
    assert list(m.pairs_of("9")) == []
    assert m.pair(30) is pairs[2]
    assert m.has_link("2") and not m.has_link("9")
    # the numbers of each pair's ends (the ground 0) and the ids, as the constraint rows read them
    assert m.pair_ends().tolist() == [[0, 1], [1, 2], [2, 0], [1, 0]]
    assert m.pair_ids().tolist() == [10, 20, 30, 40]
    in_place = Mechanism(tuple(dataclasses.replace(p, id=k) for k, p in enumerate(pairs, 1)))
    assert in_place.pair_ids().tolist() == [1, 2, 3, 4]


def test_pairs_with_options_are_those_with_any_option_but_the_angle() -> None:
    pairs = (
        make_pair(1, "R", "0", "1", "A"),
        make_pair(2, "P", "1", "2", "B", angle=30),
        make_pair(3, "H", "2", "3", "K", roller="3"),
        make_pair(4, "R", "3", "0", "D", circle=0.2),
        make_pair(5, "R", "2", "0", "E"),
    )
    m = Mechanism(pairs)
    expected = [p.id for p in pairs if p.flat or p.roller or p.circle is not None]
    assert [p.id for p in m.pairs_with_options()] == expected == [3, 4]


def test_a_pair_of_a_link_to_itself_counts_at_both_ends() -> None:
    m = Mechanism((Pair(1, PairKind.R, "0", "1"), Pair(2, PairKind.R, "1", "1")))
    assert [p.id for p in m.pairs_of("1")] == [1, 2, 2]


def test_connected_to_ground_and_the_reader_reports_loose_links() -> None:
    m = Mechanism(
        (
            Pair(1, PairKind.R, "0", "1"),
            Pair(2, PairKind.R, "2", "3"),
            Pair(3, PairKind.R, "1", "4"),
            Pair(4, PairKind.R, "3", "5"),
        )
    )
    assert m.connected_to_ground() == {"0", "1", "4"}
    with pytest.raises(EdgeListError) as caught:
        parse_edgelist(["0 1 R A", "2 3 R B", "1 4 R C", "3 5 R D"])
    assert "line 2" in str(caught.value)
    assert "link(s) not connected to the ground 0: 2, 3, 5" in str(caught.value)


def test_the_reader_shares_names_and_line_numbers() -> None:
    # names of two characters or more: Python shares one-character strings by itself
    lines = ["# title", "0 L1 R PA", "L1 L2 P PB angle=30", "L2 0 R PC", "L1 L3 R PA", "L3 0 R PD"]
    m = parse_edgelist(lines)
    first, second = m.pairs[0], m.pairs[1]
    assert first.b is second.a and first.b is m.pairs[3].a  # one string for link L1
    assert m.pairs[3].point == first.point  # the same point, its name read twice
    assert [h.point for h in m.shared_hinges] == ["PA"]
    assert [(p.id, p.line_no) for p in m.pairs] == [(1, 2), (2, 3), (3, 4), (4, 5), (5, 6)]
    assert second.angle_deg == 30.0 and second.kind is PairKind.P
