"""Figures of a solved pose: the mechanism drawing and the velocity/acceleration polygons."""

from __future__ import annotations

import itertools
import math
import re
import time
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from matplotlib.animation import FFMpegWriter
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch, Rectangle
from matplotlib.text import Annotation
from PIL import Image

from kinematics.cli.commands import main
from kinematics.figures.animation import animate, turn_inputs
from kinematics.figures.sheets import (
    acceleration_polygon,
    draw_graph,
    draw_mechanism,
    force_polygon,
    save,
    sweep_figure,
    velocity_polygon,
)
from kinematics.kinetostatics.forces import solve_forces
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_pose
from kinematics.solvers.sweep import sweep
from structure.errors import MechanismError
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze
from structure.rigidity.constraints import sketch_problems

from ..conftest import sampled

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


def _components(ax) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The drawn terms of the dyads' equations: gid -> (tail, tip), drawing units."""
    return {
        t.get_gid(): (np.asarray(t.xyann, float), np.asarray(t.xy, float))
        for t in ax.texts
        if isinstance(t, Annotation) and (t.get_gid() or "").startswith(("rel:", "comp:"))
    }


def _component_labels(ax) -> dict[str, str]:
    return {
        t.get_gid(): t.get_text()
        for t in ax.texts
        if not isinstance(t, Annotation) and (t.get_gid() or "").startswith(("rel:", "comp:"))
    }


def _check_components(ax, scale: float) -> None:
    """Every term starts and ends at a point's image (or its partner), labelled with its gid."""
    images = [np.zeros(2)] + [tip for _, tip in _arrows(ax).values()]
    size = max([1.0] + [float(np.abs(p).max()) for p in images])

    def at_image(p: np.ndarray) -> bool:
        return any(np.linalg.norm(p - q) <= 1e-7 * size for q in images)

    drawn = _components(ax)
    labels = _component_labels(ax)
    assert set(drawn) <= set(labels)
    for gid in labels:
        kind, _, key = gid.partition(":")
        head, _, sub = key.partition("_")
        if kind == "rel":
            assert head == "v"
            if gid in drawn:
                tail, tip = drawn[gid]
                assert at_image(tail) and at_image(tip), gid
            continue
        assert head in ("a^n", "a^t", "a^k", "a^r"), gid
        first = {"a^t": "a^n", "a^r": "a^k"}.get(head)
        if first is None:
            continue
        one, two = drawn.get(f"comp:{first}_{sub}"), drawn.get(gid)
        assert f"comp:{first}_{sub}" in labels
        if one is not None:
            assert at_image(one[0]), gid
        if two is not None:
            assert at_image(two[1]), gid
        if one is not None and two is not None:
            assert np.allclose(one[1], two[0], atol=1e-7 * size)
        if one is None and two is not None:
            assert at_image(two[0]), gid
        if two is None and one is not None:
            assert at_image(one[1]), gid


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


@pytest.mark.parametrize("path", sampled(_sketched(), stem=lambda p: p.stem))
def test_fixture_figures(path: Path, tmp_path: Path) -> None:
    report, plan, state = _solved(path)
    m = plan.mechanism

    fig = draw_mechanism(report, plan, state)
    ax = fig.axes[0]
    assert save(fig, tmp_path / "mechanism.png").exists()
    assert _is_png(tmp_path / "mechanism.png")

    # every moving link (those of the file, e.g. a roller, and the virtual ones) and every
    # named point (pins, markers, contact points) has a label
    links = _texts(ax, "link:")
    every_link = set(m.moving_links) | set(report.mechanism.moving_links)
    assert set(links) >= every_link
    assert all(links[k] == k for k in every_link)
    contacts = {r.pair.point for r in report.replacements if r.pair.point}
    points = _texts(ax, "point:")
    assert set(points) == set(plan.points) | contacts
    assert all(points[k] == k for k in points)
    shown = {t.get_text() for t in ax.texts}
    assert shown >= every_link | set(plan.points)

    # the legend: one entry per group, then the drivers, colours matching the links
    legend = ax.get_legend()
    assert legend is not None
    entries = [t.get_text() for t in legend.get_texts()]
    expected = [
        f"{g.label}{' ' + g.kind if g.kind else ''}, order {g.order}" for g in report.groups
    ] + [f"driver {d}" for d in report.drivers]
    if report.replacements:
        expected.append("virtual link (replaces a higher pair)")
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
    driver_handles = handles[len(report.groups) : len(report.groups) + len(report.drivers)]
    for driver, handle in zip(report.drivers, driver_handles, strict=True):
        assert to_rgba(handle.get_color()) == to_rgba("black")
        if f"link:{driver}" in lines:
            assert to_rgba(lines[f"link:{driver}"].get_color()) == to_rgba("black")

    # pins and sliders are drawn
    assert any((p.get_gid() or "").startswith("pin:") for p in ax.patches) or not any(
        p.kind.value == "R" for p in m.pairs
    )
    sliders = [p for p in ax.patches if (p.get_gid() or "").startswith("slider:")]
    assert len(sliders) == sum(p.kind.value == "P" for p in m.pairs)
    # virtual links dashed, the others solid; each higher pair's contact point is a dot
    for link in m.moving_links:
        line = lines.get(f"link:{link}")
        if line is not None:
            virtual = link in {r.virtual_link for r in report.replacements}
            assert (line.get_linestyle() == "--") == virtual, link
    dots = {ln.get_gid() for ln in ax.lines}
    assert {f"contact:{k}" for k in contacts} <= dots
    # markers are dots; each driver carries an arrow of its motion
    assert {f"marker:{n}" for n, p in m.points.items() if p.on} <= dots
    arrows = {a.get_gid() for a in ax.get_children() if isinstance(a, FancyArrowPatch)}
    assert {f"driver:{d}" for d in report.drivers} <= arrows

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
        _check_components(pax, scale)


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
    assert np.allclose(v, (-2.0, 0.0), atol=1e-9)  # (atan2 of a −0.0 y would say −180°)
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


