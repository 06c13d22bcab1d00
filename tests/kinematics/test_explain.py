"""Worked solutions of the kinematics and kinetostatics (kinematics.explain), and the CLI.

Every expected number is derived here from the fixture's coordinates by the textbook's
relations (v = ω·l, polygons solved by hand as 2×2 systems, a^k = 2·ω·v_rel, virtual power),
not read back from the solver.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from kinematics.cli.commands import main
from kinematics.explain.worked import angle_of, explain_forces, explain_kinematics
from kinematics.kinetostatics.forces import solve_forces
from kinematics.kinetostatics.polygons import vector_equations
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_pose
from structure.explain.mathml import MATHML_NAMESPACE
from structure.explain.structural import explain_structure
from structure.expressions import read_number
from structure.readwrite.edgelist import parse_edgelist, read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES


def fixture(name: str) -> str:
    return str(FIXTURES / f"{name}.edges")


def read_text(name: str) -> str:
    return (FIXTURES / f"{name}.edges").read_text()


def sketch(name: str) -> tuple[dict[str, np.ndarray], float]:
    """The fixture's point coordinates and the driver's ω, read from its lines."""
    points: dict[str, np.ndarray] = {}
    omega = math.nan
    for line in (FIXTURES / f"{name}.edges").read_text().splitlines():
        tokens = line.split("#")[0].split()
        if tokens[:1] == ["point"]:
            points[tokens[1]] = np.array([read_number(t)[0] for t in tokens[2:4]])
        if tokens[:1] == ["driver"]:
            for t in tokens[2:]:
                if t.startswith("omega="):
                    omega = float(t.split("=")[1])
    return points, omega


def g(x: float) -> str:
    """A number as the explanation writes it (6 significant digits)."""
    return f"{x:.6g}"


def J(v: np.ndarray) -> np.ndarray:
    return np.array([-v[1], v[0]])


def cross(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def kinematics_text(name: str, lang: str = "en", fmt: str = "text") -> str:
    report = analyze(read_edgelist(fixture(name)))
    plan = make_plan(report)
    return explain_kinematics(report, plan, solve_pose(plan), lang, fmt)


def forces_text(name: str, lang: str = "en", fmt: str = "text") -> str:
    report = analyze(read_edgelist(fixture(name)))
    plan = make_plan(report)
    return explain_forces(report, plan, solve_forces(plan), lang, fmt)


# ----------------------------------------------------------------------------- kinematics
def test_fourbar_velocity_polygon_by_hand():
    p, w1 = sketch("ch2_2_4_fourbar")
    A, B, C, D = p["A"], p["B"], p["C"], p["D"]
    l_ab, l_bc, l_cd = (float(np.linalg.norm(y - x)) for x, y in ((A, B), (B, C), (C, D)))
    v_b = w1 * l_ab
    # v_C = v_B + ω2·J(C−B) = ω3·J(C−D): two unknowns ω2, ω3
    w2, w3 = np.linalg.solve(np.column_stack([J(C - B), -J(C - D)]), -w1 * J(B - A))
    text = kinematics_text("ch2_2_4_fourbar")
    assert "v_C = v_B + v_CB = v_D + v_CD" in text
    assert f"v_B: ⊥AB, ω1·l_AB = {g(w1)}·{g(l_ab)} = {g(v_b)} m/s" in text
    assert "v_CB: ⊥BC, ?" in text and "v_CD: ⊥CD, ?" in text
    assert f"v_CD = {g(abs(w3) * l_cd)} m/s ⇒ ω3 = v_CD/l_CD = " in text
    assert f"= {g(w3)} rad/s (counter-clockwise)" in text
    assert abs(w2) < 1e-12 and "ω2 = v_CB/l_BC = 0/0.4 = 0 rad/s" in text
    # accelerations: normal terms known, tangential ones "?"
    assert "a_C = a_B + a^n_CB + a^τ_CB = a_D + a^n_CD + a^τ_CD" in text
    assert f"a^n_CD: C→D, ω3²·l_CD = {g(w3)}²·{g(l_cd)} = {g(w3**2 * l_cd)} m/s²" in text
    assert "a^τ_CB: ⊥BC, ?" in text and "a^τ_CD: ⊥CD, ?" in text
    # a_B + ε2·J(C−B) − ω2²(C−B) = ε3·J(C−D) − ω3²(C−D)
    rhs = w1**2 * (B - A) + w2**2 * (C - B) - w3**2 * (C - D)
    e2, e3 = np.linalg.solve(np.column_stack([J(C - B), -J(C - D)]), rhs)
    assert f"ε2 = a^τ_CB/l_BC = {g(abs(e2) * l_bc)}/{g(l_bc)} = {g(e2)} rad/s²" in text
    assert abs(e2 - 75.0) < 1e-9 and abs(e3) < 1e-9  # the printed ε2 = 75, ε3 = 0


@pytest.mark.parametrize("name", ["exam_1_slotted_link", "ch2_2_2_slotted_link"])
def test_slotted_link_coriolis_by_hand(name):
    p, w1 = sketch(name)
    A, B, C = p["A"], p["B"], p["C"]
    v_b = w1 * J(B - A)  # the crank pin (block 2)
    u = (B - C) / np.linalg.norm(B - C)  # the slot, C -> B
    v_rel = float(v_b @ u)  # v_B3 ⊥ CB, so v_B2 − v_B3 lies along the slot
    v_b3 = v_b - v_rel * u
    w3 = cross(B - C, v_b3) / float((B - C) @ (B - C))
    coriolis = 2 * abs(w3) * abs(v_rel)
    text = kinematics_text(name)
    assert "v_B3 = v_C + v_B3C = v_B2 + v_B3B2" in text
    assert "a_B3 = a_C + a^n_B3C + a^τ_B3C = a_B2 + a^k_B3B2 + a^r_B3B2" in text
    assert "v_B3B2: ∥BC, ?" in text and "a^r_B3B2: ∥BC, ?" in text
    assert f"2·ω2·v_B3B2 = 2·{g(abs(w3))}·{g(abs(v_rel))} = {g(coriolis)} m/s²" in text
    assert "Coriolis" in text
    if name == "exam_1_slotted_link":  # the exam's a·ω²/√2 with a = 0.1, ω = 10
        assert abs(coriolis - 0.1 * 100 / math.sqrt(2)) < 1e-12
        assert abs(w3 - w1 / 2) < 1e-12


def test_slider_on_the_ground_has_no_coriolis_and_a_guide_direction():
    text = kinematics_text("ch3_3_5_crank_slider")
    assert "v_C = v_B + v_CB" in text and "v_C: ∥AC, ?" in text
    assert "ω3 = 0: link 3 slides on the ground" in text
    assert "a^k" not in text


def test_marker_point_from_its_pin():
    # problem 2.2: D on block 2, v_D = v_B + v_DB with |v_DB| = ω2·l_BD = 5·0.2 = 1 m/s
    p, _ = sketch("ch2_2_2_slotted_link")
    l_bd = float(np.linalg.norm(p["D"] - p["B"]))
    text = kinematics_text("ch2_2_2_slotted_link")
    assert f"v_D = v_B + v_DB: ⊥BD, ω2·l_BD = 5·{g(l_bd)} = {g(5 * l_bd)} m/s" in text
    assert "D (on 2): |v| = 5 m/s at 180°" in text  # the print's 4 + 1 = 5 m/s


def test_triad_is_solved_as_a_whole():
    text = kinematics_text("eightbar_triad")
    group = text.split("Group III(4,5,6,7)")[1]
    assert "solved as a whole" in group and "Newton" in group and "Jacobian" in group
    assert "links 4, 5, 6, 7 (12 unknowns)" in group
    assert "pin T45 joins 4 and 5: v_T45(4) = v_T45(5)" in group


@pytest.mark.parametrize(
    "name", ["jansen", "quick_return_shaper", "ch2_2_10_sieve", "ch2_2_3_tangent", "scotch_yoke"]
)
def test_explanation_agrees_with_assur_kinematics(capsys, name):
    assert main(["kinematics", fixture(name)]) == 0
    plain = capsys.readouterr().out
    rates = {
        m[1]: (float(m[2]), float(m[3]))
        for m in re.finditer(
            r"^  (\S+): angle \S+ rad, ω = (\S+) rad/s, ε = (\S+) rad/s²", plain, re.M
        )
    }
    assert rates
    assert main(["kinematics", fixture(name), "--explain"]) == 0
    text = capsys.readouterr().out
    found = {
        m[1]: (float(m[2]), float(m[3]))
        for m in re.finditer(r"- link (\S+): ω\S* = (\S+) rad/s.*?, ε\S* = (\S+) rad/s²", text)
    }
    assert found
    for link, (w, e) in found.items():
        assert w == pytest.approx(rates[link][0], rel=1e-5, abs=1e-9)
        assert e == pytest.approx(rates[link][1], rel=1e-5, abs=1e-9)


@pytest.mark.parametrize(
    "name", ["ch2_2_4_fourbar", "exam_1_slotted_link", "ch3_3_5_crank_slider", "scotch_yoke"]
)
def test_equations_are_those_of_the_polygons(name):
    """The worked solution writes each dyad's equation as the polygons draw it, term by term."""
    report = analyze(read_edgelist(fixture(name)))
    plan = make_plan(report)
    state = solve_pose(plan)
    text = kinematics_text(name)
    count = 0
    for order, letter in ((1, "v"), (2, "a")):
        for eq in vector_equations(plan, state, order):
            ways = [
                " + ".join([f"{letter}_{c.start}", *(t.key for t in c.terms)]) for c in eq.chains
            ]
            assert " = ".join([f"{letter}_{eq.x}", *ways]) + "\n" in text, eq.label
            count += 1
    assert count >= 2


