"""A designed cam in a mechanism: its follower's motion over the whole cycle.

A mechanism's ``cam`` statement gives a higher pair the profile of a design
(:class:`~structure.cams.CamRef`). :func:`cam_contacts` places the design in
the sketch (the cam's pivot, the follower's guide or pivot, the program's
angle ``at``) and checks that the sketch shows what the program says.

Over a cycle the follower is placed from the program: at the cam's turn
``Δ`` from the sketch the program's angle is ``θ = at + sense·Δ``, a
translating follower has moved ``s(θ) − s(at)`` along its guide and a
swinging one turned ``swing·(s(θ) − s(at))`` about its pivot. Its velocity and
acceleration come from the higher-pair replacement rebuilt at that pose from
the profile's curvature (:func:`cam_rates`): a virtual link from the centre of
curvature ``C = P − ρ·n`` (on the cam) to the roller's centre ``P`` (on the
follower), or pinned at ``C`` and sliding along a flat face. Its velocity
equation ``(v_P − v_C)·n = 0`` and acceleration equation
``(a_P − a_C)·n = −ω_v²·ρ`` are written, divided through by ρ, as

    q̇·(∂P/∂q·n) = ω_c·(J·(P − O))·n
    q̈·(∂P/∂q·n) = (ε_c·J·(P − O) − ω_c²·(P − O))·n − κ·|v_r|² + 2·ω_c·(J·v_r)·n − b·n

(``κ = 1/ρ``, ``v_r`` the roller centre's velocity relative to the cam, ``b`` the
centripetal part of ``P``'s own motion), which stay finite where the pitch
curve is straight (ρ infinite: the virtual link is then a slide); a flat face
has ``(v_C − v_C∈f)·m = 0`` and ``(a_C − a_C∈f)·m = 2·ω_f·(J·v_r)·m``.
The follower's motion so found equals the program's derivatives, which
tests the curvature: ``v = s'·θ̇``, ``a = s''·θ̇² + s'·θ̈``.

:func:`cam_reactions` gives, from the follower's loads, the contact force
along the common normal and its guide's (or pivot's) reaction.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from structure.cams import CamRef, FollowerContact
from structure.model import Mechanism, Pair
from structure.replacement import Replacement

from ..errors import DEAD_CENTRE, CamGeometryError, SingularPoseError, UndercutError
from ..solvers.planar import cross, dot, perpendicular, rotate_many
from .checks import check_cam
from .design import CamDesign, make_design
from .profile import CamGeometry, cam_geometry

__all__ = [
    "CamContact",
    "CamPose",
    "cam_contacts",
    "cam_pose",
    "cam_rates",
    "cam_reactions",
    "contact_at",
    "follower_positions",
    "follower_rates",
    "sketch_profile",
    "solve_cam_step",
]

#: the sketch agrees with the program when its points are within this fraction of the cam's size
SKETCH_TOLERANCE = 1e-6


@dataclass(frozen=True)
class CamContact:
    """A cam of the mechanism with its design, placed in the sketch.

    ``cam`` turns about ``origin`` (world); ``follower`` is the link the
    contact moves (the roller's, when there is one: ``other``); ``virtual`` the
    virtual link of the pair's replacement at the sketch; ``guide`` the
    follower's pair with the ground. The design's fixed frame (cam's centre at
    the origin, a translating follower along +y) is turned by ``turn`` (rad)
    into the world; ``at`` is the program's angle at the sketch (rad).
    """

    ref: CamRef
    design: CamDesign
    cam: str
    follower: str
    other: str
    virtual: str
    pair: Pair
    guide: Pair
    origin: np.ndarray
    turn: float
    at: float
    contact_point: str | None

    @property
    def translating(self) -> bool:
        return self.design.translating

    @property
    def label(self) -> str:
        return self.ref.label

    def to_world(self, xy: np.ndarray) -> np.ndarray:
        """Points of the design's fixed frame in the world (N, 2)."""
        return self.origin + rotate_many(np.full(len(xy), self.turn), xy)

    def direction(self, xy: np.ndarray) -> np.ndarray:
        """Vectors of the design's fixed frame in the world (N, 2)."""
        return rotate_many(np.full(len(xy), self.turn), xy)

    @property
    def pivot(self) -> np.ndarray:
        """A swinging follower's pivot in the world."""
        return self.to_world(np.asarray([self.design.layout.pivot], dtype=float))[0]


def cam_contacts(mechanism: Mechanism, replacements: tuple[Replacement, ...]) -> tuple:
    """The cams of ``mechanism`` (its ``cam`` statements) with their designs, placed.

    ``replacements`` are the structural report's (each cam's virtual link).

    Raises
    ------
    CamProgramError
        A polynomial segment whose conditions fix no polynomial.
    BaseCircleError
        The follower cannot touch the base circle.
    UndercutError
        The profile loops or has a cusp: no follower can run on it.
    CamGeometryError
        The sketch does not show what the program says: it names the point,
        where it is and where the program puts it.
    """
    out = []
    for ref in mechanism.cams:
        record = next(r for r in replacements if {r.pair.a, r.pair.b} == {ref.cam, ref.other})
        design = make_design(ref.spec)
        _no_undercut(ref, design)
        follower = record.roller.follower if record.roller is not None else ref.other
        guide = mechanism.ground_joint(follower).pair  # checked by the reader's validation
        origin = np.array(mechanism.coordinates(mechanism.ground_joint(ref.cam).point) or (0, 0))
        contact = _place(mechanism, ref, design, record, follower, guide, origin)
        out.append(contact)
    return tuple(out)


def _no_undercut(ref: CamRef, design: CamDesign) -> None:
    checks = check_cam(design, 720)
    if not checks.undercut:
        return
    where = ", ".join(f"{a:g}°–{b:g}°" for a, b in checks.undercut_at[:3])
    if design.spec.follower.contact is FollowerContact.ROLLER:
        rho = checks.pitch_min.value if checks.pitch_min is not None else 0.0
        raise UndercutError(
            f"{ref.label}: the roller (radius {design.layout.roller_radius:g} m) is too large for "
            f"the pitch curve, whose smallest convex radius is {rho:.6g} m: the profile loops "
            f"at {where}; use a roller smaller than {rho:.6g} m or a larger base circle"
        )
    raise UndercutError(
        f"{ref.label}: the profile has a cusp at {where} (radius R_b + s + s'' ≤ 0 under the "
        "flat face): make the base circle larger (assur cam gives the smallest)"
    )


def _place(
    m: Mechanism,
    ref: CamRef,
    design: CamDesign,
    record: Replacement,
    follower: str,
    guide: Pair,
    origin: np.ndarray,
) -> CamContact:
    """The design turned into the sketch, and checked against it."""
    at = math.radians(ref.at_deg)
    g = cam_geometry(design, np.array([at]))
    size = design.size
    if design.translating:
        # the spec's +y: the guide's direction, pointing from the cam's centre to the follower
        u = np.array([math.cos(guide.angle or 0.0), math.sin(guide.angle or 0.0)])
        probe = _sketch(m, guide.point) if guide.point else None
        pin = _follower_point(m, record)
        if pin is not None:
            probe = pin
        degrees = (guide.angle_deg or 0.0) - 90.0  # from degrees: 90° turns by exactly 0
        if probe is not None and float(np.dot(probe - origin, u)) < 0:
            degrees += 180.0
        turn = math.radians(math.remainder(degrees, 360.0))
    else:
        spec_pivot = np.asarray(design.layout.pivot, dtype=float)
        pivot = _sketch(m, guide.point)
        if pivot is None:
            raise CamGeometryError(f"{ref.label}: the follower's pivot needs coordinates")
        reach, wanted = float(np.hypot(*(pivot - origin))), float(np.hypot(*spec_pivot))
        if abs(reach - wanted) > SKETCH_TOLERANCE * size:
            raise CamGeometryError(
                f"{ref.label}: the follower's pivot {guide.point} is {reach:.9g} m from the cam's "
                f"centre in the sketch, the program's design puts it {wanted:.9g} m away: move it"
            )
        turn = math.atan2(*(pivot - origin)[::-1]) - math.atan2(*spec_pivot[::-1])
    contact = CamContact(
        ref, design, ref.cam, follower, ref.other, record.virtual_link, record.pair, guide,
        origin, turn, at, record.pair.point,
    )  # fmt: skip
    checks = [(record.pair.point, contact.to_world(g.contact)[0], "the contact")]
    if record.roller is not None:
        checks.append((record.roller.axis, contact.to_world(g.point)[0], "the roller's axis"))
    for name, wanted, what in checks:
        found = _sketch(m, name) if name else None
        if found is None:
            raise CamGeometryError(f"{ref.label}: {what} ({name or 'unnamed'}) needs coordinates")
        if float(np.hypot(*(found - wanted))) > SKETCH_TOLERANCE * size:
            raise CamGeometryError(
                f"{ref.label}: the sketch disagrees with the program at {ref.at_deg:g}°: point "
                f"{name} ({what}) is at ({found[0]:.9g}, {found[1]:.9g}), the program puts it at "
                f"({wanted[0]:.9g}, {wanted[1]:.9g}): move it there, or set at= to the program's "
                "angle the sketch shows (assur cam SPEC -o writes a mechanism that agrees)"
            )
    return contact


def _sketch(m: Mechanism, name: str | None) -> np.ndarray | None:
    xy = m.coordinates(name) if name else None
    return None if xy is None else np.array(xy, dtype=float)


def _follower_point(m: Mechanism, record: Replacement) -> np.ndarray | None:
    """The sketch's roller axis (or knife edge, or flat contact)."""
    if record.roller is not None:
        return _sketch(m, record.roller.axis)
    return _sketch(m, record.pair.point)


@dataclass(frozen=True)
class CamPose:
    """The cam's geometry at each pose, in the world (arrays over the poses).

    ``theta`` the program's angle; ``point`` where the follower takes the
    force (the roller's centre, the knife's edge, the flat face's contact);
    ``contact`` the contact point; ``normal`` the common normal (out of the
    cam); ``centre`` the profile's centre of curvature (the replacement's pin
    on the cam); ``curvature`` ``1/ρ`` there (of the pitch curve for a roller;
    0 where it is straight); ``pressure`` the pressure angle (rad); ``s`` and
    its derivatives by θ, in the program's units (radians for a swinging arm).
    """

    theta: np.ndarray
    point: np.ndarray
    contact: np.ndarray
    normal: np.ndarray
    centre: np.ndarray
    curvature: np.ndarray
    pressure: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    #: the same in the design's own frame (the cam's centre at the origin), where the rates are
    #: found: a dwell's zero velocity is exactly zero there, whatever the sketch's orientation
    local: CamGeometry


def cam_pose(contact: CamContact, turned: np.ndarray) -> CamPose:
    """The geometry when the cam has turned ``turned`` (rad, counter-clockwise) from the sketch."""
    theta = contact.at + contact.design.layout.sense * np.asarray(turned, dtype=float)
    g = cam_geometry(contact.design, theta)
    radius = g.profile_radius if contact.design.layout.flat else g.pitch_radius
    with np.errstate(divide="ignore"):
        curvature = np.where(np.isfinite(radius), 1.0 / radius, 0.0)
    centre = np.where(np.isfinite(g.centre), g.centre, g.point)
    return CamPose(
        theta,
        contact.to_world(g.point),
        contact.to_world(g.contact),
        contact.direction(g.normal),
        contact.to_world(centre),
        curvature,
        g.pressure,
        g.s,
        g.s1,
        g.s2,
        dataclasses.replace(g, centre=centre),
    )


def follower_positions(contact: CamContact, pose: CamPose) -> np.ndarray:
    """The follower's ``(x, y, θ)`` from the sketch at each pose, from the program (N, 3)."""
    design = contact.design
    s0 = float(design_start(contact))
    out = np.zeros((len(pose.theta), 3))
    if design.translating:
        u = contact.direction(np.array([[0.0, 1.0]]))[0]
        out[:, :2] = (pose.s - s0)[:, None] * u
        return out
    psi = design.layout.swing * (pose.s - s0)
    q = contact.pivot
    out[:, :2] = q - rotate_many(psi, q)
    out[:, 2] = psi
    return out


def design_start(contact: CamContact) -> float:
    """The program's displacement at the sketch (its angle ``at``)."""
    return float(cam_geometry(contact.design, np.array([contact.at])).s[0])


def cam_rates(
    contact: CamContact, pose: CamPose, omega: np.ndarray, epsilon: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The follower's coordinate rate and acceleration from the replacement at each pose.

    ``omega`` and ``epsilon`` are the cam's (rad/s, rad/s²). Returns the
    follower's ``q̇``, ``q̈`` (m/s, m/s² along its guide, away from the cam, or
    rad/s, rad/s² of its swing, counter-clockwise) and the denominator
    ``∂P/∂q·n`` (the pressure angle's cosine, times the arm for a swinging
    follower), which vanishes where the follower jams. Worked in the design's
    own frame (the cam's centre at its origin).
    """
    g = pose.local
    n = len(g.theta)
    layout = contact.design.layout
    # the normal as found, before its length was made 1: a dwell's zero is then exactly zero
    m = g.raw_normal
    x = g.centre if layout.flat else g.point  # a flat face: the pin on the cam at C slides
    pivot = np.asarray(layout.pivot, dtype=float)
    if contact.translating:
        along = np.zeros((n, 2))
        along[:, 1] = 1.0
    else:
        along = perpendicular(x - pivot)
    den = dot(along, m)
    # J·x·m and x·m: for a flat face, x = C = (h − ρ)·m + t·J·m gives them as −t and h − ρ,
    # so that they are exactly 0 where the normal passes through the cam's centre (a dwell)
    if layout.flat:
        lever, reach = -g.along_face, dot(g.contact, m) - g.profile_radius
    else:
        lever, reach = dot(perpendicular(x), m), dot(x, m)
    qd = omega * lever / den
    v_rel = qd[:, None] * along - omega[:, None] * perpendicular(x)  # relative to the cam's point
    a_cam = epsilon * lever - omega**2 * reach  # (ε·J·x − ω²·x)·m
    own = np.zeros((n, 2)) if contact.translating else -(qd**2)[:, None] * (x - pivot)
    if layout.flat:
        # C (on the cam) runs straight along the face: a_C = a_C∈f + a_r + 2·ω_f·J·v_r, v_r = −v_rel
        spin = np.zeros(n) if contact.translating else qd
        rhs = a_cam - dot(own, m) + 2.0 * spin * dot(perpendicular(v_rel), m)
    else:
        # P (on the follower) runs along the pitch curve fixed to the cam, of curvature κ
        rhs = (
            a_cam
            - pose.curvature * np.hypot(m[:, 0], m[:, 1]) * dot(v_rel, v_rel)
            + 2.0 * omega * dot(perpendicular(v_rel), m)
            - dot(own, m)
        )
    return qd, rhs / den, den


def follower_rates(
    contact: CamContact, q: np.ndarray, qd: np.ndarray, qdd: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The follower's ``(ẋ, ẏ, θ̇)`` and second derivatives from its coordinate's rates (N, 3)."""
    n = len(qd)
    out_v, out_a = np.zeros((n, 3)), np.zeros((n, 3))
    if contact.translating:
        u = contact.direction(np.array([[0.0, 1.0]]))[0]
        out_v[:, :2] = qd[:, None] * u
        out_a[:, :2] = qdd[:, None] * u
        return out_v, out_a
    # q = (Q − R(ψ)·Q, ψ): the point that was at the origin turns about the pivot Q
    turned = rotate_many(q[:, 2], contact.pivot)
    out_v[:, :2] = -qd[:, None] * perpendicular(turned)
    out_a[:, :2] = -qdd[:, None] * perpendicular(turned) + (qd**2)[:, None] * turned
    out_v[:, 2], out_a[:, 2] = qd, qdd
    return out_v, out_a


def cam_reactions(
    contact: CamContact, pose: CamPose, load: tuple, guide_point: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The follower's equilibrium: contact force, guide (or pivot) force and couple.

    ``load`` is the follower's applied, inertia and carried loads as
    ``(Fx, Fy, M about the follower's point)``, ``guide_point`` where the
    guide's force acts (N, 2). Returns the contact force the cam exerts on the
    follower (N, 2, along the common normal through the follower's point),
    the force of the ground on the follower at ``guide_point`` (N, 2), the
    guide's couple on it (N,; 0 for a pivot) and the contact's moment on the
    cam about its centre (N,; exactly 0 where the normal passes through it).
    """
    fx, fy, moment = load
    f = np.stack([fx, fy], axis=1)
    n = pose.normal
    point = pose.contact if contact.design.layout.flat else pose.point
    if contact.translating:
        u = np.broadcast_to(contact.direction(np.array([[0.0, 1.0]])), f.shape)
        lam = -dot(f, u) / dot(n, u)
        push = lam[:, None] * n
        guide = -(f + push)  # normal to the guide: no component along u
        couple = -(moment + cross(guide_point - point, guide))
    else:
        arm = point - contact.pivot
        lam = -(moment + cross(arm, f)) / cross(arm, n)  # moments about the pivot
        push = lam[:, None] * n
        guide, couple = -(f + push), np.zeros(len(lam))
    g = pose.local
    if contact.design.layout.flat:  # K = h·m + t·J·m: K × (−λ·m) = λ·t
        on_cam = lam * g.along_face
    else:
        raw = g.raw_normal
        on_cam = -lam * cross(g.point, raw) / np.hypot(raw[:, 0], raw[:, 1])
    return push, guide, couple, on_cam


def solve_cam_step(
    contact: CamContact, tables: tuple, inputs: np.ndarray, rates: bool, kinds: tuple
) -> None:
    """Place a designed cam's follower at every pose, and its rates from the replacement.

    ``tables`` are the solve's ``(q, qd, qdd)`` link tables (the cam already
    in them); the follower's rows are written into them.

    Raises
    ------
    SingularPoseError
        The follower jams at some input: the common normal is perpendicular
        to the way it moves (a pressure angle of 90°).
    """
    q, qd, qdd = tables
    cam = q[contact.cam]
    pose = cam_pose(contact, cam[:, 2])
    q[contact.follower] = follower_positions(contact, pose)
    if not rates:
        return
    omega, epsilon = qd[contact.cam][:, 2], qdd[contact.cam][:, 2]
    speed, acceleration, den = cam_rates(contact, pose, omega, epsilon)
    reach = contact.design.size if not contact.translating else 1.0
    jammed = np.abs(den) <= DEAD_CENTRE * reach
    if jammed.any():
        k = int(np.argmax(jammed))
        raise SingularPoseError.singular(
            contact.label, inputs[k], "the follower jams: the contact normal is perpendicular "
            "to its motion (a pressure angle of 90°)", kinds,
        )  # fmt: skip
    qd[contact.follower], qdd[contact.follower] = follower_rates(
        contact, q[contact.follower], speed, acceleration
    )


def sketch_profile(contact: CamContact, samples: int = 240) -> np.ndarray:
    """The cam's profile as the sketch shows it (world, the cam at its angle ``at``), (k, 2).

    Carried by the cam link, as any of its sketch points: a figure turns it with the cam.
    """
    layout = contact.design.layout
    g = cam_geometry(contact.design, np.arange(samples) * (2.0 * math.pi / samples))
    # the cam's frame at program angle 0, turned on to the sketch's angle
    turned = rotate_many(np.full(samples, layout.sense * contact.at), g.profile)
    return contact.to_world(turned)


def contact_at(contact: CamContact, turned: np.ndarray) -> np.ndarray:
    """The contact point (world) when the cam has turned ``turned`` from the sketch (N, 2)."""
    return cam_pose(contact, np.atleast_1d(np.asarray(turned, dtype=float))).contact
