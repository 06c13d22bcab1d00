"""Tests of pylinkage's JSON linkages (structure.readwrite.pylinkage).

The JSON written by pylinkage itself (when installed) is read, classified and
solved: our positions equal the ones pylinkage steps to. Hand-written JSON in
both of its formats covers sliders, trackers, ternary links and the errors.
"""

from __future__ import annotations

import contextlib
import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_pose
from structure.errors import EdgeListError
from structure.readwrite.formats import read_mechanism
from structure.readwrite.jsonformat import mechanism_to_json
from structure.readwrite.pylinkage import is_pylinkage, mechanism_from_pylinkage, parse_pylinkage
from structure.report import analyze
from tests.conftest import FIXTURES

FOURBAR = {
    "name": "fourbar",
    "ground": "ground",
    "joints": [
        {"id": "A", "type": "ground", "position": [0.0, 0.0]},
        {"id": "B", "type": "revolute", "position": [0.0, 1.0]},
        {"id": "C", "type": "revolute", "position": [3.0, 2.0]},
        {"id": "D", "type": "ground", "position": [3.0, 0.0]},
        {"id": "P", "type": "revolute", "position": [1.0, 2.5]},
        {
            "id": "T",
            "type": "tracker",
            "ref_joint1_id": "B",
            "ref_joint2_id": "C",
            "distance": 1.0,
            "angle": 0.0,
        },
    ],
    "links": [
        {"id": "ground", "type": "ground", "joints": ["A", "D"]},
        {"id": "crank", "type": "driver", "joints": ["A", "B"], "motor_joint": "A"},
        {"id": "coupler", "type": "link", "joints": ["B", "C", "P"]},
        {"id": "rocker", "type": "link", "joints": ["C", "D"]},
    ],
}

SLIDER_CRANK = {
    "name": "slider-crank",
    "joints": [
        {"id": "O", "type": "ground", "position": [0.0, 0.0]},
        {"id": "B", "type": "revolute", "position": [0.0, 1.0]},
        {
            "id": "S",
            "type": "prismatic",
            "position": [3.0, 0.2],
            "axis": [2.0, 0.0],
            "line_point": [0.0, 0.2],
        },
    ],
    "links": [
        {"id": "ground", "type": "ground", "joints": ["O"]},
        {"id": "crank", "type": "driver", "joints": ["O", "B"], "motor_joint": "O"},
        {"id": "rod", "type": "link", "joints": ["B", "S"]},
    ],
}

# the older linkage format: joints that imply their bars
LEGACY = {
    "name": "legacy",
    "joints": [
        {"type": "Static", "name": "A", "x": 0.0, "y": 0.0},
        {"type": "Crank", "name": "B", "x": 0.0, "y": 1.0, "joint0": {"ref": "A"}},
        {
            "type": "Revolute",
            "name": "C",
            "x": 3.0,
            "y": 2.0,
            "joint0": {"ref": "B"},
            "joint1": {"inline": True, "type": "Static", "x": 3.0, "y": 0.0, "name": "D"},
        },
        {
            "type": "Fixed",
            "name": "E",
            "x": 1.0,
            "y": 2.5,
            "joint0": {"ref": "B"},
            "joint1": {"ref": "C"},
        },
        {"type": "Static", "name": "G1", "x": 0.0, "y": 3.0},
        {"type": "Static", "name": "G2", "x": 5.0, "y": 3.0},
        {
            "type": "Prismatic",
            "name": "F",
            "x": 2.0,
            "y": 3.0,
            "joint0": {"ref": "E"},
            "joint1": {"ref": "G1"},
            "joint2": {"ref": "G2"},
        },
    ],
}


def test_the_mechanism_format_maps_links_joints_and_trackers():
    m = mechanism_from_pylinkage(FOURBAR, "fourbar.json")
    assert [p.statement for p in m.pairs] == [
        "ground crank R A",
        "crank coupler R B",
        "coupler rocker R C",
        "ground rocker R D",
    ]
    assert m.driver_links == ("crank",)
    assert (m.points["P"].on, m.points["T"].on) == ("coupler", "coupler")
    assert m.coordinates("T") == pytest.approx((1 / 10**0.5 * 3, 1 + 1 / 10**0.5))
    assert analyze(m).formula == "I(crank) → II(coupler,rocker)"


