"""``assur kinematics`` (kinematics.cli.motion): JSON, text, exact values, --flip, --plot."""

from __future__ import annotations

import json

from kinematics.cli.main import main

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
