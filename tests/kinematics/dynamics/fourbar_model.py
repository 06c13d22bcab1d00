"""An independent four-bar for the dynamics tests: its closed-form positions, derived with sympy.

The crank AB turns about A = (0, 0), the rocker DC about D = (d, 0); the
coupler BC joins them. With the crank angle θ the pin C is the intersection of
the circles |C − B| = b, |C − D| = c taken on the sketch's side. Every other
quantity (the centres of mass, the link angles, their derivatives by θ) is
differentiated symbolically: nothing of assur is used.
"""

from __future__ import annotations

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
    """Lambdified functions of the crank angle θ (from the x axis)."""

    theta0: float
    centres: object  # θ -> [(x1, y1), (x2, y2), (x3, y3)]
    angles: object  # θ -> [θ1, θ2, θ3]
    velocity_ratios: object  # θ -> [(dx/dθ, dy/dθ) for each centre], [dθk/dθ]
    reduced_inertia: object  # θ -> J_r
    reduced_slope: object  # θ -> dJ_r/dθ


def _dist(p, q) -> float:
    return ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) ** 0.5


def build() -> FourBar:
    """The four-bar above, in closed form."""
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
    th1 = t
    th2 = sp.atan2(cy - by, cx - bx)
    th3 = sp.atan2(cy - D[1], cx - D[0])
    z1 = _local(S1, A, B)
    z2 = _local(S2, B, C)
    z3 = _local(S3, D, C)

    def centre(ox, oy, th, z):
        return (
            ox + z[0] * sp.cos(th) - z[1] * sp.sin(th),
            oy + z[0] * sp.sin(th) + z[1] * sp.cos(th),
        )

    s1 = centre(A[0], A[1], th1, z1)
    s2 = centre(bx, by, th2, z2)
    s3 = centre(D[0], D[1], th3, z3)
    centres = [s1, s2, s3]
    angles = [th1, th2, th3]
    dcentres = [(sp.diff(x, t), sp.diff(y, t)) for x, y in centres]
    dangles = [sp.diff(th, t) for th in angles]
    jr = sum(
        m * (dx**2 + dy**2) + j * w**2
        for m, j, (dx, dy), w in zip((M1, M2, M3), (J1, J2, J3), dcentres, dangles, strict=True)
    )
    return FourBar(
        0.0,
        sp.lambdify(t, centres, "numpy"),
        sp.lambdify(t, angles, "numpy"),
        sp.lambdify(t, (dcentres, dangles), "numpy"),
        sp.lambdify(t, jr, "numpy"),
        sp.lambdify(t, sp.diff(jr, t), "numpy"),
    )


def _sketch_sign(a: float, b: float, c: float) -> float:
    """+1 or −1: the root that puts C where the sketch has it."""
    ex, ey = D[0] - B[0], D[1] - B[1]
    e2 = ex * ex + ey * ey
    along = (b * b - c * c + e2) / (2 * e2)
    across = (b * b / e2 - along * along) ** 0.5
    plus = (B[0] + along * ex - across * ey, B[1] + along * ey + across * ex)
    return 1.0 if np.hypot(plus[0] - C[0], plus[1] - C[1]) < 1e-9 else -1.0
