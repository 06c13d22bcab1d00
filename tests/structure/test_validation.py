"""Tests of the shared statement checks (structure.validation) and the model's builders."""

from __future__ import annotations

import pytest

from structure.errors import EdgeListError, StatementError
from structure.model import Mechanism, PairKind, make_driver, make_load, make_pair, make_point
from structure.readwrite.edgelist import pair_from_tokens

# (edge-list line, the same pair built from Python values)
SAME_PAIR = [
    ("0 1 R A", ("R", "0", "1", "A"), {}),
    ("0 1 R A circle=0.01", ("R", "0", "1", "A"), {"circle": 0.01}),
    ("2 0 P C angle=30 span=0.1 friction=0.2", ("P", "2", "0", "C"),
     {"angle": 30, "span": 0.1, "friction": 0.2}),
    ("1 2 H K flat=2 centers=O1, normal=-45", ("H", "1", "2", "K"),
     {"flat": "2", "centers": ("O1", None), "normal": -45.0}),
    ("1 2 H gear z=20,? internal=2 module=0.002", ("H", "1", "2", None),
     {"gear": True, "z": (20, None), "internal": "2", "module": 0.002}),
]  # fmt: skip


@pytest.mark.parametrize(("line", "head", "options"), SAME_PAIR)
def test_make_pair_builds_what_the_grammar_reads(line, head, options):
    kind, a, b, point = head
    pair, why = pair_from_tokens(line.split(), 7, 3)
    assert why == ""
    built = make_pair(7, kind, a, b, point, line_no=3, **options)
    assert built == pair
    assert built.statement == line
    assert make_pair(7, PairKind(kind), a, b, point, **options) == pair


# (options, the reason make_pair gives, as the edge list has always said it)
BAD_PAIRS = [
    ("Q", {}, "unknown pair kind 'Q' (use R, P or H)"),
    ("R", {"angle": 10.0}, "unknown option 'angle' for a R pair (allowed: circle)"),
    ("P", {"angle": float("inf")}, "angle and normal must be finite numbers of degrees"),
    ("P", {"angle": "30"}, "angle and normal must be finite numbers of degrees"),
    ("P", {"span": 0.0}, "span= is the distance between the slide's two contact points "
     "(metres), > 0"),
    ("R", {"circle": -1.0}, "circle= is the friction-circle radius of the pin (metres), >= 0"),
    ("H", {"centers": (None, None)},
     "centers=O1,O2 names the centres of curvature on a and b (one may be empty)"),
    ("H", {"z": (20, 60)}, "z=, internal= and module= belong to a gear mesh: write 'gear'"),
    ("H", {"gear": True, "z": (0, 60)},
     "z=za,zb gives the tooth numbers of a and b (positive integers or ?)"),
    ("H", {"gear": True, "z": (20.0, 60)},
     "z=za,zb gives the tooth numbers of a and b (positive integers or ?)"),
    ("H", {"gear": True, "internal": "9"}, "internal=9 is not one of the pair's links 1, 2"),
    ("H", {"gear": True, "module": 0}, "module= is the gear module in metres"),
]  # fmt: skip


@pytest.mark.parametrize(("kind", "options", "reason"), BAD_PAIRS)
def test_make_pair_refuses_with_the_readers_reason(kind, options, reason):
    with pytest.raises(StatementError) as info:
        make_pair(1, kind, "1", "2", "K", **options)
    assert info.value.reason == reason
    assert isinstance(info.value, ValueError)


def test_make_pair_refuses_a_pair_from_a_link_to_itself():
    with pytest.raises(StatementError, match="itself"):
        make_pair(1, "R", "1", "1")


def test_none_is_an_option_left_out():
    assert make_pair(1, "P", "1", "2", "C", angle=None) == make_pair(1, "P", "1", "2", "C")


def test_other_statements_are_checked():
    assert make_point("A", 0, 1).y == 1.0
    assert make_driver("1", [("omega", 2)]).motion == (("omega", 2.0),)
    assert make_load("force", "2", "B", (1, 2)).values == (1.0, 2.0)
    for build, reason in (
        (lambda: make_point("A", float("nan"), 0), "finite"),
        (lambda: make_driver("1", [("speed", 2)]), "'speed'"),
        (lambda: make_driver("1", [("omega", float("inf"))]), "finite"),
        (lambda: make_load("mass", "2", "S", (-1, 0)), "negative"),
        (lambda: make_load("torque", "2", None, (1,)), "'torque'"),
    ):
        with pytest.raises(StatementError, match=reason):
            build()


def test_from_pairs_reports_each_bad_pair_by_its_position():
    with pytest.raises(EdgeListError) as info:
        Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "X"), ("2", "0", "R", "C", {"z": 3})])
    assert [p.reason for p in info.value.problems] == [
        "pair 2: unknown pair kind 'X' (use R, P or H)",
        "pair 3: unknown option 'z' for a R pair (allowed: circle)",
    ]


def test_from_pairs_takes_kinds_numbers_as_names_and_no_point():
    m = Mechanism.from_pairs([(0, 1, PairKind.R, None), (1, 2, "R", "B"), (2, 0, "R")])
    assert [(p.a, p.b, p.point) for p in m.pairs] == [("0", "1", None), ("1", "2", "B"),
                                                       ("2", "0", None)]  # fmt: skip


def test_a_paused_collector_resumes_with_the_phase_objects_in_the_oldest_generation() -> None:
    import gc

    from structure.utils import paused_gc

    was = gc.isenabled()
    gc.enable()
    try:
        with paused_gc():
            assert not gc.isenabled()
            made = [[k] for k in range(20000)]
        assert gc.isenabled()
        assert gc.get_count()[0] < 1000  # not a young generation of 20 000 lists to pass over
        assert any(made[0] is x for x in gc.get_objects(generation=2))
        # a program's own frozen objects stay frozen
        gc.freeze()
        frozen = gc.get_freeze_count()
        with paused_gc():
            more = [[k] for k in range(100)]
        assert gc.get_freeze_count() == frozen and len(more) == 100
    finally:
        gc.unfreeze()
        if not was:
            gc.disable()
