"""Rows of results as a table: JSON lines, CSV or Parquet, written as they come.

A row is a dict of plain values (numbers, strings, booleans, None, lists, dicts);
``columns`` names and orders them, with a type each (``int``, ``float``, ``str``,
``bool`` or ``json`` for nested values). JSON lines keep nested values as they are;
CSV and Parquet hold them as JSON text. Parquet needs pyarrow, the optional
``parquet`` extra (imported on use only).

>>> import io
>>> out = io.StringIO()
>>> writer = open_table(out, "csv", [("name", "str"), ("groups", "json")])
>>> writer.write([{"name": "four-bar", "groups": [[2, 3]]}])
>>> writer.close()
>>> out.getvalue().splitlines()
['name,groups', 'four-bar,"[[2, 3]]"']
"""

from __future__ import annotations

import csv
import json
import os
import sys
from collections.abc import Iterable, Iterator, Mapping, Sequence
from typing import IO, Any

from .textfile import open_user_file

__all__ = [
    "MAX_ROW_BYTES",
    "TABLE_FORMATS",
    "Column",
    "TableWriter",
    "open_table",
    "read_table_lines",
]

#: formats of :func:`open_table`
TABLE_FORMATS = ("jsonl", "csv", "parquet")

Column = tuple[str, str]  # (name, type): int, float, str, bool, json

_PARQUET_BATCH = 4096

#: the longest row :func:`read_table_lines` reads back (bytes): rows are far shorter
MAX_ROW_BYTES = 1_000_000


def _cell(value: Any, kind: str) -> Any:
    """A CSV or Parquet cell: nested values as JSON text."""
    if kind == "json" and value is not None:
        return json.dumps(value, ensure_ascii=False)
    return value


class TableWriter:
    """Writes rows to one table; :meth:`close` finishes it (Parquet is written in batches)."""

    def __init__(self, handle: IO[Any], fmt: str, columns: Sequence[Column], header: bool) -> None:
        if fmt not in TABLE_FORMATS:
            raise ValueError(f"unknown table format {fmt!r} (use {', '.join(TABLE_FORMATS)})")
        self.handle = handle
        self.format = fmt
        self.columns = tuple(columns)
        self._csv = None
        self._parquet: Any = None
        self._batch: list[dict[str, Any]] = []
        if fmt == "csv":
            self._csv = csv.writer(handle, lineterminator="\n")
            if header:
                self._csv.writerow([name for name, _ in self.columns])
        elif fmt == "parquet":
            self._parquet = _parquet_writer(handle, self.columns)

    def write(self, rows: Iterable[Mapping[str, Any]]) -> None:
        """Append rows (and flush them, so that an interrupted run keeps them)."""
        if self.format == "jsonl":
            for row in rows:
                self.handle.write(json.dumps(row, ensure_ascii=False) + "\n")
        elif self.format == "csv":
            assert self._csv is not None
            for row in rows:
                self._csv.writerow(
                    ["" if (v := _cell(row.get(n), k)) is None else v for n, k in self.columns]
                )
        else:
            self._batch.extend({n: _cell(row.get(n), k) for n, k in self.columns} for row in rows)
            if len(self._batch) >= _PARQUET_BATCH:
                self._flush_parquet()
            return
        self.handle.flush()

    def _flush_parquet(self) -> None:
        if self._batch:
            writer, table_type = self._parquet
            writer.write_table(table_type.from_pylist(self._batch, schema=writer.schema))
            self._batch = []

    def close(self) -> None:
        """Finish the table (the handle stays open)."""
        if self.format == "parquet":
            self._flush_parquet()
            self._parquet[0].close()
        else:
            self.handle.flush()


def _parquet_writer(handle: IO[Any], columns: Sequence[Column]) -> tuple[Any, Any]:
    try:
        import pyarrow as pa  # optional extra, imported on use
        import pyarrow.parquet as pq
    except ImportError as exc:
        raise ImportError("Parquet output needs pyarrow: pip install 'assur[parquet]'") from exc
    types = {"int": pa.int64(), "float": pa.float64(), "bool": pa.bool_()}
    schema = pa.schema([(name, types.get(kind, pa.string())) for name, kind in columns])
    return pq.ParquetWriter(handle, schema), pa.Table


def open_table(
    handle: IO[Any], fmt: str, columns: Sequence[Column], *, header: bool = True
) -> TableWriter:
    """A :class:`TableWriter` on an open handle (text for jsonl/csv, binary for parquet).

    ``header=False`` leaves out the CSV header (when appending to a table).

    Raises
    ------
    ValueError
        Unknown format.
    ImportError
        Parquet without pyarrow.
    """
    return TableWriter(handle, fmt, columns, header)


def read_table_lines(
    path: str | os.PathLike[str], fmt: str
) -> Iterator[tuple[dict[str, Any], int]]:
    """The complete rows of a JSON-lines or CSV table, each with the byte offset after it.

    A last line cut short (an interrupted run), unreadable or longer than
    :data:`MAX_ROW_BYTES` ends the reading. CSV cells come back as text. The
    table must be a regular file (of any size): a device or a FIFO is refused.

    Raises
    ------
    EdgeListError
        The file cannot be read, or is no regular file.
    """
    if fmt not in ("jsonl", "csv"):
        raise ValueError("only JSON lines and CSV tables can be read back")
    with open_user_file(path, sys.maxsize, binary=True) as handle:
        header: list[str] | None = None
        offset = 0
        pending = ""
        while raw := handle.readline(MAX_ROW_BYTES + 1):
            offset += len(raw)
            if not raw.endswith(b"\n"):
                return
            text = raw.decode("utf-8", errors="replace")
            if fmt == "jsonl":
                try:
                    row = json.loads(text)
                except ValueError:
                    return
                if not isinstance(row, dict):
                    return
                yield row, offset
                continue
            pending += text
            if len(pending) > MAX_ROW_BYTES:
                return
            if pending.count('"') % 2:  # a quoted cell goes on on the next line
                continue
            cells, pending = next(csv.reader([pending])), ""
            if header is None:
                header = cells
                continue
            if len(cells) != len(header):
                return
            yield dict(zip(header, cells, strict=True)), offset
