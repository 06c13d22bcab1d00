"""Planar kinematic chains with revolute pins: rigid-subchain test, canonical code, enumeration.

A chain of ``N`` links joined by ``J`` simple revolute pins is a graph (links are
vertices, pins edges) with ``F = 3(N - 1) - 2J`` degrees of freedom. It is
*degenerate* when some subchain of two or more links is rigid on its own,
``3(|S| - 1) - 2 e(S) <= 0``; *fractionated* when one link cuts it in two.
:func:`enumerate_chains` lists the non-isomorphic chains for ``N`` and ``F``, each
once, relabelled canonically (:mod:`structure.canonical`) and named by the graph6
string of that labelling (:attr:`KinematicChain.code`).

Method: suppressing the binary links of a chain leaves its *contracted graph*, a
multigraph whose vertices have three or more pins, with the same cycle rank
``J - N + 1``. The contracted graphs of each rank are built by adding one ear (or a
loop on a stalk) to those of the rank below, each kept once by its canonical code;
the binary links are then distributed over their edges, once per orbit of the
contracted graph's automorphisms. Two chains are isomorphic exactly when their
contracted graphs and distributions correspond, so no chain is listed twice (each
code is checked all the same). Degenerate chains are recognised by the (3, 4)
pebble game on the pins counted twice (Lee and Streinu), in ``O(N^2)``.

References: T. S. Mruthyunjaya, "Kinematic structure of mechanisms revisited",
Mech. Mach. Theory 38 (2003); H.-S. Yan, Y.-T. Chiu, "On the number synthesis of
kinematic chains", Mech. Mach. Theory 89 (2015); A. Lee, I. Streinu, "Pebble game
algorithms and sparse graphs", Discrete Math. 308 (2008); OEIS A180923 (counts).

>>> [len(enumerate_chains(n)) for n in (4, 6, 8)]
[1, 2, 16]
>>> stephenson, watt = enumerate_chains(6)  # ternary links apart, ternary links jointed
>>> stephenson.code, stephenson.joints
('ELr?', ((0, 3), (0, 4), (0, 5), (1, 2), (1, 4), (1, 5), (2, 3)))
>>> watt.code, watt.joints
('Eie_', ((0, 1), (0, 4), (0, 5), (1, 2), (1, 3), (2, 5), (3, 4)))
"""

from __future__ import annotations

import itertools
import sys
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field

from .canonical import CanonicalForm, canonical_form, group_elements, orbits

__all__ = [
    "CHAIN_BYTES",
    "ChainCounts",
    "KinematicChain",
    "chain_from_code",
    "chain_from_joints",
    "count_chains",
    "enumerate_chains",
    "estimated_chains",
    "graph6",
    "is_degenerate",
    "joint_count",
]

Joint = tuple[int, int]


@dataclass(frozen=True, slots=True)
class KinematicChain:
    """A kinematic chain in canonical labelling.

    ``joints`` are ``(i, j)`` pairs of links ``0 .. links-1`` with ``i < j``, sorted;
    ``code`` is the graph6 string of that labelled graph, the same for every
    isomorphic chain; ``generators`` generate its automorphism group (permutations
    of the links; one generating set among many, so equality ignores them).
    """

    links: int
    joints: tuple[Joint, ...]
    code: str
    generators: tuple[tuple[int, ...], ...] = field(repr=False, compare=False)

    @property
    def dof(self) -> int:
        """``F = 3(N - 1) - 2J``."""
        return 3 * (self.links - 1) - 2 * len(self.joints)

    @property
    def degrees(self) -> tuple[int, ...]:
        """Number of pins on each link (2 binary, 3 ternary, ...)."""
        out = [0] * self.links
        for i, j in self.joints:
            out[i] += 1
            out[j] += 1
        return tuple(out)

    @property
    def degenerate(self) -> bool:
        """True when a subchain of two or more links is rigid (:func:`is_degenerate`)."""
        return is_degenerate(self.links, self.joints)

    @property
    def fractionated(self) -> bool:
        """True when removing one link disconnects the others (a cut vertex)."""
        return _has_cut_vertex(self.links, self.joints)

    @property
    def link_orbits(self) -> tuple[tuple[int, ...], ...]:
        """The links in classes of the chain's symmetry."""
        return orbits(self.links, self.generators)

    def neighbours(self, link: int) -> tuple[int, ...]:
        """Links jointed to ``link``, in order."""
        return tuple(sorted({j if i == link else i for i, j in self.joints if link in (i, j)}))

    def __repr__(self) -> str:
        return f"KinematicChain({self.code!r}, {self.links} links, {len(self.joints)} joints)"


