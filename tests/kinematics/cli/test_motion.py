"""``assur kinematics`` (kinematics.cli.motion): JSON, text, exact values, --flip, --plot."""

from __future__ import annotations

import json

from kinematics.cli.commands import main

from ...conftest import FIXTURES


def test_kinematics_json_has_links_and_points(capsys):
    assert main(["kinematics", str(FIXTURES / "ch2_2_4_fourbar.edges"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    # problem 2.4 by the vector polygons: ω3 = 5, ε2 = 75, v_C = (−2, 0), a_C = (0, −10)
    assert abs(data["links"]["3"]["omega"] - 5.0) < 1e-9
    assert abs(data["links"]["2"]["epsilon"] - 75.0) < 1e-6
    assert data["points"]["C"]["velocity"] == [-2.0, 0.0] or all(
        abs(a - b) < 1e-9 for a, b in zip(data["points"]["C"]["velocity"], [-2.0, 0.0], strict=True)
    )
    assert set(data["points"]["C"]) >= {"position", "velocity", "acceleration"}


def test_kinematics_text_names_groups_and_units(capsys):
    assert main(["kinematics", str(FIXTURES / "ch2_2_4_fourbar.edges")]) == 0
    out = capsys.readouterr().out
    assert "II(2,3) RRR" in out and "rad/s²" in out and "m/s" in out


def test_exact_answer_is_a_radical(capsys):
    path = str(FIXTURES / "ch2_2_2_slotted_link.edges")
    assert main(["kinematics", path, "--exact", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["links"]["3"]["epsilon"]["value"] == "50*sqrt(3)"


def test_bad_flip_is_a_usage_error(capsys):
    assert main(["kinematics", str(FIXTURES / "fourbar.edges"), "--flip", "II(9,9)"]) == 2
    assert "cannot flip" in capsys.readouterr().err


def test_kinematics_needs_coordinates(capsys):
    assert main(["kinematics", str(FIXTURES / "ch1_1_2a_mechanical_press.edges")]) == 1
    err = capsys.readouterr().err
    assert "coordinates" in err and "Traceback" not in err


def test_kinematics_plot_writes_the_sheet(tmp_path, capsys):
    pytest_plot = tmp_path / "sheet.png"
    assert main(["kinematics", str(FIXTURES / "fourbar.edges"), "--plot", str(pytest_plot)]) == 0
    assert pytest_plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert main(["kinematics", str(FIXTURES / "fourbar.edges"), "--plot", "x.gif"]) == 1
    assert "Traceback" not in capsys.readouterr().err


# ------------------------------------------------------------------ animate (issue 22, item 16)
def frames_of(path) -> int:
    from PIL import Image

    return Image.open(path).n_frames


def test_animate_makes_the_five_bar_the_redundant_parallelogram_and_a_double_rocker(
    capsys, tmp_path
):
    rocker = FIXTURES / "double_rocker.edges"
    cases = {
        str(FIXTURES / "fivebar_two_drivers.edges"): 2 * 6 - 2,  # a stretch, there and back
        str(FIXTURES / "parallelogram_redundant.edges"): 6,  # a whole turn
        str(rocker): 2 * 6 - 2,
    }
    for source, frames in cases.items():
        out = tmp_path / "a.gif"
        assert main(["animate", source, str(out), "--steps", "6"]) == 0, source
        text = capsys.readouterr().out
        assert frames_of(out) == frames
        if frames != 6:
            assert "not a whole turn: the mechanism reaches from" in text
            assert "a dead point of group II(2,3)" in text and "change point" not in text


def test_animate_of_a_driver_that_cannot_move_is_a_named_error(capsys, tmp_path):
    path = tmp_path / "stretched.edges"
    path.write_text(
        "driver 1\n0 1 R A\n1 2 R B\n2 3 R C\n3 0 R D\n"
        "point A 0 0\npoint B 0.1 0\npoint C 0.3 0\npoint D 0.6 0\n"
    )
    assert main(["animate", str(path), str(tmp_path / "a.gif")]) == 1
    assert "driver 1 cannot move from the sketch either way" in capsys.readouterr().err


# ------------------------------------------------------------------ sweep (issue 22, item 2)
def test_sweep_of_a_slider_driven_crank_is_its_stroke(capsys, tmp_path):
    path = tmp_path / "driven_at_the_slider.edges"
    path.write_text(
        "driver 3\n0 1 R A\n1 2 R B\n2 3 R C\n3 0 P C angle=0\n"
        "point A 0 0\npoint B 0 0.1\npoint C 0.1732 0\n"
    )
    assert main(["sweep", str(path), "--steps", "36"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("36 poses over the stroke of the sliding driver(s) (3 from -0.07")


def test_inputs_too_far_from_the_sketch_to_follow_are_refused_by_their_memory(capsys, tmp_path):
    inputs = tmp_path / "far.txt"
    inputs.write_text("1e12\n")  # degrees: a Newton triad followed there in 0.05 rad steps
    assert main(["sweep", str(FIXTURES / "eightbar_triad.edges"), "--inputs", str(inputs)]) == 1
    err = capsys.readouterr().err
    assert "intermediate poses" in err and "give inputs nearer the sketch" in err
