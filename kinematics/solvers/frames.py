"""Link motions over many poses, kept in the form the closed-form solvers produce.

A closed-form dyad finds its pins' positions, velocities and accelerations,
and each link's rotation as a cosine and sine, its ω and ε; the angle θ itself
needs an ``arctan2`` (about 30 ns per pose and link, as much as the rest of a
four-bar's solve). A :class:`Frame` keeps a link's motion in that form: one
reference point of the link (its sketch coordinates, and its world position,
velocity and acceleration over the poses), the rotation's cosine and sine,
ω and ε. Any point of the link follows from it by a rotation, with no
trigonometric function.

:class:`LinkTable` is the ``link -> (N, 3)`` mapping of poses ``(x, y, θ)``
(or of their first or second derivatives) that the rest of the package reads;
an entry whose link has a frame is computed from it the first time it is read.

>>> import numpy as np
>>> f = Frame(np.array([0.0, 0.0]), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
...           np.array([0.0]), np.array([1.0]), 2.0, 0.0)   # turned by 90°, ω = 2
>>> x, y, vx, vy, ax, ay = f.point(np.array([1.0, 0.0]))
>>> [float(x[0]), float(y[0]), float(vx[0]), float(vy[0]), float(ax[0]), float(ay[0])]
[0.0, 1.0, -2.0, 0.0, 0.0, -4.0]
>>> table = LinkTable({"2": f}, "q", 1)
>>> table.declare("2")
>>> table["2"].round(9).tolist()
[[0.0, 0.0, 1.570796327]]
"""

from __future__ import annotations

import math
from collections.abc import Iterator, MutableMapping
from typing import Any

import numpy as np

__all__ = ["GROUND_FRAME", "Frame", "LinkTable", "frame_of_columns", "unwrapped"]

Values = Any  # an (N,) array, or a float when the value is the same at every pose


def unwrapped(theta: np.ndarray) -> np.ndarray:
    """Angles made continuous along the poses (jumps of 2π removed), like ``np.unwrap``."""
    if theta.shape[0] < 2:
        return theta
    turns = np.round(np.diff(theta) / (2 * math.pi))
    if not turns.any():
        return theta
    out = theta.copy()
    out[1:] -= 2 * math.pi * np.cumsum(turns)
    return out