def joint_count(links: int, dof: int) -> int:
    """Number of pins of an ``links``-link chain with ``dof`` degrees of freedom.

    Raises
    ------
    ValueError
        When ``3(links - 1) - dof`` is odd or the count is impossible.
    """
    twice = 3 * (links - 1) - dof
    if links < 2 or twice < links or twice % 2:
        raise ValueError(
            f"no chain of {links} links with F = {dof}: 3(N - 1) - F = {twice} must be "
            f"even and at least 2N (every link needs two pins)"
        )
    return twice // 2


def graph6(links: int, joints: Iterable[Joint]) -> str:
    """The graph6 string of a labelled graph (links up to 62), as nauty and networkx write it.

    >>> graph6(4, [(0, 1), (1, 2), (2, 3), (0, 3)])
    'Cl'
    """
    if links > 62:
        raise ValueError("graph6 here is for at most 62 links")
    edges = {(min(i, j), max(i, j)) for i, j in joints}
    bits = [1 if (i, j) in edges else 0 for j in range(1, links) for i in range(j)]
    bits.extend([0] * (-len(bits) % 6))
    chars = [chr(63 + links)]
    for k in range(0, len(bits), 6):
        value = 0
        for bit in bits[k : k + 6]:
            value = 2 * value + bit
        chars.append(chr(63 + value))
    return "".join(chars)


def _from_graph6(code: str) -> tuple[int, list[Joint]]:
    if not code or not 63 <= ord(code[0]) <= 63 + 62:
        raise ValueError(f"not a graph6 code of at most 62 links: {code!r}")
    links = ord(code[0]) - 63
    bits = []
    for char in code[1:]:
        value = ord(char) - 63
        if not 0 <= value < 64:
            raise ValueError(f"not a graph6 code: {code!r}")
        bits.extend((value >> shift) & 1 for shift in range(5, -1, -1))
    pairs = [(i, j) for j in range(1, links) for i in range(j)]
    if len(bits) < len(pairs) or len(bits) - len(pairs) >= 6:
        raise ValueError(f"graph6 code {code!r} has the wrong length for {links} links")
    return links, [pair for pair, bit in zip(pairs, bits, strict=False) if bit]


def _adjacency(links: int, joints: Iterable[Joint]) -> list[dict[int, int]]:
    adjacency: list[dict[int, int]] = [{} for _ in range(links)]
    for i, j in joints:
        adjacency[i][j] = adjacency[i].get(j, 0) + 1
        adjacency[j][i] = adjacency[j].get(i, 0) + 1
    return adjacency


def chain_from_joints(joints: Iterable[Joint], links: int | None = None) -> KinematicChain:
    """The chain of these pins, relabelled canonically.

    Raises
    ------
    ValueError
        Two pins between the same two links, a link pinned to itself, or a link
        number outside ``0 .. links-1``.

    >>> chain_from_joints([(0, 1), (1, 2), (2, 3), (3, 0)]).code
    'C]'
    """
    joints = [(int(i), int(j)) for i, j in joints]
    if links is None:
        links = 1 + max((max(i, j) for i, j in joints), default=-1)
    seen: set[Joint] = set()
    for i, j in joints:
        key = (min(i, j), max(i, j))
        if i == j or key in seen or not (0 <= i < links and 0 <= j < links):
            raise ValueError(f"pin {i}-{j}: a chain has simple pins between distinct links")
        seen.add(key)
    return _canonical_chain(links, joints)