def test_kinematics_in_vietnamese():
    text = kinematics_text("exam_1_slotted_link", lang="vi")
    for term in (
        "Khâu dẫn",
        "Phương trình vận tốc:",
        "Phương trình gia tốc:",
        "họa đồ vận tốc",
        "họa đồ gia tốc",
        "gia tốc Coriolis",
        "ẩn số",
        "thuộc giá",
        "khâu 3",
    ):
        assert term in text, term


def test_kinematics_markdown_and_latex():
    md = kinematics_text("ch2_2_2_slotted_link", fmt="markdown")
    assert md.startswith("# Kinematics of")
    assert "\n## 2. Group II(2,3) RPR: links 2, 3\n" in md
    assert (
        "$$\\vec{v}_{B3} = \\vec{v}_{C} + \\vec{v}_{B3C} = \\vec{v}_{B2} + \\vec{v}_{B3B2}$$" in md
    )
    assert "- $\\vec{v}_{B3C}$: $\\perp BC, ?$" in md
    assert "$$$" not in md  # adjacent mathematics is merged, never $a$$b$
    tex = kinematics_text("ch2_2_2_slotted_link", fmt="latex")
    assert "\\[ \\vec{a}_{B3} = \\vec{a}_{C} + \\vec{a}^{\\,n}_{B3C}" in tex
    assert "\\parallel BC" in tex and "\\perp BC" in tex
    assert "\\vec{a}^{\\,k}_{B3B2}" in tex
    prose = re.sub(r"\\\[.*?\\\]", "", re.sub(r"\$[^$]*\$", "", tex))
    assert not set("→⇒⊥∥ωε·²Σ") & set(prose)


