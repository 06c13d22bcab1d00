"""Tests of the edge-list reader and writer (structure.readwrite.edgelist).

Every bad description must give one EdgeListError naming the source and the
line; every valid one must survive write -> parse unchanged.
"""

from __future__ import annotations

import math
import string
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from structure.errors import EdgeListError, MechanismError
from structure.model import DRIVER_KEYS, Driver, Mechanism, PairKind, PointDef
from structure.readwrite.edgelist import parse_edgelist, read_edgelist, write_edgelist
from structure.readwrite.jsonformat import mechanism_from_json, mechanism_to_json
from structure.validation import MAX_MAGNITUDE

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
FIXTURE_FILES = sorted(FIXTURES.glob("*.edges"))

FOURBAR = ["0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]
SRC = "test.edges"


def _error(lines: list[str], source: str = SRC) -> EdgeListError:
    with pytest.raises(EdgeListError) as info:
        parse_edgelist(lines, source)
    return info.value


# ------------------------------------------------------------------ bad input, one problem
# (lines, line number of the problem, a word the reason must contain)
BAD_INPUT = [
    pytest.param(["0 1 R A", "1 2 Q B", *FOURBAR[2:]], 2, "'Q'", id="unknown-kind"),
    pytest.param(["0 1 R A", "1 2 r B", *FOURBAR[2:]], 2, "'r'", id="lowercase-kind"),
    pytest.param(["0 1 R A", "1 2", *FOURBAR[2:]], 2, "KIND", id="missing-kind"),
    pytest.param(["0 1 R A", "1", *FOURBAR[1:]], 2, "KIND", id="one-token"),
    pytest.param(
        ["0 1 R A", "1 2 R B", "2 3 P C angle=abc", "3 0 R D"], 3, "angle", id="angle-abc"
    ),
    pytest.param(
        ["0 1 R A", "1 2 R B", "2 3 P C angle=inf", "3 0 R D"], 3, "angle", id="angle-inf"
    ),
    pytest.param(
        ["0 1 R A", "1 2 R B", "2 3 P C angle=nan", "3 0 R D"], 3, "angle", id="angle-nan"
    ),
    pytest.param(["0 1 R A", "1 2 R B", "2 3 P C foo=1", "3 0 R D"], 3, "'foo'", id="unknown-key"),
    pytest.param(["0 1 R A", "1 2 R B angle=30", *FOURBAR[2:]], 2, "'angle'", id="angle-on-R"),
    pytest.param(["0 1 R A", "1 2 P B flat=2", *FOURBAR[2:]], 2, "'flat'", id="flat-on-P"),
    pytest.param(
        ["0 1 R A", "1 2 P B angle=1 angle=2", *FOURBAR[2:]], 2, "twice", id="option-twice"
    ),
    pytest.param(["0 1 R A", "1 2 R B C", *FOURBAR[2:]], 2, "'C'", id="two-points"),
    pytest.param(["0 1 R A", "1 2 P B angle=", *FOURBAR[2:]], 2, "angle=", id="empty-value"),
    pytest.param(["0 1 R A", "1 2 H K centers=a,b,c", *FOURBAR[2:]], 2, "centers", id="3-centers"),
    pytest.param(["0 1 R A", "1 2 H K centers=,", *FOURBAR[2:]], 2, "centers", id="no-centers"),
    pytest.param(["0 1 R A", "1 2 H K normal=x", *FOURBAR[2:]], 2, "normal", id="normal-x"),
    pytest.param(["0 1 R A", "1 1 R B", *FOURBAR[1:]], 2, "itself", id="self-pair"),
    pytest.param(["point A 0 0", "point A 1 1", *FOURBAR], 2, "already", id="duplicate-point"),
    pytest.param([*FOURBAR, "point A 0"], 5, "point", id="point-2-tokens"),
    pytest.param([*FOURBAR, "point A 0 0 0 0"], 5, "point", id="point-5-tokens"),
    pytest.param([*FOURBAR, "point A x 0"], 5, "finite", id="point-non-numeric"),
    pytest.param([*FOURBAR, "point A 0 inf"], 5, "finite", id="point-inf"),
    pytest.param([*FOURBAR, "point A nan 0"], 5, "finite", id="point-nan"),
    pytest.param([*FOURBAR, "point A 0 0 at=2"], 5, "at=2", id="point-bad-key"),
    pytest.param([*FOURBAR, "point A 0 0 on=9"], 5, "9", id="point-on-unknown-link"),
    pytest.param(["ground 0", "ground 1", *FOURBAR], 2, "ground", id="ground-twice"),
    pytest.param(["ground", *FOURBAR], 1, "ground", id="ground-no-link"),
    pytest.param(["ground 0 1", *FOURBAR], 1, "ground", id="ground-two-links"),
    pytest.param(["driver 9", *FOURBAR], 1, "9", id="driver-not-a-link"),
    pytest.param(["driver 2", *FOURBAR], 1, "2", id="driver-not-on-ground"),
    pytest.param(["driver 0", *FOURBAR], 1, "ground", id="driver-is-ground"),
    pytest.param(["driver 1", "driver 1", *FOURBAR], 2, "twice", id="driver-twice"),
    pytest.param(["driver", *FOURBAR], 1, "driver", id="driver-no-link"),
    pytest.param(["driver 1 3", *FOURBAR], 1, "'3'", id="two-drivers-one-line"),
    pytest.param(["driver 1 speed=3", *FOURBAR], 1, "'speed'", id="driver-unknown-key"),
    pytest.param(["driver 1 omega=fast", *FOURBAR], 1, "omega", id="driver-omega-text"),
    pytest.param(["driver 1 omega=inf", *FOURBAR], 1, "omega", id="driver-omega-inf"),
    pytest.param(
        ["0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D", "4 5 R E"], 5, "4, 5", id="loose-links"
    ),
    pytest.param(["ground 7", *FOURBAR], 1, "7", id="ground-joined-to-nothing"),
    pytest.param(
        ["0 1 R A", "1 2 R B", "2 3 R B", "3 1 R B", "3 0 R D"], 4, "cycle", id="hinge-cycle"
    ),
    pytest.param(["0 1 R A", "1 2 R B", "3 4 R B", "2 3 R C", "4 0 R D"], 2, "B", id="hinge-split"),
    pytest.param(["0 1 R A", "1 2 R B", "1 2 R B", "2 0 R C"], 3, "cycle", id="hinge-double-pair"),
    pytest.param(["0 1 R A", "1 2 H K flat=3", "2 0 R C"], 2, "flat=3", id="flat-not-own"),
    pytest.param(["0 1 R A", "1 2 H K roller=0", "2 0 R C"], 2, "roller=0", id="roller-not-own"),
    pytest.param(
        ["0 1 R A", "1 2 H K flat=2 roller=2", "2 0 R C"], 2, "both", id="flat-and-roller"
    ),
]


@pytest.mark.parametrize(("lines", "line_no", "word"), BAD_INPUT)
def test_bad_input_gives_one_problem_naming_source_and_line(lines, line_no, word):
    error = _error(lines)
    assert isinstance(error, MechanismError)
    assert isinstance(error, ValueError)
    assert len(error.problems) == 1, error.problems
    assert error.line_no == line_no
    assert error.problems[0].line_no == line_no
    assert error.source == SRC
    assert word in error.reason
    message = str(error)
    assert SRC in message
    assert f"line {line_no}" in message


# The problems found only once the whole file is read (topology) must still carry
# the text of the line they come from, like the ones found while reading it.
LINE_TEXT = [
    pytest.param(["driver 9", *FOURBAR], "driver 9", id="driver-not-a-link"),
    pytest.param(["driver 2", *FOURBAR], "driver 2", id="driver-not-on-ground"),
    pytest.param(
        ["0 1 R A", "1 2 R B", "2 3 R B", "3 1 R B", "3 0 R D"], "3 1 R B", id="hinge-cycle"
    ),
    pytest.param(
        ["0 1 R A", "1 2 R B", "3 4 R B", "2 3 R C", "4 0 R D"], "1 2 R B", id="hinge-split"
    ),
    pytest.param(["0 1 R A", "1 2 H K flat=3", "2 0 R C"], "1 2 H K flat=3", id="flat-not-own"),
    pytest.param([*FOURBAR, "point A 0 0 on=9"], "point A 0 0 on=9", id="point-on-unknown"),
]


#: each limit of the exact-expression reader, and the words its own reason uses
#: (structure.expressions: MAX_DEPTH 100, MAX_DIGITS 100, MAX_EXPONENT 400, MAX_LENGTH 1000)
LIMIT_TOKENS = [
    pytest.param("(" * 101 + "1" + ")" * 101, "deeper than 100", id="depth"),
    pytest.param("-" * 101 + "1", "deeper than 100", id="depth-of-signs"),
    pytest.param("1/" + "1" * 101, "more than 100 digits", id="digits"),
    pytest.param("1e99999999", "exponent beyond ±400", id="exponent"),
    pytest.param("1+" * 500 + "1", "longer than 1000 characters", id="length"),
]


@pytest.mark.parametrize(("token", "reason"), LIMIT_TOKENS)
@pytest.mark.parametrize(
    "line", ["point Z {} 0", "point Z 0 {}", "force 2 B {} 0", "mass 2 {} 0.1 B", "moment 2 {}"]
)
def test_an_expression_beyond_a_limit_is_refused_with_the_limit_it_passes(line, token, reason):
    """The edge-list reader names the limit, not only that numbers must be finite (issue 11)."""
    error = _error([*FOURBAR, line.format(token)])
    assert len(error.problems) == 1 and error.line_no == 5
    assert reason in error.reason
    assert len(str(error)) < 1000


@pytest.mark.parametrize(("lines", "text"), LINE_TEXT)
def test_topology_problem_quotes_its_line(lines, text):
    error = _error(lines)
    assert error.line.strip() == text
    assert repr(text) in str(error)


@pytest.mark.parametrize(
    "lines",
    [
        pytest.param([], id="empty"),
        pytest.param(["", "   ", "\t"], id="blank"),
        pytest.param(["# a comment", "   # another", "#"], id="comments-only"),
        pytest.param(["name just a title", "ground 0", "# no pairs"], id="no-pairs"),
    ],
)
def test_description_without_pairs_is_rejected(lines):
    error = _error(lines)
    assert len(error.problems) == 1
    assert error.line_no == 0
    assert str(error).startswith(f"{SRC}: ")
    assert "pair" in error.reason


# ------------------------------------------------------------------ several problems
@pytest.mark.parametrize(
    ("lines", "expected_lines"),
    [
        pytest.param(["0 1 R A", "1 2 Q B", "2 3 R C", "3 0 X D"], [2, 4], id="two-bad-pairs"),
        pytest.param(
            [
                "ground 0",
                "0 1 R A",
                "ground 1",
                "1 2",
                "point A 0",
                "2 3 R C",
                "3 0 R D",
                "driver 1 speed=1",
                "point B 1 1",
                "point B 2 2",
            ],
            [3, 4, 5, 8, 10],
            id="every-statement-kind",
        ),
        pytest.param(
            ["0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D", "driver 9", "point M 0 0 on=7"],
            [5, 6],
            id="two-topology-problems",
        ),
    ],
)
def test_every_problem_is_reported_in_file_order(lines, expected_lines):
    error = _error(lines)
    assert [p.line_no for p in error.problems] == expected_lines
    message = str(error)
    for n in expected_lines:
        assert f"{SRC}: line {n}: " in message
    positions = [message.index(f"line {n}: ") for n in expected_lines]
    assert positions == sorted(positions)


def test_problems_of_different_checks_keep_file_order():
    # the driver on line 1 is not joined to the ground; the hinge at B closes a
    # cycle on line 5: the file order is line 1, then line 5
    lines = ["driver 2", "0 1 R A", "1 2 R B", "2 3 R B", "3 1 R B", "3 0 R D"]
    error = _error(lines)
    assert [p.line_no for p in error.problems] == [1, 5]
    assert error.line_no == 1


def test_message_is_capped_but_problems_are_all_kept():
    bad = 25
    lines = [*FOURBAR, *(f"{k} {k + 1} Q" for k in range(bad))]
    error = _error(lines)
    assert len(error.problems) == bad
    assert [p.line_no for p in error.problems] == list(range(5, 5 + bad))
    message_lines = str(error).splitlines()
    assert len(message_lines) == EdgeListError.MAX_SHOWN + 1
    assert f"{bad - EdgeListError.MAX_SHOWN} more" in message_lines[-1]


# ------------------------------------------------------------------ files
def test_read_missing_file_is_an_edgelist_error(tmp_path):
    path = tmp_path / "nowhere.edges"
    with pytest.raises(EdgeListError) as info:
        read_edgelist(path)
    assert not isinstance(info.value, OSError)
    assert info.value.source == str(path)
    assert str(path) in str(info.value)


def test_read_directory_is_an_edgelist_error(tmp_path):
    with pytest.raises(EdgeListError):
        read_edgelist(tmp_path)


@pytest.mark.parametrize("suffix", [".edges", ".json"])
def test_read_non_utf8_file_is_an_edgelist_error(tmp_path, suffix):
    path = tmp_path / f"latin1{suffix}"
    path.write_bytes("name Kurbelschwinge \u00fcber\n0 1 R A\n".encode("latin-1"))
    with pytest.raises(EdgeListError) as info:
        read_edgelist(path)
    assert "UTF-8" in str(info.value)
    assert str(path) in str(info.value)


def test_read_utf8_file_with_byte_order_mark(tmp_path):
    text = "name four-bar\n" + "\n".join(FOURBAR) + "\n"
    plain, bom = tmp_path / "plain.edges", tmp_path / "bom.edges"
    plain.write_text(text, encoding="utf-8")
    bom.write_text(text, encoding="utf-8-sig")
    assert read_edgelist(bom) == read_edgelist(plain).evolve(source=str(bom))


def test_read_file_names_its_path_as_source(tmp_path):
    path = tmp_path / "four.edges"
    path.write_text("\n".join(["# four-bar", *FOURBAR, "0 1 Q"]) + "\n", encoding="utf-8")
    with pytest.raises(EdgeListError) as info:
        read_edgelist(path)
    assert info.value.line_no == 6
    assert str(info.value).startswith(f"{path}: line 6: ")


def test_read_json_file_by_suffix(tmp_path):
    m = parse_edgelist(["driver 1 omega=5", *FOURBAR, "point A 0 0"])
    path = tmp_path / "four.json"
    path.write_text(mechanism_to_json(m), encoding="utf-8")
    assert read_edgelist(path) == m.evolve(source=str(path))


def test_million_line_file_reports_the_bad_line(tmp_path):
    total, bad_line = 1_000_000, 999_999
    head = ["name long file", "driver 1", *FOURBAR]
    filler = total - len(head) - 2
    path = tmp_path / "long.edges"
    with path.open("w", encoding="utf-8") as out:
        out.write("\n".join(head) + "\n")
        out.write("# filler\n\n" * (filler // 2) + "# filler\n" * (filler % 2))
        out.write("1 2 R B angle=10\n")
        out.write("# last line\n")
    with pytest.raises(EdgeListError) as info:
        read_edgelist(path)
    assert len(info.value.problems) == 1
    assert info.value.line_no == bad_line
    assert f"line {bad_line}: " in str(info.value)


def test_million_line_valid_file(tmp_path):
    # a chain of RRR dyads: each one adds links u, v with pairs prev-u, u-v, v-0
    dyads = 20_000
    lines = ["ground 0", "driver 1 omega=1", "0 1 R A"]
    prev = "1"
    for i in range(dyads):
        lines += [f"{prev} u{i} R", f"u{i} v{i} R", f"v{i} 0 R"]
        prev = f"v{i}"
    total = 1_000_000
    path = tmp_path / "chain.edges"
    path.write_text("\n".join(lines) + "\n" + "# padding\n" * (total - len(lines)), "utf-8")
    m = read_edgelist(path)
    assert len(m.pairs) == 1 + 3 * dyads
    assert len(m.moving_links) == 1 + 2 * dyads
    assert m.pairs[-1].line_no == len(lines)
    assert (m.pairs[-1].a, m.pairs[-1].b) == (f"v{dyads - 1}", "0")


# ------------------------------------------------------------------ valid input
def test_comments_blank_lines_and_spacing_are_ignored():
    lines = [
        "# a four-bar",
        "",
        "name   four-bar crank rocker   # the title",
        "   ",
        "driver 1   omega=20 epsilon=0   # crank",
        "\t0 1 R A\t# crank pivot",
        "1  2 R   B",
        "# between pairs",
        "2 3 R C\r\n",
        "3 0 R D #",
        "point A 0 0 # origin",
    ]
    m = parse_edgelist(lines)
    assert m.name == "four-bar crank rocker"
    assert m.ground == "0"
    assert m.drivers == (Driver("1", (("omega", 20.0), ("epsilon", 0.0)), line_no=5),)
    assert [(p.a, p.b, p.point) for p in m.pairs] == [
        ("0", "1", "A"),
        ("1", "2", "B"),
        ("2", "3", "C"),
        ("3", "0", "D"),
    ]
    assert [p.line_no for p in m.pairs] == [6, 7, 9, 10]
    assert [p.id for p in m.pairs] == [1, 2, 3, 4]
    assert m.points["A"].line_no == 11


def test_default_ground_is_0_and_other_ground_is_kept():
    assert parse_edgelist(FOURBAR).ground == "0"
    m = parse_edgelist(["ground F", "F 1 R A", "1 2 R B", "2 3 R C", "3 F R D", "driver 3"])
    assert m.ground == "F"
    assert m.moving_links == ("1", "2", "3")
    assert m.driver_links == ("3",)


def test_primed_link_names():
    m = parse_edgelist(["0 1 R A", "1 2' R B", "2' 2 R C", "2 0 R D", "driver 1"])
    assert m.moving_links == ("1", "2'", "2")
    assert m.pairs[1].links == ("1", "2'")


def test_statement_words_may_name_links_in_a_pair():
    # a point, driver or ground statement never has R, P or H as its third word,
    # so such a line is a pair; ``name`` is left out: its line is a free title
    m = parse_edgelist(["0 point R A", "point driver R B", "driver ground P", "ground 0 R C"])
    assert m.moving_links == ("point", "driver", "ground")
    assert [p.kind for p in m.pairs] == [PairKind.R, PairKind.R, PairKind.P, PairKind.R]
    assert m.ground == "0"
    assert m.drivers == ()


def test_title_with_a_pair_kind_word_is_a_title():
    m = parse_edgelist(["name Type R linkage", *FOURBAR])
    assert m.name == "Type R linkage"
    assert len(m.pairs) == 4


def test_title_with_a_pair_kind_word_survives_writing():
    m = Mechanism.from_pairs([tuple(line.split()) for line in FOURBAR], name="Type R linkage")
    again = parse_edgelist(write_edgelist(m).splitlines())
    assert again.name == "Type R linkage"
    assert [p.links for p in again.pairs] == [p.links for p in m.pairs]


def test_revolute_pairs_at_one_point_form_one_hinge():
    # Jansen-style: M joins 1, 2, 3; Z joins 0, 4, 5; A and D are simple pins
    lines = [
        "0 1 R O",
        "1 2 R M",
        "1 3 R M",
        "0 4 R Z",
        "0 5 R Z",
        "2 4 R A",
        "3 5 R C",
        "4 6 R",
        "6 0 P E angle=0",
    ]
    m = parse_edgelist(lines)
    hinges = {h.point: h for h in m.hinges}
    assert len(m.hinges) == 6  # O, M, Z, A, C and the unnamed 4-6 pin
    assert set(hinges["M"].links) == {"1", "2", "3"}
    assert hinges["M"].pairs == (2, 3)
    assert set(hinges["Z"].links) == {"0", "4", "5"}
    assert hinges["Z"].pairs == (4, 5)
    assert hinges["O"].pairs == (1,)
    assert "E" not in hinges  # a P pair is no hinge
    unnamed = [h for h in m.hinges if h.point not in {"O", "M", "Z", "A", "C"}]
    assert [set(h.links) for h in unnamed] == [{"4", "6"}]
    assert all(len(h.pairs) == len(h.links) - 1 for h in m.hinges)


@pytest.mark.parametrize(
    ("text", "degrees"),
    [("0", 0.0), ("90", 90.0), ("-30", -30.0), ("45.5", 45.5), ("1e1", 10.0), ("360", 360.0)],
)
def test_prismatic_angle_in_degrees_and_radians(text, degrees):
    m = parse_edgelist(["0 1 R A", "1 2 R B", f"2 0 P C angle={text}"])
    pair = m.pairs[2]
    assert pair.kind is PairKind.P
    assert pair.angle_deg == degrees
    assert pair.angle == pytest.approx(degrees * math.pi / 180)


def test_prismatic_without_angle():
    pair = parse_edgelist(["0 1 R A", "1 2 R B", "2 0 P"]).pairs[2]
    assert (pair.point, pair.angle_deg, pair.angle) == (None, None, None)


@pytest.mark.parametrize(
    ("options", "flat", "roller", "centers", "normal"),
    [
        ("", None, None, None, None),
        ("flat=2", "2", None, None, None),
        ("roller=2", None, "2", None, None),
        ("flat=1 roller=2", "1", "2", None, None),
        ("centers=O1,O2", None, None, ("O1", "O2"), None),
        ("centers=O1,", None, None, ("O1", None), None),
        ("centers=,O2", None, None, (None, "O2"), None),
        ("normal=90", None, None, None, 90.0),
        ("flat=2 centers=O1, normal=-45", "2", None, ("O1", None), -45.0),
    ],
)
def test_higher_pair_options(options, flat, roller, centers, normal):
    m = parse_edgelist(["0 1 R O", "0 2 R Q", f"1 2 H K {options}"])
    pair = m.pairs[2]
    assert pair.kind is PairKind.H
    assert pair.point == "K"
    assert (pair.flat, pair.roller, pair.centers, pair.normal_deg) == (
        flat,
        roller,
        centers,
        normal,
    )
    if normal is None:
        assert pair.normal is None
    else:
        assert pair.normal == pytest.approx(math.radians(normal))
    if centers is not None:
        assert pair.center_of("1") == centers[0]
        assert pair.center_of("2") == centers[1]


@pytest.mark.parametrize(
    ("line", "motion"),
    [
        ("driver 1", ()),
        ("driver 1 omega=20", (("omega", 20.0),)),
        ("driver 1 omega=20 epsilon=0", (("omega", 20.0), ("epsilon", 0.0))),
        ("driver 1 epsilon=-3.5 omega=2", (("epsilon", -3.5), ("omega", 2.0))),
        ("driver 1 v=0.5 a=1e-3", (("v", 0.5), ("a", 0.001))),
    ],
)
def test_driver_motion(line, motion):
    m = parse_edgelist([line, *FOURBAR])
    assert m.drivers == (Driver("1", motion, line_no=1),)
    assert m.driver_links == ("1",)


@pytest.mark.parametrize(
    ("line", "point"),
    [
        ("point M 0.1 0.2 on=2", PointDef("M", 0.1, 0.2, "2", 5)),
        ("point M -1 2e-3", PointDef("M", -1.0, 0.002, None, 5)),
        ("point M 0 0 on=0", PointDef("M", 0.0, 0.0, "0", 5)),
    ],
)
def test_points(line, point):
    m = parse_edgelist([*FOURBAR, line])
    assert dict(m.points) == {"M": point}
    assert m.coordinates("M") == (point.x, point.y)
    assert m.coordinates("N") is None


# ------------------------------------------------------------------ round trips
def test_line_numbers_do_not_change_equality():
    plain = parse_edgelist(["driver 1", *FOURBAR, "point A 0 0"], SRC)
    commented = parse_edgelist(["# four-bar", "", "driver 1", *FOURBAR, "point A 0 0"], SRC)
    assert commented == plain


@pytest.mark.parametrize("path", FIXTURE_FILES, ids=[p.stem for p in FIXTURE_FILES])
def test_fixture_round_trip_through_edge_list(path):
    m = read_edgelist(path)
    text = write_edgelist(m)
    again = parse_edgelist(text.splitlines(), source=m.source)
    assert again == m
    assert write_edgelist(again) == text


@pytest.mark.parametrize("path", FIXTURE_FILES, ids=[p.stem for p in FIXTURE_FILES])
def test_fixture_round_trip_through_json(path):
    m = read_edgelist(path)
    assert mechanism_from_json(mechanism_to_json(m), source=m.source) == m
    assert mechanism_from_json(mechanism_to_json(m, indent=None), source=m.source) == m


def test_from_pairs_equals_parsed_file():
    text = """\
# cam with a flat follower and a crank-slider beside it
name cam and slider
ground 0
driver 1 omega=20 epsilon=0
0 1 R O
0 2 P Q angle=90
1 2 H K flat=2 centers=C1, normal=90
1 3 R B
3 4 R C
4 0 P C angle=0
point O 0 0
point K 0 0.05
point M 0.1 0.2 on=3
"""
    parsed = parse_edgelist(text.splitlines(), source="cam.edges")
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
        points=[
            PointDef("O", 0.0, 0.0),
            PointDef("K", 0.0, 0.05),
            PointDef("M", 0.1, 0.2, on="3"),
        ],
        name="cam and slider",
        source="cam.edges",
    )
    assert built == parsed


# ------------------------------------------------------------------ property test
NAME_CHARS = string.ascii_letters + string.digits + "_'"
# a link called "name" cannot start a pair line (that line is a title), and a point called
# "gear" on an H pair would read as the gear-mesh keyword
names = st.text(NAME_CHARS, min_size=1, max_size=4).filter(lambda s: s not in ("name", "gear"))
# the readers take numbers within ±MAX_MAGNITUDE (1e150, issue 11)
finite = st.floats(-MAX_MAGNITUDE, MAX_MAGNITUDE, allow_nan=False, allow_infinity=False)


@st.composite
def descriptions(draw):
    """A valid edge-list description and what it should parse to."""
    links = draw(st.lists(names, min_size=2, max_size=8, unique=True))
    ground, moving = links[0], links[1:]
    hinges: dict[str, set[str]] = {}
    pairs: list[dict] = []

    def add_pair(a: str, b: str) -> None:
        kind = draw(st.sampled_from("RPH"))
        spec = {
            "a": a,
            "b": b,
            "kind": kind,
            "point": None,
            "angle": None,
            "flat": None,
            "roller": None,
            "centers": None,
            "normal": None,
        }
        if kind == "R":
            shareable = sorted(p for p, ls in hinges.items() if (a in ls) != (b in ls))
            how = draw(st.sampled_from(["none", "new", "share"]))
            if how == "share" and shareable:
                spec["point"] = draw(st.sampled_from(shareable))
            elif how != "none":
                spec["point"] = draw(names.filter(lambda p: p not in hinges))
            if spec["point"] is not None:
                hinges.setdefault(spec["point"], set()).update((a, b))
        else:
            spec["point"] = draw(st.none() | names)
        if kind == "P":
            spec["angle"] = draw(st.none() | finite)
        if kind == "H":
            spec["flat"] = draw(st.sampled_from([None, a, b]))
            spec["roller"] = draw(
                st.sampled_from([x for x in (None, a, b) if x != spec["flat"] or x is None])
            )
            centers = draw(st.none() | st.tuples(st.none() | names, st.none() | names))
            spec["centers"] = None if centers == (None, None) else centers
            spec["normal"] = draw(st.none() | finite)
        pairs.append(spec)

    for i, b in enumerate(moving):  # a spanning tree keeps every link joined to the ground
        a = draw(st.sampled_from([ground, *moving[:i]]))
        add_pair(*draw(st.sampled_from([(a, b), (b, a)])))
    for _ in range(draw(st.integers(0, 4))):
        a, b = draw(st.lists(st.sampled_from(links), min_size=2, max_size=2, unique=True))
        add_pair(a, b)

    on_ground = sorted(
        {p["a"] if p["b"] == ground else p["b"] for p in pairs if ground in (p["a"], p["b"])}
    )
    drivers = {
        link: tuple(
            draw(
                st.lists(
                    st.tuples(st.sampled_from(DRIVER_KEYS), finite),
                    max_size=4,
                    unique_by=lambda kv: kv[0],
                )
            )
        )
        for link in draw(st.lists(st.sampled_from(on_ground), max_size=3, unique=True))
    }
    points = draw(
        st.dictionaries(
            names, st.tuples(finite, finite, st.none() | st.sampled_from(links)), max_size=5
        )
    )
    words = st.text(string.ascii_letters + string.digits + "-", min_size=2, max_size=6)
    title = " ".join(draw(st.lists(words, max_size=4)))

    def fmt(x: float) -> str:
        return repr(x)

    pair_lines = []
    for p in pairs:
        tokens = [p["a"], p["b"], p["kind"]]
        if p["point"] is not None:
            tokens.append(p["point"])
        if p["angle"] is not None:
            tokens.append(f"angle={fmt(p['angle'])}")
        if p["flat"] is not None:
            tokens.append(f"flat={p['flat']}")
        if p["roller"] is not None:
            tokens.append(f"roller={p['roller']}")
        if p["centers"] is not None:
            tokens.append("centers=" + ",".join(c or "" for c in p["centers"]))
        if p["normal"] is not None:
            tokens.append(f"normal={fmt(p['normal'])}")
        pair_lines.append(" ".join(tokens))
    other = [f"ground {ground}"] if ground != "0" or draw(st.booleans()) else []
    if title:
        other.append(f"name {title}")
    for link, motion in drivers.items():
        other.append(" ".join(["driver", link, *(f"{k}={fmt(v)}" for k, v in motion)]))
    for name, (x, y, on) in points.items():
        other.append(f"point {name} {fmt(x)} {fmt(y)}" + (f" on={on}" if on else ""))
    lines = list(pair_lines)
    for line in other:  # statements other than pairs may stand anywhere
        lines.insert(draw(st.integers(0, len(lines))), line)
    decorated = []
    for line in lines:
        if draw(st.booleans()):
            decorated.append(draw(st.sampled_from(["", "# comment", "   "])))
        decorated.append(line + draw(st.sampled_from(["", "  # note", "\t"])))
    expected = {
        "ground": ground,
        "name": title,
        "pairs": pairs,
        "drivers": drivers,
        "points": points,
    }
    return decorated, expected


def _check_parsed(m: Mechanism, expected: dict) -> None:
    assert m.ground == expected["ground"]
    assert m.name == expected["name"]
    got = [
        {
            "a": p.a,
            "b": p.b,
            "kind": p.kind.value,
            "point": p.point,
            "angle": p.angle_deg,
            "flat": p.flat,
            "roller": p.roller,
            "centers": p.centers,
            "normal": p.normal_deg,
        }
        for p in m.pairs
    ]
    assert got == expected["pairs"]
    assert {d.link: d.motion for d in m.drivers} == expected["drivers"]
    assert {k: (p.x, p.y, p.on) for k, p in m.points.items()} == expected["points"]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(descriptions())
def test_random_description_parses_as_written(description):
    lines, expected = description
    _check_parsed(parse_edgelist(lines, SRC), expected)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(descriptions())
def test_random_description_round_trip(description):
    lines, _ = description
    m = parse_edgelist(lines, SRC)
    assert parse_edgelist(write_edgelist(m).splitlines(), SRC) == m
    assert mechanism_from_json(mechanism_to_json(m), SRC) == m


@pytest.mark.parametrize(
    ("line", "reason"),
    [
        ("0 1 R a=b", "unknown option 'a' for a R pair (allowed: circle)"),
        ("0 1 R A b=2", "unknown option 'b' for a R pair"),
        ("0 1 P C point=x", "unknown option 'point' for a P pair"),
        ("0 1 H K line_no=3", "unknown option 'line_no' for a H pair"),
        ("0 1 R A gear=1", "unknown option 'gear' for a R pair"),
        ("0 1 R A kind=P", "unknown option 'kind'"),
        ("0 1 R A pair_id=9", "unknown option 'pair_id'"),
        ("0 0 R a=b", "pair joins link 0 to itself"),
    ],
)
def test_an_option_named_like_a_pairs_own_field_is_an_unknown_option(line, reason):
    """Issue 22: ``0 1 R a=b`` reached make_pair as a second value of ``a`` (TypeError, exit 3)."""
    with pytest.raises(EdgeListError) as info:
        parse_edgelist([line])
    assert info.value.line_no == 1 and reason in info.value.reason