def _canonical_chain(links: int, joints: Sequence[Joint]) -> KinematicChain:
    form: CanonicalForm = canonical_form(links, _adjacency(links, joints))
    position = form.position
    relabelled = tuple(
        sorted((min(position[i], position[j]), max(position[i], position[j])) for i, j in joints)
    )
    generators = tuple(
        tuple(position[g[form.order[p]]] for p in range(links)) for g in form.generators
    )
    return KinematicChain(links, relabelled, graph6(links, relabelled), generators)


def chain_from_code(code: str) -> KinematicChain:
    """The chain of a graph6 code (any labelling; the result is canonical).

    >>> chain_from_code('Cl').joints
    ((0, 2), (0, 3), (1, 2), (1, 3))
    """
    links, joints = _from_graph6(code.strip())
    return _canonical_chain(links, joints)


# --------------------------------------------------------------------------- degeneracy
def is_degenerate(links: int, joints: Sequence[Joint]) -> bool:
    """True when some ``S`` of two or more links has ``3(|S| - 1) - 2 e(S) <= 0``.

    Such a subchain is rigid (a structure) or over-constrained, so the chain is
    degenerate. Equivalently, the graph with every pin counted twice is not
    (3, 4)-sparse; the (3, 4) pebble game decides it.

    >>> is_degenerate(4, [(0, 1), (1, 2), (2, 0), (2, 3)])  # a triangle
    True
    >>> is_degenerate(4, [(0, 1), (1, 2), (2, 3), (3, 0)])
    False
    """
    pebbles = [3] * links
    out: list[list[int]] = [[] for _ in range(links)]
    for i, j in joints:
        for _ in range(2):
            if not _gather(i, j, pebbles, out):
                return True
            if pebbles[i]:
                pebbles[i] -= 1
                out[i].append(j)
            else:
                pebbles[j] -= 1
                out[j].append(i)
    return False


def _gather(a: int, b: int, pebbles: list[int], out: list[list[int]]) -> bool:
    """Bring five free pebbles onto ``a`` and ``b`` (pebble game, l + 1 = 5), if possible."""
    while pebbles[a] + pebbles[b] < 5:
        if not (_fetch(a, b, pebbles, out) or _fetch(b, a, pebbles, out)):
            return False
    return True


def _fetch(start: int, other: int, pebbles: list[int], out: list[list[int]]) -> bool:
    """Move one free pebble to ``start`` along a directed path, reversing it."""
    came: dict[int, tuple[int, int]] = {}
    stack = [start]
    seen = {start, other}
    while stack:
        v = stack.pop()
        for k, u in enumerate(out[v]):
            if u in seen:
                continue
            seen.add(u)
            came[u] = (v, k)
            if pebbles[u]:
                pebbles[u] -= 1
                pebbles[start] += 1
                while u != start:
                    v, k = came[u]
                    out[v][k] = out[v][-1]
                    out[v].pop()
                    out[u].append(v)
                    u = v
                return True
            stack.append(u)
    return False


def _has_cut_vertex(links: int, joints: Sequence[Joint]) -> bool:
    adjacency = _adjacency(links, joints)
    for cut in range(links):
        start = 0 if cut else 1
        seen = {cut, start}
        stack = [start]
        while stack:
            v = stack.pop()
            for u in adjacency[v]:
                if u not in seen:
                    seen.add(u)
                    stack.append(u)
        if len(seen) < links:
            return True
    return False


# --------------------------------------------------------------------- contracted graphs
@dataclass(frozen=True, slots=True)
class _Contracted:
    """A contracted graph: vertices of three or more pins, edges with repeats and loops."""

    vertices: int
    edges: tuple[Joint, ...]  # (u, v) with u <= v; u == v is a loop


def _contracted_code(vertices: int, edges: Sequence[Joint]) -> tuple:
    return canonical_form(vertices, _adjacency_loops(vertices, edges)).code


