"""Rank of a constraint system: which constraints are redundant, how much freedom is left.

Two questions, one engine:

* **generic** (topology only): rows are matched to unknowns in file order
  (:class:`~structure.rigidity.matching.Matcher`); a row left unmatched is
  structurally redundant. Free unknowns get probe rows, which makes the system
  square; it is then split into irreducible blocks and every block's
  determinant is checked at a random realization. When all blocks are regular
  the matching *is* the generic rank (block-triangular with regular diagonal
  blocks). A singular block means a hidden dependency (a floating
  over-constrained subassembly, a loop of prismatic pairs); then a dense
  rank-revealing pass at the random realization names it.
* **geometric** (the sketch pose): the same dense pass at the file's
  coordinates finds redundancy that only the dimensions create (a
  parallelogram with a third parallel crank).

The dense pass keeps rows greedily in order (pairs in file order, then
drivers), so the constraint reported as redundant is the latest listed one of
its dependent set.
"""

from __future__ import annotations

import itertools
import math
from array import array
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

from ..errors import MechanismError
from ..utils import int_array
from .constraints import (
    ROW_CODE,
    ConstraintSystem,
    Realization,
    RowKind,
    jacobian,
    random_realization,
    row_entries,
)
from .matching import (
    NUMPY_ROWS,
    Assignment,
    FlatRows,
    Matcher,
    block_arrays,
    flat_rows,
    irreducible_blocks,
)

__all__ = [
    "DENSE_LIMIT",
    "RankAnalysis",
    "dimensionless_jacobian",
    "generic_rank",
    "geometric_rank",
    "null_space",
    "singular_blocks",
    "sketch_scale",
]

#: largest number of scalar unknowns for the dense (rank-revealing) pass
DENSE_LIMIT = 6000
_RANK_TOL = 1e-8


@dataclass(frozen=True)
class RankAnalysis:
    """What the rank of a (driven) constraint system says.

    Attributes
    ----------
    system : ConstraintSystem
        The system analysed, pair rows then driver rows.
    dependent : dict
        Row block -> number of its scalar rows that depend on earlier rows.
    rank : int
        Rank of the pair rows alone.
    dof : int
        Scalar unknowns minus ``rank``: the mobility before passive motions.
    free : list of (int, int)
        Unknown blocks (and units) that the pairs and drivers leave free.
    blocks : sequence of sequences of int, or None
        Irreducible blocks of the driven system in solve order (each sorted;
        a large system's held flat, see :class:`~structure.utils.Ragged`), when it is
        square and regular (the usual case); ``None`` otherwise.
    assigned : list of tuple of int
        The matching behind ``blocks``: the unknown blocks each row is matched
        to (one entry per unit; tuples, which cost half a list's memory).
    method : str
        ``'structural'`` (matching + block determinants) or ``'dense'``.
    near_sketch : bool
        A dense analysis made at a regular pose near the sketch, because the
        sketch itself is a singular pose (its rank drops there; see
        :func:`~structure.rigidity.regularity.regular_rank`).
    """

    system: ConstraintSystem
    dependent: dict[int, int]
    rank: int
    dof: int
    free: list[tuple[int, int]]
    blocks: Sequence[Sequence[int]] | None
    assigned: Sequence[Sequence[int]] = field(repr=False)
    method: str
    near_sketch: bool = False

    @property
    def n_dependent(self) -> int:
        """How many scalar rows (pairs' and drivers') depend on earlier rows."""
        return sum(self.dependent.values())

    @property
    def dependent_pairs(self) -> dict[int, int]:
        """Pair id -> number of its scalar constraints that are redundant."""
        out: dict[int, int] = {}
        for r, k in self.dependent.items():
            if r < self.system.n_pair_rows:
                pid = self.system.row_pair[r]
                out[pid] = out.get(pid, 0) + k
        return out

    @property
    def dependent_drivers(self) -> list[str]:
        return [self.system.row_link[r] for r in self.dependent if r >= self.system.n_pair_rows]


def _match(system: ConstraintSystem) -> tuple[Matcher, dict[int, int]]:
    matcher = Matcher(system.unknown_sizes())
    unmatched = matcher.add_rows(system.adj_start, system.adj, system.row_size)
    return matcher, unmatched


