"""Classify many mechanisms: files, directories, globs, JSON lines; one row each.

:func:`batch_items` turns what a user names into items in a fixed order: a file,
every ``.edges``, ``.json`` and ``.pyslvs`` file under a directory and its subdirectories
(sorted), the files a glob
matches (sorted), or ``-`` for JSON lines on standard input (one mechanism per
line: the JSON form, or an atlas row). The text of each file is read here, when
its item is taken, so the items can travel to another process or machine and a
long batch holds few texts at a time. Only regular files under a size limit are
read (:mod:`structure.readwrite.textfile`): a FIFO, a link to a device, a file too
large is a row with its reason, skipped. :func:`classify_item` gives the
row of one item, the same answer :func:`structure.report.analyze` gives the file
(``W``, drivers, groups, class, formula); a file that cannot be read or analysed is
a row with its ``error``, never the end of the run. :func:`classify_batch` maps it
over the items in order, here, in local processes or on Dask.

>>> items = batch_items(["fixtures/fourbar.edges", "fixtures/missing.edges"])
>>> rows = list(classify_batch(items))
>>> [(r["source"], r["W"], r["formula"]) for r in rows][:1]
[('fixtures/fourbar.edges', 1, 'I(1) → II(2,3)')]
>>> rows[1]["error"]
'fixtures/missing.edges: cannot read: No such file or directory'
"""

from __future__ import annotations

import glob
import io
import json
import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import IO, Any

from .assur import roman
from .atlas import row_mechanism
from .errors import EdgeListError, EdgeListProblem, MechanismError, MobilityError
from .limits import memory_text
from .model import Mechanism
from .parallel import ordered_map
from .readwrite.edgelist import parse_edgelist
from .readwrite.formats import parse_mechanism
from .readwrite.jsonformat import mechanism_from_dict
from .readwrite.pyslvs import looks_like_expression
from .readwrite.reports import mobility_error_dict
from .readwrite.table import Column
from .readwrite.textfile import MAX_FILE_BYTES, MAX_FILE_OPTION, read_text, readable_bytes
from .report import analyze
from .utils import paused_gc

__all__ = [
    "BATCH_COLUMNS",
    "BatchItem",
    "batch_entries",
    "batch_items",
    "classify_batch",
    "classify_item",
]

#: suffixes a directory is searched for
MECHANISM_SUFFIXES = (".edges", ".json", ".pyslvs")


@dataclass(frozen=True, slots=True)
class BatchItem:
    """One mechanism to classify: where it came from, its text and its form.

    ``form`` is ``"edges"`` (edge list, or a pyslvs expression), ``"json"`` (ours or
    pylinkage's), ``"pyslvs"`` (a project or expression) or ``"line"`` (a
    JSON line); ``problem`` is set instead of ``text`` when it could not be read.
    """

    source: str
    text: str
    form: str
    problem: str | None = None


def _file_item(path: str, max_bytes: int = MAX_FILE_BYTES) -> BatchItem:
    suffix = Path(path).suffix.lower()
    form = suffix[1:] if suffix in (".json", ".pyslvs") else "edges"
    try:
        text = read_text(path, max_bytes)
    except EdgeListError as error:
        return BatchItem(path, "", form, str(error))
    return BatchItem(path, text, form)


def _directory_files(directory: str) -> list[str]:
    found = []
    for root, dirs, files in os.walk(directory):
        dirs.sort()
        found.extend(
            os.path.join(root, name)
            for name in sorted(files)
            if Path(name).suffix.lower() in MECHANISM_SUFFIXES
        )
    return found


def batch_entries(inputs: Sequence[str]) -> list[tuple[str, str | None]]:
    """Every entry ``inputs`` name, in order, as ``(path, problem)``, nothing read yet.

    A directory gives its ``.edges``, ``.json`` and ``.pyslvs`` entries (sorted,
    sub-directories included), a glob its matches (sorted), ``-`` stands for standard input; a glob
    that matches nothing has its problem. An entry that is no regular file (a FIFO,
    a link to a device) is listed too: reading it gives its problem, and it is skipped.
    """
    entries: list[tuple[str, str | None]] = []
    for name in inputs:
        if name == "-":
            entries.append(("-", None))
        elif os.path.isdir(name):
            entries.extend((path, None) for path in _directory_files(name))
        elif os.path.lexists(name) or not glob.has_magic(name):
            entries.append((name, None))  # a missing file: the same error as for one file
        else:
            matches = sorted(glob.glob(name, recursive=True))
            if not matches:
                entries.append((name, f"{name}: no file matches"))
            for path in matches:
                if os.path.isdir(path):
                    entries.extend((found, None) for found in _directory_files(path))
                else:
                    entries.append((path, None))
    return entries