def _adjacency_loops(vertices: int, edges: Iterable[Joint]) -> list[dict[int, int]]:
    adjacency: list[dict[int, int]] = [{} for _ in range(vertices)]
    for u, v in edges:
        adjacency[u][v] = adjacency[u].get(v, 0) + 1
        if u != v:
            adjacency[v][u] = adjacency[v].get(u, 0) + 1
    return adjacency


def _ears(graph: _Contracted, loops: bool) -> Iterator[tuple[int, list[Joint]]]:
    """Every graph of rank one more: an ear between two points, or a loop on a stalk.

    A point is a vertex or a new vertex on an edge. ``graph.vertices == 0`` is the
    plain cycle (rank 1), which has one kind of point.
    """
    n, edges = graph.vertices, list(graph.edges)
    if n == 0:
        yield 2, [(0, 1)] * 3  # theta
        if loops:
            yield 1, [(0, 0), (0, 0)]  # figure eight
            yield 2, [(0, 0), (0, 1), (1, 1)]  # dumbbell
        return
    points: list[tuple[str, int]] = [("v", v) for v in range(n)]
    points += [("e", k) for k in range(len(edges))]
    for first, second in itertools.combinations_with_replacement(points, 2):
        if first == second and first[0] == "v" and not loops:
            continue
        for same_point in (False, True) if first == second and first[0] == "e" else (False,):
            if same_point and not loops:
                continue
            yield _with_ear(n, edges, first, second, same_point)
    if loops:
        for point in points:
            count, new_edges, attach = _with_point(n, edges, point)
            yield count + 1, [*new_edges, (attach, count), (count, count)]


def _with_point(n: int, edges: list[Joint], point: tuple[str, int]) -> tuple[int, list, int]:
    """The graph with ``point`` made a vertex: its vertex count, edges and the vertex."""
    kind, index = point
    if kind == "v":
        return n, edges, index
    u, v = edges[index]
    rest = edges[:index] + edges[index + 1 :]
    return n + 1, [*rest, (u, n), (v, n)], n


def _with_ear(
    n: int, edges: list[Joint], first: tuple[str, int], second: tuple[str, int], same: bool
) -> tuple[int, list[Joint]]:
    if first == second and first[0] == "e":
        u, v = edges[first[1]]
        rest = edges[: first[1]] + edges[first[1] + 1 :]
        if same:  # a loop on a new vertex of the edge
            return n + 1, [*rest, (u, n), (v, n), (n, n)]
        # two new vertices on the edge, joined again by the ear
        return n + 2, [*rest, (u, n), (n, n + 1), (n, n + 1), (v, n + 1)]
    count, new_edges, a = _with_point(n, edges, first)
    if second[0] == "e" and first[0] == "e" and second[1] > first[1]:
        second = ("e", second[1] - 1)  # the first edge left the list
    count, new_edges, b = _with_point(count, new_edges, second)
    return count, [*new_edges, (min(a, b), max(a, b))]


def _contracted_graphs(rank: int, loops: bool) -> list[_Contracted]:
    """The contracted graphs of a cycle rank (2-connected ones when ``loops`` is False)."""
    level = [_Contracted(0, ())]
    for _ in range(rank - 1):
        found: dict[tuple, _Contracted] = {}
        for graph in level:
            for vertices, edges in _ears(graph, loops):
                edges = [(min(u, v), max(u, v)) for u, v in edges]
                code = _contracted_code(vertices, edges)
                if code not in found:
                    found[code] = _Contracted(vertices, tuple(sorted(edges)))
        level = list(found.values())
    return level


# ------------------------------------------------------------------------------ chains
def _slots(graph: _Contracted) -> list[tuple[Joint, int]]:
    """The distinct edges of a contracted graph with their multiplicities."""
    counts: dict[Joint, int] = {}
    for edge in graph.edges:
        counts[edge] = counts.get(edge, 0) + 1
    return sorted(counts.items())


