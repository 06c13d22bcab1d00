"""The structural worked solution (structure.explain) and ``assur classify --explain``.

The expected counts are the source's printed chapter-1 answers (DOMAIN.md's table), or
counted here from the fixture's own lines, never taken from the analysis under test.
"""

from __future__ import annotations

import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from kinematics.cli.commands import main
from structure.explain import (
    Math,
    check_options,
    explain_structure,
    formula,
    number,
    subscript,
)
from structure.explain.mathml import MATHML_NAMESPACE as MATHML
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ..conftest import FIXTURES


def report(name: str):
    return analyze(read_edgelist(FIXTURES / f"{name}.edges"))


def counted(name: str) -> tuple[int, int, int, int]:
    """n, P5, P4 and the rollers, read from the fixture's pair lines by hand."""
    links: set[str] = set()
    p5 = p4 = rollers = 0
    for line in (FIXTURES / f"{name}.edges").read_text().splitlines():
        tokens = line.split("#")[0].split()
        if len(tokens) < 3 or tokens[2] not in ("R", "P", "H"):
            continue
        links.update(tokens[:2])
        if tokens[2] == "H":
            p4 += 1
            rollers += any(t.startswith("roller=") for t in tokens)
        else:
            p5 += 1
    return len(links - {"0"}), p5, p4, rollers


# the source's printed counts n, P5, P4, r, W_th -> W (chapter 1)
PRINTED = {
    "ch1_1_2a_mechanical_press": (5, 7, 0, 0, 0, 1),
    "ch1_1_5a_coupling_control": (5, 6, 1, 0, 1, 1),
    "ch1_1_8a_crusher": (5, 6, 1, 0, 1, 1),
    "ch1_1_9a_shoe_brake": (5, 6, 2, 0, 0, 1),
    "ch1_1_10a_peaucellier": (7, 10, 0, 0, 0, 1),
    "ch1_1_13a_adder": (6, 8, 0, 0, 0, 2),
}


@pytest.mark.parametrize("name", sorted(PRINTED))
def test_w_line_has_the_printed_counts(name):
    n, p5, p4, r, wth, w = PRINTED[name]
    assert counted(name) == (n, p5, p4, wth)  # the fixture is the printed mechanism
    text = explain_structure(report(name))
    line = f"W = 3·n − (2·P5 + P4) + r − W_th = 3·{n} − (2·{p5} + {p4}) + {r} − {wth} = {w}"
    assert line in text
    assert f"n = {n} moving links" in text and f"P5 = {p5} lower pairs" in text


def test_replacement_recomputes_w_with_the_printed_counts():
    # fig. 1.5a: after replacing the cam contact (roller removed), n = 5, P5 = 7 -> W = 1
    text = explain_structure(report("ch1_1_5a_coupling_control"))
    replaced = text.split("Replacement of the higher pairs")[1]
    assert "3·5 − (2·7 + 0) + 0 − 0 = 1" in replaced
    assert "roller 2 is removed" in replaced and "virtual link v1" in replaced
    assert "the spin of roller 2" in text  # where W_th = 1 comes from


def test_flat_contact_becomes_a_prismatic_pair():
    # fig. 1.8a: the cam profile is flat at the contact, so that side becomes a P pair
    text = explain_structure(report("ch1_1_8a_crusher"))
    assert "is straight at the contact" in text and "prismatic" in text


def test_compound_hinge_counts_k_minus_one():
    # fig. 1.2a: the knuckle pin C joins links 2, 3 and 4 -> 2 revolute pairs
    text = explain_structure(report("ch1_1_2a_mechanical_press"))
    assert "compound hinge C joins 3 links (2, 3, 4): it counts 3 − 1 = 2 revolute pairs" in text


def test_groups_are_detached_from_the_farthest():
    # fig. 1.2a: (4,5) hangs on the knuckle pin C of (2,3), so it is detached first
    text = explain_structure(report("ch1_1_2a_mechanical_press"))
    first, second = text.index("Group 1: II(4,5)"), text.index("Group 2: II(2,3)")
    assert first < second
    group = text[first:second]
    assert "3·n = 2·p: 3·2 = 2·3 = 6 ✓" in group
    assert "order 2; kind RRP" in group and "attached to link(s) 2, 0" in group
    assert "Structural formula" in text and "1 = 1 + 0 + 0" in text
    assert text.rstrip().endswith("The mechanism is of class II: the highest class of its groups.")


def test_triad_is_class_three_by_its_base_link():
    text = explain_structure(report("eightbar_triad"))
    assert "Group 1: III(4,5,6,7)" in text
    assert "3·n = 2·p: 3·4 = 2·6 = 12 ✓" in text
    assert re.search(r"class III: link 5 is a base link with 3 inner pairs", text)
    assert "The mechanism is of class III" in text


def test_redundant_constraint_is_named_with_its_pair():
    # a third parallel crank: one constraint repeats (r = 1), found from the dimensions
    text = explain_structure(report("parallelogram_redundant"))
    assert "r = 1 redundant constraint(s):" in text
    assert "1 in pair 4–2 R F (line 19): the dimensions repeat a constraint" in text
    assert "3·4 − (2·6 + 0) + 1 − 0 = 1" in text
    assert "the redundant link(s) 4" in text


def test_two_drivers():
    # fig. 1.13a: W = 2, drivers 1 and 2 (printed 2 = 2 + 0; written here one term per driver)
    text = explain_structure(report("ch1_1_13a_adder"))
    assert "link 1 is the driver" in text and "link 2 is the driver" in text
    assert "W = 2: 2 driver(s)" in text
    assert "2 = 1 + 1 + 0" in text


