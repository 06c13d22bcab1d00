"""Canonical labelling and automorphisms of small coloured graphs, in pure Python.

A graph is ``n`` vertices ``0 .. n-1``, an adjacency list of ``{neighbour: weight}``
dicts (weights are edge multiplicities, all 1 for a simple graph) and one integer
colour per vertex. :func:`canonical_form` returns the order in which the vertices
are listed canonically, the code of the graph in that order (equal for two graphs
exactly when they are isomorphic, colours and weights kept) and generators of the
automorphism group.

The method is individualization-refinement, as in McKay's *nauty*: the vertices are
split into cells by colour, the partition is refined until every vertex of a cell
sees the same number of neighbours of each weight in every cell (1-dimensional
Weisfeiler-Leman), a vertex of the first smallest non-trivial cell is put alone in
a cell, and so on until every cell is a single vertex; the canonical order is the
leaf of the search tree with the smallest code. Automorphisms found between leaves
prune the tree (children in one orbit of the automorphisms found that fix the path
are explored once), and the automorphisms found generate the whole group. Meant for
kinematic chains (tens of vertices); nothing here depends on a C library.

References: B. D. McKay, A. Piperno, "Practical graph isomorphism, II",
J. Symbolic Computation 60 (2014).

>>> square = [{1: 1, 3: 1}, {0: 1, 2: 1}, {1: 1, 3: 1}, {2: 1, 0: 1}]
>>> form = canonical_form(4, square)
>>> form.code
((0, 0, 0, 0), ((0, 2, 1), (0, 3, 1), (1, 2, 1), (1, 3, 1)))
>>> group_order(4, form.generators)
8
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

__all__ = [
    "CanonicalForm",
    "canonical_form",
    "group_elements",
    "group_order",
    "orbits",
]

Adjacency = Sequence[Mapping[int, int]]
Code = tuple[tuple[int, ...], tuple[tuple[int, int, int], ...]]


@dataclass(frozen=True, slots=True)
class CanonicalForm:
    """Canonical order of a graph's vertices, its code and automorphism generators.

    ``order[i]`` is the vertex listed at canonical position ``i``; ``code`` is
    ``(colours in canonical order, sorted (i, j, weight) edges with i <= j)``;
    each generator is a permutation ``p`` (``p[v]`` is the image of ``v``).
    """

    order: tuple[int, ...]
    code: Code
    generators: tuple[tuple[int, ...], ...]

    @property
    def position(self) -> tuple[int, ...]:
        """``position[v]``: the canonical position of vertex ``v``."""
        out = [0] * len(self.order)
        for i, v in enumerate(self.order):
            out[v] = i
        return tuple(out)


def _refine(cells: list[list[int]], adjacency: Adjacency) -> list[list[int]]:
    """The coarsest equitable refinement of the ordered partition ``cells``.

    A cell splits by the multiset of (cell, weight) of its vertices' neighbours;
    the fragments keep the cell's place, in decreasing order of that multiset, so
    the result does not depend on the vertices' names.
    """
    while True:
        cell_of = {}
        for index, cell in enumerate(cells):
            for v in cell:
                cell_of[v] = index
        refined: list[list[int]] = []
        for cell in cells:
            if len(cell) == 1:
                refined.append(cell)
                continue
            by_signature: dict[tuple, list[int]] = {}
            for v in cell:
                signature = tuple(sorted((cell_of[u], w) for u, w in adjacency[v].items()))
                by_signature.setdefault(signature, []).append(v)
            if len(by_signature) == 1:
                refined.append(cell)
            else:
                refined.extend(by_signature[s] for s in sorted(by_signature, reverse=True))
        if len(refined) == len(cells):
            return refined
        cells = refined


def _leaf_code(order: list[int], adjacency: Adjacency, colours: Sequence[int]) -> Code:
    position = {v: i for i, v in enumerate(order)}
    edges = []
    for v in order:
        i = position[v]
        for u, w in adjacency[v].items():
            j = position[u]
            if i <= j:
                edges.append((i, j, w))
    edges.sort()
    return tuple(colours[v] for v in order), tuple(edges)


class _Search:
    """State of one search tree: the first and best leaves and the automorphisms."""

    def __init__(self, adjacency: Adjacency, colours: Sequence[int]) -> None:
        self.adjacency = adjacency
        self.colours = colours
        self.first: tuple[list[int], Code] | None = None
        self.best: tuple[list[int], Code] | None = None
        self.generators: list[tuple[int, ...]] = []

    def leaf(self, order: list[int]) -> None:
        code = _leaf_code(order, self.adjacency, self.colours)
        if self.first is None:
            self.first = self.best = (order, code)
            return
        assert self.best is not None
        for known, known_code in (self.first, self.best):
            if code == known_code:
                image = [0] * len(order)
                for v, u in zip(order, known, strict=True):
                    image[v] = u
                generator = tuple(image)
                if generator not in self.generators and any(
                    generator[v] != v for v in range(len(generator))
                ):
                    self.generators.append(generator)
                return
        if code < self.best[1]:
            self.best = (order, code)

    def explore(self, cells: list[list[int]], path: list[int]) -> None:
        cells = _refine(cells, self.adjacency)
        target = None
        for index, cell in enumerate(cells):
            if len(cell) > 1 and (target is None or len(cell) < len(cells[target])):
                target = index
        if target is None:
            self.leaf([cell[0] for cell in cells])
            return
        explored: list[int] = []
        for v in sorted(cells[target]):
            if explored and _same_orbit(v, explored, self._fixing(path)):
                continue
            explored.append(v)
            rest = [u for u in cells[target] if u != v]
            child = [*cells[:target], [v], rest, *cells[target + 1 :]]
            self.explore(child, [*path, v])

    def _fixing(self, path: list[int]) -> list[tuple[int, ...]]:
        return [g for g in self.generators if all(g[v] == v for v in path)]


def _same_orbit(v: int, explored: list[int], generators: list[tuple[int, ...]]) -> bool:
    if not generators:
        return False
    root = _orbit_roots(len(generators[0]), generators)
    return any(root[u] == root[v] for u in explored)


def _orbit_roots(n: int, generators: Iterable[Sequence[int]]) -> list[int]:
    parent = list(range(n))

    def find(x: int) -> int:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for g in generators:
        for v in range(n):
            a, b = find(v), find(g[v])
            if a != b:
                parent[max(a, b)] = min(a, b)
    return [find(v) for v in range(n)]


def canonical_form(
    n: int, adjacency: Adjacency, colours: Sequence[int] | None = None
) -> CanonicalForm:
    """Canonical order, code and automorphism generators of a coloured graph.

    Parameters
    ----------
    n : int
        Number of vertices, named ``0 .. n-1``.
    adjacency : sequence of mappings
        ``adjacency[v][u]`` is the weight of the edge ``v-u`` (present both ways);
        ``adjacency[v][v]`` a loop's weight.
    colours : sequence of int, optional
        One colour per vertex (default all 0); isomorphisms keep colours.

    Returns
    -------
    CanonicalForm
        Two graphs are isomorphic exactly when their codes are equal.
    """
    colours = [0] * n if colours is None else list(colours)
    if n == 0:
        return CanonicalForm((), ((), ()), ())
    by_colour: dict[int, list[int]] = {}
    for v in range(n):
        by_colour.setdefault(colours[v], []).append(v)
    search = _Search(adjacency, colours)
    search.explore([by_colour[c] for c in sorted(by_colour)], [])
    assert search.best is not None
    order, code = search.best
    return CanonicalForm(tuple(order), code, tuple(search.generators))


def orbits(n: int, generators: Iterable[Sequence[int]]) -> tuple[tuple[int, ...], ...]:
    """The orbits of ``0 .. n-1`` under the group the permutations generate, sorted.

    >>> orbits(4, [(1, 0, 2, 3)])
    ((0, 1), (2,), (3,))
    """
    root = _orbit_roots(n, generators)
    grouped: dict[int, list[int]] = {}
    for v in range(n):
        grouped.setdefault(root[v], []).append(v)
    return tuple(sorted(tuple(members) for members in grouped.values()))


def group_elements(n: int, generators: Sequence[Sequence[int]]) -> list[tuple[int, ...]]:
    """Every element of the permutation group the generators generate, sorted (identity first).

    By closure: meant for small groups (a chain's automorphisms).

    >>> group_elements(3, [(1, 0, 2)])
    [(0, 1, 2), (1, 0, 2)]
    """
    identity = tuple(range(n))
    seen = {identity}
    frontier = [identity]
    while frontier:
        nxt = []
        for element in frontier:
            for g in generators:
                product = tuple(g[element[v]] for v in range(n))
                if product not in seen:
                    seen.add(product)
                    nxt.append(product)
        frontier = nxt
    return sorted(seen)


def group_order(n: int, generators: Sequence[Sequence[int]]) -> int:
    """Order of the permutation group the generators generate (see :func:`group_elements`).

    >>> group_order(3, [(1, 2, 0), (1, 0, 2)])
    6
    """
    return len(group_elements(n, generators))
