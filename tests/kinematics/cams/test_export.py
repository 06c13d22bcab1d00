"""The profile's files: DXF, SVG and CSV hold the closed-form profile, and refuse a looping one."""

from __future__ import annotations

import csv
import io
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from kinematics.cams.checks import cam_angles
from kinematics.cams.design import make_design
from kinematics.cams.export import profile_csv, profile_svg, write_profile
from kinematics.cams.profile import cam_geometry
from kinematics.errors import UndercutError
from structure.cams import cam_spec_from_dict
from structure.errors import MechanismError

DESIGN = make_design(
    cam_spec_from_dict(
        {"omega": 10.0, "base_radius": 0.04,
         "follower": {"motion": "translating", "contact": "roller", "offset": 0.004,
                      "roller_radius": 0.01},
         "segments": [{"law": "cycloidal", "lift": 0.02, "angle": 150},
                      {"law": "cycloidal", "lift": -0.02, "angle": 150},
                      {"law": "dwell", "angle": 60}]}
    )
)  # fmt: skip


def test_csv_rows_are_the_profile_and_pitch_curve() -> None:
    rows = list(csv.DictReader(io.StringIO(profile_csv(DESIGN, 90))))
    g = cam_geometry(DESIGN, cam_angles(90))
    got = np.array([[float(r["x"]), float(r["y"])] for r in rows])
    np.testing.assert_allclose(got, g.profile, atol=1e-14)
    pitch = np.array([[float(r["pitch_x"]), float(r["pitch_y"])] for r in rows])
    # the pitch curve is R_f out from the profile along the normal: |pitch − profile| = R_f
    np.testing.assert_allclose(np.hypot(*(pitch - got).T), 0.01, atol=1e-12)
    assert [float(r["theta_deg"]) for r in rows[:3]] == [0.0, 4.0, 8.0]


def test_svg_paths_in_millimetres() -> None:
    root = ET.fromstring(profile_svg(DESIGN, 60).split("\n", 1)[1])
    paths = {e.get("id"): e.get("d") for e in root.iter() if e.tag.endswith("path")}
    points = [tuple(map(float, p.split(","))) for p in paths["profile"][2:-2].split(" L ")]
    g = cam_geometry(DESIGN, cam_angles(60))
    np.testing.assert_allclose(np.array(points), g.profile * [1000, -1000], atol=1e-3)
    circles = {e.get("id"): float(e.get("r")) for e in root.iter() if e.tag.endswith("circle")}
    assert circles["base"] == pytest.approx(40.0) and circles["prime"] == pytest.approx(50.0)


def test_dxf_has_the_profile_on_its_own_layer(tmp_path) -> None:
    ezdxf = pytest.importorskip("ezdxf")
    path = write_profile(DESIGN, tmp_path / "cam.dxf", 180)
    space = ezdxf.readfile(path).modelspace()
    (profile,) = [e for e in space if e.dxf.layer == "CAM_PROFILE"]
    assert profile.closed and len(profile) == 180
    radii = sorted(e.dxf.radius for e in space if e.dxftype() == "CIRCLE")
    assert radii == pytest.approx([0.04, 0.05])


def test_a_looping_profile_and_a_bad_suffix_are_refused(tmp_path) -> None:
    sharp = make_design(
        cam_spec_from_dict(
            {"base_radius": 0.012, "follower": {"motion": "translating", "contact": "roller",
             "roller_radius": 0.015}, "segments": [
                {"law": "cycloidal", "lift": 0.03, "angle": 50}, {"law": "dwell", "angle": 10},
                {"law": "cycloidal", "lift": -0.03, "angle": 50}, {"law": "dwell", "angle": 250}]}
        )
    )  # fmt: skip
    with pytest.raises(UndercutError, match="cannot be cut"):
        write_profile(sharp, tmp_path / "p.csv")
    with pytest.raises(MechanismError, match=r"use \.dxf, \.svg or \.csv"):
        write_profile(DESIGN, tmp_path / "p.txt")
    assert math.isfinite(DESIGN.layout.prime)
