"""Reduced (equivalent) inertia of a one-degree-of-freedom mechanism over its cycle.

The kinetic energy of the links, Σ ½·(m·v_S² + J_S·ω²), equals that of the
driver alone turning with the reduced moment of inertia

    J_r(φ) = Σ [m·|dr_S/dφ|² + J_S·(dθ/dφ)²],

a function of the driver's angle φ only. Its slope comes from the
accelerations, not by differencing:

    dJ_r/dφ = 2·Σ [m·(dr_S/dφ)·(d²r_S/dφ²) + J_S·(dθ/dφ)·(d²θ/dφ²)].

The derivatives by φ are the velocities and accelerations of the kinematic
solve with the driver turning at ω = 1 rad/s, ε = 0 (for a sliding driver, by
its displacement: the reduced mass). The masses are the file's ``mass LINK m
J S`` statements; a moving link without one is massless.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 1 omega=3", "0 1 R A", "point A 0 0", "point S 0.2 0",
...                     "mass 1 2 0.01 S"])
>>> props = reduced_properties(make_plan(analyze(m)), steps=4)
>>> props.inertia.round(12).tolist(), props.slope.round(12).tolist()   # 0.01 + 2·0.2²
([0.09, 0.09, 0.09, 0.09], [0.0, 0.0, 0.0, 0.0])
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import numpy as np

from structure.errors import MechanismError, MobilityError
from structure.model import Mechanism

from ..results.state import Motion
from ..solvers.plan import SolvePlan
from ..solvers.solve import solve_poses
from ..solvers.sweep import Sweep

__all__ = [
    "ReducedProperties",
    "massless_links",
    "reduced_inertia_over",
    "reduced_properties",
    "unit_plan",
]


@dataclass(frozen=True)
class ReducedProperties:
    """The reduced inertia over the poses of the driver, and the motion it comes from.

    Attributes
    ----------
    phi : numpy.ndarray
        The driver's rotation (rad) or displacement (m) from the sketch, shape (N,).
    inertia : numpy.ndarray
        J_r (kg·m²), or the reduced mass (kg) of a sliding driver, shape (N,).
    slope : numpy.ndarray
        dJ_r/dφ (kg·m²/rad, or kg/m), shape (N,).
    shares : Mapping[str, numpy.ndarray]
        Each link's part of J_r (the sum of its ``mass`` statements), shape (N,).
    driver : str
        The driving link.
    sliding : bool
        Whether the driver slides (then φ is a displacement and J_r a mass).
    massless : tuple of str
        The moving links without a ``mass`` statement: they count as massless.
    motion : Motion or None
        The kinematics at unit driver speed: ``qd`` and point velocities are
        derivatives by φ, ``qdd`` and point accelerations second derivatives
        (None for a gear train without coordinates).
    """

    phi: np.ndarray
    inertia: np.ndarray
    slope: np.ndarray
    shares: Mapping[str, np.ndarray]
    driver: str
    sliding: bool
    massless: tuple[str, ...]
    motion: Motion | None


def massless_links(mechanism: Mechanism, virtual: Iterable[str] = ()) -> tuple[str, ...]:
    """The moving links with no ``mass`` statement, in the mechanism's order.

    ``virtual`` names the links a higher-pair replacement added: they are left out.

    >>> from structure import parse_edgelist
    >>> massless_links(parse_edgelist(["0 1 R A", "1 2 R B", "mass 2 1 0 B"]))
    ('1',)
    """
    massive = {load.link for load in mechanism.loads if load.kind == "mass"}
    skip = massive | set(virtual)
    return tuple(link for link in mechanism.moving_links if link not in skip)


def unit_plan(plan: SolvePlan) -> SolvePlan:
    """The plan with its one driver at unit speed and no acceleration: rates become derivatives.

    Raises
    ------
    MobilityError
        Not exactly one driver.
    """
    if len(plan.drivers) != 1:
        links = ", ".join(d.link for d in plan.drivers)
        raise MobilityError(
            f"the machine's dynamics is taken to one driver; this mechanism has "
            f"{len(plan.drivers)} ({links}): W must be 1"
        )
    (driver,) = plan.drivers
    unit = dataclasses.replace(driver, speed=1.0, acceleration=0.0, speed_given=True)
    return dataclasses.replace(plan, drivers=(unit,))


def _centre(mechanism: Mechanism, link: str, point: str | None) -> np.ndarray:
    xy = mechanism.coordinates(point) if point else None
    if xy is None:
        raise MechanismError(f"the centre of mass {point} of link {link} needs coordinates")
    return np.array(xy, dtype=float)


def reduced_properties(
    plan: SolvePlan, phi: np.ndarray | None = None, *, steps: int = 360
) -> ReducedProperties:
    """J_r and dJ_r/dφ at every driver input of ``phi`` (one turn in ``steps`` by default).

    Parameters
    ----------
    plan : SolvePlan
        A plan with one driver.
    phi : array_like, optional
        The driver's rotations (rad) or displacements (m) from the sketch; by
        default one turn in ``steps`` equal steps from the sketch.
    steps : int
        Poses of the default turn.

    Raises
    ------
    MobilityError
        Not exactly one driver.
    MechanismError
        A sliding driver without ``phi`` (it has no turn), a centre of mass
        without coordinates, or a pose the kinematics cannot solve (named).
    """
    unit = unit_plan(plan)
    (driver,) = unit.drivers
    sliding = driver.kind == "P"
    if phi is None:
        if sliding:
            raise MechanismError(
                f"driver {driver.link} slides: it has no turn, give its displacements"
            )
        phi = np.linspace(0.0, 2 * math.pi, steps, endpoint=False)
    phi = np.asarray(phi, dtype=float).reshape(-1)
    motion = solve_poses(unit, phi[:, None])
    m = plan.mechanism
    inertia = np.zeros(len(phi))
    slope = np.zeros(len(phi))
    shares: dict[str, np.ndarray] = {}
    for load in m.loads:
        if load.kind != "mass" or load.link not in motion.q:
            continue
        mass, moment = load.values
        _, v, a = motion.point(load.link, _centre(m, load.link, load.point))
        w, e = motion.qd[load.link][:, 2], motion.qdd[load.link][:, 2]
        share = mass * np.einsum("ij,ij->i", v, v) + moment * w * w
        inertia += share
        slope += 2.0 * (mass * np.einsum("ij,ij->i", v, a) + moment * w * e)
        shares[load.link] = shares.get(load.link, 0.0) + share
    massless = massless_links(m, (c[0] for c in plan.contacts))
    return ReducedProperties(phi, inertia, slope, shares, driver.link, sliding, massless, motion)


def reduced_inertia_over(plan: SolvePlan, motion: Motion | Sweep) -> np.ndarray:
    """Reduced moment of inertia (or mass, for a sliding driver) at every pose of ``motion``.

    ``motion`` is a solve's :class:`~kinematics.results.state.Motion` or a
    :func:`~kinematics.solvers.sweep.sweep`'s result: only its driver inputs
    are read, so the driver's speed in the file does not matter (it may
    stand still). This is :func:`reduced_properties`' ``inertia``.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan, sweep
    >>> m = parse_edgelist(["driver 1 omega=3", "0 1 R A", "point A 0 0", "point S 0.2 0",
    ...                     "mass 1 2 0.01 S"])
    >>> plan = make_plan(analyze(m))
    >>> reduced_inertia_over(plan, sweep(plan, steps=2)).round(12)   # 0.01 + 2·0.2²
    array([0.09, 0.09])

    Raises
    ------
    MobilityError
        Not exactly one driver.
    MechanismError
        A centre of mass without coordinates.
    """
    inputs = np.asarray(motion.inputs, dtype=float)
    if inputs.ndim == 2 and inputs.shape[1] != 1:
        unit_plan(plan)  # names the drivers
    return reduced_properties(plan, inputs.reshape(-1)).inertia
