"""Tests of structure.batch: inputs expanded in order, rows equal to the single classify."""

from __future__ import annotations

import io
import json
import os
import shutil
from pathlib import Path

import pytest

from kinematics.cli.commands import main
from structure.atlas import atlas, atlas_row_dict
from structure.batch import BATCH_COLUMNS, BatchItem, batch_items, classify_batch, classify_item
from structure.readwrite.edgelist import read_edgelist
from structure.readwrite.jsonformat import mechanism_to_json

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "fixtures"
FIXTURE_FILES = sorted(str(p) for p in FIXTURES.glob("*.edges"))


def _single(capsys, path: str) -> tuple[int, dict | None, str]:
    """``assur classify PATH --json``: exit code, JSON (None on a bare error), stderr."""
    code = main(["classify", path, "--json"])
    out, err = capsys.readouterr()
    return code, json.loads(out) if out.strip() else None, err


def test_batch_rows_equal_the_single_classify(capsys):
    rows = list(classify_batch(batch_items(FIXTURE_FILES)))
    assert [row["source"] for row in rows] == FIXTURE_FILES
    for path, row in zip(FIXTURE_FILES, rows, strict=True):
        code, data, _err = _single(capsys, path)
        assert set(row) == {name for name, _ in BATCH_COLUMNS}
        if code == 0:
            assert row["error"] is None
            for key in ("n", "P5", "P4", "redundant", "passive", "W", "drivers", "formula"):
                assert row[key] == data[key], (path, key)
            assert row["mechanism_class"] == data["mechanism_class"]
            assert row["name"] == data["name"]
            assert len(row["groups"]) == len(data["groups"])
        else:
            assert data is not None and row["error"] == data["error"], path
            for key in ("n", "P5", "P4", "W"):
                if key in data:
                    assert row[key] == data[key]


def test_a_bad_file_is_a_row_with_its_error(tmp_path, capsys):
    good = tmp_path / "a_good.edges"
    shutil.copy(FIXTURES / "fourbar.edges", good)
    broken = tmp_path / "b_broken.edges"
    broken.write_text("driver 1\n0 1 Q A\n", encoding="utf-8")
    binary = tmp_path / "c_binary.edges"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    rigid = tmp_path / "d_rigid.edges"
    rigid.write_text("0 1 R A\n1 2 R B\n2 0 R C\n", encoding="utf-8")
    missing = str(tmp_path / "e_missing.edges")
    rows = list(classify_batch(batch_items([str(tmp_path), missing])))
    assert [Path(row["source"]).name for row in rows] == [
        "a_good.edges",
        "b_broken.edges",
        "c_binary.edges",
        "d_rigid.edges",
        "e_missing.edges",
    ]
    assert rows[0]["error"] is None and rows[0]["formula"] == "I(1) → II(2,3)"
    for row in rows[1:]:
        code, data, err = _single(capsys, row["source"])
        assert code == 1
        expected = data["error"] if data else err.removeprefix("error: ").rstrip("\n")
        assert row["error"] == expected
    assert rows[3]["W"] == 0


def test_directories_globs_and_missing_matches(tmp_path):
    (tmp_path / "sub").mkdir()
    for name in ("b.edges", "a.edges", "sub/c.edges", "notes.txt"):
        shutil.copy(FIXTURES / "fourbar.edges", tmp_path / name)
    shutil.copy(FIXTURES / "fourbar.edges", tmp_path / "sub" / "d.json")
    items = list(batch_items([str(tmp_path)]))
    assert [Path(i.source).relative_to(tmp_path).as_posix() for i in items] == [
        "a.edges",
        "b.edges",
        "sub/c.edges",
        "sub/d.json",
    ]
    items = list(batch_items([str(tmp_path / "*.edges"), str(tmp_path / "*.nothing")]))
    assert [Path(i.source).name for i in items] == ["a.edges", "b.edges", "*.nothing"]
    assert items[-1].problem.endswith("no file matches")


def test_json_lines_on_stdin(capsys):
    mechanism = read_edgelist(FIXTURES / "stephenson_sixbar.edges")
    atlas_row = atlas_row_dict(next(atlas(6)))
    lines = [
        mechanism_to_json(mechanism, indent=None),
        "",
        json.dumps(atlas_row),
        "{not json",
        json.dumps({"pairs": "nope"}),
    ]
    rows = list(classify_batch(batch_items(["-"], io.StringIO("\n".join(lines) + "\n"))))
    assert [row["source"] for row in rows] == [
        "<stdin>:1",
        "<stdin>:3",
        "<stdin>:4",
        "<stdin>:5",
    ]
    assert rows[0]["formula"] == "I(1) → III(2,3,4,5)"
    assert rows[1]["formula"] == atlas_row["formula"]
    assert rows[1]["mechanism_class"] == atlas_row["mechanism_class"]
    assert "invalid JSON" in rows[2]["error"]
    assert rows[3]["error"]


def test_local_processes_give_the_same_rows():
    items = list(batch_items(FIXTURE_FILES))
    assert list(classify_batch(items, jobs=2)) == list(classify_batch(items))


def test_an_item_that_could_not_be_read():
    row = classify_item(BatchItem("x.edges", "", "edges", "x.edges: cannot read: it is gone"))
    assert row["error"] == "x.edges: cannot read: it is gone"
    assert row["W"] is None


