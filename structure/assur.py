"""Assur-group decomposition and classification.

The driven constraint system of a lower-pair mechanism (pins as points) is put
in block-triangular form (:mod:`structure.rigidity.matching`). Each link is
known once all its unknowns are; the links that become known in the same
irreducible block form one Assur group (a minimal chain with W = 0 once its
external pairs are attached to known links). The block order is the solve
order, the textbook's order of detaching groups is its reverse. This is exact
and polynomial, O(E·√V)-like in practice, and needs no list of templates:
groups of any class come out.

Class of a group: ``max(2, most internal pairs on one link, largest contour)``,
a contour being a simple cycle of the bipartite graph links ↔ internal joints,
sized by its joints. Order: number of external pairs. A dyad's kind reads its
pairs external–middle–external (RRR, RRP, RPR, PRP, RPP).

References: L. V. Assur (1914); I. I. Artobolevsky, *Theory of Mechanisms and
Machines*; B. Servatius, O. Shai, W. Whiteley, "Combinatorial
characterization of the Assur graphs from engineering", EJC 31 (2010).

>>> from structure import parse_edgelist
>>> m = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"])
>>> d = decompose(m)
>>> [(g.links, g.assur_class, g.order, str(g.kind)) for g in d.groups]
[(('2', '3'), 2, 2, 'RRR')]
>>> d.groups[0].kind is DyadKind.RRR
True
"""

from __future__ import annotations

import heapq
import itertools
from array import array
from collections.abc import Collection, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from operator import attrgetter
from typing import TYPE_CHECKING

import numpy as np

from .errors import DecompositionError, MobilityError
from .kinds import DyadKind, PairKind
from .model import Hinge, Mechanism, Pair
from .rigidity.constraints import (
    ROW_CODE,
    ConstraintSystem,
    MissingGeometry,
    RowKind,
    constraint_system,
    sketch_realization,
)
from .rigidity.matching import NUMPY_ROWS, Assignment, block_arrays, strongly_connected
from .rigidity.rank import DENSE_LIMIT, RankAnalysis, generic_rank
from .rigidity.regularity import regular_rank
from .utils import UnionFind, count_components, slot_setters
from .validation import validated

if TYPE_CHECKING:
    import networkx as nx

__all__ = [
    "AssurGroup",
    "Decomposition",
    "DyadKind",
    "GroupPair",
    "GroupPlan",
    "build_decomposition",
    "classify_group",
    "decompose",
    "driver_candidates",
    "plan_groups",
    "roman",
]


def roman(number: int) -> str:
    """Roman numeral of a class: ``roman(4) == 'IV'``."""
    known = _SMALL_ROMANS.get(number)  # every group's label asks: the usual ones are kept
    return _roman_numeral(number) if known is None else known


def _roman_numeral(number: int) -> str:
    """The numeral, largest values first (subtractive pairs such as IV included)."""
    out = ""
    for value, letters in (
        (1000, "M"), (900, "CM"), (500, "D"), (400, "CD"), (100, "C"), (90, "XC"),
        (50, "L"), (40, "XL"), (10, "X"), (9, "IX"), (5, "V"), (4, "IV"), (1, "I"),
    ):  # fmt: skip
        while number >= value:
            out += letters
            number -= value
    return out


_SMALL_ROMANS = {number: _roman_numeral(number) for number in range(40)}


@dataclass(frozen=True, slots=True)
class GroupPair:
    """A pair of an Assur group: ``links[0]`` is a group link.

    External pairs join a group link to a known link (``links[1]``); internal
    pairs join two group links. A compound hinge is expanded canonically
    (``pair`` is then 0; otherwise it is the id of the mechanism's pair).
    """

    kind: PairKind
    links: tuple[str, str]
    point: str | None
    external: bool
    pair: int = 0  # id of the mechanism's pair (0 for a compound hinge's canonical pair)


# a group build makes one GroupPair per pair of the mechanism: its slots are set directly,
# as a frozen dataclass's __init__ does but without its object.__setattr__ per field
# (unpacking the setters checks at import that they are all the fields)
_set_kind, _set_links, _set_point, _set_external, _set_pair = slot_setters(GroupPair)


def _group_pair(
    kind: PairKind, links: tuple[str, str], point: str | None, external: bool, pair: int = 0
) -> GroupPair:
    """``GroupPair(kind, links, point, external, pair)``, in about half the time."""
    record = object.__new__(GroupPair)
    _set_kind(record, kind)
    _set_links(record, links)
    _set_point(record, point)
    _set_external(record, external)
    _set_pair(record, pair)
    return record


@dataclass(frozen=True, slots=True)
class AssurGroup:
    """One Assur group: links, pairs, class, order and (for dyads) kind.

    ``kind`` is a :class:`~structure.kinds.DyadKind` for a dyad (it compares
    and prints as its letters, ``'RRR'``), None for larger groups.
    """

    links: tuple[str, ...]
    pairs: tuple[GroupPair, ...]
    assur_class: int
    order: int
    kind: DyadKind | None = None

    @property
    def external_pairs(self) -> tuple[GroupPair, ...]:
        return tuple(p for p in self.pairs if p.external)

    @property
    def internal_pairs(self) -> tuple[GroupPair, ...]:
        return tuple(p for p in self.pairs if not p.external)

    @property
    def known_links(self) -> tuple[str, ...]:
        """Links outside the group that its external pairs attach to."""
        return tuple(dict.fromkeys(p.links[1] for p in self.external_pairs))

    @property
    def label(self) -> str:
        """``'II(2,3)'`` style label."""
        return f"{roman(self.assur_class)}({','.join(self.links)})"

    def __repr__(self) -> str:
        kind = f" {self.kind}" if self.kind else ""
        return f"AssurGroup({self.label}, order {self.order}{kind})"