def _slot_fillings(edge: Joint, multiplicity: int, total: int) -> list[tuple[int, ...]]:
    """Binary links on parallel edges: non-increasing counts, at most one edge bare, loops >= 2."""
    low = 2 if edge[0] == edge[1] else 0
    out = []
    for counts in itertools.combinations_with_replacement(range(total, low - 1, -1), multiplicity):
        if sum(counts) <= total and (low or counts[-2:] != (0, 0) or multiplicity == 1):
            out.append(counts)
    return out


def _distributions(graph: _Contracted, binaries: int) -> Iterator[list[tuple[int, ...]]]:
    """Ways to put ``binaries`` links on the edges, one per orbit of the graph's symmetry."""
    slots = _slots(graph)
    index = {edge: k for k, (edge, _) in enumerate(slots)}
    form = canonical_form(graph.vertices, _adjacency_loops(graph.vertices, graph.edges))
    images = []
    for g in group_elements(graph.vertices, form.generators)[1:]:
        images.append([index[(min(g[u], g[v]), max(g[u], g[v]))] for (u, v), _ in slots])
    choices = [_slot_fillings(edge, m, binaries) for edge, m in slots]

    def fill(k: int, left: int, chosen: list[tuple[int, ...]]) -> Iterator[list]:
        if k == len(slots):
            if left == 0 and all(
                [chosen[image[s]] for s in range(len(slots))] <= chosen for image in images
            ):
                yield list(chosen)
            return
        for counts in choices[k]:
            used = sum(counts)
            if used <= left:
                chosen.append(counts)
                yield from fill(k + 1, left - used, chosen)
                chosen.pop()

    yield from fill(0, binaries, [])


def _chain_joints(graph: _Contracted, slots: list, filling: list) -> list[Joint]:
    joints: list[Joint] = []
    nxt = graph.vertices
    for ((u, v), _), counts in zip(slots, filling, strict=True):
        for count in counts:
            path = [u, *range(nxt, nxt + count), v]
            nxt += count
            joints.extend(itertools.pairwise(path))
    return joints


def _candidate_chains(links: int, joints: int, loops: bool) -> Iterator[list[Joint]]:
    rank = joints - links + 1
    if rank == 1:
        yield [(k, (k + 1) % links) for k in range(links)]
        return
    for graph in _contracted_graphs(rank, loops):
        binaries = links - graph.vertices
        if binaries < 0:
            continue
        slots = _slots(graph)
        for filling in _distributions(graph, binaries):
            yield _chain_joints(graph, slots, filling)


def enumerate_chains(
    links: int, dof: int = 1, *, degenerate: bool = False, fractionated: bool = True
) -> tuple[KinematicChain, ...]:
    """The non-isomorphic chains of ``links`` links with ``dof`` degrees of freedom.

    Parameters
    ----------
    links : int
    dof : int
        ``F = 3(N - 1) - 2J``, so the chain has ``(3(N - 1) - F) / 2`` pins.
    degenerate : bool
        Keep the chains with a rigid subchain (left out by default).
    fractionated : bool
        Keep the chains that one link cuts in two (kept by default; for ``F = 1``
        no non-degenerate chain is fractionated).

    Returns
    -------
    tuple of KinematicChain
        Sorted by code.

    Raises
    ------
    ValueError
        No chain has that many links and degrees of freedom.
    """
    joints = joint_count(links, dof)
    loops = fractionated and (degenerate or dof > 1)
    found: dict[str, KinematicChain] = {}
    for candidate in _candidate_chains(links, joints, loops):
        if not degenerate and is_degenerate(links, candidate):
            continue
        if not fractionated and _has_cut_vertex(links, candidate):
            continue
        chain = _canonical_chain(links, candidate)
        if chain.code in found:
            raise AssertionError(f"chain {chain.code} generated twice")  # pragma: no cover
        found[chain.code] = chain
    return tuple(found[code] for code in sorted(found))


