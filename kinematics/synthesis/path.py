"""Path generation: a four-bar or six-bar whose coupler point P passes through N targets.

With prescribed timing each target has the crank's angle at which P should
be there, and the error is the distance from P at that angle to the target;
without, the error is each target's distance to the whole coupler curve
(P over a crank turn). The search is scipy's ``differential_evolution``
(seeded, so a run is reproduced exactly) over the design's numbers
(:data:`kinematics.synthesis.linkages.PARAMETERS`), every generation's
candidates evaluated at once with numpy (:func:`~kinematics.synthesis.linkages.linkage_poses`,
the solvers' closed forms and their branch rule), then polished by
``least_squares``. Several independent searches (``restarts``, seeds
``seed``, ``seed + 1``, ...) run in this process, in local processes
(``jobs``) or on Dask (``scheduler``), with the same answer whichever.

Constraints: the crank turns fully (Grashof, the crank or the ground the
shortest link; or, with ``allow_rocker`` and timing, the input rocks over the
targets' range on one assembly mode), every dyad's transmission angle stays
within [μ_min, 180° − μ_min] (30° by default) over the motion, the longest
link is at most ``ratio_max`` times the shortest. A candidate that breaks
one of them, does not assemble, or would change branch (a dyad's modes
meeting) is infeasible: it ranks after every feasible candidate whatever its
error, and is never returned. The design returned is checked again by the
group-by-group solvers over its whole motion (:mod:`.defects`).

Every length is scaled by the targets' size, so the answer does not depend
on the unit of length.
"""

from __future__ import annotations

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
    design_mechanism,
    grashof_kind,
    is_crank,
    link_lengths,
    linkage_poses,
    target_records,
)

__all__ = [
    "MAX_TARGETS",
    "PathDesign",
    "PathProblem",
    "evaluate",
    "synthesize_path",
]

#: the most targets a path may have
MAX_TARGETS = 100
#: the value an infeasible candidate gets, plus its violation: above any feasible error
_INFEASIBLE = 1e6
#: samples of a crank turn (the curve without timing, the constraints' check)
_TURN = 96


