"""The pitch curve and the cam profile in closed form, with their curvature and pressure angle.

For a cam turned by ``sense·θ`` the cam's own frame sees the follower's point
``P`` (the roller's centre, the knife's edge) at ``X = R(−sense·θ)·P``: the
pitch curve. Its derivatives follow from ``P``'s (:mod:`kinematics.cams.followers`)
without sampling: ``X' = R·A`` with ``A = P' − sense·J·P`` and
``X'' = R·B`` with ``B = P'' − 2·sense·J·P' − P``, so that the radius of
curvature is ``ρ = −sense·|A|³/(A × B)`` (positive where the cam is convex),
the outward normal ``N = sense·J·A/|A|`` and the profile the pitch curve
moved ``R_f`` along ``−N``; the profile's radius is ``ρ − R_f``. A flat face
``X·m = h`` is enveloped in closed form: the contact is
``K = h·m + h'/(α' − sense)·J·m`` and the profile's radius
``ρ = h + (h''·(α' − sense) − h'·α'')/(α' − sense)³`` (``R_b + s + s''`` for a
translating face). The pressure angle is the angle between the common normal
and the direction the follower's contact point moves in as it rises:
``sin φ = −sense·(N × w)``, ``cos φ = N·w`` (for a translating roller
``tan φ = (s' − ε)/(√(R_p² − ε²) + s)``, Norton's eq. 8.31).

>>> import numpy as np
>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> design = make_design(cam_spec_from_dict({"base_radius": 0.04, "follower":
...     {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
...     "segments": [{"law": "dwell", "angle": 360}]}))
>>> g = cam_geometry(design, np.array([0.0, 1.0]))
>>> g.pitch_radius.round(12).tolist(), g.profile_radius.round(12).tolist()
([0.05, 0.05], [0.04, 0.04])
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..solvers.planar import cross, dot, norm, perpendicular, rotate_many
from .followers import FollowerLayout, contact_point, face
from .program import program_values

if TYPE_CHECKING:
    from .design import CamDesign

__all__ = ["CamGeometry", "cam_geometry", "fit_measures"]


@dataclass(frozen=True)
class CamGeometry:
    """The cam's geometry at the cam angles ``theta`` (radians), arrays over them.

    In the cam's own frame (turning with it): ``pitch`` (the roller centre's
    path; None for a flat face) and ``profile``. In the fixed frame, at each
    angle: ``point`` where the follower takes the force (the roller's centre,
    the knife's edge, the flat face's contact), ``contact`` the contact point,
    ``normal`` the common normal (unit, out of the cam), ``centre`` the profile's
    centre of curvature there. ``pitch_radius`` and ``profile_radius`` are signed
    (positive convex; a knife's are its profile's), ``pressure`` the pressure
    angle (radians, signed as :mod:`kinematics.cams.profile` says), ``s``,
    ``s1``, ``s2``, ``s3`` the program's values and ``way`` the direction the
    follower's point moves in as it rises.
    """

    theta: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    s3: np.ndarray
    pitch: np.ndarray | None
    profile: np.ndarray
    point: np.ndarray
    contact: np.ndarray
    normal: np.ndarray
    centre: np.ndarray
    pitch_radius: np.ndarray | None
    profile_radius: np.ndarray
    pressure: np.ndarray
    way: np.ndarray
    #: the normal before it is made a unit vector (``sense·J·A``; ``m`` for a flat face): a
    #: product with it is exactly zero where it should be (a dwell: the normal is radial)
    raw_normal: np.ndarray | None = None
    #: a flat face: the contact's place along it, ``h'/(α' − sense)`` along ``J·m`` from the foot
    #: of the perpendicular from the cam's centre (``K = h·m + t·J·m``)
    along_face: np.ndarray | None = None


def cam_geometry(design: CamDesign, theta: np.ndarray) -> CamGeometry:
    """The pitch curve, profile, curvature, normal and pressure angle at ``theta`` (radians)."""
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    layout = design.layout
    sense = layout.sense
    s, s1, s2, s3 = program_values(design.program, theta)
    back = -sense * theta  # the fixed frame seen from the cam
    if layout.flat:
        contact, m, rho, way, along = _flat_core(layout, s, s1, s2)
        return CamGeometry(
            theta, s, s1, s2, s3,
            None, rotate_many(back, contact), contact, contact, m,
            contact - rho[:, None] * m, None, rho, _pressure(m, way, sense), way, m, along,
        )  # fmt: skip
    p, normal, rho, raw, way = _point_core(layout, s, s1, s2)
    rf = layout.roller_radius
    contact = p - rf * normal
    return CamGeometry(
        theta, s, s1, s2, s3,
        rotate_many(back, p), rotate_many(back, contact), p, contact, normal,
        p - rho[:, None] * normal, rho, rho - rf, _pressure(normal, way, sense), way, raw,
    )  # fmt: skip


def fit_measures(
    layout: FollowerLayout, s: np.ndarray, s1: np.ndarray, s2: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The pressure angle and the radius that decides undercut, from the program's values.

    The radius is the pitch curve's for a roller or knife, the profile's for a
    flat face. What :func:`cam_geometry` finds, without the cam's own frame:
    the design in reverse tries many base circles on the same program.
    """
    if layout.flat:
        _, m, rho, way, _ = _flat_core(layout, s, s1, s2)
        return _pressure(m, way, layout.sense), rho
    _, normal, rho, _, way = _point_core(layout, s, s1, s2)
    return _pressure(normal, way, layout.sense), rho


def _point_core(layout: FollowerLayout, s, s1, s2) -> tuple:
    """A roller's or knife's point, unit and raw normal, pitch radius and way (fixed frame)."""
    sense = layout.sense
    p, p1, p2, way = contact_point(layout, s, s1, s2)
    a = p1 - sense * perpendicular(p)
    b = p2 - 2.0 * sense * perpendicular(p1) - p
    speed = norm(a)
    raw = sense * perpendicular(a)
    normal = raw / speed[:, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = -sense * speed**3 / cross(a, b)
    return p, normal, rho, raw, way


def _flat_core(layout: FollowerLayout, s, s1, s2) -> tuple:
    """A flat face's contact, normal, profile radius, way and place along the face."""
    sense = layout.sense
    alpha, a1, a2, h, h1, h2 = face(layout, s, s1, s2)
    if layout.follower.translating:  # the face's normal is +y, exactly
        m = np.zeros((len(s), 2))
        m[:, 1] = 1.0
    else:
        m = np.stack([np.cos(alpha), np.sin(alpha)], axis=1)
    jm = perpendicular(m)
    turn = a1 - sense
    along = h1 / turn
    contact = h[:, None] * m + along[:, None] * jm
    rho = h + (h2 * turn - h1 * a2) / turn**3
    if layout.follower.translating:
        way = np.broadcast_to(np.array([0.0, 1.0]), contact.shape).copy()
    else:
        arm = contact - np.asarray(layout.pivot)
        way = layout.swing * perpendicular(arm) / norm(arm)[:, None]
    return contact, m, rho, way, along


def _pressure(normal: np.ndarray, way: np.ndarray, sense: float) -> np.ndarray:
    """The signed angle between the common normal and the way the follower's point rises."""
    return np.arctan2(-sense * cross(normal, way), dot(normal, way))
