"""Gear trains: Willis relations, exact speed ratios, reduced inertia, forces and losses.

The meshes and their carriers come from :mod:`structure.meshes` (``Mesh`` and
``meshes`` stay importable from here). Each mesh gives one Willis relation in
the carrier's frame,

    z_a·(ω_a − ω_c) = ∓ z_b·(ω_b − ω_c)   (− external, + internal teeth),

and the linear system of all meshes is solved exactly (sympy rationals) for
every link's speed relative to the input(s). The train's DOF is the number of
link speeds minus the rank of the relations. An unknown tooth number
(``z=25,?``) is found from coaxiality: every planet's meshes with gears on
the carrier's axis span the same centre distance.

>>> from structure import parse_edgelist
>>> m = parse_edgelist(["driver 3", "0 c R O", "0 3 R O", "c 2 R P",
...                     "2 0 H gear z=20,60", "2 3 H gear z=25,? internal=3"])
>>> r = speed_ratios(m)
>>> r.teeth_found, r.ratios["c"], r.dof
({(5, 2): 105}, 7/12, 1)
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import sympy

from structure.errors import MechanismError, MobilityError, NumberError
from structure.meshes import Mesh, is_planet, meshes
from structure.model import Mechanism

# Mesh and meshes (the topology of the meshes) are defined in structure.meshes; they stay
# importable from here
__all__ = [
    "Mesh",
    "TrainForces",
    "TrainLosses",
    "TrainRatios",
    "balancing_moment",
    "meshes",
    "reduced_inertia",
    "speed_ratios",
    "train_forces",
    "train_losses",
]


@dataclass(frozen=True)
class TrainRatios:
    """Every train link's angular velocity relative to the input(s), exact.

    ``ratios[link]`` is ω_link/ω_input (one input) or an expression in the
    input speeds ``omega_<link>``; ``teeth_found`` maps (pair id, side 1 or 2)
    to tooth numbers solved from coaxiality.
    """

    inputs: tuple[str, ...]
    ratios: Mapping[str, sympy.Expr]
    dof: int
    meshes: tuple[Mesh, ...]
    teeth_found: Mapping[tuple[int, int], int]


def _coaxial_teeth(mechanism: Mechanism, found: list[Mesh]) -> dict[tuple[int, int], int]:
    """Unknown tooth numbers from equal centre distances of each planet's meshes."""
    solved: dict[tuple[int, int], int] = {}
    by_planet: dict[tuple[str, str], list[Mesh]] = {}
    for mesh in found:
        for planet in (mesh.a, mesh.b):
            if planet != mesh.carrier and is_planet(mechanism, planet, mesh.carrier):
                by_planet.setdefault((planet, mesh.carrier), []).append(mesh)
    for (planet, _), group in by_planet.items():
        symbols = {}
        spans = []
        for mesh in group:
            z_planet = mesh.za if mesh.a == planet else mesh.zb
            z_other = mesh.zb if mesh.a == planet else mesh.za
            zp = sympy.Integer(z_planet) if z_planet is not None else None
            zo = sympy.Integer(z_other) if z_other is not None else None
            if zp is None and zo is None:
                raise MechanismError(
                    f"mesh {mesh.pair.label} gives neither tooth number: coaxiality can find "
                    "one unknown z per planet, not both of a mesh"
                )
            if zp is None or zo is None:
                # side 1 is the tooth number of a, side 2 of b
                missing_a = (zp is None) == (mesh.a == planet)
                key = (mesh.pair.id, 1 if missing_a else 2)
                symbols[key] = sympy.Symbol(f"z_{mesh.pair.id}_{key[1]}")
                if zp is None:
                    zp = symbols[key]
                else:
                    zo = symbols[key]
            # an internal gear around the planet: distance (z_ring − z_planet)
            spans.append(zo - zp if mesh.internal else zo + zp)
        if not symbols:
            continue
        if len(symbols) != 1 or len(spans) < 2:
            raise MechanismError(
                "coaxiality gives one equation per planet: "
                f"cannot find {len(symbols)} tooth numbers from it"
            )
        ((key, symbol),) = symbols.items()
        known = [s for s in spans if not s.has(symbol)]
        unknown = [s for s in spans if s.has(symbol)]
        value = sympy.solve(sympy.Eq(unknown[0], known[0]), symbol)
        if len(value) != 1 or not value[0].is_integer or value[0] <= 0:
            raise MechanismError(f"coaxiality gives no positive whole tooth number ({value})")
        solved[key] = int(value[0])
    return solved


