"""The structural report as text and as JSON: the textbook's worked answer, the CLI's ``--json``.

Text in, text out: :func:`format_report` and :func:`format_mobility_error`
write the report of :func:`~structure.report.analyze` (or the counts behind
a mobility error) the way the textbook answers; :func:`report_to_dict` and
:func:`mobility_error_dict` give their JSON-ready forms, :func:`write_report_json` writes the
first as a stream (compact for a large mechanism).

>>> from structure import analyze, parse_edgelist
>>> r = analyze(parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]))
>>> print(format_report(r).splitlines()[-2])
Structural formula: I(1) → II(2,3)
>>> report_to_dict(r)["groups"][0]["kind"]  # a plain string: the dict is JSON-ready
'RRR'
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, TextIO

from ..assur import AssurGroup, roman
from ..errors import MobilityError
from ..kinds import DyadKind, PairKind
from ..mobility import Mobility
from ..report import DriverChoice, StructuralReport
from ..utils import paused_gc

__all__ = [
    "LARGE_REPORT",
    "format_mobility_error",
    "format_report",
    "mobility_error_dict",
    "report_to_dict",
    "write_report_json",
]


def _counts_line(m: Mobility) -> str:
    return f"n = {m.n} moving links, P5 = {m.P5} lower pairs, P4 = {m.P4} higher pairs"


def format_report(report: StructuralReport, choices: Sequence[DriverChoice] = ()) -> str:
    """The report as a worked answer, in the textbook's order."""
    m, mob = report.mechanism, report.mobility
    out: list[str] = []
    title = m.name or "mechanism"
    out.append(f"{title}  ({m.source})")
    out.append("")
    out.extend(_mobility_lines(mob))
    if report.replacements:
        out.append("")
        out.append("Higher-pair replacement:")
        for rep in report.replacements:
            if rep.roller is not None:
                r = rep.roller
                out.append(
                    f"  roller {r.roller} removed with pair {r.removed_pairs[0].label} "
                    f"(its spin is passive); contact moved to its axis {r.axis} "
                    f"on link {r.follower}"
                )
            new = ", ".join(p.label for p in rep.new_pairs)
            out.append(
                f"  {rep.pair.label} (line {rep.pair.line_no}) → virtual link "
                f"{rep.virtual_link}: {new} ({rep.scheme})"
            )
        rm = report.replaced_mobility
        out.append(f"  after replacement: {_counts_line(rm)}")
        out.append(f"  {rm.formula}")
    out.append("")
    how = " (chosen: links joined to the ground)" if report.drivers_chosen else ""
    out.append(f"Drivers: {', '.join(report.drivers)}{how}")
    d = report.decomposition
    if d.removed_links or d.removed_pairs:
        pairs = ", ".join(report.replaced.pair(p).label for p in d.removed_pairs)
        links = ", ".join(d.removed_links) or "none"
        out.append(f"Set aside as redundant: link(s) {links}; pair(s) {pairs}")
    out.append("")
    out.append("Assur groups in solve order (the textbook detaches them from the last):")
    if not report.groups:
        out.append("  none: the drivers and the ground are the whole mechanism")
    for i, g in enumerate(report.groups, start=1):
        kind = f", {g.kind}" if g.kind else ""
        known = ", ".join(g.known_links)
        out.append(
            f"  {i}. {g.label}  class {roman(g.assur_class)}, order {g.order}{kind}; "
            f"attached to {known}"
        )
    out.append(f"Mechanism class: {roman(report.mechanism_class)}")
    out.append(f"Structural formula: {report.formula}")
    out.append(f"                    {report.textbook_formula}")
    for warning in report.warnings:
        out.append(f"Warning: {warning}")
    if choices:
        out.append("")
        out.append("Every admissible choice of drivers:")
        for c in choices:
            out.append(
                f"  drivers {', '.join(c.drivers)}: class {roman(c.decomposition.mechanism_class)}"
                f"  {c.decomposition.formula}"
            )
    return "\n".join(out) + "\n"


def _mobility_lines(mob: Mobility) -> list[str]:
    out = [f"Counts: {_counts_line(mob)}"]
    if mob.redundant:
        out.append(f"Redundant constraints: r = {mob.r}")
        for x in mob.redundant:
            where = f" (line {x.line_no})" if x.line_no else ""
            out.append(f"  {x.constraints} in pair {x.label}{where}, {x.source}")
    else:
        out.append("Redundant constraints: r = 0")
    if mob.passive:
        out.append(f"Passive freedoms: W_passive = {mob.W_passive}")
        for x in mob.passive:
            out.append(f"  {x.dof} of link {x.link} ({x.source})")
    else:
        out.append("Passive freedoms: W_passive = 0")
    out.append(mob.formula)
    for note in mob.notes:
        out.append(f"Note: {note}")
    return out


