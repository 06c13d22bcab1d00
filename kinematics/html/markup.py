"""Small HTML builders for the report: elements, tables, numbers tied to the JSON, strict JSON.

Everything written is well-formed XML as well as HTML (void elements closed,
attributes quoted, text escaped), so a test can read the page with an XML
parser. A number shown in a table carries where it comes from
(``data-source``: ``classify``, ``kinematics``, ``forces`` or ``gears``;
``data-path``: the keys into that command's ``--json`` answer joined by
``/``) and its full value (``data-value``), so the page can be checked
against the command line.

>>> number_cell(0.1 + 0.2, "kinematics", ("links", "2", "omega"))
'<td class="num" data-source="kinematics" data-path="links/2/omega" \
data-value="0.30000000000000004">0.3</td>'
>>> strict_json({"x": float("nan"), "y": [1.5, float("inf")], "z": "</script>"})
'{"x":null,"y":[1.5,null],"z":"\\\\u003c/script>"}'
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping, Sequence
from html import escape
from typing import Any

__all__ = [
    "element",
    "format_number",
    "json_script",
    "note",
    "number_cell",
    "strict_json",
    "table",
]

#: a value this small against the largest of its kind is shown as 0 (round-off, not a result)
_NOISE = 1e-12


def element(tag: str, content: str = "", **attributes: object) -> str:
    """``<tag attr="…">content</tag>``; ``content`` is markup (escape text first).

    An attribute whose name ends with ``_`` loses it (``class_``), one with ``_``
    inside gets ``-`` (``data_path``); ``None`` and ``False`` leave it out.

    >>> element("p", "a &amp; b", class_="note", data_key="x", hidden=None)
    '<p class="note" data-key="x">a &amp; b</p>'
    """
    parts = [tag]
    for name, value in attributes.items():
        if value is None or value is False:
            continue
        parts.append(f'{name.rstrip("_").replace("_", "-")}="{escape(str(value))}"')
    return f"<{' '.join(parts)}>{content}</{tag}>"


def format_number(value: float) -> str:
    """A number as the page shows it: six significant digits, round-off shown as 0.

    >>> format_number(-1.2e-17), format_number(2.0), format_number(1234567.0)
    ('0', '2', '1.23457e+06')
    """
    if not math.isfinite(value):
        return "—"
    if abs(value) < _NOISE:
        value = 0.0
    return f"{value + 0.0:.6g}"


def number_cell(value: float, source: str, path: Sequence[object]) -> str:
    """A table cell with a number and where it comes from in the command's JSON answer."""
    return element(
        "td",
        escape(format_number(value)),
        class_="num",
        data_source=source,
        data_path="/".join(str(key) for key in path),
        data_value=repr(float(value)),
    )


def table(headings: Sequence[str], rows: Iterable[Sequence[str]], caption: str = "") -> str:
    """A table: ``headings`` are text (escaped), each row's cells are markup.

    A cell that is not already a ``<td …>`` element is wrapped in one.
    """
    head = "".join(element("th", escape(h), scope="col") for h in headings)
    body = []
    for row in rows:
        cells = "".join(c if c.startswith("<td") else element("td", c) for c in row)
        body.append(element("tr", cells))
    title = element("caption", escape(caption)) if caption else ""
    return element(
        "table",
        title + element("thead", element("tr", head)) + element("tbody", "".join(body)),
    )


def note(text: str, kind: str = "") -> str:
    """A one-line note (a section that does not apply, or why a result stops), escaped."""
    return element("p", escape(text), class_="note", data_note=kind or None)


def _finite(data: Any) -> Any:
    """``data`` with every NaN or infinity as ``None`` (JSON has neither)."""
    if isinstance(data, float):
        return data if math.isfinite(data) else None
    if isinstance(data, Mapping):
        return {str(k): _finite(v) for k, v in data.items()}
    if isinstance(data, (list, tuple)):
        return [_finite(v) for v in data]
    return data


def strict_json(data: Any) -> str:
    """Compact strict JSON (no NaN or infinity), safe inside a ``<script>`` element."""
    text = json.dumps(_finite(data), ensure_ascii=False, allow_nan=False, separators=(",", ":"))
    return text.replace("<", "\\u003c").replace("&", "\\u0026")


def json_script(element_id: str, data: Any) -> str:
    """``<script type="application/json" id="…">`` holding ``data`` for the page's script."""
    return element("script", strict_json(data), type="application/json", id=element_id)
