"""The structural report: counts, mobility, replacement, drivers, Assur groups, formula.

:func:`analyze` runs the whole structural analysis the way the textbook
does it. Its text and JSON forms (``format_report``, ``report_to_dict``,
...) are in :mod:`structure.readwrite.reports`; importing them from here
still works for one release, with a DeprecationWarning.

>>> from structure import parse_edgelist
>>> r = analyze(parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]))
>>> r.mobility.W, r.formula, r.textbook_formula
(1, 'I(1) → II(2,3)', '1 = 1 + 0')
"""

from __future__ import annotations

import itertools
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .assur import (
    AssurGroup,
    Decomposition,
    GroupPlan,
    build_decomposition,
    decompose,
    driver_candidates,
    plan_groups,
)
from .errors import DecompositionError, EdgeListError, MobilityError
from .mobility import Mobility, PassiveMotion, mobility_analysis, rank_analyses
from .model import Mechanism
from .replacement import Replacement, replace_higher_pairs
from .rigidity.constraints import (
    MissingGeometry,
    constraint_system,
    sketch_problems,
    sketch_realization,
)
from .rigidity.rank import RankAnalysis, generic_rank, singular_blocks
from .utils import paused_gc

if TYPE_CHECKING:
    import networkx as nx

__all__ = ["DriverChoice", "StructuralReport", "all_driver_choices", "analyze"]

#: names that moved to :mod:`structure.readwrite.reports`
_MOVED_TO_READWRITE = ("format_mobility_error", "format_report", "mobility_error_dict",
                       "report_to_dict")  # fmt: skip


@dataclass(frozen=True)
class StructuralReport:
    """Everything the structural analysis found, groups in solve order.

    ``replaced`` is the lower-pair mechanism the groups belong to;
    ``replacements`` maps each virtual link back to the higher pair it stands
    for. ``drivers_chosen`` is true when the drivers were picked by the
    analyzer (none was named). ``singular`` holds the indices of the groups
    drawn at a singular pose (their Jacobian loses rank at the sketch: the
    structure is then read at a regular pose near it, and the solvers cannot
    start from the sketch); ``warnings`` says so in words.
    """

    mechanism: Mechanism
    mobility: Mobility
    replaced: Mechanism
    replaced_mobility: Mobility
    replacements: tuple[Replacement, ...]
    drivers: tuple[str, ...]
    drivers_chosen: bool
    decomposition: Decomposition
    singular: tuple[int, ...] = ()

    @property
    def groups(self) -> tuple[AssurGroup, ...]:
        return self.decomposition.groups

    @property
    def warnings(self) -> tuple[str, ...]:
        """What the user should know about the answer: each group singular at the sketch."""
        return tuple(_singular_sketch_warning(self.groups[k]) for k in self.singular)

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


def _singular_sketch_warning(group: AssurGroup) -> str:
    """The warning for a group drawn at a singular pose."""
    return (
        f"group {group.label} is at a singular pose in the sketch (its Jacobian loses rank "
        "there: a dead point, or a change point of its assembly); its structure is read at a "
        "regular pose near the sketch, and the kinematics cannot start from the sketch: draw "
        "it at another pose, or start from other inputs"
    )


def _pick_drivers(
    replaced: Mechanism, w: int, exclude: set[str]
) -> tuple[tuple[str, ...], RankAnalysis | None]:
    """Up to ``w`` independent drivers, and the generic analysis of the system they drive."""
    chosen: list[str] = []
    accepted = None
    for link in driver_candidates(replaced):
        if len(chosen) == w:
            break
        if link in exclude:
            continue
        trial = [*chosen, link]
        analysis = generic_rank(constraint_system(replaced, trial))
        if not analysis.dependent_drivers:
            chosen, accepted = trial, analysis
    return tuple(chosen), accepted


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
    # the rank analyses (a large mechanism's biggest structures) live only in _plan's
    # frame: they are gone before the groups are built
    mechanism, mob, replaced, rmob, replacements, drivers_used, chosen, plan, singular = _plan(
        mechanism, drivers
    )
    decomposition = build_decomposition(plan)
    return StructuralReport(
        mechanism,
        mob,
        replaced,
        rmob,
        replacements,
        drivers_used,
        chosen,
        decomposition,
        _singular_groups(decomposition, singular),
    )