def format_mobility_error(error: MobilityError) -> str:
    """The counts behind a mobility error, then the diagnostic."""
    lines = []
    if isinstance(error.mobility, Mobility):
        lines.extend(_mobility_lines(error.mobility))
    lines.append(f"error: {error}")
    return "\n".join(lines) + "\n"


# ----------------------------------------------------------------------------- JSON
def _mobility_dict(mob: Mobility) -> dict[str, Any]:
    return {
        "n": mob.n,
        "P5": mob.P5,
        "P4": mob.P4,
        "W_topology": mob.W_topology,
        "redundant": mob.r,
        "passive": mob.W_passive,
        "W": mob.W,
        "redundant_pairs": [
            {"pair": x.label, "line": x.line_no, "constraints": x.constraints, "source": x.source}
            for x in mob.redundant
        ],
        "passive_links": [{"link": x.link, "dof": x.dof, "source": x.source} for x in mob.passive],
        "geometric_check": mob.geometric,
        "notes": list(mob.notes),
    }


def _group_dict(g: AssurGroup) -> dict[str, Any]:
    return {
        "links": list(g.links),
        "class": g.assur_class,
        "order": g.order,
        "kind": _DYAD_TEXT.get(g.kind),
        "attached_to": list(g.known_links),
        "pairs": [
            {
                "links": list(p.links),
                "kind": _PAIR_TEXT[p.kind],
                "point": p.point,
                "external": p.external,
            }
            for p in g.pairs
        ],
    }


# the enums' text, looked up (an enum's ``.value`` is slow in a loop over every group)
_PAIR_TEXT = {kind: kind.value for kind in PairKind}
_DYAD_TEXT = {kind: kind.value for kind in DyadKind}
_quoted = json.encoder.encode_basestring  # a str as JSON text, as json.dumps(ensure_ascii=False)
_PAIR_JSON = {kind: _quoted(text) for kind, text in _PAIR_TEXT.items()}
_DYAD_JSON = {None: "null", **{kind: _quoted(text) for kind, text in _DYAD_TEXT.items()}}


def _group_json(g: AssurGroup) -> str:
    """Compact JSON of :func:`_group_dict`, written directly: the same text, several times faster.

    A large report's text is mostly its groups; building each group's dict
    for the encoder cost more than encoding it. Strings are quoted by the
    encoder's own function; the class and order are ints.
    """
    names = {x: _quoted(x) for x in g.links}
    attached: dict[str, str] = {}
    pairs = []
    for p in g.pairs:
        link, other = p.links
        first = names.get(link) or _quoted(link)  # a group link (the record's promise)
        point = "null" if p.point is None else _quoted(p.point)
        if p.external:
            known = attached.get(other)
            if known is None:
                known = attached[other] = _quoted(other)
            pairs.append(
                f'{{"links":[{first},{known}],"kind":{_PAIR_JSON[p.kind]},'
                f'"point":{point},"external":true}}'
            )
        else:
            second = names.get(other) or _quoted(other)
            pairs.append(
                f'{{"links":[{first},{second}],"kind":{_PAIR_JSON[p.kind]},'
                f'"point":{point},"external":false}}'
            )
    return (
        f'{{"links":[{",".join(map(names.__getitem__, g.links))}],"class":{g.assur_class},'
        f'"order":{g.order},"kind":{_DYAD_JSON[g.kind]},'
        f'"attached_to":[{",".join(attached.values())}],"pairs":[{",".join(pairs)}]}}'
    )


#: compact JSON of an edge ``(source, target)`` of the group DAG, ``[0,1]`` (ints: %d is repr)
_edge_json = "[%d,%d]".__mod__


@dataclass(frozen=True, slots=True)
class _LongList:
    """A long list of the report, and how an item becomes JSON-ready data or compact JSON text.

    :func:`report_to_dict` keeps ``as_data`` of each item, the compact writer
    writes ``as_json`` of each (the text ``json.dumps`` gives its data) a
    chunk at a time, so that the list is never held as data or as one text.
    """

    items: Sequence[Any]
    as_data: Callable[[Any], Any]
    as_json: Callable[[Any], str]