# ---------------------------------------------------------------- relative vectors, components


def _vec(ax, gid: str, scale: float) -> tuple[np.ndarray, np.ndarray]:
    """(tail, vector) of a drawn term, m/s or m/s²."""
    tail, tip = _components(ax)[gid]
    return tail * scale, (tip - tail) * scale


def _zero_term(ax, gid: str) -> None:
    """A zero term: no arrow, a dot, and its label ``… = 0``."""
    assert gid not in _components(ax)
    assert "= 0" in _component_labels(ax)[gid]
    assert any(ln.get_gid() == gid for ln in ax.lines)


def test_velocity_polygon_relative_vectors_of_problem_2_4(fourbar_2_4) -> None:
    # by hand: B = (0, 0.1) turns about A at ω1 = 20 CCW: v_B = ω1·J(AB) = (−2, 0) m/s.
    # AB ∥ DC and BC ⟂ both: v_B and v_C are both horizontal, the coupler's instant centre
    # is at infinity, ω2 = 0: v_CB = ω2·l_BC = 0 and v_C = v_B. From d (= p, D is on the
    # ground): v_CD = v_C − 0 = (−2, 0), |v_CD| = 2 m/s ⊥ CD (CD vertical) and ω3 = 2/0.4 = 5.
    _, plan, state = fourbar_2_4
    ax = velocity_polygon(plan, state).axes[0]
    scale = _scale(ax)
    assert set(_component_labels(ax)) == {"rel:v_CB", "rel:v_CD"}
    _zero_term(ax, "rel:v_CB")
    tail, v_cd = _vec(ax, "rel:v_CD", scale)
    assert np.allclose(tail, (0.0, 0.0), atol=1e-12)
    assert np.allclose(v_cd, (-2.0, 0.0), atol=1e-9)
    assert np.allclose(_components(ax)["rel:v_CD"][1], _arrows(ax)["C"][1])  # it ends at c
    assert "v_{CD}" in _component_labels(ax)["rel:v_CD"]


def test_acceleration_polygon_components_of_problem_2_4(fourbar_2_4) -> None:
    # by hand (ε1 = 0, ω2 = 0, ω3 = 5 from the velocities):
    #   a_B = −ω1²·AB = −400·(0, 0.1) = (0, −40), toward A.
    #   from b': a^n_CB = ω2²·l_BC = 0; a^τ_CB ⊥ BC (BC horizontal: vertical), unknown.
    #   from d' = π: a^n_CD = ω3²·l_CD = 25·0.4 = 10 m/s² from C toward D: (0, −10);
    #   a^τ_CD ⊥ CD (horizontal), unknown.
    #   a_B + a^τ_CB·(0, 1) = a^n_CD + a^τ_CD·(1, 0):  x: 0 = a^τ_CD;  y: −40 + a^τ_CB = −10,
    #   so a^τ_CB = 30 m/s² upward (ε2 = 30/0.4 = 75) and a^τ_CD = 0 (ε3 = 0); a_C = (0, −10).
    _, plan, state = fourbar_2_4
    ax = acceleration_polygon(plan, state).axes[0]
    scale = _scale(ax)
    assert set(_component_labels(ax)) == {
        "comp:a^n_CB",
        "comp:a^t_CB",
        "comp:a^n_CD",
        "comp:a^t_CD",
    }
    _zero_term(ax, "comp:a^n_CB")
    _zero_term(ax, "comp:a^t_CD")
    b = np.array([0.0, -40.0])
    tail, t_cb = _vec(ax, "comp:a^t_CB", scale)
    assert np.allclose(tail, b, atol=1e-9)  # from b' (a^n_CB = 0 adds nothing)
    assert np.allclose(t_cb, (0.0, 30.0), atol=1e-9)
    tail, n_cd = _vec(ax, "comp:a^n_CD", scale)
    assert np.allclose(tail, (0.0, 0.0), atol=1e-12)  # from d' = π
    assert np.allclose(n_cd, (0.0, -10.0), atol=1e-9)
    # the polygon closes: b' + a^n_CB + a^τ_CB = c' = d' + a^n_CD + a^τ_CD
    c = _arrows(ax)["C"][1] * scale
    assert np.allclose(b + 0.0 + t_cb, c, atol=1e-9)
    assert np.allclose(np.zeros(2) + n_cd + 0.0, c, atol=1e-9)
    assert np.allclose(c, (0.0, -10.0), atol=1e-9)
    labels = _component_labels(ax)
    assert "a^{n}_{CD}" in labels["comp:a^n_CD"] and r"a^{\tau}_{CB}" in labels["comp:a^t_CB"]
    entries = [t.get_text() for t in ax.get_legend().get_texts()]
    assert entries[0] == "absolute, from π" and len(entries) == 3


@pytest.fixture(scope="module")
def slotted_exam():
    report = analyze(read_edgelist(FIXTURES / "exam_1_slotted_link.edges"))
    plan = make_plan(report)
    return report, plan, solve_pose(plan)