@pytest.mark.parametrize("fmt", ["jsonl", "csv"])
def test_classify_batch_command(tmp_path, capsys, fmt):
    out = tmp_path / f"rows.{fmt}"
    code = main(
        ["classify", str(FIXTURES / "fourbar.edges"), "--format", fmt, "-o", str(out)]
    )
    assert code == 0
    text = out.read_text(encoding="utf-8")
    if fmt == "jsonl":
        assert json.loads(text)["formula"] == "I(1) → II(2,3)"
    else:
        assert text.splitlines()[0] == ",".join(name for name, _ in BATCH_COLUMNS)


def test_classify_batch_text_table_and_exit_code(capsys, tmp_path):
    missing = str(tmp_path / "missing.edges")
    code = main(["classify", str(FIXTURES / "fourbar.edges"), missing])
    out, _err = capsys.readouterr()
    assert code == 1
    lines = out.splitlines()
    assert lines[0].split() == ["source", "W", "class", "formula"]
    assert lines[1].endswith("1  II     I(1) → II(2,3)")
    assert "error: " in lines[2] and "cannot read" in lines[2]
    assert lines[-1] == "2 mechanisms, 1 error"


def test_parquet_needs_an_output_file(capsys):
    code = main(["classify", str(FIXTURES / "fourbar.edges"), "--format", "parquet"])
    assert code == 2
    assert "--output" in capsys.readouterr().err


def test_parquet_table(tmp_path, capsys):
    pq = pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "rows.parquet"
    assert main(["classify", str(FIXTURES), "--format", "parquet", "-o", str(out)]) == 0
    table = pq.read_table(out)
    assert table.column_names == [name for name, _ in BATCH_COLUMNS]
    mechanisms = [p for p in FIXTURES.rglob("*") if p.suffix in (".edges", ".json", ".pyslvs")]
    assert table.num_rows == len(mechanisms)


def test_a_directory_reads_every_format_by_its_reader():
    """pylinkage's JSON and a pyslvs expression in a folder are read by their own readers."""
    rows = list(classify_batch(batch_items([str(FIXTURES / "exchange")])))
    assert [(Path(r["source"]).name, r["W"], r["error"]) for r in rows] == [
        ("crank_slider_pylinkage.json", 1, None),
        ("jansen.pyslvs", 1, None),
    ]
    assert rows[1]["formula"] == "I(L1) → II(L2,L4) → II(L3,L5) → II(L6,L7)"


# ------------------------------------------------------------------ issue 22, item 6
def test_a_fifo_and_a_link_to_a_device_in_a_folder_are_skipped_with_their_reason(
    tmp_path, capsys
):
    """A FIFO in the folder hung the run; a link to /dev/zero ended in MemoryError."""
    shutil.copy(FIXTURES / "fourbar.edges", tmp_path / "a_fourbar.edges")
    os.mkfifo(tmp_path / "b_pipe.edges")
    (tmp_path / "c_zero.edges").symlink_to("/dev/zero")
    big = tmp_path / "d_big.edges"
    text = (FIXTURES / "fourbar.edges").read_text(encoding="utf-8")
    big.write_text(text + "#" * 10_000 + "\n", encoding="utf-8")
    shutil.copy(FIXTURES / "crank_slider.edges", tmp_path / "e_slider.edges")
    size = 10_000
    code = main(["classify", str(tmp_path), "--max-file-size", str(size)])
    out, err = capsys.readouterr()
    assert code == 1 and err == ""
    lines = out.splitlines()
    assert "a_fourbar.edges  1  II     I(1) → II(2,3)" in lines[1]
    assert "b_pipe.edges" in lines[2] and "not a regular file (a FIFO)" in lines[2]
    assert "c_zero.edges" in lines[3] and "not a regular file (a character device)" in lines[3]
    assert "d_big.edges" in lines[4] and "more than the 10 kB assur reads" in lines[4]
    assert "--max-file-size" in lines[4]
    assert "e_slider.edges" in lines[5] and "error" not in lines[5]  # and the run went on
    assert lines[-1] == "5 mechanisms, 3 errors"


def test_items_are_read_one_at_a_time(tmp_path):
    """A long batch does not hold every file's text at once: each is read when it is taken."""
    for k in range(3):
        shutil.copy(FIXTURES / "fourbar.edges", tmp_path / f"{k}.edges")
    items = batch_items([str(tmp_path)])
    first = next(items)
    (tmp_path / "2.edges").write_text("0 1 Q A\n", encoding="utf-8")  # changed after the start
    assert first.text and "0 1 Q A" in [i.text for i in items][-1]


def test_a_stdin_line_longer_than_the_limit_is_skipped(capsys):
    line = mechanism_to_json(read_edgelist(FIXTURES / "fourbar.edges"), indent=None)
    assert len(line) < 2000
    text = "x" * 5000 + "\n" + line + "\n"
    rows = list(classify_batch(batch_items(["-"], io.StringIO(text), max_bytes=2000)))
    assert "longer than 2 kB" in rows[0]["error"] and rows[0]["source"] == "<stdin>:1"
    assert rows[1]["source"] == "<stdin>:2" and rows[1]["error"] is None


def test_the_output_is_never_an_input(tmp_path, capsys):
    folder = tmp_path / "in"
    folder.mkdir()
    shutil.copy(FIXTURES / "fourbar.edges", folder / "m.edges")
    code = main(["classify", str(folder), "-o", str(folder / "m.edges"), "--format", "csv"])
    assert code == 2 and "a file this command reads" in capsys.readouterr().err
    assert (folder / "m.edges").read_text(encoding="utf-8").startswith("#")
