"""Motion generation: a four-bar whose coupler carries a body through 2 to 5 given poses.

A pose is ``(x, y, θ)``: where the body's reference point is and how the body
is turned. A dyad (a crank from a fixed centre point to a moving circle point
of the body) is compatible with the poses when the circle point's positions
all lie on one circle about the centre point (McCarthy & Soh, *Geometric
Design of Linkages*; Sandor & Erdman, *Advanced Mechanism Design*):

* two poses: the pole P12 (the displacement is a rotation about it); a circle
  point's two positions have their centre anywhere on their perpendicular
  bisector, which passes through the pole;
* three poses: the centre of the circle through a circle point's three
  positions (the circle points and centre points by construction);
* four poses: the circle points whose four positions are concyclic,
  ``det[|M_j|², x_j, y_j, 1] = 0`` (a cubic in the body point, the
  circle-point curve), and their centres (the centre-point curve);
* five poses: the points on the circle-point curves of poses 1234 and 1235
  both, less the poles (Burmester points; at most four).

Dyads are paired into four-bars; each pairing is checked first by the
solvers' closed form (one assembly mode at every pose: no circuit defect;
the crank turning one way through the poses: no order defect; the dyad
closing all the way between them: no branch defect), then, for the best,
through the group-by-group solvers (:mod:`.defects`). Designs free of defects
come first, then by their worst transmission angle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from itertools import combinations

import numpy as np
from scipy.optimize import least_squares

from structure.model import Mechanism

from ..errors import SynthesisError
from .defects import Defects, check_targets
from .linkages import Linkage, design_mechanism, linkage_poses, target_records

__all__ = [
    "Dyad",
    "MotionDesign",
    "burmester_points",
    "centre_point",
    "circle_point_curve",
    "pole",
    "synthesize_motion",
]


#: the most candidate dyads paired (every pair of them is checked)
_MOST_DYADS = 40


def _rotation(theta: float) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s], [s, c]])


def _world(poses: np.ndarray, m: np.ndarray) -> np.ndarray:
    """The positions (poses, 2) of body point ``m`` (body frame) at each pose."""
    return np.array([p[:2] + _rotation(p[2]) @ m for p in poses])


def pole(p1: np.ndarray, p2: np.ndarray) -> np.ndarray:
    """The pole of the displacement from pose p1 to p2 (x, y, θ in rad): its fixed point.

    >>> p = pole(np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, math.pi / 2]))
    >>> (p.round(12) + 0.0).tolist()
    [0.0, 0.0]

    Raises
    ------
    SynthesisError
        The two poses differ by a translation only (the pole is at infinity).
    """
    r = _rotation(p2[2]) @ _rotation(p1[2]).T
    t = p2[:2] - r @ p1[:2]
    m = np.eye(2) - r
    if abs(np.linalg.det(m)) < 1e-14:
        raise SynthesisError("the poses differ by a translation only: the pole is at infinity")
    return np.linalg.solve(m, t)


def centre_point(poses: np.ndarray, m: np.ndarray) -> np.ndarray | None:
    """The centre of the circle through the positions of circle point ``m`` in three poses.

    None where the three positions are in line (the centre is at infinity).
    """
    z = _world(poses[:3], m)
    a = 2 * np.array([z[1] - z[0], z[2] - z[0]])
    rhs = np.array([z[1] @ z[1] - z[0] @ z[0], z[2] @ z[2] - z[0] @ z[0]])
    if abs(np.linalg.det(a)) < 1e-12 * max(1.0, float(np.abs(a).max()) ** 2):
        return None
    return np.linalg.solve(a, rhs)


def _concyclic(poses: np.ndarray, m: np.ndarray) -> float:
    """``det[|M_j|², x_j, y_j, 1]`` of four positions of ``m`` (zero when concyclic)."""
    z = _world(poses[:4], m)
    rows = np.column_stack([(z * z).sum(axis=1), z, np.ones(4)])
    return float(np.linalg.det(rows))


def circle_point_curve(poses: np.ndarray, size: float, rays: int = 180) -> np.ndarray:
    """Points of the circle-point curve of four poses (body frame), shape (k, 2).

    Along each ray from the body's reference point the concyclicity
    determinant is a cubic in the distance (fitted exactly through four of its
    values); its real roots within ``4·size`` are the curve's points there.
    """
    out = []
    ts = np.array([-1.0, -0.3, 0.4, 1.0]) * size
    for alpha in np.linspace(0.0, math.pi, rays, endpoint=False):
        u = np.array([math.cos(alpha), math.sin(alpha)])
        values = [_concyclic(poses, t * u) for t in ts]
        coeffs = np.polyfit(ts, values, 3)
        for root in np.roots(coeffs):
            if abs(root.imag) < 1e-9 * size and abs(root.real) <= 4 * size:
                out.append(root.real * u)
    return np.array(out).reshape(-1, 2)


def burmester_points(poses: np.ndarray, size: float) -> np.ndarray:
    """The Burmester points of five poses (body frame): at most four, shape (k, 2).

    Solutions of both concyclicity conditions (poses 1234 and 1235) from a grid
    of starts; the poles' images (where two positions of the point coincide,
    trivially on both curves) are left out.
    """
    first, second = poses[[0, 1, 2, 3]], poses[[0, 1, 2, 4]]
    scale = size**4

    def residual(m):
        return [_concyclic(first, m) / scale, _concyclic(second, m) / scale]

    found: list[np.ndarray] = []
    for gx in np.linspace(-2.5, 2.5, 9):
        for gy in np.linspace(-2.5, 2.5, 9):
            fit = least_squares(residual, [gx * size, gy * size], method="lm", xtol=1e-15)
            if max(abs(v) for v in fit.fun) > 1e-12:
                continue
            m = fit.x
            z = _world(poses, m)
            gaps = [np.linalg.norm(z[i] - z[j]) for i, j in combinations(range(5), 2)]
            if min(gaps) < 1e-6 * size or np.linalg.norm(m) > 20 * size:
                continue
            if all(np.linalg.norm(m - f) > 1e-6 * size for f in found):
                found.append(m)
    return np.array(found).reshape(-1, 2)


@dataclass(frozen=True)
class Dyad:
    """A crank of the design: its centre point (fixed pivot) and circle point (body frame)."""

    centre: np.ndarray
    circle: np.ndarray  # in the body's frame


@dataclass(frozen=True)
class MotionDesign:
    """One four-bar for the poses: its two dyads, its mechanism and what the solvers found.

    ``pivots``: the fixed pivots A, D and the moving pivots B, C at the
    first pose; ``defects``: the defects found (closed form, then the
    solvers for the designs checked there); ``transmission_deg``: the least
    and largest transmission angle between the first and last pose;
    ``inputs_deg``: the crank's rotation from the first pose at each pose.
    """

    pivots: dict[str, tuple[float, float]]
    lengths: dict[str, float]
    mechanism: Mechanism
    defects: Defects
    transmission_deg: tuple[float, float]
    inputs_deg: tuple[float, ...]
    checked: bool


def _dyads(poses: np.ndarray, size: float) -> list[Dyad]:
    """Candidate dyads for the poses (see the module's text)."""
    n = len(poses)
    grid = [
        np.array([gx, gy]) * size
        for gx in np.linspace(-1.5, 1.5, 7)
        for gy in np.linspace(-1.5, 1.5, 7)
    ]
    out: list[Dyad] = []
    if n == 2:
        z = [_world(poses, m) for m in grid]
        for m, (z1, z2) in zip(grid, z, strict=True):
            chord = np.linalg.norm(z2 - z1)
            if chord < 1e-9 * size:
                continue
            mid, normal = (z1 + z2) / 2, np.array([-(z2 - z1)[1], (z2 - z1)[0]]) / chord
            for k in (-1.5, -0.6, 0.6, 1.5):
                out.append(Dyad(mid + k * chord * normal, m))
        return out[:: max(1, len(out) // _MOST_DYADS)]
    if n == 3:
        points = grid
    elif n == 4:
        points = list(circle_point_curve(poses, size, rays=60))
    else:
        points = list(burmester_points(poses, size))
    for m in points:
        c = centre_point(poses, m)
        if c is not None and np.linalg.norm(c) < 50 * size:
            out.append(Dyad(c, m))
    return out[:: max(1, len(out) // _MOST_DYADS)]


def _design_row(poses: np.ndarray, crank: Dyad, rocker: Dyad) -> np.ndarray | None:
    """The four-bar of two dyads as a row of linkage numbers, P at the body's reference point."""
    a_, d_ = crank.centre, rocker.centre
    b1, c1 = _world(poses[:1], crank.circle)[0], _world(poses[:1], rocker.circle)[0]
    d = np.linalg.norm(d_ - a_)
    a, b, c = np.linalg.norm(b1 - a_), np.linalg.norm(c1 - b1), np.linalg.norm(c1 - d_)
    if min(d, a, b, c) < 1e-9 * max(d, a, b, c, 1e-300):
        return None
    u = (c1 - b1) / b
    rel = poses[0, :2] - b1
    p, q = rel @ u, u[0] * rel[1] - u[1] * rel[0]
    side = np.sign((d_ - b1)[0] * (c1 - b1)[1] - (d_ - b1)[1] * (c1 - b1)[0])
    theta0 = math.atan2(*(d_ - a_)[::-1])
    phi1 = math.atan2(*(b1 - a_)[::-1])
    return np.array([a_[0], a_[1], theta0, d, a, b, c, p, q, phi1, side])


def _crank_inputs(poses: np.ndarray, crank: Dyad) -> np.ndarray | None:
    """The crank's rotation from the first pose at each pose, one way round; None: order defect."""
    z = _world(poses, crank.circle) - crank.centre
    angles = np.arctan2(z[:, 1], z[:, 0])
    steps = np.diff(angles)
    ccw, cw = np.mod(steps, 2 * math.pi), -np.mod(-steps, 2 * math.pi)
    for way in sorted((ccw, cw), key=lambda w: abs(w.sum())):  # the shorter way round first
        if abs(way.sum()) < 2 * math.pi - 1e-9:
            return np.concatenate([[0.0], np.cumsum(way)])
    return None


def _quick(
    rows: np.ndarray, inputs: np.ndarray, moving: np.ndarray
) -> tuple[list[Defects], np.ndarray]:
    """The closed-form check of many pairings at once: circuit, branch; transmission ranges.

    ``rows`` (K, parameters), ``inputs`` (K, poses): the crank's rotations,
    ``moving`` (K, poses, 2, 2): the circle points B and C where the poses put them.
    """
    b, c = moving[:, :, 0], moving[:, :, 1]
    d = linkage_poses(Linkage.FOURBAR, rows, rows[:, 9:10] + inputs).points["D"]
    sides = np.sign((d - b)[..., 0] * (c - b)[..., 1] - (d - b)[..., 1] * (c - b)[..., 0])
    path = rows[:, 9:10] + inputs[:, -1:] * np.linspace(0.0, 1.0, 200)[None, :]
    along = linkage_poses(Linkage.FOURBAR, rows, path)
    mu = np.degrees(along.transmission[0])
    spans = np.column_stack([mu.min(axis=1), mu.max(axis=1)])
    circuit = np.any(sides != rows[:, 10:11], axis=1)
    branch = along.heights[0].min(axis=1) <= 1e-10 * rows[:, 3] ** 2
    out = []
    for k in range(len(rows)):
        if circuit[k]:
            out.append(Defects(circuit=True, reason="a pose needs the other assembly mode"))
        elif branch[k]:
            out.append(Defects(branch=True, reason="a dead point between the poses"))
        else:
            out.append(Defects())
    return out, spans


def synthesize_motion(poses: np.ndarray, *, check: int = 12) -> list[MotionDesign]:
    """Four-bars that carry a body through ``poses`` (rows x, y, θ in degrees), best first.

    Defect-free designs come first, then by their worst transmission angle;
    the first ``check`` of them are run through the group-by-group solvers
    as well (``checked``), and a design the solvers refuse gets its defect.

    Raises
    ------
    SynthesisError
        Fewer than 2 or more than 5 poses, poses that coincide, or no pair of
        dyads that makes a four-bar.
    """
    poses = np.array(poses, dtype=float)
    if poses.ndim != 2 or poses.shape[1] != 3 or not np.all(np.isfinite(poses)):
        raise SynthesisError("poses are rows x, y, angle_deg of finite numbers")
    n = len(poses)
    if not 2 <= n <= 5:
        raise SynthesisError(f"{n} pose(s): motion generation takes 2 to 5 poses")
    poses[:, 2] = np.radians(poses[:, 2])
    centre = poses[:, :2].mean(axis=0)
    size = float(np.max(np.linalg.norm(poses[:, :2] - centre, axis=1)))
    turns = np.ptp(np.angle(np.exp(1j * (poses[:, 2] - poses[0, 2]))))
    if size <= 0 and turns == 0:
        raise SynthesisError("the poses coincide: there is no motion to generate")
    size = max(size, 1e-3 * abs(turns) or 1.0) if size <= 0 else size
    for i, j in combinations(range(n), 2):
        if np.linalg.norm(poses[i] - poses[j]) < 1e-12 * max(size, 1.0):
            raise SynthesisError(f"poses {i + 1} and {j + 1} are the same")
    dyads = _dyads(poses, size)
    rows, inputs, moving, unordered = [], [], [], 0
    for crank, rocker in ((p, q) for p in dyads for q in dyads if p is not q):
        row = _design_row(poses, crank, rocker)
        if row is None or row[3:7].max() / row[3:7].min() > 20:
            continue
        turn = _crank_inputs(poses, crank)
        if turn is None:
            unordered += 1
            continue
        rows.append(row)
        inputs.append(turn)
        moving.append(np.stack([_world(poses, crank.circle), _world(poses, rocker.circle)], 1))
    if not rows:
        why = " (the crank cannot pass the poses in order)" if unordered else ""
        raise SynthesisError(f"no pair of dyads makes a four-bar for these poses{why}")
    found, spans = _quick(np.array(rows), np.array(inputs), np.array(moving))
    rated = []
    for k, (defects, span) in enumerate(zip(found, spans, strict=True)):
        worst = min(span[0], 180.0 - span[1])
        rated.append(
            (
                not defects.ok,
                -worst,
                k,
                rows[k],
                inputs[k],
                defects,
                (float(span[0]), float(span[1])),
            )
        )
    rated.sort(key=lambda r: (r[0], r[1], r[2]))
    out = []
    for k, (_, _, _, row, inputs, defects, span) in enumerate(rated[: max(check, 1) * 3]):
        design = _motion_design(poses, row, inputs, defects, span, checked=k < check)
        out.append(design)
    out.sort(
        key=lambda d: (
            not d.defects.ok,
            not d.checked,
            -min(d.transmission_deg[0], 180 - d.transmission_deg[1]),
        )
    )
    return out


def _motion_design(poses, row, inputs, defects, span, checked: bool) -> MotionDesign:
    inputs_deg = np.degrees(inputs) if inputs is not None else np.zeros(len(poses))
    records = target_records(poses[:, :2], inputs_deg, np.degrees(poses[:, 2]))
    mech = design_mechanism(Linkage.FOURBAR, row, records, "four-bar motion generator")
    if checked and defects.ok:
        size = float(np.max(np.abs(row[3:7])))
        found = check_targets(mech, 1e-9 * size)
        if found.ok and (found.distance > 1e-9 * size or found.angle > 1e-7):
            found = Defects(
                circuit=True,
                reason="the solvers reach a pose in another place",
                distance=found.distance,
                angle=found.angle,
            )
        defects = found
    pivots = {k: (mech.points[k].x, mech.points[k].y) for k in ("A", "D", "B", "C")}
    lengths = dict(zip(("d", "a", "b", "c"), (float(v) for v in row[3:7]), strict=True))
    return MotionDesign(
        pivots, lengths, mech, defects, span, tuple(float(v) for v in inputs_deg), checked
    )
