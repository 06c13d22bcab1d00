"""Maximum matching and block-triangular (Dulmage–Mendelsohn) order of a constraint system.

Rows and unknowns come in blocks of 1 or 2 scalars, so the matching is a
b-matching: row block ``r`` needs ``size[r]`` units, unknown block ``u`` offers
``cap[u]``. Rows are matched in the order given (Kuhn's augmenting paths,
breadth first, visiting each unknown block at most once per search), so a row that stays
unmatched is one whose constraints are already implied structurally by the
rows before it: the redundant one is always the latest listed.

Once every row is matched, the unknowns form a digraph (``w -> u`` when a row
matched to ``u`` also touches ``w``); its strongly connected components in
topological order are the irreducible blocks, in an order in which they can be
solved one after another. They do not depend on which maximum matching was
found.

References: A. L. Dulmage, N. S. Mendelsohn, "Coverings of bipartite graphs",
Canad. J. Math. 10 (1958); R. Tarjan, "Depth-first search and linear graph
algorithms", SIAM J. Comput. 1 (1972).
"""

from __future__ import annotations

import itertools
from array import array
from collections.abc import Sequence
from dataclasses import dataclass
from itertools import repeat

import numpy as np

from ..utils import FlatSequence, Ragged, int_array

__all__ = [
    "NUMPY_ROWS",
    "Assignment",
    "FlatRows",
    "Matcher",
    "flat_rows",
    "irreducible_blocks",
    "strongly_connected",
]


