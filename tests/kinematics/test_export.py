"""Tests of the exports (kinematics.results.export): DXF read back with ezdxf, Parquet with pyarrow.

The DXF's entities are on their group's layers and sit where the solved pose
puts the points; the Parquet table holds the same numbers as the CSV.
"""

from __future__ import annotations

import csv
import io
import math
from collections import Counter

import numpy as np
import pytest

from kinematics.results.export import (
    CAM_LAYER,
    GROUND_LAYER,
    LABEL_LAYER,
    PITCH_LAYER,
    TEETH_LAYER,
    dxf_layers,
    dxf_left_out,
    write_dxf,
    write_parquet,
)
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_pose
from kinematics.solvers.sweep import sweep
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES

ezdxf = pytest.importorskip("ezdxf")

# fixtures with sliders, ternary links, a cam's virtual link, a class III group
DRAWN = (
    "fourbar",
    "quick_return_shaper",
    "scotch_yoke",
    "jansen",
    "cam_roller_follower",
    "eightbar_triad",
)


#: the layers of the higher pairs' own geometry (issue 22, item 11)
HIGHER_PAIR_LAYERS = {PITCH_LAYER, TEETH_LAYER, CAM_LAYER}


def _solved(name: str, turn: float = 0.7):
    report = analyze(read_edgelist(FIXTURES / f"{name}.edges"))
    plan = make_plan(report)
    inputs = None if report.replacements else tuple(turn for _ in plan.drivers)
    return report, plan, solve_pose(plan, inputs)


def _read_back(tmp_path, name: str, turn: float = 0.7):
    report, plan, state = _solved(name, turn)
    path = write_dxf(report, plan, state, tmp_path / f"{name}.dxf")
    return report, plan, state, ezdxf.readfile(path).modelspace()


@pytest.mark.parametrize("name", DRAWN)
def test_every_layer_is_a_group_the_ground_or_the_labels(tmp_path, name):
    report, _, _, msp = _read_back(tmp_path, name)
    groups = {g.label for g in report.groups} | {f"I({d})" for d in report.drivers}
    layers = {e.dxf.layer for e in msp}
    assert layers <= groups | {GROUND_LAYER, LABEL_LAYER} | HIGHER_PAIR_LAYERS
    assert groups <= layers  # every group is drawn
    assert any(e.dxftype() == "LINE" and e.dxf.layer == GROUND_LAYER for e in msp)


@pytest.mark.parametrize("name", DRAWN)
def test_pins_are_circles_where_the_pose_puts_them(tmp_path, name):
    report, plan, state, msp = _read_back(tmp_path, name)
    layers = dxf_layers(report)
    circles = [e for e in msp if e.dxftype() == "CIRCLE" and e.dxf.layer not in HIGHER_PAIR_LAYERS]
    hinges = [h for h in plan.mechanism.hinges if plan.mechanism.coordinates(h.point)]
    assert len(circles) == len(hinges)
    centres = {(round(e.dxf.center.x, 9), round(e.dxf.center.y, 9)): e.dxf.layer for e in circles}
    for hinge in hinges:
        x, y = state.points[hinge.point].position
        layer = centres[(round(float(x), 9), round(float(y), 9))]
        assert layer in {layers[link] for link in hinge.links}


def test_link_lines_join_the_solved_points_on_their_group_layer(tmp_path):
    _, _, state, msp = _read_back(tmp_path, "fourbar")
    lines = {e.dxf.layer: e for e in msp if e.dxftype() == "LINE" and e.dxf.layer != GROUND_LAYER}
    crank = lines["I(1)"]
    ends = [tuple(crank.dxf.start)[:2], tuple(crank.dxf.end)[:2]]
    expected = [tuple(state.points[p].position) for p in ("A", "B")]
    np.testing.assert_allclose(sorted(ends), sorted(expected), atol=1e-12)
    # the coupler has three points (B, C and the marker M): a closed polyline
    coupler = next(e for e in msp if e.dxftype() == "LWPOLYLINE")
    assert coupler.dxf.layer == "II(2,3)" and coupler.closed
    corners = sorted(tuple(p) for p in coupler.get_points("xy"))
    expected = sorted(tuple(map(float, state.points[p].position)) for p in ("B", "C", "M"))
    np.testing.assert_allclose(corners, expected, atol=1e-12)


def test_slider_blocks_turn_with_their_guide(tmp_path):
    _, _, state, msp = _read_back(tmp_path, "quick_return_shaper", turn=1.1)
    blocks = [e for e in msp if e.dxftype() == "LWPOLYLINE" and len(e) == 4]
    assert len(blocks) == 2  # the block in the lever's slot, the ram
    lever_angle = math.radians(76.102113752) + state.links["3"].angle
    slot_block = next(b for b in blocks if b.dxf.layer == "II(2,3)")
    a, b = (np.array(p) for p in list(slot_block.get_points("xy"))[:2])
    direction = math.atan2(*(b - a)[::-1])
    assert math.sin(direction - lever_angle) == pytest.approx(0.0, abs=1e-9)
    centre = np.mean([np.array(p) for p in slot_block.get_points("xy")], axis=0)
    assert centre == pytest.approx(state.points["B"].position)