def test_unknown_language_or_format_is_a_value_error():
    report = analyze(read_edgelist(fixture("fourbar")))
    plan = make_plan(report)
    state = solve_pose(plan)
    with pytest.raises(ValueError, match="unknown language 'de'"):
        explain_kinematics(report, plan, state, lang="de")
    with pytest.raises(ValueError, match="unknown format 'rst'"):
        explain_forces(report, plan, solve_forces(plan), fmt="rst")


def test_angle_of_is_in_the_half_open_turn():
    assert angle_of(np.array([-1.0, -0.0])) == 180.0
    assert angle_of(np.array([0.0, -1.0])) == -90.0


# ----------------------------------------------------------------------------- forces
def test_fourbar_balancing_moment_by_virtual_power():
    # problem 3.4: M_cb·ω1 + P3·v_M3 = 0, with v_M3 from the velocity polygon
    p, w1 = sketch("ch3_3_4_fourbar")
    A, B, C, D, M3 = p["A"], p["B"], p["C"], p["D"], p["M3"]
    _, w3 = np.linalg.solve(np.column_stack([J(C - B), -J(C - D)]), -w1 * J(B - A))
    p3 = np.array([500 * math.sqrt(2), -500 * math.sqrt(2)])
    m_cb = -float(p3 @ (w3 * J(M3 - D))) / w1
    assert abs(m_cb - 50 * math.sqrt(2)) < 1e-9  # the printed 50·√2
    text = forces_text("ch3_3_4_fourbar")
    assert f"balancing moment M_cb = {g(m_cb)} N·m (counter-clockwise)" in text
    assert f"M_cb = −M_A = {g(m_cb)} N·m" in text
    assert f"M_cb·ω1 = {g(m_cb)}·{g(w1)} = {g(m_cb * w1)} W" in text
    assert "Sum: 0 W ≈ 0 ✓" in text
    # printed: R^τ_12 = 0 (link 2 unloaded), R^τ_D3 = 0.5·P3 = 500 N
    assert "R^τ_12 = M_C/l_BC = 0/0.4 = 0 N" in text
    assert "R^τ_03 = M_C/l_CD = 200/0.4 = 500 N" in text


