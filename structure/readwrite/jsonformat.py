"""The JSON form of the mechanism model (same content as the edge list).

::

    {"name": "four-bar", "ground": "0",
     "drivers": ["1"]  or  [{"link": "1", "omega": 20}],
     "pairs": [{"links": ["0", "1"], "kind": "R", "point": "A"},
               {"links": ["3", "0"], "kind": "P", "point": "C", "angle": 30},
               {"links": ["1", "4"], "kind": "H", "flat": "4", "centers": ["O1", null]}],
     "points": {"A": [0, 0], "M": {"xy": [0.1, 0.2], "on": "2"}},
     "targets": {"T1": {"xy": [0.5, 1.0], "input": 30}}}

>>> m = mechanism_from_json('{"drivers": ["1"], "pairs": [{"links": [0, 1], "kind": "R"}]}')
>>> m.pairs[0].label
'0–1 R'
>>> mechanism_to_dict(m)["pairs"]
[{'links': ['0', '1'], 'kind': 'R'}]
"""

from __future__ import annotations

import json
import math
import sys
from typing import Any

from ..cycle import CycleLoad, cycle_load_from_dict, cycle_load_to_dict
from ..errors import EdgeListError, EdgeListProblem, NumberError, StatementError
from ..expressions import read_number
from ..kinds import LoadKind
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
from ..validation import DRIVER_KEYS, check_title, tooth_number, validated
from .camfile import cam_from_item, cam_to_item

__all__ = [
    "decode_json",
    "mechanism_from_dict",
    "mechanism_from_json",
    "mechanism_to_dict",
    "mechanism_to_json",
]

_TOP_KEYS = (
    "name",
    "ground",
    "drivers",
    "pairs",
    "points",
    "loads",
    "cams",
    "drive",
    "cycle",
    "targets",
)
_PAIR_FIELDS = (
    "links",
    "kind",
    "point",
    "angle",
    "flat",
    "roller",
    "centers",
    "normal",
    "span",
    "friction",
    "circle",
    "gear",
    "z",
    "internal",
    "module",
)
_LOAD_FIELDS = ("kind", "link", "point", "values")


def decode_json(text: str, source: str = "<json>") -> Any:
    """The value of a JSON text, or an :class:`EdgeListError` saying where it is not JSON.

    Every JSON reader of the project (ours, pylinkage's) decodes through this, so each
    bad text gets the same named error: invalid JSON with its line, an integer of more
    digits than Python converts, arrays or objects nested too deeply.

    >>> decode_json('{"a": [1, 2]}')
    {'a': [1, 2]}
    """
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        lines = text.splitlines()
        line = lines[exc.lineno - 1] if 0 < exc.lineno <= len(lines) else ""
        raise EdgeListError(
            source, [EdgeListProblem(exc.lineno, line, f"invalid JSON: {exc.msg}")]
        ) from None
    except ValueError:  # an integer of more digits than Python converts
        reason = f"invalid JSON: an integer of more than {sys.get_int_max_str_digits()} digits"
        raise EdgeListError(source, [EdgeListProblem(0, "", reason)]) from None
    except RecursionError:
        reason = "invalid JSON: arrays or objects nested too deeply"
        raise EdgeListError(source, [EdgeListProblem(0, "", reason)]) from None


def mechanism_from_json(text: str, source: str = "<json>") -> Mechanism:
    """Parse the JSON form of a mechanism.

    Raises
    ------
    EdgeListError
        Invalid JSON (with its line) or any problem :func:`mechanism_from_dict` finds.
    """
    data = decode_json(text, source)
    return mechanism_from_dict(data, source)


def _is_name(value: Any) -> bool:
    if isinstance(value, bool):
        return False
    return isinstance(value, (str, int)) or (isinstance(value, float) and value.is_integer())


def _is_number(value: Any) -> bool:
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return False
    try:
        return math.isfinite(float(value))
    except OverflowError:  # an integer beyond the float range
        return False


