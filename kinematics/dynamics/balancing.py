"""Balancing the shaking force: counterweights, written back as ``mass`` statements.

- **Static balance of a link** pinned to the frame at P: a counterweight m_c
  at c with m_c·(c − P) = −Σ m·(S − P) puts the link's centre of mass on its
  pivot, so that its inertia force vanishes at any speed.
- **Complete shaking-force balance of a four-bar** (Berkof & Lowen, "A new
  method for completely force balancing simple linkages", J. Eng. Ind. 91(1),
  1969, 21–26; the method of linearly independent vectors). With each link's
  mass moment μ_k in its own frame (along the link from its frame pin, and to
  its left), the loop a1·e1 + a2·e2 = (D − A) + a3·e3 eliminates e2 from the
  total centre of mass; e1 and e3 being independent, it stands still if and
  only if μ1 = μ2·a1/a2 − m2·a1 and μ3 = −μ2·a3/a2 (μ2 taken about B). A
  counterweight on the crank and one on the rocker give them.
- **A crank–slider** can be balanced only in part: a crank counterweight
  takes the rotating mass (the crank's, and the rod's share at the crank pin)
  and a fraction of the reciprocating mass's primary (first-harmonic) force,
  which it turns into a force across the slide; the secondary (second-harmonic)
  force needs two masses turning the other way at 2ω (a Lanchester balancer),
  given here and not written (the file cannot hold it).

Each counterweight is a point mass (no moment of inertia of its own) at the
radius asked for (default: the link's own length from its pivot). The
balanced mechanism is the file's with ``point CW<link> x y on=<link>`` and
``mass <link> m 0 CW<link>`` added.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from structure.model import Mechanism, PairKind, make_load, make_point
from structure.report import StructuralReport, analyze

from ..errors import DynamicsError
from ..solvers.plan import SolvePlan, make_plan
from .machine import reduced_machine
from .reduced import reduced_properties
from .shaking import Shaking, shaking

__all__ = [
    "Balanced",
    "Counterweight",
    "Harmonics",
    "balance",
    "balanced_to_dict",
    "counterweight",
    "with_counterweights",
]

_TURN = 2 * math.pi


@dataclass(frozen=True)
class Counterweight:
    """A point mass ``mass`` (kg) fixed to ``link`` at ``position`` (sketch coordinates, m)."""

    link: str
    mass: float
    position: tuple[float, float]
    radius: float  # its distance from the link's pivot
    pivot: str


@dataclass(frozen=True)
class Harmonics:
    """A crank–slider's shaking force along its slide, by harmonics of the crank angle.

    ``primary`` and ``secondary`` are the amplitudes (N) of the first and
    second harmonics of the exact force; ``reciprocating`` the mass that moves
    with the slider (its own and the rod's share at the wrist pin), ``rotating``
    the mass moment turning with the crank pin (kg·m); ``lanchester`` the mass
    moment (kg·m) of each of two masses turning at 2ω in opposite senses that
    cancels the secondary force.
    """

    primary: float
    secondary: float
    reciprocating: float
    rotating: float
    crank: float
    rod: float
    lanchester: float


@dataclass(frozen=True)
class Balanced:
    """A balanced mechanism and what the balance changed.

    ``method`` is ``"complete"`` (a four-bar, Berkof–Lowen), ``"primary"``
    (a crank–slider, with ``fraction`` of its reciprocating mass) or
    ``"static"`` (each link pinned to the frame on its own pivot).
    ``torque_before`` and ``torque_after`` are the driving torques over the
    cycle at the constant speed (N·m): the counterweights add inertia.
    """

    mechanism: Mechanism
    counterweights: tuple[Counterweight, ...]
    method: str
    before: Shaking
    after: Shaking
    torque_before: np.ndarray
    torque_after: np.ndarray
    harmonics: Harmonics | None = None
    harmonics_after: Harmonics | None = None
    fraction: float | None = None
    notes: tuple[str, ...] = ()


def _complex(xy) -> complex:
    return complex(float(xy[0]), float(xy[1]))


def _xy(mechanism: Mechanism, name: str | None, why: str) -> complex:
    xy = mechanism.coordinates(name) if name is not None else None
    if xy is None:
        raise DynamicsError(f"{why}: point {name} needs coordinates")
    return _complex(xy)


def _mass_moment(mechanism: Mechanism, link: str, about: complex) -> tuple[float, complex]:
    """The total mass of ``link``'s ``mass`` statements and their moment Σ m·(S − about)."""
    total, moment = 0.0, 0j
    for load in mechanism.loads:
        if load.kind == "mass" and load.link == link:
            centre = _xy(mechanism, load.point, f"the centre of mass of link {link}")
            total += load.values[0]
            moment += load.values[0] * (centre - about)
    return total, moment


def counterweight(
    mechanism: Mechanism,
    link: str,
    pivot: str,
    *,
    radius: float | None = None,
    moment: complex | None = None,
) -> Counterweight | None:
    """The counterweight that puts ``link``'s centre of mass on ``pivot`` (None: it is there).

    ``moment`` is the mass moment the counterweight must add (world frame, at
    the sketch), by default −Σ m·(S − P) of the link's masses; ``radius`` its
    distance from the pivot (default: the farthest pin of the link from it).

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["0 1 R A", "point A 0 0", "point S 0.1 0", "mass 1 2 0 S"])
    >>> cw = counterweight(m, "1", "A", radius=0.05)
    >>> cw.mass, cw.position
    (4.0, (-0.05, 0.0))
    """
    p = _xy(mechanism, pivot, f"the pivot of link {link}")
    if moment is None:
        moment = -_mass_moment(mechanism, link, p)[1]
    size = abs(moment)
    if size <= 1e-15 * max(1.0, _scale(mechanism)):
        return None
    if radius is None:
        radius = _link_length(mechanism, link, p)
    if not radius > 0 or not math.isfinite(radius):
        raise DynamicsError(f"a counterweight's radius must be positive, not {radius:g}")
    mass = size / radius
    at = p + moment / mass
    reach = max((abs(c) for q in mechanism.points.values() for c in (q.x, q.y)), default=1.0)
    x, y = (v if abs(v) > 1e-12 * (reach or 1.0) else 0.0 for v in (at.real, at.imag))
    return Counterweight(link, mass, (x, y), radius, pivot)


def _scale(mechanism: Mechanism) -> float:
    masses = [abs(x.values[0]) for x in mechanism.loads if x.kind == "mass"]
    coords = [abs(c) for p in mechanism.points.values() for c in (p.x, p.y)]
    return (max(masses, default=1.0) or 1.0) * (max(coords, default=1.0) or 1.0) * 1e-3


def _link_length(mechanism: Mechanism, link: str, p: complex) -> float:
    """The distance from ``p`` to the farthest pin of ``link`` (its length from the pivot)."""
    far = 0.0
    for pair in mechanism.pairs_of(link):
        xy = mechanism.coordinates(pair.point) if pair.point else None
        if xy is not None:
            far = max(far, abs(_complex(xy) - p))
    if far <= 0:
        raise DynamicsError(f"link {link} has no pin away from its pivot: give the radius")
    return far


def with_counterweights(mechanism: Mechanism, weights: tuple[Counterweight, ...]) -> Mechanism:
    """The mechanism with each counterweight as ``point CW<link> x y on=<link>`` and a ``mass``."""
    points = dict(mechanism.points)
    loads = list(mechanism.loads)
    size = max((abs(c) for p in points.values() for c in (p.x, p.y)), default=1.0) or 1.0
    for w in weights:
        name = f"CW{w.link}"
        k = 2
        while name in points:
            name, k = f"CW{w.link}_{k}", k + 1
        x, y = (_round(v) if abs(v) > 1e-12 * size else 0.0 for v in w.position)
        points[name] = make_point(name, x, y, w.link)
        loads.append(make_load("mass", w.link, name, (_round(w.mass), 0.0)))
    return mechanism.evolve(points=points, loads=tuple(loads))


def _round(x: float) -> float:
    """A float to 15 significant digits: the file shows it short, and reads it back the same."""
    return float(f"{x:.15g}")


# ------------------------------------------------------------------ the mechanisms
def _four_bar(plan: SolvePlan):
    """(A, crank, coupler, rocker, B, C, D) of a four-bar plan of revolute pairs, or None."""
    if len(plan.drivers) != 1 or plan.drivers[0].kind != "R" or len(plan.steps) != 1:
        return None
    if plan.contacts:  # a higher pair's virtual link is no coupler to balance
        return None
    group = plan.steps[0].group
    if group is None or group.kind != "RRR":
        return None
    crank = plan.drivers[0].link
    ground = plan.mechanism.ground
    outer = {
        p.links[0] if p.links[1] in group.links else p.links[1]: p for p in group.external_pairs
    }
    if set(outer) != {crank, ground}:
        return None
    to_crank, to_ground = outer[crank], outer[ground]
    coupler = next(link for link in to_crank.links if link != crank)
    rocker = next(link for link in to_ground.links if link != ground)
    (inner,) = group.internal_pairs
    return (
        plan.drivers[0].point,
        crank,
        coupler,
        rocker,
        to_crank.point,
        inner.point,
        to_ground.point,
    )


def _crank_slider(plan: SolvePlan):
    """(A, crank, rod, slider, B, C, slide direction) of a crank–slider plan, or None."""
    if len(plan.drivers) != 1 or plan.drivers[0].kind != "R" or len(plan.steps) != 1:
        return None
    if plan.contacts:  # a higher pair's virtual link is no coupler to balance
        return None
    group = plan.steps[0].group
    if group is None or group.kind != "RRP":
        return None
    crank = plan.drivers[0].link
    ground = plan.mechanism.ground
    pins = [p for p in group.external_pairs if p.kind is PairKind.R]
    slides = [p for p in group.external_pairs if p.kind is PairKind.P]
    if len(pins) != 1 or len(slides) != 1 or crank not in pins[0].links:
        return None
    if ground not in slides[0].links:
        return None
    rod = next(link for link in pins[0].links if link != crank)
    slider = next(link for link in slides[0].links if link != ground)
    (inner,) = group.internal_pairs
    angle = plan.mechanism.pair(slides[0].pair).angle or 0.0
    return plan.drivers[0].point, crank, rod, slider, pins[0].point, inner.point, angle


def _complete(mechanism: Mechanism, parts, radius: float | None) -> tuple[Counterweight, ...]:
    """Berkof–Lowen's counterweights on the crank and the rocker of a four-bar."""
    a_name, crank, coupler, rocker, b_name, c_name, d_name = parts
    a, b = _xy(mechanism, a_name, "the crank's pivot"), _xy(mechanism, b_name, "the crank pin")
    c, d = _xy(mechanism, c_name, "the coupler pin"), _xy(mechanism, d_name, "the rocker's pivot")
    a1, a2, a3 = abs(b - a), abs(c - b), abs(c - d)
    e1, e2, e3 = (b - a) / a1, (c - b) / a2, (c - d) / a3
    m2, mu2 = _mass_moment(mechanism, coupler, b)
    mu2_local = mu2 / e2
    need1 = mu2_local * a1 / a2 - m2 * a1  # in the crank's frame
    need3 = -mu2_local * a3 / a2  # in the rocker's frame
    weights = []
    for link, pivot, pivot_name, e, need in (
        (crank, a, a_name, e1, need1),
        (rocker, d, d_name, e3, need3),
    ):
        have = _mass_moment(mechanism, link, pivot)[1] / e
        add = (need - have) * e  # back in the world frame, at the sketch
        w = counterweight(mechanism, link, pivot_name, radius=radius, moment=add)
        if w is not None:
            weights.append(w)
    return tuple(weights)


def _harmonics(
    plan: SolvePlan, mechanism: Mechanism, parts, omega: float
) -> tuple[Harmonics, np.ndarray]:
    """The exact shaking force along the slide by harmonics, and the textbook's masses."""
    a_name, crank, rod, slider, b_name, c_name, angle = parts
    steps = 360
    props = reduced_properties(plan, np.linspace(0.0, _TURN, steps, endpoint=False))
    found = shaking(props, mechanism, omega)
    along = found.force @ np.array([math.cos(angle), math.sin(angle)])
    spectrum = np.fft.rfft(along) / steps * 2
    a, b, c = (_xy(mechanism, n, "the crank–slider") for n in (a_name, b_name, c_name))
    r, length = abs(b - a), abs(c - b)
    m_rod, mu_rod = _mass_moment(mechanism, rod, b)
    share_c = (mu_rod / ((c - b) / length)).real / length * 1.0 if m_rod else 0.0
    share_b = m_rod - share_c
    m_slider = _mass_moment(mechanism, slider, c)[0]
    _, mu_crank = _mass_moment(mechanism, crank, a)
    rotating = (mu_crank / ((b - a) / r)).real + share_b * r
    reciprocating = m_slider + share_c
    secondary = float(abs(spectrum[2]))
    return (
        Harmonics(
            float(abs(spectrum[1])),
            secondary,
            reciprocating,
            rotating,
            r,
            length,
            secondary / (8 * omega * omega) if omega else 0.0,
        ),
        along,
    )


def _primary(
    mechanism: Mechanism, parts, fraction: float, radius: float | None, harmonics: Harmonics
):
    """The crank counterweight: the rotating mass, and ``fraction`` of the reciprocating one."""
    a_name, crank, *_ = parts
    a = _xy(mechanism, a_name, "the crank's pivot")
    b = _xy(mechanism, parts[4], "the crank pin")
    e1 = (b - a) / abs(b - a)
    have = _mass_moment(mechanism, crank, a)[1] / e1
    need = -(fraction * harmonics.reciprocating * harmonics.crank) - (
        harmonics.rotating - have.real
    )
    add = (need - have) * e1
    w = counterweight(mechanism, crank, a_name, radius=radius, moment=add)
    return () if w is None else (w,)


def _static(mechanism: Mechanism, radius: float | None) -> tuple[Counterweight, ...]:
    """A counterweight on every link pinned to the frame, on its own pivot."""
    weights = []
    for link in mechanism.moving_links:
        joint = mechanism.ground_joint(link)
        if joint is None or joint.kind is not PairKind.R or joint.point is None:
            continue
        w = counterweight(mechanism, link, joint.point, radius=radius)
        if w is not None:
            weights.append(w)
    return tuple(weights)


def _torque(report: StructuralReport, omega: float) -> np.ndarray:
    """The driving torque over the cycle at the constant speed ω: ½·J_r'·ω² − M_loads."""
    machine = reduced_machine(report, drive=None)
    loads = machine.moment(machine.properties.phi, omega, drive=False)
    return -machine.inertia_torque(omega, 0.0) - loads


def balance(
    report: StructuralReport,
    *,
    method: str = "auto",
    omega: float | None = None,
    radius: float | None = None,
    fraction: float = 0.5,
) -> Balanced:
    """Counterweights that balance the shaking force of ``report``'s mechanism.

    Parameters
    ----------
    report : StructuralReport
        A one-degree-of-freedom mechanism with a turning driver, masses and coordinates.
    method : {"auto", "complete", "primary", "static"}
        ``auto`` takes ``complete`` for a four-bar, ``primary`` for a
        crank–slider and ``static`` for anything else.
    omega : float, optional
        The constant speed the shaking and the torque are compared at
        (default the driver's ``omega=``, else 1 rad/s: the forces scale with ω²).
    radius : float, optional
        Each counterweight's distance from its pivot (default the link's length).
    fraction : float
        ``primary``: the part of the reciprocating mass the crank takes (0 to 1).

    Raises
    ------
    DynamicsError
        No mass data; a method that does not fit the mechanism; a bad radius or fraction.
    MobilityError
        W ≠ 1.
    """
    mechanism = report.mechanism
    if not any(x.kind == "mass" for x in mechanism.loads):
        raise DynamicsError(
            "the mechanism has no mass data (a link without a 'mass' line is massless): "
            "there is nothing to balance"
        )
    if not 0 <= fraction <= 1:
        raise DynamicsError(
            f"the fraction of the reciprocating mass is in [0, 1], not {fraction:g}"
        )
    machine = reduced_machine(report, drive=None)
    if machine.properties.motion is None:
        raise DynamicsError("balancing needs the mechanism's coordinates (a sketch)")
    plan = make_plan(report)
    speed = omega if omega is not None else (machine.nominal_speed or 1.0)
    four_bar, slider = _four_bar(plan), _crank_slider(plan)
    if method == "auto":
        method = "complete" if four_bar else "primary" if slider else "static"
    notes: list[str] = []
    harmonics = harmonics_after = None
    if method == "complete":
        if four_bar is None:
            raise DynamicsError(
                "complete balance (Berkof–Lowen) is for a four-bar of revolute pairs"
            )
        weights = _complete(mechanism, four_bar, radius)
    elif method == "primary":
        if slider is None:
            raise DynamicsError("primary balance is for a crank–slider (its slide on the frame)")
        harmonics, _ = _harmonics(plan, mechanism, slider, speed)
        weights = _primary(mechanism, slider, fraction, radius, harmonics)
    elif method == "static":
        weights = _static(mechanism, radius)
    else:
        raise DynamicsError(
            f"unknown balancing method {method!r} (auto, complete, primary, static)"
        )
    balanced = with_counterweights(mechanism, weights)
    after_report = analyze(balanced, report.drivers)
    before = shaking(machine.properties, mechanism, speed)
    after_machine = reduced_machine(after_report, drive=None)
    after = shaking(after_machine.properties, balanced, speed)
    if method == "primary":
        harmonics_after, _ = _harmonics(make_plan(after_report), balanced, slider, speed)
        notes.append(
            f"the secondary force ({harmonics_after.secondary:.6g} N at {speed:.6g} rad/s) "
            "stays: two masses turning at 2ω in opposite senses, each of mass moment "
            f"{harmonics_after.lanchester:.6g} kg·m, would cancel it (a Lanchester balancer, "
            "not written: the file cannot hold it)"
        )
    return Balanced(
        balanced,
        weights,
        method,
        before,
        after,
        _torque(report, speed),
        _torque(after_report, speed),
        harmonics,
        harmonics_after,
        fraction if method == "primary" else None,
        tuple(notes),
    )


def _side(shaken: Shaking, torque: np.ndarray) -> dict:
    return {
        "force_max": shaken.force_max,
        "moment_max": shaken.moment_max,
        "torque_max": float(np.max(np.abs(torque))),
        "fx": [float(v) for v in shaken.force[:, 0]],
        "fy": [float(v) for v in shaken.force[:, 1]],
        "m": [float(v) for v in shaken.moment],
        "torque": [float(v) for v in torque],
    }


def _harmonics_dict(h: Harmonics | None) -> dict | None:
    if h is None:
        return None
    return {
        "primary": h.primary,
        "secondary": h.secondary,
        "reciprocating_mass": h.reciprocating,
        "rotating_mass_moment": h.rotating,
        "lanchester_mass_moment": h.lanchester,
    }


def balanced_to_dict(result: Balanced) -> dict:
    """The balance as plain data (the keys of ``assur balance --json``)."""
    return {
        "method": result.method,
        "omega": result.before.omega,
        "about": {"point": result.before.about_name, "xy": list(result.before.about)},
        "phi_deg": [float(v) for v in np.degrees(result.before.phi)],
        "counterweights": [
            {
                "link": w.link,
                "mass": w.mass,
                "position": list(w.position),
                "radius": w.radius,
                "pivot": w.pivot,
            }
            for w in result.counterweights
        ],
        "before": {
            **_side(result.before, result.torque_before),
            "harmonics": _harmonics_dict(result.harmonics),
        },
        "after": {
            **_side(result.after, result.torque_after),
            "harmonics": _harmonics_dict(result.harmonics_after),
        },
        "fraction": result.fraction,
        "notes": list(result.notes),
    }
