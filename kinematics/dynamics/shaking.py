"""The shaking force and moment on the frame over the cycle, at a constant driver speed.

The moving links push on the frame (through its pins and the motor's stator)
with the opposite of what it takes to accelerate them:

    F_s = −Σ m·a_S,      M_s = −Σ (J_S·α + (r_S − O) × m·a_S),

the moment taken about a point O of the frame (the driver's pivot by default).
At a constant speed ω the accelerations are those at unit speed times ω²
(:func:`~kinematics.dynamics.reduced.reduced_properties`' motion). Gravity and
the working loads are not part of the shaking: they are what the machine does,
not what its motion adds.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan, reduced_properties
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "point A 0 0", "point S 0.1 0",
...                     "mass 1 2 0 S"])
>>> props = reduced_properties(make_plan(analyze(m)), [0.0])
>>> s = shaking(props, m, 10.0)
>>> s.force.round(9).tolist(), float(s.force_max)     # m·r·ω² = 2·0.1·100, outward
([[20.0, 0.0]], 20.0)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from structure.model import Mechanism

from ..errors import DynamicsError
from .reduced import ReducedProperties

__all__ = ["Shaking", "shaking"]


@dataclass(frozen=True)
class Shaking:
    """The shaking force (N, world frame) and moment (N·m about ``about``) over the poses.

    ``phi`` is the driver's angle (rad from the sketch), ``omega`` the constant
    speed they are taken at.
    """

    phi: np.ndarray
    omega: float
    force: np.ndarray  # (N, 2)
    moment: np.ndarray  # (N,)
    about: tuple[float, float]
    about_name: str | None

    @property
    def magnitude(self) -> np.ndarray:
        return np.hypot(self.force[:, 0], self.force[:, 1])

    @property
    def force_max(self) -> float:
        """The largest shaking force over the cycle, N."""
        return float(np.max(self.magnitude))

    @property
    def moment_max(self) -> float:
        """The largest shaking moment over the cycle (in size), N·m."""
        return float(np.max(np.abs(self.moment)))


def shaking(
    props: ReducedProperties,
    mechanism: Mechanism,
    omega: float,
    about: str | None = None,
) -> Shaking:
    """The shaking force and moment at the poses of ``props``, the driver turning at ``omega``.

    Parameters
    ----------
    props : ReducedProperties
        The poses and the kinematics at unit speed.
    mechanism : Mechanism
        Its ``mass`` statements.
    omega : float
        The driver's constant speed, rad/s.
    about : str, optional
        The frame's point the moment is taken about; default the driver's
        pivot (else the origin).

    Raises
    ------
    DynamicsError
        A gear train without coordinates (no positions), a point without coordinates.
    """
    motion = props.motion
    if motion is None:
        raise DynamicsError("the shaking of a machine needs its coordinates (a sketch)")
    n = len(props.phi)
    force = np.zeros((n, 2))
    moment = np.zeros(n)
    name = about if about is not None else _pivot(mechanism, props.driver)
    xy = mechanism.coordinates(name) if name is not None else (0.0, 0.0)
    if xy is None:
        raise DynamicsError(f"point {name} needs coordinates to take the shaking moment about")
    o = np.array(xy, dtype=float)
    w2 = omega * omega
    for load in mechanism.loads:
        if load.kind != "mass" or load.link not in motion.q:
            continue
        mass, inertia = load.values
        centre = mechanism.coordinates(load.point) if load.point else None
        if centre is None:
            raise DynamicsError(
                f"the centre of mass {load.point} of link {load.link} needs coordinates"
            )
        r, _, a = motion.point(load.link, np.array(centre, dtype=float))
        a = a * w2
        alpha = motion.qdd[load.link][:, 2] * w2
        force -= mass * a
        arm = r - o
        moment -= inertia * alpha + mass * (arm[:, 0] * a[:, 1] - arm[:, 1] * a[:, 0])
    return Shaking(props.phi, float(omega), force, moment, (float(o[0]), float(o[1])), name)


def _pivot(mechanism: Mechanism, driver: str) -> str | None:
    joint = mechanism.ground_joint(driver)
    return joint.point if joint is not None and joint.kind == "R" else None