def test_slotted_link_forces_by_virtual_power():
    # problem 3.8: M_cb·ω1 + M3·ω3 = 0, ω3 from v_B3 = component of v_B across the slot CB
    p, w1 = sketch("ch3_3_8_slotted_link")
    A, B, C = p["A"], p["B"], p["C"]
    v_b = w1 * J(B - A)
    u = (B - C) / np.linalg.norm(B - C)
    w3 = cross(B - C, v_b - (v_b @ u) * u) / float((B - C) @ (B - C))
    m_cb = 600 * w3 / w1
    assert abs(m_cb - 150) < 1e-9  # the printed 150 N·m
    text = forces_text("ch3_3_8_slotted_link")
    assert f"balancing moment M_cb = {g(m_cb)} N·m" in text
    assert f"M_3·ω3 = (-600)·{g(w3)} = {g(-600 * w3)} W" in text
    # the block carries two forces: the slide's reaction passes through B (x = 0)
    assert "ΣM_B(link 2) = 0" in text and "x = M/N = 0 m from B" in text


def test_forces_away_from_the_sketch_by_virtual_power():
    # the six-link of problem 3.10 with masses and gravity, the crank turned −0.5 rad: the
    # balancing moment from virtual power at that pose, Σ P·v + Σ M·ω + M_cb·ω1 = 0, with the
    # inertia loads −m·a_S, −J·ε, from the kinematics alone (no force solve)
    extra = ["point S3 0.25 0.1 on=3", "mass 3 2 0.01 S3", "mass 5 3 0 E", "gravity 0 -9.81"]
    report = analyze(parse_edgelist(read_text("ch3_3_10_sixbar").splitlines() + extra))
    plan = make_plan(report)
    state = solve_pose(plan, (-0.5,))
    gravity = np.array([0.0, -9.81])
    point, link = state.points, state.links
    power = float(np.array([-400.0, 0.0]) @ point["E"].velocity)
    for name, mass in (("S3", 2.0), ("E", 3.0)):
        power += float(mass * (gravity - point[name].acceleration) @ point[name].velocity)
    power += -0.01 * link["3"].epsilon * link["3"].omega
    m_cb = -power / link["1"].omega
    solution = solve_forces(plan, (-0.5,))
    assert solution.inputs == (-0.5,)
    text = explain_forces(report, plan, solution)
    assert "(kinetostatics at φ1 = -0.5 rad from the sketch pose)" in text
    assert f"M_cb = −M_A = {g(m_cb)} N·m" in text
    assert f"balancing moment M_cb = {g(m_cb)} N·m" in text
    a_s3 = -2.0 * point["S3"].acceleration
    assert f"P^in_3 = −m·a_S at S3 on link 3: ({g(a_s3[0])}, {g(a_s3[1])}) N" in text
    assert "Sum: 0 W ≈ 0 ✓" in text
    sketch_text = explain_forces(report, plan, solve_forces(plan))
    assert "(kinetostatics at the sketch pose)" in sketch_text
    assert f"M_cb = −M_A = {g(m_cb)} N·m" not in sketch_text


def test_crank_slider_guide_offset_by_hand():
    # problem 3.5: the guide's normal force N = P3·tan30° acts x = P3·h3/N from C
    n = 1000 * math.tan(math.radians(30))
    text = forces_text("ch3_3_5_crank_slider")
    assert f"R_03 = -{g(n)} N" in text
    assert f"x = M/N = {g(-1000 * 0.058 / n)} m from C" in text  # toward A: negative along x
    assert "balancing moment M_cb = 100 N·m" in text


@pytest.mark.parametrize(
    "name",
    [
        "ch3_3_3_fourbar_balancing_force",
        "ch3_3_4_fourbar",
        "ch3_3_5_crank_slider",
        "ch3_3_6_sine_mechanism",
        "ch3_3_7_sieve",
        "ch3_3_8_slotted_link",
        "ch3_3_10_sixbar",
    ],
)
def test_each_step_agrees_with_the_reactions_solved(name):
    assert steps_agree(forces_text(name)) >= 1