class Frame:
    """A link's motion: reference point ``ref`` (sketch) at ``(x, y)`` with its rates; rotation.

    ``cos``, ``sin`` are those of the link's rotation from the sketch, ``omega``
    and ``epsilon`` its angular velocity and acceleration; ``theta`` the
    rotation itself when it is known without an ``arctan2`` (a crank's input).
    Each value is an (N,) array or a float that holds at every pose.

    The rotation and its rates may be left out (``None``) and given instead by

    * ``second``: another point of the link, ``(sketch xy, x, y, vx, vy, ax, ay)``:
      the link turns as the vector between the two points does, and
      ``ω = (r × Δv)/|r|²``, ``ε = (r × Δa)/|r|²``; or
    * ``turns_with``: a frame whose rotation and rates this link shares (a
      slider on its guide).

    They are then computed when first read, so a solve pays only for what is used.
    A point of a link known by a second point is found without them: it is a
    fixed linear combination of the two points (and so are its velocity and
    acceleration of theirs), and the second point itself is its own values.
    A frame solved for positions only has ``None`` for the point's rates (and
    the second point's); only its positions can be read then.
    """

    __slots__ = ("_cos", "_epsilon", "_omega", "_second", "_sin", "_turns_with", "ax", "ay",
                 "ref", "theta", "vx", "vy", "x", "y")  # fmt: skip

    def __init__(
        self,
        ref: np.ndarray,
        x: Values,
        y: Values,
        vx: Values,
        vy: Values,
        ax: Values,
        ay: Values,
        cos: Values = None,
        sin: Values = None,
        omega: Values = None,
        epsilon: Values = None,
        theta: Values = None,
        second: tuple | None = None,
        turns_with: Frame | None = None,
    ) -> None:
        self.ref, self.x, self.y, self.vx, self.vy, self.ax, self.ay = ref, x, y, vx, vy, ax, ay
        self._cos, self._sin, self._omega, self._epsilon = cos, sin, omega, epsilon
        self.theta, self._second, self._turns_with = theta, second, turns_with
        if cos is None and second is None and turns_with is None:
            raise ValueError("a frame needs its rotation, a second point or a frame to turn with")

    def __repr__(self) -> str:
        return f"Frame(ref={self.ref.tolist()})"

    def _turn(self) -> None:
        """The rotation's cosine and sine, from the frame turned with or the second point."""
        like = self._turns_with
        if like is not None:
            self._cos, self._sin, self.theta = like.cos, like.sin, like.theta
            return
        xy, x, y = self._second[:3]
        sx, sy = float(xy[0] - self.ref[0]), float(xy[1] - self.ref[1])
        k = 1.0 / (sx * sx + sy * sy)
        rx, ry = x - self.x, y - self.y
        self._cos = (sx * k) * rx + (sy * k) * ry
        self._sin = (sx * k) * ry - (sy * k) * rx

    def _turn_rates(self) -> None:
        """ω and ε, from the frame turned with or the second point (``(r × Δv)/|r|²``)."""
        like = self._turns_with
        if like is not None:
            self._omega, self._epsilon = like.omega, like.epsilon
            return
        if self.vx is None:
            raise ValueError("a frame solved for positions only has no rates")
        xy, x, y, vx, vy, ax, ay = self._second
        sx, sy = float(xy[0] - self.ref[0]), float(xy[1] - self.ref[1])
        k = 1.0 / (sx * sx + sy * sy)
        rx, ry = x - self.x, y - self.y
        self._omega = (rx * (vy - self.vy) - ry * (vx - self.vx)) * k
        self._epsilon = (rx * (ay - self.ay) - ry * (ax - self.ax)) * k

    @property
    def cos(self) -> Values:
        if self._cos is None:
            self._turn()
        return self._cos

    @property
    def sin(self) -> Values:
        if self._sin is None:
            self._turn()
        return self._sin

    @property
    def omega(self) -> Values:
        if self._omega is None:
            self._turn_rates()
        return self._omega

    @property
    def epsilon(self) -> Values:
        if self._epsilon is None:
            self._turn_rates()
        return self._epsilon

    def offset(self, point: np.ndarray) -> tuple[Values, Values]:
        """``R·(point − ref)``: where ``point`` (sketch) sits relative to the reference point."""
        dx, dy = float(point[0] - self.ref[0]), float(point[1] - self.ref[1])
        c, s = self.cos, self.sin
        return c * dx - s * dy, s * dx + c * dy

    def position(self, point: np.ndarray) -> tuple[Values, Values]:
        """World position of the link's sketch point ``point``."""
        if self._on_two_points():
            return self._combined(point, 2)
        rx, ry = self.offset(point)
        return self.x + rx, self.y + ry

    def point(self, point: np.ndarray) -> tuple[Values, ...]:
        """``(x, y, vx, vy, ax, ay)`` of the link's sketch point ``point``."""
        dx, dy = float(point[0] - self.ref[0]), float(point[1] - self.ref[1])
        if dx == 0.0 and dy == 0.0:
            return self.x, self.y, self.vx, self.vy, self.ax, self.ay
        if self._on_two_points():
            return self._combined(point, 6)
        c, s = self.cos, self.sin
        rx, ry = c * dx - s * dy, s * dx + c * dy
        w, e = self.omega, self.epsilon
        w2 = w * w
        ax, ay = self.ax - w2 * rx, self.ay - w2 * ry
        if not (isinstance(e, float) and e == 0.0):  # a crank turning at a constant rate
            ax, ay = ax - e * ry, ay + e * rx
        return self.x + rx, self.y + ry, self.vx - w * ry, self.vy + w * rx, ax, ay

    def point_into(self, point: np.ndarray, out: tuple) -> None:
        """:meth:`point` (or with two arrays in ``out``, :meth:`position`) written into ``out``.

        The same arithmetic, so the same values to the last bit; the results
        land in the caller's arrays instead of fresh ones.
        """
        dx, dy = float(point[0] - self.ref[0]), float(point[1] - self.ref[1])
        if dx == 0.0 and dy == 0.0:
            for target, value in zip(out, (self.x, self.y, self.vx, self.vy, self.ax, self.ay),
                                     strict=False):  # fmt: skip
                target[...] = value
            return
        if self._on_two_points():
            self._combine_into(point, out)
            return
        c, s = self.cos, self.sin
        rx, ry = c * dx - s * dy, s * dx + c * dy
        np.add(self.x, rx, out=out[0])
        np.add(self.y, ry, out=out[1])
        if len(out) == 2:
            return
        w, e = self.omega, self.epsilon
        np.subtract(self.vx, np.multiply(w, ry), out=out[2])
        np.add(self.vy, np.multiply(w, rx), out=out[3])
        w2 = w * w
        np.subtract(self.ax, np.multiply(w2, rx), out=out[4])
        np.subtract(self.ay, np.multiply(w2, ry), out=out[5])
        if not (isinstance(e, float) and e == 0.0):  # a crank turning at a constant rate
            np.subtract(out[4], np.multiply(e, ry), out=out[4])
            np.add(out[5], np.multiply(e, rx), out=out[5])

    def _on_two_points(self) -> bool:
        """Whether the link is known by two of its points (its rotation not yet needed)."""
        return self._second is not None and self._turns_with is None

    def _combined(self, point: np.ndarray, count: int) -> tuple:
        """:meth:`_combine_into` fresh arrays: the first ``count`` of ``(x, y, vx, vy, ax, ay)``."""
        second = self._second
        if float(point[0]) == float(second[0][0]) and float(point[1]) == float(second[0][1]):
            return tuple(second[1 : 1 + count])
        n = np.shape(second[1])[0]
        out = tuple(np.empty(n) for _ in range(count))
        self._combine_into(point, out)
        return out

    def _combine_into(self, point: np.ndarray, out: tuple) -> None:
        """A point of a link known by two points P (``ref``) and Q (``second``), into ``out``.

        With ``r = Q − P`` it is ``P + α·r + β·J·r``, ``α`` and ``β`` fixed by the
        sketch; the combination is linear, so the velocity and acceleration
        follow from those of P and Q the same way: no rotation, ω or ε needed.
        At Q itself it is Q's own values.
        """
        xy = self._second[0]
        sx, sy = float(xy[0] - self.ref[0]), float(xy[1] - self.ref[1])
        dx, dy = float(point[0] - self.ref[0]), float(point[1] - self.ref[1])
        if dx == sx and dy == sy:
            for target, value in zip(out, self._second[1:], strict=False):
                target[...] = value
            return
        k = 1.0 / (sx * sx + sy * sy)
        alpha, beta = (sx * dx + sy * dy) * k, (sx * dy - sy * dx) * k
        mine = (self.x, self.y, self.vx, self.vy, self.ax, self.ay)
        if len(out) > 2 and self.vx is None:
            raise ValueError("a frame solved for positions only has no rates")
        n = out[0].shape[0]
        rx, ry, t = np.empty(n), np.empty(n), np.empty(n)
        for i in range(0, len(out), 2):
            px, py = mine[i], mine[i + 1]
            np.subtract(self._second[1 + i], px, out=rx)
            np.subtract(self._second[2 + i], py, out=ry)
            ox, oy = out[i], out[i + 1]
            np.multiply(ry, beta, out=t)
            np.multiply(rx, alpha, out=ox)
            ox -= t
            ox += px
            np.multiply(rx, beta, out=t)
            np.multiply(ry, alpha, out=oy)
            oy += t
            oy += py

    def angle(self) -> Values:
        """The rotation from the sketch, continuous along the poses."""
        if self._cos is None:
            self._turn()
        if self.theta is not None:
            return self.theta
        return unwrapped(np.arctan2(self.sin, self.cos))

    def columns(self, order: str, n: int) -> np.ndarray:
        """The frame's ``(x, y, θ)`` (order 'q'), its velocity ('qd') or acceleration ('qdd')."""
        rx, ry = self.offset(np.zeros(2))  # the frame origin (sketch 0, 0) from the reference
        out = np.empty((n, 3))
        if order == "q":
            out[:, 0] = self.x + rx
            out[:, 1] = self.y + ry
            out[:, 2] = self.angle()
        elif order == "qd":
            w = self.omega
            out[:, 0] = self.vx - w * ry
            out[:, 1] = self.vy + w * rx
            out[:, 2] = w
        else:
            w, e = self.omega, self.epsilon
            w2 = w * w
            out[:, 0] = self.ax - e * ry - w2 * rx
            out[:, 1] = self.ay + e * rx - w2 * ry
            out[:, 2] = e
        return out


