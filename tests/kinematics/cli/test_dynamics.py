"""``assur dynamics`` and ``assur balance``: the answers, the JSON contract, files, errors."""

from __future__ import annotations

import json
import math

import pytest

from structure.readwrite.edgelist import read_edgelist

from .conftest import fixture, run

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from ...conftest import FIXTURES

with (FIXTURES / "dynamics.toml").open("rb") as _handle:
    TABLE = tomllib.load(_handle)


def _strict(text: str):
    def refuse(constant: str):
        raise ValueError(f"{constant} in the JSON")

    return json.loads(text, parse_constant=refuse)


def _json(capsys, *argv: str):
    code, out, err = run(capsys, *argv, "--json")
    return code, _strict(out), err


def test_the_json_keys_are_the_contract(capsys):
    code, data, err = _json(capsys, "dynamics", fixture("press_flywheel"))
    assert (code, err) == (0, "")
    inertia, moment = data["reduced_inertia"], data["reduced_moment"]
    assert len(inertia["phi_deg"]) == len(inertia["J"]) == len(inertia["dJ"]) == 361
    assert inertia["phi_deg"][0] == 0 and inertia["phi_deg"][-1] == 360
    assert len(moment["phi_deg"]) == len(moment["M"]) == 361
    steady = data["steady"]
    assert len(steady["omega"]) == len(steady["phi_deg"]) == 361
    assert {"omega_mean", "delta"} <= set(steady) and steady["mean"] == "(omega_max + omega_min)/2"
    wheel = data["flywheel"]
    assert {"delta_goal", "J_exact", "J_approx"} <= set(wheel) and wheel["delta_goal"] == 0.02
    shaking = data["shaking"]
    assert {"force_max", "moment_max"} <= set(shaking)
    assert len(shaking["fx"]) == len(shaking["fy"]) == len(shaking["m"]) == 361
    assert data["start_up"]["ending"] == "steady" and data["run_down"]["ending"] == "stopped"


def test_the_press_runs_at_the_motor_s_speed(capsys):
    """The mean load torque and the motor's slip, by hand (fixtures/dynamics.toml)."""
    expected = TABLE["press_flywheel"]
    _, data, _ = _json(capsys, "dynamics", fixture("press_flywheel"))
    mean = -data["reduced_moment"]["mean_loads"]
    assert mean == pytest.approx(expected["mean_load_torque"], rel=1e-9)
    assert data["steady"]["omega_time_mean"] == pytest.approx(
        expected["mean_speed_first_order"], rel=0.01
    )
    assert data["flywheel"]["delta_check"] == pytest.approx(0.02, rel=1e-5)


def test_khurmi_s_engine(capsys):
    expected = TABLE["engine_three_crank"]
    _, data, _ = _json(capsys, "dynamics", fixture("engine_three_crank"))
    assert data["steady"]["delta"] == pytest.approx(expected["delta"], rel=1e-9)
    assert data["steady"]["power"] == pytest.approx(expected["power"], rel=1e-3)
    assert data["flywheel"]["J_exact"] == 0  # 360 kg·m² hold δ within 0.02 already
    _, data, _ = _json(
        capsys,
        "dynamics",
        fixture("engine_three_crank"),
        "--delta",
        str(expected["flywheel_delta"]),
    )
    assert data["flywheel"]["J_exact"] == pytest.approx(expected["flywheel_exact"], rel=1e-9)
    assert data["flywheel"]["J_approx"] == pytest.approx(expected["flywheel_approx"], rel=1e-9)


def test_problem_3_2_and_the_exam_s_train(capsys):
    _, data, _ = _json(capsys, "dynamics", fixture("ch3_3_2_flywheel"))
    assert set(data["inertia_torque"]["M"]) == {TABLE["ch3_3_2_flywheel"]["inertia_torque"]}
    _, data, _ = _json(capsys, "dynamics", fixture("exam_2_planetary"))
    num, den = map(int, TABLE["exam_2_planetary"]["reduced_inertia"].split("/"))
    assert data["reduced_inertia"]["J"][0] == pytest.approx(num / den, rel=1e-15)
    assert any("massless" in note for note in data["notes"])


def test_no_mass_data_is_said_in_one_line(capsys):
    code, out, err = run(capsys, "dynamics", fixture("fourbar"))
    assert code == 0 and err == ""
    said = [line for line in out.splitlines() if "no mass data" in line]
    assert len(said) == 1 and "massless" in said[0]
    code, data, _ = _json(capsys, "dynamics", fixture("fourbar"))
    assert data["steady"] is None and data["flywheel"] is None and data["shaking"] is None