def _report_items(
    report: StructuralReport, choices: Sequence[DriverChoice]
) -> Iterator[tuple[str, Any]]:
    """The report's JSON keys and values in order; ``groups`` and ``group_dag`` as long lists."""
    yield "name", report.mechanism.name
    yield "source", report.mechanism.source
    yield from _mobility_dict(report.mobility).items()
    rm = report.replaced_mobility
    yield "replaced", {"n": rm.n, "P5": rm.P5, "P4": rm.P4, "W": rm.W}
    yield (
        "replacements",
        [
            {
                "virtual_link": r.virtual_link,
                "pair": r.pair.label,
                "line": r.pair.line_no,
                "scheme": r.scheme,
                "new_pairs": [p.label for p in r.new_pairs],
                "roller": r.roller.roller if r.roller else None,
            }
            for r in report.replacements
        ],
    )
    yield "drivers", list(report.drivers)
    yield "drivers_chosen", report.drivers_chosen
    d = report.decomposition
    yield (
        "set_aside",
        {
            "links": list(d.removed_links),
            "pairs": [report.replaced.pair(p).label for p in d.removed_pairs],
        },
    )
    yield "groups", _LongList(report.groups, _group_dict, _group_json)
    yield "group_dag", _LongList(report.decomposition.dag_edges, list, _edge_json)
    yield "mechanism_class", report.mechanism_class
    yield "formula", report.formula
    yield "textbook_formula", report.textbook_formula
    if report.singular:  # only then: the answers of a regular sketch stay as they were
        yield "warnings", list(report.warnings)
        yield "singular_groups", [report.groups[k].label for k in report.singular]
    if choices:
        yield (
            "driver_choices",
            [
                {
                    "drivers": list(c.drivers),
                    "mechanism_class": c.decomposition.mechanism_class,
                    "formula": c.decomposition.formula,
                    "groups": [_group_dict(g) for g in c.decomposition.groups],
                }
                for c in choices
            ],
        )


def report_to_dict(
    report: StructuralReport, choices: Sequence[DriverChoice] = ()
) -> dict[str, Any]:
    """JSON-ready dict: ``n, P5, P4, redundant, passive, W, replaced, groups, ...``."""
    return {
        key: [value.as_data(x) for x in value.items] if isinstance(value, _LongList) else value
        for key, value in _report_items(report, choices)
    }


#: from this many moving links on, ``--json`` is written compact (no indentation)
LARGE_REPORT = 2000


def write_report_json(
    report: StructuralReport, stream: TextIO, choices: Sequence[DriverChoice] = ()
) -> None:
    """Write :func:`report_to_dict` as JSON to ``stream``, ended by a newline.

    A report of fewer than :data:`LARGE_REPORT` moving links is written
    indented by 2; a larger one compact and as a stream: its groups one at a
    time, so that neither the whole dict nor the whole text is ever held.

    >>> import io
    >>> from structure import analyze, parse_edgelist
    >>> r = analyze(parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]))
    >>> out = io.StringIO()
    >>> write_report_json(r, out)
    >>> json.loads(out.getvalue()) == report_to_dict(r)
    True
    """
    if len(report.mechanism.moving_links) < LARGE_REPORT:
        stream.write(json.dumps(report_to_dict(report, choices), indent=2, ensure_ascii=False))
        stream.write("\n")
        return
    with paused_gc():  # the items are short-lived: no collector passes over the whole heap
        _write_compact(report, stream, choices)


def _write_compact(
    report: StructuralReport, stream: TextIO, choices: Sequence[DriverChoice]
) -> None:
    """The report as compact JSON, its long lists a chunk of items at a time."""
    dumps = json.JSONEncoder(ensure_ascii=False, separators=(",", ":")).encode
    sep = "{"
    for key, value in _report_items(report, choices):
        stream.write(f"{sep}{dumps(key)}:")
        sep = ","
        if isinstance(value, _LongList):
            _write_long_list(value, stream)
        else:
            stream.write(dumps(value))
    stream.write("}\n")


def _write_long_list(values: _LongList, stream: TextIO) -> None:
    """A long list as compact JSON: its items' texts joined by commas, in brackets."""
    items, as_json = values.items, values.as_json
    stream.write("[")
    for start in range(0, len(items), _CHUNK):
        stream.write(("," if start else "") + ",".join(map(as_json, items[start : start + _CHUNK])))
    stream.write("]")


#: items of a long list written in one call (a few hundred kB of text at most)
_CHUNK = 1000


def mobility_error_dict(error: MobilityError) -> dict[str, Any]:
    out: dict[str, Any] = {"error": str(error)}
    if isinstance(error.mobility, Mobility):
        out.update(_mobility_dict(error.mobility))
    return out
