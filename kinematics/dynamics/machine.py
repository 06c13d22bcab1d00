"""The machine reduced to its driver: J_r(φ), dJ_r/dφ and M_r(φ, ω) anywhere in the turn.

:func:`reduced_machine` solves the kinematics once over a turn of the driver
at unit speed (:func:`~kinematics.dynamics.reduced.reduced_properties`), takes
the loads over the same poses (:func:`~kinematics.dynamics.loads.load_terms`)
and interpolates the smooth parts, J_r and each load's velocity ratio, by
their trigonometric series (:class:`~kinematics.dynamics.series.PeriodicSeries`);
the laws (a table, a motor curve, a formula) are evaluated exactly. The
series' slope of J_r is checked against the exact one from the accelerations,
and the poses are doubled until they agree. A gear train without coordinates
has constant ratios, from its Willis relations (:mod:`kinematics.gears.trains`).

>>> from structure import analyze, parse_edgelist
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "point A 0 0", "point S 0.2 0",
...                     "mass 1 2 0.01 S", "drive 1 motor=4,20", "cycle moment 1 -1"])
>>> machine = reduced_machine(analyze(m))
>>> J, dJ, M = machine.at(0.0, 10.0)
>>> round(J, 12), round(dJ, 12), round(M, 12)    # 0.01 + 2·0.2²; 4·(1 − 10/20) − 1
(0.09, 0.0, 1.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from structure.cycle import Law, LawKind
from structure.errors import EdgeListError, MechanismError, MobilityError
from structure.meshes import meshes
from structure.model import PairKind
from structure.report import StructuralReport

from ..errors import DynamicsError
from ..solvers.plan import make_plan
from .loads import FROM_FILE, LoadTerm, law_value, law_values, load_terms, table_breaks
from .reduced import ReducedProperties, massless_links, reduced_properties
from .series import PeriodicSeries

__all__ = ["ReducedMachine", "reduced_machine"]

_TURN = 2 * math.pi
#: the series' slope of J_r agrees with the exact slope to this, relative to J_r's size
SERIES_TOLERANCE = 1e-9
#: the most poses per turn the series is made of (doubled from the asked number until it fits)
MAX_POSES = 5760
#: Gauss–Legendre nodes and weights on [0, 1], for the work of the loads between poses
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(6)
_NODES, _WEIGHTS = (_NODES + 1) / 2, _WEIGHTS / 2


@dataclass(frozen=True)
class ReducedMachine:
    """A one-degree-of-freedom machine reduced to its driver, over one turn.

    Attributes
    ----------
    name, source : str
        The mechanism's name and file.
    properties : ReducedProperties
        J_r and its exact slope at the poses of one turn, both ends included
        (``phi`` from 0 to 2π), and the kinematics at unit driver speed.
    terms : tuple of LoadTerm
        The parts of M_r over the same poses; the drive's is marked ``drive``.
    series : PeriodicSeries
        Row 0 J_r, row k + 1 the ratio of ``terms[k]``: read anywhere in the turn.
    nominal_speed : float or None
        The driver's ω in the file (``driver L omega=``), rad/s.
    assumed_drive : float or None
        With no drive given, the constant torque assumed, equal to the loads'
        mean (N·m); None when the drive is given (or none is asked for).
    accuracy : float
        How far the series' slope of J_r is from the exact one, relative to J_r.
    """

    name: str
    source: str
    properties: ReducedProperties
    terms: tuple[LoadTerm, ...]
    series: PeriodicSeries
    nominal_speed: float | None
    assumed_drive: float | None
    accuracy: float

    @property
    def driver(self) -> str:
        return self.properties.driver

    @property
    def massless(self) -> tuple[str, ...]:
        """The moving links without a ``mass`` statement."""
        return self.properties.massless

    @property
    def has_inertia(self) -> bool:
        """Whether J_r is positive over the whole turn (the equation of motion needs it)."""
        return bool(np.min(self.properties.inertia) > 0)

    @property
    def drive(self) -> LoadTerm | None:
        return next((t for t in self.terms if t.drive), None)

    @property
    def uses_omega(self) -> bool:
        """Whether M_r depends on ω (a motor curve, a formula of ``omega``)."""
        return any(t.law is not None and t.law.uses_omega for t in self.terms)

    @property
    def breaks(self) -> np.ndarray:
        """The angles of the turn where a table's slope changes or it jumps (rad, sorted)."""
        found = [table_breaks(t.law) for t in self.terms]
        return np.unique(np.concatenate([np.zeros(0), *found]))

    def at(self, phi: float, omega: float, drive: bool = True) -> tuple[float, float, float]:
        """``(J_r, dJ_r/dφ, M_r)`` at one angle (rad from the sketch) and speed (rad/s).

        The slope is the series' own (see :mod:`~kinematics.dynamics.series`);
        ``drive`` false leaves the drive out (a machine running down).
        """
        values, slopes = self.series.at(phi)
        moment = 0.0
        for k, term in enumerate(self.terms):
            if term.drive and not drive:
                continue
            ratio = values[k + 1]
            moment += ratio if term.law is None else law_value(term.law, phi, omega) * ratio
        return float(values[0]), float(slopes[0]), float(moment)

    def at_energy(self, phi: float, energy: float, flywheel: float = 0.0) -> tuple[float, float]:
        """ω = √(2E/J) and M_r(φ, ω) at one angle, for a kinetic energy E (the energy form)."""
        values, _ = self.series.at(phi)
        omega = math.sqrt(max(2.0 * energy / (values[0] + flywheel), 0.0))
        moment = 0.0
        for k, term in enumerate(self.terms):
            ratio = values[k + 1]
            moment += ratio if term.law is None else law_value(term.law, phi, omega) * ratio
        return omega, float(moment)

    def inertia(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """J_r and its slope (the series') at many angles."""
        values, slopes = self.series.over(phi)
        return values[0], slopes[0]

    def moment(
        self, phi: np.ndarray, omega: np.ndarray | float, *, drive: bool = True, loads: bool = True
    ) -> np.ndarray:
        """M_r at many angles and speeds: the drive's part, the loads' part, or both."""
        phi = np.asarray(phi, dtype=float).reshape(-1)
        values, _ = self.series.over(phi)
        total = np.zeros(len(phi))
        for k, term in enumerate(self.terms):
            if (term.drive and not drive) or (not term.drive and not loads):
                continue
            law = 1.0 if term.law is None else law_values(term.law, phi, omega)
            total = total + law * values[k + 1]
        if not np.all(np.isfinite(total)):
            bad = float(phi[~np.isfinite(total)][0])
            raise DynamicsError(
                f"the reduced moment is not finite at φ = {math.degrees(bad) % 360:.6g}°: "
                "a formula divides by zero or takes the root or logarithm of a negative number"
            )
        return total

    def work(
        self,
        phi: np.ndarray,
        omega: np.ndarray | float = 0.0,
        *,
        drive: bool = True,
        loads: bool = True,
    ) -> np.ndarray:
        """The work of M_r from ``phi[0]`` to each of ``phi`` (increasing), J.

        ``omega`` is the speed at each of ``phi`` (linear between them) or one
        number. The integral is taken by Gauss–Legendre between the machine's
        poses and a table's corners, so a table's corners and jumps cost no accuracy.
        """
        phi = np.asarray(phi, dtype=float).reshape(-1)
        omega_at = np.broadcast_to(np.asarray(omega, dtype=float), phi.shape)
        first = np.floor(phi[0] / _TURN)
        turns = np.arange(first - 1, np.floor(phi[-1] / _TURN) + 2)[:, None] * _TURN
        # the machine's poses and the tables' corners, in every turn the angles reach
        poses = self.properties.phi[None, :-1]
        extra = np.concatenate([(self.breaks[None, :] + turns).ravel(), (poses + turns).ravel()])
        inside = extra[(extra > phi[0]) & (extra < phi[-1])]
        edges = np.unique(np.concatenate([phi, inside]))
        left, width = edges[:-1], np.diff(edges)
        nodes = left[:, None] + width[:, None] * _NODES[None, :]
        speeds = np.interp(nodes.ravel(), phi, omega_at)
        m = self.moment(nodes.ravel(), speeds, drive=drive, loads=loads).reshape(nodes.shape)
        pieces = np.concatenate([[0.0], np.cumsum((m @ _WEIGHTS) * width)])
        return pieces[np.searchsorted(edges, phi)]

    def inertia_torque(self, omega: float, epsilon: float) -> np.ndarray:
        """The links' inertia reduced to the driver, −(J_r·ε + ½·J_r'·ω²), at its poses (N·m).

        At the driver's prescribed motion (ω, ε) it is the torque the inertia
        of the links opposes to the driver; the drive supplies its opposite.
        """
        props = self.properties
        return -(props.inertia * epsilon + 0.5 * props.slope * omega * omega)


def _poses(steps: int) -> np.ndarray:
    """One turn in ``steps`` equal steps, both ends included."""
    return np.linspace(0.0, _TURN, steps + 1)


def _train_properties(report: StructuralReport, steps: int) -> tuple[ReducedProperties, dict]:
    """A gear train without coordinates: constant ratios, J_r = Σ J·(ω/ω_in)² (+ planets)."""
    # sympy's exact Willis ratios: imported only for a gear train without coordinates
    from ..gears.trains import reduced_inertia, speed_ratios

    m = report.mechanism
    ratios = speed_ratios(m, report.drivers)
    inertia = float(reduced_inertia(m, ratios))
    floats = {link: float(r) for link, r in ratios.ratios.items()}
    floats.setdefault(report.drivers[0], 1.0)
    phi = _poses(steps)
    shares: dict[str, np.ndarray] = {}
    for load in m.loads:
        if load.kind == "mass" and load.link in floats:
            share = load.values[1] * floats[load.link] ** 2
            shares[load.link] = shares.get(load.link, 0.0) + np.full(len(phi), share)
    props = ReducedProperties(
        phi,
        np.full(len(phi), inertia),
        np.zeros(len(phi)),
        shares,
        report.drivers[0],
        False,
        massless_links(m),
        None,  # type: ignore[arg-type]
    )
    return props, floats


def _is_train(report: StructuralReport) -> bool:
    """A gear train whose every higher pair is a mesh with tooth numbers (ratios constant)."""
    m = report.mechanism
    higher = [p for p in m.pairs if p.kind is PairKind.H]
    try:
        found = meshes(m)
    except MechanismError:
        return False
    return bool(higher) and len(found) == len(higher)


def _check_one_driver(report: StructuralReport) -> None:
    if report.mobility.W != 1 or len(report.drivers) != 1:
        drivers = ", ".join(report.drivers) or "none"
        raise MobilityError(
            f"the machine's dynamics is that of one degree of freedom: this mechanism has "
            f"W = {report.mobility.W} (drivers {drivers})",
            report.mobility,
        )


def reduced_machine(
    report: StructuralReport,
    *,
    drive: Law | str | None = FROM_FILE,
    steps: int = 360,
) -> ReducedMachine:
    """The machine of ``report`` reduced to its driver over one turn.

    Parameters
    ----------
    report : StructuralReport
        A mechanism with W = 1 and one turning driver; coordinates, or a gear
        train whose meshes have tooth numbers.
    drive : Law, None or FROM_FILE
        The drive: the file's (default), another law (``--drive``), or none.
        With no drive in the file (and none given) a constant torque equal to
        the loads' mean over the turn is assumed, so that the machine can run
        steadily; :attr:`ReducedMachine.assumed_drive` says so.
    steps : int
        Poses per turn to start from; doubled (up to :data:`MAX_POSES`) until
        the series of J_r agrees with its exact slope.

    Raises
    ------
    MobilityError
        W ≠ 1.
    DynamicsError
        A sliding driver, a mechanism that does not repeat after one turn, a
        load that cannot act (see :func:`~kinematics.dynamics.loads.load_terms`).
    MechanismError
        The kinematics cannot turn the driver through a whole turn (named).
    """
    _check_one_driver(report)
    m = report.mechanism
    ratios = None
    try:
        plan = make_plan(report)
    except EdgeListError:
        if not _is_train(report):
            raise
        plan = None
    if plan is not None and plan.drivers[0].kind == "P":
        raise DynamicsError(
            f"driver {plan.drivers[0].link} slides: the dynamics over a cycle needs a driver "
            "that turns (a crank)"
        )
    steps = max(int(steps), 16)
    while True:
        if plan is None:
            props, ratios = _train_properties(report, steps)
        else:
            props = reduced_properties(plan, _poses(steps))
        terms = load_terms(m, props, drive, ratios)
        series, accuracy = _series(props, terms)
        if accuracy <= SERIES_TOLERANCE or steps * 2 > MAX_POSES:
            break
        steps *= 2
    _check_periodic(props, terms)
    speed = _nominal_speed(report, plan)
    machine = ReducedMachine(m.name, m.source, props, tuple(terms), series, speed, None, accuracy)
    if drive == FROM_FILE and machine.drive is None and terms:
        machine = _with_assumed_drive(machine)
    return machine


def _series(props: ReducedProperties, terms: list[LoadTerm]) -> tuple[PeriodicSeries, float]:
    """The series of J_r and the terms' ratios, and how well it gives J_r's slope."""
    rows = np.vstack([props.inertia[:-1], *(t.ratio[:-1] for t in terms)])
    series = PeriodicSeries.from_samples(rows)
    _, slopes = series.over(props.phi[:-1])
    scale = float(np.max(np.abs(props.inertia))) or 1.0
    accuracy = float(np.max(np.abs(slopes[0] - props.slope[:-1]))) / scale
    return series, accuracy


def _check_periodic(props: ReducedProperties, terms: list[LoadTerm]) -> None:
    """J_r and every load's ratio are the same after one turn: the motion repeats."""
    for name, values in [("J_r", props.inertia), *((t.label, t.ratio) for t in terms)]:
        scale = float(np.max(np.abs(values))) or 1.0
        if abs(values[-1] - values[0]) > 1e-7 * scale:
            raise DynamicsError(
                f"the mechanism does not repeat after one turn of driver {props.driver} "
                f"({name} differs): its cycle is longer than one turn"
            )


def _nominal_speed(report: StructuralReport, plan) -> float | None:
    if plan is not None:
        d = plan.drivers[0]
        return float(d.speed) if d.speed_given else None
    motion = {d.link: dict(d.motion) for d in report.mechanism.drivers}
    value = motion.get(report.drivers[0], {}).get("omega")
    return None if value is None else float(value)


def _with_assumed_drive(machine: ReducedMachine) -> ReducedMachine:
    """The machine with a constant drive equal to the loads' mean over the turn."""
    phi = machine.properties.phi
    speed = machine.nominal_speed if machine.nominal_speed is not None else 0.0
    if machine.uses_omega and machine.nominal_speed is None:
        raise DynamicsError(
            "the loads depend on ω and there is no drive: give the drive (a 'drive' line or "
            "--drive) or the driver's speed (omega=)"
        )
    work = machine.work(phi, speed)
    mean = -float(work[-1]) / _TURN
    if abs(mean) * _TURN <= 1e-12 * float(np.max(np.abs(work))):
        mean = 0.0  # the loads do no work over a turn: the rest is rounding
    law = Law(LawKind.CONSTANT, (mean,))
    label = f"drive on {machine.driver}"
    term = LoadTerm(label, law, np.ones(len(phi)), True, 0, "drive", machine.driver)
    terms = (*machine.terms, term)
    series, _ = _series(machine.properties, list(terms))
    return ReducedMachine(
        machine.name,
        machine.source,
        machine.properties,
        terms,
        series,
        machine.nominal_speed,
        mean,
        machine.accuracy,
    )
