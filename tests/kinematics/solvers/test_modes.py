"""Assembly modes of every group, and choosing one (issue 22, item 14).

``--flip`` could choose a dyad's mode only, and its message for any other
group was cut short. The modes of the eight-bar's class III triad are
counted here by a scan of its base link's angle written out in the test
(circle intersections), and every mode listed is checked against the
triad's link lengths; a flipped triad then sweeps on from its mode.
"""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest

from kinematics.cli.commands import main
from kinematics.errors import AssemblyModeError
from kinematics.solvers.plan import make_plan, parse_flip
from kinematics.solvers.solve import assembly_modes, solve_pose
from kinematics.solvers.sweep import sweep
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES

EIGHTBAR = FIXTURES / "eightbar_triad.edges"
TRIAD = "III(4,5,6,7)"


def sketch(name: str) -> np.ndarray:
    return np.array(read_edgelist(str(EIGHTBAR)).coordinates(name))


def rotation(phi: float) -> np.ndarray:
    return np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])


def triad_closures() -> list[float]:
    """The base link 5's turns from the sketch at which the triad closes, by a scan.

    The base carries T45, T56, T57; leads 4 (E–T45), 6 (G–T56), 7 (H–T57), with E, G,
    H where the sketch puts them. Turned by φ, T45 lies on the circle about E and on
    the circle about G − R(φ)·(T56 − T45) (both of the leads' lengths): two points, one
    on each side; the triad closes where T57 = T45 + R(φ)·(T57 − T45) lies at lead 7's
    length from H.
    """
    e, g, h = sketch("E"), sketch("G"), sketch("H")
    p1, p2, p3 = sketch("T45"), sketch("T56"), sketch("T57")
    l1, l2, l3 = np.linalg.norm(p1 - e), np.linalg.norm(p2 - g), np.linalg.norm(p3 - h)

    def miss(phi: np.ndarray, side: float) -> np.ndarray:
        c, s = np.cos(phi), np.sin(phi)
        d12, d13 = p2 - p1, p3 - p1
        centre = g[:, None] - np.array([c * d12[0] - s * d12[1], s * d12[0] + c * d12[1]])
        w = centre - e[:, None]
        d = np.hypot(*w)
        a = (l1**2 - l2**2 + d**2) / (2 * d)
        height = np.sqrt(np.where(l1**2 - a**2 >= 0, l1**2 - a**2, np.nan))
        t45 = e[:, None] + (a * w + side * height * np.array([-w[1], w[0]])) / d
        t57 = t45 + np.array([c * d13[0] - s * d13[1], s * d13[0] + c * d13[1]])
        return np.hypot(*(t57 - h[:, None])) - l3

    grid = np.linspace(-math.pi, math.pi, 7201)
    roots: list[float] = []
    for side in (1.0, -1.0):
        f = miss(grid, side)
        crossing = np.isfinite(f[:-1]) & np.isfinite(f[1:]) & ((f[:-1] * f[1:] < 0) | (f[:-1] == 0))
        roots += grid[:-1][crossing].tolist()
    return roots


def test_the_triad_has_as_many_modes_as_its_closure_has_roots():
    modes = assembly_modes(make_plan(analyze(read_edgelist(str(EIGHTBAR)))))
    roots = triad_closures()
    assert len(modes[TRIAD]) == len(roots) == 4
    found = sorted(math.remainder(float(m.poses["5"][2]), 2 * math.pi) for m in modes[TRIAD])
    assert found == pytest.approx(sorted(roots), abs=2 * math.pi / 7200)
    assert len(modes["II(2,3)"]) == 2


def test_every_mode_listed_keeps_the_triads_lengths_and_mode_0_is_the_sketch():
    modes = assembly_modes(make_plan(analyze(read_edgelist(str(EIGHTBAR)))))[TRIAD]
    pairs = [("E", "T45"), ("G", "T56"), ("H", "T57"), ("T45", "T56"), ("T56", "T57")]
    for mode in modes:
        for a, b in pairs:
            length = np.linalg.norm(sketch(a) - sketch(b))
            assert np.linalg.norm(mode.pins[a] - mode.pins[b]) == pytest.approx(length, rel=1e-9)
    for name in ("T45", "T56", "T57"):
        np.testing.assert_allclose(modes[0].pins[name], sketch(name), atol=1e-12)
    # numbered outward: each mode's pins lie farther from the sketch's than the one before
    far = [sum(np.linalg.norm(m.pins[n] - sketch(n)) for n in ("T45", "T56", "T57")) for m in modes]
    assert far == sorted(far)