def _slotted_by_hand():
    """Exam problem 1 by hand: a = 0.1, ω = 10 CCW; A = (0, 0), B = (a, 0), C = (0, −a).

    Block 2 on the crank pin B slides along slotted link 3, which turns about C; the slot
    is the line CB, u = (1, 1)/√2, n = u turned +90° = (−1, 1)/√2.
    """
    a, w = 0.1, 10.0
    AB, CB = np.array([a, 0.0]), np.array([a, a])
    u = CB / np.hypot(*CB)
    n = np.array([-u[1], u[0]])
    l_cb = math.hypot(*CB)  # a√2
    v_b2 = w * np.array([-AB[1], AB[0]])  # (0, 1): v_B1 = v_B2 (pin)
    # v_B3 = v_B2 + v_B3B2, v_B3 ⊥ CB (along n), v_B3B2 ∥ CB (along u):
    v_b3 = (v_b2 @ n) * n  # (−0.5, 0.5), |v_B3| = a·ω/√2
    v_rel = v_b3 - v_b2  # (−0.5, −0.5), a·ω/√2 along −u
    w3 = (v_b3 @ n) / l_cb  # = ω/2 = 5, counter-clockwise
    # Coriolis: 2·ω3·v_rel, v_rel turned 90° in the sense of ω3 (CCW: +90°)
    a_k = 2.0 * w3 * np.array([-v_rel[1], v_rel[0]])
    a_b2 = -(w**2) * AB  # (−10, 0)
    a_n = -(w3**2) * CB  # a^n_B3C: ω3²·l_CB from B toward C
    # a_n + t·n = a_b2 + a_k + r·u: the two unknowns t (a^τ_B3C) and r (a^r_B3B2)
    t, r = np.linalg.solve(np.column_stack([n, -u]), a_b2 + a_k - a_n)
    return {
        "w3": w3, "v_b2": v_b2, "v_b3": v_b3, "v_rel": v_rel, "a_k": a_k, "a_b2": a_b2,
        "a_n": a_n, "t": t, "r": r, "u": u, "n": n,
    }  # fmt: skip


def test_velocity_polygon_of_the_slotted_link(slotted_exam) -> None:
    h = _slotted_by_hand()
    assert h["w3"] == pytest.approx(5.0)  # ω/2
    _, plan, state = slotted_exam
    ax = velocity_polygon(plan, state).axes[0]
    scale = _scale(ax)
    assert set(_component_labels(ax)) == {"rel:v_B3C", "rel:v_B3B2"}
    tail, v_rel = _vec(ax, "rel:v_B3B2", scale)
    assert np.allclose(tail, h["v_b2"], atol=1e-9)  # from b (= b2 = b1)
    assert np.allclose(v_rel, h["v_rel"], atol=1e-9)  # ∥ the slot
    assert abs(v_rel[0] * h["u"][1] - v_rel[1] * h["u"][0]) < 1e-9
    tail, v_b3c = _vec(ax, "rel:v_B3C", scale)
    assert np.allclose(tail, 0.0, atol=1e-12) and np.allclose(v_b3c, h["v_b3"], atol=1e-9)
    assert np.allclose(_arrows(ax)["B3"][1] * scale, h["v_b3"], atol=1e-9)


def test_acceleration_polygon_coriolis_of_the_slotted_link(slotted_exam) -> None:
    h = _slotted_by_hand()
    # printed: Coriolis a·ω²/√2, ε3 = 0
    assert math.hypot(*h["a_k"]) == pytest.approx(0.1 * 10.0**2 / math.sqrt(2))
    assert h["t"] == pytest.approx(0.0, abs=1e-12)
    _, plan, state = slotted_exam
    ax = acceleration_polygon(plan, state).axes[0]
    scale = _scale(ax)
    assert set(_component_labels(ax)) == {
        "comp:a^n_B3C",
        "comp:a^t_B3C",
        "comp:a^k_B3B2",
        "comp:a^r_B3B2",
    }
    tail, a_k = _vec(ax, "comp:a^k_B3B2", scale)
    assert np.allclose(tail, h["a_b2"], atol=1e-9)  # from b' (the crank pin's a)
    # magnitude 2·ω3·v_rel, direction v_rel turned 90° counter-clockwise (ω3 > 0)
    v_rel = math.hypot(*h["v_rel"])
    assert math.hypot(*a_k) == pytest.approx(2 * h["w3"] * v_rel, rel=1e-9)
    turned = np.array([-h["v_rel"][1], h["v_rel"][0]]) / v_rel
    assert np.allclose(a_k / math.hypot(*a_k), turned, atol=1e-9)
    assert np.allclose(a_k, (5.0, -5.0), atol=1e-9)
    tail, a_r = _vec(ax, "comp:a^r_B3B2", scale)
    assert np.allclose(tail, h["a_b2"] + h["a_k"], atol=1e-9)  # from the point k
    assert np.allclose(a_r, h["r"] * h["u"], atol=1e-9)  # ∥ the slot, 2.5·(1, 1)
    tail, a_n = _vec(ax, "comp:a^n_B3C", scale)
    assert np.allclose(tail, 0.0, atol=1e-12) and np.allclose(a_n, h["a_n"], atol=1e-9)
    _zero_term(ax, "comp:a^t_B3C")  # ε3 = 0
    b3 = _arrows(ax)["B3"][1] * scale
    assert np.allclose(h["a_b2"] + a_k + a_r, b3, atol=1e-9)
    assert np.allclose(a_n, b3, atol=1e-9)
    nodes = {ln.get_gid(): ln for ln in ax.lines if (ln.get_gid() or "").startswith("node:")}
    k = np.array([nodes["node:k_B3B2"].get_xdata()[0], nodes["node:k_B3B2"].get_ydata()[0]])
    assert np.allclose(k * scale, h["a_b2"] + h["a_k"], atol=1e-9)
    assert "a^{k}_{B3B2}" in _component_labels(ax)["comp:a^k_B3B2"]


