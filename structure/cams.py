"""Disc cams as data: the follower program and the follower, read and checked, never evaluated.

A cam design (the ``assur cam`` spec, and the program a mechanism's ``cam``
statement refers to) is a :class:`CamSpec`: the cam speed, the follower
(translating or oscillating; knife-edge, roller or flat-faced), the base
circle and the program, a list of :class:`CamSegment` s over the cam angle
(rise, dwell, return) whose laws are named by :class:`MotionLaw`. This module
reads the JSON form (:func:`cam_spec_from_dict`), writes it back
(:func:`cam_spec_to_dict`) and checks what the data alone can tell: the
segments add up to 360°, the program brings the follower home, every law is
known, every number is finite and in its range. The laws themselves are
evaluated by :mod:`kinematics.cams` (structure never imports kinematics).

::

    {"name": "disc cam, offset roller", "omega": 10.0,
     "follower": {"motion": "translating", "contact": "roller",
                  "offset": 0.005, "roller_radius": 0.01},
     "base_radius": 0.04,
     "segments": [{"law": "cycloidal", "lift": 0.02, "angle": 120},
                  {"law": "dwell", "angle": 60},
                  {"law": "modified-trapezoid", "lift": -0.02, "angle": 120},
                  {"law": "dwell", "angle": 60}]}

Lengths in metres, angles in degrees (an oscillating follower's lifts too),
``omega`` in rad/s (counter-clockwise positive: its sign is the sense the cam
turns in, the program runs forward in time either way). A polynomial segment
is fitted to boundary conditions ``{"law": "polynomial", "angle": 90, "bc":
[{"at": 0, "s": 0, "v": 0, "a": 0}, {"at": 90, "s": 0.02, "v": 0, "a": 0}]}``:
``at`` in degrees from the segment's start, ``s`` the follower's displacement
(absolute, as the SVAJ diagram shows it), ``v``, ``a``, ``j`` its velocity,
acceleration and jerk at the cam speed ``omega`` (m/s, m/s², m/s³; rad/s, ... for
an oscillating follower); the segment's two ends need ``s``.

>>> spec = cam_spec_from_dict({"base_radius": 0.04, "omega": 10,
...     "follower": {"motion": "translating", "contact": "knife"},
...     "segments": [{"law": "harmonic", "lift": 0.01, "angle": 180},
...                  {"law": "harmonic", "lift": -0.01, "angle": 180}]})
>>> [(s.law.value, s.lift) for s in spec.segments]
[('harmonic', 0.01), ('harmonic', -0.01)]
>>> cam_spec_from_dict({"base_radius": 0.04, "follower": {"motion": "translating",
...     "contact": "knife"}, "segments": [{"law": "cycloid", "lift": 0.01, "angle": 360}]})
Traceback (most recent call last):
...
structure.errors.CamProgramError: <dict>: segments[0]: unknown law 'cycloid' (use uniform, ...
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from .errors import CamProgramError, EdgeListProblem
from .kinds import TextEnum
from .validation import MAX_MAGNITUDE

__all__ = [
    "BoundaryCondition",
    "CamRef",
    "CamSegment",
    "CamSpec",
    "FollowerContact",
    "FollowerMotion",
    "FollowerSpec",
    "MotionLaw",
    "SpringSpec",
    "cam_spec_from_dict",
    "cam_spec_to_dict",
]


class MotionLaw(TextEnum):
    """The law of a segment of a follower program (its name in the spec)."""

    UNIFORM = "uniform"
    HARMONIC = "harmonic"
    CYCLOIDAL = "cycloidal"
    MODIFIED_TRAPEZOID = "modified-trapezoid"
    MODIFIED_SINE = "modified-sine"
    POLY_345 = "3-4-5"
    POLY_4567 = "4-5-6-7"
    DWELL = "dwell"
    POLYNOMIAL = "polynomial"

    @property
    def moves(self) -> bool:
        """Whether the law is a rise or return of a given lift (not a dwell nor a fitted one)."""
        return self not in (MotionLaw.DWELL, MotionLaw.POLYNOMIAL)


class FollowerMotion(TextEnum):
    """How the follower moves: along a straight guide, or swinging about a pivot."""

    TRANSLATING = "translating"
    OSCILLATING = "oscillating"


class FollowerContact(TextEnum):
    """The follower's end on the cam: a knife edge (a point), a roller or a flat face."""

    KNIFE = "knife"
    ROLLER = "roller"
    FLAT = "flat"


