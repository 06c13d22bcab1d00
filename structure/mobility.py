"""Mobility with its corrections: W = 3n − (2·P5 + P4) + r − W_passive.

* ``r`` counts redundant constraints. Structurally they are found from the
  generic rank of the constraint system (:mod:`structure.rigidity.rank`): a
  subassembly with more constraints than its bodies can take (the (3,3)
  count, pins as points), or a loop of prismatic pairs whose angle
  constraints repeat each other. With sketch coordinates, the rank at the
  pose also catches redundancy that the dimensions create.
* ``W_passive`` counts motions that move one link only: declared rollers, and
  with coordinates, null-space directions of the constraint Jacobian (drivers
  fixed) that move a single link.

The redundant constraints are named by pair: the latest-listed pair of each
dependent set.

>>> from structure import parse_edgelist
>>> m = parse_edgelist(["0 1 R", "1 2 R", "2 3 R", "3 0 R"])
>>> mob = mobility(m)
>>> mob.W_topology, mob.r, mob.W_passive, mob.W
(1, 0, 0, 1)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .kinds import PairKind
from .model import Mechanism
from .rigidity.constraints import (
    ConstraintSystem,
    MissingGeometry,
    Realization,
    RowKind,
    constraint_system,
    sketch_realization,
)
from .rigidity.rank import DENSE_LIMIT, RankAnalysis, generic_rank, null_space
from .rigidity.regularity import regular_rank

__all__ = [
    "Mobility",
    "PassiveMotion",
    "Redundancy",
    "counts",
    "mobility",
    "mobility_analysis",
    "rank_analyses",
]


@dataclass(frozen=True, slots=True)
class Redundancy:
    """``constraints`` redundant scalar constraints in pair ``pair`` (its id)."""

    pair: int
    label: str
    constraints: int
    source: str  # "structural" or "geometric"
    line_no: int = 0


@dataclass(frozen=True, slots=True)
class PassiveMotion:
    """A freedom that moves link ``link`` only (``source``: roller or geometric)."""

    link: str
    dof: int
    source: str


@dataclass(frozen=True, slots=True)
class Mobility:
    """Counts and the degree of freedom with its corrections.

    ``redundant`` lists every redundant constraint found (structural ones and,
    with coordinates, geometric ones); ``r`` is their total.
    """

    n: int
    P5: int
    P4: int
    redundant: tuple[Redundancy, ...]
    passive: tuple[PassiveMotion, ...]
    geometric: bool
    notes: tuple[str, ...] = ()

    @property
    def W_topology(self) -> int:
        """Grübler–Chebyshev count 3n − (2·P5 + P4), before corrections."""
        return 3 * self.n - (2 * self.P5 + self.P4)

    @property
    def r(self) -> int:
        return sum(x.constraints for x in self.redundant)

    @property
    def W_passive(self) -> int:
        return sum(x.dof for x in self.passive)

    @property
    def W(self) -> int:
        return self.W_topology + self.r - self.W_passive

    @property
    def formula(self) -> str:
        """The formula with numbers, e.g. ``W = 3·3 − (2·4 + 0) + 0 − 0 = 1``."""
        return (
            f"W = 3·{self.n} − (2·{self.P5} + {self.P4}) + {self.r} − {self.W_passive} = {self.W}"
        )


def counts(mechanism: Mechanism) -> tuple[int, int, int]:
    """``(n, P5, P4)``: moving links, lower pairs, higher pairs."""
    p4 = sum(1 for p in mechanism.pairs if p.kind is PairKind.H)
    return len(mechanism.moving_links), len(mechanism.pairs) - p4, p4


def _sketch_pose(system: ConstraintSystem) -> tuple[Realization | None, tuple[str, ...]]:
    """The sketch's realization for the geometric check, or None and why not."""
    m = system.mechanism
    if not m.points:
        return None, ()
    if system.n_scalar_unknowns > DENSE_LIMIT:
        return None, (
            f"the geometric check is limited to {DENSE_LIMIT} scalar unknowns "
            f"({system.n_scalar_unknowns} here); only the structural count was used",
        )
    try:
        return sketch_realization(system), ()
    except MissingGeometry as exc:
        return None, (
            "coordinates are incomplete, so the geometric check was skipped: "
            + "; ".join(exc.reasons[:3])
            + ("; ..." if len(exc.reasons) > 3 else ""),
        )


