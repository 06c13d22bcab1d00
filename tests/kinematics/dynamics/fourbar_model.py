"""An independent four-bar for the dynamics tests: its closed-form positions, derived with sympy.

The crank AB turns about A = (0, 0), the rocker DC about D = (d, 0); the
coupler BC joins them. With the crank angle θ the pin C is the intersection of
the circles |C − B| = b, |C − D| = c taken on the sketch's side; it and its
first two derivatives by θ are sympy's. The links' angular velocities and
accelerations follow from the pins (ω = u × u'/|u|²), the centres of mass from
them (S' = O' + ω·k×r, S'' = O'' + ε·k×r − ω²·r): nothing of assur is used.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
import sympy as sp

#: the four-bar of the tests (metres, kg, kg·m²); centres of mass in each link's frame
#: (along the link from its first pin, and to its left)
A = (0.0, 0.0)
B = (0.1, 0.0)
C = (0.35, 0.2)
D = (0.3, 0.0)
S1, S2, S3 = (0.05, 0.0), (0.225, 0.1), (0.325, 0.1)
M1, M2, M3 = 1.0, 2.0, 1.5
J1, J2, J3 = 0.002, 0.012, 0.005

EDGES = f"""name four-bar with masses
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A {A[0]} {A[1]}
point B {B[0]} {B[1]}
point C {C[0]} {C[1]}
point D {D[0]} {D[1]}
point S1 {S1[0]} {S1[1]}
point S2 {S2[0]} {S2[1]}
point S3 {S3[0]} {S3[1]}
mass 1 {M1} {J1} S1
mass 2 {M2} {J2} S2
mass 3 {M3} {J3} S3
"""


def _local(point, origin, toward):
    """``point`` in the frame of the segment ``origin → toward`` (x along it, y to its left)."""
    ux, uy = toward[0] - origin[0], toward[1] - origin[1]
    length = (ux * ux + uy * uy) ** 0.5
    ux, uy = ux / length, uy / length
    dx, dy = point[0] - origin[0], point[1] - origin[1]
    return dx * ux + dy * uy, -dx * uy + dy * ux


@dataclass(frozen=True)
class FourBar:
    """Functions of the crank angle θ (from the x axis): centres, angles, J_r and its slope."""

    pin_c: object  # θ -> (C, dC/dθ, d²C/dθ²), each of shape (2, len(θ))

    def rates(self, theta):
        """For each link: (centre, its 1st and 2nd derivatives, angle, ω = dθk/dθ, ε)."""
        theta = np.atleast_1d(np.asarray(theta, dtype=float))
        a = _dist(A, B)
        unit = np.array([np.cos(theta), np.sin(theta)])
        turn = np.array([-np.sin(theta), np.cos(theta)])
        b, db, ddb = a * unit, a * turn, -a * unit
        c, dc, ddc = (np.array(x, dtype=float) for x in self.pin_c(theta))
        out = []
        frames = (
            (np.zeros_like(b), np.zeros_like(b), np.zeros_like(b), b, db, ddb, _local(S1, A, B)),
            (b, db, ddb, c - b, dc - db, ddc - ddb, _local(S2, B, C)),
            (np.array(D)[:, None] + 0 * b, 0 * b, 0 * b, c - np.array(D)[:, None], dc, ddc,
             _local(S3, D, C)),
        )  # fmt: skip
        for origin, d_origin, dd_origin, u, du, ddu, z in frames:
            n2 = (u * u).sum(0)
            cross1 = u[0] * du[1] - u[1] * du[0]
            cross2 = u[0] * ddu[1] - u[1] * ddu[0]
            omega = cross1 / n2
            epsilon = cross2 / n2 - 2 * (u * du).sum(0) * cross1 / n2**2
            angle = np.arctan2(u[1], u[0])
            ca, sa = np.cos(angle), np.sin(angle)
            r = np.array([z[0] * ca - z[1] * sa, z[0] * sa + z[1] * ca])  # R(angle)·z
            jr = np.array([-r[1], r[0]])
            centre = origin + r
            d_centre = d_origin + omega * jr
            dd_centre = dd_origin + epsilon * jr - omega**2 * r
            out.append((centre, d_centre, dd_centre, angle, omega, epsilon))
        return out

    def centres(self, theta: float) -> list[tuple[float, float]]:
        return [(float(x[0][0, 0]), float(x[0][1, 0])) for x in self.rates(theta)]

    def angles(self, theta: float) -> list[float]:
        return [float(x[3][0]) for x in self.rates(theta)]

    def reduced_inertia(self, theta):
        parts = self.rates(theta)
        return sum(
            m * (x[1] ** 2).sum(0) + j * x[4] ** 2
            for m, j, x in zip((M1, M2, M3), (J1, J2, J3), parts, strict=True)
        )

    def reduced_slope(self, theta):
        parts = self.rates(theta)
        return sum(
            2 * m * (x[1] * x[2]).sum(0) + 2 * j * x[4] * x[5]
            for m, j, x in zip((M1, M2, M3), (J1, J2, J3), parts, strict=True)
        )


def _dist(p, q) -> float:
    return ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) ** 0.5


@functools.cache
def build() -> FourBar:
    """The four-bar above: the pin C in closed form (sympy), the rest by the rules of kinematics."""
    t = sp.Symbol("theta", real=True)
    a, b, c = _dist(A, B), _dist(B, C), _dist(D, C)
    bx, by = a * sp.cos(t), a * sp.sin(t)
    # C on both circles; the sign of the root is the sketch's assembly mode
    ex, ey = D[0] - bx, D[1] - by
    e2 = ex * ex + ey * ey
    along = (b * b - c * c + e2) / (2 * e2)
    across = sp.sqrt(b * b / e2 - along * along)
    sign = _sketch_sign(a, b, c)
    cx = bx + along * ex - sign * across * ey
    cy = by + along * ey + sign * across * ex
    pin = [sp.Matrix([cx, cy]).diff(t, k) for k in range(3)]
    return FourBar(sp.lambdify(t, [list(p) for p in pin], "numpy", cse=True))


def _sketch_sign(a: float, b: float, c: float) -> float:
    """+1 or −1: the root that puts C where the sketch has it."""
    ex, ey = D[0] - B[0], D[1] - B[1]
    e2 = ex * ex + ey * ey
    along = (b * b - c * c + e2) / (2 * e2)
    across = (b * b / e2 - along * along) ** 0.5
    plus = (B[0] + along * ex - across * ey, B[1] + along * ey + across * ex)
    return 1.0 if np.hypot(plus[0] - C[0], plus[1] - C[1]) < 1e-9 else -1.0