class Matcher:
    """Incremental maximum b-matching of row blocks to unknown blocks.

    Rows and unknowns hold at most two units each (row blocks of one or two
    scalars, unknown blocks of one or two coordinates). ``assigned[r]`` are
    the unknown blocks row ``r`` is matched to (one entry per unit) and
    ``owners[u]`` the rows matched to unknown ``u`` (one entry per unit), as
    tuples made on access: the matcher itself keeps flat integer arrays, two
    slots per row and per unknown, since a large mechanism has hundreds of
    thousands of both.

    >>> m = Matcher([2, 1])              # unknown capacities
    >>> m.add_row((0, 1), 2), m.add_row((0,), 1), m.add_row((1,), 1)
    (2, 1, 0)
    >>> sorted(m.assigned[0] + m.assigned[1])
    [0, 0, 1]
    """

    def __init__(self, capacities: Sequence[int]):
        # lists, not arrays: read in the innermost loops, where a list is the fastest
        self.cap = list(capacities)
        if max(self.cap, default=0) > 2:
            raise ValueError("unknown blocks hold at most two units")
        n = len(self.cap)
        self._load = [0] * n
        self._owner = [-1] * (2 * n)  # rows on unit slots 2u, 2u + 1
        self._start = array("q", [0])
        self._adj = array("i")
        self._units = array("i")  # unknowns on row slots 2r, 2r + 1 (-1: none)
        self._useen = array("i", bytes(4 * n))
        self._rseen = array("i")
        self._stamp = 0

    @property
    def assigned(self) -> Assignment:
        """The unknown blocks each row is matched to, one entry per unit."""
        return Assignment(self._units)

    @property
    def owners(self) -> list[tuple[int, ...]]:
        """The rows matched to each unknown block, one entry per unit."""
        o = self._owner
        return [tuple(o[2 * u : 2 * u + k]) for u, k in enumerate(self._load)]

    @property
    def load(self) -> list[int]:
        """Units of each unknown block matched so far."""
        return list(self._load)

    def add_row(self, adj: Sequence[int], size: int) -> int:
        """Add a row block and match as many of its ``size`` (at most 2) units as possible.

        Returns the number of units matched; the others stay unmatched for good.
        """
        adj = array("i", adj)
        unmatched = self.add_rows(array("q", [0, len(adj)]), adj, (size,))
        return size - sum(unmatched.values())

    def add_rows(self, adj_start: array, adj: array, sizes: Sequence[int]) -> dict[int, int]:
        """Add many row blocks at once, as :meth:`add_row` one after another would.

        ``adj[adj_start[k]:adj_start[k + 1]]`` are the unknowns of the ``k``-th
        new row and ``sizes[k]`` its size. Returns ``{row: units left
        unmatched}`` for the rows not wholly matched. One loop with the
        cheap first try inlined: a large mechanism has hundreds of thousands
        of rows, and most of them find a free unit next door.
        """
        first = len(self._rseen)
        n = len(sizes)
        base = len(self._adj)
        self._adj.extend(adj[adj_start[0] : adj_start[n]])
        shift = base - adj_start[0]
        self._start.extend(
            adj_start[1 : n + 1] if not shift else (x + shift for x in adj_start[1 : n + 1])
        )
        self._units.extend(array("i", [-1]) * (2 * n))
        self._rseen.extend(array("i", bytes(4 * n)))
        load, cap, owner, units = self._load, self.cap, self._owner, self._units
        start, flat, augment = self._start, self._adj, self._augment
        unmatched: dict[int, int] = {}
        for r in range(first, first + n):
            size = sizes[r - first]
            row = flat[start[r] : start[r + 1]]
            got = 0
            while got < size:
                for u in row:
                    if load[u] < cap[u]:
                        owner[2 * u + load[u]] = r
                        load[u] += 1
                        units[2 * r + got] = u
                        break
                else:
                    if not augment(r):
                        unmatched[r] = size - got
                        break
                got += 1
        return unmatched

    def _augment(self, r0: int) -> bool:
        """Find a shortest augmenting path from row ``r0`` (breadth first) and flip it.

        Breadth first keeps the search local: the free unit a new row needs
        is almost always in the group being attached, a few steps away,
        while a depth-first search can wander through the whole mechanism.
        """
        adj, start, owner, load, cap = self._adj, self._start, self._owner, self._load, self.cap
        # the usual case first: a row next door gives way and takes a free unit of its own
        # (what the search below finds first when the path is that short)
        # (rows in the order the search reaches them, each through its first unit; the first
        # that has a free unit is the search's first find)
        tried = [r0]
        for u in adj[start[r0] : start[r0 + 1]]:
            for r in owner[2 * u : 2 * u + load[u]]:
                if r not in tried:
                    for free_u in adj[start[r] : start[r + 1]]:
                        if load[free_u] < cap[free_u]:
                            self._give_way(r0, r, u, free_u)
                            return True
                    tried.append(r)
        self._stamp += 1
        stamp = self._stamp
        useen, rseen = self._useen, self._rseen
        rseen[r0] = stamp
        reached_by: dict[int, int] = {}  # unknown -> row that reached it
        came_through: dict[int, int] = {}  # row -> unknown it was reached through
        frontier = [r0]
        while frontier:
            following: list[int] = []
            for r in frontier:
                for u in adj[start[r] : start[r + 1]]:
                    if useen[u] == stamp:
                        continue
                    useen[u] = stamp
                    reached_by[u] = r
                    if load[u] < cap[u]:
                        self._flip(r0, r, u, reached_by, came_through)
                        return True
                    for r2 in owner[2 * u : 2 * u + load[u]]:
                        if rseen[r2] != stamp:
                            rseen[r2] = stamp
                            came_through[r2] = u
                            following.append(r2)
            frontier = following
        return False

    def _give_way(self, r0: int, r: int, u: int, free_u: int) -> None:
        """:meth:`_flip` of the path ``r0 -> u -> r -> free_u``: ``r`` gives ``u`` to ``r0``."""
        self._owner[2 * free_u + self._load[free_u]] = r
        self._load[free_u] += 1
        self._pass_on(r, u, r0, free_u)
        units = self._units
        units[2 * r0 + (units[2 * r0] != -1)] = u

    def _flip(
        self,
        r0: int,
        r: int,
        free_u: int,
        reached_by: dict[int, int],
        came_through: dict[int, int],
    ) -> None:
        # r takes the free unit; each row on the path gives its unit to the row before it
        self._owner[2 * free_u + self._load[free_u]] = r
        self._load[free_u] += 1
        received = free_u
        while r != r0:
            u = came_through[r]
            taker = reached_by[u]
            self._pass_on(r, u, taker, received)
            received, r = u, taker
        units = self._units
        units[2 * r + (units[2 * r] != -1)] = received

    def _pass_on(self, r: int, u: int, taker: int, received: int) -> None:
        """Row ``r`` gives its unit of ``u`` to row ``taker`` and holds ``received`` instead."""
        owner, units = self._owner, self._units
        # u's rows less r (the others move up), then the taker last
        k = 2 * u
        if owner[k] == r and self.cap[u] == 2:
            owner[k] = owner[k + 1]
            owner[k + 1] = taker
        elif owner[k] == r:
            owner[k] = taker
        else:
            owner[k + 1] = taker
        # r's units less u (the first one), then the unit it received last
        k = 2 * r
        if units[k] == u:
            units[k] = units[k + 1]
        units[k + 1] = -1
        units[k + (units[k] != -1)] = received

    @property
    def free_units(self) -> list[tuple[int, int]]:
        """``(unknown block, free units)`` for every block not fully matched."""
        return [
            (u, c - k) for u, (c, k) in enumerate(zip(self.cap, self._load, strict=True)) if k < c
        ]