@pytest.mark.parametrize(
    ("name", "said"),
    [
        ("fivebar_two_drivers", "W = 2"),
        ("cam_flat_follower", "sketch pose only"),
        ("ch3_3_1_slider_power", "slides"),
    ],
)
def test_what_has_no_dynamics_is_a_named_error(capsys, name: str, said: str):
    code, out, err = run(capsys, "dynamics", fixture(name))
    assert code == 1 and out == "" and said in err and err.startswith("error:")
    code, data, _ = _json(capsys, "dynamics", fixture(name))
    assert code == 1 and said in data["error"]


def test_a_weak_drive_says_where_it_stalls(capsys):
    code, _, err = run(capsys, "dynamics", fixture("press_flywheel"), "--drive", "motor=40,10.5")
    assert code == 1 and "stops at φ = " in err and "on average" in err


@pytest.mark.parametrize(
    ("options", "said"),
    [
        (["--delta", "0"], "--delta"),
        (["--delta", "nan"], "--delta"),
        (["--omega", "-3"], "--omega"),
        (["--steps", "3"], "--steps"),
        (["--drive", "motor=1"], "--drive"),
        (["--drive", "eval(1)"], "--drive"),
    ],
)
def test_bad_options_are_usage_errors(capsys, options: list[str], said: str):
    code, _, err = run(capsys, "dynamics", fixture("press_flywheel"), *options)
    assert code == 2 and said in err


def test_the_drive_option_takes_a_law(capsys):
    code, data, _ = _json(capsys, "dynamics", fixture("engine_three_crank"), "--drive", "none")
    assert code == 1 and "falls short of the loads' by 25000 N·m on average" in data["error"]
    _, data, _ = _json(capsys, "dynamics", fixture("press_flywheel"), "--drive", "motor=2200,10.5")
    assert data["steady"]["omega_time_mean"] > 10


def test_plot_and_explain(capsys, tmp_path):
    out = tmp_path / "press.png"
    code, said, _ = run(capsys, "dynamics", fixture("press_flywheel"), "--plot", str(out))
    assert code == 0 and out.stat().st_size > 10_000
    for lang, word in (("en", "Wittenbauer"), ("vi", "bánh đà")):
        code, said, _ = run(
            capsys, "dynamics", fixture("press_flywheel"), "--explain", "--lang", lang
        )
        assert code == 0 and word in said


def test_balance_writes_the_counterweights(capsys, tmp_path):
    expected = TABLE["fourbar_masses"]
    out = tmp_path / "balanced.edges"
    code, data, _ = _json(capsys, "balance", fixture("fourbar_masses"), "-o", str(out))
    assert code == 0 and data["method"] == "complete" and data["output"] == str(out)
    assert data["after"]["force_max"] <= 1e-9 * data["before"]["force_max"]
    for got, want in zip(data["counterweights"], expected["counterweights"], strict=True):
        assert got["link"] == want["link"]
        assert got["mass"] == pytest.approx(want["mass"], rel=1e-12)
        assert got["position"] == pytest.approx(want["position"], abs=1e-12)
    balanced = read_edgelist(out)
    masses = [x for x in balanced.loads if x.kind == "mass" and x.point.startswith("CW")]
    assert [(x.link, x.values) for x in masses] == [("1", (1.5, 0.0)), ("3", (1.75, 0.0))]
    assert balanced.cycle_loads == read_edgelist(fixture("fourbar_masses")).cycle_loads
    code, text, _ = run(capsys, "balance", str(out))
    assert code == 0 and "No counterweight is needed." in text


def test_balance_never_writes_over_its_input(capsys, tmp_path):
    source = tmp_path / "m.edges"
    source.write_text((FIXTURES / "fourbar_masses.edges").read_text(encoding="utf-8"), "utf-8")
    before = source.read_text(encoding="utf-8")
    code, _, err = run(capsys, "balance", str(source), "-o", str(source))
    assert code == 2 and "is the file read" in err
    assert source.read_text(encoding="utf-8") == before
    code, _, err = run(capsys, "balance", str(source), "-o", str(tmp_path / "m.txt"))
    assert code == 2 and ".edges" in err


def test_balance_of_a_crank_slider_names_its_harmonics(capsys):
    code, out, _ = run(capsys, "balance", fixture("press_flywheel"), "--fraction", "1")
    assert code == 0 and "primary (1st harmonic)" in out and "Lanchester" in out
    code, data, _ = _json(capsys, "balance", fixture("press_flywheel"), "--fraction", "1")
    assert data["after"]["harmonics"]["primary"] == pytest.approx(0, abs=1e-9)
    assert math.isclose(
        data["before"]["harmonics"]["secondary"], data["after"]["harmonics"]["secondary"]
    )
    code, _, err = run(capsys, "balance", fixture("fourbar"))
    assert code == 1 and "no mass data" in err