# a large mechanism's build makes tens of thousands of groups: their slots are set directly
_set_group_links, _set_group_pairs, _set_group_class, _set_group_order, _set_group_kind = (
    slot_setters(AssurGroup)
)


@dataclass(frozen=True)
class Decomposition:
    """Groups in solve order, their dependency DAG, and what was set aside.

    ``dag_edges`` are the edges ``(i, j)`` of the dependency DAG between
    group indices, sorted: group ``j`` is attached to a link of group ``i``;
    ``dag`` is that DAG as a frozen networkx ``DiGraph``, built when asked
    for (so that classifying does not import networkx). ``removed_links`` and
    ``removed_pairs`` are the redundant links/pairs left out of the
    decomposition (``mechanism`` is what remains).
    """

    mechanism: Mechanism
    drivers: tuple[str, ...]
    groups: tuple[AssurGroup, ...]
    dag_edges: tuple[tuple[int, int], ...] = field(repr=False)
    removed_links: tuple[str, ...] = ()
    removed_pairs: tuple[int, ...] = ()

    @cached_property
    def dag(self) -> nx.DiGraph:
        """The dependency DAG: one node per group index, the edges ``dag_edges``."""
        import networkx as nx

        dag = nx.DiGraph()
        dag.add_nodes_from(range(len(self.groups)))
        dag.add_edges_from(self.dag_edges)
        return nx.freeze(dag)

    @property
    def mechanism_class(self) -> int:
        return max((g.assur_class for g in self.groups), default=1)

    @property
    def formula(self) -> str:
        """``'I(1) → II(2,3) → III(4,5,6,7)'``."""
        parts = [f"I({d})" for d in self.drivers] + [g.label for g in self.groups]
        return " → ".join(parts)

    @property
    def textbook_formula(self) -> str:
        """``'1 = 1 + 0 + 0'``: W equals one per driver plus zero per group."""
        terms = ["1"] * len(self.drivers) + ["0"] * len(self.groups)
        return f"{len(self.drivers)} = " + " + ".join(terms)


def driver_candidates(mechanism: Mechanism) -> tuple[str, ...]:
    """Links joined to the ground by an R or P pair (or a pin shared with it), in order."""
    out: dict[str, None] = {}
    ground = mechanism.ground
    hinged = {x for h in mechanism.compound_hinges.values() if ground in h.links for x in h.links}
    for p in mechanism.pairs:
        for link in p.links:
            if link != ground and (
                (p.kind is not PairKind.H and p.other(link) == ground) or link in hinged
            ):
                out.setdefault(link)
    return tuple(out)


def _geometric_analysis(mechanism: Mechanism, drivers: Sequence[str]) -> RankAnalysis | None:
    """The sketch's rank when coordinates are complete (and the system small enough).

    At a singular sketch (a dead point), the rank of a regular pose near it.
    """
    if not mechanism.points:
        return None
    system = constraint_system(mechanism, drivers)
    if system.n_scalar_unknowns > DENSE_LIMIT:
        return None
    try:
        return regular_rank(system, sketch_realization(system))[0]
    except MissingGeometry:
        return None


def _analysis(mechanism: Mechanism, drivers: Sequence[str]) -> RankAnalysis:
    """Generic rank, replaced by the sketch's rank when coordinates are complete."""
    geometric = _geometric_analysis(mechanism, drivers)
    return geometric or generic_rank(constraint_system(mechanism, drivers))


def _without_link(mechanism: Mechanism, link: str) -> Mechanism | None:
    pairs = tuple(p for p in mechanism.pairs if link not in p.links)
    try:
        return validated(mechanism.evolve(pairs=pairs))
    except Exception:
        return None


def _set_aside_redundancy(
    mechanism: Mechanism, drivers: Sequence[str], analysis: RankAnalysis
) -> tuple[Mechanism, list[str], list[int]]:
    """Remove redundant links (textbook: 'ràng buộc trùng') until the drivers determine all."""
    removed_links: list[str] = []
    removed_pairs: list[int] = []
    current = mechanism
    for _ in range(len(mechanism.pairs)):
        if not analysis.dependent_pairs and not analysis.free:
            break
        worst = max(analysis.dependent_pairs) if analysis.dependent_pairs else None
        if worst is None:
            break
        pair = current.pair(worst)
        best = None
        for link in (pair.b, pair.a):
            if link == current.ground or link in drivers:
                continue
            trial = _without_link(current, link)
            if trial is None:
                continue
            trial_analysis = _analysis(trial, drivers)
            if sum(trial_analysis.dependent.values()) < sum(analysis.dependent.values()) and (
                not trial_analysis.free
            ):
                best = (link, trial, trial_analysis)
                break
        if best is None:
            trial = validated(
                current.evolve(pairs=tuple(p for p in current.pairs if p.id != worst))
            )
            removed_pairs.append(worst)
            current, analysis = trial, _analysis(trial, drivers)
            continue
        link, current, analysis = best
        removed_links.append(link)
        removed_pairs.extend(
            p.id for p in mechanism.pairs if link in p.links and p.id not in removed_pairs
        )
    return current, removed_links, removed_pairs


def decompose(
    mechanism: Mechanism,
    drivers: Sequence[str] | None = None,
    *,
    analyses: tuple[RankAnalysis, RankAnalysis | None] | None = None,
) -> Decomposition:
    """Split a lower-pair mechanism into Assur groups in solve order.

    ``drivers`` defaults to the mechanism's own. Redundant constraints are set
    aside first (the redundant link is removed, as the textbook does).
    ``analyses`` are the generic and geometric rank analyses of the same
    mechanism driven by the same drivers, when already computed
    (:func:`~structure.mobility.mobility_analysis`).

    The same as :func:`build_decomposition` of :func:`plan_groups`: a caller
    holding large analyses can let them go between the two.

    Raises
    ------
    DecompositionError
        Higher pairs present (replace them first), or links the drivers do not
        determine.
    MobilityError
        A driver whose motion the other pairs already fix.
    """
    return build_decomposition(plan_groups(mechanism, drivers, analyses=analyses))