def speed_ratios(mechanism: Mechanism, inputs: Sequence[str] | None = None) -> TrainRatios:
    """Exact speed of every train link relative to the input link(s).

    ``inputs`` default to the mechanism's drivers. With one input the ratios
    are numbers; with several they are expressions in ``omega_<link>``.

    Raises
    ------
    MobilityError
        The train's DOF differs from the number of inputs (e.g. a differential
        with one input: it asks for a second one).
    MechanismError
        A mesh without tooth numbers or carrier.
    """
    found = list(meshes(mechanism))
    if not found:
        raise MechanismError(f"{mechanism.source}: no gear mesh (write 'a b H gear z=za,zb')")
    teeth_found = _coaxial_teeth(mechanism, found)
    inputs = tuple(mechanism.driver_links if inputs is None else inputs)
    ground = mechanism.ground
    links = sorted(
        {x for mesh in found for x in (mesh.a, mesh.b, mesh.carrier)} - {ground},
        key=mechanism.links.index,
    )
    omega = {x: sympy.Symbol(f"w_{x}") for x in links}
    omega[ground] = sympy.Integer(0)
    equations = []
    for mesh in found:
        za = mesh.za if mesh.za is not None else teeth_found.get((mesh.pair.id, 1))
        zb = mesh.zb if mesh.zb is not None else teeth_found.get((mesh.pair.id, 2))
        if za is None or zb is None:
            raise MechanismError(
                f"{mechanism.source}: line {mesh.pair.line_no}: the gear mesh {mesh.pair.label} "
                "needs tooth numbers z=za,zb"
            )
        wc = omega[mesh.carrier]
        sign = 1 if mesh.internal else -1
        equations.append(za * (omega[mesh.a] - wc) - sign * zb * (omega[mesh.b] - wc))
    unknowns = [omega[x] for x in links]
    matrix, _ = sympy.linear_eq_to_matrix(equations, unknowns)
    dof = len(unknowns) - matrix.rank()
    if dof != len(inputs):
        raise MobilityError(
            f"the gear train has {dof} degree(s) of freedom but {len(inputs)} input(s) "
            f"({', '.join(inputs) or 'none'}): "
            + ("give another input (a driver line)" if dof > len(inputs) else "name fewer inputs")
        )
    speeds = {x: sympy.Symbol(f"omega_{x}") for x in inputs}
    system = equations + [omega[x] - speeds[x] for x in inputs]
    solution = sympy.solve(system, unknowns, dict=True)
    if len(solution) != 1:
        raise MobilityError("the inputs do not fix the train's speeds")
    (values,) = solution
    ratios = {}
    for x in links:
        value = sympy.simplify(values[omega[x]])
        if len(inputs) == 1:
            value = sympy.simplify(value / speeds[inputs[0]])
        ratios[x] = value
    return TrainRatios(inputs, ratios, dof, tuple(found), teeth_found)


def balancing_moment(mechanism: Mechanism, ratios: TrainRatios) -> sympy.Expr | None:
    """Moment on the (single) input that balances the ``moment`` loads, by power.

    M_in·ω_in + Σ M_i·ω_i = 0, so M_in = −Σ M_i·(ω_i/ω_in); None without loads.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver 1", "0 1 R A", "0 2 R B", "1 2 H gear z=20,40",
    ...                     "moment 2 -10"])
    >>> balancing_moment(m, speed_ratios(m))
    -5
    """
    if len(ratios.inputs) != 1:
        raise MobilityError("the balancing moment by power needs a single input")
    moments = [x for x in mechanism.loads if x.kind == "moment"]
    if not moments:
        return None
    total = sympy.Integer(0)
    for load in moments:
        ratio = 1 if load.link == ratios.inputs[0] else ratios.ratios.get(load.link)
        if ratio is None:
            raise MechanismError(f"the moment on link {load.link} is not on a train link")
        total += sympy.Rational(repr(load.values[0])) * ratio
    return sympy.simplify(-total)