def _passive_hint(error: DecompositionError, passive: Sequence[PassiveMotion]) -> Exception:
    """The decomposition's error, saying which undetermined links have a passive freedom."""
    turning = sorted({x.link for x in passive if x.source == "geometric"} & set(error.links))
    if not turning:
        return error
    return DecompositionError(
        f"{error}: link(s) {', '.join(turning)} can move alone (a passive freedom the sketch "
        "shows, counted in W_passive); a roller is set aside when it is declared on its "
        "higher pair (roller=LINK)",
        error.links,
    )


def _singular_links(
    plan: GroupPlan, generic: RankAnalysis, geometric: RankAnalysis | None
) -> list[set[str]]:
    """The links of each structural block that is singular at the sketch, when the sketch is.

    Only asked when the geometric analysis had to leave a singular sketch for a
    regular pose near it (``near_sketch``): the usual sketch costs nothing.
    """
    if geometric is None or not geometric.near_sketch:
        return []
    mechanism, drivers = plan.mechanism, plan.drivers
    structural = generic
    if structural.system.mechanism is not mechanism or structural.blocks is None:
        structural = generic_rank(constraint_system(mechanism, drivers))
        if structural.blocks is None:
            return []
    system = structural.system
    try:
        sketch = sketch_realization(system)
    except MissingGeometry:
        return []
    found = []
    for b in singular_blocks(structural, sketch):
        owners = {system.unknowns[u].owner for u in structural.blocks[b]}
        found.append(owners & set(system.links))
    return found


def _singular_groups(decomposition: Decomposition, singular: list[set[str]]) -> tuple[int, ...]:
    """The groups that hold links of a block singular at the sketch."""
    return tuple(
        k
        for k, group in enumerate(decomposition.groups)
        if any(links & set(group.links) for links in singular)
    )


def _plan(
    mechanism: Mechanism, drivers: Sequence[str] | None
) -> tuple[
    Mechanism, Mobility, Mechanism, Mobility, tuple[Replacement, ...], tuple[str, ...], bool,
    GroupPlan, list[set[str]],
]:  # fmt: skip
    """Everything :func:`analyze` finds but the groups themselves, which ``plan`` names,
    and the links of the blocks singular at the sketch."""
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
    picked = None  # the generic analysis of the chosen drivers' system
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
        drivers_used, picked = _pick_drivers(replaced, w, virtual)
        if len(drivers_used) < w:
            raise MobilityError(
                f"W = {w} but only {len(drivers_used)} link(s) joined to the ground can be "
                f"independent drivers ({', '.join(drivers_used) or 'none'})",
                mob,
            )
    rmob = mob
    # the rank analyses are reused by the decomposition: redo them for what it sees
    if replacements:
        rmob, generic, geometric = mobility_analysis(replaced, drivers_used, generic=picked)
    elif chosen:
        generic, geometric = rank_analyses(replaced, drivers_used, generic=picked)
    del picked  # its system is generic's when it was reused
    try:
        plan = plan_groups(replaced, drivers_used, analyses=(generic, geometric))
    except DecompositionError as exc:
        raise _passive_hint(exc, (*mob.passive, *rmob.passive)) from exc
    singular = _singular_links(plan, generic, geometric)
    return (
        mechanism, mob, replaced, rmob, tuple(replacements), tuple(drivers_used), chosen, plan,
        singular,
    )  # fmt: skip


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


def __getattr__(name: str) -> Any:
    """The report's text and JSON forms, still importable from here for one release.

    The import is lazy: :mod:`structure.readwrite.reports` imports this
    module, so importing it at the top would be a cycle.
    """
    if name not in _MOVED_TO_READWRITE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    warnings.warn(
        f"structure.report.{name} is deprecated and will be removed in the next release: "
        f"import it from structure (or structure.readwrite.reports) instead",
        DeprecationWarning,
        stacklevel=2,
    )
    from .readwrite import reports

    return getattr(reports, name)