#: the conditions a polynomial segment may set at a point: displacement and its time rates
CONDITION_KEYS = ("s", "v", "a", "j")


@dataclass(frozen=True, slots=True)
class BoundaryCondition:
    """What a polynomial segment must do at ``at_deg`` from its start.

    ``values`` maps the order of the derivative (0 for ``s``, 1 ``v``, 2 ``a``,
    3 ``j``) to its value in the file's units (time rates at the cam speed).
    """

    at_deg: float
    values: tuple[tuple[int, float], ...]

    def value(self, order: int) -> float | None:
        """The condition on the ``order``-th derivative, or None when it sets none."""
        return next((v for k, v in self.values if k == order), None)


@dataclass(frozen=True, slots=True)
class CamSegment:
    """One segment of a follower program: a law over ``angle_deg`` of cam turn.

    ``lift`` is the follower's travel over the segment (negative for a
    return; 0 for a dwell); a polynomial segment's comes from its
    ``conditions``.
    """

    law: MotionLaw
    angle_deg: float
    lift: float = 0.0
    conditions: tuple[BoundaryCondition, ...] = ()

    @property
    def start_value(self) -> float | None:
        """A polynomial segment's displacement at its start, from its conditions."""
        return next((c.value(0) for c in self.conditions if c.at_deg == 0.0), None)

    @property
    def end_value(self) -> float | None:
        """A polynomial segment's displacement at its end, from its conditions."""
        return next((c.value(0) for c in self.conditions if c.at_deg == self.angle_deg), None)


@dataclass(frozen=True, slots=True)
class FollowerSpec:
    """The follower: its motion, its contact and its dimensions (metres; pivot in the cam's frame).

    Translating: ``offset`` is the distance of its axis from the cam's centre,
    positive on the side that lowers the pressure angle of a rise. Oscillating:
    ``pivot`` (x, y) from the cam's centre and ``arm``, the pivot to the
    roller's centre (or the knife's edge); a flat face passes ``face_offset``
    from the pivot.
    """

    motion: FollowerMotion
    contact: FollowerContact
    offset: float = 0.0
    roller_radius: float = 0.0
    pivot: tuple[float, float] | None = None
    arm: float | None = None
    face_offset: float = 0.0

    @property
    def translating(self) -> bool:
        return self.motion is FollowerMotion.TRANSLATING


@dataclass(frozen=True, slots=True)
class SpringSpec:
    """The closing spring: ``rate`` (N/m, or N·m/rad), ``preload`` (N, N·m) and a speed to hold.

    ``up_to`` is the cam speed (rad/s) up to which the smallest spring keeps
    contact; None: the spec's own ``omega``.
    """

    rate: float = 0.0
    preload: float = 0.0
    up_to: float | None = None


@dataclass(frozen=True, slots=True)
class CamSpec:
    """A disc cam design: speed, follower, base circle, program, and what closes the contact.

    ``follower_mass`` (kg, translating) or ``follower_inertia`` (kg·m² about
    the pivot, oscillating), ``load`` (N or N·m, pressing the follower onto
    the cam) and ``spring`` are for the force closure; ``max_pressure_angle``
    (degrees) is the limit the checks hold the design to.
    """

    follower: FollowerSpec
    base_radius: float
    segments: tuple[CamSegment, ...]
    omega: float = 1.0
    name: str = ""
    follower_mass: float = 0.0
    follower_inertia: float = 0.0
    load: float = 0.0
    spring: SpringSpec | None = None
    max_pressure_angle: float | None = None

    @property
    def pressure_limit(self) -> float:
        """The largest pressure angle allowed (degrees): given, else 30° (35° swinging)."""
        if self.max_pressure_angle is not None:
            return self.max_pressure_angle
        return 30.0 if self.follower.translating else 35.0

    @property
    def total_lift(self) -> float:
        """The largest swing of the program: max minus min displacement (metres or degrees)."""
        at = [0.0]
        s = self.segments[0].start_value if self.segments[0].law is MotionLaw.POLYNOMIAL else 0.0
        at[0] = s or 0.0
        for segment in self.segments:
            at.append(at[-1] + segment.lift)
        return max(at) - min(at)