@dataclass(frozen=True, slots=True)
class GroupPlan:
    """Which links form each Assur group, before the groups are built.

    ``members`` holds each group's links (keyed by its merged block),
    ``order`` the blocks in solve order, ``edges`` the dependencies between
    blocks; ``mechanism`` is what remains once the redundant links and pairs
    (``removed_links``, ``removed_pairs``) are set aside. Small: the rank
    analyses it comes from are no longer needed.
    """

    mechanism: Mechanism
    drivers: tuple[str, ...]
    members: Mapping[int, list[str]]
    order: Sequence[int]
    edges: Collection[tuple[int, int]]
    removed_links: tuple[str, ...]
    removed_pairs: tuple[int, ...]


def plan_groups(
    mechanism: Mechanism,
    drivers: Sequence[str] | None = None,
    *,
    analyses: tuple[RankAnalysis, RankAnalysis | None] | None = None,
) -> GroupPlan:
    """The first half of :func:`decompose`: which links form each group, in which order.

    Raises as :func:`decompose` does.
    """
    drivers = tuple(mechanism.driver_links if drivers is None else drivers)
    if PairKind.H in map(attrgetter("kind"), mechanism.pairs):
        raise DecompositionError("replace the higher pairs before decomposing")
    if analyses is None:
        generic = generic_rank(constraint_system(mechanism, drivers))
        geometric = _geometric_analysis(mechanism, drivers)
    else:
        generic, geometric = analyses
    analysis = geometric if geometric is not None else generic
    if analysis.dependent_drivers:
        raise MobilityError(
            "the motion of driver(s) "
            + ", ".join(analysis.dependent_drivers)
            + " is already fixed by the other pairs and drivers"
        )
    current, removed_links, removed_pairs = mechanism, [], []
    structural = generic
    if analysis.dependent_pairs or generic.blocks is None:
        if analysis.dependent_pairs:
            current, removed_links, removed_pairs = _set_aside_redundancy(
                mechanism, drivers, analysis
            )
        structural = generic_rank(constraint_system(current, drivers))
    if structural.blocks is None:
        system = structural.system
        loose = sorted(
            {system.unknowns[u].owner for u, _ in structural.free if u >= 0},
            key=current.links.index,
        )
        raise DecompositionError(
            "the drivers do not determine link(s) " + ", ".join(loose or ["?"]), loose
        )
    return _plan_from_blocks(current, drivers, structural, removed_links, removed_pairs)


def build_decomposition(plan: GroupPlan) -> Decomposition:
    """The second half of :func:`decompose`: the groups of ``plan`` and their DAG."""
    return _decomposition(
        plan.mechanism,
        plan.drivers,
        plan.members,
        plan.order,
        plan.edges,
        plan.removed_links,
        plan.removed_pairs,
    )


def _plan_from_blocks(
    mechanism: Mechanism,
    drivers: tuple[str, ...],
    analysis: RankAnalysis,
    removed_links: Sequence[str],
    removed_pairs: Sequence[int],
) -> GroupPlan:
    """Assur groups from the irreducible blocks of the driven system.

    A link belongs to the block that completes it. Blocks can be finer than
    whole pairs allow (in an RPP dyad the guides fix the middle link's angle
    first), so blocks whose unknowns are fixed by rows of one pair, or whose
    rows fix one pin, are merged, and so are blocks that end up depending on
    each other. The group order is a topological order of the dependencies
    that the rows' other unknowns give.

    A large mechanism's rows and matching are read as numpy arrays
    (:func:`_merged_blocks_by_numpy`), a small one's row by row
    (:func:`_merged_blocks_by_rows`, cheaper below a few thousand rows); both
    give the same blocks, named the same.
    """
    assert analysis.blocks is not None
    if analysis.system.n_pair_rows >= NUMPY_ROWS:
        nodes, edges, link_root, ascending = _merged_blocks_by_numpy(drivers, analysis)
    else:
        nodes, edges, link_root = _merged_blocks_by_rows(drivers, analysis)
        ascending = False
    members: dict[int, list[str]] = {}
    first_position: dict[int, int] = {}  # of each block's first link, the order's key
    # the ground is first in mechanism.links; the moving links follow in their order
    for i, (link, b) in enumerate(zip(analysis.system.links, link_root, strict=True), start=1):
        if b >= 0:
            found = members.get(b)
            if found is None:
                members[b] = [link]
                first_position[b] = i
            else:
                found.append(link)
    order = _topological_order(nodes, edges, first_position, ascending=ascending)
    return GroupPlan(
        mechanism, drivers, members, order, edges, tuple(removed_links), tuple(removed_pairs)
    )


#: the merged blocks (each named by a member), the DAG's edges (sorted), each moving link's
#: merged block
_MergedBlocks = tuple[list[int], list[tuple[int, int]], list[int]]


def _merged_blocks_by_numpy(
    drivers: Sequence[str], analysis: RankAnalysis
) -> tuple[list[int], Dependencies, list[int], bool]:
    """The merged blocks of :func:`_plan_from_blocks`, found with numpy.

    The fourth value tells whether every dependency goes from a block whose
    first link comes earlier to one whose first link comes later.
    """
    system, blocks = analysis.system, analysis.blocks
    assert blocks is not None
    rows = _PairRows.of(system, analysis.assigned)
    start = _completing_blocks(system, drivers, blocks)
    merged = UnionFind()  # only blocks that merge enter it: the others are their own roots
    owner = _block_owners(system, rows, start, merged)
    _merge_split_pairs(system, rows, owner, merged)
    nodes, edges, root, ascending = _merge_cycles(rows, owner, merged, start)
    return nodes, edges, np.where(start >= 0, root[np.maximum(start, 0)], -1).tolist(), ascending