@dataclass(frozen=True)
class PathProblem:
    """A path to generate.

    ``targets`` (N, 2) in metres; ``crank_deg`` the crank's angle at each
    (timing; None without); ``bounds`` overrides the search range of a
    parameter (its name -> (low, high), lengths in metres, angles in radians;
    ``side`` from -1 to 1 picks the assembly mode by its sign); ``fixed``
    holds parameters at a value (e.g. ``{"ax": 0, "ay": 0, "theta0": 0}``).
    """

    targets: np.ndarray
    crank_deg: np.ndarray | None = None
    linkage: Linkage = Linkage.FOURBAR
    transmission_min: float = 30.0
    ratio_max: float = 10.0
    allow_rocker: bool = False
    seed: int = 0
    restarts: int = 2
    generations: int = 300
    population: int = 20
    bounds: dict[str, tuple[float, float]] = field(default_factory=dict)
    fixed: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class PathDesign:
    """A path generator and its errors.

    ``x`` the design's numbers (metres and radians, names in ``PARAMETERS``);
    ``errors`` each target's distance (metres); ``inputs_deg`` the crank's
    rotation from the sketch (the first target) at each target;
    ``transmission_deg`` the least and largest transmission angle over the
    motion (every dyad); ``grashof`` the four-bar's type; ``evaluations``
    the candidates evaluated; ``rejections`` how many each constraint refused.
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


# ------------------------------------------------------------------ the problem, scaled
@dataclass(frozen=True)
class _Scaled:
    """The problem in the targets' own scale: centre 0, size 1; the search's coordinates."""

    linkage: Linkage
    targets: np.ndarray  # (N, 2), scaled
    offsets: np.ndarray | None  # crank angle of each target less the first's (rad)
    names: tuple[str, ...]  # the parameters searched
    fixed: dict[str, float]  # the others, scaled
    low: np.ndarray
    high: np.ndarray
    transmission_min: float  # rad
    ratio_max: float
    allow_rocker: bool


def _scale(problem: PathProblem) -> tuple[_Scaled, np.ndarray, float]:
    t = problem.targets
    centre = t.mean(axis=0)
    size = float(np.max(np.linalg.norm(t - centre, axis=1)))
    defaults = {
        "ax": (-3.0, 3.0),
        "ay": (-3.0, 3.0),
        "gx": (-3.0, 3.0),
        "gy": (-3.0, 3.0),
        "theta0": (-math.pi, math.pi),
        "phi1": (-math.pi, math.pi),
        "side": (-1.0, 1.0),
        "side2": (-1.0, 1.0),
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
    }
    shift = {"ax": 0, "gx": 0, "ay": 1, "gy": 1}

    def scaled(name: str, value: float) -> float:
        if name in shift:
            return (value - centre[shift[name]]) / size
        return value / size if name in LENGTHS else value

    names = [n for n in PARAMETERS[problem.linkage] if n not in problem.fixed]
    low, high = [], []
    for n in names:
        if n in problem.bounds:
            lo, hi = problem.bounds[n]
            lo, hi = scaled(n, lo), scaled(n, hi)
        else:
            lo, hi = defaults[n]
        low.append(min(lo, hi))
        high.append(max(lo, hi))
    offsets = None
    if problem.crank_deg is not None:
        offsets = np.radians(problem.crank_deg - problem.crank_deg[0])
    s = _Scaled(
        problem.linkage,
        (t - centre) / size,
        offsets,
        tuple(names),
        {n: scaled(n, v) for n, v in problem.fixed.items()},
        np.array(low),
        np.array(high),
        math.radians(problem.transmission_min),
        problem.ratio_max,
        problem.allow_rocker,
    )
    return s, centre, size


def _full(s: _Scaled, z: np.ndarray) -> np.ndarray:
    """Every parameter's column from the searched ones ``z`` (designs, searched)."""
    z = np.atleast_2d(z)
    columns = []
    for n in PARAMETERS[s.linkage]:
        if n in s.fixed:
            columns.append(np.full(len(z), s.fixed[n]))
        else:
            columns.append(z[:, s.names.index(n)])
    return np.column_stack(columns)


# ------------------------------------------------------------------ one generation at once
@dataclass(frozen=True)
class Evaluation:
    """The value of each candidate, whether it is feasible, and what refused the others."""

    value: np.ndarray
    feasible: np.ndarray
    refused: dict[str, np.ndarray]


def evaluate(s: _Scaled, x: np.ndarray) -> Evaluation:
    """Every candidate of ``x`` (designs, parameters; scaled) at once: value and feasibility.

    The value of a feasible candidate is the sum of its targets' squared
    errors (in the targets' scale); an infeasible one gets
    :data:`_INFEASIBLE` plus how far it is from feasible.
    """
    n = len(x)
    column = {name: x[:, k] for k, name in enumerate(PARAMETERS[s.linkage])}
    phi1 = column["phi1"][:, None]
    lengths = link_lengths(s.linkage, x)
    crank = is_crank(column["d"], column["a"], column["b"], column["c"])
    turn = np.linspace(0.0, 2 * math.pi, _TURN, endpoint=False)[None, :]
    if s.offsets is not None:
        span = s.offsets[-1]
        # the motion the constraints hold over: a whole turn for a crank, else the targets' range
        path = np.linspace(0.0, span, _TURN)[None, :]
        motion_phi = np.where(crank[:, None], phi1 + turn, phi1 + path)
    else:
        motion_phi = phi1 + turn
    motion = linkage_poses(s.linkage, x, motion_phi)
    closes = np.ones(n, dtype=bool)
    violation = np.zeros(n)
    for h2 in motion.heights:
        low = h2.min(axis=1)
        closes &= low > 1e-10
        violation += np.maximum(-low, 0.0)
    grip = np.ones(n, dtype=bool)
    for mu in motion.transmission:
        worst = np.minimum(mu, np.pi - mu).min(axis=1)
        grip &= worst >= s.transmission_min
        violation += np.maximum(s.transmission_min - worst, 0.0)
    ratio = lengths.max(axis=1) / np.maximum(lengths.min(axis=1), 1e-300)
    short = ratio <= s.ratio_max
    violation += np.maximum(ratio - s.ratio_max, 0.0) / s.ratio_max
    turns = crank | (s.allow_rocker and s.offsets is not None)
    violation += np.where(turns, 0.0, 1.0)
    feasible = closes & grip & short & turns
    if s.offsets is not None:
        poses = linkage_poses(s.linkage, x, phi1 + s.offsets[None, :])
        error2 = ((poses.points["P"] - s.targets[None]) ** 2).sum(axis=2)
    else:
        error2 = _curve_distances(motion.points["P"], s.targets) ** 2
    value = np.where(feasible, error2.sum(axis=1), _INFEASIBLE * (1.0 + violation))
    value = np.where(np.isfinite(value), value, _INFEASIBLE * 10)
    refused = {
        "crank (Grashof)": ~turns,
        "assembly": ~closes,
        "transmission angle": ~grip,
        "link-length ratio": ~short,
    }
    return Evaluation(value, feasible, refused)


