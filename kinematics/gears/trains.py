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

A train with several inputs (a differential) has no single ratio: each link's
speed is a linear relation in the inputs' speeds (:func:`speed_relations`,
e.g. ω4 = 2·ωc − ω3), each input its own balancing moment
(:func:`balancing_moments`, by virtual power) and the train an inertia
matrix (:func:`inertia_matrix`); the numbers follow once the inputs' speeds
are given (``omega=`` on the driver lines, :func:`input_speeds`).

Mesh losses (:func:`train_losses`) are exact, by the torque method of
Müller (*Epicyclic Drive Trains*, 1982) and Pennestrì & Freudenstein ("The
mechanical efficiency of epicyclic gear trains", ASME J. Mech. Des. 115,
1993): in the carrier's frame every mesh is a gear pair on fixed axes, whose
output moment is η times the lossless one, η applied in the direction the
power flows through that mesh in the carrier's frame.

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
from structure.expressions import exact_float, exact_value
from structure.meshes import Mesh, is_planet, meshes
from structure.model import Load, Mechanism

# Mesh and meshes (the topology of the meshes) are defined in structure.meshes; they stay
# importable from here
__all__ = [
    "Mesh",
    "TrainForces",
    "TrainLosses",
    "TrainRatios",
    "balancing_moment",
    "balancing_moments",
    "inertia_matrix",
    "input_speeds",
    "link_speeds",
    "meshes",
    "reduced_inertia",
    "relation_text",
    "speed_ratios",
    "speed_relations",
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


def speed_relations(ratios: TrainRatios) -> dict[str, dict[str, sympy.Expr]]:
    """Each train link's speed as exact coefficients of the inputs' speeds.

    ω_link = Σ k·ω_input: ``relations[link][input]`` is k (with one input,
    the speed ratio itself).

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver c", "driver 3", "0 c R O", "0 3 R O", "0 4 R O",
    ...                     "c 2 R P", "2 3 H gear z=10,20", "2 4 H gear z=10,20 internal=4"])
    >>> speed_relations(speed_ratios(m))["4"]
    {'c': 2, '3': -1}
    """
    if len(ratios.inputs) == 1:
        (only,) = ratios.inputs
        return {link: {only: value} for link, value in ratios.ratios.items()}
    symbols = [sympy.Symbol(f"omega_{x}") for x in ratios.inputs]
    return {
        link: {
            x: sympy.nsimplify(sympy.diff(value, symbol))
            for x, symbol in zip(ratios.inputs, symbols, strict=True)
        }
        for link, value in ratios.ratios.items()
    }


def relation_text(link: str, row: Mapping[str, sympy.Expr]) -> str:
    """A link's speed as a relation in the inputs' speeds, e.g. ``ω4 = 2·ωc − ω3``.

    >>> import sympy
    >>> relation_text("2", {"c": sympy.Integer(3), "3": sympy.Rational(-1, 2)})
    'ω2 = 3·ωc − 1/2·ω3'
    >>> relation_text("4", {"c": sympy.Integer(0), "3": sympy.Integer(0)})
    'ω4 = 0'
    """
    terms = []
    for x, k in row.items():
        if k == 0:
            continue
        size = abs(k)
        body = f"ω{x}" if size == 1 else f"{size}·ω{x}"
        if not terms:
            terms.append(body if k > 0 else f"−{body}")
        else:
            terms.append(f"+ {body}" if k > 0 else f"− {body}")
    return f"ω{link} = " + (" ".join(terms) or "0")


def input_speeds(mechanism: Mechanism, ratios: TrainRatios) -> dict[str, sympy.Expr] | None:
    """The inputs' speeds from the driver lines' ``omega=`` (exact), or None if one has none."""
    given = {d.link: dict(d.motion).get("omega") for d in mechanism.drivers}
    if any(given.get(x) is None for x in ratios.inputs):
        return None
    return {x: exact_float(given[x]) for x in ratios.inputs}  # type: ignore[arg-type]


def link_speeds(ratios: TrainRatios, speeds: Mapping[str, sympy.Expr]) -> dict[str, sympy.Expr]:
    """Every train link's speed (rad/s, exact) at the inputs' ``speeds``.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver c", "driver 3", "0 c R O", "0 3 R O", "0 4 R O",
    ...                     "c 2 R P", "2 3 H gear z=10,20", "2 4 H gear z=10,20 internal=4"])
    >>> link_speeds(speed_ratios(m), {"c": 10, "3": 4})
    {'c': 10, '3': 4, '4': 16, '2': 22}
    """
    return {
        link: sympy.nsimplify(sum(k * speeds[x] for x, k in row.items()))
        for link, row in speed_relations(ratios).items()
    }


def _exact_load(load: Load, k: int = 0) -> sympy.Expr:
    """A load's ``k``-th number, exact as written (``500*sqrt(2)``) or as its decimal."""
    written = load.exact[k] if k < len(load.exact) else None
    return exact_value(written) if written else exact_float(load.values[k])


def _moment_loads(mechanism: Mechanism, ratios: TrainRatios) -> dict[str, sympy.Expr]:
    """The ``moment`` loads on the train's links, added per link (exact).

    Raises
    ------
    MechanismError
        A moment on a link that is not part of the train.
    """
    out: dict[str, sympy.Expr] = {}
    for load in mechanism.loads:
        if load.kind != "moment":
            continue
        if load.link not in ratios.ratios:
            raise MechanismError(f"the moment on link {load.link} is not on a train link")
        out[load.link] = out.get(load.link, sympy.Integer(0)) + _exact_load(load)
    return out


def balancing_moments(mechanism: Mechanism, ratios: TrainRatios) -> dict[str, sympy.Expr] | None:
    """The moment on each input that balances the ``moment`` loads, by virtual power.

    Σ_j M_j·ω_j + Σ_i M_i·ω_i = 0 for every motion the inputs allow, with
    ω_i = Σ_j k_ij·ω_j: M_j = −Σ_i M_i·k_ij, one per input; None without loads.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver c", "driver 3", "0 c R O", "0 3 R O", "0 4 R O",
    ...                     "c 2 R P", "2 3 H gear z=10,20", "2 4 H gear z=10,20 internal=4",
    ...                     "moment 4 -20"])
    >>> balancing_moments(m, speed_ratios(m))   # ω4 = 2·ωc − ω3
    {'c': 40, '3': -20}
    """
    loads = _moment_loads(mechanism, ratios)
    if not loads:
        return None
    relations = speed_relations(ratios)
    return {
        x: sympy.nsimplify(-sum(value * relations[link][x] for link, value in loads.items()))
        for x in ratios.inputs
    }


def balancing_moment(mechanism: Mechanism, ratios: TrainRatios) -> sympy.Expr | None:
    """Moment on the (single) input that balances the ``moment`` loads, by power.

    M_in·ω_in + Σ M_i·ω_i = 0, so M_in = −Σ M_i·(ω_i/ω_in); None without loads.
    With several inputs see :func:`balancing_moments`.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver 1", "0 1 R A", "0 2 R B", "1 2 H gear z=20,40",
    ...                     "moment 2 -10"])
    >>> balancing_moment(m, speed_ratios(m))
    -5
    """
    if len(ratios.inputs) != 1:
        raise MobilityError(
            "the balancing moment by power needs a single input: "
            "a train with several has one per input (balancing_moments)"
        )
    moments = balancing_moments(mechanism, ratios)
    return None if moments is None else moments[ratios.inputs[0]]


def inertia_matrix(mechanism: Mechanism, ratios: TrainRatios) -> sympy.Matrix:
    """The train's inertia reduced to its inputs: T = ½·ωᵀ·J·ω over the inputs' speeds ω.

    J_jk = Σ_i J_i·k_ij·k_ik over the ``mass LINK m J S`` statements (ω_i =
    Σ_j k_ij·ω_j), and for a planet (centre of mass on its axis) also its
    orbiting mass, m·R²·k_cj·k_ck with R the carrier arm from the tooth
    numbers and the module (``module=`` is then needed on its meshes).

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver c", "driver 3", "0 c R O", "0 3 R O", "0 4 R O",
    ...                     "c 2 R P", "2 3 H gear z=10,20", "2 4 H gear z=10,20 internal=4",
    ...                     "mass 4 0 0.5 O"])
    >>> inertia_matrix(m, speed_ratios(m)).tolist()   # ω4 = 2·ωc − ω3: 0.5·(2, −1)ᵀ(2, −1)
    [[2, -1], [-1, 1/2]]
    """
    relations = speed_relations(ratios)
    arms = _planet_arms(mechanism, ratios)
    size = len(ratios.inputs)
    total = sympy.zeros(size, size)
    for load in mechanism.loads:
        if load.kind != "mass" or load.link not in relations:
            continue
        mass, inertia = _exact_load(load, 0), _exact_load(load, 1)
        k = sympy.Matrix([relations[load.link][x] for x in ratios.inputs])
        total += inertia * k * k.T
        if mass and load.link in arms:
            carrier, arm = arms[load.link]
            if arm is None:
                raise MechanismError(
                    f"the orbiting mass of planet {load.link} needs module= on its meshes"
                )
            kc = sympy.Matrix([relations[carrier][x] for x in ratios.inputs])
            total += mass * arm**2 * kc * kc.T
    return total.applyfunc(sympy.nsimplify)


def reduced_inertia(mechanism: Mechanism, ratios: TrainRatios) -> sympy.Expr:
    """Moment of inertia of the train reduced to its (single) input link: Σ J_i·(ω_i/ω_in)².

    Uses the ``mass LINK m J S`` statements: J·(ω/ω_in)² for every link, and
    for a planet (centre of mass on its axis) also its orbiting mass,
    m·(ω_c·R/ω_in)² with R the carrier arm from the tooth numbers and the
    module (``module=`` is then needed on its meshes). With several inputs
    see :func:`inertia_matrix`.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver 3", "0 c R O", "0 3 R O", "c 2 R P",
    ...                     "2 0 H gear z=20,60", "2 3 H gear z=25,105 internal=3",
    ...                     "mass c 0 0.05 O", "point O 0 0"])
    >>> reduced_inertia(m, speed_ratios(m))
    49/2880
    """
    if len(ratios.inputs) != 1:
        raise MobilityError(
            "the reduced inertia needs a single input: "
            "a train with several has an inertia matrix (inertia_matrix)"
        )
    return sympy.simplify(inertia_matrix(mechanism, ratios)[0, 0])


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
    """Tooth forces and planet pin forces of a planetary train, and the balancing moments.

    ``tooth[pair id]`` is the tangential force (N) that the mesh's link ``b``
    receives from ``a`` (signed along the common tangent); ``pins[planet]`` the
    force (N, vector in the carrier's frame: x radial outward, y tangential)
    the carrier exerts on the planet, radial components from the pressure angle
    included; ``balancing_moments[input]`` the moment on each input from the
    planets' force balance (it must equal the one found by power).
    """

    tooth: Mapping[int, float]
    pins: Mapping[str, tuple[float, float]]
    balancing_moments: Mapping[str, float]
    levers: Mapping[int, tuple[float, float]] = field(default_factory=dict)

    @property
    def balancing_moment(self) -> float:
        """The balancing moment of a train with a single input (N·m).

        Raises
        ------
        MobilityError
            The train has several inputs: see ``balancing_moments``.
        """
        if len(self.balancing_moments) != 1:
            raise MobilityError("a train with several inputs has one balancing moment per input")
        return next(iter(self.balancing_moments.values()))


def train_forces(
    mechanism: Mechanism, ratios: TrainRatios, pressure_angle: float = math.radians(20)
) -> TrainForces:
    """Force balance of every gear, planet and the carrier, in the textbook's radial layout.

    The main axis is the origin and each planet's axis lies at the carrier arm R
    on the x axis; a mesh of a central gear of pitch radius r with the planet is
    at x = r (the sun's side or the ring's side alike), a mesh between two
    planets is not supported. Each gear's moments about its own axis balance; the
    carrier takes the planets' pin forces at the arm R; every input takes a
    balancing moment. Needs ``module=`` on every mesh.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver C", "0 C R O", "0 1 R O", "C 2 R B",
    ...     "1 2 H gear z=20,20 module=0.02", "2 0 H gear z=20,60 internal=0 module=0.02",
    ...     "moment 1 20"])
    >>> f = train_forces(m, speed_ratios(m))
    >>> round(f.balancing_moment, 9), [round(x, 9) + 0.0 for x in f.pins["2"]]
    (-80.0, [0.0, -200.0])
    """
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
    first = len(ratios.meshes)
    moments = {x: float(solution[first + j]) for j, x in enumerate(ratios.inputs)}
    return TrainForces(tooth, pins, moments, levers)  # type: ignore[arg-type]


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
        if is_planet(mechanism, mesh.a, carrier) and is_planet(mechanism, mesh.b, carrier):
            raise MechanismError(
                f"the planet force balance does not cover the mesh {mesh.pair.label} between "
                "two planets"
            )
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
    inputs' balancing moments (last), and the right-hand sides (the ``moment`` loads)."""
    ground = mechanism.ground
    moving = sorted(
        {x for mesh in ratios.meshes for x in (mesh.a, mesh.b)} - {ground} | {carrier},
        key=mechanism.links.index,
    )
    size = len(ratios.meshes) + len(ratios.inputs)
    rows: list[list[float]] = []
    rhs: list[float] = []
    external = {link: float(value) for link, value in _moment_loads(mechanism, ratios).items()}
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
        if link in ratios.inputs:
            row[len(ratios.meshes) + ratios.inputs.index(link)] = 1.0
        rows.append(row)
        rhs.append(-external.get(link, 0.0))
    return rows, rhs


@dataclass(frozen=True)
class TrainLosses:
    """Balancing moments with mesh losses, the power lost and the train's efficiency.

    ``speeds`` are the inputs' speeds these are at (rad/s): with a single input
    1 rad/s unless given, so that ``lost_power`` is per rad/s of the input.
    ``mesh_power[pair id]`` is the power that enters each mesh in the
    carrier's frame (W) and ``mesh_loss[pair id]`` the part of it lost.
    """

    balancing_moments: Mapping[str, float]
    lost_power: float  # W at ``speeds``
    efficiency: float
    speeds: Mapping[str, float] = field(default_factory=dict)
    mesh_power: Mapping[int, float] = field(default_factory=dict)
    mesh_loss: Mapping[int, float] = field(default_factory=dict)

    @property
    def balancing_moment(self) -> float:
        """The balancing moment of a train with a single input (N·m).

        Raises
        ------
        MobilityError
            The train has several inputs: see ``balancing_moments``.
        """
        if len(self.balancing_moments) != 1:
            raise MobilityError("a train with several inputs has one balancing moment per input")
        return next(iter(self.balancing_moments.values()))


def train_losses(
    mechanism: Mechanism,
    ratios: TrainRatios,
    mesh_efficiency: float,
    speeds: Mapping[str, float] | None = None,
) -> TrainLosses:
    """Exact mesh losses of a gear train: the inputs' balancing moments with them.

    The torque method (Müller 1982; Pennestrì & Freudenstein 1993). Unknowns:
    the moment μ each mesh puts on its gear ``a`` about that gear's axis, and
    each input's balancing moment. In the carrier's frame the mesh is a gear
    pair on fixed axes, so the moment on gear ``b`` is ν = ρ·μ with

        ρ = ±(z_b/z_a)·η^(±1)   (+ external, − internal teeth),

    η when the power flows from ``a`` to ``b`` in the carrier's frame (μ·(ω_a −
    ω_c) < 0: ``a`` drives), 1/η when it flows from ``b`` to ``a``, and 1 when
    the mesh does not roll (ω_a = ω_c); what the mesh puts on its carrier about
    the carrier's axis is −(μ + ν) (the tooth forces are internal: their
    moments about the main axis cancel). Each moving link's moments balance.
    The directions of flow come from the lossless solution and are checked
    against the lossy one until they agree. The power lost is the sum of the
    powers of the loads and the inputs; the efficiency is the power the
    receiving ends take over the power the driving ends give.

    ``speeds`` are the inputs' speeds (rad/s); with a single input they
    default to 1 rad/s (the losses then per rad/s of the input), with several
    they are needed, since the flow through each mesh depends on them. Every
    carrier must turn about a fixed axis (be pinned to the ground) or be the
    ground.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver C", "0 C R O", "0 1 R O", "C 2 R B",
    ...     "1 2 H gear z=20,20 module=0.02", "2 0 H gear z=20,60 internal=0 module=0.02",
    ...     "moment 1 20"])
    >>> r = train_losses(m, speed_ratios(m), 0.98)   # the sun drives: −(20 + 60·0.98²)
    >>> round(r.balancing_moment, 9), round(r.lost_power, 9), round(r.efficiency, 9)
    (-77.624, 2.376, 0.9703)

    Raises
    ------
    NumberError
        An efficiency outside (0, 1].
    MechanismError
        Several inputs without their speeds, a carrier that rides on another
        moving link, a moment on a link outside the train, or losses that
        admit no steady motion (the train self-locks).
    """
    if not 0 < mesh_efficiency <= 1:
        raise NumberError("the mesh efficiency is a number in (0, 1]")
    if speeds is None:
        if len(ratios.inputs) != 1:
            raise MechanismError(
                "the mesh losses of a train with several inputs depend on the inputs' speeds: "
                "give omega= on every driver line"
            )
        speeds = {ratios.inputs[0]: 1.0}
    _check_carriers(mechanism, ratios)
    omega = {link: float(value) for link, value in link_speeds(ratios, speeds).items()}
    omega[mechanism.ground] = 0.0
    loads = {link: float(value) for link, value in _moment_loads(mechanism, ratios).items()}
    lossless = [_lossless_ratio(ratios, mesh) for mesh in ratios.meshes]
    relative = [omega[mesh.a] - omega[mesh.carrier] for mesh in ratios.meshes]
    gains = [1.0] * len(ratios.meshes)
    for _ in range(len(ratios.meshes) + 2):
        mu, moments = _torque_balance(mechanism, ratios, loads, lossless, gains)
        power_a = [m * w for m, w in zip(mu, relative, strict=True)]
        scale = max((abs(p) for p in power_a), default=0.0)
        found = [
            1.0
            if abs(p) <= 1e-12 * scale
            else (mesh_efficiency if p < 0 else 1.0 / mesh_efficiency)
            for p in power_a
        ]
        if found == gains:
            break
        gains = found
    else:
        raise MechanismError(
            f"with mesh efficiency {mesh_efficiency:g} the train self-locks: no direction of "
            "the power through its meshes balances the loads at these speeds"
        )
    mesh_power: dict[int, float] = {}
    mesh_loss: dict[int, float] = {}
    for k, mesh in enumerate(ratios.meshes):
        p_a = mu[k] * relative[k]
        p_b = lossless[k] * gains[k] * mu[k] * (omega[mesh.b] - omega[mesh.carrier])
        mesh_power[mesh.pair.id] = max(-p_a, -p_b, 0.0)  # what the driving gear gives
        mesh_loss[mesh.pair.id] = -(p_a + p_b)
    ports = [moments[x] * omega[x] for x in ratios.inputs]
    ports += [value * omega[link] for link, value in loads.items()]
    given = sum(p for p in ports if p > 0)
    lost = sum(ports)
    efficiency = (given - lost) / given if given > 0 else 1.0
    return TrainLosses(
        moments,
        lost,
        efficiency,
        {x: float(v) for x, v in speeds.items()},
        mesh_power,
        mesh_loss,
    )


def _check_carriers(mechanism: Mechanism, ratios: TrainRatios) -> None:
    """Every moving carrier turns about a fixed axis, as the torque method needs.

    Raises
    ------
    MechanismError
        A carrier pinned to another moving link (a carrier on a carrier).
    """
    ground = mechanism.ground
    for carrier in {mesh.carrier for mesh in ratios.meshes} - {ground}:
        if mechanism.ground_joint(carrier) is None:
            raise MechanismError(
                f"the mesh losses need every carrier to turn about a fixed axis; carrier "
                f"{carrier} rides on another moving link"
            )


def _lossless_ratio(ratios: TrainRatios, mesh: Mesh) -> float:
    """ν/μ of a lossless mesh: the moment on gear b per moment on gear a, ±z_b/z_a."""
    za = mesh.za if mesh.za is not None else ratios.teeth_found[(mesh.pair.id, 1)]
    zb = mesh.zb if mesh.zb is not None else ratios.teeth_found[(mesh.pair.id, 2)]
    return (-1.0 if mesh.internal else 1.0) * zb / za


def _torque_balance(
    mechanism: Mechanism,
    ratios: TrainRatios,
    loads: Mapping[str, float],
    lossless: Sequence[float],
    gains: Sequence[float],
) -> tuple[list[float], dict[str, float]]:
    """The meshes' moments μ on their gears a and the inputs' balancing moments.

    One moment balance per moving train link; a train whose load sharing is
    statically indeterminate (several planets on one carrier) gets the
    least-squares (equal) share, which leaves the balancing moments as they are.

    Raises
    ------
    MechanismError
        The balances have no solution.
    """
    links = list(ratios.ratios)
    row_of = {link: i for i, link in enumerate(links)}
    n_meshes = len(ratios.meshes)
    matrix = np.zeros((len(links), n_meshes + len(ratios.inputs)))
    rhs = np.zeros(len(links))
    for k, mesh in enumerate(ratios.meshes):
        rho = lossless[k] * gains[k]
        for link, share in ((mesh.a, 1.0), (mesh.b, rho), (mesh.carrier, -(1.0 + rho))):
            if link in row_of:
                matrix[row_of[link], k] += share
    for j, x in enumerate(ratios.inputs):
        matrix[row_of[x], n_meshes + j] = 1.0
    for link, value in loads.items():
        rhs[row_of[link]] -= value
    solution, *_ = np.linalg.lstsq(matrix, rhs, rcond=None)
    if not np.allclose(matrix @ solution, rhs, atol=1e-9 * (1 + np.abs(rhs).max())):
        raise MechanismError("the gear train's moment balance has no solution")
    moments = {x: float(solution[n_meshes + j]) for j, x in enumerate(ratios.inputs)}
    return solution[:n_meshes].tolist(), moments
