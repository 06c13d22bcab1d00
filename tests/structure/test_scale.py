"""Scale-free answers, and mobility that does not depend on whether points are given (issue 11).

A mechanism and its copy scaled by any factor (a change of the unit of
length) have the same structure: W, r, W_passive, the groups and the class;
at the kinematics level the positions scale and the angles, angular
velocities and accelerations stay, and a dead centre or a singularity is
reported the same way. For generic geometry, the answer with coordinates is
the answer without them.
"""

from __future__ import annotations

import dataclasses
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kinematics import make_plan, solve_pose
from structure import MechanismError, analyze, mobility, parse_edgelist, read_edgelist
from structure.generators import GROUP_KINDS, random_mechanism_with_groups
from structure.model import Mechanism

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"

#: the factors of the issue, and the limits the reader allows (about 1e150)
FACTORS = [1e-150, 1e-80, 1e-8, 1e8, 1e80, 1e150]

_LENGTH_OPTIONS = ("span", "circle", "module")
_LENGTH_MOTIONS = ("v", "a")


def scaled(m: Mechanism, factor: float) -> Mechanism:
    """``m`` drawn in another unit of length: points, lengths and linear driver motions."""
    points = {
        name: dataclasses.replace(p, x=p.x * factor, y=p.y * factor, exact=(None, None))
        for name, p in m.points.items()
    }
    pairs = tuple(
        dataclasses.replace(
            p,
            **{
                key: getattr(p, key) * factor
                for key in _LENGTH_OPTIONS
                if getattr(p, key, None) is not None
            },
        )
        for p in m.pairs
    )
    drivers = tuple(
        dataclasses.replace(
            d, motion=tuple((k, v * factor if k in _LENGTH_MOTIONS else v) for k, v in d.motion)
        )
        for d in m.drivers
    )
    return m.evolve(points=points, pairs=pairs, drivers=drivers)


def structure_outcome(m: Mechanism) -> tuple:
    """What the structural analysis says, free of the unit of length."""
    try:
        report = analyze(m)
    except MechanismError as exc:
        return ("error", type(exc).__name__, str(exc))
    mob = report.mobility
    groups = tuple((g.links, g.assur_class, g.order, g.kind) for g in report.groups)
    return (mob.W, mob.r, mob.W_passive, groups, report.mechanism_class, report.formula)


@cache
def located_fixtures() -> tuple[tuple[str, Mechanism], ...]:
    out = []
    for path in sorted(FIXTURES.glob("*.edges")):
        try:
            m = read_edgelist(path)
        except MechanismError:
            continue
        if m.points:
            out.append((path.name, m))
    return tuple(out)


def fixture_ids() -> list[str]:
    return [name for name, _ in located_fixtures()]


@cache
def fixture_outcome(name: str) -> tuple:
    return structure_outcome(dict(located_fixtures())[name])


@pytest.mark.parametrize("factor", FACTORS)
@pytest.mark.parametrize("name", fixture_ids())
def test_fixture_structure_is_scale_free(name: str, factor: float) -> None:
    m = dict(located_fixtures())[name]
    assert structure_outcome(scaled(m, factor)) == fixture_outcome(name)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    name=st.sampled_from(fixture_ids()),
    exponent=st.floats(min_value=-150, max_value=150, allow_nan=False),
)
def test_fixture_structure_scale_property(name: str, exponent: float) -> None:
    m = dict(located_fixtures())[name]
    assert structure_outcome(scaled(m, 10.0**exponent)) == fixture_outcome(name)


def with_random_points(m: Mechanism, seed: int, factor: float = 1.0) -> Mechanism:
    """``m`` with every named point at a random place (``factor`` times the unit) and every
    slide at a random angle: a generic sketch."""
    rng = np.random.default_rng(seed)
    names = sorted({p.point for p in m.pairs if p.point is not None})
    xy = rng.uniform(-1.0, 1.0, size=(len(names), 2)) * factor
    pairs = [
        dataclasses.replace(p, angle_deg=float(rng.uniform(0.0, 180.0)))
        if p.angle_deg is not None
        else p
        for p in m.pairs
    ]
    return Mechanism.from_pairs(
        pairs,
        ground=m.ground,
        drivers=m.drivers,
        points={n: (float(x), float(y)) for n, (x, y) in zip(names, xy, strict=True)},
        name=m.name,
    )


def without_drivers(m: Mechanism) -> Mechanism:
    return m.evolve(drivers=())


def mobility_counts(m: Mechanism) -> tuple[int, int, int]:
    mob = mobility(m)
    return mob.W, mob.r, mob.W_passive


