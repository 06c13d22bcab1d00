"""``assur report``: the page written where asked, usage and mechanism errors as lines."""

from __future__ import annotations

from kinematics.cli.parser import build_parser

from .conftest import fixture, run


def test_report_writes_the_page_and_says_where(capsys, tmp_path):
    out = tmp_path / "fourbar.html"
    code, stdout, err = run(capsys, "report", fixture("fourbar"), "-o", str(out), "--steps", "8")
    assert (code, stdout, err) == (0, f"wrote {out}\n", "")
    page = out.read_text(encoding="utf-8")
    assert page.startswith('<!DOCTYPE html>\n<html lang="en">')
    assert page.rstrip().endswith("</html>")


def test_report_in_vietnamese(capsys, tmp_path):
    out = tmp_path / "press.html"
    code, _, _ = run(
        capsys, "report", fixture("ch1_1_2a_mechanical_press"), "-o", str(out), "--lang", "vi"
    )
    assert code == 0
    page = out.read_text(encoding="utf-8")
    assert '<html lang="vi">' in page and "Phân tích cấu trúc" in page


def test_report_without_output_writes_beside_the_current_directory(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, stdout, _ = run(capsys, "report", fixture("ch1_1_2a_mechanical_press"))
    assert code == 0 and stdout == "wrote ch1_1_2a_mechanical_press.html\n"
    assert (tmp_path / "ch1_1_2a_mechanical_press.html").is_file()


def test_report_defaults():
    args = build_parser().parse_args(["report", "m.edges"])
    assert (args.output, args.lang, args.steps) == (None, "en", 120)


def test_report_refuses_zero_steps(capsys, tmp_path):
    code, stdout, err = run(
        capsys, "report", fixture("fourbar"), "-o", str(tmp_path / "x.html"), "--steps", "0"
    )
    assert (code, stdout, err) == (2, "", "error: --steps must be at least 1\n")


def test_report_of_a_bad_file_is_an_error_line(capsys, tmp_path):
    bad = tmp_path / "bad.edges"
    bad.write_text("0 1 Q A\n", encoding="utf-8")
    code, stdout, err = run(capsys, "report", str(bad), "-o", str(tmp_path / "bad.html"))
    assert code == 1 and stdout == ""
    assert err.startswith("error: ") and err.count("\n") >= 1
    assert not (tmp_path / "bad.html").exists()


def test_report_to_a_directory_that_does_not_exist(capsys, tmp_path):
    out = tmp_path / "missing" / "x.html"
    code, stdout, err = run(capsys, "report", fixture("ch1_1_2a_mechanical_press"), "-o", str(out))
    assert code == 1 and stdout == ""
    assert err.startswith(f"error: cannot write {out}")
