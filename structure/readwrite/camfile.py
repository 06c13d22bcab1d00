"""Cam programs in files, and the mechanism statement that refers to one.

The edge list names a cam's program by its file, ``cam CAM LINK FILE
[at=DEG]``: the higher pair between link ``CAM`` (turning about the ground)
and ``LINK`` (the follower, or its roller) has the profile of the design in
``FILE`` (the ``assur cam`` spec, JSON; a relative path is read from the edge
list's folder), and the sketch shows the cam at ``at`` degrees of its program
(default 0). The JSON form holds it as ``"cams": [{"links": [CAM, LINK],
"spec": {...} or "file": "FILE", "at": DEG}]``.

>>> ref = cam_from_item({"links": ["1", "3"], "at": 30, "spec": {"base_radius": 0.04,
...     "follower": {"motion": "translating", "contact": "knife"},
...     "segments": [{"law": "harmonic", "lift": 0.01, "angle": 180},
...                  {"law": "harmonic", "lift": -0.01, "angle": 180}]}}, "<dict>")
>>> ref.cam, ref.other, ref.at_deg, ref.path
('1', '3', 30.0, None)
"""

from __future__ import annotations

import json
import math
import os
import sys
from pathlib import Path
from typing import Any

from ..cams import CamRef, CamSpec, cam_spec_from_dict, cam_spec_to_dict
from ..errors import CamProgramError, EdgeListError, EdgeListProblem, StatementError
from ..validation import MAX_MAGNITUDE
from .textfile import read_text

__all__ = ["cam_from_item", "cam_from_tokens", "cam_to_item", "read_cam_spec"]

#: the usage of the statement, in its messages
CAM_USAGE = "cam CAM LINK FILE [at=DEG]"


def read_cam_spec(path: str | os.PathLike[str]) -> CamSpec:
    """Read a cam design (the ``assur cam`` spec) from a JSON file.

    Raises
    ------
    EdgeListError
        The file cannot be read (a missing file, not UTF-8, too large).
    CamProgramError
        It is not JSON, or not a valid spec (every problem at once).
    """
    text = read_text(path)
    return cam_spec_from_dict(_decode(text, str(path)), str(path))


def _decode(text: str, source: str) -> Any:
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        reason = f"invalid JSON: {exc.msg} (line {exc.lineno})"
    except ValueError:
        reason = f"invalid JSON: an integer of more than {sys.get_int_max_str_digits()} digits"
    except RecursionError:
        reason = "invalid JSON: arrays or objects nested too deeply"
    raise CamProgramError(source, [EdgeListProblem(0, "", reason)])


def _beside(name: str, source: str) -> Path:
    """``name`` as a path: relative ones from the folder of the file that names it."""
    path = Path(name)
    if path.is_absolute() or source.startswith("<"):
        return path
    return Path(source).parent / path


def _spec_of(name: str, source: str) -> CamSpec:
    """The spec in file ``name`` (named in ``source``), or a StatementError saying why not."""
    try:
        return read_cam_spec(_beside(name, source))
    except EdgeListError as exc:
        problems = "; ".join(str(p) for p in exc.problems[:5])
        raise StatementError(f"cam program {name}: {problems}") from None


def _angle(text: Any) -> float:
    try:
        value = float(text)
    except (TypeError, ValueError, OverflowError):
        value = math.nan
    if isinstance(text, bool) or not math.isfinite(value) or abs(value) > MAX_MAGNITUDE:
        raise StatementError(f"at= needs a finite angle in degrees, not {str(text)[:40]!r}")
    return value


def cam_from_tokens(tokens: list[str], line_no: int, source: str) -> CamRef:
    """The ``cam CAM LINK FILE [at=DEG]`` statement of an edge list.

    Raises
    ------
    StatementError
        Missing or extra tokens, a bad angle, a program file that cannot be
        read or is not a valid spec (its problems quoted).
    """
    if len(tokens) not in (4, 5) or "=" in tokens[3]:
        raise StatementError(f"expected '{CAM_USAGE}'")
    at = 0.0
    if len(tokens) == 5:
        key, eq, value = tokens[4].partition("=")
        if key != "at" or not eq:
            raise StatementError(f"unexpected token {tokens[4]!r} (expected '{CAM_USAGE}')")
        at = _angle(value)
    spec = _spec_of(tokens[3], source)
    return CamRef(tokens[1], tokens[2], spec, tokens[3], at, line_no)


def cam_from_item(item: Any, source: str) -> CamRef:
    """One entry of a JSON mechanism's ``cams``.

    Raises
    ------
    StatementError
        Not ``{"links": [CAM, LINK], "spec": {...} or "file": NAME, "at": DEG}``,
        or a spec (inline or in its file) that is not valid.
    """
    usage = 'must be {"links": [CAM, LINK], "spec": {...} or "file": "NAME", "at": DEG}'
    if not isinstance(item, dict) or set(item) - {"links", "spec", "file", "at"}:
        raise StatementError(usage)
    links = item.get("links")
    if (
        not isinstance(links, list)
        or len(links) != 2
        or not all(isinstance(x, (str, int)) and not isinstance(x, bool) for x in links)
    ):
        raise StatementError(usage)
    at = _angle(item.get("at", 0.0))
    if ("spec" in item) == ("file" in item):
        raise StatementError(usage + ": give one of spec and file")
    if "file" in item:
        if not isinstance(item["file"], str) or not item["file"]:
            raise StatementError(usage)
        spec = _spec_of(item["file"], source)
        path = item["file"]
    else:
        try:
            spec = cam_spec_from_dict(item["spec"], "spec")
        except CamProgramError as exc:
            problems = "; ".join(str(p) for p in exc.problems[:5])
            raise StatementError(f"cam program: {problems}") from None
        path = None
    return CamRef(str(links[0]), str(links[1]), spec, path, at)


def cam_to_item(ref: CamRef) -> dict[str, Any]:
    """The JSON entry of a cam statement, its program held inline (the file needs no copy)."""
    item: dict[str, Any] = {"links": [ref.cam, ref.other], "spec": cam_spec_to_dict(ref.spec)}
    if ref.at_deg:
        item["at"] = ref.at_deg
    return item
