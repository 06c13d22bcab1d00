"""``assur classify`` (kinematics.cli.classify): text, JSON, drivers and mechanism errors."""

from __future__ import annotations

import json

import pytest

from structure.readwrite.edgelist import read_edgelist
from structure.readwrite.jsonformat import mechanism_to_json

from .conftest import fixture, run


def run_json(capsys, *argv: str) -> dict:
    code, out, err = run(capsys, "classify", *argv, "--json")
    assert code == 0, err
    return json.loads(out)


# ------------------------------------------------------------------ text report
# W = 3n − (2·P5 + P4) + r − W_passive, counted by hand from each fixture:
#   four-bar: n = 3 (1, 2, 3), P5 = 4 pins
#   crank-slider: n = 3, P5 = 3 pins + 1 slider
#   Stephenson: n = 5, P5 = 7 pins
#   cam with roller: n = 3 (cam, arm, roller), P5 = 3, P4 = 1, the roller's spin is passive
#   gear pair: n = 2, P5 = 2 axles, P4 = 1 mesh
#   five-bar: n = 4, P5 = 5 pins, two drivers
TEXT_REPORTS = [
    ("fourbar", "W = 3·3 − (2·4 + 0) + 0 − 0 = 1", "I(1) → II(2,3)", "II"),
    ("crank_slider", "W = 3·3 − (2·4 + 0) + 0 − 0 = 1", "I(1) → II(2,3)", "II"),
    ("stephenson_sixbar", "W = 3·5 − (2·7 + 0) + 0 − 0 = 1", "I(1) → III(2,3,4,5)", "III"),
    ("cam_roller_follower", "W = 3·3 − (2·3 + 1) + 0 − 1 = 1", None, "II"),
    ("gear_pair", "W = 3·2 − (2·2 + 1) + 0 − 0 = 1", None, "II"),
    ("fivebar_two_drivers", "W = 3·4 − (2·5 + 0) + 0 − 0 = 2", "I(1) → I(4) → II(2,3)", "II"),
]


@pytest.mark.parametrize(("name", "w_line", "formula", "klass"), TEXT_REPORTS)
def test_text_report(capsys, name, w_line, formula, klass):
    code, out, err = run(capsys, "classify", fixture(name))
    assert code == 0, err
    assert err == ""
    lines = out.splitlines()
    assert w_line in lines
    assert f"Mechanism class: {klass}" in lines
    formula_lines = [line for line in lines if line.startswith("Structural formula: ")]
    assert len(formula_lines) == 1
    if formula is not None:
        assert formula_lines[0] == f"Structural formula: {formula}"


# ------------------------------------------------------------------ JSON report
# Groups are derived by hand: with crank 1 driven, links 2 and 3 of the four-bar
# form one RRR dyad; in the crank-slider the dyad 2-3 has pins B, C and the slider
# P pair to the frame, read outer-middle-outer R, R, P. After replacing the cam
# contact (roller removed, one virtual link with two pins) and the gear mesh
# (virtual link N1-N2) each is a four-bar: 3 moving links, 4 lower pairs.
JSON_REPORTS = [
    pytest.param(
        "fourbar",
        {
            "n": 3,
            "P5": 4,
            "P4": 0,
            "redundant": 0,
            "passive": 0,
            "W": 1,
            "replaced": {"n": 3, "P5": 4, "P4": 0},
            "mechanism_class": 2,
            "formula": "I(1) → II(2,3)",
        },
        [(["2", "3"], 2, 2, "RRR")],
        id="fourbar",
    ),
    pytest.param(
        "crank_slider",
        {
            "n": 3,
            "P5": 4,
            "P4": 0,
            "redundant": 0,
            "passive": 0,
            "W": 1,
            "replaced": {"n": 3, "P5": 4, "P4": 0},
            "mechanism_class": 2,
            "formula": "I(1) → II(2,3)",
        },
        [(["2", "3"], 2, 2, "RRP")],
        id="crank_slider",
    ),
    pytest.param(
        "stephenson_sixbar",
        {
            "n": 5,
            "P5": 7,
            "P4": 0,
            "redundant": 0,
            "passive": 0,
            "W": 1,
            "replaced": {"n": 5, "P5": 7, "P4": 0},
            "mechanism_class": 3,
            "formula": "I(1) → III(2,3,4,5)",
        },
        [(["2", "3", "4", "5"], 3, 3, None)],
        id="stephenson_sixbar",
    ),
    pytest.param(
        "cam_roller_follower",
        {
            "n": 3,
            "P5": 3,
            "P4": 1,
            "redundant": 0,
            "passive": 1,
            "W": 1,
            "replaced": {"n": 3, "P5": 4, "P4": 0},
            "mechanism_class": 2,
        },
        None,
        id="cam_roller_follower",
    ),
    pytest.param(
        "gear_pair",
        {
            "n": 2,
            "P5": 2,
            "P4": 1,
            "redundant": 0,
            "passive": 0,
            "W": 1,
            "replaced": {"n": 3, "P5": 4, "P4": 0},
            "mechanism_class": 2,
        },
        None,
        id="gear_pair",
    ),
]