def mobility(mechanism: Mechanism, drivers: Sequence[str] | None = None) -> Mobility:
    """Degree of freedom of ``mechanism`` with redundant and passive corrections.

    ``drivers`` (default: the mechanism's own) only matter for the passive
    motions found geometrically, which are those left once the drivers are
    fixed.
    """
    return mobility_analysis(mechanism, drivers)[0]


def _usable_drivers(mechanism: Mechanism, drivers: Sequence[str]) -> tuple[str, ...]:
    return tuple(d for d in drivers if mechanism.ground_joint(d) is not None)


def mobility_analysis(
    mechanism: Mechanism,
    drivers: Sequence[str] | None = None,
    *,
    generic: RankAnalysis | None = None,
) -> tuple[Mobility, RankAnalysis, RankAnalysis | None]:
    """:func:`mobility` and the rank analyses behind it (generic, geometric or None).

    The analyses are of the system driven by ``drivers``; the decomposition
    reuses them instead of building the system again. ``generic`` is the
    generic analysis of that same system when already computed (it is used
    only when it is of ``mechanism`` with these drivers).
    """
    drivers = mechanism.driver_links if drivers is None else tuple(drivers)
    n, p5, p4 = counts(mechanism)
    ranks = _rank_analyses(mechanism, drivers, generic)
    generic, geometric = ranks.generic, ranks.geometric
    redundant = [
        Redundancy(pid, mechanism.pair(pid).label, k, "structural", mechanism.pair(pid).line_no)
        for pid, k in sorted(generic.dependent_pairs.items())
    ]
    redundant.extend(
        Redundancy(pid, mechanism.pair(pid).label, k, "geometric", mechanism.pair(pid).line_no)
        for pid, k in sorted(ranks.extra.items())
    )
    geo_passive: dict[str, int] = {}
    if ranks.realization is not None:
        geo_passive = _geometric_passive(ranks.system, ranks.realization, ranks.jacobian)
    declared = {p.roller: 1 for p in mechanism.pairs if p.roller is not None}
    passive = []
    for link in mechanism.moving_links:
        d, g = declared.get(link, 0), geo_passive.get(link, 0)
        if d or g:
            passive.append(PassiveMotion(link, max(d, g), "roller" if d >= g else "geometric"))
    mob = Mobility(n, p5, p4, tuple(redundant), tuple(passive), geometric is not None, ranks.notes)
    return mob, generic, geometric


def rank_analyses(
    mechanism: Mechanism, drivers: Sequence[str], *, generic: RankAnalysis | None = None
) -> tuple[RankAnalysis, RankAnalysis | None]:
    """The rank analyses of :func:`mobility_analysis` (generic, geometric or None) alone.

    What the decomposition needs when the mobility itself is known: the
    passive motions are not looked for.
    """
    ranks = _rank_analyses(mechanism, tuple(drivers), generic)
    return ranks.generic, ranks.geometric


_SINGULAR_SKETCH = (
    "the sketch is a singular pose (the Jacobian of the pairs and drivers loses rank there: "
    "a dead point, or a linkage drawn folded flat): the geometric counts are those of a "
    "regular pose reached from it by a small motion"
)


@dataclass(frozen=True, slots=True)
class _RankAnalyses:
    """The generic and geometric analyses of a driven system, and what they add up to.

    ``realization`` is the pose of ``geometric`` (the sketch, or a regular pose
    near it) and ``jacobian`` the system's dimensionless Jacobian there;
    ``extra`` is the geometric redundancy beyond the structural one.
    """

    system: ConstraintSystem
    generic: RankAnalysis
    geometric: RankAnalysis | None
    realization: Realization | None
    jacobian: np.ndarray | None
    extra: dict[int, int]
    notes: tuple[str, ...]


