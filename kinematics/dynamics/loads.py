"""The drive and the loads over the cycle, reduced to the driver: M_r(φ, ω).

Each load's reduced moment is its power at unit driver speed:

    M_r = Σ F·dr_P/dφ + Σ M·dθ/dφ + Σ m·g·dr_S/dφ + M_drive,

the velocity ratios (dr_P/dφ of the point a force acts at, dθ/dφ of the link
a moment acts on) coming from the kinematics at unit driver speed
(:func:`~kinematics.dynamics.reduced.reduced_properties`' motion). A load is a
:class:`LoadTerm`: a law of φ and ω (:mod:`structure.cycle`) times its ratio.
The file's ``force`` and ``moment`` statements act with their constant values
over the whole cycle, and ``gravity`` on every ``mass``; ``balance`` is the
kinetostatics' unknown, not a load, and is left out here.

>>> law = law_from_token("table=0:0,90:10,180:0")
>>> law_values(law, np.radians([45.0, 90.0, 270.0, 405.0]), 0.0).tolist()
[5.0, 10.0, 0.0, 5.0]
>>> law_values(law_from_token("motor=40,100"), 0.0, np.array([0.0, 50.0])).tolist()
[40.0, 20.0]
"""

from __future__ import annotations

import bisect
import functools
import math
from dataclasses import dataclass

import numpy as np

from structure.cycle import CycleLoad, CycleLoadKind, Law, LawKind, law_from_token
from structure.model import Mechanism

from ..errors import DynamicsError
from .reduced import ReducedProperties

__all__ = [
    "FROM_FILE",
    "LoadTerm",
    "law_text",
    "law_value",
    "law_values",
    "load_terms",
    "parse_drive",
    "table_breaks",
]

#: the drive of ``load_terms``: the file's ``drive`` statement (or none if it has none)
FROM_FILE = "file"

_TURN = 2 * math.pi


def law_values(law: Law, phi: np.ndarray | float, omega: np.ndarray | float) -> np.ndarray:
    """The law's value at driver angles ``phi`` (rad from the sketch, any turn) and speeds.

    A table and a formula read φ within the turn, [0, 2π); a table is linear
    between its points and repeats every turn.
    """
    phi = np.asarray(phi, dtype=float)
    omega = np.asarray(omega, dtype=float)
    shape = np.broadcast(phi, omega).shape
    if law.kind is LawKind.CONSTANT:
        return np.full(shape, law.numbers[0])
    if law.kind is LawKind.MOTOR:
        m0, w0 = law.numbers
        return np.broadcast_to(m0 * (1.0 - omega / w0), shape).astype(float)
    turn = np.mod(phi, _TURN)
    if law.kind is LawKind.TABLE:
        xp, fp = _table(law)
        return np.broadcast_to(np.interp(turn, xp, fp), shape).astype(float)
    return np.array(law.formula.evaluate(turn, omega), dtype=float)  # type: ignore[union-attr]


@functools.lru_cache(maxsize=256)
def _table(law: Law) -> tuple[list[float], list[float]]:
    """A table's angles (rad) and values, a point of the turns before and after added."""
    angles = [math.radians(a) for a in law.numbers[0::2]]
    values = list(law.numbers[1::2])
    xp = [angles[-1] - _TURN, *angles, angles[0] + _TURN]
    fp = [values[-1], *values, values[0]]
    return xp, fp


def law_value(law: Law, phi: float, omega: float) -> float:
    """:func:`law_values` at one angle and speed, with floats (the integrators' fast path)."""
    kind = law.kind
    if kind is LawKind.CONSTANT:
        return law.numbers[0]
    if kind is LawKind.MOTOR:
        return law.numbers[0] * (1.0 - omega / law.numbers[1])
    turn = phi % _TURN
    if kind is LawKind.TABLE:
        xp, fp = _table(law)
        k = min(max(bisect.bisect_right(xp, turn), 1), len(xp) - 1)
        x0, x1 = xp[k - 1], xp[k]
        if x1 == x0:
            return fp[k]
        return fp[k - 1] + (fp[k] - fp[k - 1]) * (turn - x0) / (x1 - x0)
    return law.formula.value(turn, omega)  # type: ignore[union-attr]


def table_breaks(law: Law | None) -> np.ndarray:
    """The angles (rad, within the turn) where a table's slope changes or it jumps."""
    if law is None or law.kind is not LawKind.TABLE:
        return np.zeros(0)
    return np.mod(np.radians(np.array(law.numbers[0::2])), _TURN)


def law_text(law: Law) -> str:
    """The law in words and symbols, for the answers: ``M0·(1 − ω/W0) = 40·(1 − ω/150)``."""
    if law.kind is LawKind.CONSTANT:
        return f"{law.numbers[0]:.6g}"
    if law.kind is LawKind.MOTOR:
        m0, w0 = law.numbers
        return f"motor curve {m0:.6g}·(1 − ω/{w0:.6g})"
    if law.kind is LawKind.TABLE:
        return f"table of {len(law.points)} points over the turn"
    return f"formula {law.formula.text}"  # type: ignore[union-attr]


@dataclass(frozen=True)
class LoadTerm:
    """One part of the reduced moment: ``law(φ, ω) · ratio(φ)`` (the ratio alone without a law).

    ``ratio`` holds the samples over the poses of the properties it was made
    for: dθ/dφ of the link a moment acts on, the projection of dr/dφ on a
    force's direction, 1 for the drive; for the file's constant loads and for
    gravity (``law`` None) their whole reduced moment. ``kind`` is ``"loads"``
    (the file's forces and moments), ``"gravity"``, ``"moment"``, ``"force"``
    or ``"drive"``; ``link`` and ``point`` say where it acts.
    """

    label: str
    law: Law | None
    ratio: np.ndarray
    drive: bool = False
    line_no: int = 0
    kind: str = "loads"
    link: str = ""
    point: str | None = None