@dataclass(frozen=True, slots=True)
class ChainCounts:
    """How many chains a link count and DOF have.

    ``chains`` are the non-degenerate ones (the atlas), ``fractionated`` how many of
    them one link cuts in two; ``degenerate`` the chains with a rigid subchain,
    ``degenerate_fractionated`` how many of those have a cut link too;
    ``inversions`` the choices of ground link on the non-degenerate chains, up to
    their symmetry. ``kept`` and ``kept_inversions`` are the chains (and their
    inversions) that :func:`enumerate_chains` gives with the same ``degenerate`` and
    ``fractionated``: what an atlas run of those options classifies.
    """

    links: int
    dof: int
    chains: int
    fractionated: int
    degenerate: int
    degenerate_fractionated: int
    inversions: int
    kept: int = -1
    kept_inversions: int = -1


def count_chains(
    links: int, dof: int = 1, *, degenerate: bool = False, fractionated: bool = True
) -> ChainCounts:
    """Count the chains of ``links`` links and ``dof`` degrees of freedom, by kind.

    ``degenerate`` and ``fractionated`` choose, as for :func:`enumerate_chains`,
    the chains counted in ``kept`` and ``kept_inversions``.

    pyslvs's atlas has no chain with a cut link: its 40 eight-link chains are the
    16 non-degenerate ones and the 24 degenerate ones without a cut link.

    >>> c = count_chains(8)
    >>> c.chains, c.degenerate, c.degenerate_fractionated
    (16, 55, 31)
    >>> count_chains(8, degenerate=True, fractionated=False).kept
    40
    """
    joints = joint_count(links, dof)
    tally = {(bad, cut): 0 for bad in (False, True) for cut in (False, True)}
    inversions = kept = kept_inversions = 0
    for candidate in _candidate_chains(links, joints, True):
        key = (is_degenerate(links, candidate), _has_cut_vertex(links, candidate))
        tally[key] += 1
        keep = (degenerate or not key[0]) and (fractionated or not key[1])
        if not key[0] or keep:
            orbits = len(_canonical_chain(links, candidate).link_orbits)
            inversions += orbits if not key[0] else 0
            kept_inversions += orbits if keep else 0
        kept += keep
    return ChainCounts(
        links,
        dof,
        tally[False, False] + tally[False, True],
        tally[False, True],
        tally[True, False] + tally[True, True],
        tally[True, True],
        inversions,
        kept,
        kept_inversions,
    )


#: memory one chain takes while the chains of a link count are enumerated and held
#: (measured: 1.47 kB a chain at 12 links, with or without the degenerate ones; 14 links,
#: 318,162 chains in 0.6 GB, 1.9 kB)
CHAIN_BYTES = 2000

#: how many times more chains each two more links bring (measured from 10 to 12 links and
#: from 11 to 13: 25 to 35 times the non-degenerate chains, 42 to 50 times the degenerate)
_GROWTH = 50
#: the degenerate chains per non-degenerate one, at most (12 links, F = 1: 72,908 for 6,856)
_DEGENERATE_RATIO = 11


def estimated_chains(links: int, dof: int = 1, *, degenerate: bool = False) -> int:
    """About how many chains :func:`enumerate_chains` gives: an estimate to bound a run by.

    The chains grow about :data:`_GROWTH` times for every three more pins (two more
    links at the same DOF), from the 6,856 chains of 16 pins (12 links, F = 1); the
    count depends on the pins much more than on the DOF (F = 2, 13 links, 17 pins:
    29,685; F = 4, 13 links, 16 pins: 5,915).

    >>> estimated_chains(14), count_chains(10).chains, estimated_chains(10)
    (342800, 230, 137)
    """
    joints = joint_count(links, dof)
    factor = 1 + (_DEGENERATE_RATIO if degenerate else 0)
    try:
        return max(1, round(6856 * _GROWTH ** ((joints - 16) / 3) * factor))
    except OverflowError:  # beyond any machine: as many as a count can say
        return sys.maxsize