def _rank_analyses(
    mechanism: Mechanism, drivers: tuple[str, ...], generic: RankAnalysis | None
) -> _RankAnalyses:
    usable = _usable_drivers(mechanism, drivers)
    if generic is not None and _is_system_of(generic, mechanism, usable):
        system = generic.system
    else:
        system = constraint_system(mechanism, usable)
        generic = generic_rank(system)
    realization, notes = _sketch_pose(system)
    if realization is None:
        return _RankAnalyses(system, generic, None, None, None, {}, notes)
    # at a singular sketch (a dead point, a linkage drawn folded flat) the rank drops: the
    # counts are then those of a regular pose near it, never the sketch's accident
    geometric, realization, jacobian = regular_rank(
        system, realization, baseline=generic.n_dependent
    )
    if geometric.near_sketch:
        notes = (*notes, _SINGULAR_SKETCH)
    extra = _extra_geometric(generic.dependent_pairs, geometric.dependent_pairs)
    return _RankAnalyses(system, generic, geometric, realization, jacobian, extra, notes)


def _is_system_of(analysis: RankAnalysis, mechanism: Mechanism, drivers: tuple[str, ...]) -> bool:
    """Whether ``analysis`` is of ``mechanism``'s system driven by ``drivers``."""
    system = analysis.system
    return (
        system.mechanism is mechanism
        and len(system.row_kind) == system.n_pair_rows + len(drivers)
        and system.row_link[system.n_pair_rows :] == drivers
        and all(kind is RowKind.DRIVER for kind in system.row_kind[system.n_pair_rows :])
    )


def _extra_geometric(structural: dict[int, int], geometric: dict[int, int]) -> dict[int, int]:
    """Geometric redundancy beyond the structural count, attributed to pairs."""
    surplus = sum(geometric.values()) - sum(structural.values())
    out: dict[int, int] = {}
    if surplus <= 0:
        return out
    for pid in sorted(geometric, reverse=True):
        k = min(geometric[pid] - structural.get(pid, 0), surplus)
        if k > 0:
            out[pid] = k
            surplus -= k
        if surplus == 0:
            break
    return dict(sorted(out.items()))


def _geometric_passive(
    system: ConstraintSystem, realization: Realization, jacobian: np.ndarray | None
) -> dict[str, int]:
    """Null-space directions (drivers fixed) that move one link only, per link.

    ``jacobian`` is the system's dimensionless Jacobian at ``realization``.

    A link jointed to the ground that is not driven may turn (or slide) on
    its ground joint alone: that motion is a driver candidate's, counted in W
    as it is without coordinates, never a passive freedom.
    """
    N = null_space(system, realization, jacobian=jacobian)
    if N.shape[1] == 0:
        return {}
    uo, _ = system.scalar_offsets()
    m = system.mechanism
    driven = {
        system.row_link[r] for r, kind in enumerate(system.row_kind) if kind is RowKind.DRIVER
    }
    links = m.moving_links
    offsets = uo.tolist()
    placements = [(offsets[system.pos[x]], offsets[system.ang[x]]) for x in links]
    ranks = _ranks_without_links(N, placements)
    out: dict[str, int] = {}
    for link, rank in zip(links, ranks, strict=True):
        k = N.shape[1] - rank
        if k and link not in driven and m.ground_joint(link) is not None:
            k -= 1  # the candidate's own motion on its ground joint
        if k:
            out[link] = k
    return out


def _ranks_without_links(N: np.ndarray, columns: Sequence[tuple[int, int]]) -> list[int]:
    """Rank of ``N`` without the rows of each link's placement (position, angle).

    ``columns`` holds each link's (position, angle) scalar offsets. The
    matrices are all of one shape, so one batched SVD serves every link.
    """
    if not columns:
        return []
    keep = np.ones((len(columns), len(N)), dtype=bool)
    for k, (p0, a0) in enumerate(columns):
        keep[k, [p0, p0 + 1, a0]] = False
    rest = np.stack([N[row] for row in keep])
    if not rest.size:
        return [0] * len(columns)
    s = np.linalg.svd(rest, compute_uv=False)
    return np.sum(s > 1e-8, axis=1).tolist()
