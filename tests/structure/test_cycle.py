"""Loads over the cycle in the edge list and in JSON (structure.cycle): read, checked, written."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from structure.cycle import CycleLoadKind, LawKind, law_from_token, make_law
from structure.errors import EdgeListError, StatementError
from structure.readwrite.edgelist import parse_edgelist, write_edgelist
from structure.readwrite.jsonformat import mechanism_from_json, mechanism_to_json

SLIDER = [
    "driver 1 omega=10",
    "0 1 R A",
    "1 2 R B",
    "2 3 R C",
    "3 0 P C angle=0",
    "point A 0 0",
    "point B 0 0.1",
    "point C 0.3 0",
]


def _read(*extra: str):
    return parse_edgelist([*SLIDER, *extra], "t.edges")


def test_each_statement_reads_into_its_record() -> None:
    m = _read(
        "drive 1 motor=40,150",
        "cycle force 3 C angle=180 table=0:0,180:0,180:-500,340:-500,360:0",
        "cycle moment 2 formula=-2*sin(phi)",
        "cycle moment 3 -1.5",
    )
    drive, force, moment, constant = m.cycle_loads
    assert (drive.kind, drive.link, drive.law.kind, drive.law.numbers) == (
        CycleLoadKind.DRIVE, "1", LawKind.MOTOR, (40.0, 150.0))  # fmt: skip
    assert (force.point, force.angle_deg) == ("C", 180.0)
    assert force.law.points[2] == (180.0, -500.0)
    assert moment.law.formula.text == "-2*sin(phi)" and not moment.law.uses_omega
    assert drive.law.uses_omega
    assert constant.law.numbers == (-1.5,)


def test_edge_list_and_json_round_trip() -> None:
    m = _read(
        "drive 1 table=0:10,90:12.5,360:10",
        "cycle force 3 C angle=-90.5 formula=-200*step(sin(phi))*(1+omega/100)",
        "cycle moment 2 value=3",
    )
    text = write_edgelist(m)
    assert "cycle moment 2 3" in text  # value=3 is written as the plain number
    again = parse_edgelist(text.splitlines())
    assert again.cycle_loads == m.cycle_loads
    back = mechanism_from_json(mechanism_to_json(m))
    assert back.cycle_loads == m.cycle_loads
    data = json.loads(mechanism_to_json(m))
    assert data["drive"] == {"link": "1", "table": [[0.0, 10.0], [90.0, 12.5], [360.0, 10.0]]}
    assert data["cycle"][0]["kind"] == "force" and data["cycle"][0]["angle"] == -90.5


@pytest.mark.parametrize(
    ("line", "said"),
    [
        ("drive 1", "expected 'drive LINK LAW'"),
        ("drive 1 motor=40", "motor curve is motor=M0,W0"),
        ("drive 1 motor=40,0", "W0 cannot be 0"),
        ("drive 2 40", "the drive acts on a driver: 2 is not one"),
        ("drive 9 40", "drive on unknown link 9"),
        ("cycle moment 0 5", "on the ground does nothing"),
        ("cycle moment 3 motor=1,2", "a motor curve is the drive's"),
        ("cycle force 3 C 5", "expected 'cycle force LINK POINT angle=DEG LAW'"),
        ("cycle force 3 C angle=x 5", "angle= must be a number"),
        ("cycle torque 3 5", "expected 'cycle moment LINK LAW'"),
        ("cycle moment 3 table=0:1,90", "angle:value"),
        ("cycle moment 3 table=90:1,0:2", "increasing order"),
        ("cycle moment 3 table=0:1,400:2", "from 0 to 360"),
        ("cycle moment 3 table=0:1,90:2,90:3,90:4", "three times"),
        ("cycle moment 3 table=0:1,360:2", "values at 0° and 360° must agree"),
        ("cycle moment 3 formula=2*x", "unknown name 'x'"),
        ("cycle moment 3 nan", "must be a finite number"),
        ("cycle moment 3 1e200", "beyond ±1e+150"),
        ("cycle moment 3 speed=4", "a load over the cycle is a number"),
    ],
)
def test_bad_lines_are_named_with_their_line(line: str, said: str) -> None:
    with pytest.raises(EdgeListError) as info:
        _read(line)
    problem = info.value.problems[0]
    assert problem.line_no == len(SLIDER) + 1
    assert said in problem.reason


def test_a_second_drive_is_refused() -> None:
    with pytest.raises(EdgeListError, match="already given on line 9"):
        _read("drive 1 40", "drive 1 motor=40,100")


@pytest.mark.parametrize(
    ("data", "said"),
    [
        ({"drive": {"link": "1", "value": 1, "motor": [1, 2]}}, "needs one of"),
        ({"drive": {"link": "1"}}, "needs one of"),
        ({"drive": {"link": "1", "torque": 3}}, "unknown keys ['torque']"),
        ({"drive": [1]}, "must be an object"),
        ({"cycle": {"a": 1}}, "cycle: must be a list"),
        ({"cycle": [{"kind": "push", "link": "3", "value": 1}]}, "'kind' must be moment or force"),
        ({"cycle": [{"kind": "moment", "link": "3", "table": [1, 2]}]}, "[angle, value] pairs"),
        ({"cycle": [{"kind": "moment", "link": "3", "value": "1"}]}, "finite numbers"),
        ({"cycle": [{"kind": "moment", "link": "3", "formula": 3}]}, "must be a string"),
        ({"cycle": [{"kind": "force", "link": "3", "value": 1}]}, "'point' must be"),
        ({"cycle": [{"kind": "force", "link": "3", "point": "C", "value": 1}]}, "'angle'"),
        ({"cycle": [{"kind": "moment", "link": "3", "value": 10**400}]}, "finite numbers"),
    ],
)
def test_bad_json_is_named_by_its_path(data: dict, said: str) -> None:
    base = json.loads(mechanism_to_json(_read()))
    with pytest.raises(EdgeListError) as info:
        mechanism_from_json(json.dumps({**base, **data}), "t.json")
    assert said in str(info.value)


def test_law_checks() -> None:
    assert make_law("table", (0, 1, 180, 1, 180, 5)).points[-1] == (180.0, 5.0)  # a jump
    with pytest.raises(StatementError, match="unknown law"):
        make_law("spline", (1,))
    assert law_from_token("-3.5").numbers == (-3.5,)


_NUMBER = st.floats(-1e6, 1e6, allow_nan=False).map(lambda x: round(x, 3))


@st.composite
def _laws(draw) -> str:
    kind = draw(st.sampled_from(["value", "motor", "table", "formula"]))
    if kind == "value":
        return repr(draw(_NUMBER))
    if kind == "motor":
        w0 = draw(_NUMBER.filter(lambda x: x != 0))
        return f"motor={draw(_NUMBER)!r},{w0!r}"
    if kind == "table":
        angles = sorted(draw(st.lists(st.integers(0, 359), min_size=1, max_size=6, unique=True)))
        return "table=" + ",".join(f"{a}:{draw(_NUMBER)!r}" for a in angles)
    return "formula=" + draw(st.sampled_from(["-20*sin(phi)", "1+omega^2", "step(phi-pi)*5"]))


@settings(max_examples=60, deadline=None)
@given(_laws(), st.sampled_from(["moment", "force"]))
def test_any_law_round_trips_through_both_formats(law: str, kind: str) -> None:
    where = "3 C angle=30" if kind == "force" else "3"
    line = f"drive 1 {law}" if law.startswith("motor") else f"cycle {kind} {where} {law}"
    m = _read(line)
    assert parse_edgelist(write_edgelist(m).splitlines()).cycle_loads == m.cycle_loads
    assert mechanism_from_json(mechanism_to_json(m)).cycle_loads == m.cycle_loads
