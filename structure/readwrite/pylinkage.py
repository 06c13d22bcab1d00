"""Read pylinkage's JSON linkages: its mechanism format and its older linkage format.

pylinkage (``pylinkage.mechanism.serialization``) writes a mechanism as joints
(points) and links (rigid bodies listing their joints)::

    {"name": "fourbar", "ground": "ground",
     "joints": [{"id": "A", "type": "ground", "position": [0, 0]},
                {"id": "B", "type": "revolute", "position": [0.5, 0.8]},
                {"id": "S", "type": "prismatic", "position": [2, 0],
                 "axis": [1, 0], "line_point": [0, 0]},
                {"id": "T", "type": "tracker", "ref_joint1_id": "B",
                 "ref_joint2_id": "S", "distance": 1, "angle": 0.3}],
     "links": [{"id": "ground", "type": "ground", "joints": ["A"]},
               {"id": "crank", "type": "driver", "joints": ["A", "B"], "motor_joint": "A"},
               {"id": "rod", "type": "link", "joints": ["B", "S"]}]}

Mapping: each link is a link of ours (every ``ground`` link is the one
ground), each joint a point named after its id. A ``ground`` or ``revolute``
joint on k bodies is a compound hinge of k - 1 revolute pairs (a ground joint
counts the ground among them); a ``prismatic`` joint slides along a line
fixed to the frame (``line_point``, ``axis``), so its links are pinned to a
slider block ``block_<id>`` that slides (P) on the ground; a ``tracker`` is a
marker on the link holding both its reference joints; a joint on one body
is a marker on it. ``driver`` and ``arc_driver`` links are the drivers (their
speed is in radians per simulation step, not per second, so none is given).

The older format (pylinkage before its ``mechanism`` module, ``linkage_to_dict``)
lists joints only, each of a kind that implies its bars: ``Static`` a point of
the frame; ``Crank`` the driving bar from ``joint0``; ``Revolute`` two bars,
from ``joint0`` and from ``joint1``; ``Fixed`` one body with ``joint0`` and
``joint1``; ``Prismatic`` (``Linear``) a bar from ``joint0`` whose end slides
on the line through ``joint1`` and ``joint2``. Bodies that share two joints
are one body; links are numbered ``1, 2, ...`` in order, the frame is ``0``.

>>> m = mechanism_from_pylinkage({"joints": [
...     {"type": "Static", "name": "A", "x": 0, "y": 0},
...     {"type": "Static", "name": "D", "x": 3, "y": 0},
...     {"type": "Crank", "name": "B", "x": 0, "y": 1, "joint0": {"ref": "A"}},
...     {"type": "Revolute", "name": "C", "x": 3, "y": 2,
...      "joint0": {"ref": "B"}, "joint1": {"ref": "D"}}]})
>>> [p.statement for p in m.pairs], m.driver_links
(['0 1 R A', '0 3 R D', '1 2 R B', '2 3 R C'], ('1',))
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from ..errors import EdgeListError, EdgeListProblem, StatementError
from ..model import Driver, Mechanism, Pair, PairKind, PointDef, make_point, validated
from ..validation import MAX_MAGNITUDE, as_title
from .jsonformat import decode_json

__all__ = ["is_pylinkage", "mechanism_from_pylinkage", "parse_pylinkage"]

_LEGACY_KINDS = ("Static", "Crank", "Fixed", "Revolute", "Prismatic", "Linear")
_JOINT_KINDS = ("ground", "revolute", "prismatic", "tracker")
_LINK_KINDS = ("ground", "driver", "arc_driver", "link")
_UNSAFE = re.compile(r"[\s#=,]")
#: how far (relative to the drawing's size) a slider may sit off its line
_ON_LINE = 1e-6
#: what a coordinate must be, as the messages say it
_NUMBERS = f"finite numbers within ±{MAX_MAGNITUDE:g}"


class _Problems(Exception):
    """Problems of a pylinkage description, gathered before one EdgeListError."""

    def __init__(self, reasons: Sequence[str]):
        self.reasons = tuple(reasons)
        super().__init__("; ".join(reasons))


def _key(value: Any) -> str | None:
    """A joint or link reference as text, or None when it is not a name."""
    if isinstance(value, bool) or not isinstance(value, (str, int)):
        return None
    return str(value)


def _token(name: Any) -> str:
    """A name usable as an edge-list token (no spaces, ``#``, ``=`` or ``,``)."""
    return _UNSAFE.sub("_", str(name)) or "_"


def _finite(value: Any) -> float | None:
    """A number within ±:data:`~structure.validation.MAX_MAGNITUDE` as a float, else None."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        number = float(value)
    except OverflowError:  # an integer beyond the float range
        return None
    return number if math.isfinite(number) and abs(number) <= MAX_MAGNITUDE else None


def _finite_pair(value: Any) -> tuple[float, float] | None:
    """``[x, y]`` of numbers within ±:data:`~structure.validation.MAX_MAGNITUDE`, else None."""
    if not isinstance(value, (list, tuple)) or len(value) != 2:
        return None
    x, y = _finite(value[0]), _finite(value[1])
    return None if x is None or y is None else (x, y)


def is_pylinkage(data: Any) -> bool:
    """True when ``data`` (parsed JSON) is a pylinkage mechanism or linkage."""
    if not isinstance(data, dict) or not isinstance(data.get("joints"), list):
        return False
    return "pairs" not in data


# ------------------------------------------------------------ the assembly
class _Assembly:
    """Bodies (sets of joint names) with the ground as body 0, merged into links and pairs.

    ``slides`` holds each slider joint, its block body, the slide's angle
    (degrees) and the two joints of its guide line (None: the frame);
    ``markers`` each tracker's two reference joints.
    """

    def __init__(self, ground: str) -> None:
        self.xy: dict[str, tuple[float, float]] = {}
        self.bodies: list[set[str]] = [set()]
        self.names: list[str] = [ground]
        self.blocks: set[int] = set()
        self.drivers: list[int] = []
        self.slides: list[tuple[str, int, float, tuple[str, str] | None]] = []
        self.markers: dict[str, tuple[str, str]] = {}
        self.problems: list[str] = []

    def body(self, name: str, joints: Iterable[str]) -> int:
        self.bodies.append(set(joints))
        self.names.append(name)
        return len(self.bodies) - 1

    def block(self, joint: str, angle: float, guide: tuple[str, str] | None) -> None:
        taken = set(self.names)
        name = f"block_{joint}"
        while name in taken:
            name += "_"
        self.blocks.add(self.body(name, [joint]))
        self.slides.append((joint, len(self.bodies) - 1, angle, guide))

    def merge(self) -> list[int]:
        """Merge bodies that share two joints; returns each body's representative."""
        owner = list(range(len(self.bodies)))

        def find(k: int) -> int:
            while owner[k] != k:
                owner[k] = owner[owner[k]]
                k = owner[k]
            return k

        changed = True
        while changed:
            changed = False
            for i in range(len(self.bodies)):
                for j in range(i + 1, len(self.bodies)):
                    a, b = find(i), find(j)
                    if a != b and len(self.bodies[a] & self.bodies[b]) >= 2:
                        owner[max(a, b)] = min(a, b)
                        self.bodies[min(a, b)] |= self.bodies[max(a, b)]
                        changed = True
        return [find(k) for k in range(len(self.bodies))]


def _holding(assembly: _Assembly, live: Sequence[int], joints: tuple[str, str]) -> int | None:
    """The body that holds both ``joints`` (the ground first), if any."""
    return next((k for k in live if set(joints) <= assembly.bodies[k]), None)


def _mechanism(assembly: _Assembly, name: str, source: str, number: bool) -> Mechanism:
    """The validated mechanism of the merged bodies; ``number`` names links 1, 2, ..."""
    rep = assembly.merge()
    live = sorted(set(rep))
    link = {k: assembly.names[k] for k in live}
    if number:
        plain = [k for k in live if k != 0 and k not in assembly.blocks]
        link.update({k: str(i) for i, k in enumerate(plain, start=1)})
    pairs: list[Pair] = []
    points: dict[str, PointDef] = {}
    for joint, (x, y) in assembly.xy.items():
        # the blocks last: a hinge's pairs run from a link of the linkage to its block
        carriers = sorted(
            (k for k in live if joint in assembly.bodies[k]), key=lambda k: k in assembly.blocks
        )
        on = None
        if joint in assembly.markers:
            holder = _holding(assembly, live, assembly.markers[joint])
            if holder is None:
                refs = " and ".join(assembly.markers[joint])
                assembly.problems.append(f"tracker {joint}: no link holds both {refs}")
                continue
            on = link[holder]
        elif len(carriers) == 1:
            on = link[carriers[0]]
        try:
            points[joint] = make_point(joint, x, y, on)
        except StatementError as exc:
            assembly.problems.append(f"joint {joint}: {exc.reason}")
            continue
        for other in carriers[1:]:
            pairs.append(Pair(len(pairs) + 1, PairKind.R, link[carriers[0]], link[other], joint))
    for joint, block, angle, guide in assembly.slides:
        holder = 0 if guide is None else _holding(assembly, live, guide)
        if holder is None:
            assembly.problems.append(
                f"joint {joint}: its slide line {' - '.join(guide or ())} is on no one link"
            )
            continue
        pairs.append(Pair(len(pairs) + 1, PairKind.P, link[holder], link[block], joint, angle))
    if assembly.problems:
        raise _Problems(assembly.problems)
    drivers = tuple(dict.fromkeys(Driver(link[rep[k]]) for k in assembly.drivers))
    return validated(Mechanism(tuple(pairs), link[0], drivers, points, name, source))


def _slide_angle(
    where: str, point: tuple[float, float], through: tuple[float, float], axis: tuple[float, float]
) -> tuple[float, str]:
    """The slide's direction (degrees) and why ``point`` is not on the line, if it is not."""
    norm = math.hypot(*axis)
    if norm == 0:
        return 0.0, f"{where}: the slide direction is zero"
    ux, uy = axis[0] / norm, axis[1] / norm
    off = abs((point[0] - through[0]) * uy - (point[1] - through[1]) * ux)
    size = max(1.0, *map(abs, (*point, *through)))
    if off > _ON_LINE * size:
        return 0.0, f"{where}: the joint is {off:.6g} off its slide line"
    return math.degrees(math.atan2(uy, ux)), ""


# ------------------------------------------------------- the mechanism format
def _unique(name: Any, taken: set[str]) -> str:
    token = _token(name)
    while token in taken:
        token += "_"
    taken.add(token)
    return token


def _joints(data: Mapping[str, Any], assembly: _Assembly) -> dict[Any, str]:
    """Read the joints of the mechanism format; returns joint id -> point name."""
    names: dict[Any, str] = {}
    taken: set[str] = set()
    pending: list[tuple[str, dict]] = []
    for index, item in enumerate(data["joints"]):
        where = f"joints[{index}]"
        if not isinstance(item, dict) or not isinstance(item.get("id"), (str, int)):
            assembly.problems.append(f"{where}: must be an object with an 'id'")
            continue
        kind = item.get("type", "revolute")
        if kind not in _JOINT_KINDS:
            assembly.problems.append(
                f"{where} ({item['id']}): unknown joint type {kind!r} "
                f"(pylinkage has {', '.join(_JOINT_KINDS)})"
            )
            continue
        name = names[str(item["id"])] = _unique(item["id"], taken)
        xy = _finite_pair(item.get("position"))
        if kind == "tracker":
            pending.append((name, item))
            continue
        if xy is None:
            assembly.problems.append(f"joint {name}: 'position' must be [x, y], {_NUMBERS}")
            continue
        assembly.xy[name] = xy
        if kind == "ground":
            assembly.bodies[0].add(name)
        elif kind == "prismatic":
            through = _finite_pair(item.get("line_point", [0.0, 0.0]))
            axis = _finite_pair(item.get("axis", [1.0, 0.0]))
            if through is None or axis is None:
                assembly.problems.append(
                    f"joint {name}: 'axis' and 'line_point' must be [x, y], {_NUMBERS}"
                )
                continue
            angle, why = _slide_angle(f"joint {name}", xy, through, axis)
            if why:
                assembly.problems.append(why)
            assembly.block(name, angle, None)
    for name, item in pending:
        _tracker(name, item, names, assembly)
    return names


def _tracker(name: str, item: dict, names: Mapping[Any, str], assembly: _Assembly) -> None:
    """A tracker: a marker on the link of its two reference joints, placed from them."""
    refs = [names.get(_key(item.get(key))) for key in ("ref_joint1_id", "ref_joint2_id")]
    if None in refs or any(ref not in assembly.xy for ref in refs):
        assembly.problems.append(f"tracker {name}: its reference joints are not joints placed")
        return
    first, second = refs
    xy = _finite_pair(item.get("position"))
    if xy is None:
        (x1, y1), (x2, y2) = assembly.xy[first], assembly.xy[second]
        distance, angle = _finite(item.get("distance", 0.0)), _finite(item.get("angle", 0.0))
        if distance is None or angle is None:
            assembly.problems.append(f"tracker {name}: 'distance' and 'angle' must be {_NUMBERS}")
            return
        heading = math.atan2(y2 - y1, x2 - x1) + angle
        xy = (x1 + distance * math.cos(heading), y1 + distance * math.sin(heading))
    assembly.xy[name] = xy
    assembly.markers[name] = (first, second)  # type: ignore[assignment]


def _links(data: Mapping[str, Any], names: Mapping[Any, str], assembly: _Assembly) -> None:
    """Read the links of the mechanism format: ground links join the frame (body 0)."""
    taken = set(assembly.names)
    links = data.get("links")
    if links is not None and not isinstance(links, list):
        assembly.problems.append("'links' must be a list of link objects")
        return
    for index, item in enumerate(links or []):
        where = f"links[{index}]"
        if not isinstance(item, dict) or not isinstance(item.get("joints", []), list):
            assembly.problems.append(f"{where}: must be an object with a list of 'joints'")
            continue
        kind = item.get("type", "link")
        if kind not in _LINK_KINDS:
            assembly.problems.append(f"{where}: unknown link type {kind!r}")
            continue
        unknown = [j for j in item.get("joints", []) if _key(j) not in names]
        if unknown:
            assembly.problems.append(f"{where}: unknown joint(s) {', '.join(map(str, unknown))}")
            continue
        joints = [names[str(j)] for j in item.get("joints", [])]
        if kind == "ground":
            assembly.bodies[0].update(joints)
            continue
        body = assembly.body(_unique(item.get("id", f"link{index}"), taken), joints)
        if kind in ("driver", "arc_driver"):
            assembly.drivers.append(body)
            motor = _key(item.get("motor_joint"))
            if motor in names:
                assembly.bodies[0].add(names[motor])


def _from_mechanism_format(data: Mapping[str, Any], source: str) -> Mechanism:
    links = data.get("links")
    grounds = [
        item.get("id")
        for item in (links if isinstance(links, list) else [])
        if isinstance(item, dict) and item.get("type") == "ground"
    ]
    ground = _key(data.get("ground")) or _key(grounds[0] if grounds else None) or "ground"
    assembly = _Assembly(_token(ground))
    names = _joints(data, assembly)
    _links(data, names, assembly)
    if assembly.problems:
        raise _Problems(assembly.problems)
    # a slider's block was made before the links: keep the links' own names first
    return _mechanism(assembly, as_title(str(data.get("name") or "")), source, number=False)


# ---------------------------------------------------------- the older format
def _reference(item: dict, key: str, names: dict[str, str], assembly: _Assembly) -> str | None:
    """The point a ``joint0``-style reference names: ``{"ref": name}`` or an inline Static."""
    ref = item.get(key)
    if not isinstance(ref, dict):
        return None
    if ref.get("inline"):
        xy = _finite_pair([ref.get("x"), ref.get("y")])
        if xy is None:
            return None
        name = _unique(_key(ref.get("name")) or f"{key}_of_{item.get('name')}", set(assembly.xy))
        assembly.xy[name] = xy
        assembly.bodies[0].add(name)
        return name
    return names.get(_key(ref.get("ref")))


def _legacy_joint(item: dict, name: str, names: dict[str, str], assembly: _Assembly) -> None:
    kind = item["type"]
    needed = {"Crank": 1, "Revolute": 2, "Fixed": 2, "Prismatic": 3, "Linear": 3}[kind]
    refs = [_reference(item, f"joint{k}", names, assembly) for k in range(needed)]
    if None in refs:
        keys = ", ".join(f"joint{k}" for k in range(needed))
        assembly.problems.append(f"joint {name} ({kind}): {keys} must name joints of the linkage")
        return
    if kind == "Crank":
        assembly.drivers.append(assembly.body("", [refs[0], name]))
    elif kind == "Revolute":
        assembly.body("", [refs[0], name])
        assembly.body("", [refs[1], name])
    elif kind == "Fixed":
        assembly.body("", [refs[0], refs[1], name])
    else:
        assembly.body("", [refs[0], name])
        (x1, y1), (x2, y2) = assembly.xy[refs[1]], assembly.xy[refs[2]]
        angle, why = _slide_angle(f"joint {name}", assembly.xy[name], (x1, y1), (x2 - x1, y2 - y1))
        if why:
            assembly.problems.append(why)
        assembly.block(name, angle, (refs[1], refs[2]))


def _from_linkage_format(data: Mapping[str, Any], source: str) -> Mechanism:
    assembly = _Assembly("0")
    names: dict[str, str] = {}
    items: list[tuple[str, dict]] = []
    for index, item in enumerate(data["joints"]):
        if not isinstance(item, dict) or item.get("type") not in _LEGACY_KINDS:
            assembly.problems.append(
                f"joints[{index}]: 'type' must be one of {', '.join(_LEGACY_KINDS)}"
            )
            continue
        name = _unique(_key(item.get("name")) or f"j{index}", set(assembly.xy))
        names[_key(item.get("name")) or name] = name
        xy = _finite_pair([item.get("x"), item.get("y")])
        if xy is None:
            assembly.problems.append(f"joint {name}: 'x' and 'y' must be {_NUMBERS}")
            continue
        assembly.xy[name] = xy
        if item["type"] == "Static":
            assembly.bodies[0].add(name)
        else:
            items.append((name, item))
    if assembly.problems:
        raise _Problems(assembly.problems)
    for name, item in items:
        _legacy_joint(item, name, names, assembly)
    if assembly.problems:
        raise _Problems(assembly.problems)
    return _mechanism(assembly, as_title(str(data.get("name") or "")), source, number=True)


# ------------------------------------------------------------------- public
def mechanism_from_pylinkage(data: Any, source: str = "<pylinkage>") -> Mechanism:
    """The validated mechanism of a pylinkage mechanism or linkage (parsed JSON).

    Raises
    ------
    EdgeListError
        Not a pylinkage description, unknown joint or link types, references
        to unknown joints, missing or non-finite coordinates, a slider off its
        line, or any problem :func:`~structure.model.validated` finds.
    """
    if not is_pylinkage(data):
        raise EdgeListError(
            source, [EdgeListProblem(0, "", "not a pylinkage linkage: no list of 'joints'")]
        )
    legacy = any(
        isinstance(item, dict) and item.get("type") in _LEGACY_KINDS for item in data["joints"]
    )
    try:
        if legacy:
            return _from_linkage_format(data, source)
        return _from_mechanism_format(data, source)
    except _Problems as problems:
        raise EdgeListError(
            source, [EdgeListProblem(0, "", reason) for reason in problems.reasons]
        ) from None


def parse_pylinkage(text: str, source: str = "<pylinkage>") -> Mechanism:
    """Parse pylinkage JSON text (see :func:`mechanism_from_pylinkage`).

    Raises
    ------
    EdgeListError
        Invalid JSON (with its line) or any problem of the description.
    """
    data = decode_json(text, source)
    return mechanism_from_pylinkage(data, source)
