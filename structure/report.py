"""The structural report: counts, mobility, replacement, drivers, Assur groups, formula.

:func:`analyze` runs the whole structural analysis the way the textbook
does it; :func:`format_report` prints it as a worked answer and
:func:`report_to_dict` gives the JSON-ready form.

>>> from structure import parse_edgelist
>>> r = analyze(parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]))
>>> r.mobility.W, r.formula, r.textbook_formula
(1, 'I(1) → II(2,3)', '1 = 1 + 0')
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import networkx as nx

from .assur import AssurGroup, Decomposition, decompose, driver_candidates, roman
from .errors import DecompositionError, EdgeListError, MobilityError
from .mobility import Mobility, mobility_analysis
from .model import Mechanism
from .replacement import Replacement, replace_higher_pairs
from .rigidity.constraints import constraint_system, sketch_problems
from .rigidity.rank import generic_rank
from .utils import paused_gc

__all__ = [
    "DriverChoice",
    "StructuralReport",
    "all_driver_choices",
    "analyze",
    "format_mobility_error",
    "format_report",
    "mobility_error_dict",
    "report_to_dict",
]


@dataclass(frozen=True)
class StructuralReport:
    """Everything the structural analysis found, groups in solve order.

    ``replaced`` is the lower-pair mechanism the groups belong to;
    ``replacements`` maps each virtual link back to the higher pair it stands
    for. ``drivers_chosen`` is true when the drivers were picked by the
    analyzer (none was named).
    """

    mechanism: Mechanism
    mobility: Mobility
    replaced: Mechanism
    replaced_mobility: Mobility
    replacements: tuple[Replacement, ...]
    drivers: tuple[str, ...]
    drivers_chosen: bool
    decomposition: Decomposition

    @property
    def groups(self) -> tuple[AssurGroup, ...]:
        return self.decomposition.groups

    @property
    def dag(self) -> nx.DiGraph:
        return self.decomposition.dag

    @property
    def mechanism_class(self) -> int:
        return self.decomposition.mechanism_class

    @property
    def formula(self) -> str:
        return self.decomposition.formula

    @property
    def textbook_formula(self) -> str:
        return self.decomposition.textbook_formula

    @property
    def detach_order(self) -> tuple[AssurGroup, ...]:
        """Groups in the textbook's order of detaching: farthest from the drivers first."""
        return tuple(reversed(self.groups))

    def __repr__(self) -> str:
        return f"<StructuralReport W={self.mobility.W} {self.formula}>"


def _pick_drivers(replaced: Mechanism, w: int, exclude: set[str]) -> tuple[str, ...]:
    chosen: list[str] = []
    for link in driver_candidates(replaced):
        if len(chosen) == w:
            break
        if link in exclude:
            continue
        trial = [*chosen, link]
        analysis = generic_rank(constraint_system(replaced, trial))
        if not analysis.dependent_drivers:
            chosen = trial
    return tuple(chosen)


def analyze(mechanism: Mechanism, drivers: Sequence[str] | None = None) -> StructuralReport:
    """Structural analysis of ``mechanism`` with the given (or its own, or chosen) drivers.

    Raises
    ------
    EdgeListError
        Coordinates given for some pairs but missing for others (or a P pair
        without ``angle=``, an H pair without a normal) in a sketch.
    MobilityError
        W <= 0, W different from the number of drivers, or a driver whose
        motion is already fixed; the error carries the computed ``mobility``.
    DecompositionError
        Links the drivers leave undetermined.
    """
    with paused_gc():
        return _analyze(mechanism, drivers)


