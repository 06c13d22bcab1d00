"""Every answer of a machine's dynamics at once, each part with the reason when it is left out.

:func:`machine_dynamics` is what ``assur dynamics``, the report page and the
worked solution read: the machine reduced to its driver; the driver's inertia
torque at the file's ω and ε; the steady running; the flywheel for a
coefficient of speed fluctuation; the start-up from rest and the run-down
with the drive off; the shaking force and moment at the running speed. A part
that does not apply (no mass data, no drive, no mean speed, no coordinates)
is ``None`` and a note says why, in one line; a machine that cannot run (its
drive too weak or too strong, a run that diverges) is an error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from structure.cycle import Law
from structure.report import StructuralReport

from ..errors import DynamicsError, StallError
from .flywheel import Flywheel, flywheel
from .loads import FROM_FILE
from .machine import ReducedMachine, reduced_machine
from .motion import SLOWED, Limits, Run, SteadyRunning, run_down, start_up, steady_running
from .shaking import Shaking, shaking

__all__ = ["MachineDynamics", "dynamics_to_dict", "machine_dynamics"]

#: the longest start-up and run-down integrated (turns)
RUN_TURNS = 200
#: a start-up ends within this fraction of the steady running's mean speed
STEADY_WITHIN = 1e-3
#: the runs in time are summed up by their durations and turns: a looser tolerance than the
#: steady running's does for them
RUN_TOLERANCE = 1e-8


@dataclass(frozen=True)
class MachineDynamics:
    """The dynamics of one machine (see :func:`machine_dynamics`).

    ``speed`` is the running speed the shaking is taken at (the steady mean, or
    the driver's ``omega=``); ``moment_speed`` the speed at each pose the
    reduced moment is shown at (the steady running's, else ``speed``, else 0).
    ``inertia_torque`` is ``(ω, ε, M)`` at the file's driver motion.
    """

    report: StructuralReport
    machine: ReducedMachine
    delta_goal: float
    speed: float | None
    moment_speed: np.ndarray
    inertia_torque: tuple[float, float, np.ndarray] | None
    steady: SteadyRunning | None
    flywheel: Flywheel | None
    start: Run | None
    stop: Run | None
    shaking: Shaking | None
    notes: tuple[str, ...]

    @property
    def moment(self) -> np.ndarray:
        """M_r at the machine's poses, the drive included, at :attr:`moment_speed`."""
        return self.machine.moment(self.machine.properties.phi, self.moment_speed)

    @property
    def drive_moment(self) -> np.ndarray:
        return self.machine.moment(self.machine.properties.phi, self.moment_speed, loads=False)

    @property
    def drive_power(self) -> float | None:
        """The drive's mean power in steady running: its work over a turn / the turn's time (W)."""
        if self.steady is None or self.machine.drive is None:
            return None
        steady = self.steady
        work = self.machine.work(steady.fine_phi, steady.fine_omega, loads=False)
        return float(work[-1]) / steady.period

    @property
    def load_moment(self) -> np.ndarray:
        return self.machine.moment(self.machine.properties.phi, self.moment_speed, drive=False)


def _driver_motion(report: StructuralReport) -> tuple[float | None, float | None]:
    values = {d.link: dict(d.motion) for d in report.mechanism.drivers}.get(report.drivers[0], {})
    return values.get("omega"), values.get("epsilon")


def machine_dynamics(
    report: StructuralReport,
    *,
    drive: Law | str | None = FROM_FILE,
    delta: float = 0.02,
    speed: float | None = None,
    steps: int = 360,
    runs: bool = True,
) -> MachineDynamics:
    """The whole dynamics of ``report``'s machine.

    Parameters
    ----------
    report : StructuralReport
        W = 1, a turning driver, masses (``mass``), loads over the cycle.
    drive : Law, None or FROM_FILE
        The drive: the file's (default), another (``--drive``) or none.
    delta : float
        The coefficient of speed fluctuation the flywheel is for.
    speed : float, optional
        The mean speed where the moments do not depend on ω (default the
        driver's ``omega=``).
    steps : int
        Poses per turn to start from (see :func:`~kinematics.dynamics.machine.reduced_machine`).
    runs : bool
        Whether to integrate the start-up and the run-down in time.

    Raises
    ------
    MobilityError, DynamicsError, MechanismError
        The machine cannot be reduced (W ≠ 1, no whole turn, ...), or cannot run
        (:class:`~kinematics.errors.StallError`, :class:`~kinematics.errors.NoSteadyRunningError`,
        :class:`~kinematics.errors.IntegrationError`).
    """
    machine = reduced_machine(report, drive=drive, steps=steps)
    notes: list[str] = []
    props = machine.properties
    if props.massless:
        links = ", ".join(props.massless)
        notes.append(f"link(s) {links} have no 'mass' line: they count as massless")
    has_mass = machine.has_inertia
    if not np.any(props.inertia > 0):
        given = any(x.kind == "mass" for x in report.mechanism.loads)
        why = (
            "the masses given stand still or sit on the axes they turn about"
            if given
            else "no mass data: every link is massless"
        )
        notes.append(
            f"{why}, so the reduced inertia is 0 and the machine's motion is not defined "
            "(give 'mass LINK m J S' lines)"
        )
    elif not has_mass:
        where = math.degrees(float(props.phi[np.argmin(props.inertia)]))
        notes.append(
            f"the reduced inertia vanishes at φ = {where:.4g}°: the motion is not defined "
            "there (give the driver a moment of inertia)"
        )
    if machine.assumed_drive is not None:
        notes.append(
            f"no drive in the file: a constant torque equal to the loads' mean, "
            f"{machine.assumed_drive:.6g} N·m, drives it (a 'drive' line or --drive sets another)"
        )
    omega, epsilon = _driver_motion(report)
    torque = None
    if omega is not None or epsilon is not None:
        w, e = omega or 0.0, epsilon or 0.0
        torque = (w, e, machine.inertia_torque(w, e))
    steady = wheel = start = stop = None
    if has_mass:
        steady = _steady(machine, speed, notes)
    if steady is not None:
        wheel = flywheel(machine, delta, speed=steady.omega_mean, steady=steady)
    if steady is not None and runs:
        start, stop = _runs(machine, steady, notes)
    running = steady.omega_mean if steady is not None else (speed or machine.nominal_speed)
    shaken = None
    if running and props.motion is not None and np.any(props.inertia > 0):
        shaken = shaking(props, report.mechanism, running)
    elif props.motion is None:
        notes.append("the shaking forces need the mechanism's coordinates (a sketch)")
    elif np.any(props.inertia > 0):
        notes.append("the shaking forces need a running speed (the driver's omega=, or --omega)")
    if steady is not None:
        moment_speed = steady.omega_at(props.phi)
    else:
        moment_speed = np.full(len(props.phi), float(running or 0.0))
    return MachineDynamics(
        report, machine, delta, running, moment_speed, torque, steady, wheel, start, stop,
        shaken, tuple(notes),
    )  # fmt: skip


def _steady(machine: ReducedMachine, speed: float | None, notes: list[str]) -> SteadyRunning | None:
    """The steady running, or None with the note why (no drive and no speed)."""
    if not machine.uses_omega and not (speed or machine.nominal_speed):
        notes.append(
            "the steady running needs the mean speed (the driver's omega=, or --omega): "
            "the moments do not depend on ω, so any speed would do"
        )
        return None
    if machine.drive is None and not machine.terms:
        notes.append("no drive and no load: the machine runs freely, its kinetic energy kept")
    return steady_running(machine, speed=speed)


def _runs(
    machine: ReducedMachine, steady: SteadyRunning, notes: list[str]
) -> tuple[Run | None, Run | None]:
    """The start-up from rest (with a drive) and the run-down from steady running."""
    limits = Limits(turns=RUN_TURNS, rtol=RUN_TOLERANCE)
    start = None
    if machine.drive is not None:
        try:
            start = start_up(machine, steady=steady, tolerance=STEADY_WITHIN, limits=limits)
        except StallError as exc:  # it runs steadily, but does not start from rest by itself
            notes.append(f"{exc}; once started, it runs steadily")
            start = None
        if start is not None and start.ending != "steady":
            notes.append(
                f"the start-up has not come within {STEADY_WITHIN:.1%} of steady running "
                f"after {RUN_TURNS} turns ({start.duration:.4g} s)"
            )
    else:
        notes.append("no drive: no start-up")
    omega0 = float(steady.omega[0])
    energy = 0.5 * (float(machine.properties.inertia[0]) + steady.flywheel) * omega0**2
    phi = machine.properties.phi
    lost = machine.work(phi, steady.omega_at(phi), drive=False)
    if lost[-1] >= -1e-9 * energy and np.min(energy + lost) > 0:
        notes.append("with the drive off nothing takes the machine's energy: it never stops")
        return start, None
    try:
        stop = run_down(machine, omega0, limits=limits)
    except DynamicsError as exc:  # a run-down that cannot be integrated is said, not fatal
        notes.append(f"the run-down: {exc}")
        return start, None
    if stop.ending == "slowed":
        notes.append(
            f"the run-down slows below {SLOWED:.1%} of its speed after {stop.duration:.4g} s "
            "without quite stopping (its load falls with the speed)"
        )
    elif stop.ending != "stopped":
        turns = energy / max(-lost[-1], 1e-300)
        notes.append(
            f"the run-down has not stopped after {RUN_TURNS} turns ({stop.duration:.4g} s); "
            f"the loads take {-lost[-1]:.6g} J a turn of its {energy:.6g} J at full speed"
            f" (about {turns:.3g} turns)"
        )
    return start, stop


def _list(values: np.ndarray) -> list[float]:
    return [float(v) for v in np.asarray(values, dtype=float)]


def _run_dict(run: Run | None) -> dict | None:
    if run is None:
        return None
    return {
        "ending": run.ending,
        "time": run.duration,
        "turns": len(run.turns),
        "turn_times": _list(run.turns),
        "t": _list(run.t),
        "phi_deg": _list(np.degrees(run.phi)),
        "omega": _list(run.omega),
    }


def _mean(result: MachineDynamics, drive: bool) -> float:
    """The mean over the turn of the drive's or the loads' part of M_r (their work / 2π)."""
    phi = result.machine.properties.phi
    work = result.machine.work(phi, result.moment_speed, drive=drive, loads=not drive)
    return float(work[-1]) / (2 * math.pi)


def dynamics_to_dict(result: MachineDynamics) -> dict:
    """The answers as plain data (the keys of ``assur dynamics --json``)."""
    machine = result.machine
    props = machine.properties
    phi_deg = _list(np.degrees(props.phi))
    out: dict = {
        "name": result.report.mechanism.name,
        "source": result.report.mechanism.source,
        "driver": machine.driver,
        "massless": list(props.massless),
        "notes": list(result.notes),
        "reduced_inertia": {
            "phi_deg": phi_deg,
            "J": _list(props.inertia),
            "dJ": _list(props.slope),
            "shares": {link: _list(v) for link, v in props.shares.items()},
            "min": float(np.min(props.inertia)),
            "max": float(np.max(props.inertia)),
            "mean": float(np.mean(props.inertia[:-1])),
        },
        "reduced_moment": {
            "phi_deg": phi_deg,
            "M": _list(result.moment),
            "M_drive": _list(result.drive_moment),
            "M_loads": _list(result.load_moment),
            "omega": _list(result.moment_speed),
            "terms": [
                {"load": t.label, "law": t.law.token if t.law is not None else None}
                for t in machine.terms
            ],
            "assumed_drive": machine.assumed_drive,
            "mean_drive": _mean(result, drive=True),
            "mean_loads": _mean(result, drive=False),
        },
        "inertia_torque": None,
        "steady": None,
        "flywheel": None,
        "start_up": _run_dict(result.start),
        "run_down": _run_dict(result.stop),
        "shaking": None,
    }
    if result.inertia_torque is not None:
        omega, epsilon, torque = result.inertia_torque
        out["inertia_torque"] = {"omega": omega, "epsilon": epsilon, "M": _list(torque)}
    steady = result.steady
    if steady is not None:
        out["steady"] = {
            "phi_deg": phi_deg,
            "omega": _list(steady.omega),
            "t": _list(steady.t),
            "omega_mean": steady.omega_mean,
            "mean": "(omega_max + omega_min)/2",
            "omega_max": steady.omega_max,
            "omega_min": steady.omega_min,
            "omega_time_mean": steady.omega_time_mean,
            "delta": steady.delta,
            "delta_time_mean": steady.delta_time_mean,
            "period": steady.period,
            "method": steady.method,
            "power": result.drive_power,
        }
    wheel = result.flywheel
    if wheel is not None:
        out["flywheel"] = {
            "delta_goal": wheel.delta_goal,
            "omega_mean": wheel.omega_mean,
            "J_exact": wheel.exact,
            "J_approx": wheel.approximate,
            "J_approx_less_mean": wheel.approximate_less_mean,
            "energy_swing": wheel.energy_swing,
            "needed": wheel.needed,
            "delta_check": wheel.steady.delta if wheel.steady is not None else None,
            "diagram": {"J": _list(wheel.inertia), "dE": _list(wheel.work)},
        }
    shaken = result.shaking
    if shaken is not None:
        out["shaking"] = {
            "omega": shaken.omega,
            "about": {"point": shaken.about_name, "xy": list(shaken.about)},
            "force_max": shaken.force_max,
            "moment_max": shaken.moment_max,
            "phi_deg": _list(np.degrees(shaken.phi)),
            "fx": _list(shaken.force[:, 0]),
            "fy": _list(shaken.force[:, 1]),
            "m": _list(shaken.moment),
        }
    return out
