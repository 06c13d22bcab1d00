"""Loads over the cycle: the drive's torque and the moments and forces that vary with the turn.

A machine's dynamics needs what acts on it over a whole turn of its driver:
the motor (``drive``) and the working loads (``cycle``), each given by a law
of the driver's rotation φ from the sketch and its angular velocity ω:

- a constant (``40``);
- a motor curve ``motor=M0,W0``: M = M0·(1 − ω/W0), M0 the torque at standstill
  (N·m), W0 the speed without load (rad/s); for the drive only;
- a table ``table=0:0,170:0,180:-5000,350:-5000,360:0``: values at driver
  angles in degrees, over one turn, linear between them and repeated every
  turn (a repeated angle is a jump: a press's working stroke);
- a formula ``formula=25000-7500*sin(3*phi)`` of ``phi`` (rad, within the turn)
  and ``omega`` (:mod:`structure.formulas`).

The statements, in the edge list::

    drive LINK LAW                          # the motor's torque on the driver, N·m
    cycle moment LINK LAW                   # a moment on LINK, N·m, counter-clockwise +
    cycle force LINK POINT angle=DEG LAW    # a force on LINK at POINT along DEG, N

and in JSON ``"drive": {"link": "1", "motor": [40, 150]}``, ``"cycle": [{"kind":
"force", "link": "3", "point": "C", "angle": 180, "table": [[0, 0], [180, -5000]]}]``.
This module holds their records and the checks both readers share.

>>> load = make_cycle_load("force", "3", law_from_token("table=0:0,180:-500"), "C", 180)
>>> load.statement
'cycle force 3 C angle=180 table=0:0,180:-500'
>>> make_cycle_load("drive", "1", law_from_token("motor=40,150")).law.numbers
(40.0, 150.0)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from .errors import StatementError, clipped
from .formulas import Formula, read_formula
from .kinds import TextEnum
from .validation import check_magnitude

__all__ = [
    "CycleLoad",
    "CycleLoadKind",
    "Law",
    "LawKind",
    "cycle_load_from_dict",
    "cycle_load_from_tokens",
    "cycle_load_to_dict",
    "law_from_token",
    "make_cycle_load",
    "make_law",
]


class LawKind(TextEnum):
    """How a load over the cycle is given: its key in the edge list and in JSON."""

    CONSTANT = "value"
    MOTOR = "motor"
    TABLE = "table"
    FORMULA = "formula"


class CycleLoadKind(TextEnum):
    """``drive`` (the motor's torque on the driver), ``moment`` or ``force`` on a link."""

    DRIVE = "drive"
    MOMENT = "moment"
    FORCE = "force"


@dataclass(frozen=True, slots=True)
class Law:
    """A law of φ and ω: its kind, its numbers, its formula.

    ``numbers`` holds ``(M,)`` for a constant, ``(M0, W0)`` for a motor curve,
    ``(φ1, v1, φ2, v2, ...)`` (degrees) for a table, nothing for a formula.
    Build it with :func:`make_law`.
    """

    kind: LawKind
    numbers: tuple[float, ...] = ()
    formula: Formula | None = None

    @property
    def uses_omega(self) -> bool:
        """Whether the law depends on the speed (a motor curve, a formula with ``omega``)."""
        if self.kind is LawKind.MOTOR:
            return True
        return self.formula is not None and self.formula.uses_omega

    @property
    def points(self) -> tuple[tuple[float, float], ...]:
        """A table's ``(angle in degrees, value)`` points."""
        n = self.numbers
        return tuple(zip(n[0::2], n[1::2], strict=True)) if self.kind is LawKind.TABLE else ()

    @property
    def token(self) -> str:
        """The law as one edge-list token."""
        if self.kind is LawKind.CONSTANT:
            return _text(self.numbers[0])
        if self.kind is LawKind.MOTOR:
            return f"motor={_text(self.numbers[0])},{_text(self.numbers[1])}"
        if self.kind is LawKind.TABLE:
            return "table=" + ",".join(f"{_text(a)}:{_text(v)}" for a, v in self.points)
        return f"formula={self.formula.text}"  # type: ignore[union-attr]

    def to_json(self) -> dict[str, Any]:
        """The law's key and value in a JSON object."""
        if self.kind is LawKind.CONSTANT:
            return {"value": self.numbers[0]}
        if self.kind is LawKind.MOTOR:
            return {"motor": list(self.numbers)}
        if self.kind is LawKind.TABLE:
            return {"table": [list(p) for p in self.points]}
        return {"formula": self.formula.text}  # type: ignore[union-attr]


@dataclass(frozen=True, slots=True)
class CycleLoad:
    """A load over the cycle: the drive, or a moment or a force on a link.

    ``point`` (the sketch point of the link the force acts at) and
    ``angle_deg`` (the force's direction in the world frame, degrees; a
    negative value pushes the other way) are a force's only.
    """

    kind: CycleLoadKind
    link: str
    law: Law
    point: str | None = None
    angle_deg: float | None = None
    line_no: int = field(default=0, compare=False)

    @property
    def angle(self) -> float | None:
        """The force's direction, rad."""
        return None if self.angle_deg is None else math.radians(self.angle_deg)

    @property
    def statement(self) -> str:
        """The canonical edge-list line."""
        if self.kind is CycleLoadKind.DRIVE:
            return f"drive {self.link} {self.law.token}"
        if self.kind is CycleLoadKind.MOMENT:
            return f"cycle moment {self.link} {self.law.token}"
        angle = _text(self.angle_deg)  # type: ignore[arg-type]
        return f"cycle force {self.link} {self.point} angle={angle} {self.law.token}"


def _text(value: float) -> str:
    """A number's shortest text (``40`` for 40.0)."""
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e15 else repr(value)


def _number(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise StatementError(f"{what} must be a number, not {clipped(text)!r}") from None
    if not math.isfinite(value):
        raise StatementError(f"{what} must be a finite number, not {clipped(text)!r}")
    return value


def make_law(kind: LawKind | str, numbers: Sequence[float] = (), text: str = "") -> Law:
    """Build a :class:`Law` with its checks.

    Raises
    ------
    StatementError
        A motor curve without two numbers or with W0 = 0; a table whose angles
        are not in [0, 360], go back, repeat an angle more than once (a jump) or
        end at 360° with another value than at 0°; a bad formula; a number that
        is not finite or beyond ±1e150.

    >>> make_law("table", (0, 1, 90, 2)).points
    ((0.0, 1.0), (90.0, 2.0))
    >>> make_law("table", (0, 1, 360, 2))
    Traceback (most recent call last):
    ...
    structure.errors.StatementError: a table over the turn ends where it begins: its values ...
    """
    try:
        kind = LawKind(kind)
    except ValueError:
        words = ", ".join(k.value for k in LawKind)
        raise StatementError(f"unknown law {kind!r} (use {words})") from None
    if kind is LawKind.FORMULA:
        return Law(kind, (), read_formula(text))
    values = tuple(float(v) for v in numbers)
    if not all(math.isfinite(v) for v in values):
        raise StatementError("the numbers of a load over the cycle must be finite")
    check_magnitude(*values)
    if kind is LawKind.CONSTANT and len(values) != 1:
        raise StatementError("a constant load takes one number")
    if kind is LawKind.MOTOR:
        if len(values) != 2:
            raise StatementError("a motor curve is motor=M0,W0: the torque at standstill (N·m) "
                                 "and the speed without load (rad/s)")  # fmt: skip
        if values[1] == 0:
            raise StatementError("the motor's speed without load W0 cannot be 0")
    if kind is LawKind.TABLE:
        _check_table(values)
    return Law(kind, values)


def _check_table(values: tuple[float, ...]) -> None:
    if not values or len(values) % 2:
        raise StatementError("a table is angle:value pairs, e.g. table=0:0,180:-500")
    angles, points = values[0::2], values[1::2]
    if any(a < 0 or a > 360 for a in angles):
        raise StatementError("a table's angles are degrees of the turn, from 0 to 360")
    for k in range(1, len(angles)):
        if angles[k] < angles[k - 1]:
            raise StatementError(
                f"a table's angles go in increasing order ({_text(angles[k])}° after "
                f"{_text(angles[k - 1])}°)"
            )
        if k >= 2 and angles[k] == angles[k - 2]:
            raise StatementError(f"a table gives {_text(angles[k])}° three times (twice is a jump)")
    if angles[0] == 0 and angles[-1] == 360 and points[0] != points[-1]:
        raise StatementError(
            "a table over the turn ends where it begins: its values at 0° and 360° must agree "
            f"({_text(points[0])} and {_text(points[-1])})"
        )


def law_from_token(token: str) -> Law:
    """The law of one edge-list token: a number, ``motor=``, ``table=`` or ``formula=``.

    Raises
    ------
    StatementError
        A token that is none of them, or a law :func:`make_law` refuses.

    >>> law_from_token("formula=-20*step(sin(phi))").uses_omega
    False
    """
    key, eq, value = token.partition("=")
    if not eq:
        return make_law(LawKind.CONSTANT, (_number(token, "a constant load"),))
    if key == "formula":
        return make_law(LawKind.FORMULA, text=value)
    if key == "motor":
        parts = value.split(",")
        return make_law(LawKind.MOTOR, [_number(p, "a motor curve's M0 and W0") for p in parts])
    if key == "table":
        numbers: list[float] = []
        for part in value.split(","):
            angle, colon, number = part.partition(":")
            if not colon:
                raise StatementError(f"a table's point is angle:value, not {clipped(part)!r}")
            numbers += [_number(angle, "a table's angle"), _number(number, "a table's value")]
        return make_law(LawKind.TABLE, numbers)
    if key == "value":
        return make_law(LawKind.CONSTANT, (_number(value, "a constant load"),))
    raise StatementError(
        f"unexpected {clipped(token)!r}: a load over the cycle is a number, motor=M0,W0, "
        "table=ANGLE:VALUE,... or formula=EXPRESSION"
    )


def make_cycle_load(
    kind: CycleLoadKind | str,
    link: str,
    law: Law,
    point: str | None = None,
    angle: float | None = None,
    *,
    line_no: int = 0,
) -> CycleLoad:
    """Build a :class:`CycleLoad` with its checks.

    Raises
    ------
    StatementError
        An unknown kind; a force without its point and direction, a drive or
        moment with them; a motor curve on anything but the drive.
    """
    try:
        kind = CycleLoadKind(kind)
    except ValueError:
        raise StatementError(
            f"unknown load over the cycle {kind!r} (use moment or force)"
        ) from None
    if kind is CycleLoadKind.FORCE:
        if point is None or angle is None:
            raise StatementError("a force over the cycle needs its point and angle=DEG")
        if not math.isfinite(angle):
            raise StatementError("a force's angle= must be a finite number of degrees")
        check_magnitude(angle)
    elif point is not None or angle is not None:
        raise StatementError(f"a {kind} over the cycle takes no point and no angle")
    if law.kind is LawKind.MOTOR and kind is not CycleLoadKind.DRIVE:
        raise StatementError("a motor curve is the drive's: write it on a 'drive' line")
    return CycleLoad(kind, link, law, point, None if angle is None else float(angle), line_no)


_DRIVE_USAGE = "expected 'drive LINK LAW' (LAW: a number, motor=M0,W0, table=... or formula=...)"
_MOMENT_USAGE = "expected 'cycle moment LINK LAW'"
_FORCE_USAGE = "expected 'cycle force LINK POINT angle=DEG LAW'"


def cycle_load_from_tokens(tokens: Sequence[str], line_no: int = 0) -> CycleLoad:
    """A ``drive`` or ``cycle`` line's load.

    Raises
    ------
    StatementError
        The line's problem.

    >>> cycle_load_from_tokens("cycle moment 3 formula=-20*(1+cos(phi))".split()).law.kind
    <LawKind.FORMULA: 'formula'>
    """
    if tokens[0] == "drive":
        if len(tokens) != 3:
            raise StatementError(_DRIVE_USAGE)
        return make_cycle_load("drive", tokens[1], law_from_token(tokens[2]), line_no=line_no)
    word = tokens[1] if len(tokens) > 1 else ""
    if word == "moment":
        if len(tokens) != 4:
            raise StatementError(_MOMENT_USAGE)
        return make_cycle_load("moment", tokens[2], law_from_token(tokens[3]), line_no=line_no)
    if word == "force":
        if len(tokens) != 6 or not tokens[4].startswith("angle="):
            raise StatementError(_FORCE_USAGE)
        angle = _number(tokens[4][len("angle=") :], "angle=")
        law = law_from_token(tokens[5])
        return make_cycle_load("force", tokens[2], law, tokens[3], angle, line_no=line_no)
    raise StatementError(f"{_MOMENT_USAGE} or {_FORCE_USAGE}")


def _name(value: Any) -> str | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, (str, int)):
        return str(value)
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return None


def _law_from_json(item: dict[str, Any]) -> Law:
    keys = [k.value for k in LawKind if k.value in item]
    if len(keys) != 1:
        raise StatementError("needs one of 'value', 'motor', 'table', 'formula'")
    key = keys[0]
    value = item[key]
    if key == "formula":
        if not isinstance(value, str):
            raise StatementError("'formula' must be a string")
        return make_law(LawKind.FORMULA, text=value)
    if key == "value":
        numbers = [value]
    elif key == "motor":
        numbers = value if isinstance(value, list) else [None]
    else:
        rows = value if isinstance(value, list) else [None]
        if not all(isinstance(r, list) and len(r) == 2 for r in rows):
            raise StatementError("'table' must be a list of [angle, value] pairs")
        numbers = [x for r in rows for x in r]
    if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in numbers):
        raise StatementError(f"'{key}' must hold finite numbers")
    try:
        return make_law(key, [float(x) for x in numbers])
    except OverflowError:
        raise StatementError(f"'{key}' must hold finite numbers") from None


