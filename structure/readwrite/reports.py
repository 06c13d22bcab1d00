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

import itertools
import json
from collections.abc import Iterator, Sequence
from typing import Any, TextIO

from ..assur import AssurGroup, roman
from ..errors import MobilityError
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
        "kind": None if g.kind is None else g.kind.value,
        "attached_to": list(g.known_links),
        "pairs": [
            {"links": list(p.links), "kind": p.kind.value, "point": p.point, "external": p.external}
            for p in g.pairs
        ],
    }


def _report_items(
    report: StructuralReport, choices: Sequence[DriverChoice]
) -> Iterator[tuple[str, Any]]:
    """The report's JSON keys and values in order; ``groups`` and ``group_dag`` as iterators."""
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
    yield "groups", (_group_dict(g) for g in report.groups)
    yield "group_dag", (list(e) for e in report.decomposition.dag_edges)
    yield "mechanism_class", report.mechanism_class
    yield "formula", report.formula
    yield "textbook_formula", report.textbook_formula
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
        key: list(value) if isinstance(value, Iterator) else value
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
    """The report as compact JSON, its long lists one item at a time."""
    dumps = json.JSONEncoder(ensure_ascii=False, separators=(",", ":")).encode
    sep = "{"
    for key, value in _report_items(report, choices):
        stream.write(f"{sep}{dumps(key)}:")
        sep = ","
        if not isinstance(value, Iterator):
            stream.write(dumps(value))
            continue
        stream.write("[")
        sep_items = ""
        while chunk := list(itertools.islice(value, _CHUNK)):
            # a list's compact text is its items' joined by commas, in brackets
            stream.write(sep_items + dumps(chunk)[1:-1])
            sep_items = ","
        stream.write("]")
    stream.write("}\n")


#: items of a long list encoded in one call (a few hundred kB of text at most)
_CHUNK = 1000


def mobility_error_dict(error: MobilityError) -> dict[str, Any]:
    out: dict[str, Any] = {"error": str(error)}
    if isinstance(error.mobility, Mobility):
        out.update(_mobility_dict(error.mobility))
    return out