def _merged_blocks_by_rows(drivers: Sequence[str], analysis: RankAnalysis) -> _MergedBlocks:
    """The merged blocks of :func:`_plan_from_blocks`, row by row (a small mechanism's).

    The same steps as :func:`_merged_blocks_by_numpy`, in the same order.
    """
    system, blocks = analysis.system, analysis.blocks
    assert blocks is not None
    n_links, n_rows = len(system.links), system.n_pair_rows
    slots = analysis.assigned.units[: 2 * n_rows]
    units = list(zip(slots[0::2], slots[1::2], strict=True))
    block_of = [0] * system.n_unknowns
    for b, members in enumerate(blocks):
        for u in members:
            block_of[u] = b
    driver_set = set(drivers)
    start = [
        -1 if link in driver_set else max(block_of[2 * i], block_of[2 * i + 1])
        for i, link in enumerate(system.links)
    ]
    merged = UnionFind(b for b in start if b >= 0)
    owner = [start[u >> 1] for u in range(2 * n_links)] + [-1] * len(system.pins)
    kinds, pairs = system.row_kind, system.row_pair
    for r in range(n_rows):  # a pin follows the link whose row fixes it
        if kinds[r] is _PIN:
            b = start[system.links.index(system.row_link[r])]
            for u in units[r]:
                if u >= 2 * n_links and b >= 0:
                    if owner[u] < 0:
                        owner[u] = b
                    else:
                        merged.union(owner[u], b)
    first: dict[int, int] = {}
    several: dict[int, set[int]] = {}
    for r in range(n_rows):  # a pair is never split
        if kinds[r] is not _PIN:
            for u in units[r]:
                if u >= 0 and owner[u] >= 0:
                    known = first.setdefault(pairs[r], owner[u])
                    if known != owner[u]:
                        several.setdefault(pairs[r], {known}).add(owner[u])
    for found in several.values():
        merged.union(*found)
    adj, adj_start = system.adj, system.adj_start
    while True:  # blocks that depend on each other merge
        root = {b: merged[b] for b in merged}
        merged_owner = [root[b] if b >= 0 else -1 for b in owner]
        edges: set[tuple[int, int]] = set()
        for r in range(n_rows):
            target = merged_owner[units[r][0]] if units[r][0] >= 0 else -1
            if target >= 0:
                for w in adj[adj_start[r] : adj_start[r + 1]]:
                    source = merged_owner[w]
                    if source >= 0 and source != target:
                        edges.add((source, target))
        nodes = sorted(set(root.values()))
        number = {b: i for i, b in enumerate(nodes)}
        components = strongly_connected(
            [number[u] for u, _ in edges], [number[v] for _, v in edges], len(nodes)
        )
        cycles = [c for c in components if len(c) > 1]
        if not cycles:
            return nodes, sorted(edges), [root[b] if b >= 0 else -1 for b in start]
        for c in cycles:
            merged.union(*(nodes[i] for i in c))


@dataclass(frozen=True, slots=True)
class _PairRows:
    """The pair rows of a matched system as numpy arrays (drivers and probes left out).

    ``units[r]`` holds the two unknown slots of row ``r`` (-1 for none, as in
    :class:`~structure.rigidity.matching.Assignment`); ``pin`` marks the rows
    of a link at a compound pin; ``adj_start``/``adj`` are the system's
    adjacency.
    """

    units: np.ndarray
    pin: np.ndarray
    pair: np.ndarray
    adj_start: np.ndarray
    adj: np.ndarray

    @classmethod
    def of(cls, system: ConstraintSystem, assigned: Sequence[Sequence[int]]) -> _PairRows:
        n = system.n_pair_rows
        if isinstance(assigned, Assignment):
            units = np.frombuffer(assigned.units, dtype=np.int32)[: 2 * n].reshape(n, 2)
        else:
            units = np.full((n, 2), -1, dtype=np.int32)
            for r, got in enumerate(assigned[:n]):
                units[r, : len(got)] = got
        pin = system.row_codes()[:n] == ROW_CODE[_PIN]
        return cls(
            units.astype(np.int32),
            pin,
            np.frombuffer(system.row_pair, dtype=np.int32)[:n].astype(np.int64),
            np.frombuffer(system.adj_start, dtype=np.int64)[: n + 1],
            np.frombuffer(system.adj, dtype=np.int32),
        )


def _completing_blocks(
    system: ConstraintSystem, drivers: Sequence[str], blocks: Sequence[Sequence[int]]
) -> np.ndarray:
    """The block that completes each moving link (its later unknown's), -1 for a driver."""
    units, block_start = block_arrays(blocks)
    block_of = np.empty(system.n_unknowns, dtype=np.int64)
    block_of[units] = np.repeat(np.arange(len(blocks)), np.diff(block_start))
    n = len(system.links)
    start = np.maximum(block_of[0 : 2 * n : 2], block_of[1 : 2 * n : 2])
    driver_set = set(drivers)
    start[[i for i, link in enumerate(system.links) if link in driver_set]] = -1
    return start


