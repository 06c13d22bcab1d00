"""Sweeps over a whole turn: continuity, transmission angle, export."""

from __future__ import annotations

import csv
import io
import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematics.cli.commands import main
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import AssemblyError
from kinematics.solvers.sweep import parse_inputs, sweep
from structure.errors import EdgeListError
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

CRANK_ROCKER = """
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0.1 0
point C 0.3 0.3
point D 0.4 0
"""


def plan_of(text: str):
    return make_plan(analyze(parse_edgelist(text.strip().splitlines())))


def test_transmission_angle_extremes_of_a_crank_rocker():
    # a = 0.1, b = |BC| = √0.13, c = |CD| = √0.1, d = 0.4; the extremes come with the crank
    # along the base: cos μ = (b² + c² − (d ∓ a)²) / (2bc)
    result = sweep(plan_of(CRANK_ROCKER), steps=360)
    b2, c2 = 0.13, 0.1
    mu = {
        s: math.acos((b2 + c2 - s**2) / (2 * math.sqrt(b2 * c2)))
        for s in (0.3, 0.5)  # d − a, d + a
    }
    (angles,) = result.transmission.values()
    assert angles.min() == pytest.approx(mu[0.3], abs=1e-9)
    assert angles.max() == pytest.approx(mu[0.5], abs=1e-9)


def test_angular_velocity_is_the_rate_of_the_angle_over_the_sweep():
    result = sweep(plan_of(CRANK_ROCKER), steps=3600)
    dt = (2 * math.pi / 3600) / 10.0  # time per step at ω1 = 10 rad/s
    angle = np.unwrap(result.links["3"]["angle"])
    rate = np.gradient(angle, dt)
    np.testing.assert_allclose(rate[1:-1], result.links["3"]["omega"][1:-1], atol=2e-3)


def test_a_full_turn_of_a_non_grashof_linkage_stops_at_the_pose_that_cannot_close():
    text = CRANK_ROCKER.replace("point C 0.3 0.3", "point C 0.3 0.1")
    with pytest.raises(AssemblyError, match=r"II\(2,3\)"):
        sweep(plan_of(text), steps=36)


def test_csv_has_one_row_per_pose(tmp_path):
    out = tmp_path / "sweep.csv"
    path = tmp_path / "m.edges"
    path.write_text(CRANK_ROCKER)
    assert main(["sweep", str(path), "--steps", "12", "--csv", str(out)]) == 0
    rows = list(csv.reader(io.StringIO(out.read_text())))
    assert len(rows) == 13
    header = rows[0]
    assert "3.omega" in header and "C.velocity.x" in header
    omega = [float(r[header.index("1.omega")]) for r in rows[1:]]
    assert omega == [10.0] * 12


def test_crank_slider_transmission_angle_is_smallest_with_the_crank_across_the_slide():
    # central crank–slider r = 0.1, l = 0.3: the rod's angle to the slide is asin(r·sinφ/l),
    # so μ = 90° − that, smallest (asin(1/3) from 90°) at φ = 90° and 270°
    text = """
driver 1 omega=1
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0.1 0
point C 0.4 0
"""
    result = sweep(plan_of(text), steps=360)
    (mu,) = result.transmission.values()
    assert mu.min() == pytest.approx(math.pi / 2 - math.asin(1 / 3), abs=1e-9)
    assert mu.max() == pytest.approx(math.pi / 2, abs=1e-12)


def test_balancing_moment_over_a_turn_matches_virtual_power():
    # a crank–slider against a constant 500 N on the slider: at every pose M_b·ω1 = −P·v_C
    text = """
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 P C angle=0
point A 0 0
point B 0.1 0
point C 0.4 0
force 3 C -500 0
"""
    result = sweep(plan_of(text), steps=90)
    (moment,) = result.balancing.values()
    v_c = result.points["C"]["velocity"][:, 0]
    np.testing.assert_allclose(moment * 10.0, 500.0 * v_c, atol=1e-9)


