"""Classify many mechanisms at once: ``assur classify A.edges B.edges DIR 'glob*' -``.

One row per mechanism, in the order named (a directory's files and a glob's
matches sorted), as a text table, JSON lines, CSV or Parquet; a file that cannot
be read or classified is a row with its error and the run goes on (exit code 1
when any row has an error). An entry that is no regular file (a FIFO, a link to
a device) or is larger than ``--max-file-size`` is not read: its row says why it
was skipped. ``-`` reads JSON lines from standard input: the JSON form of a
mechanism, or an atlas row, per line.

:func:`run` takes parsed arguments with ``inputs`` and the table's options
(``--format``, ``--output``, ``--jobs``, Dask: declared in :mod:`kinematics.cli.parser`);
``classify`` hands it several inputs, a directory, a glob or ``-``. The table is
written whole or not at all (:mod:`structure.readwrite.atomic`), never over an input.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable
from typing import IO, Any

from structure.batch import BATCH_COLUMNS, batch_entries, batch_items, classify_batch
from structure.parallel import Counted, MissingExtraError
from structure.readwrite.table import open_table

from .output import EXIT_MECHANISM, EXIT_OK, EXIT_USAGE, check_outputs, fail, input_limit
from .tables import check_run_options, check_workers, open_output, progress_bar

__all__ = ["format_text_table", "run"]


def _one_line(text: str | None) -> str:
    return "" if text is None else "; ".join(text.splitlines())


def format_text_table(rows: Iterable[dict[str, Any]]) -> str:
    """Rows as an aligned text table: source, W, class, formula or error, then a count.

    >>> print(format_text_table([{"source": "a.edges", "W": 1, "class": "II",
    ...                           "formula": "I(1) → II(2,3)", "error": None}]), end="")
    source   W  class  formula
    a.edges  1  II     I(1) → II(2,3)
    1 mechanism, 0 errors
    """
    rows = list(rows)
    cells = [("source", "W", "class", "formula")]
    for row in rows:
        if row["error"] is not None:
            w = "" if row.get("W") is None else str(row["W"])
            cells.append((row["source"], w, "", "error: " + _one_line(row["error"])))
        else:
            cells.append((row["source"], str(row["W"]), row["class"], row["formula"]))
    widths = [max(len(c[k]) for c in cells) for k in range(3)]
    lines = ["  ".join(c[k].ljust(widths[k]) for k in range(3)) + "  " + c[3] for c in cells]
    errors = sum(1 for row in rows if row["error"] is not None)
    plural = "" if len(rows) == 1 else "s"
    lines.append(f"{len(rows)} mechanism{plural}, {errors} error{'' if errors == 1 else 's'}")
    return "\n".join(lines) + "\n"


def run(args: argparse.Namespace, stdin: IO[str] | None = None) -> int:
    """Classify ``args.inputs``; 0 when every row is classified, 1 when some has an error."""
    problem = check_run_options(args)
    if problem:
        return fail(problem, EXIT_USAGE)
    check_workers(args)
    entries = batch_entries(args.inputs)
    check_outputs((path for path, _ in entries if path != "-"), {"--output": args.output})
    items: Iterable = batch_items(
        args.inputs, stdin if stdin is not None else sys.stdin, max_bytes=input_limit(args)
    )
    total = None
    if all(path != "-" for path, _ in entries):
        total = len(entries)
        items = Counted(items, total)
    update, close = progress_bar(total, "mechanism")
    rows = classify_batch(
        items,
        jobs=args.jobs,
        scheduler=args.scheduler,
        dask_local=args.dask_local,
        progress=update,
    )
    errors = 0
    try:
        with open_output(args.output, args.format) as handle:
            if args.format == "text":
                collected = list(rows)
                close()
                errors = sum(1 for row in collected if row["error"] is not None)
                handle.write(format_text_table(collected))
            else:
                writer = open_table(handle, args.format, BATCH_COLUMNS)
                for row in rows:
                    errors += row["error"] is not None
                    writer.write([row])
                writer.close()
    except (MissingExtraError, ImportError) as exc:
        return fail(str(exc), EXIT_USAGE)
    finally:
        close()
    return EXIT_MECHANISM if errors else EXIT_OK
