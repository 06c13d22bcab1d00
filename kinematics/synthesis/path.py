"""Path generation: a four-bar or six-bar whose coupler point P passes through N targets.

With prescribed timing each target has the crank's angle at which P should
be there, and the error is the distance from P at that angle to the target.
Without, the error is each target's distance to the coupler curve: the
crank's angle at each target is an unknown too, and P must meet the targets
in their order, one way round or the other within one turn (an order defect
is refused). A closed path repeats its first target last.

The search is scipy's ``differential_evolution`` (seeded, so a run is
reproduced exactly; ``vectorized`` with ``updating='deferred'``, so a whole
generation is evaluated at once with numpy by the solvers' closed forms and
branch rule, :func:`~kinematics.synthesis.linkages.linkage_poses`), then
``least_squares`` from the best few distinct candidates of each search.
Several independent searches (``restarts``, seeds ``seed``, ``seed + 1``,
..., alternating two variants of the method) run in this process, in local
processes (``jobs``) or on Dask (``scheduler``), with the same answer
whichever.

The search does not move what least squares can fit in closed form. A
similarity of the plane (``u ↦ z·u + w`` in complex numbers u = x + iy) moves
a linkage without changing its motion, and P is fixed in the frame of its
link (origin o, unit axis e at each pose: ``P = o + e·(p + iq)``). With
``m = z·(p + iq)`` the placed coupler point ``z·o + m·e + w`` is linear in
(z, m, w), so for the crank's angles at the targets the placement (origin,
turn and size) and P's place on its link that bring P nearest the targets
are a linear least-squares problem, solved for every candidate at once. The
search runs over the linkage's shape alone: the other links' lengths as
logarithms of their ratios to the coupler (within the ratio bound), the
crank's angle to the ground at the first target, the six-bars' pins, the
assembly modes, and without timing the crank's steps between the targets
(as shares of a turn: every candidate meets the targets in order). A frame
fixed by the problem (``fixed`` holds ``ax``, ``ay`` and ``theta0``) leaves
only the size to fit, about A; a frame only bounded is searched.

Constraints: the crank turns fully (Grashof, the crank or the ground the
shortest link; or, with ``allow_rocker`` and timing, the input rocks over the
targets' range on one assembly mode); every dyad's transmission angle stays
within [μ_min, 180° − μ_min] (30° by default) over the motion (the
four-bar's exactly, at its extremes; a six-bar's second dyad at
:data:`_TURN` poses of a turn, kept :data:`_MU_MARGIN` off the bound); the
longest link is at most ``ratio_max`` times the shortest; the linkage lies
within :data:`REACH` target sizes of the targets. A candidate that breaks one
of them, does not assemble, or would change branch (a dyad's modes meeting)
is infeasible: it ranks after every feasible candidate whatever its error,
and is never returned. The design returned is checked again by the
group-by-group solvers over its whole motion and through its targets in
order (:mod:`.defects`), its transmission angle included.

Every length is scaled by the targets' size, so the answer does not depend
on the unit of length.
"""

from __future__ import annotations

import enum
import math
import time
from collections import Counter
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import differential_evolution, least_squares

from structure.errors import MechanismError
from structure.model import Mechanism
from structure.parallel import ordered_map

from ..errors import InfeasibleDesignError, SynthesisError
from .defects import check_targets, points_at, whole_cycle
from .linkages import (
    LENGTHS,
    PARAMETERS,
    Linkage,
    coupler_frame,
    design_mechanism,
    grashof_kind,
    is_crank,
    link_lengths,
    linkage_poses,
    place,
    target_records,
)

__all__ = [
    "MAX_TARGETS",
    "REACH",
    "PathDesign",
    "PathProblem",
    "synthesize_path",
]

#: the most targets a path may have
MAX_TARGETS = 100
#: how far (in target sizes, from the targets' centre) a linkage's pivots and links may reach
REACH = 10.0
#: the value an infeasible candidate gets, plus its violation: above any feasible error
_INFEASIBLE = 1e6
#: samples of a crank turn where the constraints are not in closed form (six-bars, rockers)
_TURN = 96
#: the variants of differential evolution the searches take in turn: strategy, crossover
_VARIANTS = (("best1bin", 0.9), ("currenttobest1bin", 0.7))
#: candidates of each search polished by least squares
_POLISHED = 4
#: the margin (rad) a sampled transmission angle keeps from its bound in the search
_MU_MARGIN = math.radians(0.25)
#: the largest transmission angle shortfall (degrees) the solvers' check forgives
_MU_SLACK = 1e-6


