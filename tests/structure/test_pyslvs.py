"""Tests of pyslvs expressions and projects (structure.readwrite.pyslvs).

Every example mechanism pyslvs ships is read and classified, and the positions
pyslvs publishes for some of them in its own tests are reproduced. Both are read
at test time from pyslvs's source distribution (the ``pyslvs_sdist`` fixture,
tests/pyslvs_sdist.py); nothing of pyslvs is kept here.
"""

from __future__ import annotations

import contextlib
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import SingularPoseError, solve_pose
from structure.errors import EdgeListError
from structure.model import PairKind
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.readwrite.formats import read_mechanism, write_mechanism
from structure.readwrite.pyslvs import (
    PyslvsJoint,
    format_expression,
    mechanism_from_expression,
    mechanism_to_expression,
    mechanism_to_joints,
    parse_expression,
    parse_pyslvs,
    pyslvs_link_names,
    pyslvs_project,
)
from structure.report import analyze
from structure.validation import MAX_MAGNITUDE
from tests.conftest import FIXTURES
from tests.pyslvs_sdist import PyslvsExample, PyslvsSdist

# every example pyslvs ships, by its name there:
# W, the class of the mechanism and its formula, as pyslvs's inputs name the drivers
EXPECTED = {
    "Arm": (2, 2, "I(L2) → I(L1) → II(L5,L4) → II(L6,L3) → II(L8,L7)"),
    "Ball lifter (Double)": (1, 2, "I(L1) → II(L2,L3) → II(L6,L7) → II(L4,L5) → II(L8,L9)"),
    "Ball lifter (Triple)": (
        1,
        2,
        "I(L1) → II(L2,L3) → II(L6,L7) → II(L10,L11) → II(L4,L5) → II(L8,L9) → II(L12,L13)",
    ),
    "Crank lifter": (1, 2, "I(L1) → II(L2,block_J2) → II(L3,L4) → II(L5,block_J6)"),
    "Crank rocker": (1, 2, "I(L1) → II(L2,L3)"),
    "Crank slider (P joint)": (1, 2, "I(L1) → II(L3,L2) → II(L5,L4)"),
    "Crank slider (RP joint)": (1, 2, "I(L1) → II(L2,block_J2) → II(L3,L4)"),
    "Crank slider (Three bar)": (1, 2, "I(L1) → II(L2,block_J2)"),
    "Horse leg": (1, 2, "I(link_1) → II(link_2,link_3) → II(link_5,link_4) → II(link_7,link_6)"),
    "Inverted slider": (1, 2, "I(L1) → II(L3,L2)"),
    "Jansen's linkage (Double)": (
        1,
        2,
        "I(L1) → II(L2,L3) → II(L4,L5) → II(L8,L9) → II(L10,L11) → II(L6,L7) → II(L12,L13)",
    ),
    "Jansen's linkage (Single)": (1, 2, "I(L1) → II(L2,L3) → II(L4,L5) → II(L6,L7)"),
    "Parallel Linkage": (1, 2, "I(link_1) → II(link_3,link_2)"),
    # its input (0, 0) names no link (pyslvs skips it too): the slider block is chosen
    "Slider lifter": (1, 2, "I(block_J0) → II(L2,L1)"),
    "Stephenson I": (1, 2, "I(L1) → II(L5,L4) → II(L2,L3)"),
    "Stephenson II": (1, 4, "I(L1) → IV(L2,L5,L4,L3)"),
    "Stephenson III": (1, 3, "I(L1) → III(L2,L3,L4,L5)"),
    "Stephenson III (slider)": (1, 2, "I(link_1) → II(link_3,link_2) → II(link_4,block_J5)"),
    "Ten Fold's levers": (
        1,
        2,
        "I(L2) → II(L3,L1) → II(L7,L6) → II(L4,L5) → II(L9,L8) → II(L11,L10)",
    ),
    "Watt I": (1, 2, "I(L1) → II(L2,L5) → II(L3,L4)"),
    "Watt II": (1, 2, "I(L1) → II(L2,L3) → II(L4,L5)"),
    "Watt II (slider)": (1, 2, "I(link_3) → II(link_1,link_4) → II(link_2,block_J3)"),
}


