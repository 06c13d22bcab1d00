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
from .profile import CamGeometry, cam_geometry
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


def _refine(
    design: CamDesign, theta: np.ndarray, k: int, value: Callable[[CamGeometry], np.ndarray]
) -> Extreme:
    """The largest ``value`` near sample ``k``: three passes of 21 points, each 10 times finer."""
    step = 2.0 * math.pi / len(theta)
    best = float(theta[k])
    for _ in range(3):
        around = best + np.linspace(-step, step, 21)
        found = value(cam_geometry(design, around))
        found = np.where(np.isfinite(found), found, -np.inf)
        best = float(around[int(np.argmax(found))])
        step /= 10.0
    g = cam_geometry(design, np.array([best]))
    return Extreme(float(value(g)[0]), round(math.degrees(best) % 360.0, 6))


def _smallest(
    design: CamDesign, geometry: CamGeometry, radius: Callable[[CamGeometry], np.ndarray | None]
) -> tuple[Extreme | None, Extreme | None]:
    """The smallest convex and concave radius of ``radius`` (as positive numbers) and where."""
    rho = radius(geometry)
    if rho is None:
        return None, None
    out: list[Extreme | None] = []
    for sign in (1.0, -1.0):
        # the smallest |ρ| on one side: the largest of −|ρ| there
        def side(g: CamGeometry, sign: float = sign) -> np.ndarray:
            r = radius(g)
            return np.where(sign * r > 0, -np.abs(r), -np.inf)

        values = side(geometry)
        if not np.isfinite(values).any():
            out.append(None)
            continue
        found = _refine(design, geometry.theta, int(np.argmax(values)), side)
        out.append(Extreme(-found.value, found.at_deg))
    return out[0], out[1]


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
    pressure = _refine(
        design, theta, int(np.argmax(np.abs(g.pressure))), lambda x: np.abs(x.pressure)
    )
    signed = cam_geometry(design, np.radians([pressure.at_deg])).pressure[0]
    pitch = (
        _smallest(design, g, lambda x: x.pitch_radius)
        if g.pitch_radius is not None
        else (None, None)
    )
    profile = _smallest(design, g, lambda x: x.profile_radius)
    if design.spec.follower.contact is FollowerContact.KNIFE:
        profile = pitch
    flags = _undercut(design, g)
    face = _face(design, g)
    return CamChecks(
        Extreme(math.degrees(signed), pressure.at_deg),
        design.spec.pressure_limit,
        pitch[0],
        profile[0],
        pitch[1],
        profile[1],
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


def _fits(design: CamDesign, base: float, s, limit: float) -> tuple[bool, str]:
    """Whether the base circle ``base`` meets the pressure limit with no undercut, else why not."""
    spec = dataclasses.replace(design.spec, base_radius=base)
    try:
        layout = follower_layout(spec.follower, base, spec.omega)
    except BaseCircleError:
        return False, "reach"
    trial = dataclasses.replace(design, spec=spec, layout=layout)
    g = cam_geometry(trial, s)
    if not np.all(np.isfinite(g.pressure)) or np.max(np.abs(g.pressure)) > limit:
        return False, "pressure angle"
    if _undercut(trial, g).any():
        return False, "undercut"
    return True, ""


def _bisect(design: CamDesign, theta: np.ndarray, low: float, high: float, limit: float):
    """The smallest base radius in (low, high] that fits, by bisection (high must fit)."""
    why = "reach"
    for _ in range(48):
        if high - low <= 1e-9 * high:
            break
        mid = 0.5 * (low + high)
        ok, reason = _fits(design, mid, theta, limit)
        if ok:
            high = mid
        else:
            low, why = mid, reason
    return high, why


def _pressure_height(s: np.ndarray, s1: np.ndarray, offset: np.ndarray, tangent: float):
    """``d(ε) = max_θ(|s' − ε|/T − s)`` for each offset ε (the follower's height at s = 0)."""
    return np.max(np.abs(s1[None, :] - offset[:, None]) / tangent - s[None, :], axis=1)


def smallest_base_circle(design: CamDesign, samples: int = 360) -> BaseCircle:
    """The smallest base circle meeting the spec's pressure limit with no undercut.

    See the module's docstring for the method.
    """
    spec = design.spec
    limit_deg = spec.pressure_limit
    limit = math.radians(limit_deg)
    theta = cam_angles(samples)
    s, s1, _, _ = program_values(design.program, theta)
    f = spec.follower
    if f.translating and f.contact is not FollowerContact.FLAT:
        return _translating(design, theta, s, s1, limit, limit_deg)
    if f.translating:
        _, _, s2, _ = program_values(design.program, theta)
        base = float(np.max(-(s + s2)))
        base = max(base, 0.0) * (1.0 + 1e-9) or float(np.max(np.abs(s))) * 1e-9
        return BaseCircle(base, "undercut", limit_deg)
    # a swinging follower reaches the cam only for some base circles: look along them
    reach = math.hypot(*(f.pivot or (0.0, 0.0)))
    top = reach + f.face_offset if f.contact is FollowerContact.FLAT else reach + (f.arm or 0.0)
    top -= design.layout.roller_radius
    trials = np.linspace(0.0, top, 65)[1:-1]
    why = "reach"
    for k, base in enumerate(trials):
        ok, reason = _fits(design, float(base), theta, limit)
        if ok:
            low = float(trials[k - 1]) if k else 0.0
            found, bisected = _bisect(design, theta, low, float(base), limit)
            return BaseCircle(found, bisected if k else why, limit_deg)
        why = reason
    return BaseCircle(None, why, limit_deg)


def _translating(design: CamDesign, theta, s, s1, limit: float, limit_deg: float) -> BaseCircle:
    """A translating knife or roller: the pressure bound in closed form, undercut by bisection."""
    rf = design.layout.roller_radius
    tangent = math.tan(limit)
    floor = float(np.max(-s))  # the follower stays above the cam's centre: d + s > 0

    def base_for(offset: float) -> tuple[float, str]:
        d = max(float(_pressure_height(s, s1, np.array([offset]), tangent)[0]), floor)
        base = math.hypot(d, offset) - rf
        why = "pressure angle"
        if base <= 0.0:
            base, why = 1e-9 * max(design.program.scale, rf, 1e-300), "reach"
        trial = dataclasses.replace(design.spec.follower, offset=offset)
        moved = dataclasses.replace(design, spec=dataclasses.replace(design.spec, follower=trial))
        ok, _ = _fits(moved, base * (1.0 + 1e-9), theta, limit)
        if ok:
            return base * (1.0 + 1e-9), why
        high = base * 2.0
        while not _fits(moved, high, theta, limit)[0]:
            high *= 2.0
        return _bisect(moved, theta, base, high, limit)

    base, why = base_for(design.spec.follower.offset)
    # the offset that makes the prime circle smallest: R_p(ε)² = d(ε)² + ε², convex in ε
    reach = float(np.max(np.abs(s1))) or design.program.scale
    grid = np.linspace(-reach, reach, 201)
    for _ in range(3):
        d = np.maximum(_pressure_height(s, s1, grid, tangent), floor)
        k = int(np.argmin(d**2 + grid**2))
        width = grid[1] - grid[0]
        grid = np.linspace(grid[k] - width, grid[k] + width, 21)
    best = float(grid[10])
    best_base, _ = base_for(best)
    return BaseCircle(base, why, limit_deg, best, best_base)
