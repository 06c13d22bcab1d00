"""The follower in the cam's fixed frame: where its contact element is for a displacement.

The frame has the cam's centre at the origin; it turns counter-clockwise for
``ω > 0`` (``sense`` +1) and clockwise for ``ω < 0`` (−1), and the program's
angle θ runs forward in time either way. :func:`follower_layout` places the
follower at the start of its stroke (``s = 0`` on the base circle) and says
why it cannot be placed when it cannot:

* translating (knife or roller): its axis is parallel to +y at ``x = sense·ε``,
  so that ``ε > 0`` lowers the pressure angle of a rise (Norton's offset); the
  roller's centre (the knife's edge) is at ``(sense·ε, √(R_p² − ε²) + s)``,
  ``R_p = R_b + R_f`` the prime circle;
* oscillating (knife or roller): the arm of length ``L`` swings about the
  pivot ``Q``; at ``s = 0`` the roller's centre is on the prime circle, on the
  side of the line from the cam's centre to ``Q`` from which the cam's surface
  turns toward the pivot (the arm is pushed on the rise); a positive lift
  swings it away from the cam's centre;
* flat-faced: the face is the line ``X·m = h`` with its normal ``m`` pointing
  away from the cam; translating, ``m = +y`` and ``h = R_b + s``; oscillating,
  the face passes ``e`` from the pivot, turns with the arm and touches the base
  circle at ``s = 0``.

:func:`contact_point` gives the roller's centre (or the knife's edge) and its
first two derivatives by the cam angle; :func:`face` the flat face's normal
angle and distance with theirs. All in closed form from ``s, s', s''``.

>>> from structure.cams import FollowerContact, FollowerMotion, FollowerSpec
>>> f = FollowerSpec(FollowerMotion.TRANSLATING, FollowerContact.ROLLER, offset=0.0,
...                  roller_radius=0.01)
>>> layout = follower_layout(f, 0.04, 1.0)
>>> layout.prime, layout.rise
(0.05, 0.05)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from structure.cams import FollowerContact, FollowerSpec

from ..errors import BaseCircleError
from ..solvers.planar import cross, perpendicular

__all__ = ["FollowerLayout", "contact_point", "face", "follower_layout"]


@dataclass(frozen=True, slots=True)
class FollowerLayout:
    """Where the follower stands in the cam's fixed frame at the start of its stroke.

    ``sense`` is +1 for a cam turning counter-clockwise, −1 clockwise;
    ``prime`` the prime circle's radius (``R_b + R_f``; ``R_b`` for a knife or a
    flat face). Translating: ``axis`` the axis's x (``sense·ε``), ``rise`` the
    height of the roller's centre at ``s = 0`` (``√(R_p² − ε²)``). Oscillating:
    ``pivot``, ``arm``, the arm's angle ``start`` at ``s = 0`` (the face
    normal's, for a flat face) and ``swing``, +1 or −1, the way a positive lift
    turns it.
    """

    follower: FollowerSpec
    base_radius: float
    sense: float
    prime: float
    axis: float = 0.0
    rise: float = 0.0
    pivot: tuple[float, float] = (0.0, 0.0)
    arm: float = 0.0
    start: float = 0.0
    swing: float = 1.0

    @property
    def flat(self) -> bool:
        return self.follower.contact is FollowerContact.FLAT

    @property
    def roller_radius(self) -> float:
        return (
            self.follower.roller_radius if self.follower.contact is FollowerContact.ROLLER else 0.0
        )


def follower_layout(follower: FollowerSpec, base_radius: float, omega: float) -> FollowerLayout:
    """The follower placed at the start of its stroke, for a cam turning at ``omega``.

    Raises
    ------
    BaseCircleError
        The follower cannot touch the base circle: a translating follower's
        axis farther from the cam's centre than the prime circle's radius; an
        oscillating arm too short or too long to reach the prime circle from
        its pivot; a flat face's pivot inside the base circle.
    """
    sense = 1.0 if omega > 0 else -1.0
    rf = follower.roller_radius if follower.contact is FollowerContact.ROLLER else 0.0
    prime = base_radius + rf
    if follower.translating:
        if follower.contact is FollowerContact.FLAT:
            return FollowerLayout(
                follower, base_radius, sense, base_radius, sense * follower.offset
            )
        eps = follower.offset
        if abs(eps) >= prime:
            raise BaseCircleError(
                f"the follower's axis is {abs(eps):g} m from the cam's centre, beyond the prime "
                f"circle's radius {prime:g} m (base {base_radius:g} + roller {rf:g}): make the "
                f"base circle larger than {abs(eps) - rf:g} m or the offset smaller than "
                f"{prime:g} m"
            )
        return FollowerLayout(
            follower, base_radius, sense, prime, sense * eps, math.sqrt(prime**2 - eps**2)
        )
    qx, qy = follower.pivot or (0.0, 0.0)
    dist = math.hypot(qx, qy)
    if follower.contact is FollowerContact.FLAT:
        return _flat_swinging(follower, base_radius, sense, (qx, qy), dist)
    arm = float(follower.arm or 0.0)
    if not abs(dist - arm) < prime < dist + arm:
        raise BaseCircleError(
            f"an arm of {arm:g} m about the pivot {dist:g} m from the cam's centre cannot put the "
            f"roller's centre on the prime circle of radius {prime:g} m: the prime circle must lie "
            f"between {abs(dist - arm):g} and {dist + arm:g} m (change the base circle, the arm "
            "or the pivot)"
        )
    # the roller's centre at s = 0: the two circles' intersection on the pushed side
    along = (prime**2 - arm**2 + dist**2) / (2.0 * dist)
    across = math.sqrt(max(prime**2 - along**2, 0.0))
    ux, uy = qx / dist, qy / dist
    # cross(P0, Q) has the sign of the lift's swing; the pushed side has swing = sense
    px, py = along * ux + sense * across * uy, along * uy - sense * across * ux
    start = math.atan2(py - qy, px - qx)
    swing = 1.0 if px * qy - py * qx > 0 else -1.0
    return FollowerLayout(
        follower, base_radius, sense, prime, 0.0, 0.0, (qx, qy), arm, start, swing
    )


def _flat_swinging(
    follower: FollowerSpec, base_radius: float, sense: float, pivot: tuple, dist: float
) -> FollowerLayout:
    """A swinging flat face tangent to the base circle at s = 0 (see :func:`follower_layout`)."""
    e = follower.face_offset
    if not abs(base_radius - e) < dist:
        raise BaseCircleError(
            f"a face {e:g} m from the pivot cannot touch the base circle (radius "
            f"{base_radius:g} m) from a pivot {dist:g} m from the cam's centre: the pivot must "
            f"be farther than {abs(base_radius - e):g} m (move it out, or change the base circle "
            "or the face's offset)"
        )
    beta = math.atan2(pivot[1], pivot[0])
    # Q·m(α0) = R_b − e; the side where a positive lift turns the face by the cam's sense
    delta = -sense * math.acos((base_radius - e) / dist)
    start = beta + delta
    return FollowerLayout(
        follower, base_radius, sense, base_radius, 0.0, 0.0, pivot, float(follower.arm or 0.0),
        start, sense,
    )  # fmt: skip


def contact_point(
    layout: FollowerLayout, s: np.ndarray, s1: np.ndarray, s2: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The roller's centre (knife's edge) ``P``, ``P'``, ``P''`` (N, 2), and its lift direction.

    The last is the unit direction ``P`` moves in as the lift grows (the
    follower's, for the pressure angle). Fixed frame, derivatives by θ.
    """
    n = s.shape[0]
    if layout.follower.translating:
        p = np.empty((n, 2))
        p[:, 0] = layout.axis
        p[:, 1] = layout.rise + s
        d1 = np.zeros((n, 2))
        d1[:, 1] = s1
        d2 = np.zeros((n, 2))
        d2[:, 1] = s2
        way = np.zeros((n, 2))
        way[:, 1] = 1.0
        return p, d1, d2, way
    psi = layout.start + layout.swing * s
    u = np.stack([np.cos(psi), np.sin(psi)], axis=1)
    ju = perpendicular(u)
    length, swing = layout.arm, layout.swing
    p = np.asarray(layout.pivot) + length * u
    d1 = (length * swing * s1)[:, None] * ju
    d2 = (length * swing * s2)[:, None] * ju - (length * s1**2)[:, None] * u
    return p, d1, d2, swing * ju


def face(
    layout: FollowerLayout, s: np.ndarray, s1: np.ndarray, s2: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A flat face's normal angle α, α', α'' and its distance h from the centre, h', h''."""
    n = s.shape[0]
    if layout.follower.translating:
        zero = np.zeros(n)
        return (
            np.full(n, math.pi / 2),
            zero,
            zero.copy(),
            layout.base_radius + s,
            s1.copy(),
            s2.copy(),
        )
    q = np.asarray(layout.pivot)
    alpha = layout.start + layout.swing * s
    m = np.stack([np.cos(alpha), np.sin(alpha)], axis=1)
    a1, a2 = layout.swing * s1, layout.swing * s2
    along = cross(m, np.broadcast_to(q, m.shape))  # Q·J·m
    qm = m @ q
    h = qm + layout.follower.face_offset
    return alpha, a1, a2, h, a1 * along, a2 * along - a1**2 * qm
