"""Function generation: a four-bar or a crank–slider whose output follows y = f(x) over a range.

x maps linearly onto the crank angle φ (``input_range`` degrees from
``input_start``) and y = f(x) onto the output: the rocker's angle ψ
(four-bar, degrees) or the slider's position s (crank–slider, metres).

* Four-bar, Freudenstein's equation (ground d from A to D along +x, crank a,
  coupler b, rocker c): ``K1·cos ψ − K2·cos φ + K3 = cos(φ − ψ)`` with
  ``K1 = d/a``, ``K2 = d/c``, ``K3 = (a² − b² + c² + d²)/(2ac)``.
* Crank–slider (crank a about A, rod b, slider on the line y = e):
  ``(a·cos φ − s)² + (a·sin φ − e)² = b²``, i.e.
  ``K1·s·cos φ + K2·sin φ − K3 = s²`` with ``K1 = 2a``, ``K2 = 2a·e``,
  ``K3 = a² + e² − b²``.

Both are linear in K: three precision points give K exactly; four points
also free the input's start angle, five the output's start too (each a root
of the system's consistency); more points give K by least squares. The
precision points are Chebyshev-spaced by default. The design is then moved
over the whole range on the assembly mode of its first precision point
(closed form), its structural error ``y_generated − f(x)`` computed, and the
mechanism checked through the solvers (:mod:`.defects`).

>>> chebyshev_points(1.0, 2.0, 3).round(6).tolist()
[1.066987, 1.5, 1.933013]
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq, least_squares

from structure.kinds import TextEnum
from structure.model import Mechanism, make_point, make_target
from structure.validation import validated

from ..errors import SynthesisError
from .formula import Function, check_defined
from .linkages import grashof_kind

__all__ = [
    "FunctionDesign",
    "FunctionLinkage",
    "FunctionProblem",
    "chebyshev_points",
    "synthesize_function",
]

#: the samples of the range the structural error is computed at
RANGE_SAMPLES = 401


class FunctionLinkage(TextEnum):
    """The linkages a function can be generated with."""

    FOURBAR = "fourbar"
    CRANK_SLIDER = "crank-slider"


def chebyshev_points(x0: float, x1: float, n: int) -> np.ndarray:
    """Chebyshev spacing of n precision points on [x0, x1]:
    ``x_j = (x0 + x1)/2 − (x1 − x0)/2·cos((2j − 1)π/(2n))``, j = 1..n."""
    j = np.arange(1, n + 1)
    return (x0 + x1) / 2 - (x1 - x0) / 2 * np.cos((2 * j - 1) * np.pi / (2 * n))


@dataclass(frozen=True)
class FunctionProblem:
    """What to generate: y = ``function``(x) for x in [x0, x1], with its ranges and points.

    ``input_range``, ``input_start``: the crank's swing and its angle at x0
    (degrees); ``output_range``, ``output_start``: the output's swing and its
    value at x0 (degrees for a four-bar, metres for a crank–slider);
    ``points``: how many precision points (3, 4, 5 exact; more by least
    squares); ``spacing``: ``chebyshev`` or ``even``; ``size``: the ground
    link d of a four-bar (metres).
    """

    function: Function
    x0: float
    x1: float
    input_range: float
    output_range: float
    points: int = 3
    linkage: FunctionLinkage = FunctionLinkage.FOURBAR
    input_start: float = 45.0
    output_start: float | None = None
    spacing: str = "chebyshev"
    size: float = 1.0

    def output_origin(self) -> float:
        """The output's value at x0: given, or 135° (four-bar) / 2·|range| (crank–slider)."""
        if self.output_start is not None:
            return self.output_start
        return 135.0 if self.linkage is FunctionLinkage.FOURBAR else 2.0 * abs(self.output_range)


@dataclass(frozen=True)
class FunctionDesign:
    """A function generator and how well it does.

    ``lengths``: ``d, a, b, c`` (four-bar; a, c signed: negative points the
    link the other way) or ``a, b, e`` (crank–slider: crank, rod, offset);
    ``precision_x`` and their inputs/outputs; ``input_start`` (degrees) and
    ``output_start`` as solved (four and five points free them); ``x`` the
    samples of the range and ``error`` the structural error there (y
    units); ``error_max`` its largest magnitude and ``error_at_precision``
    the largest at the precision points; ``side`` the assembly mode.
    """

    problem: FunctionProblem
    lengths: dict[str, float]
    precision_x: tuple[float, ...]
    precision_input: tuple[float, ...]
    precision_output: tuple[float, ...]
    input_start: float
    output_start: float
    x: np.ndarray
    error: np.ndarray
    error_max: float
    error_at_precision: float
    side: float
    mechanism: Mechanism
    transmission_deg: tuple[float, float]
    grashof: str
    notes: tuple[str, ...] = field(default=())


