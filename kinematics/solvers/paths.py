"""Paths of driver inputs: where a quantity sampled along one may dip to zero between samples.

A sweep's rows are a path from the sketch: consecutive rows are joined by a
straight step. A closed-form dyad samples, at each row, the square of what
keeps its two assembly modes apart (:func:`kinematics.solvers.dyads.frame_dyad`);
it is smooth along the path while both modes exist and touches zero where they
meet. :func:`suspect_steps` finds the steps where it may have dipped to zero
unseen, for the solve to look into with finer steps
(:mod:`kinematics.solvers.branches`).

What the samples say must not depend on how the path is written: a row
repeated (a step of length zero) says nothing, and a path that turns back
(the next step against the last) has at the turn a sample that is the end of
what the path covered, not a point between two sides. So the path is cut
into runs: at the turns (the sample shared by both runs), at the steps that
are jumps rather than path (``breaks``, between the pieces of a subdivided
path), with repeated rows taken once; the samples of each run lie along it
by their distance on the path, and a dip is looked for between them only.

>>> import numpy as np
>>> x = np.array([[0.0], [0.1], [0.2], [0.3], [0.4]])
>>> suspect_steps(x, np.array([4.0, 1.0, 0.0001, 1.0, 4.0])).tolist()   # a dip at 0.2
[1, 2]
>>> suspect_steps(x, np.array([4.0, 3.0, 2.0, 1.0, 0.5])).tolist()      # going down, no dip
[]
>>> back = np.array([[0.0], [0.1], [0.2], [0.1], [0.0]])                 # turning back at 0.2
>>> suspect_steps(back, np.array([4.0, 2.25, 1.0, 2.25, 4.0])).tolist()
[]
"""

from __future__ import annotations

import numpy as np

__all__ = ["Watch", "is_straight", "suspect_steps"]


class Watch(list):
    """The ``(group label, step indices)`` the closed forms note, to be looked into.

    ``breaks`` are the steps (step k: from row k to row k + 1) that join
    pieces of a path rather than follow it, whose two rows say nothing about
    each other.
    """

    def __init__(self, breaks: np.ndarray | None = None) -> None:
        super().__init__()
        self.breaks = np.zeros(0, dtype=int) if breaks is None else np.asarray(breaks, dtype=int)
        self._path: np.ndarray | None = None
        self._straight = False

    def straight(self, path: np.ndarray) -> bool:
        """Whether ``path`` is one run (:func:`is_straight`), found once for the solve's path."""
        if path is not self._path:
            self._path, self._straight = path, is_straight(path) and not len(self.breaks)
        return self._straight


def suspect_steps(
    path: np.ndarray,
    values: np.ndarray,
    breaks: np.ndarray | None = None,
    *,
    path_scale: np.ndarray | float = 1.0,
    value_scale: float = 1.0,
    watch: Watch | None = None,
) -> np.ndarray:
    """The steps of ``path`` (N, drivers) where ``values`` (N,) may dip to zero between rows.

    ``path / path_scale`` is in units of scale (radians, or the sketch's
    size), ``values / value_scale`` dimensionless (a squared length over the
    sketch's size squared), both sampled at the rows. At each local minimum
    of a run's samples (and at a run's end when the end is lowest), a
    parabola through the minimum and its two neighbours, by their distances
    along the run, gives the low point between them; when that lies between
    two samples and is no higher than the rise over one step (how far the
    higher neighbour stands above the minimum), the two steps beside the
    minimum are suspect. A run of one step is suspect when its lower value is
    no higher than its rise. A path of fewer than three distinct rows is not
    looked into. ``watch`` keeps whether the path is one run, for the next
    quantity sampled along the same path.

    Returns the suspect steps' indices (step k: from row k to row k + 1),
    sorted.
    """
    n = len(values)
    lows = _lows(values) if n >= 3 else ()
    if not len(lows):
        return np.zeros(0, dtype=int)
    unbroken = breaks is None or not len(breaks)
    if watch.straight(path) if watch is not None else unbroken and is_straight(path):
        return _straight_dips(lows, path, values, path_scale, value_scale)
    moved = np.any(path[1:] != path[:-1], axis=1)
    rows = np.concatenate([[0], np.flatnonzero(moved) + 1])  # each row once
    m = len(rows)
    if m < 3:
        return np.zeros(0, dtype=int)
    x, y = path[rows] / path_scale, values[rows] / value_scale
    step = np.diff(x, axis=0)  # (m − 1, drivers)
    length = np.sqrt(np.einsum("ij,ij->i", step, step))
    jump = np.zeros(m - 1, dtype=bool)  # a step across a break of the path
    if breaks is not None and len(breaks):
        jump[np.isin(rows[1:] - 1, breaks)] = True
    turn = np.zeros(m, dtype=bool)  # the path turns back at the sample
    turn[1:-1] = np.einsum("ij,ij->i", step[:-1], step[1:]) < 0.0
    # a run starts at the first sample, after a jump, or at a turn (shared with the run before)
    starts = np.zeros(m, dtype=bool)
    starts[0] = True
    starts[1:] |= jump
    starts |= turn
    ends = np.zeros(m, dtype=bool)
    ends[-1] = True
    ends[:-1] |= jump
    ends |= turn
    flagged = [_dips(y, length, jump, turn, starts, ends)]
    flagged.append(_single_steps(y, starts, ends, jump))
    out = np.unique(np.concatenate(flagged))
    return rows[out + 1] - 1  # the step into the row after, from the last repeat of the row before


