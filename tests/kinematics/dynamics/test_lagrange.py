"""ω(t) of a four-bar with masses against an independent Lagrangian model (issue 25).

The model is written here with sympy.physics.mechanics: three rigid bodies with
their own angles, the loop's closure as two holonomic constraints with their
multipliers, gravity, a motor curve on the crank and a resisting moment on the
rocker; integrated with scipy from rest. Nothing of assur's reduced form is
used: it must give the same crank speed to 1e-6.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from kinematics.dynamics.machine import reduced_machine
from kinematics.dynamics.motion import Limits, start_up
from structure.readwrite.edgelist import parse_edgelist
from structure.report import analyze

from . import fourbar_model as fb

M0, W0 = 6.0, 40.0  # the motor: M = M0·(1 − ω/W0) on the crank
RESIST = -1.5  # N·m on the rocker
GRAVITY = -9.81


def _lagrangian_model():
    """(right-hand side of the state (q, q̇), the sketch's angles) from sympy.physics.mechanics."""
    import sympy as sp
    import sympy.physics.mechanics as me

    q = me.dynamicsymbols("q1:4")
    qd = [me.dynamicsymbols(f"q{k}", 1) for k in range(1, 4)]
    n = me.ReferenceFrame("N")
    frames = [n.orientnew(f"L{k}", "Axis", [q[k - 1], n.z]) for k in range(1, 4)]
    origin = me.Point("O")
    origin.set_vel(n, 0)
    a_len = math.dist(fb.A, fb.B)
    b_len = math.dist(fb.B, fb.C)
    c_len = math.dist(fb.D, fb.C)
    pin_a = origin.locatenew("A", fb.A[0] * n.x + fb.A[1] * n.y)
    pin_d = origin.locatenew("D", fb.D[0] * n.x + fb.D[1] * n.y)
    pin_b = pin_a.locatenew("B", a_len * frames[0].x)
    pin_c = pin_b.locatenew("C", b_len * frames[1].x)
    pin_c3 = pin_d.locatenew("C3", c_len * frames[2].x)
    z1 = fb._local(fb.S1, fb.A, fb.B)
    z2 = fb._local(fb.S2, fb.B, fb.C)
    z3 = fb._local(fb.S3, fb.D, fb.C)
    centres = [
        pin_a.locatenew("S1", z1[0] * frames[0].x + z1[1] * frames[0].y),
        pin_b.locatenew("S2", z2[0] * frames[1].x + z2[1] * frames[1].y),
        pin_d.locatenew("S3", z3[0] * frames[2].x + z3[1] * frames[2].y),
    ]
    for point in (pin_b, pin_c, pin_c3, *centres):
        point.set_vel(n, point.pos_from(origin).dt(n))
    bodies = []
    potential = 0
    for k, (mass, inertia) in enumerate(((fb.M1, fb.J1), (fb.M2, fb.J2), (fb.M3, fb.J3))):
        dyadic = me.inertia(frames[k], 0, 0, inertia)
        bodies.append(me.RigidBody(f"B{k}", centres[k], frames[k], mass, (dyadic, centres[k])))
        potential += -mass * GRAVITY * centres[k].pos_from(origin).dot(n.y)
    lagrangian = me.Lagrangian(n, *bodies) - potential
    closure = pin_c.pos_from(origin) - pin_c3.pos_from(origin)
    constraints = [closure.dot(n.x), closure.dot(n.y)]
    loads = [
        (frames[0], M0 * (1 - qd[0] / W0) * n.z),
        (frames[2], RESIST * n.z),
    ]
    method = me.LagrangesMethod(lagrangian, q, hol_coneqs=constraints, forcelist=loads, frame=n)
    method.form_lagranges_equations()
    symbols = [*q, *qd]
    mass = sp.lambdify(symbols, method.mass_matrix_full, "numpy")
    forcing = sp.lambdify(symbols, method.forcing_full, "numpy")

    def rhs(_t, y):
        solution = np.linalg.solve(
            np.array(mass(*y), dtype=float), np.array(forcing(*y), dtype=float).ravel()
        )
        return solution[:6]

    sketch = [
        math.atan2(q[1] - p[1], q[0] - p[0]) for p, q in ((fb.A, fb.B), (fb.B, fb.C), (fb.D, fb.C))
    ]
    return rhs, np.array(sketch)


def test_omega_of_t_agrees_with_the_lagrangian_model():
    rhs, angles = _lagrangian_model()
    y0 = np.concatenate([angles, np.zeros(3)])
    times = np.linspace(0.05, 0.8, 16)
    reference = solve_ivp(rhs, (0, times[-1]), y0, method="DOP853", rtol=1e-12, atol=1e-12,
                          t_eval=times)  # fmt: skip
    assert reference.success
    edges = [*fb.EDGES.splitlines(), f"gravity 0 {GRAVITY}", f"drive 1 motor={M0},{W0}",
             f"cycle moment 3 {RESIST}"]  # fmt: skip
    machine = reduced_machine(analyze(parse_edgelist(edges)))
    run = start_up(machine, dense=True, limits=Limits(turns=40))
    assert run.duration > times[-1]
    phi, omega = run.at(times)
    expected_omega = reference.y[3]
    assert np.max(np.abs(expected_omega)) > 5  # it has sped up through several turns
    np.testing.assert_allclose(omega, expected_omega, rtol=1e-6, atol=1e-6 * np.max(expected_omega))
    np.testing.assert_allclose(phi, reference.y[0] - angles[0], rtol=1e-6, atol=1e-7)
