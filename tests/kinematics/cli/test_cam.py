"""``assur cam`` (kinematics.cli.cam): summary, the JSON contract, figures, exports, errors."""

from __future__ import annotations

import json
import math
import shutil
import tempfile

import pytest

from structure import read_edgelist

from .conftest import ROOT, run

SPEC = ROOT / "examples" / "cams" / "offset_roller.json"
ROCKER = ROOT / "examples" / "cams" / "rocker_flat.json"


def _strict(text: str):
    def refuse(constant: str):
        raise ValueError(f"not strict JSON: {constant}")

    return json.loads(text, parse_constant=refuse)


def test_the_summary_names_every_check(capsys) -> None:
    code, out, err = run(capsys, "cam", str(SPEC))
    assert code == 0, err
    for words in ("Program", "Joins", "Pressure angle", "Radius of curvature", "Undercut: none",
                  "Smallest base circle", "jump speed", "Conventions", "offset:"):  # fmt: skip
        assert words in out


def test_the_json_holds_the_contract_keys(capsys) -> None:
    code, out, _ = run(capsys, "cam", str(SPEC), "--json", "--samples", "720")
    assert code == 0
    data = _strict(out)
    for key in ("segments", "samples", "peak", "pressure_angle", "curvature", "undercut",
                "continuity", "profile", "contact_force", "jump_speed"):  # fmt: skip
        assert key in data
    assert set(data["samples"]) == {"theta_deg", "s", "v", "a", "j"}
    assert len(data["samples"]["s"]) == 720 and len(data["profile"]) == 720
    assert set(data["peak"]) == {"v", "a", "j"} and "at_deg" in data["peak"]["v"]
    assert set(data["pressure_angle"]) >= {"max_deg", "at_deg"}
    assert set(data["curvature"]) >= {"pitch_min", "profile_min"}
    assert data["undercut"] == {"found": False, "at_deg": []}
    # the cycloidal rise's peak velocity, by hand: C_v·h·ω/β = 2·0.02·10/(2π/3)
    assert data["peak"]["v"]["value"] == pytest.approx(2 * 0.02 * 10 / (2 * math.pi / 3))
    assert data["peak"]["v"]["at_deg"] == pytest.approx(60.0)
    assert [j["name"] for j in data["continuity"]] == ["C2", "C2", "C2", "C2"]
    assert data["jump_speed"] > 10.0


def test_infinite_jerk_is_named(capsys) -> None:
    spec = {"base_radius": 0.04, "omega": 5, "follower": {"motion": "translating",
            "contact": "flat"}, "segments": [{"law": "harmonic", "lift": 0.01, "angle": 150},
            {"law": "dwell", "angle": 30}, {"law": "harmonic", "lift": -0.01, "angle": 150},
            {"law": "dwell", "angle": 30}]}  # fmt: skip

    with tempfile.TemporaryDirectory() as folder:
        target = f"{folder}/h.json"
        with open(target, "w", encoding="utf-8") as handle:
            json.dump(spec, handle)
        code, out, _ = run(capsys, "cam", target)
        assert code == 0
        assert "INFINITE JERK" in out and "fundamental law" in out
        code, out, _ = run(capsys, "cam", target, "--json")
        assert _strict(out)["peak"]["j"]["infinite_at_deg"] == [150.0, 180.0, 330.0, 0.0]


def test_plot_profiles_and_mechanisms_are_written(tmp_path, capsys) -> None:
    sheet, dxf, svg, csv = (tmp_path / n for n in ("s.png", "p.dxf", "p.svg", "p.csv"))
    mechanism, edges = tmp_path / "m.json", tmp_path / "m.edges"
    code, _, err = run(
        capsys, "cam", str(SPEC), "--plot", str(sheet), "--profile", str(dxf), "--profile",
        str(svg), "--profile", str(csv), "-o", str(mechanism),
    )  # fmt: skip
    assert code == 0, err
    assert sheet.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert svg.read_text().lstrip().startswith("<?xml") and 'id="profile"' in svg.read_text()
    assert csv.read_text().splitlines()[0] == "theta_deg,x,y,pitch_x,pitch_y"
    import ezdxf

    layers = {e.dxf.layer for e in ezdxf.readfile(dxf).modelspace()}
    assert "CAM_PROFILE" in layers
    code, _, err = run(capsys, "cam", str(SPEC), "-o", str(edges))
    assert code == 0 and (tmp_path / "m.cam.json").exists()
    assert read_edgelist(edges).cams[0].path == "m.cam.json"
    for path in (mechanism, edges):
        commands = (
            ["sweep", str(path), "--steps", "24"],
            ["forces", str(path)],
            ["kinematics", str(path), "--explain"],
            ["classify", str(path)],
        )
        for command in commands:
            code, _, err = run(capsys, *command)
            assert code == 0, (command, err)