def _probe_system(system: ConstraintSystem, free: list[tuple[int, int]]) -> ConstraintSystem:
    if not free:  # the usual case: nothing to probe, and no copy of a large system
        return system
    return system.with_rows(
        [RowKind.PROBE] * len(free), [k for _, k in free], [(u,) for u, _ in free], [""] * len(free)
    )


def _singular_blocks(
    system: ConstraintSystem,
    blocks: list[list[int]],
    assigned: Sequence[Sequence[int]],
    seed: int,
    which: Sequence[int] | None = None,
    flat: FlatRows | None = None,
) -> list[int]:
    """Indices of the irreducible blocks whose square Jacobian is numerically singular.

    The Jacobians are those at the random realization of ``seed``, drawn only
    when some block has to be evaluated.

    The blocks' singular values are computed in one batched call
    (:func:`_singular_ratios`). Generic regularity depends only on a block's
    pattern, so when all blocks are checked (``which`` None) each pattern is
    evaluated once: mechanisms repeat a few group shapes many times. A
    pattern once found regular is regular for good (a polynomial that is
    nonzero at one point is not identically zero), so it is remembered across
    calls (:data:`_REGULAR_PATTERNS`); singular verdicts are never remembered,
    since a random pose may be near-singular by chance and is checked again.
    ``flat`` holds the rows as flat arrays (a large system): the blocks are
    then sorted by pattern with numpy (:func:`_singular_blocks_by_pattern`).
    """
    offsets, _ = system.scalar_offsets()
    uo = int_array(offsets, "q")
    if flat is not None:
        layout = _BlockLayout.of(system, blocks, flat)
        rows_of = layout.rows_of
        if which is None:
            return _singular_blocks_by_pattern(system, blocks, assigned, seed, layout, uo)
    else:
        rows_of = _rows_of_blocks(system, blocks, assigned)
    representative: dict[tuple, int] = {}
    judged: list[tuple[int, Sequence[int], Sequence[int]]] = []
    for b in range(len(blocks)) if which is None else which:
        units = blocks[b]
        rows = rows_of(b)
        if _trivially_regular(system, units, rows):
            continue
        if which is None:
            pattern = _block_pattern(system, units, rows, assigned)
            if pattern in _REGULAR_PATTERNS or representative.setdefault(pattern, b) != b:
                continue  # a repeat is judged with its pattern's first block, below
        judged.append((b, units, rows))
    bad = _judge(system, assigned, seed, uo, judged)
    if which is None:
        singular = set(bad)
        if singular:  # rare: the repeats of a singular pattern's first block are singular too
            bad.extend(_repeats_of(system, blocks, assigned, rows_of, representative, singular))
        _remember_regular(pattern for pattern, b in representative.items() if b not in singular)
    return sorted(bad)


@dataclass(frozen=True, slots=True)
class _BlockLayout:
    """A large system's blocks as flat arrays: their units, their rows, each row's pattern code.

    ``units[unit_start[b]:unit_start[b + 1]]`` are block ``b``'s unknowns and
    ``rows[row_start[b]:row_start[b + 1]]`` the rows matched into it, in
    order; ``codes[k]`` describes row ``rows[k]`` as :func:`_block_pattern`
    does (kind, units matched, the local number of each unknown it touches,
    its shared point's local number), as integers.
    """

    units: np.ndarray
    unit_start: np.ndarray
    rows: np.ndarray
    row_start: np.ndarray
    codes: np.ndarray

    @classmethod
    def of(cls, system: ConstraintSystem, blocks: list[list[int]], flat: FlatRows) -> _BlockLayout:
        n_blocks = len(blocks)
        units, unit_start = block_arrays(blocks)
        unit_count = np.diff(unit_start)
        block_of = np.empty(system.n_unknowns, dtype=np.int32)
        block_of[units] = np.repeat(np.arange(n_blocks), unit_count)
        local = np.empty(system.n_unknowns, dtype=np.int32)
        local[units] = np.arange(len(units)) - np.repeat(unit_start[:-1], unit_count)
        # every unit of a row lies in one block: its first unit's tells
        first = np.flatnonzero(np.r_[True, flat.unit_row[1:] != flat.unit_row[:-1]])
        matched_rows = flat.unit_row[first]
        row_block = block_of[flat.units[first]]
        order = np.argsort(row_block, kind="stable")
        rows, row_block = matched_rows[order], row_block[order]
        row_start = np.searchsorted(row_block, np.arange(n_blocks + 1))
        codes = _row_codes(system, flat, rows, row_block, block_of, local)
        return cls(units, unit_start, rows, row_start, codes)

    def rows_of(self, b: int) -> Sequence[int]:
        return self.rows[self.row_start[b] : self.row_start[b + 1]].tolist()


