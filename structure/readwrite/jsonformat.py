"""The JSON form of the mechanism model (same content as the edge list).

::

    {"name": "four-bar", "ground": "0",
     "drivers": ["1"]  or  [{"link": "1", "omega": 20}],
     "pairs": [{"links": ["0", "1"], "kind": "R", "point": "A"},
               {"links": ["3", "0"], "kind": "P", "point": "C", "angle": 30},
               {"links": ["1", "4"], "kind": "H", "flat": "4", "centers": ["O1", null]}],
     "points": {"A": [0, 0], "M": {"xy": [0.1, 0.2], "on": "2"}}}

>>> m = mechanism_from_json('{"drivers": ["1"], "pairs": [{"links": [0, 1], "kind": "R"}]}')
>>> m.pairs[0].label
'0–1 R'
>>> mechanism_to_dict(m)["pairs"]
[{'links': ['0', '1'], 'kind': 'R'}]
"""

from __future__ import annotations

import json
import math
from typing import Any

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

__all__ = ["mechanism_from_dict", "mechanism_from_json", "mechanism_to_dict", "mechanism_to_json"]

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


def mechanism_from_json(text: str, source: str = "<json>") -> Mechanism:
    """Parse the JSON form of a mechanism.

    Raises
    ------
    EdgeListError
        Invalid JSON (with its line) or any problem :func:`mechanism_from_dict` finds.
    """
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        lines = text.splitlines()
        line = lines[exc.lineno - 1] if 0 < exc.lineno <= len(lines) else ""
        raise EdgeListError(
            source, [EdgeListProblem(exc.lineno, line, f"invalid JSON: {exc.msg}")]
        ) from None
    return mechanism_from_dict(data, source)


def _is_name(value: Any) -> bool:
    if isinstance(value, bool):
        return False
    return isinstance(value, (str, int)) or (isinstance(value, float) and value.is_integer())


def _is_number(value: Any) -> bool:
    return (
        isinstance(value, (int, float))
        and not isinstance(value, bool)
        and math.isfinite(float(value))
    )