# The positions pyslvs's test/test_core.py checks (the numbers are read from it), keyed
# by (its test function, which check in it): the example, the joint and the input angle.
# test_solving's test_case(name) puts every input at 0° and returns the last joint;
# test_solving_bfgs takes result[7] with the input (0, 1) at 0°, then at 45°.
PUBLISHED = {
    ("test_solving", 0): ("Jansen's linkage (Single)", 7, 0.0),
    ("test_solving", 1): ("Crank slider (RP joint)", 5, 0.0),
    ("test_solving", 2): ("Parallel Linkage", 3, 0.0),
    ("test_solving_bfgs", 0): ("Jansen's linkage (Single)", 7, 0.0),
    ("test_solving_bfgs", 1): ("Jansen's linkage (Single)", 7, 45.0),
}
# its third check follows a changed link length (set_data): not a pose of the example
NOT_A_POSE = {("test_solving_bfgs", 2)}


@pytest.fixture(scope="session")
def examples(pyslvs_sdist: PyslvsSdist) -> dict[str, PyslvsExample]:
    return pyslvs_sdist.examples


def _example(examples: dict[str, PyslvsExample], name: str):
    example = examples[name]
    return mechanism_from_expression(example.expression, name, example.inputs, name)


def _shape(report) -> tuple:
    """What a structural report says, whatever the links are called."""
    groups = tuple((g.assur_class, g.order, g.kind, len(g.links)) for g in report.groups)
    return report.mobility.W, groups, report.mechanism_class


# ------------------------------------------------------------ the examples
def test_the_example_list_is_pyslvs_whole_list(examples):
    assert len(examples) == 22
    assert set(examples) == set(EXPECTED)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_every_pyslvs_example_is_read_and_classified(examples, name):
    report = analyze(_example(examples, name))
    w, mechanism_class, formula = EXPECTED[name]
    assert (report.mobility.W, report.mechanism_class, report.formula) == (
        w,
        mechanism_class,
        formula,
    )


def _turns(example: PyslvsExample, degrees: float) -> tuple[float, ...]:
    """Driver rotations from the sketch that put every input pair at ``degrees``."""
    joints = parse_expression(example.expression)
    turns = []
    for base, driven in example.inputs:
        b, d = joints[base], joints[driven]
        turns.append(math.radians(degrees) - math.atan2(d.y - b.y, d.x - b.x))
    return tuple(turns)


def test_every_published_position_is_accounted_for(pyslvs_sdist):
    assert set(pyslvs_sdist.checks) == set(PUBLISHED) | NOT_A_POSE


@pytest.mark.parametrize(
    ("check", "name", "joint", "degrees"),
    [(check, *what) for check, what in PUBLISHED.items()],
    ids=[f"{name} at {degrees}° ({test})" for (test, _), (name, _, degrees) in PUBLISHED.items()],
)
def test_pyslvs_published_positions_are_reproduced(
    pyslvs_sdist, examples, check, name, joint, degrees
):
    published = pyslvs_sdist.checks[check]
    # the check read is the one meant: it names the example, or the joint it takes
    assert name in published.subject or published.subject == f"result[{joint}]"
    plan = make_plan(analyze(_example(examples, name)))
    turns = _turns(examples[name], degrees)
    if name == "Parallel Linkage":
        # the parallelogram at 0° lies flat: a dead centre, where pyslvs's triangle
        # formulas still give a point; we say so, and reach it from just beside it
        with pytest.raises(SingularPoseError, match=r"II\(link_3,link_2\)"):
            solve_pose(plan, turns)
        turns = (turns[0] + math.radians(1e-3),)
        tolerance = 2e-3
    else:
        tolerance = 1e-6
    state = solve_pose(plan, turns)
    position = state.points[f"J{joint}"].position
    assert position == pytest.approx(published.xy, abs=tolerance)