def _curve_distances(curve: np.ndarray, targets: np.ndarray) -> np.ndarray:
    """Each target's distance to the closed polygon ``curve`` (designs, samples, 2)."""
    start = curve[:, None, :, :]
    edge = np.roll(curve, -1, axis=1)[:, None, :, :] - start
    rel = targets[None, :, None, :] - start
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip((rel * edge).sum(-1) / (edge * edge).sum(-1), 0.0, 1.0)
    t = np.nan_to_num(t)
    gap = rel - t[..., None] * edge
    return np.sqrt((gap * gap).sum(-1).min(axis=2))


# ------------------------------------------------------------------ the search
@dataclass(frozen=True)
class _Run:
    """One seeded search's best candidate (scaled), its value and what it cost."""

    z: np.ndarray
    value: float
    evaluations: int
    rejections: dict[str, int]


def _search(job: tuple[_Scaled, int, int, int]) -> _Run:
    """One differential evolution from ``seed`` (a module-level function: it may run elsewhere)."""
    s, seed, generations, population = job
    count = [0]
    rejections: Counter = Counter()

    def objective(zt: np.ndarray) -> np.ndarray:
        z = zt.T
        result = evaluate(s, _full(s, z))
        count[0] += len(z)
        for name, mask in result.refused.items():
            rejections[name] += int(mask.sum())
        return result.value

    found = differential_evolution(
        objective,
        list(zip(s.low, s.high, strict=True)),
        seed=seed,
        maxiter=generations,
        popsize=population,
        tol=1e-10,
        mutation=(0.5, 1.0),
        recombination=0.9,
        polish=False,
        vectorized=True,
        updating="deferred",
        init="sobol",
    )
    return _Run(np.asarray(found.x), float(found.fun), count[0], dict(rejections))


def _polish(s: _Scaled, z: np.ndarray) -> np.ndarray:
    """``least_squares`` on the targets' errors from ``z``; kept only if it stays feasible."""
    side_names = {"side", "side2"}
    frozen = np.array([n in side_names for n in s.names])
    free = ~frozen

    if s.offsets is not None:

        def residual(v):
            zz = z.copy()
            zz[free] = v
            x = _full(s, zz[None])
            poses = linkage_poses(
                s.linkage, x, x[:, [PARAMETERS[s.linkage].index("phi1")]] + s.offsets
            )
            return (poses.points["P"][0] - s.targets).ravel()

        start = z[free]
        low, high = s.low[free], s.high[free]
    else:
        # each target's own crank angle joins the unknowns: its foot on the curve
        x0 = _full(s, z[None])
        turn = np.linspace(0.0, 2 * math.pi, 720, endpoint=False)
        phi1 = x0[0, PARAMETERS[s.linkage].index("phi1")]
        curve = linkage_poses(s.linkage, x0, phi1 + turn[None]).points["P"][0]
        nearest = np.argmin(((curve[None] - s.targets[:, None]) ** 2).sum(-1), axis=1)
        angles = turn[nearest]

        def residual(v):
            zz = z.copy()
            zz[free] = v[: free.sum()]
            x = _full(s, zz[None])
            phi = x[0, PARAMETERS[s.linkage].index("phi1")] + v[free.sum() :]
            poses = linkage_poses(s.linkage, x, phi[None])
            return (poses.points["P"][0] - s.targets).ravel()

        start = np.concatenate([z[free], angles])
        low = np.concatenate([s.low[free], angles - 2 * math.pi])
        high = np.concatenate([s.high[free], angles + 2 * math.pi])
    start = np.clip(start, low, high)
    try:
        fit = least_squares(residual, start, bounds=(low, high), xtol=1e-14, ftol=1e-14)
    except ValueError:
        return z
    out = z.copy()
    out[free] = fit.x[: free.sum()]
    before = evaluate(s, _full(s, z[None]))
    after = evaluate(s, _full(s, out[None]))
    if after.feasible[0] and after.value[0] <= before.value[0]:
        return out
    return z


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
        (s, problem.seed + k, problem.generations, problem.population)
        for k in range(max(1, problem.restarts))
    ]
    runs = list(ordered_map(_search, jobs_, jobs=jobs, scheduler=scheduler, dask_local=dask_local))
    evaluations = sum(r.evaluations for r in runs)
    rejections: Counter = Counter()
    for r in runs:
        rejections.update(r.rejections)
    ranked = sorted(runs, key=lambda r: r.value)
    for run in ranked:
        if run.value >= _INFEASIBLE:
            break
        z = _polish(s, run.z)
        design = _design(problem, s, z, centre, size, name)
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