def test_guide_point_without_a_marker_is_added(slotted_exam) -> None:
    # without the marker B3, the point of the slotted link under B still has its image b3:
    # by hand v_B3 = (−0.5, 0.5) m/s (see _slotted_by_hand)
    path = FIXTURES / "exam_1_slotted_link.edges"
    lines = [ln for ln in path.read_text().splitlines() if not ln.startswith("point B3 ")]

    plan = make_plan(analyze(parse_edgelist(lines)))
    ax = velocity_polygon(plan, solve_pose(plan)).axes[0]
    scale = _scale(ax)
    assert np.allclose(_arrows(ax)["B3"][1] * scale, _slotted_by_hand()["v_b3"], atol=1e-9)
    assert _texts(ax, "label:")["B3"] == "b3"
    tail, v_rel = _vec(ax, "rel:v_B3B2", scale)
    assert np.allclose((tail + v_rel), _slotted_by_hand()["v_b3"], atol=1e-9)


def test_triad_has_only_absolute_vectors() -> None:
    # the eight-bar: the dyad II(2,3) (pin C, from B and D) has its terms, the triad none
    _, plan, state = _solved(FIXTURES / "eightbar_triad.edges")
    ax = velocity_polygon(plan, state).axes[0]
    assert set(_component_labels(ax)) == {"rel:v_CB", "rel:v_CD"}
    ax = acceleration_polygon(plan, state).axes[0]
    assert {g.split("_")[-1] for g in _component_labels(ax)} == {"CB", "CD"}


def test_save_formats(fourbar_2_4, tmp_path: Path) -> None:
    report, plan, state = fourbar_2_4
    fig = draw_mechanism(report, plan, state)
    assert _is_png(save(fig, tmp_path / "m.png"))
    assert save(fig, tmp_path / "m.svg").read_bytes().lstrip().startswith(b"<?xml")
    assert save(fig, tmp_path / "m.pdf").read_bytes().startswith(b"%PDF")
    with pytest.raises(ValueError):
        save(fig, tmp_path / "m.gif")


def test_existing_axes_are_drawn_on(fourbar_2_4) -> None:

    report, plan, state = fourbar_2_4
    fig = Figure()
    FigureCanvasAgg(fig)
    left, right = fig.subplots(1, 2)
    assert draw_mechanism(report, plan, state, ax=left) is fig
    assert velocity_polygon(plan, state, ax=right) is fig
    assert left.get_legend() is not None and _arrows(right)


# ---------------------------------------------------------------- mechanism drawing details


def _patches(ax, prefix: str) -> dict:
    return {p.get_gid(): p for p in ax.patches if (p.get_gid() or "").startswith(prefix)}


def _point(m, name: str) -> np.ndarray:
    return np.array(m.coordinates(name), dtype=float)


def test_cam_and_roller_are_two_circles_touching_at_the_contact() -> None:
    # the fixture's design: disc cam of radius 0.05 about C1, roller of radius 0.015 about R0,
    # touching at K; the roller (link 3) is removed by the replacement, v1 = C1–R0 stands in.
    report, plan, state = _solved(FIXTURES / "cam_roller_follower.edges")
    ax = draw_mechanism(report, plan, state).axes[0]
    m = report.mechanism
    (pair,) = [p for p in m.pairs if p.kind.value == "H"]
    profiles = _patches(ax, f"profile:{pair.id}:")
    cam, roller = profiles[f"profile:{pair.id}:1"], profiles[f"profile:{pair.id}:3"]
    assert isinstance(cam, Circle) and isinstance(roller, Circle)
    assert cam.get_radius() == pytest.approx(0.05, abs=1e-8)
    assert roller.get_radius() == pytest.approx(0.015, abs=1e-8)
    assert np.allclose(cam.center, _point(m, "C1")) and np.allclose(roller.center, _point(m, "R0"))
    # external contact: the centres are r1 + r2 apart and K lies on both circles
    gap = float(np.hypot(*(np.subtract(cam.center, roller.center))))
    assert gap == pytest.approx(0.05 + 0.015, abs=1e-8)
    k = _point(m, "K")
    assert float(np.hypot(*(k - cam.center))) == pytest.approx(0.05, abs=1e-8)
    dot = next(ln for ln in ax.lines if ln.get_gid() == "contact:K")
    assert np.allclose(np.ravel(dot.get_xydata()), k)
    # the virtual link is dashed from C1 to R0; the removed roller is still labelled
    v1 = next(ln for ln in ax.lines if ln.get_gid() == "link:v1")
    assert v1.get_linestyle() == "--"
    assert {tuple(p) for p in np.round(v1.get_xydata(), 9)} == {
        tuple(np.round(_point(m, "C1"), 9)),
        tuple(np.round(_point(m, "R0"), 9)),
    }
    assert _texts(ax, "link:")["3"] == "3"


def test_gear_mesh_is_two_pitch_circles_tangent_at_the_pitch_point() -> None:
    # z1 = 20, z2 = 40 on a centre distance a = |O1O2| = 0.12: pitch radii a·z/(z1 + z2)
    report, plan, state = _solved(FIXTURES / "gear_pair.edges")
    ax = draw_mechanism(report, plan, state).axes[0]
    m = report.mechanism
    (pair,) = [p for p in m.pairs if p.gear]
    a = float(np.hypot(*(_point(m, "O2") - _point(m, "O1"))))
    pitch = _patches(ax, "pitch:")
    for link, axis, z in (("1", "O1", 20), ("2", "O2", 40)):
        circle = pitch[f"pitch:{pair.id}:{link}"]
        assert circle.get_radius() == pytest.approx(a * z / 60, rel=1e-6)
        assert np.allclose(circle.center, _point(m, axis))
        assert circle.get_linestyle() == "-."
    assert a == pytest.approx(pitch[f"pitch:{pair.id}:1"].get_radius() * 3, rel=1e-6)