@pytest.mark.parametrize(("name", "expected", "groups"), JSON_REPORTS)
def test_json_report(capsys, name, expected, groups):
    code, out, err = run(capsys, "classify", fixture(name), "--json")
    assert code == 0, err
    report = json.loads(out)  # exactly one JSON object, nothing else on stdout
    assert isinstance(report, dict)
    for key in (
        "n",
        "P5",
        "P4",
        "redundant",
        "passive",
        "W",
        "replaced",
        "groups",
        "mechanism_class",
        "formula",
    ):
        assert key in report
    for key, value in expected.items():
        if key == "replaced":
            assert {k: report[key][k] for k in value} == value
        else:
            assert report[key] == value, key
    for group in report["groups"]:
        assert {"links", "class", "order", "kind"} <= set(group)
    if groups is not None:
        got = [(sorted(g["links"]), g["class"], g["order"], g["kind"]) for g in report["groups"]]
        assert got == groups


def test_json_and_edge_list_files_give_the_same_report(capsys, tmp_path):
    path = tmp_path / "fourbar.json"
    path.write_text(mechanism_to_json(read_edgelist(fixture("fourbar"))), encoding="utf-8")
    from_edges = run_json(capsys, fixture("fourbar"))
    from_json = run_json(capsys, str(path))
    del from_edges["source"], from_json["source"]
    assert from_json == from_edges


# ------------------------------------------------------------------ drivers
@pytest.mark.parametrize(
    ("name", "drivers", "groups", "klass"),
    [
        # driving the rocker 3 of the four-bar leaves the dyad 1-2
        pytest.param("fourbar", ["3"], [["1", "2"]], 2, id="fourbar-rocker"),
        # THEORY.md §1: driving a rocker of the Stephenson chain gives two dyads,
        # first the one on the driven rocker, then the crank side 1-2
        pytest.param("stephenson_sixbar", ["4"], [["3", "5"], ["1", "2"]], 2, id="sixbar-4"),
        pytest.param("stephenson_sixbar", ["5"], [["3", "4"], ["1", "2"]], 2, id="sixbar-5"),
        pytest.param("stephenson_sixbar", ["1"], [["2", "3", "4", "5"]], 3, id="sixbar-1"),
    ],
)
def test_driver_option_overrides_the_file(capsys, name, drivers, groups, klass):
    args = [a for d in drivers for a in ("--driver", d)]
    report = run_json(capsys, fixture(name), *args)
    assert report["drivers"] == drivers
    assert report["drivers_chosen"] is False
    assert [sorted(g["links"]) for g in report["groups"]] == groups
    assert report["mechanism_class"] == klass