class Assignment(FlatSequence):
    """``assignment[r]``: the unknown blocks row ``r`` is matched to, one entry per unit.

    A view of two slots per row in one flat array (-1 for an empty slot),
    made into a tuple on access.
    """

    __slots__ = ("units",)

    def __init__(self, units: array):
        self.units = units

    def __len__(self) -> int:
        return len(self.units) // 2

    def _item(self, r: int) -> tuple[int, ...]:
        a, b = self.units[2 * r], self.units[2 * r + 1]
        return () if a < 0 else (a,) if b < 0 else (a, b)

    def tolist(self) -> list[tuple[int, ...]]:
        """Every row's units as a tuple, in one pass."""
        u = self.units
        return [
            () if a < 0 else (a,) if b < 0 else (a, b)
            for a, b in zip(u[0::2], u[1::2], strict=True)
        ]


def irreducible_blocks(
    adj: Sequence[tuple[int, ...]],
    assigned: Sequence[Sequence[int]],
    n_unknowns: int,
    *,
    flat: FlatRows | None = None,
) -> list[list[int]]:
    """Strongly connected components of the matched dependency digraph, sources first.

    ``adj[r]`` are the unknowns row ``r`` touches, ``assigned[r]`` those it is
    matched to. Each block is a sorted list of unknown indices; blocks come in
    a topological order (every block after the blocks it depends on); the
    order is deterministic. (For a digraph given by its edges,
    :func:`strongly_connected`.)

    ``flat`` is the same rows as a :class:`FlatRows` (a large system's), when made.

    >>> irreducible_blocks([(0,), (0, 1), (1, 2), (2, 1)], [[0], [1], [2], [1]], 3)
    [[0], [1, 2]]
    """
    if flat is None:
        start, successors = _adjacency_arrays(*_dependency_edges(adj, assigned), n_unknowns)
        return _strongly_connected(start, successors, n_unknowns)
    start, successors = _adjacency_arrays(*_dependency_edges_flat(flat), n_unknowns)
    return Ragged.of(_strongly_connected(start, successors, n_unknowns))


def block_arrays(blocks: Sequence[Sequence[int]]) -> tuple[np.ndarray, np.ndarray]:
    """``(units, start)``: the blocks' unknowns one after another, and where each block starts."""
    if isinstance(blocks, Ragged):
        return (
            np.frombuffer(blocks.values, dtype=np.int32).astype(np.int64),
            np.frombuffer(blocks.start, dtype=np.int64),
        )
    count = np.fromiter(map(len, blocks), np.int64, len(blocks))
    start = np.zeros(len(blocks) + 1, dtype=np.int64)
    np.cumsum(count, out=start[1:])
    return np.fromiter(itertools.chain.from_iterable(blocks), np.int64, int(start[-1])), start


#: from this many rows on, the rows are also held as flat numpy arrays (:class:`FlatRows`)
NUMPY_ROWS = 2048