def _numbers(values: list[Any]) -> tuple[list[float], list[str | None], str]:
    """Numbers, or exact expressions as strings (``"0.2*sqrt(3)"``), up to the first bad one.

    Returns the float values, for each the text it was written as (None for a
    number), and why the first bad one was refused when the expression reader
    said why (too deep, too many digits, too large an exponent, ...), else "".
    """
    numbers: list[float] = []
    written: list[str | None] = []
    for v in values:
        if _is_number(v):
            numbers.append(float(v))
            written.append(None)
            continue
        try:
            number, _ = read_number(v) if isinstance(v, str) else (None, None)
        except NumberError as exc:
            return numbers, written, f": {exc.reason}"
        except ValueError:
            number = None
        if number is None:
            break
        numbers.append(number)
        written.append(v)
    return numbers, written, ""


def _text(value: Any) -> str:
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


class _Problems(list[EdgeListProblem]):
    """The problems of one document, each under the JSON path it was found at."""

    def add(self, where: str, reason: str) -> None:
        self.append(EdgeListProblem(0, "", f"{where}: {reason}"))


def mechanism_from_dict(data: Any, source: str = "<dict>") -> Mechanism:
    """Build a validated mechanism from the JSON-shaped dict.

    Link and point names are strings (integers are accepted and turned into
    strings); numbers must be finite. Each statement is built by the same
    functions as the edge list's (:func:`~structure.model.make_pair`, ...),
    so it is refused for the same reasons.

    Raises
    ------
    EdgeListError
        Every problem of the document: unknown keys, values of the wrong
        shape (each named by its path, ``pairs[2]``), statements the model
        refuses, then any problem :func:`~structure.validation.validated` finds.
    """
    if not isinstance(data, dict):
        raise EdgeListError(source, [EdgeListProblem(0, "", "the top level must be an object")])
    problems = _Problems()
    unknown = set(data) - set(_TOP_KEYS)
    if unknown:
        problems.add("top level", f"unknown keys {sorted(unknown)}")
    name = data.get("name", "")
    if not isinstance(name, str):
        problems.add("name", "must be a string")
        name = ""
    try:
        check_title(name)
    except StatementError as exc:
        problems.add("name", exc.reason)
    ground = data.get("ground", "0")
    if not _is_name(ground):
        problems.add("ground", "must be a link name")
        ground = "0"
    pairs = _read_pairs(data.get("pairs", []), problems)
    drivers = _read_drivers(data.get("drivers", []), problems)
    points = _read_points(data.get("points", {}), problems)
    loads = _read_loads(data.get("loads", []), problems)
    cams = _read_cams(data.get("cams", []), source, problems)
    cycle_loads = _read_cycle_loads(data.get("drive"), data.get("cycle", []), problems)
    targets = _read_targets(data.get("targets", {}), problems)
    if problems:
        raise EdgeListError(source, problems)
    mechanism = Mechanism(
        tuple(pairs),
        _text(ground),
        tuple(drivers),
        points,
        name,
        source,
        tuple(loads),
        cams=tuple(cams),
        cycle_loads=tuple(cycle_loads),
        targets=targets,
    )
    return validated(mechanism)


# ----------------------------------------------------------------------------- pairs
def _read_pairs(raw: Any, problems: _Problems) -> list[Pair]:
    if not isinstance(raw, list):
        problems.add("pairs", "must be a list")
        return []
    pairs: list[Pair] = []
    for i, item in enumerate(raw):
        pair = _read_pair(item, len(pairs) + 1, f"pairs[{i}]", problems)
        if pair is not None:
            pairs.append(pair)
    return pairs


