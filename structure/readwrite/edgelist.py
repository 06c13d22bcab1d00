"""Read and write the edge-list format of a mechanism: the grammar, nothing more.

The reader splits lines into tokens, ``key=value`` options and numbers, and
builds each statement with :func:`~structure.model.make_pair` (and
``make_point``, ``make_load``, ``make_driver``), whose checks the JSON reader
shares; the writer prints each statement's canonical line.

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

Pair options: ``circle=R`` (R: friction circle); ``angle=DEG`` (P: slide
direction), ``span=S``, ``friction=F``; ``flat=L``, ``roller=L``,
``centers=O1,O2``, ``normal=DEG`` (H), and for a gear mesh the word ``gear``
with ``z=ZA,ZB``, ``internal=L``, ``module=M``. Loads: ``force LINK POINT fx
fy``, ``moment LINK M``, ``mass LINK m J S``, ``gravity gx gy``, ``balance
LINK POINT angle=DEG``; over the cycle (:mod:`structure.cycle`): ``drive LINK
LAW``, ``cycle moment LINK LAW``, ``cycle force LINK POINT angle=DEG LAW``. A cam
with a profile: ``cam CAM LINK FILE [at=DEG]`` (:mod:`structure.readwrite.camfile`).
A design target of the marker P (dimensional synthesis): ``target NAME x y
[input=DEG] [angle=DEG]``. The words ``name``, ``ground``, ``driver``, ``point``,
``cam``, ``drive``, ``cycle``, ``target`` and the load words are reserved at the
start of a line (unless the third word is a pair kind).

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
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..cams import CamRef
from ..cycle import CycleLoad, cycle_load_from_tokens
from ..errors import EdgeListError, EdgeListProblem, NumberError, StatementError
from ..expressions import read_number
from ..kinds import LoadKind, PairKind
from ..model import (
    Driver,
    Load,
    Mechanism,
    Pair,
    PointDef,
    Target,
    make_driver,
    make_load,
    make_pair,
    make_point,
    make_target,
)
from ..utils import paused_gc
from ..validation import (
    MAX_MAGNITUDE,
    check_driver_option,
    check_pair_links,
    check_pair_option,
    pair_kind,
    tooth_number,
    validated,
)
from .camfile import cam_from_tokens
from .jsonformat import mechanism_from_json
from .textfile import MAX_FILE_BYTES, open_user_file, read_text

__all__ = [
    "pair_from_tokens",
    "pair_tokens",
    "parse_edgelist",
    "read_edgelist",
    "write_edgelist",
]

#: the words that start a statement other than a pair (``name`` starts a title)
_STATEMENTS = frozenset(
    (
        "ground",
        "driver",
        "point",
        "cam",
        "drive",
        "cycle",
        "target",
        *(k.value for k in LoadKind),
    )
)
_KIND_OF = {k.value: k for k in PairKind}


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
    found = _Statements(source=source)
    pairs = found.pairs
    names = found.names
    # pair k's id is the int that numbers line k (k is at most its own line): a large file
    # then keeps one int a line, not two a pair (issue 11)
    line_numbers: list[int] = []
    for line_no, raw in enumerate(lines, start=1):
        line_numbers.append(line_no)
        text = raw.split("#", 1)[0] if "#" in raw else raw
        tokens = text.split()
        if not tokens:
            continue
        head = tokens[0]
        try:
            # a statement word followed by a pair kind is a pair whose first link has that
            # name (no statement has R, P or H third); a `name` line is always a title
            if head == "name":
                found.name = text.strip()[4:].strip()
            elif head not in _STATEMENTS or (len(tokens) >= 3 and tokens[2] in _KIND_OF):
                pairs.append(_pair(tokens, line_numbers[len(pairs)], line_no, names))
            else:
                found.read_statement(tokens, line_no)
        except StatementError as exc:
            found.problems.append(EdgeListProblem(line_no, raw, exc.reason))
    if found.problems:
        raise EdgeListError(source, found.problems)
    mechanism = Mechanism(
        tuple(pairs),
        found.ground if found.ground is not None else "0",
        tuple(found.drivers),
        found.points,
        found.name,
        source,
        tuple(found.loads),
        cams=tuple(found.cams),
        cycle_loads=tuple(found.cycle_loads),
        targets=tuple(found.targets),
    )
    return validated(mechanism, ground_line=found.ground_line)


@dataclass
class _Statements:
    """The statements of one description, gathered line by line, and its problems."""

    name: str = ""
    ground: str | None = None
    ground_line: int = 0
    pairs: list[Pair] = field(default_factory=list)
    drivers: list[Driver] = field(default_factory=list)
    points: dict[str, PointDef] = field(default_factory=dict)
    loads: list[Load] = field(default_factory=list)
    cycle_loads: list[CycleLoad] = field(default_factory=list)
    targets: list[Target] = field(default_factory=list)
    problems: list[EdgeListProblem] = field(default_factory=list)
    cams: list[CamRef] = field(default_factory=list)
    #: where the description comes from: a cam's program file is read beside it
    source: str = "<string>"
    #: each name of a link once: a link is named on ~3 lines of a large file, and its pairs
    #: share one string (a local table, freed after the read, unlike sys.intern's); the
    #: point of a plain pair line is not looked up (most points are named on one line only)
    names: dict[str, str] = field(default_factory=dict)

    def read_statement(self, tokens: list[str], line_no: int) -> None:
        """Read a ``ground``, ``driver``, ``point`` or load line; raise StatementError if bad."""
        head = tokens[0]
        if head == "ground":
            self._read_ground(tokens, line_no)
        elif head == "driver":
            self.drivers.append(_driver(tokens, line_no))
        elif head == "point":
            self._add_point(_point(tokens, line_no))
        elif head == "cam":
            self.cams.append(cam_from_tokens(tokens, line_no, self.source))
        elif head in ("drive", "cycle"):
            self.cycle_loads.append(cycle_load_from_tokens(tokens, line_no))
        elif head == "target":
            self._add_target(_target(tokens, line_no))
        else:
            self.loads.append(_load(tokens, line_no))

    def _read_ground(self, tokens: list[str], line_no: int) -> None:
        if len(tokens) != 2:
            raise StatementError("expected 'ground LINK'")
        if self.ground is not None:
            raise StatementError(f"ground already given on line {self.ground_line}")
        self.ground, self.ground_line = tokens[1], line_no

    def _add_point(self, point: PointDef) -> None:
        if point.name in self.points:
            first = self.points[point.name].line_no
            raise StatementError(f"point {point.name} already given on line {first}")
        self.points[point.name] = point

    def _add_target(self, target: Target) -> None:
        first = next((t.line_no for t in self.targets if t.name == target.name), None)
        if first is not None:
            raise StatementError(f"target {target.name} already given on line {first}")
        self.targets.append(target)


# ----------------------------------------------------------------------------- pairs
def pair_from_tokens(tokens: list[str], pair_id: int, line_no: int) -> tuple[Pair | None, str]:
    """Read ``a b KIND [POINT] [key=value ...]`` into a Pair, or say what is wrong.

    Returns ``(pair, "")`` or ``(None, reason)``; never raises on bad tokens.

    >>> pair_from_tokens("3 0 P C angle=90".split(), 1, 5)[0].angle
    1.5707963267948966
    >>> pair_from_tokens("1 2 Q".split(), 1, 5)[1]
    "unknown pair kind 'Q' (use R, P or H)"
    """
    try:
        return _pair(tokens, pair_id, line_no, {}), ""
    except StatementError as exc:
        return None, exc.reason


def _pair(tokens: list[str], pair_id: int, line_no: int, names: dict[str, str]) -> Pair:
    """The pair of a line, its link names shared through ``names`` (see :class:`_Statements`).

    The lines of nearly every large file, ``a b KIND [POINT]`` and ``a b P
    POINT angle=DEG``, are built here with :func:`make_pair`'s checks for
    them (two different links, a finite angle within
    :data:`~structure.validation.MAX_MAGNITUDE`); any other line, and any
    that fails those checks, is read by :func:`_pair_with_options`, which
    says what is wrong.
    """
    size = len(tokens)
    kind = _KIND_OF.get(tokens[2]) if 3 <= size <= 5 else None
    if kind is None or tokens[0] == tokens[1]:
        return _pair_with_options(tokens, pair_id, line_no, names)
    a = names.setdefault(tokens[0], tokens[0])
    b = names.setdefault(tokens[1], tokens[1])
    if size == 3:
        return Pair.plain(pair_id, kind, a, b, line_no=line_no)
    point = tokens[3]
    if "=" in point or point == "gear":
        return _pair_with_options(tokens, pair_id, line_no, names)
    if size == 4:
        return Pair.plain(pair_id, kind, a, b, point, line_no=line_no)
    angle = _slide_angle(tokens[4]) if kind is PairKind.P else None
    if angle is None:
        return _pair_with_options(tokens, pair_id, line_no, names)
    return Pair.plain(pair_id, kind, a, b, point, angle, line_no)


def _slide_angle(token: str) -> float | None:
    """The degrees of an ``angle=DEG`` token that :func:`make_pair` takes, else None."""
    key, _, text = token.partition("=")
    if key != "angle":
        return None
    angle = _option_number(text)
    return angle if abs(angle) <= MAX_MAGNITUDE else None  # NaN and infinities fail too


def _pair_with_options(
    tokens: list[str], pair_id: int, line_no: int, names: dict[str, str]
) -> Pair:
    """The grammar of any pair line; the checks of its content are :func:`make_pair`'s.

    Raises
    ------
    StatementError
        The first problem of the line, read from the left.
    """
    if len(tokens) < 3:
        raise StatementError("a pair needs at least 'a b KIND'")
    a = names.setdefault(tokens[0], tokens[0])
    b = names.setdefault(tokens[1], tokens[1])
    kind = pair_kind(tokens[2])
    rest = tokens[3:]
    gear = kind is PairKind.H and "gear" in rest
    if gear:
        rest = [t for t in rest if t != "gear"]
    point = None
    if rest and "=" not in rest[0]:
        point, rest = names.setdefault(rest[0], rest[0]), rest[1:]
    options: dict[str, str] = {}
    for tok in rest:
        key, eq, value = tok.partition("=")
        if not eq or not key or not value:
            reason = f"unexpected token {tok!r} (options are key=value)"
            raise _grammar_problem(kind, a, b, options, reason)
        if key in options:
            raise _grammar_problem(kind, a, b, options, f"option {key!r} given twice")
        if key in _NOT_OPTIONS:  # a parameter of make_pair's own, no option of any pair
            _grammar_problem(kind, a, b, options, "")
            check_pair_option(kind, key)
        options[key] = value
    if not options:
        return make_pair(pair_id, kind, a, b, point, gear=gear, line_no=line_no)
    typed = {key: _OPTION_READERS.get(key, str)(text) for key, text in options.items()}
    return make_pair(pair_id, kind, a, b, point, gear=gear, line_no=line_no, **typed)


#: the names of :func:`make_pair`'s own parameters: ``a=b`` on a line is refused as the
#: unknown option it is, never passed on as a second value of ``a``
_NOT_OPTIONS = frozenset(("pair_id", "kind", "a", "b", "point", "gear", "line_no"))


def _grammar_problem(
    kind: PairKind, a: str, b: str, earlier: Iterable[str], reason: str
) -> StatementError:
    """The problem of a pair line whose grammar fails at some token.

    The model's checks of what comes before that token (the links, the keys
    of the earlier options) are reported first, as the line is read from the
    left: their problem, if any, is raised here; else ``reason`` is returned.
    """
    check_pair_links(a, b)
    for key in earlier:
        check_pair_option(kind, key)
    return StatementError(reason)


def _option_number(text: str) -> float:
    """The number an option's text says, or NaN when it says none.

    :func:`make_pair` refuses NaN with the option's own reason, the same as
    for a number out of its range.
    """
    try:
        return float(text)
    except ValueError:
        return math.nan


def _option_names(text: str) -> tuple[str | None, ...]:
    """``O1,O2`` as names, an empty one as None."""
    return tuple(part or None for part in text.split(","))


def _tooth_numbers(text: str) -> tuple[int | str | None, ...]:
    return tuple(tooth_number(part) for part in text.split(","))


_OPTION_READERS: dict[str, Any] = {
    "angle": _option_number,
    "normal": _option_number,
    "span": _option_number,
    "friction": _option_number,
    "circle": _option_number,
    "module": _option_number,
    "centers": _option_names,
    "z": _tooth_numbers,
}


# ------------------------------------------------------------------ loads, drivers, points
#: where each load's link, point and numbers stand on its line (token positions)
_LOAD_LAYOUT: dict[LoadKind, tuple[int, int | None, int | None, tuple[int, ...]]] = {
    # kind: (tokens, link, point, numbers)
    LoadKind.FORCE: (5, 1, 2, (3, 4)),
    LoadKind.MOMENT: (3, 1, None, (2,)),
    LoadKind.MASS: (5, 1, 4, (2, 3)),
    LoadKind.GRAVITY: (3, None, None, (1, 2)),
    LoadKind.BALANCE: (4, 1, 2, (3,)),
}


def _load(tokens: list[str], line_no: int) -> Load:
    kind = LoadKind(tokens[0])
    usage = f"expected '{kind.usage}'"
    size, link_at, point_at, numbers_at = _LOAD_LAYOUT[kind]
    if len(tokens) != size:
        raise StatementError(usage)
    texts = [tokens[k] for k in numbers_at]
    if kind is LoadKind.BALANCE:
        key, eq, texts[0] = texts[0].partition("=")
        if key != "angle" or not eq:
            raise StatementError(usage)
    values: list[float] = []
    exact: list[str | None] = []
    for text in texts:
        try:
            value, written = _number_or_expression(text)
        except ValueError as exc:
            generic = f"{usage}: numbers must be finite (or exact expressions like 500*sqrt(2))"
            raise StatementError(_with_reason(generic, exc)) from None
        values.append(value)
        exact.append(written)
    link = "" if link_at is None else tokens[link_at]
    point = None if point_at is None else tokens[point_at]
    written = tuple(exact) if any(exact) else ()
    return make_load(kind, link, point, values, line_no=line_no, exact=written)


def _number_or_expression(text: str) -> tuple[float, str | None]:
    """A finite decimal (no text kept), or an exact expression (kept as written).

    Raises
    ------
    NumberError
        The text is neither, with :func:`~structure.expressions.read_number`'s
        reason (bad syntax, too long, too deep, too many digits, too large an
        exponent, not finite).
    """
    try:
        return _number(text), None
    except ValueError:
        value, _ = read_number(text)
        return value, text


def _with_reason(generic: str, error: ValueError) -> str:
    """``generic``, followed by the expression reader's own reason when it gave one.

    >>> _with_reason("numbers must be finite", NumberError("'1e999' has an exponent beyond ±400"))
    "numbers must be finite: '1e999' has an exponent beyond ±400"
    """
    if isinstance(error, NumberError):
        return f"{generic}: {error.reason}"
    return generic


def _driver(tokens: list[str], line_no: int) -> Driver:
    if len(tokens) < 2 or "=" in tokens[1]:
        raise StatementError("expected 'driver LINK [omega=.. epsilon=.. v=.. a=..]'")
    motion: list[tuple[str, float]] = []
    for tok in tokens[2:]:
        key, eq, value = tok.partition("=")
        if not eq:
            raise StatementError(
                f"unexpected token {tok!r} (one driver per line; options are key=value)"
            )
        check_driver_option(key)
        try:
            motion.append((key, _number(value)))
        except ValueError:
            raise StatementError(
                f"driver option {key} needs a finite number, not {value!r}"
            ) from None
    return make_driver(tokens[1], motion, line_no=line_no)


def _point(tokens: list[str], line_no: int) -> PointDef:
    if len(tokens) not in (4, 5):
        raise StatementError("expected 'point NAME x y [on=LINK]'")
    on = None
    if len(tokens) == 5:
        key, eq, value = tokens[4].partition("=")
        if key != "on" or not eq or not value:
            raise StatementError(f"unexpected token {tokens[4]!r} (only on=LINK may follow x y)")
        on = value
    values: list[float] = []
    exact: list[str | None] = []
    unread: ValueError | None = None
    for token in tokens[2:4]:
        try:
            value, written = _number_or_expression(token)
        except ValueError as exc:
            value, written = math.nan, None  # make_point refuses it
            unread = unread or exc
        values.append(value)
        exact.append(written)
    try:
        return make_point(
            tokens[1], values[0], values[1], on, line_no=line_no, exact=(exact[0], exact[1])
        )
    except StatementError as refused:
        if unread is None:
            raise
        raise StatementError(_with_reason(refused.reason, unread)) from None


def _target(tokens: list[str], line_no: int) -> Target:
    """``target NAME x y [input=DEG] [angle=DEG]`` (a design target of the marker P)."""
    usage = "expected 'target NAME x y [input=DEG] [angle=DEG]'"
    if not 4 <= len(tokens) <= 6:
        raise StatementError(usage)
    options: dict[str, float] = {}
    for tok in tokens[4:]:
        key, eq, text = tok.partition("=")
        if key not in ("input", "angle") or not eq or key in options:
            raise StatementError(f"unexpected token {tok!r} ({usage})")
        options[key] = _option_number(text)
    try:
        x, y = _number(tokens[2]), _number(tokens[3])
    except ValueError:
        x = y = math.nan  # make_target refuses it with its reason
    return make_target(
        tokens[1], x, y, options.get("input"), options.get("angle"), line_no=line_no
    )


def read_edgelist(path: str | os.PathLike[str], max_bytes: int = MAX_FILE_BYTES) -> Mechanism:
    """Read a mechanism from an edge-list file (UTF-8).

    A ``.json`` file is read as the JSON form of the same model. Only a regular
    file of at most ``max_bytes`` is read (:func:`~.textfile.open_user_file`).

    Raises
    ------
    EdgeListError
        On any problem in the file, or when it cannot be read.
    """
    path = Path(path)
    if path.suffix.lower() == ".json":
        return mechanism_from_json(read_text(path, max_bytes), source=str(path))
    with open_user_file(path, max_bytes) as handle, paused_gc():
        return parse_edgelist(handle, source=str(path))


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
    out.extend(_cam_statement(mechanism, ref) for ref in mechanism.cams)
    out.extend(load.statement for load in mechanism.cycle_loads)
    out.extend(t.statement for t in mechanism.targets)
    return "\n".join(out) + "\n"


def _cam_statement(mechanism: Mechanism, ref: CamRef) -> str:
    """A ``cam`` line: it needs the program's file, which a spec read inline from JSON has not.

    Raises
    ------
    EdgeListError
        The cam's program is held inline (no file to refer to).
    """
    if ref.path is None:
        reason = (
            f"{ref.label}: its program is held inline (read from JSON), and the edge list refers "
            "to a program file: write the mechanism as JSON, or save the program to a file "
            "(assur cam SPEC -o M.edges writes both)"
        )
        raise EdgeListError(mechanism.source, [EdgeListProblem(0, "", reason)])
    return ref.statement