def _analyze(mechanism: Mechanism, drivers: Sequence[str] | None) -> StructuralReport:
    if drivers is not None:
        mechanism = mechanism.with_drivers(drivers)
    missing = sketch_problems(mechanism)
    if missing:
        raise EdgeListError(mechanism.source, missing)
    mob, generic, geometric = mobility_analysis(mechanism)
    replaced, replacements = replace_higher_pairs(mechanism)
    w = mob.W
    if w <= 0:
        why = "it is a rigid structure" if w == 0 else "it is over-constrained"
        raise MobilityError(f"W = {w}: the chain cannot move, {why} ({mob.formula})", mob)
    named = mechanism.driver_links
    chosen = not named
    if named:
        if len(named) != w:
            raise MobilityError(
                f"W = {w} but {len(named)} driver(s) named ({', '.join(named)}): "
                f"name exactly {w} ({mob.formula})",
                mob,
            )
        drivers_used = named
    else:
        virtual = {r.virtual_link for r in replacements}
        drivers_used = _pick_drivers(replaced, w, virtual)
        if len(drivers_used) < w:
            raise MobilityError(
                f"W = {w} but only {len(drivers_used)} link(s) joined to the ground can be "
                f"independent drivers ({', '.join(drivers_used) or 'none'})",
                mob,
            )
    rmob = mob
    if replacements or chosen:
        # the rank analyses are reused by the decomposition: redo them for what it sees
        replaced_mob, generic, geometric = mobility_analysis(replaced, drivers_used)
        if replacements:
            rmob = replaced_mob
    decomposition = decompose(replaced, drivers_used, analyses=(generic, geometric))
    return StructuralReport(
        mechanism, mob, replaced, rmob, replacements, tuple(drivers_used), chosen, decomposition
    )


@dataclass(frozen=True, slots=True)
class DriverChoice:
    """One admissible choice of drivers and the groups it gives."""

    drivers: tuple[str, ...]
    decomposition: Decomposition


def all_driver_choices(report: StructuralReport, limit: int = 1000) -> tuple[DriverChoice, ...]:
    """Every admissible set of W drivers joined to the ground, with its groups and class."""
    virtual = {r.virtual_link for r in report.replacements}
    candidates = [c for c in driver_candidates(report.replaced) if c not in virtual]
    out: list[DriverChoice] = []
    for combo in itertools.islice(itertools.combinations(candidates, report.mobility.W), limit):
        try:
            out.append(DriverChoice(combo, decompose(report.replaced, combo)))
        except (MobilityError, DecompositionError):
            continue
    return tuple(out)


# ----------------------------------------------------------------------------- text
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
        "kind": g.kind,
        "attached_to": list(g.known_links),
        "pairs": [
            {"links": list(p.links), "kind": p.kind.value, "point": p.point, "external": p.external}
            for p in g.pairs
        ],
    }


def report_to_dict(
    report: StructuralReport, choices: Sequence[DriverChoice] = ()
) -> dict[str, Any]:
    """JSON-ready dict: ``n, P5, P4, redundant, passive, W, replaced, groups, ...``."""
    out: dict[str, Any] = {"name": report.mechanism.name, "source": report.mechanism.source}
    out.update(_mobility_dict(report.mobility))
    rm = report.replaced_mobility
    out["replaced"] = {"n": rm.n, "P5": rm.P5, "P4": rm.P4, "W": rm.W}
    out["replacements"] = [
        {
            "virtual_link": r.virtual_link,
            "pair": r.pair.label,
            "line": r.pair.line_no,
            "scheme": r.scheme,
            "new_pairs": [p.label for p in r.new_pairs],
            "roller": r.roller.roller if r.roller else None,
        }
        for r in report.replacements
    ]
    out["drivers"] = list(report.drivers)
    out["drivers_chosen"] = report.drivers_chosen
    d = report.decomposition
    out["set_aside"] = {
        "links": list(d.removed_links),
        "pairs": [report.replaced.pair(p).label for p in d.removed_pairs],
    }
    out["groups"] = [_group_dict(g) for g in report.groups]
    out["group_dag"] = [list(e) for e in report.dag.edges]
    out["mechanism_class"] = report.mechanism_class
    out["formula"] = report.formula
    out["textbook_formula"] = report.textbook_formula
    if choices:
        out["driver_choices"] = [
            {
                "drivers": list(c.drivers),
                "mechanism_class": c.decomposition.mechanism_class,
                "formula": c.decomposition.formula,
                "groups": [_group_dict(g) for g in c.decomposition.groups],
            }
            for c in choices
        ]
    return out


def mobility_error_dict(error: MobilityError) -> dict[str, Any]:
    out: dict[str, Any] = {"error": str(error)}
    if isinstance(error.mobility, Mobility):
        out.update(_mobility_dict(error.mobility))
    return out