@pytest.mark.parametrize("name", ["scotch_yoke.edges", "inverted_crank_slider.edges"])
def test_slot_through_the_motion_transmits_at_right_angles(name):
    # a Scotch yoke's slot is square to its guide, and an inverted crank–slider's slot passes
    # through the slotted link's pivot: both transmit at 90° all the way round
    from structure.readwrite.edgelist import read_edgelist

    from ..conftest import FIXTURES

    result = sweep(make_plan(analyze(read_edgelist(FIXTURES / name))), steps=72)
    (mu,) = result.transmission.values()
    np.testing.assert_allclose(mu, np.pi / 2, atol=1e-9)


FIVEBAR = "fivebar_two_drivers.edges"


def _fivebar_plan():
    from ..conftest import FIXTURES

    return make_plan(analyze(read_edgelist(FIXTURES / FIVEBAR)))


def test_inputs_file_rows_columns_and_units():
    plan = _fivebar_plan()  # drivers 1 (turning) and 4 (turning)
    got = parse_inputs(["# two cranks", "drivers 4 1", "-2, 5", "", "-4 10  # a comment"], plan)
    want = np.radians([[5.0, -2.0], [10.0, -4.0]])  # columns back in the drivers' order
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-15)


def test_inputs_file_problems_are_named_by_line():
    plan = _fivebar_plan()
    with pytest.raises(EdgeListError) as err:
        parse_inputs(["drivers 1", "0 0", "5", "x y", "1 nan"], plan, "poses.txt")
    text = str(err.value)
    for expected in (
        "poses.txt: line 1: the drivers are 1, 4",
        "line 3: 1 value(s) for 2 driver(s)",
        "line 4: not a row of numbers",
        "line 5: not a row of numbers",
    ):
        assert expected in text
    with pytest.raises(EdgeListError, match="no inputs"):
        parse_inputs(["# nothing"], plan)


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.tuples(st.floats(-720, 720), st.floats(-720, 720)), min_size=1, max_size=12),
    st.sampled_from([", ", " ", "\t", " ,  "]),
    st.booleans(),
)
def test_inputs_file_round_trip(rows, separator, reversed_header):
    plan = _fivebar_plan()
    header = ["drivers 4 1"] if reversed_header else []
    lines = header + [
        separator.join(repr(v) for v in (row[::-1] if reversed_header else row)) for row in rows
    ]
    np.testing.assert_allclose(parse_inputs(lines, plan), np.radians(np.array(rows)), atol=1e-12)


def test_sweep_and_animate_take_an_inputs_file(tmp_path, capsys):
    # The five-bar cannot turn both cranks together through a whole turn; a
    # file gives the poses. Its rows in the other column order give the same sweep.
    from ..conftest import FIXTURES

    fixture = str(FIXTURES / FIVEBAR)
    (tmp_path / "a.txt").write_text("0 0\n5 -2\n10 -4\n")
    (tmp_path / "b.txt").write_text("drivers 4 1\n0 0\n-2 5\n-4 10\n")
    outputs = []
    for name in ("a", "b"):
        csv_path = tmp_path / f"{name}.csv"
        args = ["sweep", fixture, "--inputs", str(tmp_path / f"{name}.txt"), "--csv", str(csv_path)]
        assert main(args) == 0
        outputs.append(csv_path.read_text())
    assert outputs[0] == outputs[1]
    assert "3 poses of" in capsys.readouterr().out
    (tmp_path / "bad.txt").write_text("0 0\n5\n")
    assert main(["sweep", fixture, "--inputs", str(tmp_path / "bad.txt")]) == 1
    assert "bad.txt: line 2" in capsys.readouterr().err
    assert main(["sweep", fixture, "--inputs", str(tmp_path / "missing.txt")]) == 1
    assert "cannot read: No such file" in capsys.readouterr().err
    gif = tmp_path / "f.gif"
    assert main(["animate", fixture, str(gif), "--inputs", str(tmp_path / "a.txt")]) == 0
    from PIL import Image

    assert Image.open(gif).n_frames == 3


# ---------------------------------------------------------------- branch changes (issue 11)

PARALLELOGRAM = """
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0 0.2
point C 0.5 0.2
point D 0.5 0
"""