def _read_pair(item: Any, pair_id: int, where: str, problems: _Problems) -> Pair | None:
    """One pair object, or None (its problems added)."""
    if not isinstance(item, dict):
        problems.add(where, "must be an object")
        return None
    extra = set(item) - set(_PAIR_FIELDS)
    if extra:
        problems.add(where, f"unknown keys {sorted(extra)}")
        return None
    links = item.get("links")
    if not isinstance(links, list) or len(links) != 2 or not all(map(_is_name, links)):
        problems.add(where, "'links' must be a list of two link names")
        return None
    kind = item.get("kind")
    if not isinstance(kind, str):
        problems.add(where, "'kind' must be one of R, P, H")
        return None
    point = item.get("point")
    if point is not None:
        if not _is_name(point):
            problems.add(where, "'point' must be a point name")
            return None
        point = _text(point)
    found = len(problems)
    options = _pair_options(item, where, problems)
    if len(problems) > found:
        return None
    try:
        return make_pair(
            pair_id,
            kind,
            _text(links[0]),
            _text(links[1]),
            point,
            gear=bool(item.get("gear")),
            **options,
        )
    except StatementError as exc:
        problems.add(where, exc.reason)
        return None


def _pair_options(item: dict[str, Any], where: str, problems: _Problems) -> dict[str, Any]:
    """The options of a pair object as typed values, in the order the model checks them.

    Values of the wrong shape are added to ``problems``; their ranges are
    the model's to check.
    """
    options: dict[str, Any] = {}
    for key in ("angle", "normal", "span", "friction", "circle"):
        if item.get(key) is not None:
            if _is_number(item[key]):
                options[key] = item[key]
            else:
                problems.add(where, f"'{key}' must be a finite number of degrees")
    for key in ("flat", "roller"):
        if item.get(key) is not None:
            if _is_name(item[key]):
                options[key] = _text(item[key])
            else:
                problems.add(where, f"'{key}' must be a link name")
    centers = item.get("centers")
    if centers is not None:
        if (
            not isinstance(centers, list)
            or len(centers) != 2
            or not all(v is None or _is_name(v) for v in centers)
        ):
            problems.add(where, "'centers' must be a list of two point names (or null)")
        else:
            options["centers"] = tuple(None if v is None else _text(v) for v in centers)
    teeth = item.get("z")
    if teeth is not None:
        if not isinstance(teeth, list) or len(teeth) != 2:
            problems.add(where, "'z' must be [za, zb] (integers or '?')")
            return options
        options["z"] = tuple(tooth_number(t) for t in teeth)
    if item.get("internal") is not None:
        options["internal"] = _text(item["internal"])
    if item.get("module") is not None:
        options["module"] = _module(item["module"])
    return options


def _module(value: Any) -> Any:
    """A gear module; a string holding a number is read as that number, as it always was."""
    if isinstance(value, str):
        try:
            return float(value)
        except ValueError:
            return value
    return value


# ------------------------------------------------------------------ drivers, points, loads
def _read_drivers(raw: Any, problems: _Problems) -> list[Driver]:
    if not isinstance(raw, list):
        problems.add("drivers", "must be a list of link names or objects with 'link'")
        return []
    drivers: list[Driver] = []
    for i, item in enumerate(raw):
        where = f"drivers[{i}]"
        try:
            if _is_name(item):
                drivers.append(make_driver(_text(item)))
            elif isinstance(item, dict) and _is_name(item.get("link")):
                drivers.append(_read_driver(item, where, problems))
            else:
                problems.add(where, "must be a link name or an object with 'link'")
        except StatementError as exc:
            problems.add(where, exc.reason)
    return drivers


def _read_driver(item: dict[str, Any], where: str, problems: _Problems) -> Driver:
    motion: list[tuple[str, float]] = []
    for key, value in item.items():
        if key == "link":
            continue
        if key not in DRIVER_KEYS:
            problems.add(where, f"unknown option {key!r} (use {', '.join(DRIVER_KEYS)})")
        elif not _is_number(value):
            problems.add(where, f"option {key!r} must be a finite number")
        else:
            motion.append((key, value))
    return make_driver(_text(item["link"]), motion)


def _read_points(raw: Any, problems: _Problems) -> dict[str, PointDef]:
    if not isinstance(raw, dict):
        problems.add("points", "must be an object NAME: [x, y]")
        return {}
    points: dict[str, PointDef] = {}
    for key, value in raw.items():
        point = _read_point(str(key), value, f"points[{key!r}]", problems)
        if point is not None:
            points[point.name] = point
    return points


