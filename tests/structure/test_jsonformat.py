"""Tests of the JSON form of the mechanism model (structure.readwrite.jsonformat)."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from structure.errors import EdgeListError, MechanismError
from structure.model import Driver, Mechanism, PairKind, PointDef
from structure.readwrite.edgelist import parse_edgelist, write_edgelist
from structure.readwrite.jsonformat import (
    mechanism_from_dict,
    mechanism_from_json,
    mechanism_to_dict,
    mechanism_to_json,
)

FOURBAR_PAIRS = [
    {"links": ["0", "1"], "kind": "R", "point": "A"},
    {"links": ["1", "2"], "kind": "R", "point": "B"},
    {"links": ["2", "3"], "kind": "R", "point": "C"},
    {"links": ["3", "0"], "kind": "R", "point": "D"},
]


def _fourbar(**extra) -> dict:
    return {"pairs": [dict(p) for p in FOURBAR_PAIRS], **extra}


def _error(data, source: str = "t.json") -> EdgeListError:
    text = data if isinstance(data, str) else json.dumps(data)
    with pytest.raises(EdgeListError) as info:
        mechanism_from_json(text, source)
    assert isinstance(info.value, MechanismError)
    assert isinstance(info.value, ValueError)
    return info.value


# ------------------------------------------------------------------ valid input
def test_json_equals_the_same_mechanism_built_in_python():
    data = {
        "name": "cam and slider",
        "ground": "0",
        "drivers": [{"link": "1", "omega": 20, "epsilon": 0}],
        "pairs": [
            {"links": ["0", "1"], "kind": "R", "point": "O"},
            {"links": ["0", "2"], "kind": "P", "point": "Q", "angle": 90},
            {
                "links": ["1", "2"],
                "kind": "H",
                "point": "K",
                "flat": "2",
                "centers": ["C1", None],
                "normal": 90,
            },
            {"links": ["1", "3"], "kind": "R", "point": "B"},
            {"links": ["3", "4"], "kind": "R", "point": "C"},
            {"links": ["4", "0"], "kind": "P", "point": "C", "angle": 0},
        ],
        "points": {"O": [0, 0], "K": [0, 0.05], "M": {"xy": [0.1, 0.2], "on": "3"}},
    }
    built = Mechanism.from_pairs(
        [
            ("0", "1", "R", "O"),
            ("0", "2", "P", "Q", {"angle": 90}),
            ("1", "2", "H", "K", {"flat": "2", "centers": ("C1", None), "normal": 90}),
            ("1", "3", "R", "B"),
            ("3", "4", "R", "C"),
            ("4", "0", "P", "C", {"angle": 0}),
        ],
        drivers=[Driver("1", (("omega", 20.0), ("epsilon", 0.0)))],
        points=[PointDef("O", 0.0, 0.0), PointDef("K", 0.0, 0.05), PointDef("M", 0.1, 0.2, "3")],
        name="cam and slider",
        source="cam.json",
    )
    assert mechanism_from_json(json.dumps(data), "cam.json") == built
    assert mechanism_from_dict(data, "cam.json") == built


def test_numbers_stand_for_link_names():
    data = {
        "ground": 0,
        "drivers": [1],
        "pairs": [
            {"links": [0, 1], "kind": "R"},
            {"links": [1, 2.0], "kind": "R"},
            {"links": [2, 0], "kind": "P", "angle": 30},
        ],
        "points": {"M": {"xy": [0.5, 0], "on": 2}},
    }
    m = mechanism_from_dict(data)
    assert m.ground == "0"
    assert m.moving_links == ("1", "2")
    assert m.driver_links == ("1",)
    assert m.pairs[2].angle_deg == 30.0
    assert m.points["M"] == PointDef("M", 0.5, 0.0, "2")


def test_minimal_document_gets_the_defaults():
    m = mechanism_from_json('{"pairs": [{"links": ["0", "1"], "kind": "R"}]}')
    assert (m.ground, m.name, m.drivers, dict(m.points), m.source) == ("0", "", (), {}, "<json>")
    assert m.pairs[0].kind is PairKind.R
    assert m.pairs[0].point is None


@pytest.mark.parametrize(
    "data",
    [
        pytest.param({"ground": "0", "pairs": FOURBAR_PAIRS}, id="plain"),
        pytest.param(
            {
                "name": "four-bar",
                "ground": "F",
                "drivers": ["1", {"link": "3", "omega": -2.5}],
                "pairs": [
                    {"links": ["F", "1"], "kind": "R", "point": "A"},
                    {"links": ["1", "2"], "kind": "R", "point": "B"},
                    {"links": ["2", "3"], "kind": "R", "point": "C"},
                    {"links": ["3", "F"], "kind": "R", "point": "D"},
                ],
                "points": {"A": [0.0, 0.0], "M": {"xy": [0.1, 0.2], "on": "2"}},
            },
            id="drivers-and-points",
        ),
        pytest.param(
            {
                "ground": "0",
                "pairs": [
                    {"links": ["0", "1"], "kind": "R", "point": "O1"},
                    {"links": ["0", "2"], "kind": "R", "point": "O2"},
                    {
                        "links": ["1", "2"],
                        "kind": "H",
                        "point": "K",
                        "roller": "2",
                        "centers": [None, "N2"],
                        "normal": 20.5,
                    },
                ],
            },
            id="higher-pair",
        ),
        pytest.param(
            {
                "ground": "0",
                "pairs": [
                    {"links": ["0", "1"], "kind": "R"},
                    {"links": ["1", "2"], "kind": "R"},
                    {"links": ["2", "0"], "kind": "P", "angle": -12.25},
                ],
            },
            id="slider",
        ),
    ],
)
def test_canonical_dict_round_trip(data):
    m = mechanism_from_dict(data)
    assert mechanism_to_dict(m) == data
    assert json.loads(mechanism_to_json(m)) == data
    assert json.loads(mechanism_to_json(m, indent=None)) == data
    assert "\n" not in mechanism_to_json(m, indent=None)


# ------------------------------------------------------------------ invalid JSON
@pytest.mark.parametrize(
    ("text", "line_no"),
    [
        pytest.param(
            '{\n  "pairs": [\n    {"links": ["0", "1"] "kind": "R"}\n  ]\n}', 3, id="missing-comma"
        ),
        pytest.param('{"pairs": []\n,,}', 2, id="double-comma"),
        pytest.param('{"pairs": [1,]}', 1, id="trailing-comma"),
        pytest.param("", 1, id="empty"),
        pytest.param("{\n", 2, id="unclosed-object"),
        pytest.param("\n\n", 3, id="blank-lines"),
        pytest.param('{"pairs": [\n', 2, id="unclosed-list"),
    ],
)
def test_invalid_json_reports_its_line(text, line_no):
    error = _error(text)
    assert len(error.problems) == 1
    assert error.line_no == line_no
    assert "invalid JSON" in error.reason
    assert str(error).startswith(f"t.json: line {line_no}: ")


# ------------------------------------------------------------------ unknown keys and shapes
# (document, a word the reason must contain: where the problem is or what is wrong)
BAD_DOCUMENTS = [
    pytest.param(_fourbar(foo=1), "'foo'", id="unknown-top-key"),
    pytest.param(_fourbar(driver=["1"]), "'driver'", id="misspelt-drivers"),
    pytest.param(
        {"pairs": [{**FOURBAR_PAIRS[0], "bar": 2}, *FOURBAR_PAIRS[1:]]},
        "'bar'",
        id="unknown-pair-key",
    ),
    pytest.param(_fourbar(drivers=[{"link": "1", "speed": 3}]), "'speed'", id="unknown-driver-key"),
    pytest.param(
        _fourbar(points={"A": {"xy": [0, 0], "colour": "red"}}), "colour", id="unknown-point-key"
    ),
    pytest.param([1, 2], "object", id="top-level-list"),
    pytest.param("four-bar", "object", id="top-level-string"),
    pytest.param(None, "object", id="top-level-null"),
    pytest.param({"pairs": {"0-1": "R"}}, "pairs", id="pairs-object"),
    pytest.param({"pairs": [*FOURBAR_PAIRS, 7]}, "pairs[4]", id="pair-number"),
    pytest.param({"pairs": [{"kind": "R"}, *FOURBAR_PAIRS]}, "links", id="links-missing"),
    pytest.param(
        {"pairs": [{"links": ["0"], "kind": "R"}, *FOURBAR_PAIRS]}, "links", id="links-one"
    ),
    pytest.param(
        {"pairs": [{"links": ["0", "1", "2"], "kind": "R"}, *FOURBAR_PAIRS]},
        "links",
        id="links-three",
    ),
    pytest.param(
        {"pairs": [{"links": "01", "kind": "R"}, *FOURBAR_PAIRS]}, "links", id="links-string"
    ),
    pytest.param(
        {"pairs": [{"links": [["0"], "1"], "kind": "R"}, *FOURBAR_PAIRS[1:]]},
        "links",
        id="links-nested-list",
    ),
    pytest.param(
        {"pairs": [{"links": [None, "1"], "kind": "R"}, *FOURBAR_PAIRS[1:]]},
        "links",
        id="links-null",
    ),
    pytest.param({"pairs": [{"links": ["0", "1"]}, *FOURBAR_PAIRS[1:]]}, "kind", id="kind-missing"),
    pytest.param(
        {"pairs": [{"links": ["0", "1"], "kind": "X"}, *FOURBAR_PAIRS[1:]]},
        "'X'",
        id="kind-unknown",
    ),
    pytest.param(
        {"pairs": [{"links": ["0", "1"], "kind": "P", "angle": "steep"}, *FOURBAR_PAIRS[1:]]},
        "angle",
        id="angle-text",
    ),
    pytest.param(
        {"pairs": [{"links": ["0", "1"], "kind": "R", "angle": 10}, *FOURBAR_PAIRS[1:]]},
        "'angle'",
        id="angle-on-R",
    ),
    pytest.param(
        {"pairs": [{"links": ["0", "1"], "kind": "H", "centers": "C1"}, *FOURBAR_PAIRS[1:]]},
        "centers",
        id="centers-string",
    ),
    pytest.param(
        {"pairs": [{"links": ["0", "1"], "kind": "H", "centers": ["C1"]}, *FOURBAR_PAIRS[1:]]},
        "centers",
        id="centers-one",
    ),
    pytest.param(
        {"pairs": [{"links": ["1", "1"], "kind": "R"}, *FOURBAR_PAIRS]}, "itself", id="self-pair"
    ),
    pytest.param(_fourbar(drivers=1), "drivers", id="drivers-number"),
    pytest.param(_fourbar(drivers="13"), "drivers", id="drivers-string"),
    pytest.param(_fourbar(drivers={"link": "1"}), "drivers", id="drivers-object"),
    pytest.param(_fourbar(drivers=[["1"]]), "drivers[0]", id="driver-list"),
    pytest.param(_fourbar(drivers=[{"omega": 1}]), "drivers[0]", id="driver-without-link"),
    pytest.param(
        _fourbar(drivers=[{"link": "1", "omega": "fast"}]), "omega", id="driver-omega-text"
    ),
    pytest.param(_fourbar(drivers=[{"link": "1", "omega": True}]), "omega", id="driver-omega-bool"),
    pytest.param(_fourbar(drivers=["9"]), "9", id="driver-not-a-link"),
    pytest.param(_fourbar(points=[[0, 0]]), "points", id="points-list"),
    pytest.param(_fourbar(points={"A": [0]}), "'A'", id="point-one-coordinate"),
    pytest.param(_fourbar(points={"A": [0, 0, 0]}), "'A'", id="point-three-coordinates"),
    pytest.param(_fourbar(points={"A": ["zero", "0"]}), "'A'", id="point-text-coordinates"),
    pytest.param(_fourbar(points={"A": [True, False]}), "'A'", id="point-bool-coordinates"),
    pytest.param(_fourbar(points={"A": {"on": "1"}}), "'A'", id="point-without-xy"),
    pytest.param(_fourbar(points={"A": {"xy": [0, 0], "on": "9"}}), "9", id="point-on-unknown"),
    pytest.param(_fourbar(name=["four", "bar"]), "name", id="name-list"),
    pytest.param(_fourbar(ground=["0"]), "ground", id="ground-list"),
]


@pytest.mark.parametrize(("data", "word"), BAD_DOCUMENTS)
def test_bad_document_is_one_edgelist_error(data, word):
    error = _error(json.dumps(data))
    assert error.source == "t.json"
    assert any(word in p.reason for p in error.problems), error.problems
    assert str(error).startswith("t.json: ")


@pytest.mark.parametrize(
    ("text", "word"),
    [
        pytest.param(
            '{"pairs": %s, "drivers": [{"link": "1", "omega": NaN}]}',
            "omega",
            id="driver-omega-nan",
        ),
        pytest.param(
            '{"pairs": %s, "drivers": [{"link": "1", "omega": Infinity}]}',
            "omega",
            id="driver-omega-inf",
        ),
        pytest.param('{"pairs": %s, "points": {"A": [NaN, 0]}}', "'A'", id="point-nan"),
        pytest.param('{"pairs": %s, "points": {"A": [0, -Infinity]}}', "'A'", id="point-inf"),
        pytest.param(
            '{"pairs": [{"links": ["0", "1"], "kind": "P", "angle": NaN}]}',
            "angle",
            id="angle-nan",
        ),
    ],
)
def test_non_finite_numbers_are_rejected(text, word):
    if "%s" in text:
        text = text % json.dumps(FOURBAR_PAIRS)
    error = _error(text)
    assert any(word in p.reason for p in error.problems), error.problems


def test_every_problem_of_a_document_is_reported_in_order():
    data = {
        "pairs": [
            {"links": ["0", "1"], "kind": "Q"},
            {"links": ["1", "2"], "kind": "R"},
            {"links": ["2"], "kind": "R"},
            {"links": ["2", "0"], "kind": "R", "colour": "red"},
        ],
        "drivers": [{"link": "1", "speed": 2}],
        "points": {"A": [0]},
    }
    error = _error(data)
    where = [p.reason.split(":")[0] for p in error.problems]
    assert where == ["pairs[0]", "pairs[2]", "pairs[3]", "drivers[0]", "points['A']"]
    assert len(str(error).splitlines()) == 5


def test_dict_source_names_the_error():
    with pytest.raises(EdgeListError) as info:
        mechanism_from_dict({"pairs": 3})
    assert info.value.source == "<dict>"
    assert str(info.value).startswith("<dict>: ")


# ------------------------------------------------------------------ one verdict for both readers
# The same bad content written as an edge-list line and as a JSON load: both readers
# build it through the same checks (structure.validation), so both refuse it for the
# same reason. Each row is a case where the JSON reader used to accept what the edge
# list refused.
SAME_VERDICT = [
    pytest.param(
        "mass 2 -1 0.1 B",
        {"kind": "mass", "link": "2", "point": "B", "values": [-1, 0.1]},
        "mass and moment of inertia cannot be negative",
        id="negative-mass",
    ),
    pytest.param(
        "mass 2 1 -0.1 B",
        {"kind": "mass", "link": "2", "point": "B", "values": [1, "-0.1"]},
        "mass and moment of inertia cannot be negative",
        id="negative-moment-of-inertia",
    ),
    pytest.param(
        "mass 2 5 B",
        {"kind": "mass", "link": "2", "point": "B", "values": [5]},
        "expected 'mass LINK m J S'",
        id="missing-value",
    ),
    pytest.param(
        "force 2 B 1 2 3",
        {"kind": "force", "link": "2", "point": "B", "values": [1, 2, 3]},
        "expected 'force LINK POINT fx fy'",
        id="extra-value",
    ),
    pytest.param(
        "balance 1 A angle=30 angle=40",
        {"kind": "balance", "link": "1", "point": "A", "values": [30, 40]},
        "expected 'balance LINK POINT angle=DEG'",
        id="balance-two-directions",
    ),
    pytest.param(
        "moment 2 B 5",
        {"kind": "moment", "link": "2", "point": "B", "values": [5]},
        "expected 'moment LINK M'",
        id="moment-at-a-point",
    ),
    pytest.param(
        "gravity 2 0 -9.81",
        {"kind": "gravity", "link": "2", "values": [0, -9.81]},
        "expected 'gravity gx gy'",
        id="gravity-on-a-link",
    ),
]


@pytest.mark.parametrize(("line", "load", "reason"), SAME_VERDICT)
def test_json_refuses_what_the_edge_list_refuses_for_the_same_reason(line, load, reason):
    lines = [f"{' '.join(p['links'])} {p['kind']} {p['point']}" for p in FOURBAR_PAIRS]
    with pytest.raises(EdgeListError) as info:
        parse_edgelist([*lines, line], "t.edges")
    assert [p.reason for p in info.value.problems] == [reason]
    error = _error(_fourbar(loads=[load]))
    assert [p.reason for p in error.problems] == [f"loads[0]: {reason}"]


@pytest.mark.parametrize(
    ("load", "word"),
    [
        pytest.param(
            {"kind": "force", "link": "2", "point": "B", "values": [1, 2], "colour": "red"},
            "'colour'",
            id="unknown-load-key",
        ),
        pytest.param({"kind": ["mass"], "link": "2", "values": [1, 2]}, "kind", id="kind-list"),
    ],
)
def test_bad_load_object_is_one_edgelist_error(load, word):
    error = _error(_fourbar(loads=[load]))
    assert len(error.problems) == 1
    assert word in error.reason


def test_good_loads_read_as_in_the_edge_list():
    lines = [f"{' '.join(p['links'])} {p['kind']} {p['point']}" for p in FOURBAR_PAIRS]
    statements = ["mass 2 3 0.1 B", "force 2 B 1 -2", "moment 3 5", "gravity 0 -9.81",
                  "balance 1 A angle=30"]  # fmt: skip
    loads = [
        {"kind": "mass", "link": "2", "point": "B", "values": [3, 0.1]},
        {"kind": "force", "link": "2", "point": "B", "values": [1, -2]},
        {"kind": "moment", "link": "3", "point": None, "values": [5]},
        {"kind": "gravity", "link": "", "values": [0, -9.81]},
        {"kind": "balance", "link": "1", "point": "A", "values": [30]},
    ]
    parsed = parse_edgelist([*lines, *statements], "t")
    assert mechanism_from_dict(_fourbar(loads=loads), "t") == parsed


#: each limit of the exact-expression reader and the words of its reason (as in test_edgelist)
LIMIT_TEXTS = [
    pytest.param("(" * 101 + "1" + ")" * 101, "deeper than 100", id="depth"),
    pytest.param("1/" + "1" * 101, "more than 100 digits", id="digits"),
    pytest.param("1e99999999", "exponent beyond ±400", id="exponent"),
    pytest.param("1+" * 500 + "1", "longer than 1000 characters", id="length"),
]


@pytest.mark.parametrize(("text", "reason"), LIMIT_TEXTS)
def test_a_json_expression_beyond_a_limit_names_the_limit(text, reason):
    """Like the edge-list reader, the JSON reader says which limit an expression passes."""
    point = _error(_fourbar(points={"A": [text, 0]}))
    load = _error(_fourbar(loads=[{"kind": "moment", "link": "2", "values": [text]}]))
    for error in (point, load):
        assert len(error.problems) == 1 and reason in error.reason
        assert len(str(error)) < 1000


# ------------------------------------------------------------------ lossless (issue 22, item 11)
_NAMES = st.text(min_size=0, max_size=6)
_TITLES = st.text(max_size=12)


def _round_trip_document(a, b, c, point, title, kind, angle):
    pairs = [
        {"links": ["0", a], "kind": "R", "point": "A"},
        {"links": [a, b], "kind": "R", "point": point},
        {"links": [b, c], "kind": "R", "point": "C"},
        {
            "links": [c, "0"],
            "kind": kind,
            "point": "D",
            **({"angle": angle} if kind == "P" else {}),
        },
    ]
    return {
        "name": title,
        "ground": "0",
        "drivers": [{"link": a, "omega": 10}],
        "pairs": pairs,
        "points": {"A": [0, 0], point: [0, 1], "C": {"xy": ["0.2*sqrt(3)", 1], "on": b}},
        "loads": [{"kind": "force", "link": b, "point": "C", "values": [1, "500*sqrt(2)"]}],
    }


@settings(max_examples=150, deadline=None)
@given(
    a=_NAMES,
    b=_NAMES,
    c=_NAMES,
    point=_NAMES,
    title=_TITLES,
    kind=st.sampled_from(["R", "P"]),
    angle=st.floats(-1e150, 1e150, allow_nan=False),
)
def test_what_json_reads_the_edge_list_writes_and_reads_back_the_same(
    a, b, c, point, title, kind, angle
):
    """Any names: the JSON reader refuses them with a named error, or the mechanism goes
    to the edge list and back (and to JSON and back) unchanged. Issue 22: a link named
    'a b' or a point named 'a=b' was read from JSON and written as a broken edge list."""
    data = _round_trip_document(a, b, c, point, title, kind, angle)
    try:
        m = mechanism_from_dict(data)
    except EdgeListError:
        return
    expected = mechanism_to_dict(m)
    assert mechanism_to_dict(parse_edgelist(write_edgelist(m).splitlines())) == expected
    assert mechanism_to_dict(mechanism_from_json(mechanism_to_json(m))) == expected


@pytest.mark.parametrize(
    ("change", "reason"),
    [
        pytest.param({"a": "slider block"}, "link name 'slider block' is not one word", id="space"),
        pytest.param({"a": "a#b"}, "is not one word", id="hash"),
        pytest.param({"a": "a=b"}, "is not one word", id="equals"),
        pytest.param({"point": "P,Q"}, "point name 'P,Q' is not one word", id="comma"),
        pytest.param({"a": ""}, "is not one word", id="empty"),
        pytest.param({"a": "x\u2028y"}, "is not one word", id="line-separator"),
        pytest.param({"title": "four-bar #2"}, "cannot be written on a 'name' line", id="title"),
        pytest.param({"title": "two\nlines"}, "cannot be written on a 'name' line", id="title-lf"),
        pytest.param({"a": "name"}, "first link cannot be named 'name'", id="name-first"),
    ],
)
def test_names_the_edge_list_cannot_hold_are_refused_by_name(change, reason):
    base = {"a": "1", "b": "2", "c": "3", "point": "B", "title": "t", "kind": "R", "angle": 0}
    with pytest.raises(EdgeListError, match=reason):
        mechanism_from_dict(_round_trip_document(**{**base, **change}))


def test_a_gear_word_is_no_higher_pairs_point():
    data = {"pairs": [{"links": ["0", "1"], "kind": "H", "point": "gear"}]}
    with pytest.raises(EdgeListError, match="cannot be named 'gear'"):
        mechanism_from_dict(data)
