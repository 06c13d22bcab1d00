"""Assembly modes: the ways a group can close at the sketch's inputs, and how a user names one.

A group's pairs fix its links' poses up to a finite choice: a dyad has two
assembly modes (the two roots of its closed form; a PRP or RPP dyad one), a
class III triad up to six, a class IV group more. :func:`group_solutions`
finds the solutions of a group's closure equations at one pose, its known
links placed: Newton's method from many starts (each link turned about the
middle of its pairs to a spread of angles), every start that converges
kept once. They are numbered from the one the solve takes by itself (mode
0: the sketch's, when the groups before it are in theirs) outward, by how
far the group's pins lie from it; so mode 1 is the next assembly found from
the sketch.

A user names a mode in ``flip`` (:func:`kinematics.solvers.plan.parse_flip`):
``'III(4,5,6,7)'`` for the next one (a dyad's other one), ``'III(4,5,6,7)=2'``
for mode 2 as :func:`kinematics.solvers.solve.assembly_modes` lists them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..errors import DEAD_CENTRE, AssemblyError
from .equations import group_system
from .newton import angle_rows, newton_pose, scaled_jacobian, scaled_residual
from .plan import GroupStep, SolvePlan

__all__ = ["Mode", "group_solutions"]

#: starts of Newton's method per group; the first is the solve's own solution
STARTS = 256
_ITERATIONS = 60
_TRUST = 0.5  # the largest Newton step: rad, or sketch sizes
_SAME = 1e-6  # two solutions closer than this (rad, or sketch sizes) are one


@dataclass(frozen=True)
class Mode:
    """One assembly mode of a group: its number, its links' poses, its pins' positions.

    ``poses[link]`` is the link's ``(x, y, θ)`` from the sketch, ``pins[name]``
    a named pin's position (m), at the sketch's inputs.
    """

    index: int
    poses: Mapping[str, np.ndarray]
    pins: Mapping[str, np.ndarray]


def group_solutions(
    step: GroupStep,
    plan: SolvePlan,
    known: Mapping[str, np.ndarray],
    first: Mapping[str, np.ndarray],
    starts: int = STARTS,
) -> list[dict[str, np.ndarray]]:
    """The solutions of ``step``'s equations with the ``known`` links' poses (3,) given.

    ``first`` is the solution the solve takes (mode 0); the others follow, by
    the distance of the group's pins from their places in it. Solutions where
    the group's Jacobian loses rank (a dead centre, where two modes meet) are
    left out. Each is ``{link: (x, y, θ)}``, θ within (−π, π] for the others.
    """
    length = plan.length
    angles = angle_rows(step.equations)
    poses = _spread(step, first, starts)
    active = np.arange(starts)  # the starts still moving
    for _ in range(_ITERATIONS):
        q = {
            link: np.broadcast_to(np.asarray(p, float), (len(active), 3))
            for link, p in known.items()
        }
        q.update({link: poses[link][active] for link in step.links})
        phi, jac, _, _ = group_system(step.links, step.equations, q, {}, len(active))
        dz = -_solved(scaled_jacobian(jac, length, angles), scaled_residual(phi, length, angles))
        size = np.max(np.abs(dz), axis=1)
        dz *= np.minimum(1.0, _TRUST / np.where(size > 0, size, 1.0))[:, None]
        dz[:, 2::3] /= length
        for i, link in enumerate(step.links):
            poses[link][active] += dz[:, 3 * i : 3 * i + 3]
        active = active[~(size <= 1e-12)]
        if not len(active):
            break
    q = {link: np.broadcast_to(np.asarray(p, float), (starts, 3)) for link, p in known.items()}
    q.update(poses)
    found = [dict(first)]
    phi, jac, _, _ = group_system(step.links, step.equations, q, {}, starts)
    closed = np.max(np.abs(scaled_residual(phi, length, angles)), axis=1) <= 1e-9 * length
    ratio = _conditioning(scaled_jacobian(jac, length, angles))
    for k in np.flatnonzero(closed & (ratio > DEAD_CENTRE)):
        solution = _polished(step, plan, known, {link: q[link][k] for link in step.links})
        if solution is not None and not any(_same(solution, s, step, length) for s in found):
            found.append(solution)
    return sorted(found, key=lambda s: _distance(s, first, step, length))


def _solved(jac: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Batched ``jac·x = rhs`` (square: by LU, the singular ones by least squares)."""
    if jac.shape[1] == jac.shape[2]:
        try:
            return np.linalg.solve(jac, rhs[..., None])[..., 0]
        except np.linalg.LinAlgError:
            pass
    return np.einsum("nij,nj->ni", np.linalg.pinv(jac), rhs)


