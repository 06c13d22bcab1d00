"""Small helpers shared by the modules of the package."""

from __future__ import annotations

import gc
from collections.abc import Hashable, Iterable, Iterator
from contextlib import contextmanager

__all__ = ["UnionFind", "paused_gc"]


@contextmanager
def paused_gc() -> Iterator[None]:
    """Pause Python's cyclic garbage collector for an allocation-heavy phase.

    Building a large mechanism allocates millions of small containers and
    none of them form reference cycles that need collecting meanwhile; the
    collector's full passes over the growing heap would otherwise make the
    time grow faster than the size. The previous state is restored on exit.

    >>> import gc
    >>> with paused_gc():
    ...     gc.isenabled()
    False
    """
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


class UnionFind:
    """Disjoint sets with union by weight and path compression.

    The same structure and the same answers (representatives, the order of
    :meth:`to_sets`) as ``networkx.utils.UnionFind``, kept here so that
    classifying a mechanism does not import networkx at all: networkx costs
    about as much start-up time as the whole rest of ``assur classify``.

    >>> sets = UnionFind("abcd")
    >>> sets.union("a", "b"); sets.union("c", "d")
    >>> sets["b"] == sets["a"], sets["c"] == sets["a"]
    (True, False)
    >>> [sorted(s) for s in sets.to_sets()]
    [['a', 'b'], ['c', 'd']]
    """

    def __init__(self, elements: Iterable[Hashable] = ()) -> None:
        self.parents: dict[Hashable, Hashable] = {}
        self.weights: dict[Hashable, int] = {}
        for x in elements:
            self.weights[x] = 1
            self.parents[x] = x

    def __getitem__(self, element: Hashable) -> Hashable:
        """The representative of ``element``'s set (a new singleton when unseen)."""
        if element not in self.parents:
            self.parents[element] = element
            self.weights[element] = 1
            return element
        path = []
        root = self.parents[element]
        while root != element:
            path.append(element)
            element = root
            root = self.parents[element]
        for ancestor in path:
            self.parents[ancestor] = root
        return root

    def __iter__(self) -> Iterator[Hashable]:
        """Every element seen so far."""
        return iter(self.parents)

    def to_sets(self) -> Iterator[set[Hashable]]:
        """The sets, in the order of their first element."""
        sets: dict[Hashable, set[Hashable]] = {}
        for x in list(self.parents):
            sets.setdefault(self[x], set()).add(x)
        yield from sets.values()

    def union(self, *elements: Hashable) -> None:
        """Merge the sets of ``elements`` into the heaviest one."""
        roots = iter(
            sorted({self[x] for x in elements}, key=lambda r: self.weights[r], reverse=True)
        )
        try:
            root = next(roots)
        except StopIteration:
            return
        for other in roots:
            self.weights[root] += self.weights[other]
            self.parents[other] = root