def test_the_cam_virtual_link_is_dashed(tmp_path):
    report, _, _, msp = _read_back(tmp_path, "cam_roller_follower")
    virtual = {r.virtual_link for r in report.replacements}
    dashed = [e for e in msp if e.dxf.hasattr("linetype") and e.dxf.linetype == "DASHED"]
    assert dashed and all(e.dxf.layer == dxf_layers(report)[next(iter(virtual))] for e in dashed)


def test_entity_counts_of_the_four_bar(tmp_path):
    _, _, _, msp = _read_back(tmp_path, "fourbar")
    counts = Counter(e.dxftype() for e in msp)
    assert counts["CIRCLE"] == 4 and counts["POINT"] == 1  # pins A, B, C, D; marker M
    assert counts["TEXT"] == 6  # the four pins, M and the mechanism's name


def test_parquet_holds_the_csv_numbers(tmp_path):
    pyarrow_parquet = pytest.importorskip("pyarrow.parquet")
    plan = make_plan(analyze(read_edgelist(FIXTURES / "quick_return_shaper.edges")))
    result = sweep(plan, steps=12)
    table = pyarrow_parquet.read_table(write_parquet(result, tmp_path / "s.parquet"))
    rows = list(csv.reader(io.StringIO(result.to_csv())))
    assert table.column_names == rows[0]
    assert table.num_rows == 12
    for k, name in enumerate(rows[0]):
        assert table.column(name).to_pylist() == [float(row[k]) for row in rows[1:]]


# ------------------------------------------------------------------ higher pairs (issue 22, 11)
def _circles(msp, layer: str) -> list[tuple[float, float, float]]:
    return sorted(
        (round(e.dxf.center.x, 9), round(e.dxf.center.y, 9), round(e.dxf.radius, 9))
        for e in msp
        if e.dxftype() == "CIRCLE" and e.dxf.layer == layer
    )


def test_a_gear_pair_keeps_its_pitch_circles_and_tooth_numbers(tmp_path):
    """fixtures/gear_pair.edges: z = 20, 40, module 4 mm, centres O1 (0, 0) and O2 (0.12, 0):
    pitch radii m·z/2 = 0.04 and 0.08 m, which touch at the pitch point K (0.04, 0)."""
    _, _, _, msp = _read_back(tmp_path, "gear_pair")
    assert _circles(msp, PITCH_LAYER) == [(0.0, 0.0, 0.04), (0.12, 0.0, 0.08)]
    numbers = sorted(
        e.dxf.text for e in msp if e.dxftype() == "TEXT" and e.dxf.layer == TEETH_LAYER
    )
    assert numbers == ["z = 20", "z = 40"]


def test_a_cam_keeps_its_disc_and_roller(tmp_path):
    """fixtures/cam_roller_follower.edges: the disc of radius 0.05 about C1 (0.0173205, 0.01),
    the roller of radius 0.015 about R0 (0.0286076, 0.0740125), at the sketch pose."""
    _, _, _, msp = _read_back(tmp_path, "cam_roller_follower")
    found = _circles(msp, CAM_LAYER)
    expected = [(0.017320508, 0.01, 0.05), (0.02860764, 0.074012504, 0.015)]
    np.testing.assert_allclose(found, expected, atol=1e-8)


def test_a_flat_faced_follower_keeps_its_face(tmp_path):
    _, _, _, msp = _read_back(tmp_path, "cam_flat_follower")
    assert any(e.dxftype() == "LINE" and e.dxf.layer == CAM_LAYER for e in msp)
    assert any(e.dxftype() == "CIRCLE" and e.dxf.layer == CAM_LAYER for e in msp)


def test_the_name_and_every_named_point_are_in_the_drawing(tmp_path):
    report, _, _, msp = _read_back(tmp_path, "gear_pair")
    texts = {e.dxf.text for e in msp if e.dxftype() == "TEXT"}
    assert report.mechanism.name in texts
    assert set(report.mechanism.points) <= texts  # N1, N2: the centres of curvature too


def test_what_a_drawing_leaves_out_is_named():
    mechanism = read_edgelist(FIXTURES / "ch3_3_5_crank_slider.edges")
    kinds = {load.kind.value for load in mechanism.loads}
    lines = dxf_left_out(mechanism)
    assert any(line.startswith("DXF drawings hold no loads:") for line in lines)
    assert all(kind in " ".join(lines) for kind in kinds)
    assert dxf_left_out(read_edgelist(FIXTURES / "gear_pair.edges")) == (
        "DXF drawings hold no driver motion: omega of driver 1 left out",
    )
