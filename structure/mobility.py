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
from .rigidity.rank import DENSE_LIMIT, RankAnalysis, generic_rank, geometric_rank, null_space
from .rigidity.regularity import nearby_pose

__all__ = ["Mobility", "PassiveMotion", "Redundancy", "counts", "mobility", "mobility_analysis"]


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


def _geometric(
    system: ConstraintSystem,
) -> tuple[RankAnalysis | None, tuple[str, ...], Realization | None]:
    m = system.mechanism
    if not m.points:
        return None, (), None
    if system.n_scalar_unknowns > DENSE_LIMIT:
        return (
            None,
            (
                f"the geometric check is limited to {DENSE_LIMIT} scalar unknowns "
                f"({system.n_scalar_unknowns} here); only the structural count was used",
            ),
            None,
        )
    try:
        realization = sketch_realization(system)
    except MissingGeometry as exc:
        return (
            None,
            (
                "coordinates are incomplete, so the geometric check was skipped: "
                + "; ".join(exc.reasons[:3])
                + ("; ..." if len(exc.reasons) > 3 else ""),
            ),
            None,
        )
    return geometric_rank(system, realization), (), realization


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
    mechanism: Mechanism, drivers: Sequence[str] | None = None
) -> tuple[Mobility, RankAnalysis, RankAnalysis | None]:
    """:func:`mobility` and the rank analyses behind it (generic, geometric or None).

    The analyses are of the system driven by ``drivers``; the decomposition
    reuses them instead of building the system again.
    """
    drivers = mechanism.driver_links if drivers is None else tuple(drivers)
    n, p5, p4 = counts(mechanism)
    system = constraint_system(mechanism, _usable_drivers(mechanism, drivers))
    generic = generic_rank(system)
    geometric, notes, realization = _geometric(system)
    redundant = [
        Redundancy(pid, mechanism.pair(pid).label, k, "structural", mechanism.pair(pid).line_no)
        for pid, k in sorted(generic.dependent_pairs.items())
    ]
    geo_passive: dict[str, int] = {}
    if geometric is not None and realization is not None:
        extra = _extra_geometric(generic.dependent_pairs, geometric.dependent_pairs)
        moved = nearby_pose(system, realization) if extra else None
        if moved is not None and (regular := geometric_rank(system, moved)).rank > geometric.rank:
            geometric, realization = regular, moved
            extra = _extra_geometric(generic.dependent_pairs, geometric.dependent_pairs)
            notes = (
                *notes,
                "the sketch is a singular pose (the pairs' Jacobian loses rank there, as for "
                "a linkage drawn folded flat): the geometric counts are those of a regular "
                "pose reached from it by a small motion",
            )
        redundant.extend(
            Redundancy(pid, mechanism.pair(pid).label, k, "geometric", mechanism.pair(pid).line_no)
            for pid, k in sorted(extra.items())
        )
        geo_passive = _geometric_passive(system, realization)
    declared = {p.roller: 1 for p in mechanism.pairs if p.roller is not None}
    passive = []
    for link in mechanism.moving_links:
        d, g = declared.get(link, 0), geo_passive.get(link, 0)
        if d or g:
            passive.append(PassiveMotion(link, max(d, g), "roller" if d >= g else "geometric"))
    mob = Mobility(n, p5, p4, tuple(redundant), tuple(passive), geometric is not None, notes)
    return mob, generic, geometric


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


def _geometric_passive(system: ConstraintSystem, realization: Realization) -> dict[str, int]:
    """Null-space directions (drivers fixed) that move one link only, per link.

    A link jointed to the ground that is not driven may turn (or slide) on
    its ground joint alone: that motion is a driver candidate's, counted in W
    as it is without coordinates, never a passive freedom.
    """
    N = null_space(system, realization)
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