@dataclass(frozen=True)
class PathProblem:
    """A path to generate.

    ``targets`` (N, 2) in metres; ``crank_deg`` the crank's angle at each
    (timing; None without), measured from the +x axis, or from the ground
    line A→D with ``crank_from_ground``; ``bounds`` overrides the search range
    of a parameter (its name -> (low, high), lengths in metres, angles in
    radians; ``side`` from -1 to 1 picks the assembly mode by its sign);
    ``fixed`` holds parameters at a value (e.g. ``{"ax": 0, "ay": 0,
    "theta0": 0}``). ``population`` is the number of candidates per searched
    parameter, ``generations`` the generations of each of the ``restarts``
    searches.
    """

    targets: np.ndarray
    crank_deg: np.ndarray | None = None
    linkage: Linkage = Linkage.FOURBAR
    transmission_min: float = 30.0
    ratio_max: float = 10.0
    allow_rocker: bool = False
    seed: int = 0
    restarts: int = 4
    generations: int = 600
    population: int = 15
    bounds: dict[str, tuple[float, float]] = field(default_factory=dict)
    fixed: dict[str, float] = field(default_factory=dict)
    crank_from_ground: bool = False


@dataclass(frozen=True)
class PathDesign:
    """A path generator and its errors.

    ``x`` the design's numbers (metres and radians, names in ``PARAMETERS``);
    ``errors`` each target's distance (metres); ``inputs_deg`` the crank's
    rotation from the sketch (the first target) at each target;
    ``transmission_deg`` the least and largest transmission angle over the
    motion (every dyad); ``grashof`` the four-bar's type; ``evaluations``
    the candidates evaluated; ``rejections`` how many each constraint refused;
    ``in_order`` whether the targets are met in order (always, for a design
    returned).
    """

    problem: PathProblem
    x: np.ndarray
    mechanism: Mechanism
    errors: np.ndarray
    error_max: float
    error_rms: float
    inputs_deg: np.ndarray
    transmission_deg: tuple[float, float]
    grashof: str
    evaluations: int
    seconds: float
    rejections: dict[str, int]
    in_order: bool

    @property
    def parameters(self) -> dict[str, float]:
        """The design's numbers by name."""
        return dict(zip(PARAMETERS[self.problem.linkage], map(float, self.x), strict=True))

    @property
    def error_sum_squares(self) -> float:
        """The sum of the targets' squared distances (square metres)."""
        return float(np.sum(self.errors**2))


# ------------------------------------------------------------------ the problem, scaled
class _Placement(enum.Enum):
    """How a candidate is placed in the plane after the search proposes its shape."""

    FREE = "similarity"  # origin, turn and size fitted
    SIZE = "size about A"  # the frame fixed: only the size fitted, about A
    NONE = "as searched"  # the placement is among the searched parameters


_FRAME = ("ax", "ay", "theta0")
_SIDES = ("side", "side2")


@dataclass(frozen=True)
class _Scaled:
    """The problem in the targets' own scale (centre 0, size 1); the search's coordinates."""

    linkage: Linkage
    targets: np.ndarray  # (N, 2), scaled
    offsets: np.ndarray | None  # crank angle of each target less the first's (rad)
    placement: _Placement
    names: tuple[str, ...]  # the parameters searched
    fixed: dict[str, float]  # the others, scaled (in the search's frame)
    low: np.ndarray
    high: np.ndarray
    user: dict[str, tuple[float, float]]  # the problem's own fixed values and bounds, scaled
    logs: frozenset[str]  # the lengths searched by their logarithm
    solve_point: bool  # P's place on its link fitted with the placement (not searched)
    transmission_min: float  # rad
    ratio_max: float
    allow_rocker: bool
    closed: bool  # the first and last targets coincide
    crank_from_ground: float | None  # the first target's crank angle from the ground (rad)


_DEFAULTS = {
    "ax": (-3.0, 3.0),
    "ay": (-3.0, 3.0),
    "gx": (-3.0, 3.0),
    "gy": (-3.0, 3.0),
    "theta0": (-math.pi, math.pi),
    "phi1": (-math.pi, math.pi),
    "side": (-1.0, 1.0),
    "side2": (-1.0, 1.0),
    "sense": (-1.0, 1.0),
    "d": (0.1, 4.0),
    "a": (0.05, 2.0),
    "b": (0.1, 4.0),
    "c": (0.1, 4.0),
    "e": (0.1, 4.0),
    "f": (0.1, 4.0),
    "p": (-3.0, 3.0),
    "q": (-3.0, 3.0),
    "ex": (-3.0, 3.0),
    "ey": (-3.0, 3.0),
    "hx": (-3.0, 3.0),
    "hy": (-3.0, 3.0),
}
# the shape's ranges with the coupler b = 1 (the placement gives the size); the other
# links are searched by the logarithm of their ratio to the coupler, within the ratio bound
_SHAPE = {
    "p": (-3.0, 3.0),
    "q": (-3.0, 3.0),
    "ex": (-3.0, 3.0),
    "ey": (-3.0, 3.0),
    "hx": (-3.0, 3.0),
    "hy": (-3.0, 3.0),
    "gx": (-4.0, 4.0),
    "gy": (-4.0, 4.0),
}
_RATIOS = ("d", "a", "c", "e", "f")


def _placement(problem: PathProblem) -> _Placement:
    """How candidates are placed: fitted wholly, fitted in size about A, or as searched."""
    user = set(problem.fixed) | set(problem.bounds)
    if user & {"gx", "gy"}:
        return _Placement.NONE
    frame = set(_FRAME)
    if frame <= set(problem.fixed) and not frame & set(problem.bounds):
        return _Placement.NONE if "d" in user else _Placement.SIZE
    if user & (frame | {"d"}):
        return _Placement.NONE
    if "phi1" in user and not (problem.crank_deg is not None and problem.crank_from_ground):
        return _Placement.NONE
    return _Placement.FREE