def _block_owners(
    system: ConstraintSystem, rows: _PairRows, start: np.ndarray, merged: UnionFind
) -> np.ndarray:
    """The block each unknown belongs to (-1 for the knowns).

    A pin follows the link whose row fixes it; links whose pin rows fix one
    pin are merged into one block.
    """
    n = len(system.links)
    owner = np.full(system.n_unknowns, -1, dtype=np.int64)
    owner[: 2 * n] = np.repeat(start, 2)
    pin_rows = np.flatnonzero(rows.pin)
    if not len(pin_rows):
        return owner
    # a pin row's last unknown is its link's position, twice the link's number
    link_at = rows.adj[rows.adj_start[pin_rows + 1] - 1] // 2
    block = np.repeat(start[link_at], 2)
    units = rows.units[pin_rows].reshape(-1)  # each pin row's units, in row order
    claims = np.flatnonzero((units >= 2 * n) & (block >= 0))  # a pin's unknown, by a block
    if not len(claims):
        return owner
    pin, block = units[claims], block[claims]
    # the first row to claim a pin gives it its block; each later claim merges with that block
    by_pin = np.argsort(pin, kind="stable")
    first = np.r_[True, pin[by_pin][1:] != pin[by_pin][:-1]]
    owner[pin[by_pin][first]] = block[by_pin][first]
    later = np.sort(by_pin[~first])
    for known, b in zip(owner[pin[later]].tolist(), block[later].tolist(), strict=True):
        merged.union(known, b)
    return owner


