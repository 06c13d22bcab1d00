"""The cam spec as data: read, checked, written back; every bad spec a named error."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from structure.cams import (
    FollowerContact,
    FollowerMotion,
    MotionLaw,
    cam_spec_from_dict,
    cam_spec_to_dict,
)
from structure.errors import CamProgramError, EdgeListError

ISSUE_SPEC = {
    "name": "disc cam, offset roller",
    "omega": 10.0,
    "follower": {"motion": "translating", "contact": "roller", "offset": 0.005,
                 "roller_radius": 0.01},
    "base_radius": 0.04,
    "segments": [{"law": "cycloidal", "lift": 0.02, "angle": 120},
                 {"law": "dwell", "angle": 60},
                 {"law": "modified-trapezoid", "lift": -0.02, "angle": 120},
                 {"law": "dwell", "angle": 60}],
}  # fmt: skip


def _with(**changes) -> dict:
    data = json.loads(json.dumps(ISSUE_SPEC))
    data.update(changes)
    return data


def test_the_issue_spec_reads() -> None:
    spec = cam_spec_from_dict(ISSUE_SPEC)
    assert spec.follower.motion is FollowerMotion.TRANSLATING
    assert spec.follower.contact is FollowerContact.ROLLER
    assert [s.law for s in spec.segments] == [
        MotionLaw.CYCLOIDAL,
        MotionLaw.DWELL,
        MotionLaw.MODIFIED_TRAPEZOID,
        MotionLaw.DWELL,
    ]
    assert spec.total_lift == 0.02 and spec.pressure_limit == 30.0
    assert cam_spec_from_dict(cam_spec_to_dict(spec)) == spec


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"segments": [{"law": "cycloidal", "lift": 0.02, "angle": 120},
                       {"law": "cycloidal", "lift": -0.02, "angle": 120}]},
         r"segments: the angles add up to 240°, not 360°: lengthen or shorten a segment by \+120°"),
        ({"segments": [{"law": "cycloidal", "lift": 0.02, "angle": 180},
                       {"law": "cycloidal", "lift": -0.015, "angle": 180}]},
         r"the program ends at s = 0.005, not home at 0 .*change a lift by -0.005"),
        ({"segments": [{"law": "cycloid", "lift": 0.02, "angle": 360}]},
         r"segments\[0\]: unknown law 'cycloid' \(use uniform, harmonic, cycloidal, "
         r"modified-trapezoid, modified-sine, 3-4-5, 4-5-6-7, dwell, polynomial\)"),
        ({"segments": [{"law": "harmonic", "angle": 180}, {"law": "dwell", "angle": 180}]},
         r"segments\[0\]: a harmonic segment needs a 'lift' other than 0"),
        ({"segments": [{"law": "dwell", "lift": 0.01, "angle": 360}]},
         r"a dwell has no lift"),
        ({"base_radius": -0.01}, r"'base_radius' must be a finite number > 0"),
        ({"omega": 0}, r"omega: the cam speed must not be 0"),
        ({"follower": {"motion": "translating", "contact": "roller"}},
         r"a translating roller follower needs 'roller_radius'"),
        ({"follower": {"motion": "translating", "contact": "knife", "arm": 0.1}},
         r"'arm' does not apply to a translating knife follower"),
        ({"follower": {"motion": "swinging", "contact": "knife"}},
         r"follower.motion: 'swinging' is not one of translating, oscillating"),
        ({"colour": "red"}, r"unknown keys \['colour'\]"),
        ({"follower_inertia": 1.0}, r"applies to an oscillating follower"),
        ({"max_pressure_angle": 95}, r"must be below 90 degrees"),
        ({"segments": [{"law": "polynomial", "angle": 180, "bc": [{"at": 0, "s": 0}]},
                       {"law": "dwell", "angle": 180}]},
         r"'bc' needs the displacement s at 180°"),
        ({"segments": [{"law": "polynomial", "angle": 180, "bc": [{"at": 0, "s": 0},
                                                                   {"at": 200, "s": 0}]},
                       {"law": "dwell", "angle": 180}]},
         r"'at' 200 is outside the segment"),
        ({"segments": [{"law": "cycloidal", "lift": 0.01, "angle": 120},
                       {"law": "polynomial", "angle": 120,
                        "bc": [{"at": 0, "s": 0.02}, {"at": 120, "s": 0}]},
                       {"law": "dwell", "angle": 120}]},
         r"segments\[1\]: starts at s = 0.02 but the follower is at 0.01 there"),
    ],
)  # fmt: skip
def test_bad_specs_are_named_errors_that_say_what_to_change(changes: dict, message: str) -> None:
    with pytest.raises(CamProgramError, match=message) as caught:
        cam_spec_from_dict(_with(**changes), "cam.json")
    assert isinstance(caught.value, EdgeListError)
    assert str(caught.value).startswith("cam.json: ")


def test_every_problem_at_once() -> None:
    bad = _with(base_radius=0, omega=0, segments=[{"law": "x", "angle": 1}])
    with pytest.raises(CamProgramError) as caught:
        cam_spec_from_dict(bad)
    assert len(caught.value.problems) == 3


def test_an_oscillating_spec_and_a_polynomial_read_and_write_back() -> None:
    data = {
        "omega": -4,
        "follower": {"motion": "oscillating", "contact": "flat", "pivot": [0.1, 0.0],
                     "face_offset": 0.004},
        "base_radius": 0.03,
        "follower_inertia": 0.01,
        "load": 2.0,
        "spring": {"rate": 3.0, "preload": 1.0, "up_to": 8},
        "segments": [{"law": "polynomial", "angle": 200,
                      "bc": [{"at": 0, "s": 0, "v": 0}, {"at": 100, "s": 10},
                             {"at": 200, "s": 0, "v": 0}]},
                     {"law": "dwell", "angle": 160}],
    }  # fmt: skip
    spec = cam_spec_from_dict(data)
    assert spec.segments[0].lift == 0.0 and spec.total_lift == 0.0  # the middle is not an end
    assert cam_spec_from_dict(cam_spec_to_dict(spec)) == spec


_SCALARS = st.one_of(
    st.none(), st.booleans(), st.integers(-10, 400), st.floats(allow_nan=True),
    st.text(max_size=6), st.sampled_from([law.value for law in MotionLaw]),
)  # fmt: skip
_VALUES = st.recursive(
    _SCALARS,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.dictionaries(
            st.sampled_from(["law", "angle", "lift", "bc", "at", "s", "v", "motion", "contact",
                             "offset", "roller_radius", "pivot", "arm", "rate", "preload"]),
            inner, max_size=4,
        ),
    ),
    max_leaves=12,
)  # fmt: skip


@settings(max_examples=100, deadline=None)
@given(
    st.dictionaries(
        st.sampled_from(["omega", "follower", "base_radius", "segments", "spring", "load",
                         "max_pressure_angle", "name", "extra"]),
        _VALUES, max_size=6,
    )
)  # fmt: skip
def test_any_json_value_is_read_or_refused_by_name(data: dict) -> None:
    """No spec raises anything but CamProgramError (no TypeError, no KeyError)."""
    try:
        spec = cam_spec_from_dict(data)
    except CamProgramError:
        return
    assert cam_spec_from_dict(cam_spec_to_dict(spec)) == spec
