"""Reduced (equivalent) moment of inertia and mass of a linkage, at a pose or over a sweep.

The kinetic energy of every link, ½·(m·v_S² + J_S·ω²), equals that of the
driver alone turning with the reduced moment of inertia, so

    J_red = Σ (m·v_S² + J_S·ω²) / ω_in²   (rotating driver),
    m_red = Σ (m·v_S² + J_S·ω²) / v_in²   (sliding driver).

The link motions come from the kinematics at each pose; the masses from the
``mass LINK m J S`` statements.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan, solve_poses
>>> m = parse_edgelist(["driver 1 omega=3", "0 1 R A", "point A 0 0", "point S 0.2 0",
...                     "mass 1 2 0.01 S"])
>>> plan = make_plan(analyze(m))
>>> reduced_inertia_over(plan, solve_poses(plan, [[0.0]]))   # 0.01 + 2·0.2²
array([0.09])
"""

from __future__ import annotations

import numpy as np

from structure.errors import MechanismError, MobilityError

from ..results.state import Motion
from ..solvers.plan import SolvePlan

__all__ = ["reduced_inertia_over"]


def reduced_inertia_over(plan: SolvePlan, motion: Motion) -> np.ndarray:
    """Reduced moment of inertia (or mass, for a sliding driver) at every pose of ``motion``.

    Raises
    ------
    MobilityError
        Not exactly one driver, or a driver standing still.
    MechanismError
        A centre of mass without coordinates.
    """
    if len(plan.drivers) != 1:
        raise MobilityError("the reduced inertia is taken to a single driver")
    (driver,) = plan.drivers
    m = plan.mechanism
    energy = np.zeros(motion.inputs.shape[0])
    for load in m.loads:
        if load.kind != "mass":
            continue
        mass, inertia = load.values
        xy = m.coordinates(load.point) if load.point else None
        if xy is None:
            raise MechanismError(
                f"the centre of mass {load.point} of link {load.link} needs coordinates"
            )
        _, v, _ = motion.point(load.link, np.array(xy, dtype=float))
        w = motion.qd[load.link][:, 2]
        energy += mass * np.einsum("ij,ij->i", v, v) + inertia * w * w
    speed = (
        motion.qd[driver.link][:, 2]
        if driver.kind == "R"
        else np.einsum("ij,j->i", motion.qd[driver.link][:, :2], driver.direction)
    )
    if np.any(speed == 0):
        raise MobilityError(f"driver {driver.link} stands still: give its speed (omega= or v=)")
    return energy / (speed * speed)