def _lows(y: np.ndarray) -> np.ndarray:
    """The middles of the triples of samples whose middle (or an end) is lowest.

    Samples that fall or rise all along have none, on any run they could be
    cut into (a run turning back rises again from its turn): nothing to look
    into then, and a long sweep is done with one pass.
    """
    mid = y[1:-1]
    c = np.flatnonzero((mid <= y[:-2]) & (mid <= y[2:])) + 1
    ends = [k for k, low in ((1, y[0] < y[1]), (len(y) - 2, y[-1] < y[-2])) if low]
    return np.unique(np.concatenate([c, np.array(ends, dtype=int)])) if ends else c


def is_straight(path: np.ndarray) -> bool:
    """Whether every step of ``path`` goes on the way of the one before: one run.

    (No row repeated, no turn back; a sweep's rows, as a rule.)
    """
    step = np.diff(path, axis=0)
    if step.shape[1] == 1:
        on = step[:-1, 0] * step[1:, 0]
    else:
        on = np.einsum("ij,ij->i", step[:-1], step[1:])
    return bool((on > 0.0).all())


def _straight_dips(c, path, values, path_scale, value_scale) -> np.ndarray:
    """The suspect steps of a path of one run, looked at only at its samples' lows ``c``.

    The test of :func:`_dips` at far fewer places: a long sweep's samples
    have a few local minima, and only they (and a lowest end) are looked into.
    """
    x0, x1, x2 = (path[k] / path_scale for k in (c - 1, c, c + 1))
    p = np.sqrt(np.einsum("ij,ij->i", x1 - x0, x1 - x0))
    q = np.sqrt(np.einsum("ij,ij->i", x2 - x1, x2 - x1))
    y0, y1, y2 = (values[k] / value_scale for k in (c - 1, c, c + 1))
    near = _near(y0, y1, y2, p, q)
    return np.unique(np.concatenate([c[near] - 1, c[near]]))


def _dips(y, length, jump, turn, starts, ends, c=None) -> np.ndarray:
    """The steps beside the triples' minima whose parabola dips low between samples.

    ``c``: the middle samples to look at (all but the ends when None).
    """
    m = len(y)
    c = np.arange(1, m - 1) if c is None else c
    valid = ~jump[c - 1] & ~jump[c] & ~turn[c]  # c − 1, c, c + 1 on one run
    y0, y1, y2 = y[c - 1], y[c], y[c + 1]
    low = (y1 <= y0) & (y1 <= y2)
    low |= starts[c - 1] & (y0 < y1)  # the run's first sample lowest
    low |= ends[c + 1] & (y2 < y1)  # its last
    keep = valid & low
    c, y0, y1, y2 = c[keep], y0[keep], y1[keep], y2[keep]
    near = _near(y0, y1, y2, length[c - 1], length[c])
    return np.concatenate([c[near] - 1, c[near]])


def _near(y0, y1, y2, p, q) -> np.ndarray:
    """Whether the parabola through (−p, y0), (0, y1), (q, y2) dips as low as its rise, between.

    The rise is how far the higher neighbour stands above ``y1``: a minimum
    well above it is a real one, which finer steps leave in place; a low point
    outside the two steps is not on the way.
    """
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        span = p * q * (p + q)
        a = (q * (y0 - y1) + p * (y2 - y1)) / span
        b = (p * p * (y2 - y1) - q * q * (y0 - y1)) / span
        vertex = -b / (2.0 * a)
        bottom = y1 - b * b / (4.0 * a)
    rise = np.maximum(y0, y2) - y1
    between = (a > 0.0) & (vertex > -p) & (vertex < q) & (bottom <= rise)
    flat = ~(a > 0.0) & (np.minimum(np.minimum(y0, y1), y2) <= 0.0)
    return between | flat


def _single_steps(y, starts, ends, jump) -> np.ndarray:
    """Runs of one step (a start followed by an end), suspect when low for their rise."""
    k = np.flatnonzero(starts[:-1] & ends[1:] & ~jump)
    lower = np.minimum(y[k], y[k + 1])
    return k[lower <= np.abs(y[k + 1] - y[k])]