def synthesize_function(problem: FunctionProblem) -> FunctionDesign:
    """The function generator of ``problem`` (see the module's text).

    Raises
    ------
    SynthesisError
        Fewer than 3 points, a range of zero, a function undefined on its
        range or equal at both ends, a system with no solution (the message
        says which start angles to change), a design whose precision points
        lie on two assembly modes or that cannot move over the whole range.
    """
    p = problem
    if p.points < 3:
        raise SynthesisError(f"{p.points} precision points: give at least 3 (--points)")
    if p.points > 100:
        raise SynthesisError(f"{p.points} precision points: give at most 100 (--points)")
    if not (math.isfinite(p.x0) and math.isfinite(p.x1)) or p.x0 == p.x1:
        raise SynthesisError(f"the range of x [{p.x0:g}, {p.x1:g}] is empty: give two values")
    if p.input_range == 0 or p.output_range == 0 or p.size <= 0:
        raise SynthesisError("the input and output ranges must not be zero, the size positive")
    check_defined(p.function, p.x0, p.x1)
    y0, y1 = (float(v) for v in p.function(np.array([p.x0, p.x1])))
    if y0 == y1:
        raise SynthesisError(
            f"f(x0) = f(x1) = {y0:g}: the output range cannot be mapped onto y; choose a range "
            "over which the function changes"
        )
    if p.spacing == "chebyshev":
        xs = chebyshev_points(p.x0, p.x1, p.points)
    else:
        xs = np.linspace(p.x0, p.x1, p.points)
    ys = p.function(xs)
    solver = _fourbar if p.linkage is FunctionLinkage.FOURBAR else _crank_slider
    return solver(p, xs, ys, y0, y1)


# ------------------------------------------------------------------ shared pieces
def _maps(p: FunctionProblem, y0: float, y1: float):
    """x ↦ φ (rad) and y ↦ output (rad or m), given the two start values."""
    out_scale = math.radians(p.output_range) if p.linkage is FunctionLinkage.FOURBAR else None

    def phi(x, start):
        return start + (np.asarray(x) - p.x0) / (p.x1 - p.x0) * math.radians(p.input_range)

    def out(y, start):
        scale = out_scale if out_scale is not None else p.output_range
        return start + (np.asarray(y) - y0) / (y1 - y0) * scale

    return phi, out


def _starts(p: FunctionProblem) -> list[tuple[float, float, bool, bool]]:
    """Start values (φ0 in rad, output start) and which of them are solved for."""
    four = p.linkage is FunctionLinkage.FOURBAR
    out0 = p.output_origin()
    out0 = math.radians(out0) if four else out0
    phi0 = math.radians(p.input_start)
    return [(phi0, out0, p.points >= 4 and p.points <= 5, p.points == 5)]


def _solve_starts(system, p: FunctionProblem, phi0: float, out0: float):
    """All start values (φ0, out0) that make an exact system consistent (4 or 5 points).

    ``system(phi0, out0)`` returns the augmented matrix; consistency is a zero
    smallest singular value (4 points: a root in φ0 found by sign changes of
    the determinant; 5 points: least squares from a grid of starts).
    """
    if p.points == 4:
        grid = np.linspace(0.0, 2 * math.pi, 721)
        det = np.array([np.linalg.det(system(g, out0)) for g in grid])
        roots = []
        for k in np.flatnonzero(np.sign(det[:-1]) * np.sign(det[1:]) < 0):
            root = brentq(lambda g: np.linalg.det(system(g, out0)), grid[k], grid[k + 1])
            roots.append((float(root), out0))
        return roots
    four = p.linkage is FunctionLinkage.FOURBAR
    span = 2 * math.pi if four else 4.0 * abs(p.output_range)
    found = []

    def residual(v):
        m = system(v[0], v[1])
        k, *_ = np.linalg.lstsq(m[:, :3], m[:, 3], rcond=None)
        return m[:, :3] @ k - m[:, 3]

    for g in np.linspace(0.0, 2 * math.pi, 12, endpoint=False):
        for h in np.linspace(out0 - span / 2, out0 + span / 2, 12, endpoint=False):
            fit = least_squares(residual, [g, h], method="lm", xtol=1e-15, ftol=1e-15)
            if np.max(np.abs(fit.fun)) < 1e-12:
                found.append((float(fit.x[0] % (2 * math.pi)), float(fit.x[1])))
    unique: list[tuple[float, float]] = []
    for r in found:
        if all(abs(r[0] - u[0]) + abs(r[1] - u[1]) > 1e-7 for u in unique):
            unique.append(r)
    return unique


