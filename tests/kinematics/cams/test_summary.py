"""The report of a design as data: strict JSON for every follower, per-segment peaks by hand."""

from __future__ import annotations

import json
import math

import pytest

from kinematics.cams.design import make_design
from kinematics.cams.summary import cam_report, cam_report_to_dict
from structure.cams import cam_spec_from_dict

FOLLOWERS = [
    {"motion": "translating", "contact": "knife"},
    {"motion": "translating", "contact": "flat", "offset": 0.003},
    {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
    {"motion": "oscillating", "contact": "roller", "pivot": [0.1, 0.0], "arm": 0.08,
     "roller_radius": 0.01},
    {"motion": "oscillating", "contact": "flat", "pivot": [0.1, 0.03]},
]  # fmt: skip


@pytest.mark.parametrize("follower", FOLLOWERS)
def test_the_json_is_strict_and_whole(follower: dict) -> None:
    swinging = follower["motion"] == "oscillating"
    lift = 15 if swinging else 0.015
    spec = cam_spec_from_dict(
        {"omega": 8.0, "base_radius": 0.04, "follower": follower,
         "segments": [{"law": "3-4-5", "lift": lift, "angle": 100},
                      {"law": "dwell", "angle": 80},
                      {"law": "uniform", "lift": -lift, "angle": 180}]}
    )  # fmt: skip
    data = cam_report_to_dict(cam_report(make_design(spec), 90))

    def refuse(constant):
        raise ValueError(constant)

    text = json.dumps(data, allow_nan=False)
    assert json.loads(text, parse_constant=refuse) == data
    first = data["segments"][0]
    beta = math.radians(100)
    h = math.radians(lift) if swinging else lift
    # 3-4-5: C_v = 15/8, C_a = 10/√3 (by hand); uniform: v = h·ω/β exactly
    assert first["peak"]["v"] == pytest.approx(15 / 8 * h * 8 / beta, rel=1e-12)
    assert first["peak"]["a"] == pytest.approx(10 / math.sqrt(3) * h * 64 / beta**2, rel=1e-12)
    assert data["segments"][2]["peak"]["v"] == pytest.approx(h * 8 / math.pi, rel=1e-12)
    assert data["units"]["s"] == ("deg" if swinging else "m")
    assert max(data["samples"]["s"]) == pytest.approx(lift, rel=1e-12)
    # the uniform return: the velocity jumps at both its ends, C0
    names = [j["name"] for j in data["continuity"]]
    assert names == ["C2", "C0", "C0"]
    assert data["peak"]["j"]["infinite_at_deg"] == [180.0, 0.0]
