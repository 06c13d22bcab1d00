"""A follower program: its segments laid end to end over a turn, evaluated in closed form.

:func:`make_program` turns the segments of a :class:`~structure.cams.CamSpec`
into pieces with their start angles, the displacement each starts from and,
for a fitted polynomial, its coefficients. :func:`program_values` gives the
displacement ``s(θ)`` and its derivatives by the cam angle ``s', s'', s'''`` at
any angles (in closed form, per piece); :func:`time_values` the velocity,
acceleration and jerk at the cam speed ``ω`` (``v = s'·|ω|``, ``a = s''·ω²``,
``j = s'''·|ω|³``). :func:`continuity` reports the order of continuity at each
join (a jump in acceleration is an infinite jerk: the fundamental law of cam
design) and :func:`peaks` the largest values and where.

Inside, an oscillating follower's displacement is in radians (degrees in the
files and the outputs); a translating follower's in metres.

>>> from structure.cams import cam_spec_from_dict
>>> spec = cam_spec_from_dict({"base_radius": 0.04, "omega": 10,
...     "follower": {"motion": "translating", "contact": "knife"},
...     "segments": [{"law": "harmonic", "lift": 0.01, "angle": 90},
...                  {"law": "dwell", "angle": 90},
...                  {"law": "cycloidal", "lift": -0.01, "angle": 90},
...                  {"law": "dwell", "angle": 90}]})
>>> program = make_program(spec)
>>> [(j.at_deg, j.order) for j in continuity(program)]
[(90.0, 1), (180.0, 2), (270.0, 2), (0.0, 1)]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from structure.cams import CamSpec, MotionLaw
from structure.errors import CamProgramError, EdgeListProblem

from .laws import (
    fit_polynomial,
    law_candidates,
    polynomial_candidates,
    polynomial_derivatives,
    unit_law,
)

__all__ = [
    "Join",
    "Peak",
    "Piece",
    "Program",
    "continuity",
    "make_program",
    "peaks",
    "program_values",
    "time_values",
]

TURN = 2.0 * math.pi
#: a jump at a join is one where the two sides differ by more than this, relative to the
#: largest value of that derivative over the program
JUMP_TOLERANCE = 1e-9


@dataclass(frozen=True, slots=True)
class Piece:
    """One segment of the program, laid on the turn.

    ``start`` and ``duration`` in radians of cam angle, ``base`` the
    displacement it starts from, ``lift`` its travel (metres, or radians for an
    oscillating follower); ``coefficients`` those of a fitted polynomial of
    ``x = (θ − start)/duration`` giving the displacement itself.
    """

    index: int
    law: MotionLaw
    start: float
    duration: float
    base: float
    lift: float
    coefficients: tuple[float, ...] | None = None
    #: the points of [0, 1] that hold the extremes of the piece's derivatives (found once)
    extremes: tuple[float, ...] = ()

    @property
    def end(self) -> float:
        return self.start + self.duration

    def values(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(s, s', s'', s''')`` at ``x`` in [0, 1] of the piece (derivatives by the cam angle)."""
        beta = self.duration
        if self.coefficients is not None:
            y, y1, y2, y3 = polynomial_derivatives(np.array(self.coefficients), x)
            return y, y1 / beta, y2 / beta**2, y3 / beta**3
        y, y1, y2, y3 = unit_law(self.law, x)
        h = self.lift
        return self.base + h * y, h * y1 / beta, h * y2 / beta**2, h * y3 / beta**3

    def candidates(self) -> tuple[float, ...]:
        """Points of [0, 1] holding the extremes of the piece's s', s'' and s'''."""
        if self.extremes:
            return self.extremes
        if self.coefficients is not None:
            return polynomial_candidates(np.array(self.coefficients))
        return law_candidates(self.law)


@dataclass(frozen=True, slots=True)
class Program:
    """The pieces of a follower program over one turn, and its units.

    ``angular``: the follower swings (displacements in radians inside);
    ``scale`` is the program's largest swing (for tolerances).
    """

    pieces: tuple[Piece, ...]
    angular: bool
    scale: float

    @property
    def starts(self) -> np.ndarray:
        return np.array([p.start for p in self.pieces])

    def to_file_units(self, s: np.ndarray) -> np.ndarray:
        """Displacements in the files' units: degrees for a swinging follower, else metres."""
        return np.degrees(s) if self.angular else s


def make_program(spec: CamSpec) -> Program:
    """The pieces of ``spec``'s program, polynomials fitted to their conditions.

    Raises
    ------
    CamProgramError
        A polynomial segment whose conditions do not fix one polynomial (two
        on the same point and order, too few, or a singular set).
    """
    angular = not spec.follower.translating
    unit = math.radians if angular else float
    pieces: list[Piece] = []
    start = 0.0
    first = spec.segments[0]
    base = unit(first.start_value) if first.law is MotionLaw.POLYNOMIAL else 0.0
    problems: list[EdgeListProblem] = []
    omega = abs(spec.omega)
    for i, segment in enumerate(spec.segments):
        beta = math.radians(segment.angle_deg)
        coefficients = None
        if segment.law is MotionLaw.POLYNOMIAL:
            conditions = []
            for c in segment.conditions:
                for order, value in c.values:
                    # s in the files' units; v, a, j are time rates: per radian of cam turn
                    v = unit(value) if order == 0 else value / omega**order
                    conditions.append((c.at_deg / segment.angle_deg, order, v))
            fitted = fit_polynomial(conditions, beta)
            if fitted is None:
                problems.append(
                    EdgeListProblem(
                        0,
                        "",
                        f"segments[{i}]: the boundary conditions do not fix one polynomial "
                        "(give each condition once, at distinct points, e.g. s, v, a at both "
                        "ends)",
                    )
                )
                continue
            coefficients = tuple(float(c) for c in fitted)
            base = float(np.polynomial.Polynomial(fitted)(0.0))
        lift = unit(segment.lift)
        extremes = (
            polynomial_candidates(np.array(coefficients))
            if coefficients is not None
            else law_candidates(segment.law)
        )
        pieces.append(Piece(i, segment.law, start, beta, base, lift, coefficients, extremes))
        base += lift
        start += beta
    if problems:
        raise CamProgramError("<cam spec>", problems)
    scale = unit(spec.total_lift) or 1.0
    return Program(tuple(pieces), angular, scale)