def _unscaled(s: _Scaled, z: np.ndarray, centre: np.ndarray, size: float) -> np.ndarray:
    x = _full(s, z[None])[0].copy()
    for k, n in enumerate(PARAMETERS[s.linkage]):
        if n in ("ax", "gx"):
            x[k] = x[k] * size + centre[0]
        elif n in ("ay", "gy"):
            x[k] = x[k] * size + centre[1]
        elif n in LENGTHS:
            x[k] *= size
    return x


def _design(problem, s, z, centre, size, name) -> PathDesign | None:
    """The design of ``z`` checked through the solvers, or None where they refuse it."""
    linkage = problem.linkage
    x = _unscaled(s, z, centre, size)
    k = PARAMETERS[linkage].index("phi1")
    targets = problem.targets
    if problem.crank_deg is not None:
        inputs = np.degrees(s.offsets)
    else:
        turn = np.linspace(0.0, 2 * math.pi, 3600, endpoint=False)
        curve = linkage_poses(linkage, x[None], x[k] + turn[None]).points["P"][0]
        nearest = np.argmin(((curve[None] - targets[:, None]) ** 2).sum(-1), axis=1)
        inputs = np.degrees(turn[nearest])
    names = ("d", "a", "b", "c")
    d, a, b, c = (np.array([x[PARAMETERS[linkage].index(n)]]) for n in names)
    crank = bool(is_crank(d, a, b, c)[0])
    grashof = str(grashof_kind(d, a, b, c)[0])
    order = np.argsort(inputs) if problem.crank_deg is None else np.arange(len(targets))
    in_order = bool(np.all(np.diff(order) > 0) or np.all(np.diff(order[::-1]) > 0))
    records = target_records(targets, inputs if problem.crank_deg is not None else None)
    mech = design_mechanism(linkage, x, records, name or f"{linkage} path generator")
    try:
        cycle = whole_cycle(mech, crank)
    except MechanismError:
        return None
    if problem.crank_deg is not None:
        defects = check_targets(mech, 1e-6 * size + 10 * _error_max(problem, x))
        if not defects.ok:
            return None
    p = linkage_poses(linkage, x[None], x[k] + np.radians(inputs)[None]).points["P"][0]
    errors = np.linalg.norm(p - targets, axis=1)
    # the solvers' P at the targets agrees with the closed forms (the same branch)
    poses = np.radians(inputs)
    try:
        solved = points_at(mech, poses, crank)
    except MechanismError:
        return None
    if np.max(np.linalg.norm(solved - p, axis=1)) > 1e-6 * size:
        return None
    mus = [np.degrees(v) for v in cycle.transmission.values()]
    if mus:
        low = float(min(m.min() for m in mus))
        high = float(max(m.max() for m in mus))
    else:
        low = high = 90.0
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
