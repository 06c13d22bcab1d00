"""The checks of a cam over its cycle, and the smallest base circle that passes them.

:func:`check_cam` looks over a turn at the pressure angle (the largest, and
where), the radius of curvature of the pitch curve and of the profile (the
smallest convex and the smallest concave, and where), undercut (a roller
whose radius reaches the pitch curve's convex radius: the profile loops; a
flat face on a profile of radius ``R_b + s + s'' ≤ 0``: a cusp) and a flat
face's width. Each extreme is found on the samples, then refined by two
finer passes around it (the geometry is in closed form at any angle).

:func:`smallest_base_circle` answers the design question in reverse: the
smallest base circle meeting the largest pressure angle allowed with no
undercut, and for a translating knife or roller the offset that makes it
smallest. For those the pressure angle bound is in closed form: with
``T = tan φ_max`` the follower's height at ``s = 0`` must be
``d ≥ max_θ (|s' − ε|/T − s)`` and ``R_p = √(d² + ε²)``; the offset minimises
``R_p``. Undercut (and every other follower) is met by bisection on the base
radius.

>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> spec = cam_spec_from_dict({"base_radius": 0.04, "follower": {"motion": "translating",
...     "contact": "roller", "roller_radius": 0.01}, "segments": [
...     {"law": "harmonic", "lift": 0.02, "angle": 180},
...     {"law": "harmonic", "lift": -0.02, "angle": 180}]})
>>> checks = check_cam(make_design(spec), 360)
>>> round(checks.pressure.value, 4), checks.pressure.at_deg < 90, checks.undercut
(9.5941, True, False)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from structure.cams import FollowerContact

from ..errors import BaseCircleError
from ..solvers.planar import perpendicular
from .design import CamDesign
from .followers import follower_layout
from .profile import CamGeometry, cam_geometry, fit_measures
from .program import program_values

__all__ = [
    "BaseCircle",
    "CamChecks",
    "Extreme",
    "cam_angles",
    "check_cam",
    "smallest_base_circle",
    "stretches",
]


@dataclass(frozen=True, slots=True)
class Extreme:
    """A value over the cycle and the cam angle it is at (degrees)."""

    value: float
    at_deg: float


@dataclass(frozen=True)
class CamChecks:
    """What the checks found over the cycle (lengths in metres, angles in degrees).

    ``pressure`` the largest pressure angle (signed, by magnitude) against
    ``limit``; ``pitch_min`` and ``profile_min`` the smallest convex radii of
    curvature (None where there is no pitch curve: a flat face),
    ``pitch_concave`` and ``profile_concave`` the smallest concave ones (as
    positive radii; None where the curve is convex all round); ``undercut``
    whether the profile loops or has a cusp, and ``undercut_at`` the stretches
    of cam angle where (from, to); ``face`` a flat face's (min, max) contact
    position from its axis (or from the pivot's foot) and ``face_width`` its
    span. ``geometry`` holds the samples.
    """

    pressure: Extreme
    limit: float
    pitch_min: Extreme | None
    profile_min: Extreme | None
    pitch_concave: Extreme | None
    profile_concave: Extreme | None
    undercut: bool
    undercut_at: tuple[tuple[float, float], ...]
    face: tuple[float, float] | None
    face_width: float | None
    geometry: CamGeometry

    @property
    def pressure_ok(self) -> bool:
        return abs(self.pressure.value) <= self.limit


def cam_angles(samples: int) -> np.ndarray:
    """``samples`` cam angles over a turn, from 0 (radians), the end left out."""
    return np.arange(samples) * (2.0 * math.pi / samples)


#: a quantity to make largest over the cycle, read from a geometry
Measure = Callable[[CamGeometry], np.ndarray]


def _slice(g: CamGeometry, part: slice) -> CamGeometry:
    """The geometry at some of its angles (every array field cut to ``part``)."""
    cut = {
        f.name: getattr(g, f.name)[part]
        for f in dataclasses.fields(g)
        if isinstance(getattr(g, f.name), np.ndarray)
    }
    return dataclasses.replace(g, **cut)


def _refined(
    design: CamDesign, theta: np.ndarray, targets: list[tuple[int, Measure]]
) -> list[Extreme]:
    """For each ``(sample k, measure)``, its largest value near sample k, and where.

    Three passes of 21 points around each, each ten times finer than the last;
    every target's points are found in one geometry per pass (the closed form
    holds at any angle).
    """
    if not targets:
        return []
    step = 2.0 * math.pi / len(theta)
    best = [float(theta[k]) for k, _ in targets]
    width = 21
    for _ in range(3):
        around = np.concatenate([b + np.linspace(-step, step, width) for b in best])
        g = cam_geometry(design, around)
        for i, (_, measure) in enumerate(targets):
            found = measure(_slice(g, slice(i * width, (i + 1) * width)))
            found = np.where(np.isfinite(found), found, -np.inf)
            best[i] = float(around[i * width + int(np.argmax(found))])
        step /= 10.0
    g = cam_geometry(design, np.array(best))
    return [
        Extreme(float(measure(_slice(g, slice(i, i + 1)))[0]), round(math.degrees(b) % 360, 6))
        for i, ((_, measure), b) in enumerate(zip(targets, best, strict=True))
    ]


def _sides(radius: Callable[[CamGeometry], np.ndarray | None]) -> tuple[Measure, Measure]:
    """The measures whose largest is the smallest convex, and concave, ``|radius|``."""

    def side(sign: float) -> Measure:
        def measure(g: CamGeometry) -> np.ndarray:
            r = radius(g)
            return np.where(sign * r > 0, -np.abs(r), -np.inf)

        return measure

    return side(1.0), side(-1.0)


def stretches(theta: np.ndarray, flag: np.ndarray) -> tuple[tuple[float, float], ...]:
    """The stretches of cam angle (degrees, from, to) where ``flag`` holds, around the turn."""
    if not flag.any():
        return ()
    degrees = np.degrees(theta)
    edges = np.flatnonzero(np.diff(np.concatenate([[False], flag, [False]]).astype(int)))
    runs = [(int(a), int(b) - 1) for a, b in zip(edges[::2], edges[1::2], strict=True)]
    if len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == len(flag) - 1:
        first, last = runs.pop(0), runs.pop()
        runs.append((last[0], first[1]))
    return tuple((round(float(degrees[a]), 6), round(float(degrees[b]), 6)) for a, b in runs)


def _undercut(design: CamDesign, g: CamGeometry) -> np.ndarray:
    """Where the profile loops or has a cusp."""
    contact = design.spec.follower.contact
    if contact is FollowerContact.ROLLER:
        rf = design.layout.roller_radius
        return (g.pitch_radius > 0) & (g.pitch_radius <= rf)  # type: ignore[operator]
    if contact is FollowerContact.FLAT:
        return g.profile_radius <= 0
    return np.zeros(g.theta.shape, dtype=bool)


def _face(design: CamDesign, g: CamGeometry) -> tuple[float, float] | None:
    """A flat face's contact positions along it: from its axis, or from the pivot's foot."""
    if not design.layout.flat:
        return None
    along = -perpendicular(g.normal)
    if design.translating:
        origin = np.array([design.layout.axis, 0.0])
    else:
        origin = np.asarray(design.layout.pivot)
    c = np.einsum("ij,ij->i", g.contact - origin, along)
    return float(c.min()), float(c.max())


def check_cam(design: CamDesign, samples: int = 360) -> CamChecks:
    """The pressure angle, curvature, undercut and face width of ``design`` over a turn."""
    theta = cam_angles(samples)
    g = cam_geometry(design, theta)
    knife = design.spec.follower.contact is FollowerContact.KNIFE
    measures: dict[str, Measure] = {"pressure": lambda x: np.abs(x.pressure)}
    if g.pitch_radius is not None:
        measures["pitch"], measures["pitch_concave"] = _sides(lambda x: x.pitch_radius)
    if not knife:
        measures["profile"], measures["profile_concave"] = _sides(lambda x: x.profile_radius)
    targets, names = [], []
    for name, measure in measures.items():
        values = measure(g)
        if np.isfinite(values).any():
            targets.append((int(np.argmax(values)), measure))
            names.append(name)
    found = dict(zip(names, _refined(design, theta, targets), strict=True))
    radii = {key: Extreme(-x.value, x.at_deg) for key, x in found.items() if key != "pressure"}
    if knife:
        radii["profile"], radii["profile_concave"] = radii.get("pitch"), radii.get("pitch_concave")
    pressure = found["pressure"]
    signed = cam_geometry(design, np.radians([pressure.at_deg])).pressure[0]
    flags = _undercut(design, g)
    face = _face(design, g)
    return CamChecks(
        Extreme(math.degrees(signed), pressure.at_deg),
        design.spec.pressure_limit,
        radii.get("pitch"),
        radii.get("profile"),
        radii.get("pitch_concave"),
        radii.get("profile_concave"),
        bool(flags.any()),
        stretches(theta, flags),
        face,
        None if face is None else face[1] - face[0],
        g,
    )


# ------------------------------------------------------------------ the design in reverse
@dataclass(frozen=True, slots=True)
class BaseCircle:
    """The smallest base circle (m) meeting ``limit`` (degrees) with no undercut.

    ``base_radius`` keeps the spec's offset; for a translating knife or roller,
    ``best_offset`` is the offset that allows the smallest base circle of all,
    ``best_base_radius``. ``bound`` says what sets it: ``'pressure angle'``,
    ``'undercut'`` or ``'reach'`` (the follower must reach the cam). None where
    no base circle meets it (an oscillating follower whose arm and pivot allow
    only some).
    """

    base_radius: float | None
    bound: str
    limit: float
    best_offset: float | None = None
    best_base_radius: float | None = None


def _fits(design: CamDesign, base: float, values: tuple, limit: float) -> tuple[bool, str]:
    """Whether the base circle ``base`` meets the pressure limit with no undercut, else why not.

    ``values`` are the program's ``s, s', s''`` over the samples (the same for every base).
    """
    try:
        layout = follower_layout(design.spec.follower, base, design.spec.omega)
    except BaseCircleError:
        return False, "reach"
    pressure, rho = fit_measures(layout, *values)
    if not np.all(np.isfinite(pressure)) or np.max(np.abs(pressure)) > limit:
        return False, "pressure angle"
    contact = design.spec.follower.contact
    if contact is FollowerContact.ROLLER and np.any((rho > 0) & (rho <= layout.roller_radius)):
        return False, "undercut"
    if contact is FollowerContact.FLAT and np.any(rho <= 0):
        return False, "undercut"
    return True, ""


def _bisect(design: CamDesign, values: tuple, low: float, high: float, limit: float):
    """The smallest base radius in (low, high] that fits, by bisection (high must fit)."""
    why = "reach"
    for _ in range(48):
        if high - low <= 1e-7 * high:
            break
        mid = 0.5 * (low + high)
        ok, reason = _fits(design, mid, values, limit)
        if ok:
            high = mid
        else:
            low, why = mid, reason
    return high, why


def smallest_base_circle(design: CamDesign, samples: int = 360) -> BaseCircle:
    """The smallest base circle meeting the spec's pressure limit with no undercut.

    See the module's docstring for the method.
    """
    spec = design.spec
    limit_deg = spec.pressure_limit
    limit = math.radians(limit_deg)
    theta = cam_angles(samples)
    s, s1, s2, _ = program_values(design.program, theta)
    values = (s, s1, s2)
    f = spec.follower
    if f.translating and f.contact is not FollowerContact.FLAT:
        return _translating(design, values, limit, limit_deg)
    if f.translating:
        base = float(np.max(-(s + s2)))
        base = max(base, 0.0) * (1.0 + 1e-9) or float(np.max(np.abs(s))) * 1e-9
        return BaseCircle(base, "undercut", limit_deg)
    # a swinging follower reaches the cam only for some base circles: look along them
    reach = math.hypot(*(f.pivot or (0.0, 0.0)))
    top = reach + f.face_offset if f.contact is FollowerContact.FLAT else reach + (f.arm or 0.0)
    top -= design.layout.roller_radius
    trials = np.linspace(0.0, top, 17)[1:-1]
    coarse = tuple(v[::4] for v in values)  # the search on a quarter of the angles first
    why = "reach"
    for k, base in enumerate(trials):
        ok, reason = _fits(design, float(base), coarse, limit)
        if ok:
            low = float(trials[k - 1]) if k else 0.0
            found, bisected = _bisect(design, coarse, low, float(base), limit)
            return BaseCircle(_confirmed(design, values, found, limit), bisected, limit_deg)
        why = reason
    return BaseCircle(None, why, limit_deg)


def _confirmed(design: CamDesign, values: tuple, base: float, limit: float) -> float:
    """``base`` checked on every angle, grown a little until it fits there too."""
    if _fits(design, base, values, limit)[0]:
        return base
    grow = 1e-7
    while not _fits(design, base * (1.0 + grow), values, limit)[0] and grow < 1.0:
        grow *= 4.0
    found, _ = _bisect(design, values, base * (1.0 + grow / 4.0), base * (1.0 + grow), limit)
    return found


def _best_offset(a: float, b: float, floor: float, tangent: float) -> float:
    """The offset that makes ``R_p² = d(ε)² + ε²`` least, ``d(ε) = max(a − ε/T, b + ε/T, floor)``.

    ``d`` is convex and piecewise linear in ε, so ``R_p²`` is convex: its least value is at a
    stationary point of one of the pieces or at a kink where two meet.
    """
    t = tangent
    candidates = [a * t / (t * t + 1.0), -b * t / (t * t + 1.0), t * (a - b) / 2.0, 0.0]
    candidates += [t * (a - floor), t * (floor - b)]

    def size(eps: float) -> float:
        d = max(a - eps / t, b + eps / t, floor)
        return d * d + eps * eps

    return min(candidates, key=size)


def _translating(design: CamDesign, values: tuple, limit: float, limit_deg: float) -> BaseCircle:
    """A translating knife or roller: the pressure bound in closed form, undercut by bisection.

    With ``T = tan φ_max``, ``|s' − ε|/T − s ≤ d`` at every angle splits into
    ``d ≥ a − ε/T`` and ``d ≥ b + ε/T`` with ``a = max(s'/T − s)`` and ``b = max(−s'/T − s)``;
    the follower stays above the cam's centre, ``d > max(−s)``.
    """
    s, s1, _ = values
    rf = design.layout.roller_radius
    tangent = math.tan(limit)
    a = float(np.max(s1 / tangent - s))
    b = float(np.max(-s1 / tangent - s))
    floor = float(np.max(-s))

    def base_for(offset: float) -> tuple[float, str]:
        d = max(a - offset / tangent, b + offset / tangent, floor)
        base = math.hypot(d, offset) - rf
        why = "pressure angle"
        if base <= 0.0:
            base, why = 1e-9 * max(design.program.scale, rf, 1e-300), "reach"
        trial = dataclasses.replace(design.spec.follower, offset=offset)
        moved = dataclasses.replace(design, spec=dataclasses.replace(design.spec, follower=trial))
        ok, _ = _fits(moved, base * (1.0 + 1e-9), values, limit)
        if ok:
            return base * (1.0 + 1e-9), why
        high = base * 2.0
        while not _fits(moved, high, values, limit)[0]:
            high *= 2.0
        return _bisect(moved, values, base, high, limit)

    base, why = base_for(design.spec.follower.offset)
    best = _best_offset(a, b, floor, tangent)
    best_base, _ = base_for(best)
    return BaseCircle(base, why, limit_deg, best, best_base)