def test_flat_faced_follower_and_knife_edge() -> None:
    # disc cam (radius 0.05 about C1) on a horizontal flat face through K
    report, plan, state = _solved(FIXTURES / "cam_flat_follower.edges")
    ax = draw_mechanism(report, plan, state).axes[0]
    m = report.mechanism
    (pair,) = [p for p in m.pairs if p.kind.value == "H"]
    face = next(ln for ln in ax.lines if ln.get_gid() == f"profile:{pair.id}:2")
    xy = face.get_xydata()
    assert np.allclose(xy[:, 1], 0.06)  # horizontal, at the face's height
    assert xy[:, 0].min() < _point(m, "K")[0] < xy[:, 0].max()
    disc = _patches(ax, "profile:")[f"profile:{pair.id}:1"]
    assert disc.get_radius() == pytest.approx(0.05, abs=1e-8)
    # the virtual link's slide along the face is dashed and hollow
    (virtual_slide,) = [p for p in plan.mechanism.pairs if "v1" in p.links and p.kind.value == "P"]
    block = _patches(ax, "slider:")[f"slider:{virtual_slide.id}"]
    assert block.get_linestyle() == "--" and block.get_facecolor()[3] == 0.0

    # problem 3.9: the cam's flat at 45° through the knife edge B, no curve for the knife edge
    report, plan, state = _solved(FIXTURES / "ch3_3_9_cam_flat.edges")
    ax = draw_mechanism(report, plan, state).axes[0]
    (pair,) = [p for p in report.mechanism.pairs if p.kind.value == "H"]
    face = next(ln for ln in ax.lines if ln.get_gid() == f"profile:{pair.id}:1")
    d = np.diff(face.get_xydata(), axis=0)[0]
    assert math.degrees(math.atan2(d[1], d[0])) % 180 == pytest.approx(45.0, abs=1e-9)
    assert f"profile:{pair.id}:2" not in {ln.get_gid() for ln in ax.lines} | set(
        _patches(ax, "profile:")
    )


def test_drawing_follows_the_pose(fourbar_2_4) -> None:
    # crank turned by φ from the sketch: B = 0.1·(cos(90° + φ), sin(90° + φ)); C on the circles
    # |CB| = |CD| = 0.4 about B and D = (0.4, −0.3), on the left of B→D as in the sketch
    report, plan, _ = fourbar_2_4
    phi = 1.0
    state = solve_pose(plan, (phi,))
    ax = draw_mechanism(report, plan, state).axes[0]
    b, c = _fourbar_bc(np.array([phi]))
    coupler = next(ln for ln in ax.lines if ln.get_gid() == "link:2").get_xydata()
    assert np.allclose(sorted(map(tuple, coupler)), sorted([tuple(b[0]), tuple(c[0])]))
    assert np.allclose(_patches(ax, "pin:")["pin:C"].center, c[0])
    label = next(t for t in ax.texts if t.get_gid() == "point:C")
    nudge = np.subtract(label.get_position(), c[0])  # beside the pin, up and to the right
    assert nudge[0] == pytest.approx(nudge[1]) and 0 < nudge[0] < 0.05


# ---------------------------------------------------------------- kinematic graph


def _graph_parts(ax):
    nodes = {p.get_gid()[5:]: p for p in ax.patches if (p.get_gid() or "").startswith("node:")}
    edges = {
        int(p.get_gid()[5:]): p
        for p in ax.patches
        if isinstance(p, FancyArrowPatch) and (p.get_gid() or "").startswith("edge:")
    }
    labels = {int(t.get_gid()[5:]): t for t in ax.texts if (t.get_gid() or "").startswith("edge:")}
    return nodes, edges, labels


def test_kinematic_graph_of_the_oxygen_pump() -> None:
    # printed counts (fig. 1.4a): n = 6 moving links, P5 = 8, P4 = 1; the gear contact becomes
    # one virtual link with two R pairs: 7 + 1 nodes, 9 + 2 edges
    report = analyze(read_edgelist(FIXTURES / "ch1_1_4a_oxygen_pump.edges"))
    fig = draw_graph(report)
    ax = fig.axes[0]
    nodes, edges, labels = _graph_parts(ax)
    assert len(nodes) == 6 + 1 + 1 and set(nodes) == {*report.mechanism.links, "v1"}
    assert len(edges) == 8 + 1 + 2 == len(labels)
    m = report.mechanism
    (rep,) = report.replacements
    assert set(edges) == {p.id for p in m.pairs} | {p.id for p in rep.new_pairs}
    for pair in (*m.pairs, *rep.new_pairs):
        assert labels[pair.id].get_text().split()[0] == pair.kind.value
        dashed = pair in rep.new_pairs
        assert (edges[pair.id].get_linestyle() == "--") == dashed
    # colours: each group's nodes in its legend colour, drivers black, ground hatched square
    legend = ax.get_legend()
    handles = dict(
        zip([t.get_text() for t in legend.get_texts()], legend.legend_handles, strict=True)
    )
    for group in report.groups:
        colour = to_rgba(handles[f"{group.label}{' ' + group.kind if group.kind else ''}, "
                                 f"order {group.order}"].get_color())  # fmt: skip
        for link in group.links:
            node = nodes[link]
            shown = node.get_edgecolor() if link == "v1" else node.get_facecolor()
            assert to_rgba(shown) == colour, link
    assert to_rgba(nodes["1"].get_facecolor()) == to_rgba("black")
    assert to_rgba(handles["driver 1"].get_color()) == to_rgba("black")
    assert isinstance(nodes["0"], Rectangle) and nodes["0"].get_hatch()
    assert nodes["v1"].get_linestyle() == "--"
    assert "virtual link (replaces a higher pair)" in handles
    # each node is labelled with its link, at its centre
    names = {t.get_gid()[5:]: t for t in ax.texts if (t.get_gid() or "").startswith("node:")}
    assert all(names[n].get_text() == n for n in nodes)