def test_fourbar_driven_by_rocker_in_text(capsys):
    code, out, _ = run(capsys, "classify", fixture("fourbar"), "--driver", "3")
    assert code == 0
    assert "Structural formula: I(3) → II(1,2)" in out.splitlines()


def test_all_drivers_lists_every_choice(capsys):
    # links joined to the frame: 1, 4 and 5; THEORY.md §1: driver 1 gives the
    # class III triad, a driven rocker 4 or 5 gives two class II dyads
    report = run_json(capsys, fixture("stephenson_sixbar"), "--all-drivers")
    choices = {tuple(c["drivers"]): c["mechanism_class"] for c in report["driver_choices"]}
    assert len(choices) > 1
    assert {2, 3} <= set(choices.values())
    assert choices == {("1",): 3, ("4",): 2, ("5",): 2}
    assert report["mechanism_class"] == 3  # the file's own driver is still reported


def test_all_drivers_in_text(capsys):
    code, out, _ = run(capsys, "classify", fixture("stephenson_sixbar"), "--all-drivers")
    assert code == 0
    section = out.split("Every admissible choice of drivers:")[1].splitlines()
    choices = [line.strip() for line in section if line.strip()]
    assert len(choices) == 3
    assert any("class III" in line for line in choices)
    assert any("class II " in line for line in choices)


# ------------------------------------------------------------------ mechanism errors: exit 1
def test_bad_file_exits_1_with_message_on_stderr(capsys, tmp_path):
    path = tmp_path / "bad.edges"
    path.write_text("0 1 R A\n1 2 Q B\n2 0 R C\n", encoding="utf-8")
    code, out, err = run(capsys, "classify", str(path))
    assert code == 1
    assert out == ""
    assert str(path) in err
    assert "line 2" in err
    assert "'Q'" in err
    assert "Traceback" not in err


@pytest.mark.parametrize(
    "content",
    [
        pytest.param(None, id="missing"),
        pytest.param(b"", id="empty"),
        pytest.param("0 1 R A\n# \u00fcber\n".encode("latin-1"), id="not-utf8"),
        pytest.param(b'{"pairs": 3}', id="json-shape"),
    ],
)
def test_unreadable_file_exits_1(capsys, tmp_path, content):
    path = tmp_path / ("m.json" if content and content.startswith(b"{") else "m.edges")
    if content is not None:
        path.write_bytes(content)
    code, out, err = run(capsys, "classify", str(path))
    assert code == 1
    assert out == ""
    assert str(path) in err
    assert "Traceback" not in err


def test_bad_file_with_json_prints_an_error_object(capsys, tmp_path):
    path = tmp_path / "bad.edges"
    path.write_text("0 1 R A\n1 2 Q B\n", encoding="utf-8")
    code, out, _ = run(capsys, "classify", str(path), "--json")
    assert code == 1
    assert "line 2" in json.loads(out)["error"]


@pytest.mark.parametrize(
    ("name", "drivers", "w"),
    [
        pytest.param("fourbar", ["1", "3"], 1, id="fourbar-two-drivers"),
        pytest.param("fivebar_two_drivers", ["1"], 2, id="fivebar-one-driver"),
    ],
)
def test_driver_count_different_from_w_exits_1(capsys, name, drivers, w):
    args = [a for d in drivers for a in ("--driver", d)]
    code, out, err = run(capsys, "classify", fixture(name), *args)
    assert code == 1
    assert out == ""
    assert f"W = {w}" in err
    error_lines = [line for line in err.splitlines() if line.startswith("error:")]
    assert len(error_lines) == 1
    assert f"{len(drivers)} driver" in error_lines[0]
    assert "Traceback" not in err