def test_vietnamese_uses_the_source_vocabulary():
    text = explain_structure(report("ch1_1_5a_coupling_control"), lang="vi")
    for term in (
        "Bậc tự do cơ cấu được tính theo công thức",
        "khâu động",
        "giá 0 không tính",
        "khớp quay",
        "khớp tịnh tiến",
        "ràng buộc trùng",
        "bậc tự do thừa",
        "Thay thế khớp cao",
        "Bậc tự do cơ cấu thay thế",
        "chọn khâu 1 là khâu dẫn",
        "nhóm tĩnh định",
        "khớp chờ",
        "nhóm loại 2",
        "bậc 2",
        "Công thức cấu tạo cơ cấu",
        "Đây là cơ cấu loại 2",
    ):
        assert term in text, term
    assert "r_th − W_th = 3·5 − (2·6 + 1) + 0 − 1 = 1" in text
    assert "Degree of freedom" not in text


def test_markdown_and_latex_have_their_markers():
    r = report("ch1_1_5a_coupling_control")
    md = explain_structure(r, fmt="markdown")
    assert md.startswith("# Structure of")
    assert "\n## 1. Degree of freedom\n" in md and "\n### Group 1: II(4,5)\n" in md
    assert "\n$$W = 3 \\cdot n - (2 \\cdot P_5 + P_4) + r - W_{th}" in md
    assert "\n- n = 5 moving links" in md
    tex = explain_structure(r, fmt="latex", lang="vi")
    assert tex.startswith("\\section*{")
    assert "\\subsection*{1. Bậc tự do}" in tex
    assert "\\begin{itemize}" in tex and "\\end{itemize}" in tex
    assert "\\[ W = 3 \\cdot n" in tex
    assert tex.count("\\begin{itemize}") == tex.count("\\end{itemize}")
    # no bare Unicode mathematics or unescaped specials outside $…$
    prose = re.sub(r"\$[^$]*\$", "", tex)
    prose = re.sub(r"\\\[.*?\\\]", "", prose)
    assert not set("→⊥∥ω·²−Σ") & set(prose)
    assert "W_th" not in prose and "W\\_th" in prose


def test_unknown_language_or_format_is_a_value_error():
    r = report("fourbar")
    with pytest.raises(ValueError, match="unknown language 'fr': use one of en, vi"):
        explain_structure(r, lang="fr")
    with pytest.raises(
        ValueError, match="unknown format 'rtf': use one of text, markdown, latex, html"
    ):
        explain_structure(r, fmt="rtf")
    with pytest.raises(ValueError):
        check_options("en", "pdf")


def test_html_is_a_section_of_escaped_text_and_mathml():
    r = report("ch1_1_4a_oxygen_pump")
    html = explain_structure(r, lang="vi", fmt="html")
    root = ET.fromstring(f"<root>{html}</root>")  # well-formed: it parses as XML
    (section,) = root
    assert section.tag == "section" and section.get("class") == "worked-solution"
    assert section.get("lang") == "vi"
    assert [e.tag for e in section if e.tag.startswith("h")][:2] == ["h2", "h3"]
    maths = list(root.iter(f"{{{MATHML}}}math"))
    displayed = explain_structure(r, lang="vi", fmt="latex").count("\\[ ")
    assert [m.get("display") for m in maths].count("block") == displayed == 5
    formula_ = next(m for m in maths if m.find(f"{{{MATHML}}}mtext") is not None)
    assert [t.text for t in formula_.iter(f"{{{MATHML}}}mtext")] == [
        "I(1)",
        "II(2,v1)",
        "III(3,4,5,6)",
    ]
    assert "<script" not in html and "href" not in html and "src=" not in html
    text = explain_structure(r, lang="vi")
    assert set(re.findall(r"\d+", text)) == set(re.findall(r"\d+", " ".join(root.itertext())))


def test_math_pieces():
    f = formula("{w}·{l} = {x}", w=subscript("ω", "1"), l=subscript("l", "AB"), x=2.0)
    assert f.text == "ω1·l_AB = 2"
    assert f.latex == "\\omega_{1} \\cdot l_{AB} = 2"
    assert (Math("a", "A") + "b").latex == "Ab"
    assert number(-1e-15) == "0" and number(70.71067811865476) == "70.7107"


def test_structure_explain_never_imports_kinematics():
    code = (
        "import sys, structure.explain; "
        "print(sorted(m for m in sys.modules if m.split('.')[0] == 'kinematics'))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


# ----------------------------------------------------------------------------- CLI
def test_classify_explain(capsys):
    path = str(FIXTURES / "ch1_1_2a_mechanical_press.edges")
    assert main(["classify", path, "--explain"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Structure of mechanical knuckle press")
    assert "3·5 − (2·7 + 0) + 0 − 0 = 1" in out
    assert "Counts:" not in out  # the worked solution replaces the plain report
    assert main(["classify", path, "--explain", "markdown", "--lang", "vi"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("# Cấu trúc") and "Công thức cấu tạo cơ cấu" in out


@pytest.mark.parametrize(
    "argv",
    [
        ["--explain", "--lang", "fr"],
        ["--explain", "rtf"],
        ["--lang", "xx"],
        ["--explain", "--json"],
    ],
)
def test_classify_explain_usage_errors(capsys, argv):
    assert main(["classify", str(FIXTURES / "fourbar.edges"), *argv]) == 2
    err = capsys.readouterr().err
    assert "error" in err and "Traceback" not in err


def test_classify_explain_of_a_bad_file_is_a_mechanism_error(capsys, tmp_path):
    bad = tmp_path / "bad.edges"
    bad.write_text("0 1 R A\n1 2 R B\n2 0 R C\n")  # a rigid triangle: W = 0
    assert main(["classify", str(bad), "--explain"]) == 1
    assert "W = 0" in capsys.readouterr().err