def test_parallel_pairs_are_drawn_apart() -> None:
    # links 2 and 3 joined twice: a pin C and a higher pair K (five-bar with one more contact)

    m = parse_edgelist(
        ["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 4 R D", "4 0 R E", "2 3 H K"]
    )
    report = analyze(m)
    ax = draw_graph(report).axes[0]
    _, edges, labels = _graph_parts(ax)
    pin, contact = (p.id for p in m.pairs if set(p.links) == {"2", "3"})
    rads = {edges[pin].get_connectionstyle().rad, edges[contact].get_connectionstyle().rad}
    assert len(rads) == 2 and 0.0 not in rads  # bowed to either side
    assert labels[pin].get_text() == "R C" and labels[contact].get_text() == "H K"
    gap = np.subtract(labels[pin].get_position(), labels[contact].get_position())
    assert float(np.hypot(*gap)) > 0.05


# ---------------------------------------------------------------- force polygons


def _force_arrows(ax) -> list[tuple[str, np.ndarray, np.ndarray]]:
    return [
        (t.get_gid()[6:], np.asarray(t.xyann, float), np.asarray(t.xy, float))
        for t in ax.texts
        if isinstance(t, Annotation) and (t.get_gid() or "").startswith("force:")
    ]


def _mu_f(ax) -> float:
    found = re.search(r"μ_F = ([0-9.eE+-]+) N/unit", ax.get_title())
    assert found, ax.get_title()
    return float(found.group(1))


def _check_closed(ax) -> dict[str, np.ndarray]:
    """Head to tail from the origin back to it; the forces (N) by key."""
    arrows = _force_arrows(ax)
    mu = _mu_f(ax)
    if not arrows:  # no force at all (a flywheel loaded by its inertia moment only)
        return {}
    extent = max(float(np.hypot(*(tip - tail))) for _, tail, tip in arrows)
    assert np.allclose(arrows[0][1], 0.0)
    for (_, _, tip), (_, tail, _) in itertools.pairwise(arrows):
        assert np.allclose(tail, tip)
    assert float(np.hypot(*arrows[-1][2])) <= 1e-9 * extent  # it closes
    return {key: (tip - tail) * mu for key, tail, tip in arrows}


def test_force_polygons_of_problem_3_4() -> None:
    # by hand: coupler 2 (B→C, horizontal) carries only pin forces, so R12 = (f, 0); moments of
    # rocker 3 about D: C − D = 0.2√2·(1, 1), M3 − D = 0.1√2·(1, 1), P3 = 500√2·(1, −1):
    # −0.2√2·f − 200 = 0 → f = −500√2; R03 = −(P3 + R12) = (0, 500√2). Crank 1: R21 = −R12 at
    # B = (0, 0.1), R01 = −R21, M_cb = −(B × R21) = 0.1·500√2 = 50√2 N·m.

    _, plan, _ = _solved(FIXTURES / "ch3_3_4_fourbar.edges")
    solution = solve_forces(plan)
    fig = force_polygon(plan, solution)
    group, driver = fig.axes
    s = 500 * math.sqrt(2)
    forces = _check_closed(group)
    assert set(forces) == {"load:3:M3", "reaction:1->2:B", "reaction:0->3:D"}
    assert np.allclose(forces["load:3:M3"], (s, -s))
    assert np.allclose(forces["reaction:1->2:B"], (-s, 0.0))
    assert np.allclose(forces["reaction:0->3:D"], (0.0, s))
    labels = _texts(group, "label:")
    assert labels["reaction:1->2:B"] == "R12" and labels["reaction:0->3:D"] == "R03"
    assert "II(2,3)" in group.get_title()
    forces = _check_closed(driver)
    assert np.allclose(forces["reaction:2->1:B"], (s, 0.0))
    assert np.allclose(forces["reaction:0->1:A"], (-s, 0.0))
    found = re.search(r"M_cb = ([0-9.eE+-]+) N·m", driver.get_title())
    assert found and float(found.group(1)) == pytest.approx(50 * math.sqrt(2), rel=1e-5)
    # one group alone, a given scale; an unknown label
    ax = force_polygon(plan, solution, "II(2,3)", scale=5.0).axes[0]
    assert _mu_f(ax) == 5.0
    arrows = {k: tip - tail for k, tail, tip in _force_arrows(ax)}
    assert np.allclose(arrows["load:3:M3"], (s / 5, -s / 5))
    with pytest.raises(ValueError, match="II\\(2,3\\)"):
        force_polygon(plan, solution, "II(4,5)")


def test_force_polygon_of_problem_3_5() -> None:
    # by hand: rod 2 is a two-force member along C→B = (−√3/2, 1/2); the slide pushes along y;
    # P3 = (1000, 0): R12 = t·(−√3/2, 1/2) with t = 2000/√3, R03 = (0, −t/2)

    _, plan, _ = _solved(FIXTURES / "ch3_3_5_crank_slider.edges")
    ax = force_polygon(plan, solve_forces(plan), "II(2,3)").axes[0]
    forces = _check_closed(ax)
    t = 2000 / math.sqrt(3)
    assert np.allclose(forces["load:3:E"], (1000.0, 0.0))
    assert np.allclose(forces["reaction:1->2:B"], (-t * math.sqrt(3) / 2, t / 2))
    assert np.allclose(forces["reaction:0->3:C"], (0.0, -t / 2))


def test_force_polygon_with_weight_and_inertia() -> None:
    # crank of 2 kg, centre of mass S at 0.1 m on the x axis, ω = 10, ε = 0, g = (0, −9.81):
    # a_S = −ω²·S = (−10, 0) → inertia Φ1 = −m·a_S = (20, 0); weight G1 = (0, −19.62);
    # the frame's pin R01 = −(Φ1 + G1); M_cb = −(S × G1) = 0.1·19.62 = 1.962 N·m

    m = parse_edgelist(
        ["driver 1 omega=10", "0 1 R A", "point A 0 0", "point S 0.1 0 on=1",
         "mass 1 2 0.01 S", "gravity 0 -9.81"]
    )  # fmt: skip
    plan = make_plan(analyze(m))
    ax = force_polygon(plan, solve_forces(plan)).axes[0]
    forces = _check_closed(ax)
    assert np.allclose(forces["inertia:1"], (20.0, 0.0))
    assert np.allclose(forces["weight:1"], (0.0, -19.62))
    assert np.allclose(forces["reaction:0->1:A"], (-20.0, 19.62))
    assert "M_cb = 1.962 N·m" in ax.get_title()
    assert _texts(ax, "label:")["inertia:1"] == "Φ1"