@pytest.mark.parametrize(
    "name",
    ["ch3_3_5_crank_slider", "ch3_3_6_sine_mechanism", "ch3_3_8_slotted_link", "ch3_3_10_sixbar"],
)
def test_each_step_agrees_with_the_reactions_away_from_the_sketch(name):
    # turned 0.3 rad the slides have moved: a slide's reaction acts at its point on the link
    # it acts on (E3, not the E of the block), and its moment is about that point
    report = analyze(read_edgelist(fixture(name)))
    plan = make_plan(report)
    text = explain_forces(report, plan, solve_forces(plan, (0.3,)))
    assert steps_agree(text) >= 1


def steps_agree(text: str) -> int:
    """Every reaction and slide moment a step gives equals the one the solve found; how many."""
    found = {
        m[1]: np.array([float(m[2]), float(m[3])])
        for m in re.finditer(r"- (R_\S+) at \S+: \((\S+), (\S+)\) N", text)
    }
    moments = {
        "M_" + m[1]: float(m[2])
        for m in re.finditer(r"- R_(\S+) at .*; moment about \S+ (\S+) N·m", text)
    }
    checked = 0
    for m in re.finditer(r"⇒ (R_\S+) = \((\S+), (\S+)\) N", text):
        if m[1] in found:
            assert np.allclose([float(m[2]), float(m[3])], found[m[1]], atol=1e-4), m[0]
            checked += 1
    for m in re.finditer(r"⇒ (M_\S+) = (\S+) N·m", text):
        if m[1] in moments:
            assert float(m[2]) == pytest.approx(moments[m[1]], rel=1e-5, abs=1e-4), m[0]
            checked += 1
    assert "≈ 0 ✓" in text
    return checked


def test_balancing_force_and_slider_driver():
    text = forces_text("ch3_3_3_fourbar_balancing_force")
    # derived in forces.toml by hand: P_cb·(l_AB/2) = 50 N·m -> 1000 N, horizontal
    assert "balancing force P_cb = -1000 N along 0° at M1" in text
    text = forces_text("ch3_3_1_slider_power")
    # problem 3.1: P = m·a = 2·10 = 20 N, power P·v = 20·5 = 100 W
    assert "balancing force F_cb = 20 N" in text and "F_cb·v1 = 20·5 = 100 W" in text


def test_flywheel_uses_virtual_velocities():
    # problem 3.2: ω = 0 at the start, ε = 7: M = J·ε = 14 N·m
    text = forces_text("ch3_3_2_flywheel")
    assert "M^in_1 = −J_S·ε on link 1: -14 N·m" in text
    assert "virtual velocities" in text and "balancing moment M_cb = 14 N·m" in text


def test_forces_in_vietnamese_latex():
    text = forces_text("ch3_3_4_fourbar", lang="vi")
    for term in ("áp lực khớp động", "mômen cân bằng", "phương pháp công suất", "khớp chờ",
                 "Tách nhóm tĩnh định", "khâu dẫn"):  # fmt: skip
        assert term in text, term
    tex = forces_text("ch3_3_4_fourbar", fmt="latex")
    assert "\\sum M_{C}" in tex and "\\vec{R}^{\\,\\tau}_{12}" in tex
    assert tex.count("\\begin{itemize}") == tex.count("\\end{itemize}")