def _range_error(p, xs_range, generated_y, ys_range):
    error = generated_y - ys_range
    return error, float(np.max(np.abs(error)))


# ------------------------------------------------------------------ the four-bar
def _fourbar(p: FunctionProblem, xs, ys, y0, y1) -> FunctionDesign:
    phi_of, psi_of = _maps(p, y0, y1)
    ((phi0, psi0, free_phi, _),) = _starts(p)

    def rows(g, h):
        phi, psi = phi_of(xs, g), psi_of(ys, h)
        return np.column_stack([np.cos(psi), -np.cos(phi), np.ones_like(phi)]), np.cos(phi - psi)

    def system(g, h):
        m, rhs = rows(g, h)
        return np.column_stack([m, rhs])

    if free_phi:
        candidates = _solve_starts(system, p, phi0, psi0)
        if not candidates:
            raise SynthesisError(
                f"{p.points} precision points: no start angles make Freudenstein's equations "
                "consistent for these ranges; change --output-start or the ranges"
            )
    else:
        candidates = [(phi0, psi0)]
    best, last_error = None, None
    for g, h in candidates:
        try:
            design = _fourbar_design(p, xs, ys, y0, y1, g, h, rows)
        except SynthesisError as exc:
            last_error = exc
            continue
        if best is None or _preferred(design, best):
            best = design
    if best is None:
        raise last_error  # type: ignore[misc]
    return best


def _preferred(design: FunctionDesign, other: FunctionDesign) -> bool:
    """Of two solutions, the one whose transmission angle keeps farthest from 0° and 180°."""

    def worst(d: FunctionDesign) -> float:
        low, high = d.transmission_deg
        return min(low, 180.0 - high) if d.problem.linkage is FunctionLinkage.FOURBAR else low

    return worst(design) > worst(other)


def _fourbar_design(p, xs, ys, y0, y1, phi0, psi0, rows) -> FunctionDesign:
    phi_of, psi_of = _maps(p, y0, y1)
    m, rhs = rows(phi0, psi0)
    k, *_ = np.linalg.lstsq(m, rhs, rcond=None)
    k1, k2, k3 = (float(v) for v in k)
    if abs(k1) < 1e-12 or abs(k2) < 1e-12:
        raise SynthesisError("Freudenstein's constants give an infinite crank or rocker")
    d = p.size
    a, c = d / k1, d / k2
    b2 = a * a + c * c + d * d - 2 * a * c * k3
    if not b2 > 1e-12 * d * d:
        raise SynthesisError(
            f"Freudenstein's constants give a coupler of length² {b2:.3g} (no real coupler): "
            "change the start angles (--input-start, --output-start) or the ranges"
        )
    b = math.sqrt(b2)
    phis, psis = phi_of(xs, phi0), psi_of(ys, psi0)
    bx, by = a * np.cos(phis), a * np.sin(phis)
    cx, cy = d + c * np.cos(psis), c * np.sin(psis)
    sides = np.sign((d - bx) * (cy - by) - (0.0 - by) * (cx - bx))
    if np.any(sides != sides[0]) or sides[0] == 0:
        raise SynthesisError(
            "the precision points lie on both assembly modes of the linkage (a circuit "
            "defect): change the start angles or the ranges"
        )
    side = float(sides[0])
    x_range = np.linspace(p.x0, p.x1, RANGE_SAMPLES)
    phi_range = phi_of(x_range, phi0)
    psi_range, mu = _rocker_angle(a, b, c, d, phi_range, side)
    # the rocker's angle unwrapped next to the desired one, then mapped back onto y
    desired = psi_of(p.function(x_range), psi0)
    psi_range = desired + np.angle(np.exp(1j * (psi_range - desired)))
    generated_y = y0 + (psi_range - psi0) / math.radians(p.output_range) * (y1 - y0)
    error, error_max = _range_error(p, x_range, generated_y, p.function(x_range))
    at_psi, _ = _rocker_angle(a, b, c, d, phis, side)
    at = np.angle(np.exp(1j * (at_psi - psis))) / math.radians(p.output_range) * (y1 - y0)
    kind = str(grashof_kind(*(np.array([v]) for v in (d, abs(a), b, abs(c))))[0])
    mech = _fourbar_mechanism(p, a, b, c, d, phis, psis, phi_range[0], psi_range[0])
    mu_deg = np.degrees(mu)
    return FunctionDesign(
        p,
        {"d": d, "a": a, "b": b, "c": c},
        tuple(float(v) for v in xs),
        tuple(float(math.degrees(v)) for v in phis),
        tuple(float(math.degrees(v)) for v in psis),
        math.degrees(phi0),
        math.degrees(psi0),
        x_range,
        error,
        error_max,
        float(np.max(np.abs(at))),
        side,
        mech,
        (float(mu_deg.min()), float(mu_deg.max())),
        kind,
    )