def _read_point(name: str, value: Any, where: str, problems: _Problems) -> PointDef | None:
    on = None
    if isinstance(value, dict):
        extra = set(value) - {"xy", "on"}
        if extra:
            problems.add(where, f"unknown keys {sorted(extra)}")
            return None
        on = value.get("on")
        if on is not None and not _is_name(on):
            problems.add(where, "'on' must be a link name")
            return None
        on = None if on is None else _text(on)
        value = value.get("xy")
    if not isinstance(value, list) or len(value) != 2:
        problems.add(where, "must be [x, y] with finite numbers")
        return None
    coords, exact, why = _numbers(value)
    if len(coords) != 2:
        problems.add(
            where,
            "must be [x, y] with finite numbers or exact expressions like '0.2*sqrt(3)'" + why,
        )
        return None
    try:
        return make_point(name, coords[0], coords[1], on, exact=(exact[0], exact[1]))
    except StatementError as exc:
        problems.add(where, exc.reason)
        return None


def _read_loads(raw: Any, problems: _Problems) -> list[Load]:
    if not isinstance(raw, list):
        problems.add("loads", "must be a list")
        return []
    loads: list[Load] = []
    for i, item in enumerate(raw):
        load = _read_load(item, f"loads[{i}]", problems)
        if load is not None:
            loads.append(load)
    return loads


def _read_load(item: Any, where: str, problems: _Problems) -> Load | None:
    kind = item.get("kind") if isinstance(item, dict) else None
    if not isinstance(kind, str) or kind not in _LOAD_WORDS:
        words = ", ".join(k.value for k in LoadKind)
        problems.add(where, f"must be an object with kind one of {words}")
        return None
    kind = LoadKind(kind)
    extra = set(item) - set(_LOAD_FIELDS)
    if extra:
        problems.add(where, f"unknown keys {sorted(extra)}")
        return None
    values = item.get("values", [])
    link = item.get("link", "")
    point = item.get("point")
    numbers, written, why = _numbers(values if isinstance(values, list) else [None])
    if (
        not isinstance(values, list)
        or len(numbers) != len(values)
        or (kind.takes_link and not _is_name(link))
        or (kind.takes_point and not _is_name(point))
    ):
        problems.add(
            where, "needs 'link', 'point' (force, mass, balance) and finite 'values'" + why
        )
        return None
    try:
        return make_load(
            kind,
            _text(link) if link not in (None, "") else "",
            None if point is None else _text(point),
            numbers,
            exact=tuple(written) if any(written) else (),
        )
    except StatementError as exc:
        problems.add(where, exc.reason)
        return None


_LOAD_WORDS = frozenset(k.value for k in LoadKind)


def _read_cams(raw: Any, source: str, problems: _Problems) -> list:
    """The ``cams`` entries (:func:`~structure.readwrite.camfile.cam_from_item`)."""
    if not isinstance(raw, list):
        problems.add("cams", "must be a list")
        return []
    cams = []
    for i, item in enumerate(raw):
        try:
            cams.append(cam_from_item(item, source))
        except StatementError as exc:
            problems.add(f"cams[{i}]", exc.reason)
    return cams


def _read_cycle_loads(drive: Any, raw: Any, problems: _Problems) -> list[CycleLoad]:
    """The ``drive`` object and the ``cycle`` list (:mod:`structure.cycle`)."""
    out: list[CycleLoad] = []
    items = [] if drive is None else [("drive", "drive", drive)]
    if not isinstance(raw, list):
        problems.add("cycle", "must be a list")
    else:
        items += [("cycle", f"cycle[{i}]", item) for i, item in enumerate(raw)]
    for kind, where, item in items:
        try:
            out.append(cycle_load_from_dict(kind, item))
        except StatementError as exc:
            problems.add(where, exc.reason)
    return out