def _scale(problem: PathProblem) -> tuple[_Scaled, np.ndarray, float]:
    t = np.asarray(problem.targets, dtype=float)
    centre = t.mean(axis=0)
    size = float(np.max(np.linalg.norm(t - centre, axis=1)))
    shift = {"ax": 0, "gx": 0, "ay": 1, "gy": 1}

    def scaled(name: str, value: float) -> float:
        if name in shift:
            return (value - centre[shift[name]]) / size
        return value / size if name in LENGTHS else value

    timed = problem.crank_deg is not None
    mode = _placement(problem)
    reduced = mode is not _Placement.NONE  # the placement fitted, not searched
    fixed = {n: scaled(n, v) for n, v in problem.fixed.items()}
    from_ground = None
    if timed and problem.crank_from_ground:
        from_ground = math.radians(float(problem.crank_deg[0]))
    if reduced and mode is _Placement.FREE:
        fixed.update({"ax": 0.0, "ay": 0.0, "theta0": 0.0, "b": 1.0})
    elif reduced:
        fixed["b"] = 1.0
    if from_ground is not None and "theta0" in fixed:
        fixed["phi1"] = fixed["theta0"] + from_ground
    solve_point = not {"p", "q"} & (set(problem.fixed) | set(problem.bounds))
    if solve_point:  # fitted with the placement, from the frame P is fixed in
        fixed.update({"p": 0.0, "q": 0.0})
    names = [n for n in PARAMETERS[problem.linkage] if n not in fixed]
    if from_ground is not None:
        names = [n for n in names if n != "phi1"]
    closed = bool(np.linalg.norm(t[0] - t[-1]) <= 1e-9 * size)
    if not timed:  # the crank's steps from target to target, as weights (see _angles)
        names += ["sense"] + [f"u{k}" for k in range(1, len(t) + (0 if closed else 1))]
    ranges = _SHAPE if reduced else {}
    low, high = [], []
    for n in names:
        if n.startswith("u"):
            lo, hi = 0.02, 1.0
        elif n in problem.bounds:
            lo, hi = problem.bounds[n]
            lo, hi = scaled(n, lo), scaled(n, hi)
        elif reduced and n in _RATIOS:
            lo, hi = -math.log(problem.ratio_max), math.log(problem.ratio_max)
        else:
            lo, hi = ranges.get(n, _DEFAULTS[n])
        low.append(min(lo, hi))
        high.append(max(lo, hi))
    user = {n: (v, v) for n, v in problem.fixed.items()}
    user.update({n: b for n, b in problem.bounds.items() if n not in user})
    user = {n: tuple(sorted((scaled(n, lo), scaled(n, hi)))) for n, (lo, hi) in user.items()}
    offsets = None
    if timed:
        offsets = np.radians(problem.crank_deg - problem.crank_deg[0])
    scaled_targets = (t - centre) / size
    s = _Scaled(
        problem.linkage,
        scaled_targets,
        offsets,
        mode,
        tuple(names),
        fixed,
        np.array(low),
        np.array(high),
        user,
        frozenset(n for n in names if reduced and n in _RATIOS and n not in problem.bounds),
        solve_point,
        math.radians(problem.transmission_min),
        problem.ratio_max,
        problem.allow_rocker,
        closed,
        from_ground,
    )
    return s, centre, size


def _full(s: _Scaled, z: np.ndarray) -> np.ndarray:
    """Every parameter's column from the searched ones ``z`` (designs, searched)."""
    z = np.atleast_2d(z)
    columns = []
    names = PARAMETERS[s.linkage]
    for n in names:
        if n in s.fixed:
            columns.append(np.full(len(z), s.fixed[n]))
        elif n in s.logs:
            columns.append(np.exp(z[:, s.names.index(n)]))
        elif n in s.names:
            columns.append(z[:, s.names.index(n)])
        else:  # φ1 tied to the ground's angle (crank angles measured from the ground)
            columns.append(z[:, s.names.index("theta0")] + s.crank_from_ground)
    return np.column_stack(columns)


# ------------------------------------------------------------------ one generation at once
@dataclass(frozen=True)
class _Evaluation:
    """The value of each candidate, whether it is feasible, what refused the others, and the
    candidates as placed (scaled rows) with their crank angles at the targets."""

    value: np.ndarray
    feasible: np.ndarray
    refused: dict[str, np.ndarray]
    placed: np.ndarray
    angles: np.ndarray  # the crank's angle at each target, as placed


def _column(s: _Scaled, x: np.ndarray, name: str) -> np.ndarray:
    return x[:, PARAMETERS[s.linkage].index(name)]


