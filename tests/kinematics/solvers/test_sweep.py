"""A sweep's answers do not depend on the unit of length or on the direction of travel.

Issue 22, item 4: branch decisions depended on both. Properties over the
fixtures, with hypothesis: the mechanism with every coordinate times k gives
positions, velocities and accelerations times k and the same angles, ω and
ε (to the last bit for k a power of two, which scales every float exactly;
to rounding for a power of ten); the poses swept in the reverse order give
the same answer at each pose (a link's angle up to whole turns, as it is
counted along the rows).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kinematics.solvers.plan import make_plan
from kinematics.solvers.sweep import sweep
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES

#: fixtures that make a whole cycle: dyads of every kind, a triad, a redundant link, a slider
STEMS = [
    "fourbar",
    "crank_slider",
    "jansen",
    "klann",
    "watt_sixbar",
    "stephenson_sixbar_dyads",
    "eightbar_triad",
    "quick_return_shaper",
    "scotch_yoke",
    "inverted_crank_slider",
    "ch2_2_8a_rocking_guide",
    "ch2_2_10_sieve",
    "parallelogram_redundant",
]
#: a crank–slider driven at its block: its stroke, in metres, scales with the unit too
SLIDER_DRIVEN = [
    "driver 3 v=2",
    "0 1 R A",
    "1 2 R B",
    "2 3 R C",
    "3 0 P C angle=0",
    "point A 0 0",
    "point B 0 0.1",
    "point C 0.1732 0",
]
STEPS = 12
LENGTHS = ("position", "velocity", "acceleration")


def mechanism(stem: str):
    if stem == "slider_driven":
        return parse_edgelist(SLIDER_DRIVEN)
    return read_edgelist(str(FIXTURES / f"{stem}.edges"))


def scaled(m, k: float):
    """The mechanism in a unit of length 1/k: coordinates, and a slider's speed and acceleration."""
    points = {n: dataclasses.replace(p, x=p.x * k, y=p.y * k) for n, p in m.points.items()}
    drivers = tuple(
        dataclasses.replace(
            d, motion=tuple((key, v * k if key in "va" else v) for key, v in d.motion)
        )
        for d in m.drivers
    )
    return dataclasses.replace(m, points=points, drivers=drivers)


def solved(m, inputs=None):
    return sweep(make_plan(analyze(m)), inputs, steps=STEPS)


def as_arrays(result) -> dict[str, np.ndarray]:
    """The sweep's kinematic columns (the balancing, which depends on the loads, left out)."""
    return {k: v for k, v in result.as_dict().items() if not k.startswith("balancing")}


def kind(name: str) -> str:
    """What a column holds: 'position', 'omega', 'transmission', ... (its unit, in short)."""
    if name.startswith("transmission") or name.startswith("input"):
        return name.split()[0].rstrip("0123456789")
    parts = name.split(".")
    return parts[1] if len(parts) > 1 else name


def kind_sizes(columns: dict[str, np.ndarray]) -> dict[str, float]:
    """What a difference in each kind of column is measured against.

    The largest magnitude of the kind, and at least the mechanism's own scale
    of it: its size L, its fastest turning rate ω (1/s), ω·L, ω², ω²·L.
    """
    out: dict[str, float] = {}
    for name, values in columns.items():
        out[kind(name)] = max(out.get(kind(name), 0.0), float(np.max(np.abs(values))))
    w, size = max(out.get("omega", 0.0), 1.0), max(out.get("position", 0.0), 1e-300)
    floors = {"position": size, "velocity": w * size, "acceleration": w * w * size}
    floors |= {"omega": w, "epsilon": w * w, "angle": 1.0, "transmission": 1.0}
    return {k: max(v, floors.get(k, 1.0)) for k, v in out.items()}


def length_column(name: str) -> bool:
    return any(f".{q}." in name for q in LENGTHS)


def check_a_power_of_two_unit_scales_every_answer_exactly(stem, m):
    # from 2^-64 to 2^64 m a sketch is solved as it stands: every float scales exactly
    k = 2.0**m
    plain = solved(mechanism(stem))
    far = solved(scaled(mechanism(stem), k))
    a, b = as_arrays(plain), as_arrays(far)
    assert a.keys() == b.keys()
    sliding = stem == "slider_driven"
    for name in a:
        unit = k if length_column(name) or (sliding and name == "input1") else 1.0
        np.testing.assert_array_equal(b[name], a[name] * unit, err_msg=f"{stem} {name} k=2^{m}")


def check_a_far_power_of_two_unit_scales_every_answer_to_the_last_bits(stem, m):
    # beyond, a sketch is solved in a power of two near its size: the same arithmetic but the
    # last steps (points from the links' poses), within a few units of the last place
    k = 2.0**m
    a, b = as_arrays(solved(mechanism(stem))), as_arrays(solved(scaled(mechanism(stem), k)))
    sliding = stem == "slider_driven"
    tops = kind_sizes(a)
    for name in a:
        unit = k if length_column(name) or (sliding and name == "input1") else 1.0
        np.testing.assert_allclose(b[name] / unit, a[name], rtol=0, atol=1e-13 * tops[kind(name)])