def reduced_inertia(mechanism: Mechanism, ratios: TrainRatios) -> sympy.Expr:
    """Moment of inertia of the train reduced to its (single) input link: Σ J_i·(ω_i/ω_in)².

    Uses the ``mass LINK m J S`` statements: J·(ω/ω_in)² for every link, and
    for a planet (centre of mass on its axis) also its orbiting mass,
    m·(ω_c·R/ω_in)² with R the carrier arm from the tooth numbers and the
    module (``module=`` is then needed on its meshes).

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver 3", "0 c R O", "0 3 R O", "c 2 R P",
    ...                     "2 0 H gear z=20,60", "2 3 H gear z=25,105 internal=3",
    ...                     "mass c 0 0.05 O", "point O 0 0"])
    >>> reduced_inertia(m, speed_ratios(m))
    49/2880
    """
    if len(ratios.inputs) != 1:
        raise MobilityError("the reduced inertia needs a single input")
    total = sympy.Integer(0)
    arms = _planet_arms(mechanism, ratios)
    for load in mechanism.loads:
        if load.kind != "mass" or load.link not in ratios.ratios:
            continue
        mass, inertia = (sympy.Rational(repr(v)) for v in load.values)
        total += inertia * ratios.ratios[load.link] ** 2
        if mass and load.link in arms:
            carrier, arm = arms[load.link]
            if arm is None:
                raise MechanismError(
                    f"the orbiting mass of planet {load.link} needs module= on its meshes"
                )
            total += mass * (ratios.ratios[carrier] * arm) ** 2
    return sympy.simplify(total)


def _planet_arms(
    mechanism: Mechanism, ratios: TrainRatios
) -> dict[str, tuple[str, sympy.Expr | None]]:
    """Each planet's carrier and carrier arm (exact, or None without a module)."""
    ground = mechanism.ground
    out: dict[str, tuple[str, sympy.Expr | None]] = {}
    for mesh in ratios.meshes:
        carrier = mesh.carrier
        if carrier == ground:
            continue
        for planet in (mesh.a, mesh.b):
            if not is_planet(mechanism, planet, carrier):
                continue
            za = mesh.za if mesh.za is not None else ratios.teeth_found.get((mesh.pair.id, 1))
            zb = mesh.zb if mesh.zb is not None else ratios.teeth_found.get((mesh.pair.id, 2))
            z_p, z_c = (za, zb) if mesh.a == planet else (zb, za)
            if mesh.pair.module is None or z_p is None or z_c is None:
                out.setdefault(planet, (carrier, None))
                continue
            module = sympy.Rational(repr(mesh.pair.module))
            span = (z_c - z_p) if mesh.internal else (z_c + z_p)
            out[planet] = (carrier, module * span / 2)
    return out


@dataclass(frozen=True)
class TrainForces:
    """Tooth forces and planet pin forces of a planetary train, and the balancing moment.

    ``tooth[pair id]`` is the tangential force (N) that the mesh's link ``b``
    receives from ``a`` (signed along the common tangent); ``pins[planet]`` the
    force (N, vector in the carrier's frame: x radial outward, y tangential)
    the carrier exerts on the planet, radial components from the pressure angle
    included; ``balancing_moment`` the moment on the input from the planets'
    force balance (it must equal the one found by power).
    """

    tooth: Mapping[int, float]
    pins: Mapping[str, tuple[float, float]]
    balancing_moment: float
    levers: Mapping[int, tuple[float, float]] = field(default_factory=dict)


