"""Figures of a solved pose: the mechanism drawing and the velocity/acceleration polygons."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from matplotlib.colors import to_rgba
from matplotlib.text import Annotation

from kinematics.figures import (
    acceleration_polygon,
    draw_mechanism,
    save,
    velocity_polygon,
)
from kinematics.plan import make_plan
from kinematics.solve import solve_pose
from structure.constraints import sketch_problems
from structure.edgelist import read_edgelist
from structure.report import analyze

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _solved(path: Path):
    """(report, plan, state) of a fixture, or skip when it has no complete, solvable sketch."""
    try:
        report = analyze(read_edgelist(path))
        plan = make_plan(report)
        state = solve_pose(plan)
    except Exception as exc:
        pytest.fail(f"{path.name}: {type(exc).__name__}: {exc}")
    return report, plan, state


def _texts(ax, prefix: str) -> dict[str, str]:
    return {
        t.get_gid()[len(prefix) :]: t.get_text()
        for t in ax.texts
        if not isinstance(t, Annotation) and (t.get_gid() or "").startswith(prefix)
    }


def _scale(ax) -> float:
    found = re.search(r"μ_[va] = ([0-9.eE+-]+) ", ax.get_title())
    assert found, ax.get_title()
    return float(found.group(1))


def _arrows(ax) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    return {
        t.get_gid()[len("arrow:") :]: (np.asarray(t.xyann, float), np.asarray(t.xy, float))
        for t in ax.texts
        if isinstance(t, Annotation) and (t.get_gid() or "").startswith("arrow:")
    }


def _is_png(path: Path) -> bool:
    data = path.read_bytes()
    return len(data) > len(PNG_SIGNATURE) and data.startswith(PNG_SIGNATURE)


def _sketched() -> list[Path]:
    """Fixtures with a complete sketch (the others have nothing to draw)."""
    out = []
    for path in sorted(FIXTURES.glob("*.edges")):
        m = read_edgelist(path)
        if m.points and not sketch_problems(m):
            out.append(path)
    return out


@pytest.mark.parametrize("path", _sketched(), ids=lambda p: p.stem)
def test_fixture_figures(path: Path, tmp_path: Path) -> None:
    report, plan, state = _solved(path)
    m = plan.mechanism

    fig = draw_mechanism(report, plan, state)
    ax = fig.axes[0]
    assert save(fig, tmp_path / "mechanism.png").exists()
    assert _is_png(tmp_path / "mechanism.png")

    # every moving link and every named point has a label
    links = _texts(ax, "link:")
    assert {k for k in links} >= set(m.moving_links)
    assert all(links[k] == k for k in m.moving_links)
    points = _texts(ax, "point:")
    assert set(points) == set(plan.points)
    assert all(points[k] == k for k in plan.points)
    shown = {t.get_text() for t in ax.texts}
    assert shown >= set(m.moving_links) | set(plan.points)

    # the legend: one entry per group, then the drivers, colours matching the links
    legend = ax.get_legend()
    assert legend is not None
    entries = [t.get_text() for t in legend.get_texts()]
    expected = [
        f"{g.label}{' ' + g.kind if g.kind else ''}, order {g.order}" for g in report.groups
    ] + [f"driver {d}" for d in report.drivers]
    assert entries == expected
    handles = legend.legend_handles
    assert len(handles) == len(entries)
    lines = {ln.get_gid(): ln for ln in ax.lines}
    for group, handle in zip(report.groups, handles, strict=False):
        for link in group.links:
            line = lines.get(f"link:{link}")
            if line is None:  # a one-point link (a slider block) has no bar
                continue
            assert to_rgba(line.get_color()) == to_rgba(handle.get_color()), (group.label, link)
    for driver, handle in zip(report.drivers, handles[len(report.groups) :], strict=True):
        assert to_rgba(handle.get_color()) == to_rgba("black")
        if f"link:{driver}" in lines:
            assert to_rgba(lines[f"link:{driver}"].get_color()) == to_rgba("black")

    # pins and sliders are drawn
    assert any((p.get_gid() or "").startswith("pin:") for p in ax.patches) or not any(
        p.kind.value == "R" for p in m.pairs
    )
    sliders = [p for p in ax.patches if (p.get_gid() or "").startswith("slider:")]
    assert len(sliders) == sum(p.kind.value == "P" for p in m.pairs)

    for name, make in (("velocity", velocity_polygon), ("acceleration", acceleration_polygon)):
        fig = make(plan, state)
        pax = fig.axes[0]
        target = tmp_path / f"{name}.png"
        save(fig, target)
        assert _is_png(target)
        scale = _scale(pax)
        arrows = _arrows(pax)
        labels = _texts(pax, "label:")
        for point, ps in state.points.items():
            vec = ps.velocity if name == "velocity" else ps.acceleration
            biggest = max(
                float(np.linalg.norm(s.velocity if name == "velocity" else s.acceleration))
                for s in state.points.values()
            )
            if np.linalg.norm(vec) <= 1e-9 * max(biggest, 1e-12):
                assert point not in arrows
                continue
            tail, tip = arrows[point]
            assert np.allclose(tail, 0.0)
            assert np.allclose(tip * scale, vec, atol=1e-9 * max(biggest, 1.0))
            assert labels[point] == point.lower()


@pytest.fixture(scope="module")
def fourbar_2_4():
    report = analyze(read_edgelist(FIXTURES / "ch2_2_4_fourbar.edges"))
    plan = make_plan(report)
    return report, plan, solve_pose(plan)


def test_velocity_polygon_of_problem_2_4(fourbar_2_4, tmp_path: Path) -> None:
    # by hand: v_B = ω·AB = 20 · 0.1 = 2 m/s, to the left (B above A, ω CCW); BC ⟂ CD at this
    # pose, so the coupler translates instantaneously and v_C = v_B = (−2, 0) m/s.
    _, plan, state = fourbar_2_4
    fig = velocity_polygon(plan, state)
    ax = fig.axes[0]
    assert "μ_v" in ax.get_title() and "(m/s)/unit" in ax.get_title()
    scale = _scale(ax)
    tail, tip = _arrows(ax)["C"]
    assert np.allclose(tail, (0.0, 0.0))
    v = (tip - tail) * scale
    assert math.hypot(*v) == pytest.approx(2.0, rel=1e-9)
    assert math.degrees(math.atan2(v[1], v[0])) == pytest.approx(180.0, abs=1e-6)
    # the fixed pivots A and D have no arrow; the labels are lower case, the pole is p
    assert set(_arrows(ax)) == {"B", "C"}
    labels = _texts(ax, "label:")
    assert labels["C"] == "c" and labels["B"] == "b" and labels["pole"] == "p"
    path = save(fig, tmp_path / "v.png")
    assert _is_png(path)


def test_given_scale_is_used(fourbar_2_4) -> None:
    _, plan, state = fourbar_2_4
    ax = velocity_polygon(plan, state, scale=0.05).axes[0]
    assert _scale(ax) == pytest.approx(0.05)
    assert np.allclose(_arrows(ax)["C"][1], (-40.0, 0.0))
    with pytest.raises(ValueError):
        velocity_polygon(plan, state, scale=0.0)


def test_acceleration_polygon_pole_is_pi(fourbar_2_4) -> None:
    _, plan, state = fourbar_2_4
    ax = acceleration_polygon(plan, state).axes[0]
    assert _texts(ax, "label:")["pole"] == "π"
    assert "μ_a" in ax.get_title() and "(m/s²)/unit" in ax.get_title()


def test_save_formats(fourbar_2_4, tmp_path: Path) -> None:
    report, plan, state = fourbar_2_4
    fig = draw_mechanism(report, plan, state)
    assert _is_png(save(fig, tmp_path / "m.png"))
    assert save(fig, tmp_path / "m.svg").read_bytes().lstrip().startswith(b"<?xml")
    assert save(fig, tmp_path / "m.pdf").read_bytes().startswith(b"%PDF")
    with pytest.raises(ValueError):
        save(fig, tmp_path / "m.gif")


def test_existing_axes_are_drawn_on(fourbar_2_4) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    report, plan, state = fourbar_2_4
    fig = Figure()
    FigureCanvasAgg(fig)
    left, right = fig.subplots(1, 2)
    assert draw_mechanism(report, plan, state, ax=left) is fig
    assert velocity_polygon(plan, state, ax=right) is fig
    assert left.get_legend() is not None and _arrows(right)
