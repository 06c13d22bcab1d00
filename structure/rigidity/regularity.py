"""Is the sketch a regular pose? Step along the free motions, project back, compare ranks.

The rank of the constraint Jacobian at the sketch gives the geometric
redundancy r and the passive freedoms, but only at a *regular* pose. At a
singular one (a parallelogram drawn folded flat, a change point) the rank
drops and the counts would report a redundancy the mechanism does not have.
THEORY §3: step along the null space of the pair rows (the motions the pairs
allow, drivers free), project back onto the constraints by Gauss–Newton and
recompute the rank. A higher rank there means the sketch was singular; the
nearby pose is regular and its counts are the mechanism's. The same holds for
the drivers: at a dead point (a dyad drawn with its links in line) a driver's
row depends on the pairs' at the sketch only (:func:`regular_rank`).

>>> from structure import parse_edgelist
>>> from structure.rigidity import constraint_system, sketch_realization
>>> m = parse_edgelist(["0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D", "point A 0 0",
...                     "point B 1 0", "point C 3 0", "point D 2 0"])   # a flat parallelogram
>>> system = constraint_system(m)
>>> moved = nearby_pose(system, sketch_realization(system))
>>> moved is not None
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from .constraints import ConstraintSystem, Realization, RowKind
from .rank import (
    RankAnalysis,
    dimensionless_jacobian,
    geometric_rank,
    null_space,
    sketch_scale,
)

__all__ = ["nearby_pose", "regular_rank"]

_STEP = 1e-3  # of the sketch's size
_TOL = 1e-12  # residual, of the sketch's size


def _state(system: ConstraintSystem, z: np.ndarray, uo: Sequence[int]):
    """Link positions and angles, and free pins' displacements, from the scalar unknowns."""
    links = {
        link: (z[uo[p]], z[uo[p] + 1], z[uo[system.ang[link]]]) for link, p in system.pos.items()
    }
    pins = {point: (z[uo[u]], z[uo[u] + 1]) for point, u in system.pin.items()}
    return links, pins


def _world(links: dict, link: str, c: tuple[float, float]) -> np.ndarray:
    if link not in links:  # the ground
        return np.array(c, dtype=float)
    x, y, t = links[link]
    cs, sn = math.cos(t), math.sin(t)
    return np.array([x + cs * c[0] - sn * c[1], y + sn * c[0] + cs * c[1]])


def _rotated(links: dict, link: str, d: tuple[float, float] | None):
    if d is None or link not in links:
        return d
    t = links[link][2]
    cs, sn = math.cos(t), math.sin(t)
    return (cs * d[0] - sn * d[1], sn * d[0] + cs * d[1])


def _moved(
    system: ConstraintSystem, sketch: Realization, z: np.ndarray, uo: Sequence[int]
) -> tuple[Realization, np.ndarray]:
    """The realization of the pose ``z`` (displacements from the sketch) and its pair residuals.

    Each row's point is where its pin (or slider) now is; slide directions
    turn with the pair's first link. With those, :func:`~structure.rigidity.constraints.jacobian`
    gives the exact Jacobian of the residuals at the pose.
    """
    m = system.mechanism
    links, pins = _state(system, z, uo)
    points = list(sketch.point)
    directions = list(sketch.direction)
    residual: list[float] = []
    for r in range(system.n_pair_rows):
        kind = system.row_kind[r]
        pair = m.pair(system.row_pair[r])
        c = sketch.point[r]
        if kind is RowKind.HINGE:
            pa, pb = _world(links, pair.a, c), _world(links, pair.b, c)
            residual += list(pa - pb)
            points[r] = tuple((pa + pb) / 2)
        elif kind is RowKind.PIN:
            link = system.row_link[r]
            p = _world(links, link, c)
            shift = pins.get(pair.point, (0.0, 0.0))
            residual += [p[0] - c[0] - shift[0], p[1] - c[1] - shift[1]]
            points[r] = tuple(p)
        elif kind is RowKind.SLIDE_ANGLE:
            ta = links[pair.a][2] if pair.a in links else 0.0
            tb = links[pair.b][2] if pair.b in links else 0.0
            residual.append(ta - tb)
            directions[r] = _rotated(links, pair.a, sketch.direction[r])
        else:  # SLIDE (CONTACT rows are refused by the caller)
            u = _rotated(links, pair.a, sketch.direction[r])
            pa, pb = _world(links, pair.a, c), _world(links, pair.b, c)
            residual.append(-u[1] * (pb[0] - pa[0]) + u[0] * (pb[1] - pa[1]))
            points[r] = tuple(pb)  # with the slider's point the Jacobian is exact
            directions[r] = u
    origin = {
        link: (links[link][0], links[link][1]) if link in links else (0.0, 0.0)
        for link in sketch.origin
    }
    return Realization(origin, tuple(points), tuple(directions)), np.array(residual)


