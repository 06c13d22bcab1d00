"""What the command line prints (kinematics.cli.output), issue 22, item 19.

A control character or an escape sequence in a name (of the mechanism, a link,
a point, a file) is printed escaped, in text answers and in error messages;
JSON keeps the same strings (a strict parser reads them back) with no raw
control character either.
"""

from __future__ import annotations

import json

import pytest
from hypothesis import given
from hypothesis import strategies as st

from kinematics.cli.output import check_outputs, printable
from structure.errors import UsageError

from .conftest import run

ESC = "\x1b[2J\x1b[31m"  # clear the screen, then red
CSI = "\x9b31m"  # the 8-bit form some terminals read


def _raw_controls(text: str) -> set[str]:
    return {c for c in text if (ord(c) < 0x20 and c != "\n") or 0x7F <= ord(c) <= 0x9F}


@pytest.fixture
def odd(tmp_path):
    """A four-bar whose name, links and points hold escape sequences (as JSON can)."""
    path = tmp_path / "odd.json"
    path.write_text(
        json.dumps(
            {
                "name": f"evil{ESC}name{CSI}",
                "drivers": [{"link": f"crank{ESC}", "omega": 10}],
                "pairs": [
                    {"links": ["0", f"crank{ESC}"], "kind": "R", "point": "A"},
                    {"links": [f"crank{ESC}", "2"], "kind": "R", "point": f"B{CSI}"},
                    {"links": ["2", "3"], "kind": "R", "point": "C"},
                    {"links": ["3", "0"], "kind": "R", "point": "D"},
                ],
                "points": {"A": [0, 0], f"B{CSI}": [0, 0.1], "C": [0.3, 0.3], "D": [0.4, 0]},
            }
        ),
        encoding="utf-8",
    )
    return path


@pytest.mark.parametrize(
    "argv",
    [
        ["classify", "{file}"],
        ["classify", "{file}", "--explain"],
        ["kinematics", "{file}"],
        ["classify", "{file}", "{file}"],  # the batch's text table
    ],
    ids=["classify", "explain", "kinematics", "batch"],
)
def test_text_answers_print_names_escaped(capsys, odd, argv):
    code, out, err = run(capsys, *(a.format(file=odd) for a in argv))
    assert code == 0, err
    assert not _raw_controls(out) and not _raw_controls(err)
    assert "\\x1b[2J" in out or "\\x9b" in out


@pytest.mark.parametrize(
    "argv", [["classify", "{file}", "--json"], ["kinematics", "{file}", "--json"]]
)
def test_json_answers_keep_the_strings_without_raw_controls(capsys, odd, argv):
    code, out, _ = run(capsys, *(a.format(file=odd) for a in argv))
    assert code == 0 and not _raw_controls(out)
    text = json.dumps(json.loads(out), ensure_ascii=False)
    assert f"crank{ESC}" in text or f"B{CSI}" in text


def test_jsonl_rows_on_stdout_keep_the_strings(capsys, odd):
    code, out, _ = run(capsys, "classify", str(odd), "--format", "jsonl")
    assert code == 0 and not _raw_controls(out)
    assert json.loads(out)["name"] == f"evil{ESC}name{CSI}"


def test_error_messages_print_names_escaped(capsys, tmp_path):
    bad = tmp_path / f"bad{ESC}.edges"
    bad.write_text(f"driver x{ESC}\n0 1 R A\n", encoding="utf-8")
    code, out, err = run(capsys, "classify", str(bad))
    assert code == 1 and not _raw_controls(err) and not _raw_controls(out)
    assert "bad\\x1b[2J\\x1b[31m.edges" in err and "x\\x1b[2J" in err
    code, _, err = run(capsys, "classify", str(tmp_path / f"missing{CSI}.edges"))
    assert code == 1 and "missing\\x9b31m.edges" in err and not _raw_controls(err)


@given(st.text())
def test_json_escaping_reads_back_the_same_string(text):
    dumped = json.dumps({"name": text}, ensure_ascii=False)
    shown = printable(dumped, json_text=True)
    assert json.loads(shown) == {"name": text}
    assert not _raw_controls(shown)


@given(st.text())
def test_text_escaping_leaves_no_control_but_newlines(text):
    assert not _raw_controls(printable(text))


def test_printable_keeps_letters_of_every_script():
    assert printable("thanh truyền 连杆 ω ε → ≈\n") == "thanh truyền 连杆 ω ε → ≈\n"


def test_check_outputs_refuses_inputs_and_twins(tmp_path):
    source = tmp_path / "m.edges"
    source.write_text("0 1 R A\n", encoding="utf-8")
    with pytest.raises(UsageError, match="a file this command reads"):
        check_outputs([str(source)], {"-o": str(tmp_path / "." / "m.edges")})
    with pytest.raises(UsageError, match="are the same file"):
        check_outputs(
            [], {"--csv": str(tmp_path / "a"), "--plot": str(tmp_path / "x" / ".." / "a")}
        )
    check_outputs([str(source)], {"--csv": "/dev/null", "--plot": "/dev/null"})
    check_outputs([None, str(source)], {"-o": None, "OUT": str(tmp_path / "new.edges")})
