"""The edge list's cam statement and the JSON form's cams (structure.readwrite.camfile)."""

from __future__ import annotations

import json

import pytest

from structure.errors import StatementError
from structure.readwrite.camfile import cam_from_item, cam_from_tokens, cam_to_item, read_cam_spec

SPEC = {
    "base_radius": 0.04,
    "follower": {"motion": "translating", "contact": "knife"},
    "segments": [
        {"law": "cycloidal", "lift": 0.01, "angle": 180},
        {"law": "cycloidal", "lift": -0.01, "angle": 180},
    ],
}


@pytest.fixture
def program(tmp_path):
    path = tmp_path / "disc.json"
    path.write_text(json.dumps(SPEC))
    return path


def test_a_statement_reads_its_program_beside_the_file(program) -> None:
    source = str(program.parent / "m.edges")
    ref = cam_from_tokens(["cam", "1", "2", "disc.json", "at=45"], 7, source)
    assert (ref.cam, ref.other, ref.path, ref.at_deg, ref.line_no) == (
        "1",
        "2",
        "disc.json",
        45.0,
        7,
    )
    assert ref.statement == "cam 1 2 disc.json at=45"
    assert ref.spec == read_cam_spec(program)


@pytest.mark.parametrize(
    ("tokens", "message"),
    [
        (["cam", "1", "2"], "expected 'cam CAM LINK FILE"),
        (["cam", "1", "2", "disc.json", "at=x"], "at= needs a finite angle"),
        (["cam", "1", "2", "disc.json", "at=1e999"], "at= needs a finite angle"),
        (["cam", "1", "2", "disc.json", "phase=3"], "unexpected token 'phase=3'"),
        (["cam", "1", "2", "none.json"], "cam program none.json: .*cannot read"),
    ],
)
def test_bad_statements(program, tokens, message) -> None:
    with pytest.raises(StatementError, match=message):
        cam_from_tokens(tokens, 1, str(program.parent / "m.edges"))


def test_a_program_that_is_not_json_is_named(tmp_path) -> None:
    (tmp_path / "x.json").write_text("{not json")
    with pytest.raises(StatementError, match=r"cam program x.json: invalid JSON"):
        cam_from_tokens(["cam", "1", "2", "x.json"], 1, str(tmp_path / "m.edges"))


def test_json_items_inline_or_by_file(program) -> None:
    source = str(program.parent / "m.json")
    by_file = cam_from_item({"links": ["1", 2], "file": "disc.json"}, source)
    inline = cam_from_item({"links": [1, "2"], "spec": SPEC, "at": 10}, source)
    assert by_file.spec == inline.spec and by_file.path == "disc.json" and inline.path is None
    assert cam_to_item(inline) == {"links": ["1", "2"], "spec": cam_to_item(by_file)["spec"],
                                   "at": 10.0}  # fmt: skip
    for bad in ({"links": ["1"], "spec": SPEC}, {"links": ["1", "2"]},
                {"links": ["1", "2"], "spec": SPEC, "file": "disc.json"}, "cam",
                {"links": ["1", "2"], "spec": {"segments": []}}):  # fmt: skip
        with pytest.raises(StatementError):
            cam_from_item(bad, source)
