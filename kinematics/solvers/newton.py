"""Groups without a closed form, by Newton's method, followed pose by pose from the sketch.

A group's pair equations (:func:`~kinematics.solvers.equations.group_system`) are
solved for its links' poses: on one pose by damped Newton steps
(:func:`newton_pose`), over many poses by :func:`follow`, which starts each
chunk of poses from a quadratic extrapolation of the last solutions and runs
one batched Newton over the chunk, its Jacobian inverted once for several
steps. Far-apart inputs are first joined by intermediate poses
(:func:`densified`, a continuation from the sketch) so that Newton keeps the
sketch's assembly mode. The Jacobian is measured in the sketch's own unit of
length (:func:`scaled_jacobian`: θ columns divided by the sketch's size, angle
rows such as a P pair's θa − θb multiplied by it, the residual's angle rows too,
:func:`scaled_residual`), so that lengths and angles weigh alike whatever the
unit of length.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 1", "point C 2 1", "point D 2 0"])
>>> plan = make_plan(analyze(m))
>>> rows, picks = densified(plan, np.array([[0.2]]))
>>> rows.round(6).tolist(), picks.tolist()
([[0.05], [0.1], [0.15], [0.2]], [3])
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import AssemblyError
from .equations import Equation, group_residual, group_system
from .memory import check_poses
from .plan import GroupStep, SolvePlan

__all__ = [
    "CONTINUATION_STEP",
    "angle_rows",
    "densified",
    "follow",
    "needs_continuation",
    "newton_pose",
    "scaled_jacobian",
    "scaled_residual",
]

_MAX_NEWTON = 60
_CHUNK_SPAN = 0.3  # input span (rad, or fraction of the sketch) of one batched Newton chunk
_CHUNK_MAX = 1024
_CHUNK_ITERATIONS = 12
_KEEP_JACOBIAN = 4  # Newton steps over a chunk that share one inverted Jacobian
_MODE_JUMP = 0.2  # rad: a chunk whose angles land this far from the prediction changed mode
#: rad for a turning driver, fraction of the sketch for a sliding one: the largest step
#: between poses that needs no intermediate poses
CONTINUATION_STEP = 0.05


def angle_rows(equations: tuple[Equation, ...]) -> np.ndarray:
    """Which rows of a group's stacked equations are angles (ANGLE, GEAR), the others lengths.

    >>> angle_rows((Equation("HINGE", "1", "2"), Equation("ANGLE", "2", "0"))).tolist()
    [False, False, True]
    """
    return np.array(
        [eq.kind in ("ANGLE", "GEAR") for eq in equations for _ in range(eq.size)], dtype=bool
    )


def scaled_jacobian(jac: np.ndarray, length: float, angles: np.ndarray) -> np.ndarray:
    """The Jacobian in the sketch's unit of length: θ columns / ``length``, ``angles`` rows × it.

    The same matrix for a mechanism and any scaled copy of it (the idea of
    :func:`structure.rigidity.dimensionless_jacobian`), so one relative
    tolerance serves every unit of length. A step ``dz`` solved against it
    is turned back by dividing its θ entries by ``length``.
    """
    scaled = jac.copy()
    scaled[..., 2::3] /= length
    scaled[..., angles, :] *= length
    return scaled


def scaled_residual(phi: np.ndarray, length: float, angles: np.ndarray) -> np.ndarray:
    """The residual with its ``angles`` rows × ``length``: every row a length."""
    if not angles.any():
        return phi
    scaled = phi.copy()
    scaled[..., angles] *= length
    return scaled


def newton_pose(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray) -> None:
    """Newton on one pose (arrays of one row) from the current ``q`` of the group's links.

    Raises
    ------
    AssemblyError
        The residual stays above ``1e-9`` of the sketch's size.
    """
    tol = 1e-13 * plan.length
    angles = angle_rows(step.equations)
    norm, taken = math.inf, 0
    for taken in range(1, _MAX_NEWTON + 1):  # noqa: B007 - the count is reported
        phi, jac, _, _ = group_system(step.links, step.equations, q, {}, 1)
        phi = scaled_residual(phi, plan.length, angles)
        norm = float(np.linalg.norm(phi))
        if norm <= tol:
            return
        dz = np.linalg.lstsq(scaled_jacobian(jac, plan.length, angles)[0], -phi[0], rcond=None)[0]
        dz[2::3] /= plan.length
        if not _line_search(step, plan.length, q, dz, norm):
            break  # no step along dz lowers the residual: Newton is stuck
    if norm > 1e-9 * plan.length:
        raise AssemblyError.at(
            step.label,
            inputs,
            f"its pairs do not close (residual {norm * plan.unit:.3g} m after {taken} Newton "
            "steps)",
            plan.driver_kinds,
        )


def _line_search(step: GroupStep, length: float, q: dict, dz: np.ndarray, norm: float) -> bool:
    """Move the group's links along the Newton step ``dz``, halved until the residual drops.

    The residual is measured as :func:`newton_pose` measures it (angle rows × ``length``).
    Returns whether it dropped (else the links are left at the smallest step tried).
    """
    angles = angle_rows(step.equations)
    base = {link: q[link].copy() for link in step.links}
    step_size = 1.0
    while True:
        for i, link in enumerate(step.links):
            q[link] = base[link] + step_size * dz[3 * i : 3 * i + 3]
        phi = group_system(step.links, step.equations, q, {}, 1)[0]
        trial = float(np.linalg.norm(scaled_residual(phi, length, angles)))
        if trial < norm:
            return True
        if step_size < 1e-6:
            return False
        step_size /= 2


def _sequential(
    step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray, k: int, start: dict
) -> dict[str, np.ndarray]:
    """Newton on pose ``k`` alone, from ``start`` (link -> (3,))."""
    one = {link: value[k : k + 1] for link, value in q.items()}
    for link in step.links:
        one[link] = start[link][None, :].copy()
    newton_pose(step, plan, one, inputs[k])
    return {link: one[link][0] for link in step.links}


def _chunk_size(plan: SolvePlan, inputs: np.ndarray) -> int:
    """Poses per batched Newton chunk: about ``_CHUNK_SPAN`` of input at the typical step."""
    n = inputs.shape[0]
    scale = plan.driver_scale
    steps = np.max(np.abs(np.diff(inputs, axis=0)) / scale, axis=1) if n > 1 else np.zeros(1)
    typical = float(np.median(steps)) if len(steps) else 0.0
    return int(np.clip(_CHUNK_SPAN / typical, 8, _CHUNK_MAX)) if typical > 0 else 8


def _predicted(
    links: tuple[str, ...], out: dict, inputs: np.ndarray, k: int, idx: np.ndarray
) -> dict[str, np.ndarray]:
    """The poses ``idx`` extrapolated in the input from the solutions before ``k``.

    A quadratic through the last three solutions (k−3, k−2, k−1), by their
    distances along the inputs (a pose the path reaches by turning back at
    k − 1 at a distance behind); a line through two when only two are solved
    (or the three are not distinct); the last solution with only one.
    """
    if k < 2:
        return {link: np.broadcast_to(out[link][k - 1], (len(idx), 3)).copy() for link in links}
    here = inputs[k - 1]
    back1 = -float(np.linalg.norm(inputs[k - 2] - here))
    back2 = 0.0
    if k >= 3:
        back2 = back1 - float(np.linalg.norm(inputs[k - 3] - inputs[k - 2]))
    ahead = inputs[idx] - here
    reach = np.linalg.norm(ahead, axis=1)
    # a pose the path reaches by turning back lies behind: the same way as the last step
    reach = np.where(ahead @ (here - inputs[k - 2]) < 0.0, -reach, reach)
    if back1 == 0.0:
        return {link: np.broadcast_to(out[link][k - 1], (len(idx), 3)).copy() for link in links}
    if k < 3 or back2 == back1:
        weights = [(1.0 - reach / back1, k - 1), (reach / back1, k - 2)]
    else:  # Lagrange weights of the nodes 0, back1, back2 at the distances reach
        w0 = (reach - back1) * (reach - back2) / (back1 * back2)
        w1 = reach * (reach - back2) / (back1 * (back1 - back2))
        w2 = reach * (reach - back1) / (back2 * (back2 - back1))
        weights = [(w0, k - 1), (w1, k - 2), (w2, k - 3)]
    return {
        link: sum(w[:, None] * out[link][j] for w, j in weights)  # type: ignore[misc]
        for link in links
    }


def _batched_newton(step: GroupStep, plan: SolvePlan, chunk: dict, size: int) -> bool:
    """Newton over a chunk of poses at once (``chunk`` updated in place); True if it converged.

    The chunk's Jacobian is inverted once and kept for the following steps
    (which need the residual only), renewed every ``_KEEP_JACOBIAN`` steps.
    """
    tol = 1e-13 * plan.length
    angles = angle_rows(step.equations)
    inverse = None
    for iteration in range(_CHUNK_ITERATIONS):
        if iteration % _KEEP_JACOBIAN == 0:
            phi, jac, _, _ = group_system(step.links, step.equations, chunk, {}, size)
        else:
            phi = group_residual(step.equations, chunk, size)
        phi = scaled_residual(phi, plan.length, angles)
        worst = float(np.max(np.abs(phi)))
        if worst <= tol:
            return True
        if iteration % _KEEP_JACOBIAN == 0:
            try:
                inverse = np.linalg.inv(scaled_jacobian(jac, plan.length, angles))
            except np.linalg.LinAlgError:
                return False
        dz = -np.einsum("nij,nj->ni", inverse, phi)
        dz[:, 2::3] /= plan.length
        for i, link in enumerate(step.links):
            chunk[link] = chunk[link] + dz[:, 3 * i : 3 * i + 3]
    return False


def follow(step: GroupStep, plan: SolvePlan, q: dict, inputs: np.ndarray, start: dict) -> None:
    """Solve a Newton group for every pose, following the inputs in order.

    The first pose starts from ``start``; then chunks of poses start from a
    quadratic extrapolation of the last three solutions and run one batched
    Newton together. A chunk where any pose fails to converge, or lands farther from
    its prediction than the step between poses allows (another assembly mode),
    is redone pose by pose from the previous solution. The group's links'
    poses are stored in ``q``.

    Raises
    ------
    AssemblyError
        At the first pose where the group does not close.
    """
    n = inputs.shape[0]
    links = step.links
    out = {link: np.zeros((n, 3)) for link in links}
    first = _sequential(step, plan, q, inputs, 0, start)
    for link in links:
        out[link][0] = first[link]
    k = 1
    size = _chunk_size(plan, inputs)
    while k < n:
        stop = min(n, k + size)
        idx = np.arange(k, stop)
        chunk = {name: value[idx] for name, value in q.items()}
        predicted = _predicted(links, out, inputs, k, idx)
        for link in links:
            chunk[link] = predicted[link].copy()
        converged = _batched_newton(step, plan, chunk, len(idx))
        jumps = max(float(np.max(np.abs(chunk[link] - predicted[link])[:, 2])) for link in links)
        if converged and jumps <= _MODE_JUMP:
            for link in links:
                out[link][idx] = chunk[link]
        else:
            for j in idx:
                solved = _sequential(
                    step, plan, q, inputs, int(j), {link: out[link][j - 1] for link in links}
                )
                for link in links:
                    out[link][j] = solved[link]
        k = stop
    for link in links:
        q[link] = out[link]


def needs_continuation(plan: SolvePlan) -> bool:
    """Whether some step is solved by Newton (so far-apart inputs need intermediate poses)."""
    return any(step.group is None or step.group.kind is None for step in plan.steps)


def densified(
    plan: SolvePlan, inputs: np.ndarray, origin: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Inputs with intermediate rows from the sketch (or ``origin``) on, so Newton never jumps far.

    Returns the rows and, for each row of ``inputs``, its index among them.
    """
    scale = plan.driver_scale
    start = np.zeros((1, inputs.shape[1])) if origin is None else np.reshape(origin, (1, -1))
    previous = np.vstack([start, inputs[:-1]])
    jump = np.max(np.abs(inputs - previous) / scale, axis=1) if len(scale) else np.zeros(0)
    pieces = np.ceil(jump / CONTINUATION_STEP)
    if not len(pieces) or float(pieces.max()) <= 1.0:  # no step too long: the rows as they are
        return inputs, np.arange(len(inputs))
    rows = int(min(float(np.sum(np.maximum(pieces, 1.0))), 2.0**62))
    check_poses(
        plan,
        rows,
        rates=False,
        what=f"following these inputs from the sketch through {rows} intermediate poses (one "
        f"every {CONTINUATION_STEP:g} rad, or {CONTINUATION_STEP:g} of the sketch's size for a "
        "sliding driver)",
        advice="give inputs nearer the sketch and to each other",
    )
    pieces = np.maximum(1, pieces).astype(int)
    picks = np.cumsum(pieces) - 1
    # row i's pieces: previous_i + (input_i − previous_i)·k/pieces_i, k = 1 … pieces_i
    owner = np.repeat(np.arange(len(inputs)), pieces)
    k = np.arange(len(owner)) - np.repeat(picks - pieces + 1, pieces) + 1
    fraction = (k / pieces[owner])[:, None]
    rows = previous[owner] + (inputs[owner] - previous[owner]) * fraction
    return rows, picks