def test_force_polygon_of_a_sliding_driver() -> None:
    # problem 3.1: a 2 kg slider driven along x with a = 10 m/s² on a smooth guide: the
    # inertia force −m·a = (−20, 0) N is balanced by the driving force P_cb = m·a = 20 N along x

    _, plan, _ = _solved(FIXTURES / "ch3_3_1_slider_power.edges")
    ax = force_polygon(plan, solve_forces(plan)).axes[0]
    forces = _check_closed(ax)
    assert np.allclose(forces["inertia:1"], (-20.0, 0.0))
    assert np.allclose(forces["balance:1"], (20.0, 0.0))
    assert "P_cb = 20 N along the slide" in ax.get_title()


FORCE_FIXTURES = [
    p
    for p in sorted(FIXTURES.glob("ch3_*.edges"))
    if "planetary" not in p.stem and any(ln.startswith(("force", "moment", "mass"))
                                         for ln in p.read_text().splitlines())
]  # fmt: skip


@pytest.mark.parametrize("path", FORCE_FIXTURES, ids=lambda p: p.stem)
def test_force_polygons_close_with_the_solved_reactions(path: Path) -> None:
    # each arrow is F/μ_F of a reaction the solver found (or a load of the file), and every
    # group's and driver's polygon closes

    _, plan, _ = _solved(path)
    solution = solve_forces(plan)
    fig = force_polygon(plan, solution)
    assert len(fig.axes) == sum(s.group is not None for s in plan.steps) + len(plan.drivers)
    reactions = {
        (r.links, r.point): np.asarray(r.force) for r in solution.reactions if r.kind != "H"
    }
    for ax in fig.axes:
        forces = _check_closed(ax)
        assert "rest" not in forces  # closed by the loads and reactions alone (no friction)
        for key, force in forces.items():
            kind, _, rest = key.partition(":")
            if kind != "reaction":
                continue
            pair, _, point = rest.partition(":")
            source, target = pair.split("->")
            expected = reactions.get(((source, target), point))
            if expected is None:
                expected = -reactions[((target, source), point)]
            assert np.allclose(force, expected, atol=1e-9 * (1 + np.abs(expected).max()))


# ---------------------------------------------------------------- sweeps