def cycle_load_from_dict(kind: str, item: Any) -> CycleLoad:
    """The load of a JSON ``drive`` object (``kind`` ``"drive"``) or a ``cycle`` list item.

    Raises
    ------
    StatementError
        Unknown keys, values of the wrong shape, or a load the checks refuse.
    """
    if not isinstance(item, dict):
        raise StatementError("must be an object")
    if kind != "drive":
        kind = item.get("kind")
        if kind not in ("moment", "force"):
            raise StatementError("'kind' must be moment or force")
    allowed = {"link", *(k.value for k in LawKind)}
    allowed |= {"kind", "point", "angle"} if kind == "force" else set()
    allowed |= {"kind"} if kind == "moment" else set()
    extra = set(item) - allowed
    if extra:
        raise StatementError(f"unknown keys {sorted(extra)}")
    link = _name(item.get("link"))
    if link is None:
        raise StatementError("'link' must be a link name")
    law = _law_from_json(item)
    if kind != "force":
        return make_cycle_load(kind, link, law)
    point, angle = _name(item.get("point")), item.get("angle")
    if point is None:
        raise StatementError("'point' must be a point name")
    if not isinstance(angle, (int, float)) or isinstance(angle, bool):
        raise StatementError("'angle' must be a finite number of degrees")
    return make_cycle_load(kind, link, law, point, float(angle))


def cycle_load_to_dict(load: CycleLoad) -> dict[str, Any]:
    """The JSON object of a load over the cycle (the drive's has no ``kind``)."""
    out: dict[str, Any] = {} if load.kind is CycleLoadKind.DRIVE else {"kind": load.kind.value}
    out["link"] = load.link
    if load.kind is CycleLoadKind.FORCE:
        out["point"] = load.point
        out["angle"] = load.angle_deg
    out.update(load.law.to_json())
    return out