GROUND_FRAME = Frame(np.zeros(2), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)


def frame_of_columns(q: np.ndarray, qd: np.ndarray | None, qdd: np.ndarray | None) -> Frame:
    """The frame of a link given as ``(N, 3)`` poses and rates (reference: the frame origin).

    ``qd`` and ``qdd`` None: a frame of positions only.
    """
    theta = q[:, 2]
    if qd is None or qdd is None:
        return Frame(
            np.zeros(2), q[:, 0], q[:, 1], None, None, None, None,
            np.cos(theta), np.sin(theta), None, None, theta,
        )  # fmt: skip
    return Frame(
        np.zeros(2),
        q[:, 0],
        q[:, 1],
        qd[:, 0],
        qd[:, 1],
        qdd[:, 0],
        qdd[:, 1],
        np.cos(theta),
        np.sin(theta),
        qd[:, 2],
        qdd[:, 2],
        theta,
    )


_PENDING = None


class LinkTable(MutableMapping):
    """``link -> (N, 3)`` array; a declared link's array is computed from its frame when read.

    ``order`` is 'q' (poses), 'qd' or 'qdd'; ``frames`` is shared with the
    solver, which adds a link's frame and then :meth:`declare`\\ s it.
    """

    def __init__(self, frames: dict[str, Frame], order: str, n: int) -> None:
        self._data: dict[str, np.ndarray | None] = {}
        self._frames = frames
        self._order = order
        self._n = n

    def declare(self, link: str) -> None:
        """``link``'s entry is now its frame's (computed on first read)."""
        self._data[link] = _PENDING

    def frame(self, link: str) -> Frame | None:
        """The frame ``link``'s entry comes from, if it has one."""
        return self._frames.get(link)

    def __getitem__(self, link: str) -> np.ndarray:
        value = self._data[link]
        if value is None:
            value = self._data[link] = self._frames[link].columns(self._order, self._n)
        return value

    def __setitem__(self, link: str, value: np.ndarray) -> None:
        self._data[link] = value

    def __delitem__(self, link: str) -> None:
        del self._data[link]

    def __contains__(self, link: object) -> bool:
        return link in self._data

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __repr__(self) -> str:
        return f"LinkTable({self._order}, links {list(self._data)})"