@pytest.mark.parametrize("steps", [7, 360])
def test_a_parallelogram_never_jumps_to_the_antiparallelogram_silently(steps):
    # crank AB = rocker DC = 0.2, coupler = frame = 0.5, crank at 90° in the sketch: all four
    # links come into line when the crank lies along the frame, at inputs 90° and 270°
    # (change points). Before them the parallelogram turns the rocker with the crank, ω3 = ω1.
    from kinematics.errors import BranchChangeError

    plan = plan_of(PARALLELOGRAM)
    with pytest.raises(BranchChangeError, match=r"II\(2,3\).* at input 90°") as err:
        sweep(plan, steps=steps)
    assert isinstance(err.value, AssemblyError)
    assert err.value.group == "II(2,3)"
    assert err.value.pose[0] == pytest.approx(math.pi / 2, abs=1e-6)
    # up to the change point the sweep is the parallelogram's: ω3 = 10 at every pose
    before = np.linspace(0.0, 2 * math.pi, steps, endpoint=False)
    before = before[before < math.pi / 2 - 1e-3]
    result = sweep(plan, before)
    np.testing.assert_allclose(result.links["3"]["omega"], 10.0, rtol=0, atol=1e-9)
    np.testing.assert_allclose(result.links["2"]["omega"], 0.0, rtol=0, atol=1e-9)


def test_a_deltoid_whose_outer_pins_meet_is_singular_not_too_short():
    # a kite: crank AB = frame AD = 0.3, coupler BC = rocker DC = 0.5; B meets D at input 270°
    s = 0.15 + math.sqrt(0.25 - 0.045) / math.sqrt(2)
    text = f"""
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0 0.3
point C {s!r} {s!r}
point D 0.3 0
"""
    from kinematics.errors import SingularPoseError

    for steps in (7, 360):
        with pytest.raises(SingularPoseError, match="singular pose at input 270°") as err:
            sweep(plan_of(text), steps=steps)
        assert "too short" not in str(err.value)
        assert "B and D coincide" in str(err.value)


@pytest.mark.parametrize("steps", [7, 36, 360])
def test_a_non_grashof_sweep_names_the_whole_range_it_cannot_assemble_in_degrees(steps):
    # a = 0.1 (crank), b = |BC| = √0.05, c = |CD| = √0.02, d = 0.4: the dyad stretches out
    # when |BD| = b + c, |BD|² = a² + d² − 2ad·cos φ: the dead points at ±φ0
    text = CRANK_ROCKER.replace("point C 0.3 0.3", "point C 0.3 0.1")
    b, c = math.sqrt(0.05), math.sqrt(0.02)
    phi0 = math.degrees(math.acos((0.01 + 0.16 - (b + c) ** 2) / 0.08))
    with pytest.raises(AssemblyError) as err:
        sweep(plan_of(text), steps=steps)
    message = str(err.value)
    low, high = (float(x) for x in re.findall(r"([\d.]+)°", message)[:2])
    # printed to 6 significant figures
    assert low == pytest.approx(phi0, abs=1e-3)
    assert high == pytest.approx(360 - phi0, abs=1e-3)
    assert "dead points" in message and "rad" not in message