def _row_codes(
    system: ConstraintSystem,
    flat: FlatRows,
    rows: np.ndarray,
    row_block: np.ndarray,
    block_of: np.ndarray,
    local: np.ndarray,
) -> np.ndarray:
    """One line of integers per row (in block order) that :func:`_block_pattern` tells apart.

    Kind, units matched, the local number of each unknown touched (-1 in
    another block, -2 past the row's end) and the local number of its
    shared point (pin or P pair), counted in order of first use in the block.
    """
    kind = system.row_codes()
    begin, end = flat.adj_start[rows], flat.adj_start[rows + 1]
    width = int((end - begin).max(initial=0))
    touched = np.full((len(rows), width), -2, dtype=np.int32)
    for k in range(width):
        has = begin + k < end
        u = flat.adj[begin[has] + k]
        touched[has, k] = np.where(block_of[u] == row_block[has], local[u], -1)
    shared = _shared_numbers(system, rows, row_block, kind)
    return np.column_stack([kind[rows], flat.matched[rows], touched, shared]).astype(np.int32)


def _shared_numbers(
    system: ConstraintSystem, rows: np.ndarray, row_block: np.ndarray, kind: np.ndarray
) -> np.ndarray:
    """Each row's shared point (a pin, or its pair) numbered in order of first use in its block."""
    pair = np.frombuffer(system.row_pair, dtype=np.int32)[rows].astype(np.int64)
    key = 2 * pair + 1
    pins = np.flatnonzero(kind[rows] == ROW_CODE[RowKind.PIN])
    if len(pins):
        point_of = system.mechanism.pair
        names = [point_of(pid).point for pid in pair[pins].tolist()]
        number = {name: k for k, name in enumerate(dict.fromkeys(names))}
        key[pins] = 2 * np.array([number[name] for name in names], dtype=np.int64)
    position = np.arange(len(rows))
    by_key = np.lexsort((position, key, row_block))
    new = np.r_[True, (row_block[by_key][1:] != row_block[by_key][:-1])
                | (key[by_key][1:] != key[by_key][:-1])]  # fmt: skip
    first_use = np.empty(len(rows), dtype=np.int64)
    first_use[by_key] = np.maximum.accumulate(np.where(new, position[by_key], 0))
    # a block's first uses, in row order, are numbered 0, 1, ...
    is_first = first_use == position
    before = np.cumsum(is_first) - is_first
    block_first = np.searchsorted(row_block, row_block)  # each row's block's first row
    return before[first_use] - before[block_first]


def _singular_blocks_by_pattern(
    system: ConstraintSystem,
    blocks: list[list[int]],
    assigned: Sequence[Sequence[int]],
    seed: int,
    layout: _BlockLayout,
    uo: Sequence[int],
) -> list[int]:
    """:func:`_singular_blocks` of every block, the patterns told apart by numpy.

    Blocks of one size (units, rows) are stacked as lines of integers (unit
    sizes, then each row's code) and sorted once; each distinct line is a
    pattern, judged with its first block as the plain path does.
    """
    sizes = np.array(system.unknown_sizes(), dtype=np.int64)
    n_units = np.diff(layout.unit_start)
    n_rows = np.diff(layout.row_start)
    trivial = (n_units == 1) & (n_rows == 1)
    trivial[trivial] = np.isin(
        layout.codes[layout.row_start[:-1][trivial], 0],
        [ROW_CODE[RowKind.DRIVER], ROW_CODE[RowKind.PROBE]],
    )
    pattern_of = np.full(len(blocks), -1, dtype=np.int64)
    firsts: list[int] = []
    for nu, nr in sorted(
        set(zip(n_units[~trivial].tolist(), n_rows[~trivial].tolist(), strict=True))
    ):
        members = np.flatnonzero((n_units == nu) & (n_rows == nr) & ~trivial)
        lines = np.hstack([
            sizes[layout.units[layout.unit_start[members, None] + np.arange(nu)]],
            layout.codes[layout.row_start[members, None] + np.arange(nr)].reshape(len(members), -1),
        ])  # fmt: skip
        first, inverse = _distinct_lines(lines)
        pattern_of[members] = len(firsts) + inverse
        firsts.extend(members[first].tolist())
    representative: dict[tuple, int] = {}
    judged: list[tuple[int, Sequence[int], Sequence[int]]] = []
    for b in sorted(firsts):
        units, rows = blocks[b], layout.rows_of(b)
        pattern = _block_pattern(system, units, rows, assigned)
        if pattern not in _REGULAR_PATTERNS:
            representative[pattern] = b
            judged.append((b, units, rows))
    bad = _judge(system, assigned, seed, uo, judged)
    singular = set(bad)
    if singular:  # every block of a singular pattern is singular
        hit = np.isin(pattern_of, pattern_of[sorted(singular)])
        bad = np.flatnonzero(hit).tolist()
    _remember_regular(pattern for pattern, b in representative.items() if b not in singular)
    return sorted(bad)