# ----------------------------------------------------------------------------- HTML
MATHML_MATH = f"{{{MATHML_NAMESPACE}}}math"
NUMBER = re.compile(r"\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def numbers_in(text: str) -> set[str]:
    """The numbers written in a text; a square (²) counts as the 2 that MathML writes."""
    return set(NUMBER.findall(text.replace("²", " 2 ")))


def formulas_in_markdown(markdown: str) -> int:
    """The formulas of a solution: its $$…$$ and $…$ spans in Markdown, where text has none."""
    return len(re.findall(r"\$\$.*?\$\$|\$.*?\$", markdown, re.S))


def explanations(name: str, lang: str, fmt: str) -> dict[str, str]:
    report = analyze(read_edgelist(fixture(name)))
    plan = make_plan(report)
    return {
        "structure": explain_structure(report, lang, fmt),
        "kinematics": explain_kinematics(report, plan, solve_pose(plan), lang, fmt),
        "forces": explain_forces(report, plan, solve_forces(plan), lang, fmt),
    }


@pytest.mark.parametrize(
    "name", ["ch2_2_4_fourbar", "ch2_2_2_slotted_link", "ch3_3_4_fourbar", "ch3_3_9_cam_flat"]
)
@pytest.mark.parametrize("lang", ["en", "vi"])
def test_html_fragment_has_the_formulas_and_numbers_of_the_text(name, lang):
    html = explanations(name, lang, "html")
    text = explanations(name, lang, "text")
    markdown = explanations(name, lang, "markdown")
    for kind, fragment in html.items():
        root = ET.fromstring(f"<root>{fragment}</root>")  # well-formed XML, MathML namespaced
        assert [e.tag for e in root] == ["section"], kind
        assert sum(1 for _ in root.iter(MATHML_MATH)) == formulas_in_markdown(markdown[kind])
        assert numbers_in(" ".join(root.itertext())) == numbers_in(text[kind]), kind
        assert "<script" not in fragment and "href=" not in fragment and "src=" not in fragment


def test_html_formulas_are_presentation_mathml():
    html = explanations("ch2_2_2_slotted_link", "en", "html")["kinematics"]
    root = ET.fromstring(f"<root>{html}</root>")
    tags = {e.tag.split("}")[1] for m in root.iter(MATHML_MATH) for e in m.iter()}
    assert {"mi", "mn", "mo", "msub", "msup", "msubsup", "mover", "mrow"} <= tags
    shown = [m for m in root.iter(MATHML_MATH) if m.get("display") == "block"]
    assert shown and all(m.get("display") in ("block", None) for m in root.iter(MATHML_MATH))
    # the Coriolis term: a^k = 2·ω·v_rel with its numbers, as in the text
    text = explanations("ch2_2_2_slotted_link", "en", "text")["kinematics"]
    coriolis = re.search(r"2·ω\d+·v_\w+ = 2·([\d.]+)·([\d.]+) = ([\d.]+) m/s²", text)
    assert coriolis is not None
    numbers = [m for m in root.iter(MATHML_MATH) if "2⋅" in "".join(m.itertext())]
    assert any(
        all(f"⋅{x}" in "".join(m.itertext()) for x in coriolis.groups()[:2]) for m in numbers
    )


# ----------------------------------------------------------------------------- CLI
def test_cli_kinematics_and_forces_explain(capsys):
    assert main(["kinematics", fixture("ch2_2_4_fourbar"), "--explain"]) == 0
    out = capsys.readouterr().out
    assert "v_C = v_B + v_CB = v_D + v_CD" in out and "Points:" not in out
    assert main(["forces", fixture("ch3_3_4_fourbar"), "--explain", "markdown"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("# Forces on") and "$$" in out
    assert main(["forces", fixture("ch3_3_4_fourbar"), "--explain", "latex", "--lang", "vi"]) == 0
    assert "\\section*{Phân tích lực" in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv",
    [
        ["kinematics", "ch2_2_4_fourbar", "--explain", "--lang", "xx"],
        ["kinematics", "ch2_2_4_fourbar", "--explain", "pdf"],
        ["kinematics", "ch2_2_4_fourbar", "--explain", "--exact"],
        ["forces", "ch3_3_4_fourbar", "--explain", "--json"],
        ["forces", "ch3_3_4_fourbar", "--lang", "fr"],
    ],
)
def test_cli_explain_usage_errors_exit_2(capsys, argv):
    command, name, *rest = argv
    assert main([command, fixture(name), *rest]) == 2
    assert "error" in capsys.readouterr().err


def test_cli_explain_html(capsys):
    assert main(["forces", fixture("ch3_3_4_fourbar"), "--explain", "html", "--lang", "vi"]) == 0
    out = capsys.readouterr().out
    assert out.startswith('<section class="worked-solution" lang="vi">\n<h2>Phân tích lực')
    assert out.endswith("</section>\n")
    ET.fromstring(f"<root>{out}</root>")


def test_cli_forces_explain_of_an_indeterminate_mechanism_exits_1(capsys):
    assert main(["forces", fixture("parallelogram_redundant"), "--explain"]) == 1
    assert "statically indeterminate" in capsys.readouterr().err
    assert main(["forces", fixture("parallelogram_redundant"), "--explain", "--minimum-norm"]) == 0
    assert "minimum-norm" in capsys.readouterr().out