def _similarity(
    mode: _Placement, p: np.ndarray, t: np.ndarray, anchor: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The similarity ``u ↦ z·u + w`` bringing points ``p`` (designs, N; complex) nearest ``t``.

    FREE: any similarity (closed form); SIZE: a growth about ``anchor``
    (designs; complex) only; NONE: the identity. A fitted size that is not
    positive gives z = 0 (the caller refuses it).
    """
    n = len(p)
    if mode is _Placement.NONE:
        return np.ones(n, dtype=complex), np.zeros(n, dtype=complex)
    if mode is _Placement.SIZE:
        u, v = p - anchor[:, None], t - anchor[:, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            k = (np.conj(u) * v).real.sum(axis=1) / (np.abs(u) ** 2).sum(axis=1)
        k = np.where(np.isfinite(k) & (k > 0), k, 0.0)
        return k.astype(complex), anchor * (1 - k)
    pm, tm = p.mean(axis=1), t.mean(axis=1)
    u, v = p - pm[:, None], t - tm[:, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        z = (np.conj(u) * v).sum(axis=1) / (np.abs(u) ** 2).sum(axis=1)
    z = np.where(np.isfinite(z), z, 0.0)
    return z, tm - z * pm


def _solve(a: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Least squares of the stacked systems ``a @ v ≈ t`` (designs, rows, k): v (designs, k)."""
    ah = np.conj(np.swapaxes(a, 1, 2))
    g = ah @ a
    g = g + 1e-14 * np.trace(g, axis1=1, axis2=2).real[:, None, None] * np.eye(a.shape[2])
    rhs = ah @ np.broadcast_to(t, a.shape[:2])[..., None]
    with np.errstate(all="ignore"):
        try:
            return np.linalg.solve(g, rhs)[..., 0]
        except np.linalg.LinAlgError:
            return np.full(a.shape[::2], np.nan, dtype=a.dtype)


def _fit(
    s: _Scaled,
    mode: _Placement,
    o: np.ndarray,
    u: np.ndarray,
    pq: np.ndarray,
    t: np.ndarray,
    anchor: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The placement ``u ↦ z·u + w`` (and P's place ``pq`` on its link when the problem
    leaves it free) bringing ``P = o + u·pq`` nearest the targets ``t``.

    ``o``, ``u`` (designs, N; complex) are the origin and axis of the frame P
    is fixed in, at each target's pose. With ``m = z·pq`` the targets are
    linear in (z, m, w): ``t ≈ z·o + m·u + w``, solved by least squares (FREE;
    SIZE: z real and w = A·(1 − z); NONE: z = 1, w = 0). A fit that is not a
    placement (z = 0, a size not positive) gives z = 0 (refused by the caller).
    """
    n = len(o)
    if not s.solve_point:
        z, w = _similarity(mode, o + u * pq[:, None], np.broadcast_to(t, o.shape), anchor)
        return z, w, pq
    if mode is _Placement.FREE:
        z, m, w = _solve(np.stack([o, u, np.ones_like(o)], axis=2), t).T
    elif mode is _Placement.SIZE:
        g, v = o - anchor[:, None], t[None] - anchor[:, None]
        cols = np.stack([g, u, 1j * u], axis=2)
        real = np.concatenate([cols.real, cols.imag], axis=1)
        k, mr, mi = _solve(real, np.concatenate([v.real, v.imag], axis=1)).T
        k = np.where(k > 0, k, 0.0)
        z, m, w = k.astype(complex), mr + 1j * mi, anchor * (1 - k)
    else:
        z, w = np.ones(n, dtype=complex), np.zeros(n, dtype=complex)
        m = (np.conj(u) * (t[None] - o)).sum(axis=1) / (np.abs(u) ** 2).sum(axis=1)
    ok = np.isfinite(z) & np.isfinite(m) & np.isfinite(w) & (np.abs(z) > 0)
    with np.errstate(all="ignore"):
        pq = np.where(ok, m / np.where(ok, z, 1.0), pq)
    return np.where(ok, z, 0.0), np.where(ok, w, 0.0), pq


def _angles_in_order(angles: np.ndarray, closed: bool) -> np.ndarray:
    """Whether the crank's angles (designs, N) go one way within one turn (a closed path's
    last target, the first again, a whole turn on)."""
    steps = np.diff(angles, axis=1)
    one_way = np.all(steps >= 0, axis=1) | np.all(steps <= 0, axis=1)
    span = np.abs(angles[:, -1] - angles[:, 0])
    turn = 2 * math.pi
    within = np.abs(span - turn) <= 1e-6 if closed else span < turn
    return one_way & within


def _angles(s: _Scaled, z: np.ndarray, x: np.ndarray) -> np.ndarray:
    """The crank's angle at each target (designs, N): from φ1, by the timing or by the search.

    Without timing the search proposes the angles: ``φ1`` at the first
    target, then the steps from target to target as shares of a turn (weights
    ``u1``, ``u2``, ... normalised to sum to one turn; an open path has one
    more weight, the rest of the turn after its last target), so the targets
    always come in order, one way round or the other by the sign of ``sense``.
    A closed path's last target is its first one, a turn on.
    """
    phi1 = _column(s, x, "phi1")[:, None]
    if s.offsets is not None:
        return phi1 + s.offsets[None, :]
    z = np.atleast_2d(z)
    weights = z[:, [s.names.index(n) for n in s.names if n.startswith("u")]]
    shares = np.cumsum(weights, axis=1) / weights.sum(axis=1, keepdims=True)
    n = len(s.targets)
    steps = np.concatenate([np.zeros((len(z), 1)), shares[:, : n - 1]], axis=1)
    sense = np.where(z[:, s.names.index("sense")] >= 0, 1.0, -1.0)[:, None]
    return phi1 + sense * 2 * math.pi * steps


def _evaluate(s: _Scaled, x: np.ndarray, angles: np.ndarray, *, fit: bool = True) -> _Evaluation:
    """Every candidate of ``x`` (designs, parameters; scaled) at once: value and feasibility.

    ``angles`` (designs, N) are the crank's angles at the targets (without
    timing they must come in order, :func:`_angles_in_order`). With ``fit``
    each candidate is placed first (see the module's text); without, it is
    taken where it is. The value of a feasible
    candidate is the sum of its targets' squared errors (in the targets'
    scale); an infeasible one gets :data:`_INFEASIBLE` plus how far it is from
    feasible.
    """
    n = len(x)
    phi1 = _column(s, x, "phi1")[:, None]
    lengths = link_lengths(s.linkage, x)
    crank = is_crank(*(_column(s, x, k) for k in ("d", "a", "b", "c")))
    rocks = s.offsets is not None and s.allow_rocker
    closes = np.ones(n, dtype=bool)
    grip = np.ones(n, dtype=bool)
    violation = np.zeros(n)
    worsts = []
    if s.linkage is Linkage.FOURBAR and not rocks:
        # a crank (Grashof) always closes; its transmission angle's extremes are exact
        worsts.append(_fourbar_worst(s, x))
    else:
        turn = np.linspace(0.0, 2 * math.pi, _TURN, endpoint=False)[None, :]
        if rocks:  # the motion the constraints hold over: a turn, or the targets' range
            span = np.linspace(0.0, s.offsets[-1], _TURN)[None, :]
            motion_phi = np.where(crank[:, None], phi1 + turn, phi1 + span)
        else:
            motion_phi = phi1 + turn
        motion = linkage_poses(s.linkage, x, motion_phi)
        for h2 in motion.heights:
            low = h2.min(axis=1)
            closes &= low > 1e-10
            violation += np.maximum(-low, 0.0)
        sampled = [np.minimum(mu, np.pi - mu).min(axis=1) for mu in motion.transmission]
        # the four-bar's exact over a crank's turn, at its extremes; the others sampled, so
        # kept off the bound between the samples
        worsts.append(np.where(crank, _fourbar_worst(s, x), sampled[0]))
        worsts += [worst - _MU_MARGIN for worst in sampled[1:]]
    for worst in worsts:
        grip &= worst >= s.transmission_min
        violation += np.maximum(s.transmission_min - worst, 0.0)
    ratio = lengths.max(axis=1) / np.maximum(lengths.min(axis=1), 1e-300)
    short = ratio <= s.ratio_max
    violation += np.maximum(ratio - s.ratio_max, 0.0) / s.ratio_max
    turns = crank | rocks
    violation += np.where(turns, 0.0, 1.0)
    targets = s.targets[:, 0] + 1j * s.targets[:, 1]
    anchor = _column(s, x, "ax") + 1j * _column(s, x, "ay")
    pq = _column(s, x, "p") + 1j * _column(s, x, "q")
    ordered = np.ones(n, dtype=bool)
    if s.offsets is None:
        ordered = _angles_in_order(angles, s.closed)
        violation += np.where(ordered, 0.0, 1.0)
    z, w = np.ones(n, dtype=complex), np.zeros(n, dtype=complex)
    at = linkage_poses(s.linkage, x, angles)
    o, u = coupler_frame(s.linkage, at, x)
    if fit:
        z, w, pq = _fit(s, s.placement, o, u, pq, targets, anchor)
    error2 = np.abs(z[:, None] * (o + u * pq[:, None]) + w[:, None] - targets[None]) ** 2
    x = x.copy()
    x[:, PARAMETERS[s.linkage].index("p")] = pq.real
    x[:, PARAMETERS[s.linkage].index("q")] = pq.imag
    placed_ok = np.abs(z) > 0
    placed = place(s.linkage, x, np.where(placed_ok, z, 1.0), w)
    reach = _reach(s, placed)
    near_enough = placed_ok & (reach <= REACH)
    violation += np.maximum(np.nan_to_num(reach, nan=1e3) - REACH, 0.0) / REACH
    feasible = closes & grip & short & turns & ordered & near_enough
    value = np.where(feasible, error2.sum(axis=1), _INFEASIBLE * (1.0 + violation))
    value = np.where(np.isfinite(value), value, _INFEASIBLE * 10)
    refused = {
        "crank (Grashof)": ~turns,
        "assembly": ~closes,
        "transmission angle": ~grip,
        "link-length ratio": ~short,
        "order of the targets": ~ordered,
        "size": ~near_enough,
    }
    angles = angles + np.angle(np.where(placed_ok, z, 1.0))[:, None]
    return _Evaluation(value, feasible, refused, placed, angles)


def _fourbar_worst(s: _Scaled, x: np.ndarray) -> np.ndarray:
    """The four-bar's least transmission angle over a whole crank turn (rad), exactly.

    With the crank at angle θ from the ground, BD² = a² + d² − 2ad·cos θ and
    cos μ = (b² + c² − BD²)/(2bc): μ is least (``narrow``) and largest
    (``wide``) where BD is, at θ = 0 and π (BD = |d − a| and d + a); the worst
    of min(μ, π − μ) over the turn is the smaller of ``narrow`` and π − ``wide``.
    """
    d, a, b, c = (_column(s, x, k) for k in ("d", "a", "b", "c"))
    with np.errstate(divide="ignore", invalid="ignore"):
        narrow = np.arccos(np.clip((b * b + c * c - (d - a) ** 2) / (2 * b * c), -1, 1))
        wide = np.arccos(np.clip((b * b + c * c - (d + a) ** 2) / (2 * b * c), -1, 1))
    return np.nan_to_num(np.minimum(narrow, np.pi - wide))  # narrow ≤ wide


def _reach(s: _Scaled, x: np.ndarray) -> np.ndarray:
    """The farthest a design's pivots lie from the targets' centre, or its longest link (sizes)."""
    names = PARAMETERS[s.linkage]
    far = link_lengths(s.linkage, x).max(axis=1)
    pivots = [("ax", "ay")]
    if "gx" in names:
        pivots.append(("gx", "gy"))
    for px, py in pivots:
        far = np.maximum(far, np.hypot(_column(s, x, px), _column(s, x, py)))
    d, t0 = _column(s, x, "d"), _column(s, x, "theta0")
    dx = _column(s, x, "ax") + d * np.cos(t0)
    dy = _column(s, x, "ay") + d * np.sin(t0)
    return np.maximum(far, np.hypot(dx, dy))


# ------------------------------------------------------------------ the search
@dataclass(frozen=True)
class _Run:
    """One seeded search's best distinct candidates (placed, scaled rows), their crank angles
    at the targets, their values, and what the search cost."""

    rows: np.ndarray
    angles: np.ndarray
    values: np.ndarray
    evaluations: int
    rejections: dict[str, int]


def _search(job: tuple[_Scaled, int, int, int, int]) -> _Run:
    """One differential evolution from ``seed`` (a module-level function: it may run elsewhere).

    The searches alternate between two variants of the method (``variant``
    0, 1, ...): 'best1bin' with crossover 0.9, which converges fast, and
    'currenttobest1bin' with crossover 0.7, which keeps more diversity.
    """
    s, seed, generations, population, variant = job
    strategy, crossover = _VARIANTS[variant % len(_VARIANTS)]
    count = [0]
    rejections: Counter = Counter()

    def evaluated(z: np.ndarray) -> _Evaluation:
        x = _full(s, z)
        return _evaluate(s, x, _angles(s, z, x))

    def objective(zt: np.ndarray) -> np.ndarray:
        result = evaluated(zt.T)
        count[0] += zt.shape[1]
        for name, mask in result.refused.items():
            rejections[name] += int(mask.sum())
        return result.value

    found = differential_evolution(
        objective,
        list(zip(s.low, s.high, strict=True)),
        seed=seed,
        maxiter=generations,
        popsize=population,
        tol=1e-12,
        atol=0.0,
        mutation=(0.5, 1.0),
        recombination=crossover,
        strategy=strategy,
        polish=False,
        vectorized=True,
        updating="deferred",
        init="latinhypercube",
    )
    final = evaluated(np.asarray(found.population))
    order = np.argsort(final.value, kind="stable")
    keep: list[int] = []
    for k in order:
        if final.value[k] >= _INFEASIBLE or len(keep) == _POLISHED:
            break
        if all(np.max(np.abs(final.placed[k] - final.placed[j])) > 1e-6 for j in keep):
            keep.append(int(k))
    return _Run(
        final.placed[keep], final.angles[keep], final.value[keep], count[0], dict(rejections)
    )


def _judged(s: _Scaled, x: np.ndarray, angles: np.ndarray) -> _Evaluation:
    """Designs (scaled rows) taken where they are, at the timing's angles or at ``angles``."""
    if s.offsets is not None:
        angles = _column(s, x, "phi1")[:, None] + s.offsets[None, :]
    return _evaluate(s, x, angles, fit=False)


