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
    GROUND_LAYER,
    LABEL_LAYER,
    dxf_layers,
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
    assert layers <= groups | {GROUND_LAYER, LABEL_LAYER}
    assert groups <= layers  # every group is drawn
    assert any(e.dxftype() == "LINE" and e.dxf.layer == GROUND_LAYER for e in msp)


@pytest.mark.parametrize("name", DRAWN)
def test_pins_are_circles_where_the_pose_puts_them(tmp_path, name):
    report, plan, state, msp = _read_back(tmp_path, name)
    layers = dxf_layers(report)
    circles = [e for e in msp if e.dxftype() == "CIRCLE"]
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
    assert counts["TEXT"] == 5  # the four pins and M


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