@dataclass(frozen=True, slots=True)
class CamRef:
    """A mechanism's ``cam`` statement: the higher pair of link ``cam`` and ``other`` has a profile.

    ``other`` is the link the cam touches (the follower, or its roller);
    ``spec`` the design whose program gives the profile; ``path`` the program
    file as the statement names it (None when the spec is held inline, as the
    JSON form may); ``at_deg`` the program's cam angle at the sketch pose.
    """

    cam: str
    other: str
    spec: CamSpec
    path: str | None = field(default=None, compare=False)
    at_deg: float = 0.0
    line_no: int = field(default=0, compare=False)

    @property
    def statement(self) -> str:
        """The edge-list line (which needs the program's file)."""
        at = f" at={_number_text(self.at_deg)}" if self.at_deg else ""
        return f"cam {self.cam} {self.other} {self.path or '?'}{at}"

    @property
    def label(self) -> str:
        return f"cam {self.cam}–{self.other}"


def _number_text(value: float) -> str:
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


# ----------------------------------------------------------------------------- reading
_TOP_KEYS = (
    "name",
    "omega",
    "follower",
    "base_radius",
    "segments",
    "follower_mass",
    "follower_inertia",
    "load",
    "spring",
    "max_pressure_angle",
)
_FOLLOWER_KEYS = ("motion", "contact", "offset", "roller_radius", "pivot", "arm", "face_offset")
#: the follower keys each motion and contact takes, besides motion and contact
_TAKES = {
    (FollowerMotion.TRANSLATING, FollowerContact.KNIFE): ("offset",),
    (FollowerMotion.TRANSLATING, FollowerContact.ROLLER): ("offset", "roller_radius"),
    (FollowerMotion.TRANSLATING, FollowerContact.FLAT): ("offset",),
    (FollowerMotion.OSCILLATING, FollowerContact.KNIFE): ("pivot", "arm"),
    (FollowerMotion.OSCILLATING, FollowerContact.ROLLER): ("pivot", "arm", "roller_radius"),
    (FollowerMotion.OSCILLATING, FollowerContact.FLAT): ("pivot", "face_offset", "arm"),
}
_NEEDS = {
    (FollowerMotion.TRANSLATING, FollowerContact.ROLLER): ("roller_radius",),
    (FollowerMotion.OSCILLATING, FollowerContact.KNIFE): ("pivot", "arm"),
    (FollowerMotion.OSCILLATING, FollowerContact.ROLLER): ("pivot", "arm", "roller_radius"),
    (FollowerMotion.OSCILLATING, FollowerContact.FLAT): ("pivot",),
}
#: the tolerance of the sums a program must meet (360°; back home), relative to their terms
_SUM_TOLERANCE = 1e-9


class _Problems(list[EdgeListProblem]):
    def add(self, where: str, reason: str) -> None:
        self.append(EdgeListProblem(0, "", f"{where}: {reason}"))