def train_forces(
    mechanism: Mechanism, ratios: TrainRatios, pressure_angle: float = math.radians(20)
) -> TrainForces:
    """Force balance of every gear, planet and the carrier, in the textbook's radial layout.

    The main axis is the origin and each planet's axis lies at the carrier arm R
    on the x axis; a mesh of a central gear of pitch radius r with the planet is
    at x = r (the sun's side or the ring's side alike), a mesh between two
    planets is not supported. Each gear's moments about its own axis balance; the
    carrier takes the planets' pin forces at the arm R. Needs ``module=`` on
    every mesh.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver C", "0 C R O", "0 1 R O", "C 2 R B",
    ...     "1 2 H gear z=20,20 module=0.02", "2 0 H gear z=20,60 internal=0 module=0.02",
    ...     "moment 1 20"])
    >>> f = train_forces(m, speed_ratios(m))
    >>> round(f.balancing_moment, 9), [round(x, 9) + 0.0 for x in f.pins["2"]]
    (-80.0, [0.0, -200.0])
    """
    if len(ratios.inputs) != 1:
        raise MobilityError("the force balance needs a single input")
    carriers = {mesh.carrier for mesh in ratios.meshes}
    if len(carriers) != 1 or mechanism.ground in carriers:
        raise MechanismError(
            "the planet force balance covers planetary trains with one moving carrier"
        )
    (carrier,) = carriers
    planets, arm, place = _radial_layout(mechanism, ratios, carrier)
    rows, rhs = _moment_balances(mechanism, ratios, carrier, planets, arm, place)
    solution, *_ = np.linalg.lstsq(np.array(rows), np.array(rhs), rcond=None)
    if not np.allclose(np.array(rows) @ solution, rhs, atol=1e-9 * (1 + np.abs(rhs).max())):
        raise MechanismError("the gear train's force balance has no solution")
    tooth = {mesh.pair.id: float(solution[k]) for k, mesh in enumerate(ratios.meshes)}
    pins: dict[str, tuple[float, float]] = {}
    for planet in arm:
        fx = fy = 0.0
        for mesh in ratios.meshes:
            if planets[mesh.pair.id] != planet:
                continue
            sign = 1.0 if mesh.b == planet else -1.0
            f = sign * tooth[mesh.pair.id]
            fy += f
            # separating force: away from an external partner, toward a ring's centre
            fx += abs(f) * math.tan(pressure_angle) * (-1.0 if mesh.internal else 1.0)
        pins[planet] = (-fx, -fy)
    levers = {
        mesh.pair.id: tuple(
            place[mesh.pair.id] - arm[x] if x in arm else place[mesh.pair.id]
            for x in (mesh.a, mesh.b)
        )
        for mesh in ratios.meshes
    }
    return TrainForces(tooth, pins, float(solution[-1]), levers)  # type: ignore[arg-type]


def _planet_of(mechanism: Mechanism, mesh: Mesh, carrier: str) -> str:
    """The gear of ``mesh`` that is a planet of ``carrier``."""
    for x in (mesh.a, mesh.b):
        if is_planet(mechanism, x, carrier):
            return x
    raise MechanismError(f"the mesh {mesh.pair.label} joins no planet of carrier {carrier}")


def _teeth(ratios: TrainRatios) -> dict[int, tuple[int, int, float]]:
    """``(z_a, z_b, module)`` of every mesh (tooth numbers found by coaxiality included).

    Raises
    ------
    MechanismError
        A mesh without ``module=``.
    """
    teeth = {}
    for mesh in ratios.meshes:
        za = mesh.za if mesh.za is not None else ratios.teeth_found[(mesh.pair.id, 1)]
        zb = mesh.zb if mesh.zb is not None else ratios.teeth_found[(mesh.pair.id, 2)]
        if mesh.pair.module is None:
            raise MechanismError(f"the gear mesh {mesh.pair.label} needs module= for forces")
        teeth[mesh.pair.id] = (za, zb, mesh.pair.module)
    return teeth


def _radial_layout(
    mechanism: Mechanism, ratios: TrainRatios, carrier: str
) -> tuple[dict[int, str], dict[str, float], dict[int, float]]:
    """Each mesh's planet, each planet's carrier arm R, each mesh's x (central pitch radius).

    Raises
    ------
    MechanismError
        A mesh without ``module=`` or without a planet, or a planet whose meshes
        are not coaxial.
    """
    teeth = _teeth(ratios)
    planets: dict[int, str] = {}
    arm: dict[str, float] = {}
    place: dict[int, float] = {}  # x of each mesh
    for mesh in ratios.meshes:
        planet = planets[mesh.pair.id] = _planet_of(mechanism, mesh, carrier)
        za, zb, module = teeth[mesh.pair.id]
        z_planet, z_central = (za, zb) if mesh.a == planet else (zb, za)
        r_central = module * z_central / 2
        r_planet = module * z_planet / 2
        place[mesh.pair.id] = r_central
        radius = r_central - r_planet if mesh.internal else r_central + r_planet
        if planet in arm and not math.isclose(arm[planet], radius, rel_tol=1e-9):
            raise MechanismError(f"the meshes of planet {planet} are not coaxial")
        arm[planet] = radius
    return planets, arm, place