def nearby_pose(
    system: ConstraintSystem, sketch: Realization, seed: int = 20261121, tries: int = 3
) -> Realization | None:
    """A pose near the sketch, reached along the motions its pairs allow (drivers free).

    None when the pairs allow no motion, when the mechanism has higher pairs
    (their profiles are not known away from the sketch), or when the
    projection back onto the constraints does not converge.
    """
    rows = range(system.n_pair_rows)
    if any(system.row_kind[r] is RowKind.CONTACT for r in rows):
        return None
    offsets, _ = system.scalar_offsets()
    uo = offsets.tolist()
    length = sketch_scale(system, sketch)
    angle_columns = [uo[u] for u in range(1, 2 * len(system.links), 2)]
    # residuals in the sketch's unit: lengths divided by its size, angles as they are
    residual_unit = np.concatenate(
        [
            np.full(system.row_size[r], 1.0 if kind is RowKind.SLIDE_ANGLE else length)
            for r in rows
            for kind in (system.row_kind[r],)
        ]
    )
    position_columns = np.ones(int(offsets[-1]), dtype=bool)
    position_columns[angle_columns] = False
    basis = null_space(system, sketch, rows)
    if basis.shape[1] == 0:
        return None
    rng = np.random.default_rng(seed)
    for _ in range(tries):
        step = basis @ rng.standard_normal(basis.shape[1])
        z = _STEP * length * step / np.linalg.norm(step)
        z[angle_columns] /= length
        for _ in range(30):
            moved, residual = _moved(system, sketch, z, uo)
            if np.max(np.abs(residual), initial=0.0) <= _TOL * length:
                return moved
            jac, _ = dimensionless_jacobian(system, moved, rows)
            step = np.linalg.lstsq(jac, -residual / residual_unit, rcond=None)[0]
            step[position_columns] *= length
            z = z + step
    return None


def regular_rank(
    system: ConstraintSystem,
    sketch: Realization,
    *,
    jacobian: np.ndarray | None = None,
    baseline: int = 0,
) -> tuple[RankAnalysis, Realization, np.ndarray]:
    """The rank at the sketch, or at a regular pose near it when the sketch is singular.

    The sketch's rank tells geometric redundancy from a lucky count only at a
    regular pose. When the sketch shows more dependent rows (pairs' or
    drivers') than ``baseline`` (what every pose has, e.g. the generic count),
    a pose reached from it along the motions its pairs allow is tried: if it
    has fewer, the sketch was singular (a dead point, a change point) and that
    pose's analysis is returned, marked ``near_sketch``. A true geometric
    redundancy (a parallelogram's third crank) is there at every pose and
    stays. Returns the analysis, its pose and the dimensionless Jacobian there
    (``jacobian``: the sketch's, when already computed).

    >>> from structure import parse_edgelist
    >>> from structure.rigidity import constraint_system, sketch_realization
    >>> m = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
    ...     "point A 0 0", "point B 0 1", "point C 2 1", "point D 3 1"])  # B, C, D in line
    >>> system = constraint_system(m, ["1"])
    >>> analysis, _, _ = regular_rank(system, sketch_realization(system))
    >>> analysis.dependent_drivers, analysis.near_sketch
    ([], True)
    """
    if jacobian is None:
        jacobian = dimensionless_jacobian(system, sketch)[0]
    analysis = geometric_rank(system, sketch, jacobian=jacobian)
    if analysis.n_dependent <= baseline:
        return analysis, sketch, jacobian
    moved = nearby_pose(system, sketch)
    if moved is None:
        return analysis, sketch, jacobian
    moved_jacobian = dimensionless_jacobian(system, moved)[0]
    regular = geometric_rank(system, moved, jacobian=moved_jacobian)
    if regular.n_dependent >= analysis.n_dependent:
        return analysis, sketch, jacobian
    return replace(regular, near_sketch=True), moved, moved_jacobian
