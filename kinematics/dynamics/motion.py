"""The equation of motion of a machine reduced to its driver: start-up, run-down, steady running.

With J_r(φ) the reduced inertia and M_r(φ, ω) the reduced moment
(:class:`~kinematics.dynamics.machine.ReducedMachine`), the driver's angle
obeys

    J_r·φ̈ + ½·J_r'·φ̇² = M_r(φ, φ̇),      or, in energy form,   d(½·J_r·ω²)/dφ = M_r.

- :func:`start_up` and :func:`run_down` integrate it in time (scipy's
  ``solve_ivp``, DOP853, LSODA where the machine is stiff, an event at each turn
  of the driver and where it stops): from rest with the drive until the machine
  runs steadily, and from steady running with the drive off until it stops (or
  has slowed below a thousandth of its speed: a load like −k·ω² never quite stops it);
- :func:`steady_running` finds the periodic motion directly. Where M_r does not
  depend on ω, ½·J_r·ω² = E0 + W(φ) with W the work of M_r since φ = 0: the
  one constant E0 is the root that gives the mean speed asked for (the turn's
  work must be zero, or there is no steady running). Where it does (a motor
  curve), the speed at φ = 0 is the fixed point of one turn of the energy form
  (a one-dimensional shooting problem).

The coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m is given with the
textbook's mean ω_m = (ω_max + ω_min)/2 (the flywheel's formulas use it) and
with the time mean 2π/T of one turn, both named.

Every run is bounded: turns, time, right-hand sides evaluated and seconds of
wall clock; a run that exceeds them, or whose integrator gives up (a stiff or
diverging run), ends in a :class:`~kinematics.errors.IntegrationError`.
"""

from __future__ import annotations

import itertools
import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from ..errors import DynamicsError, IntegrationError, NoSteadyRunningError, StallError
from .machine import ReducedMachine

__all__ = [
    "DEFAULT_LIMITS",
    "Limits",
    "Run",
    "SteadyRunning",
    "run_down",
    "start_up",
    "steady_running",
]

_TURN = 2 * math.pi


@dataclass(frozen=True)
class Limits:
    """Bounds of one integration: it ends with a named error beyond them, never hangs.

    ``rtol`` is the integrator's relative tolerance (its absolute one is
    relative to the motion's own size).
    """

    turns: int = 500
    seconds: float = 20.0  # of wall clock
    evaluations: int = 4_000_000
    rtol: float = 1e-11


#: a run in time takes DOP853 (its energy drifts least); a turn that needs more evaluations than
#: this is stiff (a light machine against a load that grows with the speed), and the run goes
#: on with LSODA, which takes BDF steps where the machine is stiff; steady running takes LSODA
STIFF_EVALUATIONS = 20_000
_EXPLICIT, _SWITCHING = "DOP853", "LSODA"
#: a run-down ends where the speed falls below this fraction of the speed it started at
SLOWED = 1e-3


class _Stiff(Exception):
    """One turn of a run in time needs too many explicit steps: it is stiff."""


#: the bounds of a run unless others are given
DEFAULT_LIMITS = Limits()