def _joint_key(joint: PyslvsJoint) -> tuple:
    """A joint as pyslvs reads it: the order of an R joint's links does not matter,
    a slider's first link (the slot) does; colours are not kept. (Sorted tuples, not
    frozensets: a frozenset's repr, the sort key below, depends on the hash seed.)"""
    if joint.kind == "R":
        links: tuple = (tuple(sorted(joint.links)),)
    else:
        links = (joint.links[0], tuple(sorted(joint.links[1:])))
    return joint.kind, links, joint.x, joint.y, joint.angle


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_pyslvs_examples_round_trip_through_our_expression(examples, name):
    """pyslvs -> ours -> pyslvs: the same joints; -> ours again: the same report."""
    mechanism = _example(examples, name)
    joints, inputs = mechanism_to_joints(mechanism)
    original = parse_expression(examples[name].expression)
    assert sorted(map(_joint_key, original), key=repr) == sorted(map(_joint_key, joints), key=repr)
    again = mechanism_from_expression(format_expression(joints), name, inputs)
    assert again.driver_links == mechanism.driver_links
    first, second = analyze(mechanism), analyze(again)
    if mechanism.driver_links:
        assert _shape(second) == _shape(first)
    else:  # Slider lifter: no input, so the drivers are chosen, maybe others
        assert (second.mobility.W, second.mechanism_class) == (1, 2)


# ------------------------------------------------------------- our fixtures
def _exportable(path: Path):
    mechanism = read_edgelist(path)
    try:
        text = pyslvs_project(mechanism)
    except EdgeListError as exc:
        return mechanism, None, exc
    return mechanism, text, None


@pytest.mark.parametrize("path", sorted(FIXTURES.glob("*.edges")), ids=lambda p: p.stem)
def test_our_fixtures_round_trip_through_pyslvs(path):
    """ours -> pyslvs project -> ours: the same W, groups and class, or a named refusal."""
    mechanism, text, refusal = _exportable(path)
    if refusal is not None:
        assert refusal.reason.startswith(
            ("pyslvs has no higher pair", "a pyslvs joint needs coordinates")
        )
        assert any(p.kind is PairKind.H for p in mechanism.pairs) or any(
            p.point is None or mechanism.coordinates(p.point) is None for p in mechanism.pairs
        )
        return
    report = analyze(mechanism)
    back = parse_pyslvs(text, path.name)
    names = pyslvs_link_names(mechanism)
    # a sliding driver, or one with a single joint, has no pyslvs input: name it again
    again = analyze(back, [names[d] for d in report.drivers])
    assert _shape(again) == _shape(report)


def test_a_block_pinned_to_a_block_keeps_the_pin():
    """Two sliders pinned together (the tangent mechanism): one RP joint, one P joint."""
    mechanism = read_edgelist(FIXTURES / "ch2_2_3_tangent.edges")
    joints, _ = mechanism_to_joints(mechanism)
    assert sorted(j.kind for j in joints) == ["P", "R", "R", "RP"]
    rp = next(j for j in joints if j.kind == "RP")
    assert rp.links == ("L1", "L3") and rp.angle == 60