def test_the_shipped_edge_list_runs(capsys) -> None:
    code, out, err = run(capsys, "sweep", str(ROOT / "examples" / "cams" / "offset_roller.edges"))
    assert code == 0, err
    assert "balancing moment 1" in out


def test_an_oscillating_spec_and_its_explanation_in_vietnamese(capsys) -> None:
    code, out, _ = run(capsys, "cam", str(ROCKER), "--explain", "--lang", "vi")
    assert code == 0
    assert "Góc áp lực" in out and "đáy bằng" in out


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ({"segments": [{"law": "cycloidal", "lift": 0.02, "angle": 100}]},
         "not 360°"),
        ({"segments": [{"law": "cycloidal", "lift": 0.02, "angle": 180},
                       {"law": "cycloidal", "lift": -0.01, "angle": 180}]},
         "not home"),
        ({"segments": [{"law": "sine", "lift": 0.02, "angle": 360}]}, "unknown law 'sine'"),
        ({"follower": {"motion": "translating", "contact": "roller", "offset": 0.06,
                       "roller_radius": 0.01}},
         "make the base circle larger than 0.05"),
    ],
)  # fmt: skip
def test_bad_specs_are_named_errors(tmp_path, capsys, spec, message) -> None:
    data = json.loads(SPEC.read_text())
    data.update(spec)
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(data))
    code, out, err = run(capsys, "cam", str(path))
    assert code == 1 and message in err and "Traceback" not in err
    code, out, _ = run(capsys, "cam", str(path), "--json")
    assert code == 1 and message in _strict(out)["error"]


def test_an_undercut_cam_is_reported_and_its_profile_refused(tmp_path, capsys) -> None:
    data = json.loads(SPEC.read_text())
    data["base_radius"] = 0.012
    data["follower"]["offset"] = 0.0
    data["follower"]["roller_radius"] = 0.015
    data["segments"] = [
        {"law": "cycloidal", "lift": 0.03, "angle": 50},
        {"law": "dwell", "angle": 10},
        {"law": "cycloidal", "lift": -0.03, "angle": 50},
        {"law": "dwell", "angle": 250},
    ]
    path = tmp_path / "sharp.json"
    path.write_text(json.dumps(data))
    code, out, _ = run(capsys, "cam", str(path), "--json")
    assert code == 0 and _strict(out)["undercut"]["found"] is True
    code, _, err = run(capsys, "cam", str(path), "--profile", str(tmp_path / "p.dxf"))
    assert code == 1 and "cannot be cut" in err
    code, _, err = run(capsys, "cam", str(path), "-o", str(tmp_path / "m.json"))
    assert code == 0  # the mechanism is written; the solvers refuse it by name
    code, _, err = run(capsys, "sweep", str(tmp_path / "m.json"))
    assert code == 1 and "too large for the pitch curve" in err


@pytest.mark.parametrize(
    "argv",
    [
        ["--samples", "3"],
        ["--profile", "p.txt"],
        ["-o", "m.yaml"],
    ],
)
def test_usage_errors(tmp_path, capsys, argv) -> None:
    shutil.copy(SPEC, tmp_path / "spec.json")
    args = [a if not a.startswith(("p.", "m.")) else str(tmp_path / a) for a in argv]
    code, _, err = run(capsys, "cam", str(tmp_path / "spec.json"), *args)
    assert code == 2, err


def test_no_output_writes_over_the_spec(tmp_path, capsys) -> None:
    shutil.copy(SPEC, tmp_path / "spec.json")
    before = (tmp_path / "spec.json").read_text()
    code, _, err = run(capsys, "cam", str(tmp_path / "spec.json"), "-o",
                       str(tmp_path / "spec.json"))  # fmt: skip
    assert code == 2 and "the spec being read" in err
    assert (tmp_path / "spec.json").read_text() == before