def _spread(step: GroupStep, first: Mapping[str, np.ndarray], starts: int) -> dict:
    """Start poses: the first the solve's solution, the others each link turned about its pins.

    Each link turns by an angle of a low-discrepancy spread over the circle
    (a different one per link) about the middle of its pair points, from its
    pose in ``first``.
    """
    out = {}
    golden = (math.sqrt(5.0) - 1.0) / 2.0
    k = np.arange(starts)
    for i, link in enumerate(step.links):
        points = [eq.point for eq in step.equations if link in (eq.a, eq.b) and eq.kind != "GEAR"]
        centre = np.mean(points, axis=0) if points else np.zeros(2)
        base = np.asarray(first[link], dtype=float)
        turn = 2.0 * math.pi * ((k * (golden + 0.1 * i) + 0.37 * i) % 1.0)
        turn[0] = 0.0
        theta = base[2] + turn
        c, s = np.cos(theta), np.sin(theta)
        # the point at ``centre`` (sketch) stays where ``first`` put it
        at = base[:2] + _rotated(base[2], centre)
        x = at[0] - (c * centre[0] - s * centre[1])
        y = at[1] - (s * centre[0] + c * centre[1])
        out[link] = np.column_stack([x, y, theta])
    return out


def _rotated(theta: float, v: np.ndarray) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def _polished(
    step: GroupStep, plan: SolvePlan, known: Mapping[str, np.ndarray], start: dict
) -> dict[str, np.ndarray] | None:
    """A solution refined by Newton on its own pose, its angles within (−π, π]; None if it fails."""
    q = {link: np.asarray(p, dtype=float)[None, :] for link, p in known.items()}
    for link, p in start.items():
        p = np.array(p, dtype=float)
        p[2] = math.remainder(p[2], 2.0 * math.pi)
        q[link] = p[None, :]
    try:
        newton_pose(step, plan, q, np.zeros(len(plan.drivers)))
    except AssemblyError:  # a start that does not settle is no solution
        return None
    return {link: q[link][0] for link in step.links}


def _conditioning(jac: np.ndarray) -> np.ndarray:
    """σ_min/σ_max of each row's Jacobian."""
    s = np.linalg.svd(jac, compute_uv=False)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(s[:, 0] > 0, s[:, -1] / s[:, 0], 0.0)


def _pins(step: GroupStep, solution: Mapping[str, np.ndarray]) -> np.ndarray:
    """Where each of the group's pair points lies in ``solution`` (on the pair's first link)."""
    out = []
    for eq in step.equations:
        if eq.kind == "GEAR":
            continue
        link = eq.a if eq.a in solution else eq.b
        pose = solution.get(link)
        if pose is None:
            continue
        out.append(pose[:2] + _rotated(float(pose[2]), eq.point))
    return np.array(out)


def _distance(solution, first, step: GroupStep, length: float) -> float:
    """How far the group's pins lie from their places in ``first``, in sketch sizes."""
    return float(np.sum(np.hypot(*(_pins(step, solution) - _pins(step, first)).T))) / length


def _same(a, b, step: GroupStep, length: float) -> bool:
    """Whether two solutions are one (the same pins, within :data:`_SAME` sketch sizes)."""
    gap = np.max(np.hypot(*(_pins(step, a) - _pins(step, b)).T)) / length
    turns = max(abs(math.remainder(float(a[k][2] - b[k][2]), 2.0 * math.pi)) for k in step.links)
    return bool(gap <= _SAME and turns <= _SAME)
