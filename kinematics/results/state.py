"""What a solve returns: the motion over many poses, or the state at one pose.

Each link's state is ``(x, y, θ)``: the displacement and rotation of its
frame from the sketch pose (where every link is at ``(0, 0, 0)``), with its
first and second time derivatives. :class:`Motion` holds them as arrays over
the poses and gives any point's motion; :class:`KinematicState` holds one
pose's links (:class:`LinkState`) and named points (:class:`PointState`).

>>> import numpy as np
>>> zero = np.zeros((1, 3))
>>> turning = np.array([[0.0, 0.0, 2.0]])   # ω = 2 about the origin
>>> motion = Motion(np.zeros((1, 1)), {"1": zero}, {"1": turning}, {"1": zero})
>>> x, v, a = motion.point("1", np.array([0.5, 0.0]))
>>> v.tolist(), a.tolist()
([[0.0, 1.0]], [[-2.0, 0.0]])
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from ..solvers.frames import Frame
from ..solvers.planar import perpendicular, rotate_many, vectors

__all__ = ["KinematicState", "LinkState", "Motion", "PointState"]


@dataclass(frozen=True)
class Motion:
    """Arrays over poses: ``q``, ``qd``, ``qdd`` per link (shape (N, 3)), and the inputs.

    ``frames`` holds the links solved in closed form as
    :class:`~kinematics.solvers.frames.Frame` s; their ``q`` (which needs the angle's
    ``arctan2``) is computed the first time it is read, and :meth:`point`
    uses the frame directly. ``pins`` holds the points the solve found on
    the way from a link's frame, ``(link, x, y) -> (x, y, vx, vy, ax, ay)``,
    so that they need not be found again; a solve of positions only (the
    rates None) also holds the dyads' joints there, as their closed forms
    found them (through a link's frame they agree to rounding).
    """

    inputs: np.ndarray
    q: Mapping[str, np.ndarray]
    qd: Mapping[str, np.ndarray]
    qdd: Mapping[str, np.ndarray]
    frames: Mapping[str, Frame] = field(default_factory=dict)
    pins: Mapping[tuple, tuple] = field(default_factory=dict)

    def point(self, link: str, c: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity, acceleration (each (N, 2)) of sketch point ``c`` on ``link``."""
        frame = self.frames.get(link)
        if frame is not None:
            n = self.inputs.shape[0]
            x, y, vx, vy, ax, ay = frame.point(c)
            return vectors(x, y, n), vectors(vx, vy, n), vectors(ax, ay, n)
        q, v, a = self.q[link], self.qd[link], self.qdd[link]
        r = rotate_many(q[:, 2], c)
        jr = perpendicular(r)
        w, e = v[:, 2:3], a[:, 2:3]
        return q[:, :2] + r, v[:, :2] + w * jr, a[:, :2] + e * jr - w**2 * r


@dataclass(frozen=True)
class LinkState:
    """A link's pose (from the sketch), angular velocity and angular acceleration."""

    q: np.ndarray  # (x, y, θ)
    qd: np.ndarray
    qdd: np.ndarray

    @property
    def angle(self) -> float:
        """Rotation from the sketch pose, rad (counter-clockwise positive)."""
        return float(self.q[2])

    @property
    def omega(self) -> float:
        return float(self.qd[2])

    @property
    def epsilon(self) -> float:
        return float(self.qdd[2])


@dataclass(frozen=True)
class PointState:
    """Position, velocity and acceleration of a point, world frame, SI units."""

    link: str
    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray


@dataclass(frozen=True)
class KinematicState:
    """Every link's and every named point's motion at one pose."""

    links: Mapping[str, LinkState]
    points: Mapping[str, PointState]
    inputs: tuple[float, ...]