# ------------------------------------------------------------------ errors
@pytest.mark.parametrize(
    ("text", "line", "reason"),
    [
        ("M[\n  J[Q, P[0, 0], L[ground, L1]]\n]", 2, "column 5: unknown joint kind 'Q'"),
        (
            "M[\n  J[R, P[0, 0] L[ground, L1]]\n]",
            2,
            "column 16: expected ',' after P[x, y] but found 'L'",
        ),
        ("M[J[R, P[0, 0], L[ground, L1]]", 1, "expected ',' or ']' after a joint but the"),
        ("M[J[R, P[0, x], L[ground]]]", 1, "column 13: expected the y coordinate but found 'x'"),
        ("M[J[R, P[0, 1e999], L[ground]]]", 1, "the y coordinate 1e999 is not a finite number"),
        ("M[J[R, A[3], P[0, 0], L[ground, L1]]]", 1, "joint J0: an R joint takes no slot angle"),
        ("M[\nJ[RP, P[0, 0], L[ground, L1]]]", 2, "joint J0: a RP joint needs its slot angle"),
        ("M[J[R, P[0, 0], L[L1, L1]]]", 1, "joint J0: link L1 is named twice"),
        ("M[J[R, P[0, 0], L[ground, L1]]] extra", 1, "expected the end after the mechanism's"),
        ("M[J[R, P[0, 0], L[ground, L1]]] #[ open", 1, "comment '#[' is not closed by '#]'"),
        (
            "M[J[R, P[0, 0], L[ground, L1]], J[R, P[1, 0], L[L1, 2L]]]",
            1,
            "column 53: expected a link",
        ),
        ("M[J[R, P[0, 0], L[ground, L$]]]", 1, "column 28: unexpected character '$'"),
    ],
)
def test_syntax_errors_name_the_line_and_what_is_wrong(text, line, reason):
    with pytest.raises(EdgeListError) as info:
        parse_expression(text, "arm.pyslvs")
    assert info.value.source == "arm.pyslvs"
    assert info.value.line_no == line
    assert reason in info.value.reason
    assert str(info.value).startswith(f"arm.pyslvs: line {line}: ")


def test_a_p_joint_of_three_links_is_refused_by_name():
    text = "M[J[R, P[0, 0], L[ground, L1]],\n J[P, A[0], P[1, 0], L[ground, L1, L2]]]"
    with pytest.raises(EdgeListError, match="line 2: joint J1: a P joint of 3 links welds L1, L2"):
        mechanism_from_expression(text, "weld.pyslvs")


def test_a_link_off_the_ground_is_reported_on_its_joint_line():
    text = "M[\nJ[R, P[0, 0], L[ground, L1]],\nJ[R, P[1, 0], L[L2, L3]]\n]"
    with pytest.raises(EdgeListError, match=r"line 3: link\(s\) not connected to the ground"):
        mechanism_from_expression(text, "loose.pyslvs")


@pytest.mark.parametrize(
    ("inputs", "reason"),
    [
        ([(0, 9)], "input 1 (0, 9): there are joints J0 to J4 only"),
        ([(0, 2)], "input 1 (0, 2): J0 and J2 share no link"),
        ([(0,)], "input 1 (0,): expected two joint numbers"),
    ],
)
def test_bad_input_pairs_are_named(examples, inputs, reason):
    with pytest.raises(EdgeListError) as info:
        mechanism_from_expression(examples["Crank rocker"].expression, "cr", inputs)
    assert info.value.reason == reason


def test_higher_pairs_and_missing_coordinates_cannot_be_written():
    with pytest.raises(EdgeListError, match="pyslvs has no higher pair"):
        mechanism_to_expression(read_edgelist(FIXTURES / "gear_pair.edges"))
    bare = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"])
    with pytest.raises(EdgeListError, match="a pyslvs joint needs coordinates"):
        mechanism_to_expression(bare)


# ------------------------------------------------------------------ files
def test_project_files_round_trip_with_their_inputs(examples, tmp_path):
    mechanism = _example(examples, "Arm")
    path = write_mechanism(mechanism, tmp_path / "arm.pyslvs")
    assert path.read_text(encoding="utf-8").startswith("mechanism: 'M[J[R, ")
    back = read_mechanism(path)
    assert back.driver_links == mechanism.driver_links
    assert analyze(back).formula == analyze(mechanism).formula