def test_a_flipped_triad_is_solved_and_swept_in_its_mode():
    report = analyze(read_edgelist(str(EIGHTBAR)))
    listed = assembly_modes(make_plan(report))[TRIAD]
    for flip, k in ((TRIAD, 1), (f"{TRIAD}=1", 1), (f"{TRIAD}=3", 3)):
        plan = make_plan(report, flip=[flip])
        state = solve_pose(plan)
        for name in ("T45", "T56", "T57"):
            np.testing.assert_allclose(
                state.points[name].position, listed[k].pins[name], atol=1e-12
            )
    # mode 1 sweeps on from there: the lengths hold at every pose, the first is the mode's
    result = sweep(make_plan(report, flip=[TRIAD]), np.radians(np.arange(0.0, 30.0, 2.0)))
    t45, e = result.points["T45"]["position"], result.points["E"]["position"]
    np.testing.assert_allclose(
        np.linalg.norm(t45 - e, axis=1), np.linalg.norm(sketch("T45") - sketch("E")), rtol=1e-9
    )
    np.testing.assert_allclose(t45[0], listed[1].pins["T45"], atol=1e-12)


def test_a_class_iv_group_lists_its_modes_and_each_closes():
    path = FIXTURES / "class4_group.edges"
    m = read_edgelist(str(path))
    modes = assembly_modes(make_plan(analyze(m)))["IV(2,3,4,5)"]
    assert len(modes) >= 2
    pairs = [
        ("B", "K23"),
        ("K23", "K34"),
        ("K34", "K45"),
        ("K45", "K25"),
        ("K25", "B"),
        ("K45", "G"),
    ]
    for mode in modes:
        for a, b in pairs:
            length = math.dist(m.coordinates(a), m.coordinates(b))
            assert np.linalg.norm(mode.pins[a] - mode.pins[b]) == pytest.approx(length, rel=1e-9)
    state = solve_pose(make_plan(analyze(m), flip=["IV(2,3,4,5)"]))
    np.testing.assert_allclose(state.points["K34"].position, modes[1].pins["K34"], atol=1e-12)


def test_modes_asked_for_that_a_group_lacks_are_named_errors():
    report = analyze(read_edgelist(str(EIGHTBAR)))
    with pytest.raises(AssemblyModeError, match=r"has 4 assembly modes .* 0 to 3 .* no mode 4"):
        solve_pose(make_plan(report, flip=[f"{TRIAD}=4"]))
    with pytest.raises(
        AssemblyModeError, match=r"II\(2,3\), a dyad \(RRR\), has two assembly modes"
    ):
        make_plan(report, flip=["II(2,3)=2"])
    with pytest.raises(
        ValueError, match=r"cannot flip X: the groups are II\(2,3\), III\(4,5,6,7\)"
    ):
        make_plan(report, flip=["X"])
    with pytest.raises(ValueError, match="number of an assembly mode"):
        parse_flip(["II(2,3)=one"])
    tangent = analyze(read_edgelist(str(FIXTURES / "ch2_2_3_tangent.edges")))
    with pytest.raises(AssemblyModeError, match=r"a dyad \(PRP\), has a single assembly mode"):
        make_plan(tangent, flip=["II(2,3)"])


def test_the_command_lists_the_modes_and_flips_a_triad(capsys):
    assert main(["kinematics", str(EIGHTBAR), "--modes", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)["modes"]
    assert [m["mode"] for m in listed[TRIAD]] == [0, 1, 2, 3]
    assert main(["kinematics", str(EIGHTBAR), "--flip", f"{TRIAD}=2", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["points"]["T45"]["position"] == pytest.approx(listed[TRIAD][2]["pins"]["T45"])
    assert main(["kinematics", str(EIGHTBAR), "--flip", TRIAD, "--exact"]) == 2
    assert "--exact solves the sketch pose" in capsys.readouterr().err
    assert main(["kinematics", str(EIGHTBAR), "--flip", f"{TRIAD}=9"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("error: group III(4,5,6,7) has 4 assembly modes") and "mode 9" in err
    assert main(["kinematics", str(FIXTURES / "fourbar.edges"), "--flip", "II(9,9)"]) == 2
    assert "the groups are II(2,3)" in capsys.readouterr().err


@pytest.mark.parametrize("k", [1e-300, 1e120])
def test_the_modes_are_the_same_in_any_unit_of_length(k):
    m = read_edgelist(str(EIGHTBAR))
    points = {n: dataclasses.replace(p, x=p.x * k, y=p.y * k) for n, p in m.points.items()}
    far = assembly_modes(make_plan(analyze(dataclasses.replace(m, points=points))))[TRIAD]
    near = assembly_modes(make_plan(analyze(m)))[TRIAD]
    assert len(far) == len(near)
    for a, b in zip(far, near, strict=True):
        for name in ("T45", "T56", "T57"):
            np.testing.assert_allclose(a.pins[name] / k, b.pins[name], rtol=1e-9, atol=1e-12)
