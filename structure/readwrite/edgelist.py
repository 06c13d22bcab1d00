"""Read and write the edge-list format of a mechanism.

One statement per line, ``#`` starts a comment, tokens are separated by
whitespace::

    name  four-bar linkage          # optional title
    ground 0                        # optional, default 0
    driver 1 omega=20               # one line per driving link
    0 1 R A                         # a b KIND [POINT] [key=value ...]
    1 2 R B
    2 3 R C
    3 0 R D
    point A 0 0                     # sketch coordinates, metres
    point D 0.4 0
    point M 0.1 0.2 on=2            # a marker fixed to link 2

Pair options: ``angle=DEG`` (P: slide direction), ``flat=L``, ``roller=L``,
``centers=O1,O2``, ``normal=DEG`` (H). The words ``name``, ``ground``,
``driver`` and ``point`` are reserved at the start of a line.

>>> m = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"])
>>> m.driver_links, len(m.pairs)
(('1',), 4)
>>> print(write_edgelist(m), end="")
ground 0
driver 1
0 1 R A
1 2 R B
2 3 R C
3 0 R D
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from pathlib import Path

from ..errors import EdgeListError, EdgeListProblem
from ..expressions import read_number
from ..model import (
    DRIVER_KEYS,
    LOAD_KINDS,
    Driver,
    Load,
    Mechanism,
    Pair,
    PointDef,
    pair_from_tokens,
    validated,
)
from ..utils import paused_gc
from .jsonformat import mechanism_from_json

__all__ = ["pair_tokens", "parse_edgelist", "read_edgelist", "write_edgelist"]

_KEYWORDS = ("name", "ground", "driver", "point", *LOAD_KINDS)


def _number(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(text)
    return value


def parse_edgelist(lines: Iterable[str], source: str = "<string>") -> Mechanism:
    """Parse edge-list lines into a validated :class:`Mechanism`.

    Every problem of the file is gathered and raised once as an
    :class:`~structure.errors.EdgeListError` naming the source and line.

    Raises
    ------
    EdgeListError
        Unknown pair kind or option, missing or extra tokens, bad numbers,
        a pair from a link to itself, duplicate points, a compound hinge with
        a cycle, a link or driver not joined to the ground, an empty file.
    """
    problems: list[EdgeListProblem] = []
    loads: list[Load] = []
    pairs: list[Pair] = []
    drivers: list[Driver] = []
    points: dict[str, PointDef] = {}
    name = ""
    ground: str | None = None
    ground_line = 0

    for line_no, raw in enumerate(lines, start=1):
        text = raw.split("#", 1)[0]
        tokens = text.split()
        if not tokens:
            continue
        head = tokens[0]
        # a statement word followed by a pair kind is a pair whose first link has that
        # name (no statement has R, P or H third); a `name` line is always a title
        if head == "name" or (
            head in _KEYWORDS and not (len(tokens) >= 3 and tokens[2] in ("R", "P", "H"))
        ):
            if head == "name":
                name = text.strip()[4:].strip()
            elif head == "ground":
                if len(tokens) != 2:
                    problems.append(EdgeListProblem(line_no, raw, "expected 'ground LINK'"))
                elif ground is not None:
                    problems.append(
                        EdgeListProblem(line_no, raw, f"ground already given on line {ground_line}")
                    )
                else:
                    ground, ground_line = tokens[1], line_no
            elif head == "driver":
                driver, why = _driver(tokens, line_no)
                if driver is None:
                    problems.append(EdgeListProblem(line_no, raw, why))
                else:
                    drivers.append(driver)
            elif head in LOAD_KINDS:
                load, why = _load(tokens, line_no)
                if load is None:
                    problems.append(EdgeListProblem(line_no, raw, why))
                else:
                    loads.append(load)
            else:
                point, why = _point(tokens, line_no)
                if point is None:
                    problems.append(EdgeListProblem(line_no, raw, why))
                elif point.name in points:
                    first = points[point.name].line_no
                    problems.append(
                        EdgeListProblem(
                            line_no, raw, f"point {point.name} already given on line {first}"
                        )
                    )
                else:
                    points[point.name] = point
            continue
        pair, why = pair_from_tokens(tokens, len(pairs) + 1, line_no)
        if pair is None:
            problems.append(EdgeListProblem(line_no, raw, why))
        else:
            pairs.append(pair)
    if problems:
        raise EdgeListError(source, problems)
    mechanism = Mechanism(
        tuple(pairs),
        ground if ground is not None else "0",
        tuple(drivers),
        points,
        name,
        source,
        tuple(loads),
    )
    return validated(mechanism, ground_line=ground_line)


_LOAD_USAGE = {
    "force": "force LINK POINT fx fy",
    "moment": "moment LINK M",
    "mass": "mass LINK m J S",
    "gravity": "gravity gx gy",
    "balance": "balance LINK POINT angle=DEG",
}


def _written(exact: list[str | None]) -> tuple[str | None, ...]:
    return tuple(exact) if any(exact) else ()


def _load(tokens: list[str], line_no: int) -> tuple[Load | None, str]:
    kind = tokens[0]
    usage = f"expected '{_LOAD_USAGE[kind]}'"
    exact: list[str | None] = []

    def value(token: str) -> float:
        try:
            number = _number(token)
        except ValueError:
            number, _ = read_number(token)
            exact.append(token)
            return number
        exact.append(None)
        return number

    try:
        if kind == "gravity":
            if len(tokens) != 3:
                return None, usage
            values = (value(tokens[1]), value(tokens[2]))
            return Load(kind, "", None, values, line_no, _written(exact)), ""
        if kind == "moment":
            if len(tokens) != 3:
                return None, usage
            return Load(kind, tokens[1], None, (value(tokens[2]),), line_no, _written(exact)), ""
        if kind == "force":
            if len(tokens) != 5:
                return None, usage
            values = (value(tokens[3]), value(tokens[4]))
            return Load(kind, tokens[1], tokens[2], values, line_no, _written(exact)), ""
        if kind == "mass":
            if len(tokens) != 5:
                return None, usage
            m, inertia = value(tokens[2]), value(tokens[3])
            if m < 0 or inertia < 0:
                return None, "mass and moment of inertia cannot be negative"
            return Load(kind, tokens[1], tokens[4], (m, inertia), line_no, _written(exact)), ""
        key, eq, text = tokens[3].partition("=") if len(tokens) == 4 else ("", "", "")
        if key != "angle" or not eq:
            return None, usage
        return Load(kind, tokens[1], tokens[2], (value(text),), line_no, _written(exact)), ""
    except ValueError:
        return None, f"{usage}: numbers must be finite (or exact expressions like 500*sqrt(2))"


def _driver(tokens: list[str], line_no: int) -> tuple[Driver | None, str]:
    if len(tokens) < 2 or "=" in tokens[1]:
        return None, "expected 'driver LINK [omega=.. epsilon=.. v=.. a=..]'"
    motion: list[tuple[str, float]] = []
    for tok in tokens[2:]:
        key, eq, value = tok.partition("=")
        if not eq:
            return None, f"unexpected token {tok!r} (one driver per line; options are key=value)"
        if key not in DRIVER_KEYS:
            return None, f"unknown driver option {key!r} (use {', '.join(DRIVER_KEYS)})"
        try:
            motion.append((key, _number(value)))
        except ValueError:
            return None, f"driver option {key} needs a finite number, not {value!r}"
    return Driver(tokens[1], tuple(motion), line_no), ""


def _point(tokens: list[str], line_no: int) -> tuple[PointDef | None, str]:
    if len(tokens) not in (4, 5):
        return None, "expected 'point NAME x y [on=LINK]'"
    on = None
    if len(tokens) == 5:
        key, eq, value = tokens[4].partition("=")
        if key != "on" or not eq or not value:
            return None, f"unexpected token {tokens[4]!r} (only on=LINK may follow x y)"
        on = value
    values: list[float] = []
    exact: list[str | None] = []
    for token in tokens[2:4]:
        try:
            values.append(_number(token))
            exact.append(None)
        except ValueError:
            try:
                value, _ = read_number(token)
            except ValueError:
                return None, (
                    "point coordinates must be finite numbers (metres) or exact expressions "
                    "such as 0.2*sqrt(3)"
                )
            values.append(value)
            exact.append(token)
    return PointDef(tokens[1], values[0], values[1], on, line_no, (exact[0], exact[1])), ""


def read_edgelist(path: str | os.PathLike[str]) -> Mechanism:
    """Read a mechanism from an edge-list file (UTF-8).

    A ``.json`` file is read as the JSON form of the same model.

    Raises
    ------
    EdgeListError
        On any problem in the file, or when it cannot be read.
    """
    path = Path(path)
    try:
        if path.suffix.lower() == ".json":
            return mechanism_from_json(path.read_text(encoding="utf-8-sig"), source=str(path))
        with path.open(encoding="utf-8-sig") as handle, paused_gc():
            return parse_edgelist(handle, source=str(path))
    except OSError as exc:
        raise EdgeListError(
            str(path), [EdgeListProblem(0, "", f"cannot read: {exc.strerror}")]
        ) from exc
    except UnicodeDecodeError as exc:
        raise EdgeListError(str(path), [EdgeListProblem(0, "", "not a UTF-8 text file")]) from exc


def pair_tokens(pair: Pair) -> list[str]:
    """The tokens of ``pair``'s edge-list line."""
    return pair.statement.split()


def write_edgelist(mechanism: Mechanism) -> str:
    """The edge-list text of ``mechanism``; parsing it gives an equal mechanism."""
    out: list[str] = []
    if mechanism.name:
        out.append(f"name {mechanism.name}")
    out.append(f"ground {mechanism.ground}")
    out.extend(d.statement for d in mechanism.drivers)
    out.extend(p.statement for p in mechanism.pairs)
    out.extend(p.statement for p in mechanism.points.values())
    out.extend(load.statement for load in mechanism.loads)
    return "\n".join(out) + "\n"