def _point_rates(mechanism: Mechanism, props: ReducedProperties, link: str, point: str | None):
    xy = mechanism.coordinates(point) if point else None
    if xy is None:
        raise DynamicsError(f"point {point} of a load on link {link} needs coordinates")
    if props.motion is None or link not in props.motion.q:
        raise DynamicsError(f"link {link} is not solved by the kinematics: its load cannot act")
    _, v, _ = props.motion.point(link, np.array(xy, dtype=float))
    return v


def _link_rate(props: ReducedProperties, link: str) -> np.ndarray:
    if props.motion is None or link not in props.motion.q:
        raise DynamicsError(f"link {link} is not solved by the kinematics: its load cannot act")
    return props.motion.qd[link][:, 2]


def load_terms(
    mechanism: Mechanism,
    props: ReducedProperties,
    drive: Law | str | None = FROM_FILE,
    ratios: dict[str, float] | None = None,
) -> list[LoadTerm]:
    """The terms of M_r over the poses of ``props``: the file's loads, gravity, the drive.

    Parameters
    ----------
    mechanism : Mechanism
        Its ``force``, ``moment``, ``gravity`` and ``mass`` statements and its
        loads over the cycle.
    props : ReducedProperties
        The poses and the kinematics at unit driver speed.
    drive : Law, None or FROM_FILE
        A drive instead of the file's (``--drive``), None for no drive, or
        :data:`FROM_FILE` (the default) for the file's ``drive`` statement.
    ratios : dict, optional
        For a gear train without coordinates, each link's constant ω/ω_driver:
        moments only act then.

    Raises
    ------
    DynamicsError
        A force or gravity on a mechanism without coordinates, a load on a
        link the kinematics does not solve, a point without coordinates.
    """
    n = len(props.phi)
    terms: list[LoadTerm] = []
    fixed = np.zeros(n)
    gravity = np.zeros(2)
    for load in mechanism.loads:
        if load.kind == "gravity":
            gravity += np.array(load.values, dtype=float)
    has_fixed = False
    for load in mechanism.loads:
        if load.kind == "moment":
            fixed += load.values[0] * _rate(props, load.link, ratios)
            has_fixed = True
        elif load.kind == "force":
            if ratios is not None:
                raise DynamicsError("a force on a gear train needs the mechanism's coordinates")
            v = _point_rates(mechanism, props, load.link, load.point)
            fixed += v @ np.array(load.values, dtype=float)
            has_fixed = True
    if has_fixed:
        terms.append(LoadTerm("the file's forces and moments", None, fixed))
    if np.any(gravity != 0):
        weight = np.zeros(n)
        for load in mechanism.loads:
            if load.kind != "mass" or load.values[0] == 0:
                continue
            if ratios is not None:
                raise DynamicsError("gravity on a gear train needs the mechanism's coordinates")
            weight += load.values[0] * (
                _point_rates(mechanism, props, load.link, load.point) @ gravity
            )
        terms.append(LoadTerm("gravity", None, weight, kind="gravity"))
    for load in mechanism.cycle_loads:
        if load.kind is CycleLoadKind.DRIVE:
            continue
        terms.append(_cycle_term(mechanism, props, load, ratios))
    found = next((x for x in mechanism.cycle_loads if x.kind is CycleLoadKind.DRIVE), None)
    if found is not None and found.link != props.driver:
        raise DynamicsError(
            f"the drive acts on link {found.link}, but the driver is {props.driver}: "
            f"write 'driver {found.link}'"
        )
    law = (found.law if found is not None else None) if drive == FROM_FILE else drive
    if isinstance(law, Law):
        line = found.line_no if drive == FROM_FILE and found is not None else 0
        terms.append(
            LoadTerm(f"drive on {props.driver}", law, np.ones(n), True, line, "drive", props.driver)
        )
    return terms


def _rate(props: ReducedProperties, link: str, ratios: dict[str, float] | None) -> np.ndarray:
    if ratios is None:
        return _link_rate(props, link)
    if link not in ratios:
        raise DynamicsError(f"the moment on link {link} is not on a link of the train")
    return np.full(len(props.phi), float(ratios[link]))


def _cycle_term(
    mechanism: Mechanism,
    props: ReducedProperties,
    load: CycleLoad,
    ratios: dict[str, float] | None,
) -> LoadTerm:
    line = f" (line {load.line_no})" if load.line_no else ""
    if load.kind is CycleLoadKind.MOMENT:
        ratio = _rate(props, load.link, ratios)
        label = f"moment on {load.link}{line}"
        return LoadTerm(label, load.law, ratio, False, load.line_no, "moment", load.link)
    if ratios is not None:
        raise DynamicsError("a force on a gear train needs the mechanism's coordinates")
    v = _point_rates(mechanism, props, load.link, load.point)
    angle = load.angle or 0.0
    ratio = v @ np.array([math.cos(angle), math.sin(angle)])
    label = f"force on {load.link} at {load.point}{line}"
    return LoadTerm(label, load.law, ratio, False, load.line_no, "force", load.link, load.point)


def parse_drive(text: str) -> Law | None:
    """A ``--drive`` value: a law token of the edge list, or ``none`` (no drive).

    Raises
    ------
    StatementError
        A token that is no law.

    >>> parse_drive("motor=40,150").kind, parse_drive("none")
    (<LawKind.MOTOR: 'motor'>, None)
    """
    if text.strip().lower() == "none":
        return None
    return law_from_token(text.strip())