def _merge_split_pairs(
    system: ConstraintSystem, rows: _PairRows, owner: np.ndarray, merged: UnionFind
) -> None:
    """Merge the blocks whose unknowns rows of one pair fix: a pair is never split.

    Most pairs lie in one block: the few whose matched units lie in several
    are found with numpy, then merged in the order the rows name them.
    """
    slots = np.flatnonzero(~rows.pin[:, None].repeat(2, axis=1).reshape(-1))
    units = rows.units.reshape(-1)[slots]
    slots, units = slots[units >= 0], units[units >= 0]
    blocks = owner[units]
    slots, blocks = slots[blocks >= 0], blocks[blocks >= 0]
    pids = rows.pair[slots // 2]
    if not len(pids):
        return
    by_pair = np.argsort(pids, kind="stable")
    first_block = np.empty_like(blocks)
    head = np.r_[True, pids[by_pair][1:] != pids[by_pair][:-1]]
    first_block[by_pair] = blocks[by_pair][
        np.maximum.accumulate(np.where(head, np.arange(len(pids)), 0))
    ]
    split = np.zeros(int(pids.max()) + 1, dtype=bool)
    split[pids[blocks != first_block]] = True
    keep = split[pids]
    if not keep.any():
        return
    # the split pairs' blocks as sets, filled in the order of the rows, pairs by first row
    several: dict[int, set[int]] = {}
    for pid, b in zip(pids[keep].tolist(), blocks[keep].tolist(), strict=True):
        several.setdefault(pid, set()).add(b)
    for found in several.values():
        merged.union(*found)


def _merge_cycles(
    rows: _PairRows, owner: np.ndarray, merged: UnionFind, start: np.ndarray
) -> tuple[list[int], Dependencies, np.ndarray, bool]:
    """Merge blocks that depend on each other until their dependencies form a DAG.

    Returns the merged blocks (each named by a member), the DAG's edges, the
    merged block of every block (-1 for none), and whether every edge goes
    from a block whose first link (``start`` holds each link's block) comes
    earlier to one whose first link comes later: then there is no cycle to
    look for, and the order by first link is the solve order.
    """
    n_blocks = int(start.max(initial=-1)) + 1
    linked = np.flatnonzero(start >= 0)
    while True:
        root = np.full(n_blocks, -1, dtype=np.int32)
        root[start[linked]] = start[linked]
        members = list(merged)
        root[members] = [merged[b] for b in members]
        merged_owner = np.where(owner >= 0, root[np.maximum(owner, 0)], -1).astype(np.int32)
        sources, targets = _distinct_edges(*_block_dependencies(rows, merged_owner))
        nodes = np.sort(root[root >= 0])
        nodes = nodes[np.r_[True, nodes[1:] != nodes[:-1]][: len(nodes)]]
        first_link = np.full(n_blocks, len(start), dtype=np.int64)
        np.minimum.at(first_link, root[start[linked]], linked)
        edges = Dependencies.of_arrays(sources, targets)
        if bool((first_link[sources] < first_link[targets]).all()):
            return nodes.tolist(), edges, root, True
        # strongly connected components of the group graph (nodes numbered in order): cycles merge
        components = strongly_connected(
            np.searchsorted(nodes, sources), np.searchsorted(nodes, targets), len(nodes)
        )
        cycles = [c for c in components if len(c) > 1]
        del components
        if not cycles:
            return nodes.tolist(), edges, root, False
        for c in cycles:
            merged.union(*(int(nodes[i]) for i in c))


class Dependencies(Collection):
    """Dependencies ``(source, target)`` between merged blocks, distinct and sorted, held flat.

    Two arrays of 4-byte numbers: a large mechanism has about a hundred
    thousand of them, and a set of tuples costs ten times the memory.
    """

    __slots__ = ("sources", "targets")

    def __init__(self, sources: array, targets: array):
        self.sources, self.targets = sources, targets

    @classmethod
    def of_arrays(cls, sources: np.ndarray, targets: np.ndarray) -> Dependencies:
        """The edges ``(sources[k], targets[k])``, as they are (distinct and sorted)."""
        return cls(
            array("i", sources.astype(np.intc).tobytes()),
            array("i", targets.astype(np.intc).tobytes()),
        )

    def __iter__(self) -> Iterator[tuple[int, int]]:
        return zip(self.sources, self.targets, strict=True)

    def __len__(self) -> int:
        return len(self.sources)

    def __contains__(self, edge: object) -> bool:
        return edge in set(self)


def _distinct_edges(sources: np.ndarray, targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The edges ``(sources[k], targets[k])`` without repeats, sorted by source then target."""
    width = int(targets.max(initial=0)) + 1
    key = np.unique(sources.astype(np.int64) * width + targets)
    return key // width, key % width


def _block_dependencies(rows: _PairRows, merged_owner: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(sources, targets)``: each merged block a row of another block also touches.

    ``merged_owner`` is the merged block of each unknown (-1 for the knowns).
    The edges come in the order of the rows and of their unknowns (repeats
    included), so a set made of them is the one a loop over the rows makes.
    """
    first = rows.units[:, 0]
    target = np.where(first >= 0, merged_owner[np.maximum(first, 0)], -1).astype(np.int32)
    target = np.repeat(target, np.diff(rows.adj_start))
    source = merged_owner[rows.adj[rows.adj_start[0] : rows.adj_start[-1]]]
    keep = (target >= 0) & (source >= 0) & (source != target)
    return source[keep], target[keep]


def _decomposition(
    mechanism: Mechanism,
    drivers: Sequence[str],
    members: Mapping[int, list[str]],
    order: Sequence[int],
    edges: Collection[tuple[int, int]],
    removed_links: tuple[str, ...],
    removed_pairs: tuple[int, ...],
) -> Decomposition:
    """The groups of the merged blocks, in ``order``, and their dependency DAG."""
    links = [members[b] for b in order]
    compound = dict(mechanism.compound_hinges)  # a plain dict for the per-pair lookups
    dag = _dag_edges(order, edges)
    found = None
    if len(mechanism.pairs) >= NUMPY_ROWS:
        found = _all_group_pairs(mechanism, drivers, links, compound)
    if found is None:
        level = {mechanism.ground: -1, **dict.fromkeys(drivers, -1)}  # each link's group
        places = map(itertools.repeat, range(len(links)), map(len, links))  # i, len(links[i]) times
        level.update(zip(_flat(links), _flat(places), strict=True))
        found = (_group_pairs(mechanism, x, level, i, compound) for i, x in enumerate(links))
    groups = tuple(map(_build_group, links, found))
    return Decomposition(mechanism, tuple(drivers), groups, dag, removed_links, removed_pairs)


def _dag_edges(
    order: Sequence[int], edges: Collection[tuple[int, int]]
) -> tuple[tuple[int, int], ...]:
    """The ``edges`` between merged blocks as edges between their places in ``order``, sorted.

    A large mechanism's (a :class:`Dependencies`) renumbered and sorted by numpy.
    """
    if isinstance(edges, Dependencies) and len(edges) >= NUMPY_ROWS:
        place = np.zeros(max(order) + 1, dtype=np.int64)
        place[order] = np.arange(len(order))
        sources = place[np.frombuffer(edges.sources, dtype=np.intc)]
        targets = place[np.frombuffer(edges.targets, dtype=np.intc)]
        by_place = np.lexsort((targets, sources))
        return tuple(zip(sources[by_place].tolist(), targets[by_place].tolist(), strict=True))
    index = {b: i for i, b in enumerate(order)}
    return tuple(sorted((index[u], index[v]) for u, v in edges))


def _topological_order(
    nodes: Sequence[int],
    edges: Collection[tuple[int, int]],
    key: dict[int, int],
    *,
    ascending: bool = False,
) -> list[int]:
    """Kahn's algorithm, always taking the ready node of smallest ``key`` (keys are distinct).

    When every edge goes from a smaller key to a larger one (``ascending``
    says it is known), that order is the nodes sorted by key (the smallest
    key left never waits for a predecessor), found without the heap.
    """
    if ascending or all(key[u] < key[v] for u, v in edges):
        return sorted(nodes, key=key.__getitem__)
    indegree = dict.fromkeys(nodes, 0)
    out: dict[int, list[int]] = {}
    for u, v in edges:
        indegree[v] += 1
        out.setdefault(u, []).append(v)
    ready = [(key[b], b) for b in nodes if indegree[b] == 0]
    heapq.heapify(ready)
    order: list[int] = []
    while ready:
        _, b = heapq.heappop(ready)
        order.append(b)
        for v in out.get(b, ()):
            indegree[v] -= 1
            if indegree[v] == 0:
                heapq.heappush(ready, (key[v], v))
    return order


_R = PairKind.R  # enum member lookups are slow in hot loops
_flat = itertools.chain.from_iterable
_PIN = RowKind.PIN


_GroupPairs = tuple[list[GroupPair], list[tuple[str, ...]], int]


def _build_group(links: list[str], found: _GroupPairs) -> AssurGroup:
    """The group of ``links`` from its pairs, internal joints and number of external pairs."""
    pairs, joints, n_external = found
    if 3 * len(links) != 2 * len(pairs):
        raise DecompositionError(
            f"group {','.join(links)} has {len(pairs)} pairs for {len(links)} links "
            "(3·links = 2·pairs fails)",
            links,
        )
    group = object.__new__(AssurGroup)  # AssurGroup(...), its slots set directly (_group_pair)
    _set_group_links(group, tuple(links))
    _set_group_pairs(group, tuple(pairs))
    _set_group_class(group, classify_group(links, joints))
    _set_group_order(group, n_external)
    _set_group_kind(group, _dyad_kind(links, pairs) if len(links) == 2 else None)
    return group


def _dyad_kind(links: list[str], pairs: list[GroupPair]) -> DyadKind | None:
    """A dyad's letters read external–middle–external, as its kind (None if no kind fits).

    Each link's letter is its first external pair's, the middle letter the
    last internal pair's ('?' and '' where there is none).
    """
    first = links[0]
    left = right = None
    middle = ""
    for p in pairs:
        if not p.external:
            middle = p.kind
        elif p.links[0] == first:
            left = left or p.kind
        else:
            right = right or p.kind
    return DyadKind.from_letters((left or "?") + middle + (right or "?"))


def _group_pairs(
    mechanism: Mechanism,
    links: list[str],
    done: dict[str, int],
    level: int,
    compound: Mapping[str, Hinge] | None = None,
) -> _GroupPairs:
    """Pairs of a group known at ``level``, its internal joints and its number of external pairs.

    ``done`` is the level of every link (the group's own are at ``level``).
    The group's links are read in order, each link's pairs in file order: a
    pair to a link known before ``level`` is external, a pair to another group
    link internal (taken from the first of the two read), the pairs at a
    compound hinge are taken once, from the first group link at it
    (:func:`_hinge_pairs`).
    """
    if compound is None:
        compound = mechanism.compound_hinges
    ends = _group_ends(mechanism, links, done, level, compound)
    return _pairs_of_ends(ends, done, level, mechanism.ground, compound)


#: a pair end of a group link that gives a group pair: the link, the link at the pair's other
#: end, the pair, whether it is at a compound hinge, whether it is external
_End = tuple[str, str, Pair, bool, bool]


def _group_ends(
    mechanism: Mechanism,
    links: list[str],
    done: Mapping[str, int],
    level: int,
    compound: Mapping[str, Hinge],
) -> Iterator[_End]:
    """The pair ends of the group of ``links`` that give its pairs, in reading order."""
    read: set[str] = set()  # the group links whose pairs are taken
    for link in links:
        for p in mechanism.pairs_of(link):
            a = p.a
            other = p.b if link == a else a
            if compound and p.point in compound and p.kind is _R:  # (None is in no dict)
                yield link, other, p, True, False
                continue
            known = done[other]
            if known < level:
                yield link, other, p, False, True
            elif known == level and other not in read:
                yield link, other, p, False, False
        read.add(link)


def _pairs_of_ends(
    ends: Iterable[_End],
    done: Mapping[str, int],
    level: int,
    ground: str,
    compound: Mapping[str, Hinge],
) -> _GroupPairs:
    """The pairs, internal joints and number of external pairs of a group from its ends."""
    pairs: list[GroupPair] = []
    joints: list[tuple[str, ...]] = []  # internal joints as the group links they join
    n_external = 0
    seen_hinges: set[str] = set()
    for link, other, p, at_hinge, external in ends:
        if at_hinge:
            if p.point not in seen_hinges:
                seen_hinges.add(p.point)
                n_external += _hinge_pairs(compound[p.point], done, level, ground, pairs, joints)
        elif external:
            pairs.append(_group_pair(p.kind, (link, other), p.point, True, p.id))
            n_external += 1
        else:
            joint = (link, other)
            pairs.append(_group_pair(p.kind, joint, p.point, False, p.id))
            joints.append(joint)
    return pairs, joints, n_external


def _all_group_pairs(
    mechanism: Mechanism,
    drivers: Sequence[str],
    groups: list[list[str]],
    compound: dict[str, Hinge],
) -> Iterator[_GroupPairs] | None:
    """:func:`_group_pairs` of every group (a large mechanism's), a few thousand groups at a time.

    ``groups`` are the groups' links in solve order; the ground and the
    ``drivers`` are known before them (level -1). Whether a pair end gives
    a group pair does not depend on the pairs read before it: the end of
    group link ``x`` at a pair to link ``y`` gives an external pair when
    ``y`` is known before ``x``'s group, an internal one when ``y`` is in the
    group after ``x``, and the ends at compound hinges go to
    :func:`_hinge_pairs`; numpy picks those ends out, in the order
    :func:`_group_ends` gives them, and only they are read in Python. Each
    group's comes as it is made: the groups are built one by one from them.
    The levels stay an array (no dict of every link). None when some link
    is in no group and is neither the ground nor a driver.
    """
    sizes = np.fromiter(map(len, groups), np.int64, len(groups))
    seq = mechanism.link_numbers(_flat(groups))
    group_of = np.repeat(np.arange(len(groups), dtype=np.intc), sizes)
    link_level = np.full(len(mechanism.links), -2, dtype=np.intc)
    before = [x for x in (mechanism.ground, *drivers) if mechanism.has_link(x)]
    link_level[mechanism.link_numbers(before)] = -1
    link_level[seq] = group_of
    if (link_level == -2).any():
        return None
    return _group_pairs_by_chunk(mechanism, compound, sizes, seq, group_of, link_level)


def _group_pairs_by_chunk(
    mechanism: Mechanism,
    compound: dict[str, Hinge],
    sizes: np.ndarray,
    seq: np.ndarray,
    group_of: np.ndarray,
    link_level: np.ndarray,
) -> Iterator[_GroupPairs]:
    """The body of :func:`_all_group_pairs`: its groups' pairs, :data:`_GROUP_CHUNK` at a time.

    ``seq`` are the groups' link numbers one group after another (``sizes``
    each), ``group_of`` the group of each, ``link_level`` every link's level.
    """
    starts = np.cumsum(sizes) - sizes
    place = (np.arange(len(seq)) - np.repeat(starts, sizes)).astype(np.intc)  # in its group
    link_place = np.zeros(len(mechanism.links), dtype=np.intc)
    link_place[seq] = place
    offsets, slot_pairs, others = mechanism.incidence()
    at_hinge = mechanism.at_compound_hinge()
    level = _LinkLevels(mechanism, link_level.tolist())
    pairs, names, ground = mechanism.pairs, mechanism.links, mechanism.ground
    n_groups = len(sizes)
    for first in range(0, n_groups, _GROUP_CHUNK):  # bounded temporaries (issue 11)
        last = min(first + _GROUP_CHUNK, n_groups)
        entries = slice(starts[first], starts[last - 1] + sizes[last - 1])
        links, own, at = seq[entries], group_of[entries], place[entries]
        # every pair end of these groups' links, in reading order
        counts = offsets[links + 1] - offsets[links]
        reading = np.repeat(np.arange(len(links)), counts)
        slot = np.repeat(offsets[links] - (np.cumsum(counts) - counts), counts)
        slot += np.arange(len(slot), dtype=slot.dtype)
        other, pair, own = others[slot], slot_pairs[slot], own[reading]
        hinge, known = at_hinge[pair], link_level[other]
        external = known < own
        keep = hinge | external | ((known == own) & (link_place[other] > at[reading]))
        ends = zip(
            map(names.__getitem__, links[reading[keep]].tolist()),
            map(names.__getitem__, other[keep].tolist()),
            map(pairs.__getitem__, pair[keep].tolist()),
            hinge[keep].tolist(),
            external[keep].tolist(),
            strict=True,
        )
        counts = np.bincount(own[keep] - first, minlength=last - first).tolist()
        del reading, slot, other, pair, hinge, known, external, keep
        for i, count in enumerate(counts, start=first):
            yield _pairs_of_ends(itertools.islice(ends, count), level, i, ground, compound)


class _LinkLevels(Mapping[str, int]):
    """Each link's level (its group's place; -1 the ground and drivers) read from a list.

    What :func:`_hinge_pairs` reads as ``done`` for a large mechanism: the
    few links at compound hinges are looked up, not a dict made of them all.
    """

    __slots__ = ("_levels", "_links", "_number")

    def __init__(self, mechanism: Mechanism, levels: list[int]) -> None:
        self._number = mechanism.link_number
        self._levels = levels
        self._links = mechanism.links

    def __getitem__(self, link: str) -> int:
        return self._levels[self._number(link)]

    def __iter__(self) -> Iterator[str]:
        return iter(self._links)

    def __len__(self) -> int:
        return len(self._links)


#: groups whose pair ends :func:`_all_group_pairs` sorts out at a time
_GROUP_CHUNK = 4096


def _hinge_pairs(
    hinge: Hinge,
    done: Mapping[str, int],
    level: int,
    ground: str,
    pairs: list[GroupPair],
    joints: list[tuple[str, ...]],
) -> int:
    """Append a compound hinge's canonical pairs in a group; return its external ones (0 or 1).

    The group links at it are joined to the first of them; the pin is fixed by
    the earliest known link at it (the ground first).
    """
    inside: list[str] = []  # the group's links at the hinge
    known: list[str] = []  # the links known before the group
    for x in hinge.links:
        at = done[x]
        if at == level:
            inside.append(x)
        elif at < level:
            known.append(x)
    for x in inside[1:]:
        pairs.append(_group_pair(_R, (inside[0], x), hinge.point, False))
    if len(inside) > 1:
        joints.append(tuple(inside))
    if not known:
        return 0
    anchor = known[0] if len(known) == 1 else min(known, key=lambda x: (done[x], x != ground))
    pairs.append(_group_pair(_R, (inside[0], anchor), hinge.point, True))
    return 1


def classify_group(links: Sequence[str], joints: Sequence[tuple[str, ...]]) -> int:
    """Class of a group from its internal joints (each: the group links it joins).

    ``max(2, most joints on one link, largest contour)``. A group with at most
    one joint is class 2, a forest has no contour and a plain ring's contour
    is all its joints: only the other shapes need the contour search.

    >>> classify_group(["2", "3"], [("2", "3")])
    2
    >>> classify_group(["B", "a", "b", "c"], [("B", "a"), ("B", "b"), ("B", "c")])  # triad
    3
    >>> classify_group(list("1234"), [("1", "2"), ("2", "3"), ("3", "4"), ("4", "1")])
    4
    """
    if not joints or (len(joints) == 1 and len(joints[0]) == 2 and joints[0][0] != joints[0][1]):
        return 2  # a dyad's one joint: no link on two joints, no contour
    degree = dict.fromkeys(links, 0)
    n_edges = 0
    for j in joints:
        n_edges += len(j)
        for x in j:
            degree[x] += 1
    most = max(degree.values())
    components = count_components(links, joints)
    if n_edges == len(links) + len(joints) - components:  # a forest: no contour
        return max(2, most)
    if (
        components == 1
        and all(d == 2 for d in degree.values())
        and all(len(j) == 2 and j[0] != j[1] for j in joints)
    ):
        return max(2, len(joints))  # a ring: the one contour runs through every joint
    return max(2, most, _longest_contour(links, joints))


def _longest_contour(links: Sequence[str], joints: Sequence[tuple[str, ...]]) -> int:
    """Most joints on a simple cycle of the bipartite graph links ↔ joints (backtracking)."""
    joints_of: dict[str, list[int]] = {x: [] for x in links}
    for k, j in enumerate(joints):
        for x in j:
            joints_of[x].append(k)
    rank = {x: i for i, x in enumerate(links)}
    best = 0

    def extend(start: str, link: str, used_links: set[str], used_joints: set[int]) -> None:
        nonlocal best
        for k in joints_of[link]:
            if k in used_joints:
                continue
            used_joints.add(k)
            for nxt in joints[k]:
                if nxt == link:
                    continue
                if nxt == start:
                    best = max(best, len(used_joints))
                elif nxt not in used_links and rank[nxt] > rank[start]:
                    used_links.add(nxt)
                    extend(start, nxt, used_links, used_joints)
                    used_links.discard(nxt)
            used_joints.discard(k)

    for start in links:  # cycles whose first link (in group order) is `start`
        extend(start, start, {start}, set())
    return best