def _numbers(values: list[Any]) -> tuple[list[float], list[str | None]]:
    """Numbers, or exact expressions as strings (``"0.2*sqrt(3)"``), up to the first bad one.

    Returns the float values and, for each, the text it was written as (None for a number).
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
        except ValueError:
            number = None
        if number is None:
            break
        numbers.append(number)
        written.append(v)
    return numbers, written


def _text(value: Any) -> str:
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


def mechanism_from_dict(data: Any, source: str = "<dict>") -> Mechanism:
    """Build a validated mechanism from the JSON-shaped dict.

    Link and point names are strings (integers are accepted and turned into
    strings); numbers must be finite.
    """
    problems: list[EdgeListProblem] = []

    def bad(where: str, reason: str) -> None:
        problems.append(EdgeListProblem(0, "", f"{where}: {reason}"))

    if not isinstance(data, dict):
        raise EdgeListError(source, [EdgeListProblem(0, "", "the top level must be an object")])
    unknown = set(data) - {"name", "ground", "drivers", "pairs", "points", "loads"}
    if unknown:
        bad("top level", f"unknown keys {sorted(unknown)}")
    name = data.get("name", "")
    if not isinstance(name, str):
        bad("name", "must be a string")
        name = ""
    ground = data.get("ground", "0")
    if not _is_name(ground):
        bad("ground", "must be a link name")
        ground = "0"
    pairs: list[Pair] = []
    raw_pairs = data.get("pairs", [])
    if not isinstance(raw_pairs, list):
        bad("pairs", "must be a list")
        raw_pairs = []
    for i, item in enumerate(raw_pairs):
        where = f"pairs[{i}]"
        if not isinstance(item, dict):
            bad(where, "must be an object")
            continue
        extra = set(item) - set(_PAIR_FIELDS)
        if extra:
            bad(where, f"unknown keys {sorted(extra)}")
            continue
        links = item.get("links")
        if not isinstance(links, list) or len(links) != 2 or not all(map(_is_name, links)):
            bad(where, "'links' must be a list of two link names")
            continue
        kind = item.get("kind")
        if not isinstance(kind, str):
            bad(where, "'kind' must be one of R, P, H")
            continue
        tokens = [_text(links[0]), _text(links[1]), kind]
        if item.get("point") is not None:
            if not _is_name(item["point"]):
                bad(where, "'point' must be a point name")
                continue
            tokens.append(_text(item["point"]))
        shape_ok = True
        for key in ("angle", "normal", "span", "friction", "circle"):
            if item.get(key) is not None:
                if not _is_number(item[key]):
                    bad(where, f"'{key}' must be a finite number of degrees")
                    shape_ok = False
                else:
                    tokens.append(f"{key}={item[key]!r}")
        for key in ("flat", "roller"):
            if item.get(key) is not None:
                if not _is_name(item[key]):
                    bad(where, f"'{key}' must be a link name")
                    shape_ok = False
                else:
                    tokens.append(f"{key}={_text(item[key])}")
        if item.get("centers") is not None:
            c = item["centers"]
            if (
                not isinstance(c, list)
                or len(c) != 2
                or not all(v is None or _is_name(v) for v in c)
            ):
                bad(where, "'centers' must be a list of two point names (or null)")
                shape_ok = False
            else:
                tokens.append("centers=" + ",".join("" if v is None else _text(v) for v in c))
        if item.get("gear"):
            tokens.append("gear")
        if item.get("z") is not None:
            z = item["z"]
            if not isinstance(z, list) or len(z) != 2:
                bad(where, "'z' must be [za, zb] (integers or '?')")
                continue
            tokens.append("z=" + ",".join(str(t) for t in z))
        for key in ("internal", "module"):
            if item.get(key) is not None:
                tokens.append(f"{key}={_text(item[key])}")
        if not shape_ok:
            continue
        pair, why = pair_from_tokens(tokens, len(pairs) + 1, 0)
        if pair is None:
            bad(where, why)
        else:
            pairs.append(pair)
    drivers: list[Driver] = []
    raw_drivers = data.get("drivers", [])
    if not isinstance(raw_drivers, list):
        bad("drivers", "must be a list of link names or objects with 'link'")
        raw_drivers = []
    for i, item in enumerate(raw_drivers):
        where = f"drivers[{i}]"
        if _is_name(item):
            drivers.append(Driver(_text(item)))
        elif isinstance(item, dict) and _is_name(item.get("link")):
            motion = []
            for key, value in item.items():
                if key == "link":
                    continue
                if key not in DRIVER_KEYS:
                    bad(where, f"unknown option {key!r} (use {', '.join(DRIVER_KEYS)})")
                elif not _is_number(value):
                    bad(where, f"option {key!r} must be a finite number")
                else:
                    motion.append((key, float(value)))
            drivers.append(Driver(_text(item["link"]), tuple(motion)))
        else:
            bad(where, "must be a link name or an object with 'link'")
    points: dict[str, PointDef] = {}
    raw_points = data.get("points", {})
    if not isinstance(raw_points, dict):
        bad("points", "must be an object NAME: [x, y]")
        raw_points = {}
    for key, value in raw_points.items():
        where = f"points[{key!r}]"
        on = None
        if isinstance(value, dict):
            extra = set(value) - {"xy", "on"}
            if extra:
                bad(where, f"unknown keys {sorted(extra)}")
                continue
            on = value.get("on")
            if on is not None and not _is_name(on):
                bad(where, "'on' must be a link name")
                continue
            on = None if on is None else _text(on)
            value = value.get("xy")
        if not isinstance(value, list) or len(value) != 2:
            bad(where, "must be [x, y] with finite numbers")
            continue
        coords, exact = _numbers(value)
        if len(coords) != 2:
            bad(where, "must be [x, y] with finite numbers or exact expressions like '0.2*sqrt(3)'")
            continue
        points[str(key)] = PointDef(str(key), coords[0], coords[1], on, 0, (exact[0], exact[1]))
    loads: list[Load] = []
    raw_loads = data.get("loads", [])
    if not isinstance(raw_loads, list):
        bad("loads", "must be a list")
        raw_loads = []
    for i, item in enumerate(raw_loads):
        where = f"loads[{i}]"
        if not isinstance(item, dict) or item.get("kind") not in LOAD_KINDS:
            bad(where, f"must be an object with kind one of {', '.join(LOAD_KINDS)}")
            continue
        kind = item["kind"]
        point_role, _ = LOAD_KINDS[kind]
        values = item.get("values", [])
        link = item.get("link", "")
        point = item.get("point")
        numbers, written = _numbers(values if isinstance(values, list) else [None])
        if (
            not isinstance(values, list)
            or len(numbers) != len(values)
            or (kind != "gravity" and not _is_name(link))
            or (point_role and not _is_name(point))
        ):
            bad(where, "needs 'link', 'point' (force, mass, balance) and finite 'values'")
            continue
        loads.append(
            Load(
                kind,
                _text(link) if kind != "gravity" else "",
                _text(point) if point_role else None,
                tuple(numbers),
                0,
                tuple(written) if any(written) else (),
            )
        )
    if problems:
        raise EdgeListError(source, problems)
    mechanism = Mechanism(
        tuple(pairs), _text(ground), tuple(drivers), points, name, source, tuple(loads)
    )
    return validated(mechanism)


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
                "kind": x.kind,
                "link": x.link,
                "point": x.point,
                "values": [
                    (x.exact[k] if k < len(x.exact) and x.exact[k] else v)
                    for k, v in enumerate(x.values)
                ],
            }
            for x in mechanism.loads
        ]
    if mechanism.points:
        out["points"] = {}
        for p in mechanism.points.values():
            xy = [p.exact[0] or p.x, p.exact[1] or p.y]
            out["points"][p.name] = {"xy": xy, "on": p.on} if p.on else xy
    return out


def mechanism_to_json(mechanism: Mechanism, indent: int | None = 2) -> str:
    """The JSON text of ``mechanism``."""
    return json.dumps(mechanism_to_dict(mechanism), indent=indent, ensure_ascii=False)