@pytest.mark.parametrize(
    ("driver", "word"),
    [
        pytest.param("2", "ground", id="coupler"),
        pytest.param("9", "not a link", id="unknown-link"),
    ],
)
def test_driver_that_cannot_drive_exits_1(capsys, driver, word):
    code, out, err = run(capsys, "classify", fixture("fourbar"), "--driver", driver)
    assert code == 1
    assert out == ""
    assert driver in err
    assert word in err
    assert "Traceback" not in err


def test_rigid_truss_exits_1(capsys, tmp_path):
    path = tmp_path / "truss.edges"
    path.write_text("0 1 R A\n1 2 R B\n2 0 R C\n", encoding="utf-8")  # W = 3·2 − 2·3 = 0
    code, out, err = run(capsys, "classify", str(path))
    assert code == 1
    assert out == ""
    assert "W = 3·2 − (2·3 + 0) + 0 − 0 = 0" in err.splitlines()
    assert "error: W = 0" in err
    assert "Traceback" not in err
    code, out, _ = run(capsys, "classify", str(path), "--json")
    assert code == 1
    report = json.loads(out)
    assert (report["n"], report["P5"], report["W"]) == (2, 3, 0)
    assert "W = 0" in report["error"]


# ------------------------------------------------------------ a sketch at a singular pose
# Issue 22, item 13: the four-bar drawn with its crank and coupler in line, the rocker 3
# driving (hand count and dead point in tests/structure/test_mobility.py): classify answers
# as for any pose, and warns that II(1,2) is singular at the sketch; the solvers refuse that
# pose, naming the group and the input.
TOGGLE = """name four-bar with the crank and the coupler in line
driver 3 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0.1 0
point C 0.3 0
point D 0.3 0.2
"""


def _toggle(tmp_path) -> str:
    path = tmp_path / "toggle.edges"
    path.write_text(TOGGLE, encoding="utf-8")
    return str(path)


def test_classify_a_toggle_sketch_warns_of_its_singular_group(capsys, tmp_path):
    code, out, err = run(capsys, "classify", _toggle(tmp_path))
    assert (code, err) == (0, "")
    assert "Structural formula: I(3) → II(1,2)" in out
    assert "W = 3·3 − (2·4 + 0) + 0 − 0 = 1" in out
    assert "Warning: group II(1,2) is at a singular pose in the sketch" in out
    data = run_json(capsys, _toggle(tmp_path))
    assert data["W"] == 1 and data["formula"] == "I(3) → II(1,2)"
    assert data["singular_groups"] == ["II(1,2)"]
    assert len(data["warnings"]) == 1 and "II(1,2)" in data["warnings"][0]


def test_a_regular_sketch_has_no_warnings_key(capsys):
    assert "warnings" not in run_json(capsys, fixture("fourbar"))


@pytest.mark.parametrize("exact", [(), ("--exact",)], ids=["numbers", "exact"])
@pytest.mark.parametrize("command", ["kinematics", "forces"])
def test_the_solvers_refuse_a_toggle_sketch_naming_the_group(capsys, tmp_path, command, exact):
    code, out, err = run(capsys, command, _toggle(tmp_path), *exact)
    assert (code, out) == (1, "")
    assert "group II(1,2)" in err and "input 0°" in err and "dead centre" in err


def test_the_rocker_at_its_limit_moves_the_crank_driven_four_bar(capsys, tmp_path):
    # the crank driving at the same pose: v_B = ω1 × AB = (0, 0.1); C moves across DC (along
    # x) and v_C = v_B + ω2 × BC = (0, 0.1 + 0.2·ω2): so ω2 = −0.5 and v_C = 0, ω3 = 0
    path = tmp_path / "limit.edges"
    path.write_text(TOGGLE.replace("driver 3", "driver 1"), encoding="utf-8")
    code, out, _ = run(capsys, "kinematics", str(path), "--json")
    assert code == 0
    links = json.loads(out)["links"]
    assert links["2"]["omega"] == pytest.approx(-0.5)
    assert links["3"]["omega"] == pytest.approx(0.0, abs=1e-12)