def _read_targets(raw: Any, problems: _Problems) -> tuple[Target, ...]:
    """``{"T1": {"xy": [x, y], "input": DEG, "angle": DEG}}`` (or ``"T1": [x, y]``)."""
    if not isinstance(raw, dict):
        problems.add("targets", "must be an object NAME: {xy: [x, y], input: DEG, angle: DEG}")
        return ()
    targets: list[Target] = []
    for key, value in raw.items():
        where = f"targets[{key!r}]"
        item = value if isinstance(value, dict) else {"xy": value}
        extra = set(item) - {"xy", "input", "angle"}
        xy = item.get("xy")
        options = [item.get(k) for k in ("input", "angle")]
        if extra:
            problems.add(where, f"unknown keys {sorted(extra)}")
        elif (
            not isinstance(xy, list)
            or len(xy) != 2
            or not all(map(_is_number, xy))
            or not all(v is None or _is_number(v) for v in options)
        ):
            problems.add(where, "needs 'xy': [x, y] and optional 'input', 'angle' as numbers")
        else:
            try:
                targets.append(make_target(str(key), xy[0], xy[1], *options))
            except StatementError as exc:
                problems.add(where, exc.reason)
    return tuple(targets)


def mechanism_to_dict(mechanism: Mechanism) -> dict[str, Any]:
    """The JSON-shaped dict of ``mechanism`` (inverse of :func:`mechanism_from_dict`)."""
    out: dict[str, Any] = {}
    if mechanism.name:
        out["name"] = mechanism.name
    out["ground"] = mechanism.ground
    if mechanism.drivers:
        out["drivers"] = [
            {"link": d.link, **dict(d.motion)} if d.motion else d.link for d in mechanism.drivers
        ]
    pairs = []
    for p in mechanism.pairs:
        item: dict[str, Any] = {"links": [p.a, p.b], "kind": p.kind.value}
        if p.point is not None:
            item["point"] = p.point
        for key, value in (
            ("angle", p.angle_deg),
            ("flat", p.flat),
            ("roller", p.roller),
            ("normal", p.normal_deg),
            ("span", p.span),
            ("friction", p.friction),
            ("circle", p.circle),
            ("internal", p.internal),
            ("module", p.module),
        ):
            if value is not None:
                item[key] = value
        if p.centers is not None:
            item["centers"] = list(p.centers)
        if p.gear:
            item["gear"] = True
        if p.teeth is not None:
            item["z"] = ["?" if t is None else t for t in p.teeth]
        pairs.append(item)
    out["pairs"] = pairs
    if mechanism.loads:
        out["loads"] = [
            {
                "kind": x.kind.value,
                "link": x.link,
                "point": x.point,
                "values": [
                    (x.exact[k] if k < len(x.exact) and x.exact[k] else v)
                    for k, v in enumerate(x.values)
                ],
            }
            for x in mechanism.loads
        ]
    if mechanism.cams:
        out["cams"] = [cam_to_item(ref) for ref in mechanism.cams]
    for load in mechanism.cycle_loads:
        if load.kind == "drive":
            out["drive"] = cycle_load_to_dict(load)
        else:
            out.setdefault("cycle", []).append(cycle_load_to_dict(load))
    if mechanism.points:
        out["points"] = {}
        for p in mechanism.points.values():
            xy = [p.exact[0] or p.x, p.exact[1] or p.y]
            out["points"][p.name] = {"xy": xy, "on": p.on} if p.on else xy
    if mechanism.targets:
        out["targets"] = {}
        for t in mechanism.targets:
            item: dict[str, Any] = {"xy": [t.x, t.y]}
            if t.input_deg is not None:
                item["input"] = t.input_deg
            if t.angle_deg is not None:
                item["angle"] = t.angle_deg
            out["targets"][t.name] = item
    return out


def mechanism_to_json(mechanism: Mechanism, indent: int | None = 2) -> str:
    """The JSON text of ``mechanism`` (strict JSON: its numbers are finite, as read)."""
    return json.dumps(
        mechanism_to_dict(mechanism), indent=indent, ensure_ascii=False, allow_nan=False
    )