def _number(value: Any) -> float | None:
    """A finite real number (not a bool) within the magnitude assur takes, as a float."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return None
    try:
        x = float(value)
    except OverflowError:
        return None
    return x if math.isfinite(x) and abs(x) <= MAX_MAGNITUDE else None


def _read_number(
    data: Mapping[str, Any],
    key: str,
    where: str,
    problems: _Problems,
    what: str,
    *,
    default: float | None = None,
    low: float | None = None,
    strict: bool = False,
) -> float | None:
    """``data[key]`` as a number above ``low`` (``strict``: not equal to it), or ``default``."""
    if key not in data or data[key] is None:
        return default
    x = _number(data[key])
    bound = low is not None and (x is not None) and (x <= low if strict else x < low)
    if x is None or bound:
        limit = "" if low is None else f" {'>' if strict else '>='} {_number_text(low)}"
        problems.add(where, f"'{key}' must be a finite number{limit}: {what}")
        return default
    return x


def cam_spec_from_dict(data: Any, source: str = "<dict>") -> CamSpec:
    """Read and check a cam design from its JSON-shaped dict.

    Raises
    ------
    CamProgramError
        Every problem of the spec at once, each under its JSON path: unknown
        keys, values of the wrong shape or out of range, an unknown law,
        segments that do not add up to 360°, a program that does not bring the
        follower home or whose displacement jumps between segments, a
        polynomial segment without its ends' displacement.
    """
    if not isinstance(data, Mapping):
        raise CamProgramError(source, [EdgeListProblem(0, "", "the cam spec must be an object")])
    problems = _Problems()
    unknown = sorted(set(data) - set(_TOP_KEYS))
    if unknown:
        problems.add("top level", f"unknown keys {unknown} (a cam spec has {', '.join(_TOP_KEYS)})")
    name = data.get("name", "")
    if not isinstance(name, str):
        problems.add("name", "must be a string")
        name = ""
    omega = _read_number(data, "omega", "omega", problems, "the cam speed in rad/s", default=1.0)
    if omega == 0.0:
        problems.add("omega", "the cam speed must not be 0 (its sign is the sense it turns in)")
        omega = 1.0
    base = _read_number(
        data, "base_radius", "base_radius", problems, "the base circle's radius (m)",
        low=0.0, strict=True,
    )  # fmt: skip
    if "base_radius" not in data:
        problems.add("base_radius", "missing: the base circle's radius (m), > 0")
    follower = _read_follower(data.get("follower"), problems)
    segments = _read_segments(data.get("segments"), problems)
    spring = _read_spring(data.get("spring"), problems)
    mass = _read_number(
        data, "follower_mass", "follower_mass", problems, "the follower's mass (kg)",
        default=0.0, low=0.0,
    )  # fmt: skip
    inertia = _read_number(
        data, "follower_inertia", "follower_inertia", problems,
        "the follower's moment of inertia about its pivot (kg·m²)", default=0.0, low=0.0,
    )  # fmt: skip
    load = _read_number(data, "load", "load", problems, "the load on the follower", default=0.0)
    limit = _read_number(
        data, "max_pressure_angle", "max_pressure_angle", problems,
        "the largest pressure angle allowed (degrees), below 90", low=0.0, strict=True,
    )  # fmt: skip
    if limit is not None and limit >= 90.0:
        problems.add("max_pressure_angle", "must be below 90 degrees")
        limit = None
    if follower is not None:
        _check_inertia_keys(data, follower, problems)
    if segments:
        _check_program(segments, problems)
    if problems or follower is None or base is None or not segments:
        if not problems:  # pragma: no cover - every None above adds its problem
            problems.add("top level", "incomplete cam spec")
        raise CamProgramError(source, problems)
    return CamSpec(
        follower, base, tuple(segments), omega or 1.0, name, mass or 0.0, inertia or 0.0,
        load or 0.0, spring, limit,
    )  # fmt: skip


def _read_follower(raw: Any, problems: _Problems) -> FollowerSpec | None:
    if not isinstance(raw, Mapping):
        problems.add(
            "follower",
            "must be an object with 'motion' (translating, oscillating) and 'contact' "
            "(knife, roller, flat)",
        )
        return None
    motion = _enum(FollowerMotion, raw.get("motion"), "follower.motion", problems)
    contact = _enum(FollowerContact, raw.get("contact"), "follower.contact", problems)
    unknown = sorted(set(raw) - set(_FOLLOWER_KEYS))
    if unknown:
        problems.add("follower", f"unknown keys {unknown}")
    if motion is None or contact is None:
        return None
    takes, needs = _TAKES[motion, contact], _NEEDS.get((motion, contact), ())
    found = len(problems)
    for key in _FOLLOWER_KEYS[2:]:
        if key in raw and key not in takes:
            problems.add("follower", f"'{key}' does not apply to a {motion} {contact} follower")
        elif key in needs and key not in raw:
            problems.add("follower", f"a {motion} {contact} follower needs '{key}'")
    offset = _read_number(raw, "offset", "follower", problems, "the axis's offset (m)", default=0.0)
    roller = _read_number(
        raw, "roller_radius", "follower", problems, "the roller's radius (m)",
        default=0.0, low=0.0, strict=True,
    )  # fmt: skip
    arm = _read_number(
        raw, "arm", "follower", problems, "the arm from the pivot (m)", low=0.0, strict=True
    )
    face = _read_number(
        raw, "face_offset", "follower", problems, "the face's distance from the pivot (m)",
        default=0.0,
    )  # fmt: skip
    pivot = None
    if "pivot" in raw and "pivot" in takes:
        value = raw["pivot"]
        xy = [_number(v) for v in value] if isinstance(value, list) and len(value) == 2 else None
        if xy is None or None in xy:
            problems.add("follower", "'pivot' must be [x, y] in metres from the cam's centre")
        else:
            pivot = (float(xy[0]), float(xy[1]))  # type: ignore[arg-type]
    if len(problems) > found:
        return None
    return FollowerSpec(motion, contact, offset or 0.0, roller or 0.0, pivot, arm, face or 0.0)


def _enum(kind: type[TextEnum], value: Any, where: str, problems: _Problems) -> Any:
    names = ", ".join(k.value for k in kind)
    if not isinstance(value, str) or value not in {k.value for k in kind}:
        shown = repr(value) if isinstance(value, str) else "missing"
        problems.add(where, f"{shown[:40]} is not one of {names}")
        return None
    return kind(value)


def _check_inertia_keys(data: Mapping[str, Any], follower: FollowerSpec, problems: _Problems):
    if follower.translating and data.get("follower_inertia"):
        problems.add(
            "follower_inertia", "applies to an oscillating follower: give 'follower_mass' (kg)"
        )
    if not follower.translating and data.get("follower_mass"):
        problems.add(
            "follower_mass",
            "an oscillating follower's inertia is 'follower_inertia' (kg·m² about its pivot)",
        )


def _read_spring(raw: Any, problems: _Problems) -> SpringSpec | None:
    if raw is None:
        return None
    if not isinstance(raw, Mapping):
        problems.add("spring", "must be an object with 'rate', 'preload' and 'up_to' (optional)")
        return None
    unknown = sorted(set(raw) - {"rate", "preload", "up_to"})
    if unknown:
        problems.add("spring", f"unknown keys {unknown} (use rate, preload, up_to)")
    rate = _read_number(raw, "rate", "spring", problems, "N/m (N·m/rad)", default=0.0, low=0.0)
    preload = _read_number(raw, "preload", "spring", problems, "N (N·m)", default=0.0)
    up_to = _read_number(
        raw, "up_to", "spring", problems, "the cam speed to keep contact up to (rad/s)",
        low=0.0, strict=True,
    )  # fmt: skip
    return SpringSpec(rate or 0.0, preload or 0.0, up_to)


def _read_segments(raw: Any, problems: _Problems) -> list[CamSegment]:
    if not isinstance(raw, list) or not raw:
        problems.add("segments", "must be a non-empty list of {law, angle, lift}")
        return []
    segments: list[CamSegment] = []
    for i, item in enumerate(raw):
        segment = _read_segment(item, f"segments[{i}]", problems)
        if segment is not None:
            segments.append(segment)
    return segments if len(segments) == len(raw) else []


_LAW_NAMES = ", ".join(law.value for law in MotionLaw)


def _read_segment(item: Any, where: str, problems: _Problems) -> CamSegment | None:
    if not isinstance(item, Mapping):
        problems.add(where, "must be an object {law, angle, lift}")
        return None
    law_name = item.get("law")
    if not isinstance(law_name, str) or law_name not in {law.value for law in MotionLaw}:
        shown = repr(law_name)[:40] if law_name is not None else "missing"
        problems.add(where, f"unknown law {shown} (use {_LAW_NAMES})")
        return None
    law = MotionLaw(law_name)
    fitted = law is MotionLaw.POLYNOMIAL
    allowed = {"law", "angle", "bc"} if fitted else {"law", "angle", "lift"}
    unknown = sorted(set(item) - allowed)
    if unknown:
        problems.add(where, f"unknown keys {unknown} for a {law} segment (use {sorted(allowed)})")
    found = len(problems)
    angle = _read_number(
        item, "angle", where, problems, "the segment's cam angle (degrees)", low=0.0, strict=True
    )
    if "angle" not in item:
        problems.add(where, "needs 'angle', the cam angle it takes (degrees)")
    lift = _read_number(item, "lift", where, problems, "the follower's travel", default=0.0)
    if law.moves and not lift:
        problems.add(where, f"a {law} segment needs a 'lift' other than 0 (negative to return)")
    if law is MotionLaw.DWELL and lift:
        problems.add(where, "a dwell has no lift: make it 0 or use a rise or return law")
    conditions: tuple[BoundaryCondition, ...] = ()
    if law is MotionLaw.POLYNOMIAL and angle is not None:
        conditions = _read_conditions(item.get("bc"), angle, where, problems)
    if len(problems) > found or angle is None:
        return None
    if law is MotionLaw.POLYNOMIAL:
        start = next(c.value(0) for c in conditions if c.at_deg == 0.0)
        end = next(c.value(0) for c in conditions if c.at_deg == angle)
        lift = float(end) - float(start)  # type: ignore[arg-type]
    return CamSegment(law, angle, lift or 0.0, conditions)


def _read_conditions(
    raw: Any, angle: float, where: str, problems: _Problems
) -> tuple[BoundaryCondition, ...]:
    usage = "[{at, s, v, a, j}, ...] with 'at' in degrees from the segment's start"
    if not isinstance(raw, list) or not raw:
        problems.add(where, f"a polynomial segment needs 'bc', a list {usage}")
        return ()
    out: list[BoundaryCondition] = []
    for k, item in enumerate(raw):
        here = f"{where}.bc[{k}]"
        if not isinstance(item, Mapping):
            problems.add(here, f"must be an object {{at, s, v, a, j}}: {usage}")
            continue
        unknown = sorted(set(item) - {"at", *CONDITION_KEYS})
        if unknown:
            problems.add(here, f"unknown keys {unknown} (use at, s, v, a, j)")
        at = _read_number(item, "at", here, problems, "degrees from the segment's start")
        if at is None:
            if "at" not in item:
                problems.add(here, "needs 'at', degrees from the segment's start")
            continue
        if not 0.0 <= at <= angle:
            problems.add(here, f"'at' {_number_text(at)} is outside the segment (0 to {angle:g})")
            continue
        values = []
        for order, key in enumerate(CONDITION_KEYS):
            value = _read_number(item, key, here, problems, "the condition's value")
            if value is not None:
                values.append((order, value))
        if not values:
            problems.add(here, "sets nothing: give at least one of s, v, a, j")
            continue
        out.append(BoundaryCondition(at, tuple(values)))
    points = {}
    for c in out:
        for order, _ in c.values:
            if (c.at_deg, order) in points:
                problems.add(where, f"two conditions on the same quantity at {c.at_deg:g}°")
            points[c.at_deg, order] = True
    for end in (0.0, angle):
        if (end, 0) not in points:
            problems.add(
                where, f"'bc' needs the displacement s at {end:g}° (each end of the segment)"
            )
    return tuple(out)


def _check_program(segments: list[CamSegment], problems: _Problems) -> None:
    """The segments add up to a turn, the displacement never jumps, the follower comes home."""
    total = sum(s.angle_deg for s in segments)
    if abs(total - 360.0) > _SUM_TOLERANCE * 360.0:
        problems.add(
            "segments",
            f"the angles add up to {total:g}°, not 360°: lengthen or shorten a segment "
            f"by {360.0 - total:+g}°",
        )
    first = segments[0]
    start = first.start_value if first.law is MotionLaw.POLYNOMIAL else 0.0
    here = start or 0.0
    scale = max([abs(s.lift) for s in segments] + [abs(here), 1e-300])
    for i, s in enumerate(segments):
        if s.law is MotionLaw.POLYNOMIAL and i > 0:
            begin = float(s.start_value)  # type: ignore[arg-type]
            if abs(begin - here) > _SUM_TOLERANCE * scale:
                problems.add(
                    f"segments[{i}]",
                    f"starts at s = {begin:g} but the follower is at {here:g} there: make its "
                    f"condition s at 0° {here:g}, or change the segments before it",
                )
            here = begin
        here += s.lift
    if abs(here - (start or 0.0)) > _SUM_TOLERANCE * scale:
        lifts = ", ".join(f"{s.lift:+g}" for s in segments if s.lift)
        problems.add(
            "segments",
            f"the program ends at s = {here:g}, not home at {start or 0.0:g} (lifts {lifts}): "
            f"the lifts must add up to 0; change a lift by {(start or 0.0) - here:+g}",
        )


# ----------------------------------------------------------------------------- writing
def cam_spec_to_dict(spec: CamSpec) -> dict[str, Any]:
    """The JSON-shaped dict of ``spec`` (:func:`cam_spec_from_dict` reads it back equal).

    >>> spec = cam_spec_from_dict({"base_radius": 0.04, "follower": {"motion": "translating",
    ...     "contact": "flat"}, "segments": [{"law": "cycloidal", "lift": 0.01, "angle": 180},
    ...     {"law": "cycloidal", "lift": -0.01, "angle": 180}]})
    >>> cam_spec_from_dict(cam_spec_to_dict(spec)) == spec
    True
    """
    f = spec.follower
    follower: dict[str, Any] = {"motion": f.motion.value, "contact": f.contact.value}
    takes = _TAKES[f.motion, f.contact]
    values = {
        "offset": f.offset,
        "roller_radius": f.roller_radius,
        "pivot": list(f.pivot) if f.pivot is not None else None,
        "arm": f.arm,
        "face_offset": f.face_offset,
    }
    for key in takes:
        if values[key] is not None and (
            values[key] != 0.0 or key in _NEEDS.get((f.motion, f.contact), ())
        ):
            follower[key] = values[key]
    out: dict[str, Any] = {}
    if spec.name:
        out["name"] = spec.name
    out["omega"] = spec.omega
    out["follower"] = follower
    out["base_radius"] = spec.base_radius
    out["segments"] = [_segment_dict(s) for s in spec.segments]
    if spec.follower_mass:
        out["follower_mass"] = spec.follower_mass
    if spec.follower_inertia:
        out["follower_inertia"] = spec.follower_inertia
    if spec.load:
        out["load"] = spec.load
    if spec.spring is not None:
        spring: dict[str, Any] = {"rate": spec.spring.rate, "preload": spec.spring.preload}
        if spec.spring.up_to is not None:
            spring["up_to"] = spec.spring.up_to
        out["spring"] = spring
    if spec.max_pressure_angle is not None:
        out["max_pressure_angle"] = spec.max_pressure_angle
    return out


def _segment_dict(segment: CamSegment) -> dict[str, Any]:
    item: dict[str, Any] = {"law": segment.law.value, "angle": segment.angle_deg}
    if segment.law is MotionLaw.POLYNOMIAL:
        item["bc"] = [
            {"at": c.at_deg, **{CONDITION_KEYS[k]: v for k, v in c.values}}
            for c in segment.conditions
        ]
    elif segment.law is not MotionLaw.DWELL:
        item["lift"] = segment.lift
    return item