@dataclass(frozen=True)
class Run:
    """A run in time: ``t`` (s), ``phi`` (rad from the sketch, cumulative), ``omega`` (rad/s).

    ``turns`` holds the time at which each whole turn of the driver was
    completed; ``ending`` says why the run ended: ``"steady"`` (within
    ``tolerance`` of steady running), ``"stopped"`` (ω came to 0, at ``phi[-1]``),
    ``"slowed"`` (a run-down below :data:`SLOWED` of its first speed), ``"turns"`` (the
    most turns asked for). ``solution`` holds scipy's dense
    output of each turn when the run was asked for it (``dense=True``): then
    :meth:`at` gives (φ, ω) at any time of the run.
    """

    kind: str
    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    turns: np.ndarray
    ending: str
    solution: Any = field(repr=False, compare=False, default=None)

    @property
    def duration(self) -> float:
        return float(self.t[-1] - self.t[0])

    def at(self, t: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
        """φ and ω at times of the run (from its dense output)."""
        if not self.solution or self.solution[0] is None:
            raise ValueError("the run was made without its dense output: ask for dense=True")
        t = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.empty((2, len(t)))
        ends = np.array([piece.t_max for piece in self.solution])
        for k, value in enumerate(t):
            piece = self.solution[min(int(np.searchsorted(ends, value)), len(ends) - 1)]
            out[:, k] = piece(value)
        return out[0], out[1]


@dataclass(frozen=True)
class SteadyRunning:
    """The periodic motion over one turn (both ends included).

    Attributes
    ----------
    phi, omega, t : numpy.ndarray
        The driver's angle from the sketch (rad), its speed (rad/s) and the time
        since φ = 0 (s) at the poses of the machine.
    period : float
        The time of one turn, s.
    omega_max, omega_min : float
        The extremes of ω over the turn.
    omega_mean : float
        (ω_max + ω_min)/2, the textbook's mean speed.
    omega_time_mean : float
        2π/T, the mean over time.
    delta, delta_time_mean : float
        (ω_max − ω_min) over each mean.
    energy : float
        ½·J_r·ω² at φ = 0 (J).
    flywheel : float
        The constant inertia added to J_r (kg·m²).
    method : str
        ``"energy"`` (M_r without ω: closed form and one root) or ``"shooting"``.
    fine_phi, fine_omega : numpy.ndarray
        The same on poses eight times finer, with a table's corners (where
        the extremes are taken).
    """

    phi: np.ndarray
    omega: np.ndarray
    t: np.ndarray
    period: float
    omega_max: float
    omega_min: float
    omega_mean: float
    omega_time_mean: float
    delta: float
    delta_time_mean: float
    energy: float
    flywheel: float
    method: str
    fine_phi: np.ndarray = field(repr=False, compare=False, default=None)
    fine_omega: np.ndarray = field(repr=False, compare=False, default=None)

    def omega_at(self, phi: np.ndarray | float) -> np.ndarray:
        """ω at angles of the turn (any turn), linear between the fine poses."""
        return np.interp(np.mod(phi, _TURN), self.fine_phi, self.fine_omega)


class _Budget:
    """Counts the right-hand sides and the wall clock of one integration."""

    def __init__(self, limits: Limits, what: str):
        self.limits = limits
        self.what = what
        self.count = 0
        self.start = time.monotonic()

    def spend(self) -> None:
        self.count += 1
        if self.count > self.limits.evaluations:
            raise IntegrationError(
                f"the {self.what} needs more than {self.limits.evaluations} evaluations of the "
                "equation of motion: it is stiff (an inertia tiny beside its loads) or diverges"
            )
        if self.count % 2000 == 0 and time.monotonic() - self.start > self.limits.seconds:
            raise IntegrationError(
                f"the {self.what} takes longer than {self.limits.seconds:g} s: it is stiff or "
                "diverges (an inertia tiny beside its loads?)"
            )


def _check_inertia(machine: ReducedMachine, flywheel: float) -> None:
    if flywheel < 0 or not math.isfinite(flywheel):
        raise DynamicsError(f"a flywheel's inertia cannot be {flywheel:g}")
    inertia = machine.properties.inertia + flywheel
    if np.max(inertia) <= 0:
        raise DynamicsError(
            "the machine has no mass: every link is massless (give 'mass LINK m J S' lines), so "
            "its reduced inertia is 0 and its motion is not defined"
        )
    if np.min(inertia) <= 1e-12 * np.max(inertia):
        where = math.degrees(float(machine.properties.phi[np.argmin(inertia)]))
        raise DynamicsError(
            f"the reduced inertia vanishes at φ = {where:.4g}° (every mass stands still there): "
            "give the driver a moment of inertia, or a flywheel"
        )


# ------------------------------------------------------------------ in time
def _time_run(
    machine: ReducedMachine,
    kind: str,
    phi0: float,
    omega0: float,
    *,
    drive: bool,
    flywheel: float,
    limits: Limits,
    steady: SteadyRunning | None,
    tolerance: float,
    dense: bool = False,
) -> Run:
    """Integrate turn by turn from (φ0, ω0) until steady, stopped, or the limits."""
    _check_inertia(machine, flywheel)
    budget = _Budget(limits, kind)
    scale = max(abs(omega0), steady.omega_max if steady is not None else 0.0, 1.0)
    cap = 1e6 * scale
    method = [_EXPLICIT, 0]  # the method, and the evaluations of the turn under way

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        budget.spend()
        method[1] += 1
        if method[1] > STIFF_EVALUATIONS and method[0] == _EXPLICIT:
            raise _Stiff
        inertia, slope, moment = machine.at(y[0], y[1], drive)
        inertia += flywheel
        return [y[1], (moment - 0.5 * slope * y[1] * y[1]) / inertia]

    def stopped(_t: float, y: np.ndarray) -> float:
        return y[1]

    stopped.terminal = True  # type: ignore[attr-defined]
    stopped.direction = -1  # type: ignore[attr-defined]

    def runaway(_t: float, y: np.ndarray) -> float:
        return abs(y[1]) - cap

    runaway.terminal = True  # type: ignore[attr-defined]
    slow = SLOWED * abs(omega0) if kind == "run-down" else 0.0

    def slowed(_t: float, y: np.ndarray) -> float:
        return abs(y[1]) - slow

    slowed.terminal = True  # type: ignore[attr-defined]
    slowed.direction = -1  # type: ignore[attr-defined]
    events = [stopped, runaway] + ([slowed] if slow > 0 else [])

    ts, phis, omegas = [np.array([0.0])], [np.array([phi0])], [np.array([omega0])]
    turns: list[float] = []
    pieces: list[Any] = []
    t0, y = 0.0, np.array([phi0, omega0], dtype=float)
    ending = "turns"
    for _ in range(4 * limits.turns):
        if len(turns) >= limits.turns:
            break
        goal = phi0 + _TURN * (len(turns) + 1)

        def turned(_t: float, z: np.ndarray, goal: float = goal) -> float:
            return z[0] - goal

        turned.terminal = True  # type: ignore[attr-defined]
        turned.direction = 1  # type: ignore[attr-defined]
        span = _span(machine, y, flywheel, drive)
        method[1] = 0
        try:
            sol = _integrate(
                rhs, (t0, t0 + span), y, [turned, *events], limits, kind, dense, method[0],
            )  # fmt: skip
        except _Stiff:
            method[:] = [_SWITCHING, 0]
            sol = _integrate(
                rhs, (t0, t0 + span), y, [turned, *events], limits, kind, dense, method[0],
            )  # fmt: skip
        pieces.append(sol.sol)
        ts.append(sol.t[1:])
        phis.append(sol.y[0, 1:])
        omegas.append(sol.y[1, 1:])
        t0, y = float(sol.t[-1]), sol.y[:, -1].copy()
        if sol.t_events[2].size:
            raise IntegrationError(
                f"the {kind} diverges: ω passes {cap:.3g} rad/s after {t0:.4g} s"
            )
        if sol.t_events[1].size:
            y[1] = 0.0
            omegas[-1][-1] = 0.0
            ending = "stopped"
            break
        if slow > 0 and sol.t_events[3].size:
            ending = "slowed"
            break
        if not sol.t_events[0].size:  # neither turned nor stopped within the span: go on
            continue
        turns.append(t0)
        if steady is not None:
            target = float(steady.omega_at(y[0]))
            if abs(y[1] - target) <= tolerance * steady.omega_mean:
                ending = "steady"
                break
    return Run(
        kind,
        np.concatenate(ts),
        np.concatenate(phis),
        np.concatenate(omegas),
        np.array(turns),
        ending,
        tuple(pieces),
    )


def _span(machine: ReducedMachine, y: np.ndarray, flywheel: float, drive: bool) -> float:
    """A time long enough for one turn, or for the speed to change a lot, from state ``y``."""
    inertia, _, moment = machine.at(y[0], y[1], drive)
    inertia += flywheel
    accel = abs(moment) / inertia + 1e-300
    speed = abs(y[1])
    by_speed = _TURN / speed if speed > 0 else math.inf
    by_accel = math.sqrt(2 * _TURN / accel)
    return 4.0 * min(by_speed, by_accel, 1e9)


def _integrate(rhs, span, y0, events, limits: Limits, what: str, dense: bool, method: str):
    scale = np.array([1.0, max(abs(y0[1]), 1.0)])
    try:
        sol = solve_ivp(
            rhs,
            span,
            y0,
            method=method,
            rtol=limits.rtol,
            atol=limits.rtol * scale * 1e-2,
            events=events,
            dense_output=dense,
        )
    except (FloatingPointError, OverflowError, ZeroDivisionError) as exc:
        raise IntegrationError(f"the {what} diverges ({exc})") from exc
    if sol.status == -1:
        raise IntegrationError(f"the {what} cannot go on: {sol.message} (a stiff or diverging run)")
    if not np.all(np.isfinite(sol.y)):
        raise IntegrationError(f"the {what} diverges: its speed is no longer finite")
    return sol


def start_up(
    machine: ReducedMachine,
    *,
    phi0: float = 0.0,
    omega0: float = 0.0,
    flywheel: float = 0.0,
    steady: SteadyRunning | None = None,
    tolerance: float = 1e-3,
    limits: Limits = DEFAULT_LIMITS,
    dense: bool = False,
) -> Run:
    """The machine started from rest (or ``omega0``) at ``phi0`` with its drive.

    The run ends when the driver's speed at the end of a turn is within
    ``tolerance`` (relative to the mean) of ``steady`` running, when it
    stops, or after ``limits.turns`` turns.

    Raises
    ------
    StallError
        The drive cannot move the machine from rest at ``phi0``, or it stops
        it (the message names where and by how much the torque falls short).
    DynamicsError
        No mass, or no drive.
    IntegrationError
        A stiff or diverging run, or one beyond ``limits``.
    """
    if machine.drive is None:
        raise DynamicsError("a start-up needs a drive: give a 'drive' line or --drive")
    run = _time_run(
        machine, "start-up", phi0, omega0, drive=True, flywheel=flywheel, limits=limits,
        steady=steady, tolerance=tolerance, dense=dense,
    )  # fmt: skip
    if run.ending == "stopped":
        lead = "the drive does not start the machine" if steady is not None else None
        raise _stall(
            machine, float(run.phi[-1]), run.duration, flywheel,
            lead=lead or "the drive is too weak to reach steady running",
        )  # fmt: skip
    return run


def run_down(
    machine: ReducedMachine,
    omega0: float,
    *,
    phi0: float = 0.0,
    flywheel: float = 0.0,
    limits: Limits = DEFAULT_LIMITS,
    dense: bool = False,
) -> Run:
    """The machine running at ``omega0`` at ``phi0`` with the drive off, until it stops.

    With no load that takes energy (no friction, no working load) it never
    stops: the run then ends after ``limits.turns`` turns (``ending`` ``"turns"``).

    Raises
    ------
    DynamicsError
        No mass.
    IntegrationError
        A stiff or diverging run, or one beyond ``limits``' time.
    """
    return _time_run(
        machine, "run-down", phi0, omega0, drive=False, flywheel=flywheel, limits=limits,
        steady=None, tolerance=0.0, dense=dense,
    )  # fmt: skip


# ------------------------------------------------------------------ steady running
#: the steady running is found on the machine's poses each cut in this many parts (its
#: extremes and its time are taken there; it is given at the machine's poses)
_REFINE = 8


def _fine_poses(machine: ReducedMachine) -> tuple[np.ndarray, np.ndarray]:
    """The machine's poses each cut in :data:`_REFINE` parts, with the tables' corners; and where
    the machine's poses are among them."""
    phi = machine.properties.phi
    parts = np.arange(_REFINE) / _REFINE
    fine = (phi[:-1, None] + np.diff(phi)[:, None] * parts[None, :]).ravel()
    fine = np.unique(np.concatenate([fine, [phi[-1]], machine.breaks]))
    return fine, np.searchsorted(fine, phi)


def _summary(
    machine: ReducedMachine,
    fine: np.ndarray,
    omega: np.ndarray,
    times: np.ndarray,
    energy: float,
    flywheel: float,
    method: str,
) -> SteadyRunning:
    """The steady running from its speed and time on the fine poses."""
    at = np.searchsorted(fine, machine.properties.phi)
    period = float(times[-1])
    high, low = float(np.max(omega)), float(np.min(omega))
    mean = 0.5 * (high + low)
    time_mean = _TURN / period
    return SteadyRunning(
        machine.properties.phi, omega[at], times[at], period, high, low, mean, time_mean,
        (high - low) / mean, (high - low) / time_mean, energy, flywheel, method, fine, omega,
    )  # fmt: skip


def _trapezoid_times(phi: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """t(φ) = ∫ dφ/ω by trapezoids (the fine poses hold every corner of ω)."""
    slowness = 0.5 * (1 / omega[1:] + 1 / omega[:-1])
    return np.concatenate([[0.0], np.cumsum(np.diff(phi) * slowness)])


def _no_steady(machine: ReducedMachine, surplus: float, flywheel: float) -> NoSteadyRunningError:
    """The error of a turn whose work is not zero with M_r independent of ω."""
    mean = surplus / _TURN
    drive = machine.drive
    balance = (
        f"; a constant drive of {(drive.law.numbers[0] - mean):.6g} N·m balances the loads"
        if drive is not None and drive.law is not None and drive.law.kind == "value"
        else ""
    )
    if surplus > 0:
        return NoSteadyRunningError(
            f"no steady running: the drive does {surplus:.6g} J more work per turn than the "
            f"loads take ({mean:.6g} N·m on average): the machine speeds up without end{balance}"
        )
    return _stall(machine, None, None, flywheel, surplus)


def _stall(
    machine: ReducedMachine,
    phi: float | None,
    after: float | None,
    flywheel: float,
    surplus: float | None = None,
    lead: str = "the drive is too weak to reach steady running",
) -> StallError:
    """A drive too weak: where the machine stops and by how much its torque falls short."""
    props = machine.properties
    speed = 0.0
    drive_part = machine.moment(props.phi, speed, loads=False)
    load_part = machine.moment(props.phi, speed, drive=False)
    if surplus is None:
        surplus = float(machine.work(props.phi, speed)[-1])
    if phi is None:
        try:
            run = _time_run(
                machine, "start-up", 0.0, 0.0, drive=True, flywheel=flywheel,
                limits=Limits(turns=50, seconds=5.0), steady=None, tolerance=0.0,
            )  # fmt: skip
            if run.ending == "stopped":
                phi, after = float(run.phi[-1]), run.duration
        except (IntegrationError, DynamicsError):
            phi = None
    k = int(np.argmin(drive_part + load_part)) if phi is None else None
    where_phi = phi if phi is not None else float(props.phi[k])
    turn = math.degrees(where_phi) % 360
    here_drive = float(machine.moment(np.array([where_phi]), speed, loads=False)[0])
    here_load = float(machine.moment(np.array([where_phi]), speed, drive=False)[0])
    when = f" after {after:.4g} s" if after is not None else ""
    whole = int(where_phi // _TURN) if phi is not None else 0
    turns = f" (in turn {whole + 1})" if whole else ""
    mean_short = -min(surplus, 0.0) / _TURN
    short = max(-(here_drive + here_load), 0.0) + 0.0
    message = (
        f"{lead}: from rest the machine stops at "
        f"φ = {turn:.4g}°{turns}{when}, where the loads need {-here_load + 0.0:.6g} N·m "
        f"(reduced to the driver) and the drive gives {here_drive + 0.0:.6g} N·m at standstill, "
        f"short by {short:.6g} N·m"
        if phi is not None
        else lead
    )
    if mean_short > 0:
        message += (
            f"; over a turn its torque falls short of the loads' by {mean_short:.6g} N·m on average"
        )
    return StallError(message, where_phi, mean_short if mean_short > 0 else short)


def steady_running(
    machine: ReducedMachine,
    *,
    speed: float | None = None,
    flywheel: float = 0.0,
    limits: Limits = DEFAULT_LIMITS,
    guess: float | None = None,
) -> SteadyRunning:
    """The periodic motion of the machine over one turn, found directly.

    Parameters
    ----------
    machine : ReducedMachine
        J_r and M_r (its drive included).
    speed : float, optional
        The mean speed (ω_m = (ω_max + ω_min)/2, rad/s) where M_r does not
        depend on ω; default the driver's ``omega=``. Ignored where it does:
        the speed is then the drive's.
    flywheel : float
        A constant inertia added to J_r (kg·m²).
    guess : float, optional
        Where M_r depends on ω: a speed at φ = 0 near the answer (a nearby
        machine's), to start the search from.

    Raises
    ------
    NoSteadyRunningError
        The drive does more work per turn than the loads take (it runs away).
    StallError
        The drive is too weak (where the machine stops, and by how much).
    DynamicsError
        No mass; no mean speed for M_r without ω.
    IntegrationError
        A stiff or diverging turn.
    """
    _check_inertia(machine, flywheel)
    if machine.uses_omega:
        return _shooting(machine, flywheel, limits, guess)
    target = machine.nominal_speed if speed is None else speed
    if target is not None and target < 0:
        raise DynamicsError(
            f"the driver turns clockwise ({target:g} rad/s): the dynamics follows a "
            "counter-clockwise turn, φ increasing (give a positive speed, and mirror the sketch "
            "of a machine that runs the other way)"
        )
    if target is None or target <= 0 or not math.isfinite(target):
        raise DynamicsError(
            "the steady running of a machine whose moments do not depend on ω has any mean "
            "speed: give it (the driver's omega=, or --omega)"
        )
    phi, _ = _fine_poses(machine)
    inertia = machine.inertia(phi)[0] + flywheel
    work = machine.work(phi)
    scale = float(np.max(np.abs(work))) + 1e-12 * float(np.max(inertia)) * target**2
    if abs(work[-1]) > 1e-9 * max(scale, 1e-300):
        raise _no_steady(machine, float(work[-1]), flywheel)
    work = work - work[-1] * phi / _TURN  # the rounding of the turn's zero work, spread

    def mean_speed(energy: float) -> float:
        omega = np.sqrt(np.maximum(2 * (energy + work) / inertia, 0.0))
        return 0.5 * (float(np.max(omega)) + float(np.min(omega))) - target

    low = -float(np.min(work))
    if mean_speed(low) > 0:
        raise DynamicsError(
            f"the machine cannot turn at a mean speed of {target:.6g} rad/s: at that speed it "
            "stops within the turn (the loads take more than its kinetic energy); ask for a "
            "higher speed, or add a flywheel"
        )
    high = max(low, 0.0) + 0.5 * float(np.max(inertia)) * target**2 + 1.0
    while mean_speed(high) < 0:
        high *= 2
    energy0 = brentq(mean_speed, low, high, xtol=1e-14 * high, rtol=1e-15, maxiter=200)
    omega = np.sqrt(np.maximum(2 * (energy0 + work) / inertia, 0.0))
    if np.min(omega) <= 0:
        raise DynamicsError(
            f"the machine cannot turn at a mean speed of {target:.6g} rad/s: its speed falls "
            "to 0 within the turn; ask for a higher speed, or add a flywheel"
        )
    times = _trapezoid_times(phi, omega)
    return _summary(machine, phi, omega, times, float(energy0 + work[0]), flywheel, "energy")


def _balanced_speed(machine: ReducedMachine, flywheel: float) -> float:
    """The constant speed at which M_r does no work over a turn: the first guess of the mean.

    Raises
    ------
    StallError
        M_r does negative work over a turn even at standstill: the drive is too weak.
    """
    phi = machine.properties.phi

    def surplus(omega: float) -> float:
        return float(machine.work(phi, omega)[-1])

    at_rest = surplus(0.0)
    if at_rest <= 0:
        raise _stall(machine, None, None, flywheel, at_rest)
    drive = machine.drive
    high = max(machine.nominal_speed or 0.0, 1.0)
    if drive is not None and drive.law is not None and drive.law.kind == "motor":
        high = max(high, abs(drive.law.numbers[1]))
    for _ in range(80):
        if surplus(high) < 0:
            return brentq(surplus, 0.0, high, xtol=1e-12 * high, rtol=1e-12)
        high *= 2
    raise NoSteadyRunningError(
        "no steady running: the drive does more work per turn than the loads take at every "
        f"speed up to {high:.3g} rad/s: it runs away"
    )


def _secant(gap, guess: float) -> float | None:
    """The root of ``gap`` by secant steps from ``guess`` (a nearby machine's speed), or None."""
    a, b = guess, guess * (1 + 1e-4)
    fa, fb = gap(a), gap(b)
    for _ in range(12):
        if not (math.isfinite(fa) and math.isfinite(fb)) or fa == fb:
            return None
        a, b, fa = b, b - fb * (b - a) / (fb - fa), fb
        if not b > 0:
            return None
        fb = gap(b)
        if abs(b - a) <= 1e-11 * abs(b):
            return b if math.isfinite(fb) else None
    return None


def _bracket(machine: ReducedMachine, gap, guess: float | None) -> tuple[float, float]:
    """Speeds at φ = 0 below and above steady running: the turn speeds up, and slows down."""
    step = 0.05
    if guess is None:
        guess = _balanced_speed(machine, 0.0)
    else:
        step = 1e-3
    low = high = guess
    for _ in range(200):
        value = gap(high)
        if math.isfinite(value) and value < 0:
            break
        low = high if value > 0 else low
        high *= 1 + step
        step *= 1.5
    else:
        raise NoSteadyRunningError("no steady running: the machine speeds up at every speed tried")
    if low == high or not gap(low) > 0:
        low, step = high, 0.05
        for _ in range(200):
            low *= 1 - step
            step = min(step * 1.5, 0.5)
            value = gap(low)
            if value > 0:
                break
            if low < 1e-9 * high:
                raise _stall(machine, None, None, 0.0)
        else:
            raise _stall(machine, None, None, 0.0)
    return low, high


def _shooting(
    machine: ReducedMachine, flywheel: float, limits: Limits, guess: float | None
) -> SteadyRunning:
    """The speed at φ = 0 that comes back after one turn (M_r depends on ω)."""
    props = machine.properties
    fine, _ = _fine_poses(machine)
    budget = _Budget(limits, "steady running")
    inertia0 = float(props.inertia[0]) + flywheel

    def rhs(phi: float, y: np.ndarray, left: float) -> list[float]:
        budget.spend()
        # a hair inside the segment: a table's jump at its end is met from the left
        inside = left + (phi - left) * (1.0 - 2.0**-40)
        omega, moment = machine.at_energy(inside, y[0], flywheel)
        return [moment, 1.0 / omega if omega > 0 else 1e300]

    def empty(_phi: float, y: np.ndarray, _left: float) -> float:
        return y[0]

    empty.terminal = True  # type: ignore[attr-defined]
    empty.direction = -1  # type: ignore[attr-defined]

    inner = machine.breaks[(machine.breaks > 0) & (machine.breaks < _TURN)]
    edges = np.concatenate([[0.0], inner, [_TURN]])

    def turn(omega0: float, dense: bool = False) -> tuple[np.ndarray, bool]:
        """The energy and time at the poses (dense) or at the turn's end; whether it stopped."""
        y = np.array([0.5 * inertia0 * omega0 * omega0, 0.0])
        atol = [limits.rtol * 1e-2 * max(y[0], 1e-300), limits.rtol * 1e-2 * _TURN / omega0]
        kept = [y[:, None]] if dense else []
        for left, right in itertools.pairwise(edges):
            poses = fine[(fine > left) & (fine < right)] if dense else []
            sol = solve_ivp(
                rhs, (left, right), y, method=_SWITCHING, rtol=limits.rtol, atol=atol,
                events=[empty], t_eval=np.append(poses, right) if dense else None, args=(left,),
            )  # fmt: skip
            if sol.status == -1:
                raise IntegrationError(
                    f"a turn of steady running cannot be integrated: {sol.message}"
                )
            if sol.t_events[0].size:
                return y[:, None], True
            y = sol.y[:, -1]
            if dense:  # the poses inside, and the segment's end when it is a pose
                keep = np.isin(sol.t, fine)
                kept.append(sol.y[:, keep])
        return (np.hstack(kept) if dense else y[:, None]), False

    def gap(omega0: float) -> float:
        end, stopped = turn(omega0)
        if stopped:
            return -math.inf  # stops within the turn
        return math.sqrt(2 * max(float(end[0, -1]), 0.0) / inertia0) - omega0

    start = guess if guess is not None else _balanced_speed(machine, 0.0)
    omega0 = _secant(gap, start)
    if omega0 is None:
        low, high = _bracket(machine, gap, guess)
        omega0 = brentq(gap, low, high, xtol=1e-11 * high, rtol=1e-12, maxiter=200)
    states, _ = turn(omega0, dense=True)
    energy, times = states
    omega = np.sqrt(2 * np.maximum(energy, 0.0) / (machine.inertia(fine)[0] + flywheel))
    return _summary(machine, fine, omega, times, float(energy[0]), flywheel, "shooting")
