"""The ``target`` statement: a design target of the marker P, in the edge list and in JSON."""

from __future__ import annotations

import json

import pytest

from structure import parse_edgelist
from structure.errors import EdgeListError
from structure.readwrite.edgelist import write_edgelist
from structure.readwrite.jsonformat import mechanism_from_json, mechanism_to_json

FOURBAR = ["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D", "point P 1 2 on=2"]


def test_targets_read_in_order_with_their_options() -> None:
    m = parse_edgelist([*FOURBAR, "target T1 1 2 input=0", "target T2 1.5 -2 input=10 angle=5"])
    assert [(t.name, t.x, t.y, t.input_deg, t.angle_deg) for t in m.targets] == [
        ("T1", 1.0, 2.0, 0.0, None),
        ("T2", 1.5, -2.0, 10.0, 5.0),
    ]


def test_edge_list_and_json_round_trip() -> None:
    m = parse_edgelist([*FOURBAR, "target T1 1 2", "target T2 3 4 angle=-90"])
    again = parse_edgelist(write_edgelist(m).splitlines())
    assert again.targets == m.targets
    data = json.loads(mechanism_to_json(m))
    assert data["targets"] == {"T1": {"xy": [1.0, 2.0]}, "T2": {"xy": [3.0, 4.0], "angle": -90.0}}
    assert mechanism_from_json(mechanism_to_json(m)).targets == m.targets


@pytest.mark.parametrize(
    "line, reason",
    [
        ("target T1 1", "expected 'target NAME x y"),
        ("target T1 1 nan", "finite"),
        ("target T1 1 2 speed=3", "unexpected token 'speed=3'"),
        ("target T1 1 2 input=inf", "finite"),
    ],
)
def test_a_bad_target_is_named_with_its_line(line: str, reason: str) -> None:
    with pytest.raises(EdgeListError) as info:
        parse_edgelist([*FOURBAR, line])
    assert info.value.line_no == len(FOURBAR) + 1 and reason in info.value.reason


def test_a_target_named_twice_is_refused() -> None:
    with pytest.raises(EdgeListError, match="already given on line 7"):
        parse_edgelist([*FOURBAR, "target T1 1 2", "target T1 2 3"])


def test_json_targets_of_the_wrong_shape_are_refused() -> None:
    text = json.dumps(
        {
            "drivers": ["1"],
            "pairs": [{"links": [0, 1], "kind": "R"}],
            "targets": {"T1": {"xy": [1]}},
        }
    )
    with pytest.raises(EdgeListError, match=r"targets\['T1'\]"):
        mechanism_from_json(text)
