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

from array import array
from collections.abc import Sequence
from itertools import repeat

import numpy as np

__all__ = ["Matcher", "irreducible_blocks", "strongly_connected"]


class Matcher:
    """Incremental maximum b-matching of row blocks to unknown blocks.

    ``assigned[r]`` are the unknown blocks row ``r`` is matched to (one entry
    per unit) and ``owners[u]`` the rows matched to unknown ``u`` (one entry
    per unit), both as tuples: most rows and unknowns hold one or two units,
    and a tuple of them is half a list's size (an empty one costs nothing).

    >>> m = Matcher([2, 1])              # unknown capacities
    >>> m.add_row((0, 1), 2), m.add_row((0,), 1), m.add_row((1,), 1)
    (2, 1, 0)
    >>> sorted(m.assigned[0] + m.assigned[1])
    [0, 0, 1]
    """

    def __init__(self, capacities: Sequence[int]):
        self.cap = list(capacities)
        self.owners: list[tuple[int, ...]] = [()] * len(self.cap)
        self.adj: list[tuple[int, ...]] = []
        self.assigned: list[tuple[int, ...]] = []
        self._useen = [0] * len(self.cap)
        self._rseen: list[int] = []
        self._stamp = 0

    @property
    def load(self) -> list[int]:
        """Units of each unknown block matched so far."""
        return [len(rows) for rows in self.owners]

    def add_row(self, adj: tuple[int, ...], size: int) -> int:
        """Add a row block and match as many of its ``size`` units as possible.

        Returns the number of units matched; the others stay unmatched for good.
        """
        r = len(self.adj)
        self.adj.append(adj)
        self.assigned.append(())
        self._rseen.append(0)
        owners, cap = self.owners, self.cap
        got = 0
        for _ in range(size):
            for u in adj:  # cheap first try: a free unit next door
                if len(owners[u]) < cap[u]:
                    self._take(r, u)
                    got += 1
                    break
            else:
                if not self._augment(r):
                    break
                got += 1
        return got

    def remove_row(self, r: int) -> None:
        """Unmatch row block ``r`` (it keeps its index but touches nothing)."""
        for u in self.assigned[r]:
            self.owners[u] = _without(self.owners[u], r)
        self.assigned[r] = ()
        self.adj[r] = ()

    def _take(self, r: int, u: int) -> None:
        self.owners[u] += (r,)
        self.assigned[r] += (u,)

    def _augment(self, r0: int) -> bool:
        """Find a shortest augmenting path from row ``r0`` (breadth first) and flip it.

        Breadth first keeps the search local: the free unit a new row needs
        is almost always in the group being attached, a few steps away,
        while a depth-first search can wander through the whole mechanism.
        """
        self._stamp += 1
        stamp = self._stamp
        useen, rseen, adj, owners, cap = (
            self._useen,
            self._rseen,
            self.adj,
            self.owners,
            self.cap,
        )
        rseen[r0] = stamp
        reached_by: dict[int, int] = {}  # unknown -> row that reached it
        came_through: dict[int, int] = {}  # row -> unknown it was reached through
        frontier = [r0]
        while frontier:
            following: list[int] = []
            for r in frontier:
                for u in adj[r]:
                    if useen[u] == stamp:
                        continue
                    useen[u] = stamp
                    reached_by[u] = r
                    if len(owners[u]) < cap[u]:
                        self._flip(r0, r, u, reached_by, came_through)
                        return True
                    for r2 in owners[u]:
                        if rseen[r2] != stamp:
                            rseen[r2] = stamp
                            came_through[r2] = u
                            following.append(r2)
            frontier = following
        return False

    def _flip(
        self,
        r0: int,
        r: int,
        free_u: int,
        reached_by: dict[int, int],
        came_through: dict[int, int],
    ) -> None:
        # r takes the free unit; each row on the path gives its unit to the row before it
        self._take(r, free_u)
        owners, assigned = self.owners, self.assigned
        while r != r0:
            u = came_through[r]
            taker = reached_by[u]
            owners[u] = (*_without(owners[u], r), taker)
            assigned[r] = _without(assigned[r], u)
            assigned[taker] += (u,)
            r = taker

    @property
    def free_units(self) -> list[tuple[int, int]]:
        """``(unknown block, free units)`` for every block not fully matched."""
        return [
            (u, c - len(rows))
            for u, (c, rows) in enumerate(zip(self.cap, self.owners, strict=True))
            if len(rows) < c
        ]


def _without(items: tuple[int, ...], item: int) -> tuple[int, ...]:
    """``items`` less the first ``item`` (as ``list.remove`` does)."""
    k = items.index(item)
    return items[:k] + items[k + 1 :]


def irreducible_blocks(
    adj: Sequence[tuple[int, ...]],
    assigned: Sequence[Sequence[int]],
    n_unknowns: int,
) -> list[list[int]]:
    """Strongly connected components of the matched dependency digraph, sources first.

    ``adj[r]`` are the unknowns row ``r`` touches, ``assigned[r]`` those it is
    matched to. Each block is a sorted list of unknown indices; blocks come in
    a topological order (every block after the blocks it depends on); the
    order is deterministic. (For a digraph given by its edges,
    :func:`strongly_connected`.)

    >>> irreducible_blocks([(0,), (0, 1), (1, 2), (2, 1)], [[0], [1], [2], [1]], 3)
    [[0], [1, 2]]
    """
    start, flat = _adjacency_arrays(*_dependency_edges(adj, assigned), n_unknowns)
    return _strongly_connected(start, flat, n_unknowns)


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
        return _as_array(start), _as_array(dst[np.argsort(src, kind="stable")])
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


def _as_array(values: np.ndarray) -> array:
    out = array("i")
    out.frombytes(memoryview(np.ascontiguousarray(values, dtype=np.intc)).cast("B"))
    return out


def _strongly_connected(start: array, flat: array, n_nodes: int) -> list[list[int]]:
    """Strongly connected components, sources first (Tarjan, iterative); each one sorted.

    The successors of ``v`` are ``flat[start[v]:start[v + 1]]``. A node whose
    component is complete gets an index above every other, so that it never
    lowers a link value again (no separate on-stack flags).
    """
    done = n_nodes + 1
    index = array("i", [-1]) * n_nodes
    low = array("i", [0]) * n_nodes
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
