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

from collections.abc import Sequence

__all__ = ["Matcher", "irreducible_blocks"]


class Matcher:
    """Incremental maximum b-matching of row blocks to unknown blocks.

    >>> m = Matcher([2, 1])              # unknown capacities
    >>> m.add_row((0, 1), 2), m.add_row((0,), 1), m.add_row((1,), 1)
    (2, 1, 0)
    >>> sorted(m.assigned[0] + m.assigned[1])
    [0, 0, 1]
    """

    def __init__(self, capacities: Sequence[int]):
        self.cap = list(capacities)
        self.load = [0] * len(self.cap)
        self.owners: list[list[int]] = [[] for _ in self.cap]
        self.adj: list[tuple[int, ...]] = []
        self.assigned: list[list[int]] = []
        self._useen = [0] * len(self.cap)
        self._rseen: list[int] = []
        self._stamp = 0

    def add_row(self, adj: tuple[int, ...], size: int) -> int:
        """Add a row block and match as many of its ``size`` units as possible.

        Returns the number of units matched; the others stay unmatched for good.
        """
        r = len(self.adj)
        self.adj.append(adj)
        self.assigned.append([])
        self._rseen.append(0)
        got = 0
        for _ in range(size):
            for u in adj:  # cheap first try: a free unit next door
                if self.load[u] < self.cap[u]:
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
            self.owners[u].remove(r)
            self.load[u] -= 1
        self.assigned[r] = []
        self.adj[r] = ()

    def _take(self, r: int, u: int) -> None:
        self.load[u] += 1
        self.owners[u].append(r)
        self.assigned[r].append(u)

    def _augment(self, r0: int) -> bool:
        """Find a shortest augmenting path from row ``r0`` (breadth first) and flip it.

        Breadth first keeps the search local: the free unit a new row needs
        is almost always in the group being attached, a few steps away,
        while a depth-first search can wander through the whole mechanism.
        """
        self._stamp += 1
        stamp = self._stamp
        useen, rseen, adj, owners, load, cap = (
            self._useen,
            self._rseen,
            self.adj,
            self.owners,
            self.load,
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
                    if load[u] < cap[u]:
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
        while r != r0:
            u = came_through[r]
            taker = reached_by[u]
            self.owners[u].remove(r)
            self.assigned[r].remove(u)
            self.owners[u].append(taker)
            self.assigned[taker].append(u)
            r = taker

    @property
    def free_units(self) -> list[tuple[int, int]]:
        """``(unknown block, free units)`` for every block not fully matched."""
        return [
            (u, c - used)
            for u, (c, used) in enumerate(zip(self.cap, self.load, strict=True))
            if used < c
        ]


def irreducible_blocks(
    adj: Sequence[tuple[int, ...]],
    assigned: Sequence[Sequence[int]],
    n_unknowns: int,
    *,
    as_successors: bool = False,
) -> list[list[int]]:
    """Strongly connected components of the matched dependency digraph, sources first.

    ``adj[r]`` are the unknowns row ``r`` touches, ``assigned[r]`` those it is
    matched to. Each block is a sorted list of unknown indices; blocks come in
    a topological order (every block after the blocks it depends on); the
    order is deterministic. With ``as_successors=True``, ``adj`` is already
    the digraph (``adj[v]`` lists the successors of ``v``) and ``assigned``
    is ignored: plain strongly connected components, sources first.
    """
    succ = adj if as_successors else _dependency_digraph(adj, assigned, n_unknowns)
    return _strongly_connected(succ, n_unknowns)


def _dependency_digraph(
    adj: Sequence[tuple[int, ...]], assigned: Sequence[Sequence[int]], n_unknowns: int
) -> list[list[int]]:
    """Successors of each unknown: ``w -> u`` when a row matched to ``u`` also touches ``w``."""
    succ: list[list[int]] = [[] for _ in range(n_unknowns)]
    for r, units in enumerate(assigned):
        if not units:
            continue
        a = adj[r]
        first = units[0]
        if len(units) == 1 or all(u == first for u in units):
            for w in a:
                if w != first:
                    succ[w].append(first)
            continue
        for u in set(units):
            for w in a:
                if w != u:
                    succ[w].append(u)
    return succ


def _strongly_connected(succ: Sequence[Sequence[int]], n_nodes: int) -> list[list[int]]:
    """Strongly connected components, sources first (Tarjan, iterative); each one sorted."""
    index = [-1] * n_nodes
    low = [0] * n_nodes
    ptr = [0] * n_nodes
    on_stack = [False] * n_nodes
    stack: list[int] = []
    comps: list[list[int]] = []
    counter = 0
    for root in range(n_nodes):
        if index[root] != -1:
            continue
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack[root] = True
        call = [root]
        while call:
            v = call[-1]
            s = succ[v]
            i = ptr[v]
            if i < len(s):
                ptr[v] = i + 1
                w = s[i]
                if index[w] == -1:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on_stack[w] = True
                    call.append(w)
                elif on_stack[w] and index[w] < low[v]:
                    low[v] = index[w]
                continue
            call.pop()
            if call:
                parent = call[-1]
                if low[v] < low[parent]:
                    low[parent] = low[v]
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack[w] = False
                    comp.append(w)
                    if w == v:
                        break
                comps.append(sorted(comp))
    # Tarjan finds sinks first
    comps.reverse()
    return comps