def _fourbar_bc(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """B and C of problem 2.4's four-bar with the crank turned by ``phi`` (closed form)."""
    t = math.pi / 2 + phi
    b = 0.1 * np.column_stack([np.cos(t), np.sin(t)])
    d = np.array([0.4, -0.3])
    bd = d - b
    dist = np.hypot(bd[:, 0], bd[:, 1])
    h = np.sqrt(0.4**2 - (dist / 2) ** 2)
    left = np.column_stack([-bd[:, 1], bd[:, 0]]) / dist[:, None]
    return b, (b + d) / 2 + h[:, None] * left


def test_sweep_figure_of_the_fourbar() -> None:
    # ω2, ω3 from the velocity loop v_B + ω2 × (C − B) = ω3 × (C − D) with the closed-form
    # positions; the transmission angle at C between C − B and C − D

    _, plan, _ = _solved(FIXTURES / "ch2_2_4_fourbar.edges")
    result = sweep(plan, steps=36)
    fig = sweep_figure(result, plan)
    lines = {ln.get_gid(): ln for ax in fig.axes for ln in ax.lines}
    phi = np.linspace(0.0, 2 * math.pi, 36, endpoint=False)
    b, c = _fourbar_bc(phi)
    d = np.array([0.4, -0.3])
    vb = 20.0 * np.column_stack([-b[:, 1], b[:, 0]])
    cb, cd = c - b, c - d
    # [k×cb, −k×cd]·(ω2, ω3) = −v_B, k×r = (−r_y, r_x)
    mat = np.stack(
        [np.column_stack([-cb[:, 1], cd[:, 1]]), np.column_stack([cb[:, 0], -cd[:, 0]])], axis=1
    )
    w2, w3 = np.linalg.solve(mat, -vb[..., None])[..., 0].T
    omega3 = lines["omega:3"]
    assert np.allclose(omega3.get_xdata(), np.degrees(phi))
    assert np.allclose(omega3.get_ydata(), w3, atol=1e-9)
    assert np.allclose(lines["omega:2"].get_ydata(), w2, atol=1e-9)
    assert omega3.get_ydata()[0] == pytest.approx(5.0)  # the printed ω3 of problem 2.4
    assert np.allclose(lines["omega:1"].get_ydata(), 20.0)
    assert np.allclose(lines["speed:B"].get_ydata(), 2.0)  # |v_B| = ω1·AB
    cos = np.einsum("ij,ij->i", cb, cd) / (np.hypot(*cb.T) * np.hypot(*cd.T))
    mu = lines["transmission:II(2,3)"].get_ydata()
    assert np.allclose(mu, np.degrees(np.arccos(cos)), atol=1e-7)
    path = lines["path:C"].get_xydata()
    assert np.allclose(path, c, atol=1e-9)
    assert {"epsilon:3", "accel:C", "fixed:A", "fixed:D"} <= set(lines)
    assert lines["omega:3"].get_label() == "3"


def test_sweep_figure_has_the_balancing_moment() -> None:

    _, plan, _ = _solved(FIXTURES / "ch3_3_4_fourbar.edges")
    result = sweep(plan, steps=8)
    lines = {ln.get_gid(): ln for ax in sweep_figure(result).axes for ln in ax.lines}
    assert np.allclose(lines["balancing:moment 1"].get_ydata(), result.balancing["moment 1"])
    assert lines["balancing:moment 1"].get_ydata()[0] == pytest.approx(50 * math.sqrt(2))


# ---------------------------------------------------------------- animation


def test_animation_gif_has_the_frames(fourbar_2_4, tmp_path: Path) -> None:

    report, plan, _ = fourbar_2_4
    start = time.perf_counter()
    out = animate(report, plan, turn_inputs(plan, 36), tmp_path / "fourbar.gif", fps=10,
                  size=(4.0, 3.2), dpi=50)  # fmt: skip
    elapsed = time.perf_counter() - start
    assert elapsed < 10.0  # about a second: frames are blitted, not redrawn
    with Image.open(out) as gif:
        assert gif.n_frames == 36
        assert gif.size == (200, 160)
        assert gif.info["duration"] == 100
        gif.seek(0)
        first = np.asarray(gif.convert("RGB"), dtype=int)
        gif.seek(9)  # a quarter turn later: the crank and coupler have moved
        later = np.asarray(gif.convert("RGB"), dtype=int)
    assert np.abs(first - later).sum(axis=2).astype(bool).mean() > 0.005
    # a sweep gives its inputs
    with Image.open(animate(report, plan, sweep(plan, steps=5), tmp_path / "s.gif", dpi=30)) as g:
        assert g.n_frames == 5


def test_animation_errors(fourbar_2_4, tmp_path: Path, monkeypatch) -> None:

    report, plan, _ = fourbar_2_4
    with pytest.raises(MechanismError, match=r"unsupported animation format '\.avi'"):
        animate(report, plan, [0.0, 1.0], tmp_path / "a.avi")
    monkeypatch.setattr(FFMpegWriter, "isAvailable", classmethod(lambda cls: False))
    with pytest.raises(MechanismError, match="ffmpeg"):
        animate(report, plan, [0.0, 1.0], tmp_path / "a.mp4")
    cam = _solved(FIXTURES / "cam_roller_follower.edges")
    with pytest.raises(MechanismError, match="sketch pose"):
        animate(cam[0], cam[1], [0.0, 0.5], tmp_path / "cam.gif")
    assert not list(tmp_path.iterdir())


# ---------------------------------------------------------------- command line


def _cli(capsys, *argv: str) -> tuple[int, str, str]:

    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_cli_plots(tmp_path: Path, capsys) -> None:

    graph = tmp_path / "graph.png"
    code, out, err = _cli(
        capsys, "classify", str(FIXTURES / "ch1_1_4a_oxygen_pump.edges"), "--plot", str(graph)
    )
    assert code == 0, err
    assert "III(3,4,5,6)" in out and _is_png(graph) and graph.stat().st_size > 10_000
    forces = tmp_path / "forces.svg"
    code, _, err = _cli(
        capsys, "forces", str(FIXTURES / "ch3_3_4_fourbar.edges"), "--plot", str(forces)
    )
    assert code == 0, err
    svg = forces.read_text()
    assert svg.lstrip().startswith("<?xml") and "label:reaction:1-&gt;2:B" in svg
    curves = tmp_path / "sweep.pdf"
    code, _, err = _cli(
        capsys, "sweep", str(FIXTURES / "ch2_2_4_fourbar.edges"), "--steps", "12", "--plot",
        str(curves),
    )  # fmt: skip
    assert code == 0, err
    assert curves.read_bytes().startswith(b"%PDF")
    gif = tmp_path / "fourbar.gif"
    code, out, err = _cli(
        capsys, "animate", str(FIXTURES / "ch2_2_4_fourbar.edges"), str(gif), "--steps", "6",
        "--fps", "5",
    )  # fmt: skip
    assert code == 0, err
    assert "6 frames" in out
    with Image.open(gif) as image:
        assert image.n_frames == 6


def test_cli_plot_errors(tmp_path: Path, capsys, monkeypatch) -> None:
    four = str(FIXTURES / "ch2_2_4_fourbar.edges")
    for argv in (
        ("classify", four, "--plot", str(tmp_path / "g.gif")),
        ("forces", str(FIXTURES / "ch3_3_4_fourbar.edges"), "--plot", str(tmp_path / "f.txt")),
        ("sweep", four, "--plot", str(tmp_path / "s.jpg")),
        ("kinematics", four, "--plot", str(tmp_path / "k")),
    ):
        code, _, err = _cli(capsys, *argv)
        assert code == 1, argv
        assert err.startswith("error: ") and "unsupported figure format" in err, err
        assert "Traceback" not in err and "use .png, .svg or .pdf" in err
    code, _, err = _cli(capsys, "forces", four, "--plot", str(tmp_path / "missing" / "f.png"))
    assert code == 1 and err.startswith("error: cannot write") and "No such file" in err
    code, _, err = _cli(capsys, "animate", four, str(tmp_path / "a.webm"))
    assert code == 1 and "unsupported animation format" in err

    monkeypatch.setattr(FFMpegWriter, "isAvailable", classmethod(lambda cls: False))
    code, _, err = _cli(capsys, "animate", four, str(tmp_path / "a.mp4"))
    assert code == 1 and err.startswith("error: ") and "ffmpeg" in err
    code, _, err = _cli(
        capsys, "animate", str(FIXTURES / "cam_roller_follower.edges"), str(tmp_path / "c.gif")
    )
    assert code == 1 and "higher pair" in err
    code, _, err = _cli(capsys, "animate", four, str(tmp_path / "a.gif"), "--steps", "0")
    assert code == 2
    assert not list(tmp_path.iterdir())  # nothing written on any error