def _moment_balances(
    mechanism: Mechanism,
    ratios: TrainRatios,
    carrier: str,
    planets: Mapping[int, str],
    arm: Mapping[str, float],
    place: Mapping[int, float],
) -> tuple[list[list[float]], list[float]]:
    """Each moving link's moment balance about its axis: rows in the tooth forces and the
    balancing moment (last), and the right-hand sides (the ``moment`` loads)."""
    ground = mechanism.ground
    moving = sorted(
        {x for mesh in ratios.meshes for x in (mesh.a, mesh.b)} - {ground} | {carrier},
        key=mechanism.links.index,
    )
    size = len(ratios.meshes) + 1
    rows: list[list[float]] = []
    rhs: list[float] = []
    external = {x.link: x.values[0] for x in mechanism.loads if x.kind == "moment"}
    for link in moving:
        row = [0.0] * size
        for k, mesh in enumerate(ratios.meshes):
            x = place[mesh.pair.id]
            if link == carrier:
                planet = planets[mesh.pair.id]
                # force on the planet from this mesh, passed to the carrier through the pin
                sign = 1.0 if mesh.b == planet else -1.0
                row[k] += arm[planet] * sign
                continue
            if link not in (mesh.a, mesh.b):
                continue
            sign = 1.0 if link == mesh.b else -1.0
            lever = x - arm[link] if link in arm else x
            row[k] += lever * sign
        if link == ratios.inputs[0]:
            row[-1] = 1.0
        rows.append(row)
        rhs.append(-external.get(link, 0.0))
    return rows, rhs


@dataclass(frozen=True)
class TrainLosses:
    """Balancing moment with mesh losses, the power lost and the train's efficiency."""

    balancing_moment: float
    lost_power: float  # W per rad/s of the input
    efficiency: float


def train_losses(mechanism: Mechanism, ratios: TrainRatios, mesh_efficiency: float) -> TrainLosses:
    """Mesh losses of a planetary train, to first order in 1 − η.

    Each mesh loses (1 − η) of the power it transmits in the carrier's frame,
    |T_a·(ω_a − ω_c)|, T_a the moment its teeth put on gear a (from the
    lossless force balance); the input must supply it too:
    M_b·ω_in = −Σ M_i·ω_i + Σ losses. The efficiency is the useful power over
    the input power.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver C", "0 C R O", "0 1 R O", "C 2 R B",
    ...     "1 2 H gear z=20,20 module=0.02", "2 0 H gear z=20,60 internal=0 module=0.02",
    ...     "moment 1 20"])
    >>> r = train_losses(m, speed_ratios(m), 0.98)   # each mesh carries 20 N·m at 3 rad/s
    >>> round(r.lost_power, 9), round(r.balancing_moment, 9), round(r.efficiency, 9)
    (2.4, -77.6, 0.97)
    """
    if not 0 < mesh_efficiency <= 1:
        raise NumberError("the mesh efficiency is a number in (0, 1]")
    forces = train_forces(mechanism, ratios)
    omega = {**{k: float(v) for k, v in ratios.ratios.items()}, mechanism.ground: 0.0}
    omega[ratios.inputs[0]] = 1.0
    lost = 0.0
    for mesh in ratios.meshes:
        lever_a, _ = forces.levers[mesh.pair.id]
        torque_a = -lever_a * forces.tooth[mesh.pair.id]
        relative = omega[mesh.a] - omega[mesh.carrier]
        lost += (1 - mesh_efficiency) * abs(torque_a * relative)
    external = {x.link: x.values[0] for x in mechanism.loads if x.kind == "moment"}
    useful = -sum(value * omega.get(link, 0.0) for link, value in external.items())
    balancing = useful + lost  # M_b·ω_in with ω_in = 1: the input also pays the losses
    # the input drives: the loads take useful of what it gives; the loads drive and the input
    # brakes: it receives what the losses leave
    driving = useful >= 0
    efficiency = (useful / balancing if balancing else 1.0) if driving else balancing / useful
    return TrainLosses(balancing, lost, efficiency)