def _judge(
    system: ConstraintSystem,
    assigned: Sequence[Sequence[int]],
    seed: int,
    uo: Sequence[int],
    blocks: Sequence[tuple[int, Sequence[int], Sequence[int]]],
) -> list[int]:
    """Which of ``blocks`` (index, units, rows) are singular at the random realization of ``seed``.

    A block whose rows do not fill its square matrix is singular; the others
    are judged by their singular values, all in one batched call.
    """
    if not blocks:
        return []
    realization = random_realization(system, seed)
    bad: list[int] = []
    evaluated: list[tuple[int, list[list[float]]]] = []
    for b, units, rows in blocks:
        a = _block_matrix(system, realization, units, rows, assigned, uo)
        if a is None:
            bad.append(b)
        else:
            evaluated.append((b, a))
    if evaluated:
        ratios = _singular_ratios([a for _, a in evaluated]).tolist()
        bad.extend(b for (b, _), x in zip(evaluated, ratios, strict=True) if x <= _RANK_TOL)
    return bad


def _distinct_lines(lines: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The first index of each distinct line of ``lines``, and each line's distinct number.

    The lines are told apart by a 64-bit hash first (sorting one column is
    far cheaper than sorting whole lines); the grouping is then checked line
    by line, and any collision sends the lines to an exact sort.
    """
    weights = np.random.default_rng(len(lines[0])).integers(1, 2**63, len(lines[0]), np.uint64)
    with np.errstate(over="ignore"):
        hashed = (lines.astype(np.uint64) * weights).sum(axis=1, dtype=np.uint64)
    _, first, inverse = np.unique(hashed, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    if not np.array_equal(lines, lines[first[inverse]]):
        _, first, inverse = np.unique(lines, axis=0, return_index=True, return_inverse=True)
        inverse = inverse.reshape(-1)
    return first, inverse


def _trivially_regular(system: ConstraintSystem, units: Sequence[int], rows: Sequence[int]) -> bool:
    """A single driver/probe row on one block: regular by construction."""
    return len(units) == 1 and len(rows) == 1 and system.row_kind[rows[0]] in _TRIVIAL


_TRIVIAL = (RowKind.DRIVER, RowKind.PROBE)


def _repeats_of(
    system: ConstraintSystem,
    blocks: list[list[int]],
    assigned: Sequence[Sequence[int]],
    rows_of: Callable[[int], Sequence[int]],
    representative: dict[tuple, int],
    singular: set[int],
) -> list[int]:
    """The blocks (in order) whose pattern's first block is in ``singular``, other than it.

    The patterns are computed again rather than remembered for every block:
    a large mechanism has hundreds of thousands of blocks, and a singular
    pattern is rare.
    """
    out: list[int] = []
    for b, units in enumerate(blocks):
        rows = rows_of(b)
        if _trivially_regular(system, units, rows):
            continue
        first = representative.get(_block_pattern(system, units, rows, assigned))
        if first is not None and first != b and first in singular:
            out.append(b)
    return out


#: block patterns found regular at a random realization (see :func:`_singular_blocks`)
_REGULAR_PATTERNS: dict[tuple, None] = {}
#: patterns remembered at most (the oldest are forgotten first)
_REGULAR_PATTERNS_LIMIT = 1 << 14


def _remember_regular(patterns: Iterable[tuple]) -> None:
    for pattern in patterns:
        _REGULAR_PATTERNS[pattern] = None
    while len(_REGULAR_PATTERNS) > _REGULAR_PATTERNS_LIMIT:
        del _REGULAR_PATTERNS[next(iter(_REGULAR_PATTERNS))]


def _singular_ratios(matrices: Sequence[list[list[float]]]) -> np.ndarray:
    """Smallest over largest singular value (at least 1) of each square matrix.

    The matrices are stacked, each padded to the largest size with an identity
    block, for a single batched SVD: the padding adds singular values 1, which
    leaves the ratio unchanged whenever it is below 1 (the only place where
    it is compared with the rank tolerance).
    """
    size = max(len(a) for a in matrices)
    stack = np.zeros((len(matrices), size, size))
    stack[:, range(size), range(size)] = 1.0
    for k, a in enumerate(matrices):
        stack[k, : len(a), : len(a)] = a
    s = np.linalg.svd(stack, compute_uv=False)
    return s[:, -1] / np.maximum(1.0, s[:, 0])


def _rows_of_blocks(
    system: ConstraintSystem, blocks: list[list[int]], assigned: Sequence[Sequence[int]]
) -> Callable[[int], Sequence[int]]:
    """The rows matched into each block, in order: ``rows_of(b)`` for block ``b``.

    Held as two flat integer arrays (each block's rows are a slice of one),
    not a list per block: a large mechanism has hundreds of thousands of blocks.
    """
    block_of = array("i", [0]) * system.n_unknowns
    for b, units in enumerate(blocks):
        for u in units:
            block_of[u] = b
    # a counting sort of the matched rows by block, stable in row order
    start = array("i", [0]) * (len(blocks) + 1)
    row_block = array("i", [-1]) * len(assigned)
    for r, units in enumerate(assigned):
        if units:
            b = row_block[r] = block_of[units[0]]
            start[b + 1] += 1
    del block_of
    for b in range(len(blocks)):
        start[b + 1] += start[b]
    fill = start[:-1]
    flat = array("i", [0]) * start[-1]
    for r, b in enumerate(row_block):
        if b >= 0:
            flat[fill[b]] = r
            fill[b] += 1
    del fill, row_block

    def rows_of(b: int) -> Sequence[int]:
        return flat[start[b] : start[b + 1]]

    return rows_of


def _block_pattern(
    system: ConstraintSystem,
    units: list[int],
    rows: Sequence[int],
    assigned: Sequence[Sequence[int]],
) -> tuple:
    """What a block's regularity depends on: sizes, row kinds, local incidences, shared points."""
    local = {u: i for i, u in enumerate(units)}
    shared: dict[tuple[int, object], int] = {}
    row_kind, row_pair, adj, start = system.row_kind, system.row_pair, system.adj, system.adj_start
    pin_kind = RowKind.PIN  # a local: enum attribute lookups are slow in the loop below
    pattern = tuple(
        (
            row_kind[r],
            len(assigned[r]),
            tuple(local.get(u, -1) for u in adj[start[r] : start[r + 1]]),
            # rows that share a point (one pin, one P pair) share it in the pattern
            shared.setdefault(
                (0, system.mechanism.pair(row_pair[r]).point)
                if row_kind[r] is pin_kind
                else (1, row_pair[r]),
                len(shared),
            ),
        )
        for r in rows
    )
    return (tuple(map(system.unknown_size, units)), pattern)


def _block_matrix(
    system: ConstraintSystem,
    realization: Realization,
    units: list[int],
    rows: Sequence[int],
    assigned: Sequence[Sequence[int]],
    uo: Sequence[int],
) -> list[list[float]] | None:
    """The block's square Jacobian at ``realization``, or None when its rows do not fill it."""
    cols: dict[int, int] = {}
    for u in units:
        for k in range(system.unknown_size(u)):
            cols[uo[u] + k] = len(cols)
    size = len(cols)
    a = [[0.0] * size for _ in range(size)]
    i = 0
    for r in rows:
        matched = len(assigned[r])
        whole = matched == system.row_size[r]
        if i + matched > size:
            break
        for lr, col, value in row_entries(system, realization, r, uo):
            j = cols.get(col)
            if j is not None:
                # a half-matched row block stands for one generic combination of its rows
                if whole:
                    a[i + lr][j] += value
                else:
                    a[i][j] += (1.0, 0.61)[lr] * value
        i += matched
    return a if i == size else None


def generic_rank(system: ConstraintSystem, seed: int = 20261121) -> RankAnalysis:
    """Generic rank analysis of ``system`` (pair rows, then driver rows).

    >>> from structure import Mechanism
    >>> from structure.rigidity import constraint_system
    >>> m = Mechanism.from_pairs([("0", "1", "R", "O"), ("1", "2", "R", "p"),
    ...                           ("1", "2", "R", "q")])          # a double pin
    >>> g = generic_rank(constraint_system(m, ["1"]))
    >>> g.dof, g.dependent_pairs
    (1, {3: 1})
    """
    matcher, unmatched = _match(system)
    free = matcher.free_units
    units = matcher.assigned.units
    del matcher  # the matching alone is kept, as one flat array
    rank = len(units[: 2 * system.n_pair_rows]) - units[: 2 * system.n_pair_rows].count(-1)
    probed = _probe_system(system, free)
    # each probe row is matched to the free units it fixes
    if free:
        units = units + array(
            "i", itertools.chain.from_iterable((u, u if k == 2 else -1) for u, k in free)
        )
    assigned = Assignment(units)
    del units
    flat = (
        flat_rows(probed.adj_start, probed.adj, assigned.units)
        if len(assigned) >= NUMPY_ROWS
        else None
    )
    # a small system's rows are read as plain tuples: cheaper than the flat arrays' views
    matched = assigned if flat is not None else assigned.tolist()
    adjacency = probed.row_adj if flat is not None else probed.row_adj.tolist()
    blocks = irreducible_blocks(adjacency, matched, system.n_unknowns, flat=flat)
    suspects = _singular_blocks(probed, blocks, matched, seed, flat=flat)
    if suspects:
        # a generic dependency persists at another random pose; a near-coincidence does not
        suspects = _singular_blocks(probed, blocks, matched, seed + 1, suspects, flat=flat)
    del matched, adjacency
    del flat
    if not suspects:
        return RankAnalysis(
            system,
            unmatched,
            rank,
            system.n_scalar_unknowns - rank,
            free,
            None if free or unmatched else blocks,
            assigned,
            "structural",
        )
    return dense_rank(system, random_realization(system, seed), method="dense")


def geometric_rank(
    system: ConstraintSystem, realization: Realization, *, jacobian: np.ndarray | None = None
) -> RankAnalysis:
    """Rank analysis at the sketch pose (dense; see :func:`dense_rank`)."""
    return dense_rank(system, realization, method="dense", jacobian=jacobian)


def singular_blocks(analysis: RankAnalysis, realization: Realization) -> list[int]:
    """The blocks of a regular structural ``analysis`` singular at ``realization``.

    Generically every block is regular (that is what ``analysis`` found); at a
    particular pose one may not be: a dyad drawn with its two links in line (a
    dead point), a parallelogram folded flat. Each block's square Jacobian is
    made dimensionless as :func:`dimensionless_jacobian` does and judged with
    the rank's tolerance.

    >>> from structure import parse_edgelist
    >>> from structure.rigidity import constraint_system, sketch_realization
    >>> m = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
    ...     "point A 0 0", "point B 0 1", "point C 2 1", "point D 3 1"])  # B, C, D in line
    >>> system = constraint_system(m, ["1"])
    >>> analysis = generic_rank(system)
    >>> [sorted({system.unknowns[u].owner for u in analysis.blocks[b]})
    ...  for b in singular_blocks(analysis, sketch_realization(system))]
    [['2', '3']]
    """
    system, blocks = analysis.system, analysis.blocks
    if blocks is None:
        raise ValueError("singular_blocks needs a regular structural analysis (with blocks)")
    offsets, _ = system.scalar_offsets()
    uo = offsets.tolist()
    assigned = analysis.assigned
    matched = assigned.tolist() if isinstance(assigned, Assignment) else assigned
    rows_of = _rows_of_blocks(system, list(blocks), matched)
    length = sketch_scale(system, realization)
    bad = []
    for b, units in enumerate(blocks):
        rows = rows_of(b)
        if _trivially_regular(system, units, rows):
            continue
        a = _block_matrix(system, realization, list(units), rows, matched, uo)
        if a is None:
            bad.append(b)
            continue
        matrix = np.array(a)
        angle_columns = [
            system.unknown_kind(u) == "ang" for u in units for _ in range(system.unknown_size(u))
        ]
        matrix[:, np.array(angle_columns, dtype=bool)] /= length
        # a row block gives the matrix as many rows as units it is matched to
        angle_rows = [_is_angle_row(system, r) for r in rows for _ in matched[r]]
        matrix[np.array(angle_rows, dtype=bool)] *= length
        if _singular_ratios([matrix.tolist()])[0] <= _RANK_TOL:
            bad.append(b)
    return bad


def sketch_scale(system: ConstraintSystem, realization: Realization) -> float:
    """The realization's size (largest span of its points), which makes lengths dimensionless.

    A sketch whose points all coincide has the size of its distance from the
    origin (1 when that is zero too), so that scaling a mechanism scales it.
    """
    pts = [p for p in realization.point if p is not None]
    if not pts:
        return 1.0
    xs = [float(p[0]) for p in pts]
    ys = [float(p[1]) for p in pts]
    if not all(map(math.isfinite, xs + ys)):
        return 1.0  # no finite size: lengths are left as they are
    span = max(max(xs) - min(xs), max(ys) - min(ys))
    if span > 0 and math.isfinite(span):
        return span
    far = max(map(abs, xs + ys))
    return far if far > 0 else 1.0


def _is_angle_row(system: ConstraintSystem, r: int) -> bool:
    """Whether row block ``r`` is an angle (the others are lengths)."""
    kind = system.row_kind[r]
    if kind is RowKind.SLIDE_ANGLE:
        return True
    if kind in (RowKind.DRIVER, RowKind.PROBE):
        return system.unknown_kind(system.row_adj[r][0]) == "ang"
    return False


def _angle_rows(system: ConstraintSystem, rows: Sequence[int]) -> list[bool]:
    """Which scalar rows of the row blocks ``rows`` are angles (the others are lengths)."""
    out: list[bool] = []
    for r in rows:
        out.extend([_is_angle_row(system, r)] * system.row_size[r])
    return out


def dimensionless_jacobian(
    system: ConstraintSystem, realization: Realization, rows: Sequence[int] | None = None
) -> tuple[np.ndarray, float]:
    """The Jacobian of ``rows`` (default all) in the sketch's own unit of length, and that unit.

    Positions are measured in units of :func:`sketch_scale` and length rows
    divided by it; angles and angle rows are unchanged. The matrix, its rank
    and its null space are then the same for a mechanism and for any scaled
    copy of it, so one relative tolerance serves every unit of length.

    >>> from structure import Mechanism
    >>> from structure.rigidity import constraint_system, random_realization
    >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "0", "R")])
    >>> s = constraint_system(m, ["1"])
    >>> J, length = dimensionless_jacobian(s, random_realization(s))
    >>> J.shape, bool(length > 0)
    ((7, 6), True)
    """
    rows = list(range(len(system.row_kind)) if rows is None else rows)
    J = jacobian(system, realization, rows)
    length = sketch_scale(system, realization)
    uo, _ = system.scalar_offsets()
    offsets = uo.tolist()
    angle_cols = [offsets[u] for u in range(1, 2 * len(system.links), 2)]
    J[:, angle_cols] /= length
    J[np.array(_angle_rows(system, rows), dtype=bool)] *= length
    return J, length


def dense_rank(
    system: ConstraintSystem,
    realization: Realization,
    method: str,
    *,
    jacobian: np.ndarray | None = None,
) -> RankAnalysis:
    """Rank-revealing pass over the rows in order at ``realization``.

    Lengths are made dimensionless by the sketch's size
    (:func:`dimensionless_jacobian`), then each scalar row
    is kept when its component orthogonal to the rows kept so far exceeds
    1e-8 of its norm. ``jacobian`` is that dimensionless Jacobian (all rows)
    when already computed; it is not changed.
    """
    n = system.n_scalar_unknowns
    if n > DENSE_LIMIT:
        raise MechanismError(
            f"the mechanism has {n} scalar unknowns and a dependency the block analysis "
            f"cannot resolve; the dense rank pass is limited to {DENSE_LIMIT}"
        )
    J = dimensionless_jacobian(system, realization)[0] if jacobian is None else jacobian
    _, ro = system.scalar_offsets()
    kept = _kept_rows(J)
    block_of = np.repeat(np.arange(len(system.row_size)), system.row_size).tolist()
    dependent: dict[int, int] = {}
    kept_set = set(kept)
    for i, r in enumerate(block_of):
        if i not in kept_set:
            dependent[r] = dependent.get(r, 0) + 1
    n_pair_scalar = int(ro[system.n_pair_rows])
    rank = sum(1 for i in kept if i < n_pair_scalar)
    free = [] if len(kept) == n else [(-1, n - len(kept))]
    return RankAnalysis(system, dependent, rank, n - rank, free, None, [], method)


def _kept_rows(J: np.ndarray) -> list[int]:
    """The rows of ``J`` kept in order: those not within 1e-8 (relative) of the span before.

    A row is kept when its component orthogonal to the rows kept so far
    exceeds ``1e-8`` of its norm. Runs of clearly independent rows (that
    component above ``1e-6`` of the norm) are found at once by a QR
    factorization of what is left of the rows; the first row of a run that
    is not clearly independent is decided on its own by projecting it out
    of the kept rows twice, exactly as a row-by-row pass would.
    """
    m, n = J.shape
    norms = np.linalg.norm(J, axis=1)
    basis = np.zeros((0, n))
    kept: list[int] = []
    i = 0
    while i < m:
        run, rest = _independent_run(J[i:], norms[i:], basis) if n else (0, J[i:])
        kept.extend(range(i, i + run))
        i += run
        if i == m:
            break  # the usual end: every row left was clearly independent
        if run:
            q, _ = np.linalg.qr(rest[:run].T)
            basis = np.vstack([basis, q.T])
        v, norm = J[i], float(norms[i])
        if norm != 0.0:
            w = _project_out(v, basis)
            wn = float(np.linalg.norm(w))
            if wn > _RANK_TOL * norm:
                basis = np.vstack([basis, w / wn])
                kept.append(i)
        i += 1
    return kept


#: a row whose component orthogonal to the rows before exceeds this share of its
#: norm is independent beyond doubt (the rank tolerance is 1e-8)
_CLEARLY_INDEPENDENT = 1e-6


def _project_out(rows: np.ndarray, basis: np.ndarray) -> np.ndarray:
    """``rows`` less their components on the orthonormal rows of ``basis`` (twice, for accuracy)."""
    if not len(basis):
        return rows
    rows = rows - (rows @ basis.T) @ basis
    return rows - (rows @ basis.T) @ basis


def _independent_run(
    rows: np.ndarray, norms: np.ndarray, basis: np.ndarray
) -> tuple[int, np.ndarray]:
    """How many leading ``rows`` are clearly independent, and the rows less ``basis``.

    The run stops before the first row not clearly independent of ``basis``
    and of the rows before it (the triangular factor's diagonal tells).
    """
    rest = _project_out(rows, basis)
    diag = np.abs(np.diagonal(np.linalg.qr(rest.T, mode="r")))
    clear = diag > _CLEARLY_INDEPENDENT * norms[: len(diag)]
    return (len(diag) if bool(clear.all()) else int(np.argmin(clear))), rest


def null_space(
    system: ConstraintSystem,
    realization: Realization,
    rows: Sequence[int] | None = None,
    *,
    jacobian: np.ndarray | None = None,
) -> np.ndarray:
    """Orthonormal basis (columns) of the null space of the given rows at ``realization``.

    The basis is in the sketch's own unit of length (see
    :func:`dimensionless_jacobian`): positions in units of :func:`sketch_scale`.
    ``jacobian`` is the dimensionless Jacobian of those rows when already
    computed; it is not changed.
    """
    J = dimensionless_jacobian(system, realization, rows)[0] if jacobian is None else jacobian
    n = system.n_scalar_unknowns
    if J.shape[0] == 0:
        return np.eye(n)
    if J.shape[0] >= n > 0:
        # the singular values alone cost a third of the factorization: when they
        # leave no null space (the usual driven system), the vectors are not needed
        s = np.linalg.svd(J, compute_uv=False)
        if s[-1] > _RANK_TOL * max(1.0, s[0]):
            return np.zeros((n, 0))
    _, s, vt = np.linalg.svd(J)
    rank = int(np.sum(s > _RANK_TOL * max(1.0, s[0] if len(s) else 1.0)))
    return vt[rank:].T
