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

__all__ = ["Watch", "suspect_steps"]


class Watch(list):
    """The ``(group label, step indices)`` the closed forms note, to be looked into.

    ``breaks`` are the steps (step k: from row k to row k + 1) that join
    pieces of a path rather than follow it, whose two rows say nothing about
    each other.
    """

    def __init__(self, breaks: np.ndarray | None = None) -> None:
        super().__init__()
        self.breaks = np.zeros(0, dtype=int) if breaks is None else np.asarray(breaks, dtype=int)


def suspect_steps(
    path: np.ndarray, values: np.ndarray, breaks: np.ndarray | None = None
) -> np.ndarray:
    """The steps of ``path`` (N, drivers) where ``values`` (N,) may dip to zero between rows.

    ``path`` is in units of scale (radians, or the sketch's size), ``values``
    dimensionless (a squared length over the sketch's size squared), both
    sampled at the rows. At each local minimum of a run's samples (and at a
    run's end when the end is lowest), a parabola through the minimum and its
    two neighbours, by their distances along the run, gives the low point
    between them; when that lies between two samples and is no higher than
    the rise over one step (how far the higher neighbour stands above the
    minimum), the two steps beside the minimum are suspect. A run of one step
    is suspect when its lower value is no higher than its rise. A path of
    fewer than three distinct rows is not looked into.

    Returns the suspect steps' indices (step k: from row k to row k + 1),
    sorted.
    """
    n = len(values)
    if n < 3 or not _has_low(values):
        return np.zeros(0, dtype=int)
    moved = np.any(path[1:] != path[:-1], axis=1)
    rows = np.concatenate([[0], np.flatnonzero(moved) + 1])  # each row once
    m = len(rows)
    if m < 3:
        return np.zeros(0, dtype=int)
    x, y = path[rows], values[rows]
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


def _has_low(y: np.ndarray) -> bool:
    """Whether the samples have a local minimum or an end below its neighbour.

    Samples that fall or rise all along have neither, on any run they could
    be cut into (a run turning back rises again from its turn): nothing to
    look into then, and a long sweep is done with one pass.
    """
    mid = y[1:-1]
    return bool(y[0] < y[1] or y[-1] < y[-2] or ((mid <= y[:-2]) & (mid <= y[2:])).any())


def _dips(y, length, jump, turn, starts, ends) -> np.ndarray:
    """The steps beside the triples' minima whose parabola dips low between samples."""
    m = len(y)
    c = np.arange(1, m - 1)
    valid = ~jump[c - 1] & ~jump[c] & ~turn[c]  # c − 1, c, c + 1 on one run
    y0, y1, y2 = y[c - 1], y[c], y[c + 1]
    low = (y1 <= y0) & (y1 <= y2)
    low |= starts[c - 1] & (y0 < y1)  # the run's first sample lowest
    low |= ends[c + 1] & (y2 < y1)  # its last
    keep = valid & low
    c, y0, y1, y2 = c[keep], y0[keep], y1[keep], y2[keep]
    p, q = length[c - 1], length[c]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        span = p * q * (p + q)
        a = (q * (y0 - y1) + p * (y2 - y1)) / span
        b = (p * p * (y2 - y1) - q * q * (y0 - y1)) / span
        vertex = -b / (2.0 * a)
        bottom = y1 - b * b / (4.0 * a)
    rise = np.maximum(y0, y2) - y1
    between = (a > 0.0) & (vertex > -p) & (vertex < q) & (bottom <= rise)
    flat = ~(a > 0.0) & (np.minimum(np.minimum(y0, y1), y2) <= 0.0)
    near = between | flat
    return np.concatenate([c[near] - 1, c[near]])


def _single_steps(y, starts, ends, jump) -> np.ndarray:
    """Runs of one step (a start followed by an end), suspect when low for their rise."""
    k = np.flatnonzero(starts[:-1] & ends[1:] & ~jump)
    lower = np.minimum(y[k], y[k + 1])
    return k[lower <= np.abs(y[k + 1] - y[k])]
