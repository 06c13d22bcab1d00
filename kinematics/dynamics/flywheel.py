"""The flywheel that holds the coefficient of speed fluctuation δ at a goal: exact and approximate.

**Exact (Wittenbauer's energy–inertia diagram).** Over the turn, plot the
energy the loads and the drive put in since φ = 0, ΔE(φ) = W(φ), against the
reduced inertia J_r(φ). With a flywheel J_F the kinetic energy
½·(J_F + J_r)·ω² = E0 + W, so ω²/2 is the slope of the line from the point
(−J_F, −E0) (the true origin of energy and inertia) to the curve's point. The
speed stays within ω_max,min = ω_m·(1 ± δ/2) when the two tangents to the
curve with slopes k = ω_max²/2 and ω_min²/2 meet at that origin:

    A = max_φ (W − k_max·J_r),   B = min_φ (W − k_min·J_r),
    J_F = (A − B)/(k_max − k_min) = (A − B)/(δ·ω_m²),   E0 = k_max·J_F − A.

**Approximate.** The machine taken as one constant inertia:
J_F ≈ ΔE_max/(δ·ω_m²), ΔE_max = max W − min W, the largest swing of the
energy over the turn; some books then subtract the mechanism's mean J_r. With
J_r constant the exact J_F is ΔE_max/(δ·ω_m²) − J_r; the rest of the difference
is the links' own kinetic energy, which J_r(φ) moves in and out over the turn.

Where M_r depends on ω (a motor curve), W depends on the speed: J_F is then
the one at which the steady running (:func:`~kinematics.dynamics.motion.steady_running`)
has δ at the goal, found from Wittenbauer's by a few steady runs. The mean is
ω_m = (ω_max + ω_min)/2 throughout.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import DynamicsError
from .machine import ReducedMachine
from .motion import DEFAULT_LIMITS, Limits, SteadyRunning, steady_running

__all__ = ["Flywheel", "flywheel", "wittenbauer"]

_TURN = 2 * math.pi
_REFINE = 8


@dataclass(frozen=True)
class Flywheel:
    """A flywheel for a coefficient of speed fluctuation, by both methods, and its diagram.

    Attributes
    ----------
    delta_goal : float
        The δ asked for, over ω_m = (ω_max + ω_min)/2.
    omega_mean : float
        ω_m, rad/s.
    exact : float
        J_F by Wittenbauer's tangents (kg·m², added to the driver's shaft); 0 when
        the machine's own inertia keeps δ within the goal (``needed`` False).
    approximate : float
        ΔE_max/(δ·ω_m²).
    approximate_less_mean : float
        The same less the mechanism's mean reduced inertia.
    energy_swing : float
        ΔE_max = max W − min W over the turn, J.
    needed : bool
        Whether a flywheel is needed at all.
    phi, work, inertia : numpy.ndarray
        The diagram: W(φ) against J_r(φ) (without the flywheel) at the machine's poses.
    origin : tuple of float
        (−J_F, −E0): where the tangents meet (the diagram's true origin; where M_r
        depends on ω, the diagram's at the speed without the flywheel).
    tangents : tuple of tuple of float
        For ω_max and ω_min: (slope k = ω²/2, the angle of contact in rad, and
        A = max(W − k_max·J_r) or B = min(W − k_min·J_r) in J).
    steady : SteadyRunning or None
        The steady running with the flywheel: its δ checks the answer.
    """

    delta_goal: float
    omega_mean: float
    exact: float
    approximate: float
    approximate_less_mean: float
    energy_swing: float
    needed: bool
    phi: np.ndarray
    work: np.ndarray
    inertia: np.ndarray
    origin: tuple[float, float]
    tangents: tuple[tuple[float, float, float], tuple[float, float, float]]
    steady: SteadyRunning | None


def _fine(machine: ReducedMachine) -> np.ndarray:
    phi = machine.properties.phi
    parts = np.arange(_REFINE) / _REFINE
    fine = (phi[:-1, None] + np.diff(phi)[:, None] * parts[None, :]).ravel()
    return np.unique(np.concatenate([fine, [phi[-1]], machine.breaks]))


def wittenbauer(
    phi: np.ndarray, work: np.ndarray, inertia: np.ndarray, omega_mean: float, delta: float
) -> tuple[float, float, int, int]:
    """``(J_F, E0, where the ω_max tangent touches, where the ω_min one does)`` (indices).

    ``work`` and ``inertia`` are W(φ) and J_r(φ) over a turn; the tangents have
    slopes ω_max²/2 and ω_min²/2 with ω_max,min = ω_m·(1 ± δ/2).

    >>> phi = np.linspace(0, 2 * np.pi, 9)
    >>> j, e0, _, _ = wittenbauer(phi, np.sin(phi), np.full(9, 0.5), 10.0, 0.02)
    >>> round(j, 9), round(2 / (0.02 * 100) - 0.5, 9)   # ΔE/(δ·ω²) − J_r for a constant J_r
    (0.5, 0.5)
    """
    k_max = 0.5 * (omega_mean * (1 + delta / 2)) ** 2
    k_min = 0.5 * (omega_mean * (1 - delta / 2)) ** 2
    upper = work - k_max * inertia
    lower = work - k_min * inertia
    top, bottom = int(np.argmax(upper)), int(np.argmin(lower))
    flywheel = (upper[top] - lower[bottom]) / (k_max - k_min)
    energy0 = k_max * flywheel - upper[top]
    return float(flywheel), float(energy0), top, bottom


def flywheel(
    machine: ReducedMachine,
    delta: float,
    *,
    speed: float | None = None,
    steady: SteadyRunning | None = None,
    limits: Limits = DEFAULT_LIMITS,
) -> Flywheel:
    """The flywheel that holds δ at ``delta``, by Wittenbauer and by ΔE_max/(δ·ω_m²).

    Parameters
    ----------
    machine : ReducedMachine
        The machine with its drive.
    delta : float
        The coefficient of speed fluctuation asked for, in (0, 2).
    speed : float, optional
        ω_m where M_r does not depend on ω (default the driver's ``omega=``).
    steady : SteadyRunning, optional
        The machine's steady running without a flywheel, if already found
        (where M_r depends on ω it gives the speed the energy is taken at).

    Raises
    ------
    DynamicsError
        δ out of (0, 2); no mean speed; no steady running (see
        :func:`~kinematics.dynamics.motion.steady_running`).
    """
    if not 0 < delta < 2 or not math.isfinite(delta):
        raise DynamicsError(f"a coefficient of speed fluctuation is in (0, 2), not {delta:g}")
    phi = _fine(machine)
    inertia = machine.inertia(phi)[0]
    if machine.uses_omega:
        if steady is None:
            steady = steady_running(machine, limits=limits)
        omega_mean = steady.omega_mean
        phi = steady.fine_phi
        inertia = machine.inertia(phi)[0] + steady.flywheel
        # along the steady motion the work of M_r is the change of kinetic energy
        energy = 0.5 * inertia * steady.fine_omega**2
        work = energy - energy[0]
        inertia = inertia - steady.flywheel
    else:
        omega_mean = machine.nominal_speed if speed is None else speed
        if omega_mean is None or not omega_mean > 0:
            raise DynamicsError(
                "the flywheel of a machine whose moments do not depend on ω is for a mean speed: "
                "give it (the driver's omega=, or --omega)"
            )
        work = machine.work(phi, float(omega_mean))
    turn_work = float(work[-1])
    if abs(turn_work) > 1e-9 * (float(np.max(np.abs(work))) + 1e-300):
        raise DynamicsError(
            f"the drive and the loads do {turn_work:.6g} J of work per turn, not 0: there is no "
            "steady running to hold (give a drive that balances the loads)"
        )
    exact, energy0, top, bottom = wittenbauer(phi, work, inertia, omega_mean, delta)
    swing = float(np.max(work) - np.min(work))
    approximate = swing / (delta * omega_mean**2)
    needed = exact > 0
    wheel = max(exact, 0.0)
    check = None
    if machine.uses_omega and needed:
        wheel, check = _at_goal(machine, delta, wheel, steady, limits)
    elif machine.has_inertia or wheel > 0:
        check = steady_running(machine, speed=omega_mean, flywheel=wheel, limits=limits)
    at = np.searchsorted(phi, machine.properties.phi)
    k_max = 0.5 * (omega_mean * (1 + delta / 2)) ** 2
    k_min = 0.5 * (omega_mean * (1 - delta / 2)) ** 2
    upper = float(work[top] - k_max * inertia[top])
    lower = float(work[bottom] - k_min * inertia[bottom])
    return Flywheel(
        delta,
        float(omega_mean),
        wheel,
        approximate,
        approximate - float(np.mean(machine.properties.inertia[:-1])),
        swing,
        needed,
        machine.properties.phi,
        work[at],
        inertia[at],
        (-exact, -energy0),
        ((k_max, float(phi[top]), upper), (k_min, float(phi[bottom]), lower)),
        check,
    )


def _at_goal(
    machine: ReducedMachine,
    delta: float,
    start: float,
    steady: SteadyRunning,
    limits: Limits,
) -> tuple[float, SteadyRunning]:
    """The flywheel whose steady running has δ = ``delta`` (M_r depends on ω), and that running.

    1/δ is nearly linear in the inertia: secant steps on it, from Wittenbauer's
    answer at the speed without the flywheel; each steady running starts from
    the last one's speed.
    """
    runs: dict[float, SteadyRunning] = {}
    last = [steady]

    def gap(wheel: float) -> float:
        run = steady_running(machine, flywheel=wheel, limits=limits, guess=float(last[0].omega[0]))
        runs[wheel] = run
        last[0] = run
        return 1.0 / run.delta - 1.0 / delta

    own = float(np.mean(machine.properties.inertia[:-1]))
    a, fa = start, gap(start)
    # δ·(J_F + J_r) is nearly constant: the first step from that, then secant steps
    b = max((start + own) * last[0].delta / delta - own, 0.0)
    fb = gap(b)
    for _ in range(30):
        if abs(fb) <= 1e-5 / delta or fb == fa:
            break
        a, b, fa = b, max(b - fb * (b - a) / (fb - fa), 0.0), fb
        fb = gap(b)
    return float(b), runs[b]