def _stdin_items(stdin: IO[str] | None, max_bytes: int) -> Iterator[BatchItem]:
    """One item per non-blank line of ``stdin``; a line longer than ``max_bytes`` is skipped."""
    if stdin is None:
        return
    max_bytes = readable_bytes(max_bytes)
    number = 0
    while True:
        line = stdin.readline(max_bytes + 1)
        if not line:
            return
        number += 1
        source = f"<stdin>:{number}"
        if len(line) > max_bytes and not line.endswith("\n"):
            while (rest := stdin.readline(max_bytes + 1)) and not rest.endswith("\n"):
                pass  # the rest of the line, dropped piece by piece
            reason = f"{source}: the line is longer than {memory_text(max_bytes)} (skipped; raise "
            yield BatchItem(source, "", "line", reason + f"the limit with {MAX_FILE_OPTION})")
        elif line.strip():
            yield BatchItem(source, line, "line")


def batch_items(
    inputs: Sequence[str], stdin: IO[str] | None = None, *, max_bytes: int = MAX_FILE_BYTES
) -> Iterator[BatchItem]:
    """The items named by ``inputs``, in order (see :func:`batch_entries`).

    Each file is read when its item is taken (regular files of at most
    ``max_bytes`` only: :func:`~structure.readwrite.textfile.read_text`), so that
    a long batch holds few texts at a time. A name that is no file, directory or
    matching glob, or an entry that cannot be read, is an item with a problem.
    """
    for path, problem in batch_entries(inputs):
        if problem is not None:
            yield BatchItem(path, "", "edges", problem)
        elif path == "-":
            yield from _stdin_items(stdin, max_bytes)
        else:
            yield _file_item(path, max_bytes)


def _mechanism(item: BatchItem) -> Mechanism:
    if item.form in ("json", "pyslvs"):  # ours or pylinkage's JSON; a pyslvs project
        return parse_mechanism(item.text, f".{item.form}", item.source)
    if item.form == "edges":
        if looks_like_expression(item.text):
            return parse_mechanism(item.text, ".edges", item.source)
        with paused_gc():
            return parse_edgelist(io.StringIO(item.text), source=item.source)
    try:
        data = json.loads(item.text)
    except json.JSONDecodeError as exc:
        problem = EdgeListProblem(1, item.text.strip(), f"invalid JSON: {exc.msg}")
        raise EdgeListError(item.source, [problem]) from None
    if isinstance(data, dict) and "joints" in data and "pairs" not in data:
        try:
            return row_mechanism(data)
        except (KeyError, TypeError, ValueError) as exc:
            problem = EdgeListProblem(1, "", f"not an atlas row: {exc}")
            raise EdgeListError(item.source, [problem]) from None
    return mechanism_from_dict(data, source=item.source)


#: columns of a batch table, in order, with their types
BATCH_COLUMNS: tuple[Column, ...] = (
    ("source", "str"),
    ("name", "str"),
    ("n", "int"),
    ("P5", "int"),
    ("P4", "int"),
    ("redundant", "int"),
    ("passive", "int"),
    ("W", "int"),
    ("drivers", "json"),
    ("mechanism_class", "int"),
    ("class", "str"),
    ("groups", "json"),
    ("formula", "str"),
    ("error", "str"),
)

_EMPTY = dict.fromkeys(name for name, _ in BATCH_COLUMNS)


def classify_item(item: BatchItem) -> dict[str, Any]:
    """The row of one item: counts, drivers, groups, class and formula, or its error.

    ``groups`` are the groups' labels in solve order (``'II(2,3)'``); the counts are
    those of ``assur classify --json`` (``n, P5, P4, redundant, passive, W``).
    """
    row: dict[str, Any] = {**_EMPTY, "source": item.source}
    if item.problem is not None:
        row["error"] = item.problem
        return row
    try:
        mechanism = _mechanism(item)
        row["name"] = mechanism.name
        report = analyze(mechanism)
    except MobilityError as exc:
        counts = mobility_error_dict(exc)
        row.update({k: counts[k] for k in ("n", "P5", "P4", "redundant", "passive", "W")
                    if k in counts})  # fmt: skip
        row["error"] = str(exc)
        return row
    except MechanismError as exc:
        row["error"] = str(exc)
        return row
    mob = report.mobility
    row.update(
        n=mob.n,
        P5=mob.P5,
        P4=mob.P4,
        redundant=mob.r,
        passive=mob.W_passive,
        W=mob.W,
        drivers=list(report.drivers),
        mechanism_class=report.mechanism_class,
        groups=[g.label for g in report.groups],
        formula=report.formula,
    )
    row["class"] = roman(report.mechanism_class)
    return row


def classify_batch(
    items: Iterable[BatchItem],
    *,
    jobs: int = 1,
    scheduler: str | None = None,
    dask_local: int = 0,
    progress: Callable[[int], None] | None = None,
) -> Iterator[dict[str, Any]]:
    """One row per item (:func:`batch_items`), in order.

    ``jobs``, ``scheduler`` and ``dask_local`` say where to run
    (:func:`~structure.parallel.ordered_map`); the rows are the same everywhere.

    Raises
    ------
    MissingExtraError
        Dask asked for but not installed.
    """
    chunk = 1 if jobs <= 1 and not (scheduler or dask_local) else 64
    rows = ordered_map(
        classify_item, items, jobs=jobs, scheduler=scheduler, dask_local=dask_local, chunk=chunk
    )
    for done, row in enumerate(rows, start=1):
        yield row
        if progress is not None:
            progress(done)