def _locate(program: Program, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each angle's piece and its ``x`` in that piece (angles wrapped to one turn)."""
    t = np.mod(theta, TURN)
    starts = program.starts
    index = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(starts) - 1)
    durations = np.array([p.duration for p in program.pieces])
    x = np.clip((t - starts[index]) / durations[index], 0.0, 1.0)
    return index, x


def program_values(
    program: Program, theta: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(s, s', s'', s''')`` at cam angles ``theta`` (radians; any turn), by the cam angle.

    At a join the piece that starts there gives the values.
    """
    theta = np.asarray(theta, dtype=float)
    flat = theta.reshape(-1)
    index, x = _locate(program, flat)
    out = [np.empty_like(flat) for _ in range(4)]
    for k, piece in enumerate(program.pieces):
        mine = index == k
        if mine.any():
            for target, value in zip(out, piece.values(x[mine]), strict=True):
                target[mine] = value
    return tuple(o.reshape(theta.shape) for o in out)  # type: ignore[return-value]


def time_values(
    program: Program, theta: np.ndarray, omega: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(s, v, a, j)`` in time at the constant cam speed ``omega`` (rad/s; its size is used)."""
    s, s1, s2, s3 = program_values(program, theta)
    w = abs(omega)
    return s, s1 * w, s2 * w**2, s3 * w**3


@dataclass(frozen=True, slots=True)
class Join:
    """Where segment ``before`` meets segment ``after``, at ``at_deg`` of cam angle.

    ``order`` is the order of continuity there: 3 when s, s', s'' and s''' all
    agree, 2 when the jerk jumps, 1 when the acceleration jumps (an infinite
    jerk), 0 when the velocity jumps (an infinite acceleration), −1 when the
    displacement does. ``jumps`` holds ``(order, left, right)`` of each
    derivative that jumps (by the cam angle, per radian^order).
    """

    at_deg: float
    before: int
    after: int
    order: int
    jumps: tuple[tuple[int, float, float], ...]

    @property
    def infinite_jerk(self) -> bool:
        """The acceleration (or a lower derivative) jumps: the jerk is infinite there."""
        return self.order < 2

    @property
    def name(self) -> str:
        """``'C2'`` and the like (``'C−1'`` for a jump of the displacement)."""
        return f"C{self.order}" if self.order >= 0 else "C−1"


def _scales(program: Program) -> list[float]:
    """The largest magnitudes of s and its three derivatives over the program (join tolerances)."""
    values = [piece.values(np.array(piece.candidates())) for piece in program.pieces]
    tiny = program.scale * 1e-12
    return [max(max(float(np.max(np.abs(v[k]))) for v in values), tiny) for k in range(4)]


def continuity(program: Program) -> tuple[Join, ...]:
    """The order of continuity at each join (the last segment's end to the first's start too)."""
    scales = _scales(program)
    joins: list[Join] = []
    n = len(program.pieces)
    one, zero = np.array([1.0]), np.array([0.0])
    for k, piece in enumerate(program.pieces):
        after = program.pieces[(k + 1) % n]
        left = [float(v[0]) for v in piece.values(one)]
        right = [float(v[0]) for v in after.values(zero)]
        jumps = tuple(
            (order, left[order], right[order])
            for order in range(4)
            if abs(left[order] - right[order]) > JUMP_TOLERANCE * scales[order]
        )
        order = min((j[0] for j in jumps), default=4) - 1
        at = round(math.degrees(piece.end), 9) % 360.0
        joins.append(Join(at, piece.index, after.index, min(order, 3), jumps))
    return tuple(joins)


@dataclass(frozen=True, slots=True)
class Peak:
    """The largest magnitude of a quantity over the cycle, signed, and the cam angle it is at."""

    value: float
    at_deg: float


def peaks(program: Program, omega: float, samples: np.ndarray | None = None) -> dict[str, Peak]:
    """The peaks of ``v``, ``a`` and ``j`` at ``omega``, found at each law's own extremes.

    Every law's velocity, acceleration and jerk take their extremes at known
    points (:func:`~kinematics.cams.laws.law_candidates`), so the peaks are
    exact, not those of a sampling; ``samples`` (cam angles, radians) are
    looked at too. At a join where the acceleration jumps the jerk is infinite:
    :func:`continuity` says where; ``j`` here is the largest finite jerk.
    """
    thetas = []
    for piece in program.pieces:
        x = np.array(piece.candidates())
        # just inside the piece: its own values at its ends, not its neighbour's
        x = np.clip(x, 0.0, np.nextafter(1.0, 0.0))
        thetas.append(piece.start + piece.duration * x)
    theta = np.concatenate([*thetas, *(() if samples is None else (np.asarray(samples),))])
    _, v, a, j = time_values(program, theta, omega)
    out = {}
    for key, values in (("v", v), ("a", a), ("j", j)):
        k = int(np.argmax(np.abs(values)))
        out[key] = Peak(float(values[k]), round(math.degrees(float(theta[k])) % 360.0, 9))
    return out