def test_a_sweep_too_large_for_memory_is_refused_with_a_clear_message(tmp_path, capsys):
    from kinematics.errors import SweepSizeError

    with pytest.raises(SweepSizeError, match="30000000 poses"):
        sweep(plan_of(CRANK_ROCKER), steps=30_000_000)
    path = tmp_path / "m.edges"
    path.write_text(CRANK_ROCKER)
    assert main(["sweep", str(path), "--steps", "30000000"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("error: ") and "--steps" in err and "Traceback" not in err


# ---------------------------------------------------------------- what a sweep returns (issue 12)


def test_positions_only_sweep_gives_the_same_positions_and_nothing_more():
    plan = make_plan(analyze(read_edgelist(_fixture("jansen.edges"))))
    full = sweep(plan, steps=720)
    bare = sweep(plan, steps=720, rates=False)
    assert set(bare.points) == set(full.points)
    for name, values in bare.points.items():
        assert list(values) == ["position"]
        np.testing.assert_allclose(
            values["position"], full.points[name]["position"], rtol=0, atol=1e-15
        )
    for name, values in bare.links.items():
        assert list(values) == ["angle"]
        np.testing.assert_array_equal(values["angle"], full.links[name]["angle"])
    assert dict(bare.balancing) == {}


def test_sweep_points_share_one_block_and_ground_points_are_constants():
    plan = plan_of(CRANK_ROCKER)
    result = sweep(plan, steps=16)
    moving = [result.points[p]["position"] for p in "BC"]
    assert moving[0].base is not None and moving[0].base is moving[1].base
    a = result.points["A"]
    np.testing.assert_array_equal(a["position"], np.zeros((16, 2)))
    np.testing.assert_array_equal(a["velocity"], np.zeros((16, 2)))
    assert not a["position"].flags.writeable
    # the crank tip: B = A + 0.1·(cos φ, sin φ), v = 10·J·(B − A), a = −100·(B − A)
    phi = result.inputs[:, 0]
    r = 0.1 * np.column_stack([np.cos(phi), np.sin(phi)])
    np.testing.assert_allclose(result.points["B"]["position"], r, rtol=0, atol=1e-15)
    np.testing.assert_allclose(
        result.points["B"]["velocity"], 10 * np.column_stack([-r[:, 1], r[:, 0]]), atol=1e-14
    )
    np.testing.assert_allclose(result.points["B"]["acceleration"], -100 * r, atol=1e-13)


def test_link_angles_and_transmission_are_computed_when_first_read(monkeypatch):
    import kinematics.solvers.sweep as sweep_module

    calls = []
    real = sweep_module._angles
    monkeypatch.setattr(sweep_module, "_angles", lambda *a: calls.append(1) or real(*a))
    result = sweep(plan_of(CRANK_ROCKER), steps=36)
    assert calls == []
    assert len(result.transmission) == 1 and calls == [1]
    # the coupler's angle read lazily is the rotation of BC from the sketch
    b, c = result.points["B"]["position"], result.points["C"]["position"]
    bc = c - b
    turned = np.unwrap(np.arctan2(bc[:, 1], bc[:, 0]) - math.atan2(0.3, 0.2))
    np.testing.assert_allclose(result.links["2"]["angle"], turned, atol=1e-12)


def _fixture(name: str):
    from ..conftest import FIXTURES

    return FIXTURES / name


def test_a_kept_sweep_is_never_overwritten_by_the_next_one():
    # the next sweep may reuse the memory of a dropped one, never of one still held
    plan = make_plan(analyze(read_edgelist(_fixture("jansen.edges"))))
    kept = sweep(plan, steps=64)
    before = {name: {k: v.copy() for k, v in q.items()} for name, q in kept.points.items()}
    only_a_view = sweep(plan, steps=64).points["E"]["velocity"]
    snapshot = only_a_view.copy()
    for rates in (True, True, False):
        sweep(plan, np.linspace(1.0, 2.0, 64), rates=rates)  # dropped at once
    for name, values in kept.points.items():
        for key, array in values.items():
            np.testing.assert_array_equal(array, before[name][key])
    np.testing.assert_array_equal(only_a_view, snapshot)


def test_a_point_of_a_coupler_moves_rigidly_with_its_pins():
    # M rides on the coupler BC: its distances to B and C never change, and the
    # rigid-body relations hold: (v_M − v_B)·(M − B) = 0, (a_M − a_B)·(M − B) = −|v_M − v_B|²
    plan = make_plan(analyze(read_edgelist(_fixture("fourbar.edges"))))
    result = sweep(plan, steps=180)
    m, b, c = (result.points[p] for p in "MBC")
    for pin in (b, c):
        r = m["position"] - pin["position"]
        length = np.hypot(r[:, 0], r[:, 1])
        np.testing.assert_allclose(length, length[0], rtol=1e-12)
        dv = m["velocity"] - pin["velocity"]
        da = m["acceleration"] - pin["acceleration"]
        scale = length[0] * np.abs(dv).max()
        np.testing.assert_allclose(np.einsum("ij,ij->i", dv, r), 0.0, atol=1e-12 * scale)
        np.testing.assert_allclose(
            np.einsum("ij,ij->i", da, r), -np.einsum("ij,ij->i", dv, dv), atol=1e-11 * scale**2
        )