def check_a_power_of_ten_unit_scales_every_answer_to_rounding(stem, j):
    k = 10.0**j
    plain = solved(mechanism(stem))
    far = solved(scaled(mechanism(stem), k))
    a, b = as_arrays(plain), as_arrays(far)
    tops = kind_sizes(a)
    sliding = stem == "slider_driven"
    for name in a:
        unit = k if length_column(name) or (sliding and name == "input1") else 1.0
        np.testing.assert_allclose(
            b[name] / unit, a[name], rtol=0, atol=1e-9 * tops[kind(name)], err_msg=f"{stem} {name}"
        )


def check_the_poses_swept_backward_give_the_same_answers(stem, shift):
    m = mechanism(stem)
    plan = make_plan(analyze(m))
    rows = np.roll(sweep(plan, steps=STEPS).inputs, shift, axis=0)
    ahead, behind = sweep(plan, rows), sweep(plan, rows[::-1])
    for name in ahead.points:
        for q in LENGTHS:
            np.testing.assert_allclose(
                behind.points[name][q][::-1],
                ahead.points[name][q],
                rtol=1e-9,
                atol=1e-9 * plan.length * 1e3,
                err_msg=f"{stem} {name} {q}",
            )
    for link in ahead.links:
        turned = behind.links[link]["angle"][::-1] - ahead.links[link]["angle"]
        whole = np.round(turned / (2 * math.pi)) * 2 * math.pi
        np.testing.assert_allclose(turned, whole, atol=1e-9, err_msg=f"{stem} {link}")
        np.testing.assert_allclose(
            behind.links[link]["omega"][::-1], ahead.links[link]["omega"], rtol=1e-9, atol=1e-9
        )


# ------------------------------------------------------------------ the properties, run
#: the default run's draws (a few seconds); CI's slow run draws many more, from every fixture
FEW, MANY = 6, 60
QUICK = [stem for stem in STEMS if stem != "parallelogram_redundant"]  # (1.5 s a sweep)
ANY = [*STEMS, "slider_driven"]
SETTINGS = {"deadline": None, "suppress_health_check": [HealthCheck.too_slow]}


@settings(max_examples=FEW, **SETTINGS)
@given(stem=st.sampled_from([*QUICK, "slider_driven"]), m=st.integers(-60, 60))
def test_a_power_of_two_unit_scales_every_answer_exactly(stem, m):
    check_a_power_of_two_unit_scales_every_answer_exactly(stem, m)


@settings(max_examples=FEW, **SETTINGS)
@given(stem=st.sampled_from([*QUICK, "slider_driven"]), m=st.integers(-1000, 480))
def test_a_far_power_of_two_unit_scales_every_answer_to_the_last_bits(stem, m):
    check_a_far_power_of_two_unit_scales_every_answer_to_the_last_bits(stem, m)


@settings(max_examples=FEW, **SETTINGS)
@given(stem=st.sampled_from([*QUICK, "slider_driven"]), j=st.integers(-300, 140))
def test_a_power_of_ten_unit_scales_every_answer_to_rounding(stem, j):
    check_a_power_of_ten_unit_scales_every_answer_to_rounding(stem, j)


@settings(max_examples=FEW, **SETTINGS)
@given(stem=st.sampled_from(QUICK), shift=st.integers(0, STEPS - 1))
def test_the_poses_swept_backward_give_the_same_answers(stem, shift):
    check_the_poses_swept_backward_give_the_same_answers(stem, shift)


@pytest.mark.slow
@settings(max_examples=MANY, **SETTINGS)
@given(stem=st.sampled_from(ANY), m=st.integers(-60, 60), n=st.integers(-1000, 480))
def test_many_units_scale_every_answer(stem, m, n):
    check_a_power_of_two_unit_scales_every_answer_exactly(stem, m)
    check_a_far_power_of_two_unit_scales_every_answer_to_the_last_bits(stem, n)
    check_a_power_of_ten_unit_scales_every_answer_to_rounding(stem, n // 4)


@pytest.mark.slow
@settings(max_examples=MANY, **SETTINGS)
@given(stem=st.sampled_from(STEMS), shift=st.integers(0, STEPS - 1))
def test_many_sweeps_backward_give_the_same_answers(stem, shift):
    check_the_poses_swept_backward_give_the_same_answers(stem, shift)


@pytest.mark.parametrize("stem", QUICK)
def test_every_cycle_fixture_sweeps_its_cycle(stem):
    result = solved(mechanism(stem))
    assert len(result.inputs) == STEPS
    assert all(np.all(np.isfinite(v)) for v in result.as_dict().values())
