"""Small helpers shared by the modules of the package."""

from __future__ import annotations

import gc
import itertools
from array import array
from collections.abc import Hashable, Iterable, Iterator, Sequence
from contextlib import contextmanager
from typing import Any

import numpy as np

__all__ = [
    "FlatSequence",
    "Ragged",
    "UnionFind",
    "count_components",
    "int_array",
    "paused_gc",
    "slot_setters",
]


@contextmanager
def paused_gc() -> Iterator[None]:
    """Pause Python's cyclic garbage collector for an allocation-heavy phase.

    Building a large mechanism allocates millions of small containers and
    none of them form reference cycles that need collecting meanwhile; the
    collector's full passes over the growing heap would otherwise make the
    time grow faster than the size. The previous state is restored on exit.

    What the phase built is then all in the collector's youngest generation,
    and the first allocation after re-enabling it would pass over every
    object (a tenth of a second for a 10^5-link mechanism). Those objects
    are the phase's result, long-lived: they are moved to the oldest
    generation, where a pass that found them alive would put them, without
    the pass (``gc.freeze`` then ``gc.unfreeze``; skipped when the program
    has frozen objects of its own, which that would unfreeze). They stay
    collectable.

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
            if not gc.get_freeze_count():
                gc.freeze()
                gc.unfreeze()
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


_DTYPES = {"b": np.int8, "i": np.int32, "q": np.int64}


def int_array(values: np.ndarray, typecode: str = "i") -> array:
    """``values`` as a flat :class:`array.array` of machine integers (``"b"``, ``"i"`` or ``"q"``).

    Indexing such an array gives Python ints at a few bytes per entry, where a
    list costs about 36: the large mechanisms' tables are kept this way.

    >>> int_array(np.array([3, 1, 2])).tolist()
    [3, 1, 2]
    """
    out = array(typecode)
    out.frombytes(memoryview(np.ascontiguousarray(values, dtype=_DTYPES[typecode])).cast("B"))
    return out


class FlatSequence(Sequence):
    """A sequence whose items are made on access from flat arrays (:meth:`_item` says how).

    A large mechanism's rows, matching and blocks are held in a few flat
    integer arrays rather than one tuple or list per item; these views give
    them back item by item. Two of them (or one and a list) are equal when
    their items are, as tuples.
    """

    __slots__ = ()

    def _item(self, k: int) -> Any:
        raise NotImplementedError

    def __getitem__(self, k):  # type: ignore[override]
        if isinstance(k, slice):
            return [self._item(i) for i in range(*k.indices(len(self)))]
        if k < 0:
            k += len(self)
        if not 0 <= k < len(self):
            raise IndexError(k)
        return self._item(k)

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, Sequence)
            and len(self) == len(other)
            and all(tuple(a) == tuple(b) for a, b in zip(self, other, strict=True))
        )

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"{type(self).__name__}({list(self)!r})"


class Ragged(FlatSequence):
    """Items of different lengths in two flat arrays: item ``k`` is ``values[start[k]:start[k+1]]``.

    >>> r = Ragged.of([(3, 1), (), (2,)])
    >>> list(r), len(r)
    ([(3, 1), (), (2,)], 3)
    """

    __slots__ = ("start", "values")

    def __init__(self, values: array, start: array):
        self.values, self.start = values, start

    @classmethod
    def of(cls, items: Sequence[Sequence[int]]) -> Ragged:
        """The items of a list of sequences, held flat."""
        values = array("i", itertools.chain.from_iterable(items))
        return cls(values, array("q", itertools.accumulate(map(len, items), initial=0)))

    def __len__(self) -> int:
        return len(self.start) - 1

    def _item(self, k: int) -> tuple[int, ...]:
        return tuple(self.values[self.start[k] : self.start[k + 1]])

    def tolist(self) -> list[tuple[int, ...]]:
        """Every item as a tuple, in one pass."""
        values, start = self.values, self.start
        return [tuple(values[a:b]) for a, b in itertools.pairwise(start)]


def count_components(nodes: Iterable[Hashable], joints: Iterable[Sequence[Hashable]]) -> int:
    """Connected components of a small graph whose joints each join some ``nodes``.

    A union-find in a plain dict (path halving): no object per call, for the
    tens of thousands of groups and hinges a large mechanism has.

    >>> count_components("abcd", [("a", "b"), ("b", "c", "a")])
    2
    """
    parent = {x: x for x in nodes}
    count = len(parent)
    for joint in joints:
        if not joint:
            continue
        root = _root(parent, joint[0])
        for x in joint[1:]:
            other = _root(parent, x)
            if other != root:
                parent[other] = root
                count -= 1
    return count


def _root(parent: dict, x: Hashable) -> Hashable:
    """The representative of ``x`` in the union-find ``parent`` (halving the path)."""
    while parent[x] != x:
        parent[x] = x = parent[parent[x]]
    return x


def slot_setters(cls: type, names: Sequence[str] | None = None) -> tuple[Any, ...]:
    """The setters of ``cls``'s slots (default: all, in order), to fill a new frozen record.

    A frozen dataclass's ``__init__`` sets each field through
    ``object.__setattr__``; the slots' own setters do it in half the time,
    and a large mechanism makes hundreds of thousands of records.
    """
    return tuple(getattr(cls, name).__set__ for name in (names or cls.__slots__))