def _rocker_angle(a, b, c, d, phi, side):
    """ψ (the rocker's angle of the signed rocker c) and the transmission angle, over φ.

    Raises SynthesisError where the linkage cannot be assembled or meets a
    dead point (the coupler and rocker in line) inside the range.
    """
    bx, by = a * np.cos(phi), a * np.sin(phi)
    ex, ey = d - bx, -by
    e2 = ex * ex + ey * ey
    along = (e2 + b * b - c * c) / (2 * np.sqrt(e2))
    h2 = b * b - along * along
    if np.any(h2 <= 1e-12 * d * d):
        raise SynthesisError(
            "the linkage cannot move over the whole input range on one assembly mode (it "
            "meets a dead point or cannot close inside the range: a branch defect); change "
            "the ranges or the start angles"
        )
    h = np.sqrt(h2)
    inv = 1 / np.sqrt(e2)
    cx = bx + along * ex * inv - side * h * ey * inv
    cy = by + along * ey * inv + side * h * ex * inv
    psi = np.arctan2(cy, cx - d)
    if c < 0:
        psi = psi + math.pi
    mu = np.arccos(np.clip((b * b + c * c - e2) / (2 * b * abs(c)), -1, 1))
    return psi, mu


def _fourbar_mechanism(p, a, b, c, d, phis, psis, phi_start, psi_start) -> Mechanism:
    """The four-bar at x0 (the sketch), P on the rocker at C; the targets C's precision places."""
    points = [
        make_point("A", 0.0, 0.0),
        make_point("B", a * math.cos(phi_start), a * math.sin(phi_start)),
        make_point("C", d + c * math.cos(psi_start), c * math.sin(psi_start)),
        make_point("D", d, 0.0),
    ]
    points.append(make_point("P", points[2].x, points[2].y, "3"))
    targets = tuple(
        make_target(
            f"T{j + 1}",
            d + c * math.cos(psi),
            c * math.sin(psi),
            math.degrees(phi - phi_start),
            math.degrees(psi),
        )
        for j, (phi, psi) in enumerate(zip(phis, psis, strict=True))
    )
    m = Mechanism.from_pairs(
        [("0", "1", "R", "A"), ("1", "2", "R", "B"), ("2", "3", "R", "C"), ("3", "0", "R", "D")],
        drivers=["1"],
        points=points,
        name=f"four-bar function generator of y = {p.function.text}",
        source="<synthesis>",
    )
    return validated(m.evolve(targets=targets))


# ------------------------------------------------------------------ the crank–slider
def _crank_slider(p: FunctionProblem, xs, ys, y0, y1) -> FunctionDesign:
    phi_of, s_of = _maps(p, y0, y1)
    ((phi0, s0, free_phi, _),) = _starts(p)

    def rows(g, h):
        phi, s = phi_of(xs, g), s_of(ys, h)
        return np.column_stack([s * np.cos(phi), np.sin(phi), -np.ones_like(phi)]), s * s

    def system(g, h):
        m, rhs = rows(g, h)
        return np.column_stack([m, rhs])

    if free_phi:
        candidates = _solve_starts(system, p, phi0, s0)
        if not candidates:
            raise SynthesisError(
                f"{p.points} precision points: no start values make the crank–slider's "
                "equations consistent for these ranges; change --output-start or the ranges"
            )
    else:
        candidates = [(phi0, s0)]
    best, last_error = None, None
    for g, h in candidates:
        try:
            design = _slider_design(p, xs, ys, y0, y1, g, h, rows)
        except SynthesisError as exc:
            last_error = exc
            continue
        if best is None or _preferred(design, best):
            best = design
    if best is None:
        raise last_error  # type: ignore[misc]
    return best