def test_a_bare_expression_is_read_whatever_its_extension(examples, tmp_path):
    text = "# a comment\n#[ and a\nblock #]\n" + examples["Crank rocker"].expression
    for suffix in (".pyslvs", ".txt", ".edges"):
        path = tmp_path / f"crank{suffix}"
        path.write_text(text, encoding="utf-8")
        mechanism = read_mechanism(path)
        assert mechanism.name == "crank"
        assert analyze(mechanism).formula == "I(L1) → II(L2,L3)"


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("mechanism: [1, 2]\n", "neither a pyslvs expression M[...] nor a Pyslvs project"),
        ("input: [[0, 1]]\n", "neither a pyslvs expression M[...] nor a Pyslvs project"),
        ("mechanism: 'M[]'\ninput: 3\n", "'input' must be a list of [base joint, driven joint]"),
        ("mechanism: 'M[]'\n  bad: [\n", "invalid Pyslvs project"),
        ("mechanism: 2001-02-30\n", "invalid Pyslvs project: day is out of range for month"),
        # issue 22, item 5: a RecursionError, exit 3, before
        ("mechanism: " + "[" * 100_000 + "]" * 100_000 + "\n", "nested too deeply"),
        ("mechanism: " + "{a: " * 50_000 + "1" + "}" * 50_000 + "\n", "nested too deeply"),
    ],
)
def test_bad_project_files_are_named(tmp_path, text, reason):
    path = tmp_path / "bad.pyslvs"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(EdgeListError) as info:
        read_mechanism(path)
    assert reason in info.value.reason


# -------------------------------------------------------- property tests
_names = st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,6}", fullmatch=True)
# the readers take numbers within ±MAX_MAGNITUDE (1e150, issue 11)
_numbers = st.floats(-MAX_MAGNITUDE, MAX_MAGNITUDE, allow_nan=False, allow_infinity=False, width=64)
_colours = st.one_of(
    st.none(),
    st.sampled_from(["Green", "Blue", "red"]),
    st.tuples(*[st.integers(0, 255)] * 3).map(lambda c: f"({c[0]}, {c[1]}, {c[2]})"),
)


@st.composite
def _joints(draw):
    kind = draw(st.sampled_from(["R", "P", "RP"]))
    links = tuple(draw(st.lists(_names, max_size=4, unique=True)))
    angle = None if kind == "R" else draw(_numbers)
    return PyslvsJoint(kind, links, draw(_numbers), draw(_numbers), angle, draw(_colours))


@settings(max_examples=200, deadline=None)
@given(st.lists(_joints(), max_size=6))
def test_random_valid_expressions_round_trip(joints):
    text = format_expression(joints)
    assert parse_expression(text) == tuple(joints)
    squeezed = "M[" + "".join(f"{j.expression}," for j in joints) + "]"  # a trailing comma
    assert parse_expression(squeezed) == tuple(joints)


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=st.sampled_from(list("MJLPARcolr[](),.-+e0159 #\nground")), max_size=80))
def test_garbage_gives_only_our_error(text):
    with contextlib.suppress(EdgeListError):
        mechanism_from_expression(text, "garbage")


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(sorted(EXPECTED)), st.integers(0, 10_000), st.integers(0, 3), st.text())
def test_damaged_examples_give_only_our_error(examples, name, where, how, noise):
    text = examples[name].expression
    at = where % (len(text) + 1)
    damaged = [text[:at] + text[at + 1 :], text[:at] + noise + text[at:], text[:at], noise][how]
    with contextlib.suppress(EdgeListError):
        mechanism_from_expression(damaged, "damaged", examples[name].inputs)


@pytest.mark.parametrize(
    ("text", "column", "what"),
    [
        ("M[J[R, P[1e200, 1], L[ground, L1]], J[R, P[0, 0], L[L1]]]", 10, "the x coordinate"),
        ("M[J[R, P[0, -2e150], L[ground, L1]], J[R, P[0, 0], L[L1]]]", 13, "the y coordinate"),
        ("M[J[RP, A[1e151], P[0, 0], L[ground, L1]], J[R, P[0, 1], L[L1]]]", 11, "the slot angle"),
    ],
)
def test_numbers_beyond_the_limit_every_reader_takes_are_refused(text, column, what):
    """Issue 22, item 5: coordinates beyond ±1e150 passed (LAPACK then printed DLASCL noise);
    the limit is the edge list's and JSON's (MAX_MAGNITUDE)."""
    with pytest.raises(EdgeListError) as info:
        mechanism_from_expression(text, "big")
    assert info.value.line_no == 1
    assert f"column {column}: {what}" in info.value.reason
    assert f"beyond ±{MAX_MAGNITUDE:g}" in info.value.reason