def test_a_prismatic_joint_is_a_block_sliding_on_the_frame():
    m = mechanism_from_pylinkage(SLIDER_CRANK)
    assert [p.statement for p in m.pairs] == [
        "ground crank R O",
        "crank rod R B",
        "rod block_S R S",
        "ground block_S P S angle=0",
    ]
    assert analyze(m).formula == "I(crank) → II(rod,block_S)"


def test_the_older_linkage_format_merges_bars_into_bodies():
    m = mechanism_from_pylinkage(LEGACY)
    report = analyze(m)
    # bars B–C (Revolute) and B, C, E (Fixed) are one ternary coupler
    assert len(m.moving_links) == 5 and m.driver_links == ("1",)
    assert report.formula == "I(1) → II(2,3) → II(4,block_F)"
    assert {p.statement for p in m.pairs if p.kind.value == "P"} == {"0 block_F P F angle=0"}


def test_our_positions_follow_the_sketch_as_pylinkage_would():
    """Turn the crank of the hand-written four-bar: its rocker keeps the lengths."""
    plan = make_plan(analyze(mechanism_from_pylinkage(FOURBAR)))
    state = solve_pose(plan, (-0.3,))
    b, c = state.points["B"].position, state.points["C"].position
    assert float(((c - b) ** 2).sum()) == pytest.approx(10.0)
    assert float(((c - [3.0, 0.0]) ** 2).sum()) == pytest.approx(4.0)


def test_json_written_by_pylinkage_is_read_and_solved_like_pylinkage():
    mechanism_module = pytest.importorskip("pylinkage.mechanism")
    omega = 0.1
    for built in (
        mechanism_module.fourbar(1.0, 3.0, 3.0, 4.0, omega=omega, initial_angle=1.0),
        mechanism_module.slider_crank(1.0, 3.0, omega=omega, initial_angle=0.5),
    ):
        data = json.loads(json.dumps(mechanism_module.mechanism_to_dict(built)))
        ids = [joint.id for joint in built.joints]
        plan = make_plan(analyze(mechanism_from_pylinkage(data)))
        for step, positions in enumerate(built.step(iterations=3), start=1):
            state = solve_pose(plan, (step * omega,))
            for joint, xy in zip(ids, positions, strict=True):
                assert state.points[joint].position == pytest.approx(xy, abs=1e-9)


def test_read_mechanism_tells_pylinkage_json_from_ours(tmp_path):
    theirs = tmp_path / "theirs.json"
    theirs.write_text(json.dumps(SLIDER_CRANK), encoding="utf-8")
    ours = tmp_path / "ours.json"
    ours.write_text(mechanism_to_json(read_mechanism(FIXTURES / "fourbar.edges")), "utf-8")
    assert read_mechanism(theirs).ground == "ground"
    assert mechanism_to_json(read_mechanism(ours)) == mechanism_to_json(
        read_mechanism(FIXTURES / "fourbar.edges")
    )
    assert is_pylinkage(SLIDER_CRANK) and not is_pylinkage({"pairs": [], "joints": []})


@pytest.mark.parametrize(
    ("change", "reason"),
    [
        (lambda d: d["joints"].append({"id": "X", "type": "ball"}), "unknown joint type 'ball'"),
        (lambda d: d["joints"][1].pop("position"), "joint B: 'position' must be [x, y]"),
        (lambda d: d["links"][2]["joints"].append("Z"), "links[2]: unknown joint(s) Z"),
        (lambda d: d["joints"][2].update(line_point=[0, 1]), "joint S: the joint is 0.8 off"),
        (lambda d: d["joints"][2].update(axis=[0, 0]), "joint S: the slide direction is zero"),
        (lambda d: d["links"].append({"id": "x", "type": "gear"}), "unknown link type 'gear'"),
    ],
)
def test_problems_of_the_mechanism_format_are_named(change, reason):
    data = json.loads(json.dumps(SLIDER_CRANK))
    change(data)
    with pytest.raises(EdgeListError) as info:
        mechanism_from_pylinkage(data, "bad.json")
    assert any(reason in p.reason for p in info.value.problems), info.value