@dataclass(frozen=True, slots=True)
class FlatRows:
    """A large system's rows and matching as flat integer arrays.

    ``adj[adj_start[r]:adj_start[r + 1]]`` are the unknowns row ``r``
    touches; ``units`` lists, row after row, the distinct unknowns each row
    is matched to, in the order :func:`_dependency_edges` takes them, and
    ``unit_row`` the row of each; ``matched[r]`` counts the units of row ``r``
    (repeats included). One array each instead of a tuple per row: a large
    mechanism has hundreds of thousands of rows.
    """

    adj_start: np.ndarray
    adj: np.ndarray
    unit_row: np.ndarray
    units: np.ndarray
    matched: np.ndarray


def flat_rows(adj_start: array, adj: array, units: array) -> FlatRows:
    """A :class:`FlatRows` of rows given as flat arrays.

    ``adj[adj_start[r]:adj_start[r + 1]]`` are the unknowns row ``r``
    touches, ``units[2r]`` and ``units[2r + 1]`` those it is matched to (-1
    for none; see :class:`Assignment`). Two different units of a row are
    taken in the order of a set of them, as :func:`_dependency_edges` does.
    """
    start = np.frombuffer(adj_start, dtype=np.int64)
    slots = np.frombuffer(units, dtype=np.int32).reshape(-1, 2)
    first, second = slots[:, 0].copy(), slots[:, 1].copy()
    matched = ((first >= 0).astype(np.int8) + (second >= 0)).astype(np.int8)
    two = np.flatnonzero((second >= 0) & (second != first))
    if len(two):
        swap = ~_set_keeps_order(first[two], second[two])
        first[two[swap]], second[two[swap]] = second[two[swap]], first[two[swap]]
    rows = np.concatenate([np.flatnonzero(first >= 0), two]).astype(np.int32)
    distinct = np.concatenate([first[first >= 0], second[two]])
    del first, second, two
    # each row's units together, its first before its second
    order = np.argsort(
        2 * rows.astype(np.int64) + (np.arange(len(rows)) >= np.count_nonzero(slots[:, 0] >= 0)),
        kind="stable",
    )
    return FlatRows(
        start, np.frombuffer(adj, dtype=np.int32), rows[order], distinct[order], matched
    )


def _set_keeps_order(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Whether ``tuple({a, b})`` is ``(a, b)``, for each pair of distinct non-negative ints.

    A two-element set lists its members by their slots in a table of 8:
    ``a`` sits at ``a & 7``; ``b`` at ``b & 7`` unless that is taken, then
    wherever CPython's probe sequence (``i = (5 i + 1 + perturb) & 7``, the
    perturbation starting at ``b`` and shifted right by 5 each step) first
    finds free.
    """
    slot_a = a & 7
    slot_b = b & 7
    perturb = b.copy()
    pending = slot_b == slot_a
    while pending.any():
        perturb[pending] >>= 5
        slot_b[pending] = (slot_b[pending] * 5 + 1 + perturb[pending]) & 7
        pending &= slot_b == slot_a
    return slot_a < slot_b


def _dependency_edges_flat(rows: FlatRows) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_dependency_edges` of a :class:`FlatRows`, the same edges in the same order."""
    begin = rows.adj_start[rows.unit_row]
    counts = rows.adj_start[rows.unit_row + 1] - begin
    total = int(counts.sum())
    # each unit's row's adjacency, one after another
    at = np.repeat((begin - np.cumsum(counts) + counts).astype(np.int32), counts)
    at += np.arange(total, dtype=np.int32)
    return rows.adj[at], np.repeat(rows.units, counts)


def strongly_connected(
    sources: Sequence[int], targets: Sequence[int], n_nodes: int
) -> list[list[int]]:
    """Strongly connected components of the digraph with edges ``sources[k] -> targets[k]``.

    Sources first, each component sorted, in a deterministic order: the
    successors of a node are taken in the order of its edges.

    >>> strongly_connected([0, 1, 2], [1, 2, 1], 3)
    [[0], [1, 2]]
    """
    start, flat = _adjacency_arrays(sources, targets, n_nodes)
    return _strongly_connected(start, flat, n_nodes)


