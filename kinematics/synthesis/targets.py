"""Targets and poses read from text: rows of numbers, a header line allowed, ``#`` comments.

``x,y`` (a path), ``x,y,crank_deg`` (a path with prescribed timing) or
``x,y,angle_deg`` (a pose of motion generation), separated by commas or
blanks. Every bad line is reported at once, with its number, as an
:class:`~structure.errors.EdgeListError`.

>>> read_rows(["x,y", "0, 1", "2 3  # the second"], 2).tolist()
[[0.0, 1.0], [2.0, 3.0]]
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable

import numpy as np

from structure.errors import EdgeListError, EdgeListProblem

__all__ = ["read_rows", "read_rows_file"]


def read_rows(lines: Iterable[str], columns: int, source: str = "<rows>") -> np.ndarray:
    """The rows of ``columns`` numbers each, shape (rows, columns).

    Raises
    ------
    EdgeListError
        A line that is not a row of ``columns`` finite numbers (a first line of
        words is a header and is skipped), or no row at all.
    """
    rows: list[list[float]] = []
    problems: list[EdgeListProblem] = []
    first = True
    for line_no, raw in enumerate(lines, start=1):
        tokens = raw.split("#", 1)[0].replace(",", " ").replace(";", " ").split()
        if not tokens:
            continue
        try:
            values = [float(t) for t in tokens]
        except ValueError:
            if first and not any(_is_number(t) for t in tokens):
                first = False
                continue
            problems.append(EdgeListProblem(line_no, raw.rstrip("\n"), "not a row of numbers"))
            first = False
            continue
        first = False
        if len(values) != columns:
            reason = f"{len(values)} value(s): each row needs {columns}"
            problems.append(EdgeListProblem(line_no, raw.rstrip("\n"), reason))
        elif not all(math.isfinite(v) and abs(v) <= 1e150 for v in values):
            problems.append(EdgeListProblem(line_no, raw.rstrip("\n"), "numbers must be finite"))
        else:
            rows.append(values)
    if not rows and not problems:
        problems.append(EdgeListProblem(0, "", "no rows: one line per point is needed"))
    if problems:
        raise EdgeListError(source, problems)
    return np.array(rows, dtype=float)


def _is_number(token: str) -> bool:
    try:
        float(token)
    except ValueError:
        return False
    return True


def read_rows_file(path: str | os.PathLike[str], columns: int) -> np.ndarray:
    """:func:`read_rows` of a file; an unreadable file is an :class:`EdgeListError` too."""
    try:
        with open(path, encoding="utf-8-sig") as handle:
            lines = handle.readlines()
    except (OSError, UnicodeDecodeError) as exc:
        reason = getattr(exc, "strerror", None) or str(exc)
        raise EdgeListError(
            str(path), [EdgeListProblem(0, "", f"cannot read it: {reason}")]
        ) from exc
    return read_rows(lines, columns, str(path))