@pytest.mark.parametrize(
    ("change", "reason"),
    [
        (lambda d: d["joints"][1].update(joint0={"ref": "Q"}), "joint B (Crank): joint0"),
        (lambda d: d["joints"][0].update(x=None), "joint A: 'x' and 'y' must be finite"),
        (lambda d: d["joints"][0].update(type="Gear"), "joints[0]: 'type' must be one of"),
        (lambda d: d["joints"][6].update(y=3.5), "joint F: the joint is 0.5 off"),
    ],
)
def test_problems_of_the_linkage_format_are_named(change, reason):
    data = json.loads(json.dumps(LEGACY))
    change(data)
    with pytest.raises(EdgeListError) as info:
        mechanism_from_pylinkage(data, "bad.json")
    assert any(reason in p.reason for p in info.value.problems), info.value


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        pytest.param(
            json.dumps({**FOURBAR, "links": True}),
            "'links' must be a list of link objects",
            id="links-true",
        ),
        pytest.param(
            json.dumps(FOURBAR).replace("[3.0, 0.0]", "[3" + "0" * 400 + ", 0.0]", 1),
            "joint D: 'position' must be [x, y], finite numbers within ±1e+150",
            id="401-digits",
        ),
        pytest.param(
            json.dumps(FOURBAR).replace("[3.0, 0.0]", "[3e200, 0.0]", 1),
            "joint D: 'position' must be [x, y], finite numbers within ±1e+150",
            id="beyond-1e150",
        ),
    ],
)
def test_values_that_crashed_the_reader_are_named(text, reason):
    """Issue 22, item 5: ``"links": true`` (TypeError) and a 401-digit integer
    (OverflowError) ended ``assur convert`` with exit 3."""
    with pytest.raises(EdgeListError) as info:
        parse_pylinkage(text, "x.json")
    assert any(reason in p.reason for p in info.value.problems), info.value


def test_text_that_is_not_json_or_not_a_linkage_is_named():
    with pytest.raises(EdgeListError, match=r"line 2: invalid JSON"):
        parse_pylinkage('{"joints":\n ]', "x.json")
    with pytest.raises(EdgeListError, match="not a pylinkage linkage"):
        parse_pylinkage('{"pairs": []}', "x.json")


_scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-3, 3),
    st.sampled_from([10**400, -(10**400), 2**1024, 1e200]),  # issue 22: OverflowError before
    st.floats(allow_nan=True),
    st.sampled_from(["A", "B", "S", "ground", "driver", "link", "prismatic", "Crank", "Static"]),
)
_values = st.recursive(
    _scalars,
    lambda inner: st.one_of(
        st.lists(inner, max_size=3),
        st.dictionaries(
            st.sampled_from(["id", "type", "ref", "inline", "x", "y", "name", "joints"]),
            inner,
            max_size=4,
        ),
    ),
    max_leaves=12,
)


@settings(max_examples=300, deadline=None)
@given(
    st.sampled_from([FOURBAR, SLIDER_CRANK, LEGACY]),
    st.integers(0, 10),
    st.sampled_from(
        [
            "id",
            "type",
            "position",
            "joints",
            "axis",
            "line_point",
            "joint0",
            "joint1",
            "x",
            "ref_joint1_id",
            "motor_joint",
            "distance",
            "ground",
            "name",
            "links",
        ]
    ),
    _values,
)
def test_damaged_linkages_give_only_our_error(base, index, key, value):
    data = json.loads(json.dumps(base))
    items = data["joints"] + data.get("links", [])
    target = items[index % len(items)] if index < 9 else data
    target[key] = value
    with contextlib.suppress(EdgeListError):
        mechanism_from_pylinkage(data, "fuzz.json")