def _dependency_edges(
    adj: Sequence[tuple[int, ...]], assigned: Sequence[Sequence[int]]
) -> tuple[array, array]:
    """``w -> u`` when a row matched to ``u`` also touches ``w``: sources and targets, in order.

    Self-loops (``w == u``) are listed too; :func:`_adjacency_arrays` drops them.
    Flat arrays of machine integers: a large mechanism has about a million edges.
    """
    sources = array("i")
    targets = array("i")
    for r, units in enumerate(assigned):
        if not units:
            continue
        a = adj[r]
        first = units[0]
        if len(units) == 1 or all(u == first for u in units):
            sources.extend(a)
            targets.extend(repeat(first, len(a)))
            continue
        for u in set(units):
            sources.extend(a)
            targets.extend(repeat(u, len(a)))
    return sources, targets


#: from this many edges on, the successor arrays are sorted by numpy (below, by a
#: counting sort in Python, which costs less for the small mechanisms of a batch)
_NUMPY_EDGES = 2048


def _adjacency_arrays(
    sources: Sequence[int], targets: Sequence[int], n_nodes: int
) -> tuple[array, array]:
    """Successor lists as one flat array: ``flat[start[v]:start[v + 1]]`` are ``v``'s, in order.

    Two flat arrays of machine integers instead of one list per node: a large
    mechanism's digraph has hundreds of thousands of nodes. Self-loops are dropped.
    """
    if len(sources) >= _NUMPY_EDGES:
        src = np.asarray(sources, dtype=np.intc)
        dst = np.asarray(targets, dtype=np.intc)
        keep = src != dst
        src, dst = src[keep], dst[keep]
        del keep
        start = np.zeros(n_nodes + 1, dtype=np.int64)
        np.cumsum(np.bincount(src, minlength=n_nodes), out=start[1:])
        return int_array(start), int_array(dst[np.argsort(src, kind="stable")])
    pairs = [(v, w) for v, w in zip(sources, targets, strict=True) if v != w]
    counts = array("i", [0]) * (n_nodes + 1)
    for v, _ in pairs:
        counts[v + 1] += 1
    for v in range(n_nodes):
        counts[v + 1] += counts[v]
    fill = counts[:-1]
    flat = array("i", [0]) * len(pairs)
    for v, w in pairs:
        flat[fill[v]] = w
        fill[v] += 1
    return counts, flat


def _strongly_connected(start: array, flat: array, n_nodes: int) -> list[list[int]]:
    """Strongly connected components, sources first (Tarjan, iterative); each one sorted.

    The successors of ``v`` are ``flat[start[v]:start[v + 1]]``. A node whose
    component is complete gets an index above every other, so that it never
    lowers a link value again (no separate on-stack flags).
    """
    done = n_nodes + 1
    # lists: read once per edge, where a list's item costs less than an array's
    index = [-1] * n_nodes
    low = [0] * n_nodes
    ptr = start[:-1]
    stack: list[int] = []
    comps: list[list[int]] = []
    counter = 0
    for root in range(n_nodes):
        if index[root] != -1:
            continue
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        call = [root]
        while call:
            v = call[-1]
            i, end, lv = ptr[v], start[v + 1], low[v]
            w = -1
            while i < end:
                w = flat[i]
                i += 1
                iw = index[w]
                if iw == -1:
                    break
                if iw < lv:
                    lv = iw
                w = -1
            ptr[v], low[v] = i, lv
            if w != -1:  # descend into the unvisited successor
                index[w] = low[w] = counter
                counter += 1
                stack.append(w)
                call.append(w)
                continue
            call.pop()
            if call:
                parent = call[-1]
                if lv < low[parent]:
                    low[parent] = lv
            if lv == index[v]:
                k = len(stack) - 1
                while stack[k] != v:
                    k -= 1
                comp = stack[k:]
                del stack[k:]
                for x in comp:
                    index[x] = done
                comp.sort()
                comps.append(comp)
    # Tarjan finds sinks first
    comps.reverse()
    return comps