def _polish(s: _Scaled, x: np.ndarray, angles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``least_squares`` on the targets' errors from the placed design ``x`` (one scaled row).

    Every parameter the problem leaves free moves (the assembly modes stay);
    without timing each target's crank angle joins the unknowns, from
    ``angles``. The result is kept only if it stays feasible and is better.
    """
    names = PARAMETERS[s.linkage]
    tied = s.crank_from_ground is not None
    timed = s.offsets is not None
    free = [
        k
        for k, n in enumerate(names)
        if n not in _SIDES
        and not (n in s.user and s.user[n][0] == s.user[n][1])
        and not (n == "phi1" and (tied or not timed))
    ]
    k_phi, k_theta = names.index("phi1"), names.index("theta0")
    lower = np.full(len(free), -np.inf)
    upper = np.full(len(free), np.inf)
    for i, k in enumerate(free):
        if names[k] in s.user:
            lower[i], upper[i] = s.user[names[k]]
        elif names[k] in ("d", "a", "b", "c", "e", "f"):
            lower[i] = 1e-9
    m = len(free)

    def rows(v: np.ndarray) -> np.ndarray:
        out = np.repeat(x[None], len(v), axis=0)
        out[:, free] = v[:, :m]
        if tied:
            out[:, k_phi] = out[:, k_theta] + s.crank_from_ground
        return out

    def residuals(v: np.ndarray) -> np.ndarray:
        """The residuals of many unknown vectors ``v`` (k, unknowns) at once: (k, 2N)."""
        r = rows(v)
        if timed:
            at = r[:, [k_phi]] + s.offsets[None]
        elif s.closed:  # the last target is the first, a turn on
            at = np.concatenate([v[:, m:], v[:, [m]] + turn], axis=1)
        else:
            at = v[:, m:]
        return (linkage_poses(s.linkage, r, at).points["P"] - s.targets).reshape(len(v), -1)

    def jacobian(v: np.ndarray) -> np.ndarray:
        step = 1e-7 * np.maximum(1.0, np.abs(v))
        moved = residuals(np.vstack([v, v + np.diag(step)]))
        return ((moved[1:] - moved[0]) / step[:, None]).T

    turn = 2 * math.pi * np.sign(angles[-1] - angles[0])
    known = angles[:-1] if s.closed else angles
    extra = 0 if timed else len(known)
    start = np.concatenate([x[free], [] if timed else known])
    low = np.concatenate([lower, np.full(extra, -np.inf)])
    high = np.concatenate([upper, np.full(extra, np.inf)])
    start = np.clip(start, low, high)
    try:
        with np.errstate(all="ignore"):
            fit = least_squares(
                lambda v: residuals(v[None])[0],
                start,
                jac=jacobian,
                bounds=(low, high),
                xtol=1e-13,
                ftol=1e-13,
                max_nfev=200,
            )
    except ValueError:
        return x, angles
    out = rows(fit.x[None])[0]
    turned = angles
    if not timed:
        turned = np.concatenate([fit.x[m:], fit.x[m : m + 1] + turn] if s.closed else [fit.x[m:]])
    if not np.all(np.isfinite(out)) or not np.all(np.isfinite(turned)):
        return x, angles
    judged = _judged(s, np.stack([x, out]), np.stack([angles, turned]))
    if judged.feasible[1] and judged.value[1] <= judged.value[0]:
        return out, turned
    return x, angles


def _check_problem(problem: PathProblem) -> None:
    t = np.asarray(problem.targets, dtype=float)
    if t.ndim != 2 or t.shape[1] != 2 or not np.all(np.isfinite(t)):
        raise SynthesisError("targets must be finite x, y pairs")
    n = len(t)
    if n < 3:
        raise SynthesisError(f"{n} target(s): a path needs at least 3")
    if n > MAX_TARGETS:
        raise SynthesisError(f"{n} targets: at most {MAX_TARGETS} are taken")
    centre = t.mean(axis=0)
    size = float(np.max(np.linalg.norm(t - centre, axis=1)))
    if not size > 0:
        raise SynthesisError("the targets all coincide: they make no path")
    u = t - centre
    spread = np.linalg.svd(u, compute_uv=False)
    collinear = spread[-1] <= 1e-9 * spread[0]
    closed = np.linalg.norm(t[0] - t[-1]) <= 1e-9 * size
    if problem.crank_deg is not None:
        c = np.asarray(problem.crank_deg, dtype=float)
        if c.shape != (n,) or not np.all(np.isfinite(c)):
            raise SynthesisError("give one finite crank angle per target (the third column)")
        steps = np.diff(c)
        if not (np.all(steps > 0) or np.all(steps < 0)):
            raise SynthesisError(
                "the crank angles must rise (or fall) from target to target: the crank "
                "passes the targets in order"
            )
        closed = closed or abs(c[-1] - c[0]) >= 360.0
    elif problem.crank_from_ground:
        raise SynthesisError("crank angles from the ground need targets with timing")
    if collinear and closed:
        raise SynthesisError(
            "the targets lie on one straight line and the path is closed: no coupler curve "
            "runs along a segment and back; give targets off the line, or an open path"
        )
    if problem.transmission_min < 0 or problem.transmission_min >= 90:
        raise SynthesisError("the least transmission angle must lie in [0°, 90°)")
    if problem.ratio_max <= 1:
        raise SynthesisError("the link-length ratio bound must exceed 1")


def synthesize_path(
    problem: PathProblem,
    *,
    jobs: int = 1,
    scheduler: str | None = None,
    dask_local: int = 0,
    name: str = "",
) -> PathDesign:
    """The path generator of ``problem`` (see the module's text).

    Raises
    ------
    SynthesisError
        Too few (< 3) or too many targets, coincident targets, a closed path of
        collinear targets, crank angles that do not go one way.
    InfeasibleDesignError
        No candidate met the constraints within the budget; the message names
        the constraint that refused most candidates.
    """
    started = time.perf_counter()
    _check_problem(problem)
    s, centre, size = _scale(problem)
    jobs_ = [
        (s, problem.seed + k, problem.generations, problem.population, k)
        for k in range(max(1, problem.restarts))
    ]
    runs = list(ordered_map(_search, jobs_, jobs=jobs, scheduler=scheduler, dask_local=dask_local))
    evaluations = sum(r.evaluations for r in runs)
    rejections: Counter = Counter()
    for r in runs:
        rejections.update(r.rejections)
    polished = [_polish(s, x, a) for r in runs for x, a in zip(r.rows, r.angles, strict=True)]
    values = []
    if polished:
        rows, angles = (np.array(v) for v in zip(*polished, strict=True))
        values = _judged(s, rows, angles).value
    for k in np.argsort(values, kind="stable"):
        design = _design(problem, s, *polished[k], centre, size, name)
        if design is not None:
            seconds = time.perf_counter() - started
            return _finished(design, evaluations, seconds, dict(rejections))
    worst = max(rejections, key=rejections.get) if rejections else "assembly"
    raise InfeasibleDesignError(
        f"no feasible {problem.linkage} within the budget ({evaluations} candidates): the "
        f"{worst} constraint refused most of them ({rejections.get(worst, 0)}); relax it "
        "(--transmission, --ratio, --allow-rocker) or raise --generations",
        dict(rejections),
    )


def _unscaled(linkage: Linkage, x: np.ndarray, centre: np.ndarray, size: float) -> np.ndarray:
    """A scaled design row in metres: a growth by ``size`` and a shift to ``centre``."""
    shift = complex(centre[0], centre[1])
    return place(linkage, x[None], np.array([size + 0j]), np.array([shift]))[0]


def _design(problem, s, xs, angles, centre, size, name) -> PathDesign | None:
    """The design of the scaled row ``xs`` (its crank at ``angles`` at the targets) checked
    through the solvers, or None where they refuse it."""
    linkage = problem.linkage
    x = _unscaled(linkage, xs, centre, size)
    k = PARAMETERS[linkage].index("phi1")
    for n, value in problem.fixed.items():  # as given, not as scaled and back
        x[PARAMETERS[linkage].index(n)] = value
    if s.crank_from_ground is not None and "theta0" in problem.fixed:
        x[k] = problem.fixed["theta0"] + s.crank_from_ground
    targets = problem.targets
    if problem.crank_deg is not None:
        inputs = np.degrees(s.offsets)
        in_order = True
    else:
        in_order = bool(_angles_in_order(angles[None], s.closed)[0])
        if not in_order:
            return None
        x[k] = angles[0]  # the sketch at the first target
        inputs = np.degrees(angles - angles[0])
    names = ("d", "a", "b", "c")
    d, a, b, c = (np.array([x[PARAMETERS[linkage].index(n)]]) for n in names)
    crank = bool(is_crank(d, a, b, c)[0])
    grashof = str(grashof_kind(d, a, b, c)[0])
    records = target_records(targets, inputs if problem.crank_deg is not None else None)
    mech = design_mechanism(linkage, x, records, name or f"{linkage} path generator")
    try:
        cycle = whole_cycle(mech, crank)
    except MechanismError:
        return None
    mus = [np.degrees(v) for v in cycle.transmission.values()]
    low = float(min(m.min() for m in mus)) if mus else 90.0
    high = float(max(m.max() for m in mus)) if mus else 90.0
    if min(low, 180.0 - high) < problem.transmission_min - _MU_SLACK:
        return None
    if problem.crank_deg is not None:
        defects = check_targets(mech, 1e-6 * size + 10 * _error_max(problem, x))
        if not defects.ok:
            return None
    p = linkage_poses(linkage, x[None], x[k] + np.radians(inputs)[None]).points["P"][0]
    errors = np.linalg.norm(p - targets, axis=1)
    # the solvers' P at the targets agrees with the closed forms (the same branch)
    try:
        solved = points_at(mech, np.radians(inputs), crank)
    except MechanismError:
        return None
    if np.max(np.linalg.norm(solved - p, axis=1)) > 1e-6 * size:
        return None
    return PathDesign(
        problem,
        x,
        mech,
        errors,
        float(errors.max()),
        float(np.sqrt(np.mean(errors**2))),
        inputs,
        (low, high),
        grashof,
        0,
        0.0,
        {},
        in_order,
    )


def _error_max(problem: PathProblem, x: np.ndarray) -> float:
    k = PARAMETERS[problem.linkage].index("phi1")
    offsets = np.radians(problem.crank_deg - problem.crank_deg[0])
    p = linkage_poses(problem.linkage, x[None], x[k] + offsets[None]).points["P"][0]
    return float(np.max(np.linalg.norm(p - problem.targets, axis=1)))


def _finished(design: PathDesign, evaluations: int, seconds: float, rejections) -> PathDesign:
    return PathDesign(
        design.problem,
        design.x,
        design.mechanism,
        design.errors,
        design.error_max,
        design.error_rms,
        design.inputs_deg,
        design.transmission_deg,
        design.grashof,
        evaluations,
        seconds,
        rejections,
        design.in_order,
    )
