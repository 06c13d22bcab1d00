"""The `assur convert` command: formats in and out, drawings, sweeps, and named errors."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kinematics.cli.commands import main
from structure.readwrite.edgelist import read_edgelist, write_edgelist
from structure.readwrite.formats import read_mechanism
from structure.readwrite.jsonformat import mechanism_to_json
from structure.report import analyze

from ..conftest import FIXTURES


def _convert(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(["convert", *map(str, argv)])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("path", sorted(FIXTURES.glob("*.edges")), ids=lambda p: p.stem)
def test_edges_to_json_to_edges_is_lossless(tmp_path, capsys, path):
    as_json, back = tmp_path / "m.json", tmp_path / "m.edges"
    assert _convert(capsys, path, as_json)[0] == 0
    assert _convert(capsys, as_json, back)[0] == 0
    original = read_edgelist(path)
    assert mechanism_to_json(read_mechanism(back)) == mechanism_to_json(original)
    assert back.read_text(encoding="utf-8") == write_edgelist(original)


def test_a_mechanism_goes_to_pyslvs_and_back(tmp_path, capsys):
    out = tmp_path / "shaper.pyslvs"
    code, said, err = _convert(capsys, FIXTURES / "quick_return_shaper.edges", out)
    assert (code, said) == (0, f"wrote {out}\n")
    # what a pyslvs project cannot hold is named, one warning line per kind (issue 22, item 11)
    assert err.splitlines() == [
        f"warning: {out}: pyslvs projects have no title: the name "
        "'quick-return shaper (crank and slotted lever with ram)' left out",
        f"warning: {out}: pyslvs projects hold no driver motion: omega of driver 1 left out",
        f"warning: {out}: pyslvs projects name things their own way: link 0 → ground, "
        "link 1 → L1, link 2 → L2, link 3 → L3, link 4 → L4, link 5 → L5, ...",
    ]
    assert out.read_text(encoding="utf-8").startswith(
        "mechanism: 'M[J[R, P[0, 0.3], L[ground, L1]]"
    )
    back = tmp_path / "shaper.edges"
    assert _convert(capsys, out, back)[0] == 0
    assert analyze(read_mechanism(back)).formula == "I(L1) → II(L3,block_J4) → II(L4,L5)"


def test_a_pyslvs_expression_comes_in(tmp_path, capsys, pyslvs_sdist):
    jansen = tmp_path / "jansen.txt"
    jansen.write_text(pyslvs_sdist.examples["Jansen's linkage (Single)"].expression, "utf-8")
    assert _convert(capsys, jansen, tmp_path / "jansen.edges")[0] == 0
    text = (tmp_path / "jansen.edges").read_text(encoding="utf-8")
    assert text.startswith("name jansen\nground ground\nground L1 R J0\n")


def test_pylinkage_json_comes_in(tmp_path, capsys):
    linkage = tmp_path / "crank.json"
    linkage.write_text(
        json.dumps(
            {
                "joints": [
                    {"type": "Static", "name": "A", "x": 0, "y": 0},
                    {"type": "Crank", "name": "B", "x": 0, "y": 1, "joint0": {"ref": "A"}},
                ]
            }
        ),
        "utf-8",
    )
    assert _convert(capsys, linkage, tmp_path / "crank.edges")[0] == 0
    assert "driver 1\n0 1 R A\n" in (tmp_path / "crank.edges").read_text(encoding="utf-8")


def test_the_drawing_as_svg_parses_as_xml(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "fourbar.svg"
    assert _convert(capsys, FIXTURES / "fourbar.edges", out, "--pose", "30")[0] == 0
    root = ET.parse(out).getroot()
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    ids = {element.get("id") for element in root.iter()}
    assert {"pin:A", "pin:B", "link:2"} <= ids  # the figure's gids survive as ids


def test_the_drawing_as_dxf_at_a_pose(tmp_path, capsys):
    ezdxf = pytest.importorskip("ezdxf")
    out = tmp_path / "yoke.dxf"
    assert _convert(capsys, FIXTURES / "scotch_yoke.edges", out, "--pose", "90")[0] == 0
    msp = ezdxf.readfile(out).modelspace()
    pin_b = [e.dxf.center for e in msp if e.dxftype() == "CIRCLE" and e.dxf.layer == "II(2,3)"]
    # crank AB = 0.08 turned 90° from 40°: B at 130°
    assert pin_b[0].x == pytest.approx(-0.051423009, abs=1e-8)
    assert pin_b[0].y == pytest.approx(0.061283555, abs=1e-8)


def test_sweeps_as_csv_and_parquet(tmp_path, capsys):
    csv_out = tmp_path / "turn.csv"
    assert _convert(capsys, FIXTURES / "fourbar.edges", csv_out, "--steps", "8")[0] == 0
    lines = csv_out.read_text(encoding="utf-8").splitlines()
    assert len(lines) == 9 and lines[0].startswith("input1,")
    pytest.importorskip("pyarrow")
    assert (
        _convert(capsys, FIXTURES / "fourbar.edges", tmp_path / "t.parquet", "--steps", "8")[0] == 0
    )


@pytest.mark.parametrize(
    ("argv", "code", "message"),
    [
        (["fixtures/none.edges", "x.json"], 1, "error: fixtures/none.edges: cannot read"),
        (["{fixtures}/gear_pair.edges", "x.pyslvs"], 1, "line 16: pyslvs has no higher pair"),
        (["{fixtures}/fourbar.edges", "x.step"], 2, "x.step: unknown format '.step'"),
        (["{fixtures}/fourbar.edges", "x.svg", "--pose", "1", "2"], 1, "error: --pose: line 1"),
        (["{fixtures}/fourbar.edges", "x.svg", "--flip", "II(9,9)"], 2, "cannot flip"),
        (["{fixtures}/fourbar.edges", "x.csv", "--steps", "0"], 2, "--steps must be at least 1"),
    ],
)
def test_bad_input_is_a_named_error(tmp_path, capsys, argv, code, message):
    argv = [a.replace("{fixtures}", str(FIXTURES)) for a in argv]
    argv[1] = str(tmp_path / argv[1])
    got, out, err = _convert(capsys, *argv)
    assert got == code and out == ""
    assert message in err and err.startswith("error: ") and "Traceback" not in err


def test_a_bad_line_is_named_with_its_file_and_number(tmp_path, capsys):
    bad = tmp_path / "bad.pyslvs"
    bad.write_text("M[\n  J[R, P[0, 0], L[ground, L1]],\n  J[X, P[1, 0], L[L1]]\n]", "utf-8")
    code, _, err = _convert(capsys, bad, tmp_path / "x.edges")
    assert code == 1
    assert err == (
        f"error: {bad}: line 3: column 5: unknown joint kind 'X' (use R, P or RP): "
        "'J[X, P[1, 0], L[L1]]'\n"
    )


@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(
    st.sampled_from([".edges", ".json", ".pyslvs", ".txt"]),
    st.sampled_from([".edges", ".json", ".pyslvs", ".dxf", ".csv"]),
    st.one_of(
        st.binary(max_size=200).map(lambda b: b.decode("latin-1")),
        st.text(
            alphabet=st.sampled_from(list('M[]J(),RP{}":01 .-\nground#pointsjoints')), max_size=120
        ),
    ),
)
def test_garbage_in_never_gives_a_traceback(tmp_path, capsys, suffix, target, text):
    source = tmp_path / f"in{suffix}"
    source.write_text(text, encoding="utf-8")
    code, _, err = _convert(capsys, source, tmp_path / f"out{target}")
    assert code in (0, 1)
    if code:
        assert err.startswith("error: ") and "Traceback" not in err
