"""Force closure: the contact force over the cycle, the jump speed, the spring that holds contact.

A translating follower of mass ``m`` held on the cam by a spring (rate ``k``,
preload ``F0``) and a load ``F`` (pressing it onto the cam) needs from the cam,
along its axis, ``F_c(θ) = m·s''·ω² + k·s + F0 + F``; the contact force along
the common normal is ``F_c/cos φ``; contact is lost where ``F_c < 0``. The cam
speed at which the follower jumps is ``ω_jump² = min over s'' < 0 of
(k·s + F0 + F)/(−m·s'')``; the smallest preload that keeps contact up to a
speed ``ω_u`` is ``max_θ(−m·s''·ω_u² − k·s − F)``, the smallest rate (with the
preload given) ``max over s > 0 of (−m·s''·ω_u² − F0 − F)/s``. The camshaft
torque follows from power, ``T·ω = F_c·v``: ``T = F_c·s'`` (no friction). An
oscillating follower is the same with moments about its pivot (inertia ``J``,
a torsion spring in N·m/rad and N·m, the displacement in radians); its contact
force is the moment over the normal's lever arm about the pivot.

>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> spec = cam_spec_from_dict({"base_radius": 0.03, "omega": 100, "follower_mass": 1.0,
...     "spring": {"rate": 1000, "preload": 10}, "follower": {"motion": "translating",
...     "contact": "flat"}, "segments": [{"law": "harmonic", "lift": 0.01, "angle": 180},
...     {"law": "harmonic", "lift": -0.01, "angle": 180}]})
>>> c = force_closure(make_design(spec), 360)
>>> round(c.jump_speed, 6)   # √((k·h + F0)/(m·h/2)): at the top, s'' = −h/2
63.245553
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..solvers.planar import cross
from .checks import Extreme, cam_angles, stretches
from .design import CamDesign
from .profile import CamGeometry, cam_geometry

__all__ = ["Closure", "force_closure"]


@dataclass(frozen=True)
class Closure:
    """The force closure over the cycle at the spec's cam speed (arrays over ``theta``).

    ``axial`` is what the cam must give the follower along its motion (N; N·m
    about the pivot for an oscillating follower), ``contact`` the force along
    the common normal (N), ``torque`` the camshaft torque (N·m, positive
    against the cam's turning: the drive supplies it). ``lost_at`` the
    stretches (degrees) where contact is lost at the spec's speed;
    ``jump_speed`` the cam speed at which the follower first leaves the cam
    (rad/s; 0 when it leaves it at rest, None when it never does);
    ``preload_needed`` and ``rate_needed`` the smallest preload (with the
    spring's rate) and rate (with its preload) keeping contact up to
    ``up_to`` rad/s (``rate_needed`` None when no rate can: the follower needs a
    preload where it sits at ``s = 0``).
    """

    theta: np.ndarray
    axial: np.ndarray
    contact: np.ndarray
    torque: np.ndarray
    lost_at: tuple[tuple[float, float], ...]
    jump_speed: float | None
    preload_needed: float
    rate_needed: float | None
    up_to: float
    peak_contact: Extreme
    peak_torque: Extreme

    @property
    def contact_lost(self) -> bool:
        return bool(self.lost_at)


def force_closure(design: CamDesign, samples: int = 360) -> Closure:
    """The contact force, camshaft torque, jump speed and the spring needed, over a turn."""
    spec = design.spec
    theta = cam_angles(samples)
    g = cam_geometry(design, theta)
    s, s1, s2 = g.s, g.s1, g.s2
    mass = spec.follower_mass if design.translating else spec.follower_inertia
    spring = spec.spring
    rate = spring.rate if spring is not None else 0.0
    preload = spring.preload if spring is not None else 0.0
    up_to = abs(spring.up_to) if spring is not None and spring.up_to else abs(spec.omega)
    omega = abs(spec.omega)
    static = rate * s + preload + spec.load
    axial = mass * s2 * omega**2 + static
    contact = axial / _lever(design, g)
    torque = axial * s1
    lost = axial < -1e-12 * max(float(np.max(np.abs(axial))), 1e-300)
    return Closure(
        theta,
        axial,
        contact,
        torque,
        stretches(theta, lost),
        _jump_speed(mass, s2, static),
        max(float(np.max(-mass * s2 * up_to**2 - rate * s - spec.load)), 0.0) + 0.0,
        _rate_needed(mass, s, s2, up_to, preload + spec.load),
        up_to,
        _peak(theta, contact),
        _peak(theta, torque),
    )


def _lever(design: CamDesign, g: CamGeometry) -> np.ndarray:
    """What turns the axial force (moment) into the contact force: cos φ, or the normal's arm."""
    if design.translating:
        return np.cos(g.pressure)
    arm = g.point - np.asarray(design.layout.pivot)
    return design.layout.swing * cross(arm, g.normal)


def _jump_speed(mass: float, s2: np.ndarray, static: np.ndarray) -> float | None:
    if (static < 0).any():
        return 0.0
    pulling = s2 < 0
    if mass <= 0 or not pulling.any():
        return None
    return float(math.sqrt(np.min(static[pulling] / (-mass * s2[pulling]))))


def _rate_needed(mass: float, s, s2, up_to: float, held: float) -> float | None:
    need = -mass * s2 * up_to**2 - held
    short = need > 0
    if not short.any():
        return 0.0
    if (s[short] <= 0).any():
        return None
    return float(np.max(need[short] / s[short]))


def _peak(theta: np.ndarray, values: np.ndarray) -> Extreme:
    k = int(np.argmax(np.abs(values)))
    return Extreme(float(values[k]), round(math.degrees(float(theta[k])), 6))