random_mechanisms = st.builds(
    lambda n, seed, compound: random_mechanism_with_groups(
        n, seed=seed, kinds=tuple(GROUP_KINDS), compound=compound
    )[0],
    st.integers(min_value=1, max_value=15),
    st.integers(min_value=0, max_value=2**32 - 1),
    st.sampled_from([0.0, 0.5]),
)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(m=random_mechanisms, seed=st.integers(0, 2**16), driven=st.booleans())
def test_random_mechanism_answer_with_and_without_points(
    m: Mechanism, seed: int, driven: bool
) -> None:
    if not driven:
        m = without_drivers(m)
    assert mobility_counts(with_random_points(m, seed)) == mobility_counts(m)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    m=random_mechanisms,
    seed=st.integers(0, 2**16),
    exponent=st.sampled_from([-150, -80, -8, 0, 8, 80, 150]),
)
def test_random_mechanism_structure_is_scale_free(m: Mechanism, seed: int, exponent: int) -> None:
    unit = with_random_points(m, seed)
    assert structure_outcome(with_random_points(m, seed, 10.0**exponent)) == structure_outcome(unit)


# --- the examples --------------------------------------------------------------------

FOURBAR = (FIXTURES / "fourbar.edges").read_text().splitlines()


@pytest.mark.parametrize("factor", [4e-8 / 0.4, 1e-8, 1e80, 1e150])
def test_scaled_fourbar_has_one_freedom(factor: float) -> None:
    m = scaled(parse_edgelist(FOURBAR), factor)
    mob = analyze(m).mobility
    assert (mob.W, mob.r, mob.W_passive) == (1, 0, 0)


def test_lone_crank_with_coordinates_moves() -> None:
    bare = parse_edgelist(["0 1 R A"])
    drawn = parse_edgelist(["0 1 R A", "point A 0.3 -0.2"])
    assert mobility_counts(bare) == mobility_counts(drawn) == (1, 0, 0)


IDLE_WHEEL = [
    "driver 1",
    "0 1 R A",
    "1 2 R B",
    "2 3 R C",
    "3 0 R D",
    "0 4 R E",
]
IDLE_POINTS = ["point A 0 0", "point B 0.05 0.0866", "point C 0.333 0.2924", "point D 0.4 0",
               "point E 0.2 -0.1"]  # fmt: skip


def test_idle_wheel_beside_a_fourbar_same_with_points() -> None:
    bare = parse_edgelist(IDLE_WHEEL)
    drawn = parse_edgelist(IDLE_WHEEL + IDLE_POINTS)
    assert mobility_counts(bare) == mobility_counts(drawn) == (2, 0, 0)
    assert structure_outcome(bare) == structure_outcome(drawn)


def test_declared_roller_still_passive() -> None:
    m = read_edgelist(FIXTURES / "cam_roller_follower.edges")
    assert analyze(m).mobility.W_passive == analyze(scaled(m, 1e-8)).mobility.W_passive >= 1


# --- kinematics: positions scale, angles and rates stay ------------------------------------------


def kinematics_outcome(m: Mechanism, factor: float) -> tuple:
    try:
        state = solve_pose(make_plan(analyze(m)))
    except MechanismError as exc:
        return ("error", type(exc).__name__, str(exc))
    links = {k: (s.q[2], s.qd[2], s.qdd[2]) for k, s in state.links.items()}
    points = {k: (p.position / factor, p.velocity / factor) for k, p in state.points.items()}
    return links, points


def same_kinematics(a: tuple, b: tuple) -> bool:
    if a[0] == "error" or b[0] == "error":
        return a == b
    if a[0].keys() != b[0].keys() or a[1].keys() != b[1].keys():
        return False
    for k in a[0]:
        # rates to 1e-8 of ω² (a redundant link's ε is a least-squares value)
        if not np.allclose(a[0][k], b[0][k], rtol=1e-7, atol=1e-6):
            return False
    for k in a[1]:
        for u, v in zip(a[1][k], b[1][k], strict=True):
            if not np.allclose(u, v, rtol=1e-7, atol=1e-9 * (1 + float(np.max(np.abs(v))))):
                return False
    return True


@cache
def kinematic_fixtures() -> tuple[str, ...]:
    names = []
    for name, m in located_fixtures():
        if any(p.gear or p.kind.value == "H" for p in m.pairs):
            continue  # gear trains and cams: their own scale (module, profiles)
        names.append(name)
    return tuple(names)


@pytest.mark.parametrize("factor", [1e-8, 1e8, 1e150])
@pytest.mark.parametrize("name", kinematic_fixtures())
def test_fixture_kinematics_is_scale_free(name: str, factor: float) -> None:
    m = dict(located_fixtures())[name]
    base = kinematics_outcome(m, 1.0)
    other = kinematics_outcome(scaled(m, factor), factor)
    assert same_kinematics(other, base), (other, base)