def _slider_design(p, xs, ys, y0, y1, phi0, s0, rows) -> FunctionDesign:
    phi_of, s_of = _maps(p, y0, y1)
    m, rhs = rows(phi0, s0)
    k, *_ = np.linalg.lstsq(m, rhs, rcond=None)
    k1, k2, k3 = (float(v) for v in k)
    a = k1 / 2
    if abs(a) < 1e-12 * abs(p.output_range):
        raise SynthesisError("the crank–slider's constants give a crank of zero length")
    e = k2 / k1
    b2 = a * a + e * e - k3
    scale = abs(p.output_range)
    if not b2 > 1e-12 * scale * scale:
        raise SynthesisError(
            f"the crank–slider's constants give a rod of length² {b2:.3g} (no real rod): change "
            "--output-start, --input-start or the ranges"
        )
    b = math.sqrt(b2)
    phis, ss = phi_of(xs, phi0), s_of(ys, s0)
    sides = np.sign(ss - a * np.cos(phis))
    if np.any(sides != sides[0]) or sides[0] == 0:
        raise SynthesisError(
            "the precision points lie on both assembly modes of the crank–slider (a circuit "
            "defect): change the start values or the ranges"
        )
    side = float(sides[0])
    x_range = np.linspace(p.x0, p.x1, RANGE_SAMPLES)
    phi_range = phi_of(x_range, phi0)
    rise = b2 - (a * np.sin(phi_range) - e) ** 2
    if np.any(rise <= 1e-12 * b2):
        raise SynthesisError(
            "the crank–slider cannot move over the whole input range on one assembly mode (a "
            "dead point or no closure inside the range: a branch defect); change the ranges"
        )
    s_range = a * np.cos(phi_range) + side * np.sqrt(rise)
    generated_y = y0 + (s_range - s0) / p.output_range * (y1 - y0)
    error, error_max = _range_error(p, x_range, generated_y, p.function(x_range))
    s_at = a * np.cos(phis) + side * np.sqrt(b2 - (a * np.sin(phis) - e) ** 2)
    at = (s_at - ss) / p.output_range * (y1 - y0)
    # transmission: the rod against the slide's normal (90° pushing along it), as the solvers say
    mu = np.degrees(np.arcsin(np.clip(np.abs(s_range - a * np.cos(phi_range)) / b, 0, 1)))
    mech = _slider_mechanism(p, a, b, e, phis, ss, phi_range[0], s_range[0])
    return FunctionDesign(
        p,
        {"a": a, "b": b, "e": e},
        tuple(float(v) for v in xs),
        tuple(float(math.degrees(v)) for v in phis),
        tuple(float(v) for v in ss),
        math.degrees(phi0),
        float(s0),
        x_range,
        error,
        error_max,
        float(np.max(np.abs(at))),
        side,
        mech,
        (float(mu.min()), float(mu.max())),
        "crank" if abs(a) + abs(e) < b else "rocker",
    )


def _slider_mechanism(p, a, b, e, phis, ss, phi_start, s_start) -> Mechanism:
    """The crank–slider at x0, P on the slider at C; the targets C's precision places."""
    points = [
        make_point("A", 0.0, 0.0),
        make_point("B", a * math.cos(phi_start), a * math.sin(phi_start)),
        make_point("C", s_start, e),
        make_point("P", s_start, e, "3"),
    ]
    targets = tuple(
        make_target(f"T{j + 1}", float(s), e, math.degrees(phi - phi_start))
        for j, (phi, s) in enumerate(zip(phis, ss, strict=True))
    )
    m = Mechanism.from_pairs(
        [
            ("0", "1", "R", "A"),
            ("1", "2", "R", "B"),
            ("2", "3", "R", "C"),
            ("3", "0", "P", "C", {"angle": 0}),
        ],
        drivers=["1"],
        points=points,
        name=f"crank–slider function generator of y = {p.function.text}",
        source="<synthesis>",
    )
    return validated(m.evolve(targets=targets))
