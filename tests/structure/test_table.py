"""Tests of structure.readwrite.table: rows written and read back, cut lines ignored."""

from __future__ import annotations

import pytest

from structure.readwrite.table import open_table, read_table_lines

COLUMNS = [("n", "int"), ("text", "str"), ("nested", "json")]
ROWS = [
    {"n": 1, "text": 'two\nlines, "quoted"', "nested": [1, [2, 3]]},
    {"n": 2, "text": None, "nested": {"a": None}},
]


@pytest.mark.parametrize("fmt", ["jsonl", "csv"])
def test_rows_read_back_with_their_end_offsets(tmp_path, fmt):
    path = tmp_path / f"rows.{fmt}"
    with open(path, "w", encoding="utf-8", newline="") as handle:
        writer = open_table(handle, fmt, COLUMNS)
        writer.write(ROWS)
        writer.close()
    read = list(read_table_lines(path, fmt))
    assert read[-1][1] == path.stat().st_size
    if fmt == "jsonl":
        assert [row for row, _ in read] == ROWS
    else:
        assert [row["text"] for row, _ in read] == [ROWS[0]["text"], ""]
        assert read[0][0]["nested"] == "[1, [2, 3]]"
    path.write_bytes(path.read_bytes()[:-3])  # an interrupted write
    assert [end for _, end in read_table_lines(path, fmt)] == [read[0][1]]


def test_unknown_formats():
    with pytest.raises(ValueError, match="unknown table format"):
        open_table(None, "xlsx", COLUMNS)
    with pytest.raises(ValueError, match="read back"):
        list(read_table_lines("x.parquet", "parquet"))
