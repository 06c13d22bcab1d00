"""Worked solutions: the structural analysis written out step by step, as the textbook does.

:func:`explain_structure` turns a :class:`~structure.report.StructuralReport`
into the steps of a chapter-1 answer: the counts, the formula
``W = 3·n − (2·P5 + P4) + r − W_th`` with numbers, where each correction comes
from, the higher-pair replacements, the Assur groups as they are detached
from the farthest, the driver(s), the structural formula and the class.

The text is built once as a small document (headings, paragraphs, bullet
items, display equations) whose mathematics carries a plain (Unicode) and a
LaTeX form, and rendered as ``text``, ``markdown`` (with ``$…$`` / ``$$…$$``
LaTeX mathematics) or ``latex`` (a fragment: ``\\section*``, ``itemize``,
``\\[ … \\]``; it needs ``amsmath`` and ``amssymb``, and Vietnamese text needs
``\\usepackage[vietnamese]{babel}``). The same machinery (:class:`Math`,
:class:`Doc`, :func:`render`) is used by :mod:`kinematics.explain`.

Languages: ``en`` (default) and ``vi``, in the source's vocabulary (khâu,
giá, khâu dẫn, khớp quay, khớp tịnh tiến, bậc tự do, ràng buộc trùng, bậc tự
do thừa, nhóm tĩnh định, loại, bậc, công thức cấu tạo). All phrases are in
:data:`PHRASES`.

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> r = analyze(parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]))
>>> text = explain_structure(r)
>>> "W = 3·n − (2·P5 + P4) + r − W_th = 3·3 − (2·4 + 0) + 0 − 0 = 1" in text
True
>>> "Công thức cấu tạo" in explain_structure(r, lang="vi")
True
"""

from __future__ import annotations

import math
import string
import textwrap
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from ..assur import AssurGroup, roman
from ..mobility import Mobility
from ..model import Mechanism, PairKind
from ..report import StructuralReport

__all__ = [
    "FORMATS",
    "LANGUAGES",
    "PHRASES",
    "Doc",
    "Math",
    "check_options",
    "explain_structure",
    "formula",
    "math_join",
    "number",
    "render",
    "subscript",
]

#: output formats and languages the explanations accept
FORMATS = ("text", "markdown", "latex")
LANGUAGES = ("en", "vi")


# ============================================================================ phrases
#: every sentence of the structural explanation, by language; ``{name}`` fields take
#: prose or mathematics
PHRASES: dict[str, dict[str, str]] = {
    "en": {
        "title": "Structure of {name}",
        "mobility": "1. Degree of freedom",
        "formula_intro": "The degree of freedom is given by",
        "n": "n = {n} moving links ({links}); the ground {ground} is not counted",
        "p5": "P5 = {p5} lower pairs: {r} revolute (R), {p} prismatic (P)",
        "compound": (
            "compound hinge {point} joins {k} links ({links}): it counts {k} − 1 = {pairs} "
            "revolute pairs"
        ),
        "p4": "P4 = {p4} higher pair(s): {pairs}",
        "p4_none": "P4 = 0: no higher pairs",
        "cam": "cam contact",
        "gear": "gear teeth",
        "r_none": "r = 0: no redundant constraints",
        "r": "r = {r} redundant constraint(s):",
        "r_structural": (
            "{k} in pair {pair}{line}: a sub-chain with more constraints than its links can take "
            "(structural count)"
        ),
        "r_geometric": (
            "{k} in pair {pair}{line}: the dimensions repeat a constraint (rank of the constraint "
            "Jacobian at the sketch pose)"
        ),
        "line": " (line {line})",
        "w_none": "W_th = 0: no passive freedoms",
        "w": "W_th = {w} passive freedom(s):",
        "w_roller": "the spin of roller {link} about its own axis",
        "w_geometric": "link {link} can move alone ({k} freedom(s), found at the sketch pose)",
        "substituted": "With the numbers:",
        "note": "Note: {note}",
        "replacement": "2. Replacement of the higher pairs",
        "replacement_intro": (
            "The higher pairs are replaced by lower pairs (valid at this pose, for positions, "
            "velocities and accelerations): each becomes a virtual link with two lower pairs."
        ),
        "roller": (
            "roller {roller} is removed with its pair {pair}: its spin was the passive freedom; "
            "the contact now acts at its axis {axis}, a point of link {follower}"
        ),
        "replace_rr": (
            "{pair} ({what}) → virtual link {v} with {new}: revolute pairs at the centres of "
            "curvature of the two profiles"
        ),
        "replace_rp": (
            "{pair} ({what}) → virtual link {v} with {new}: the profile of link {flat} is straight "
            "at the contact, so that side becomes a prismatic pair along it"
        ),
        "replaced_counts": (
            "The replaced mechanism: n = {n}, P5 = {p5}, P4 = 0; the roller spins are gone "
            "(W_th = 0):"
        ),
        "unchanged": "W is unchanged, as it must be.",
        "drivers": "{k}. Driver(s)",
        "driver": "link {link} is the driver, joined to the ground by {pair}",
        "driver_chosen": ("(no driver was named: chosen among the links joined to the ground)"),
        "w_drivers": "W = {w}: {w} driver(s) with one freedom each.",
        "set_aside": (
            "the redundant link(s) {links} (pairs {pairs}) are set aside before the groups are "
            "detached"
        ),
        "groups": "{k}. Assur groups, detached from the farthest",
        "groups_intro": (
            "Each group is the smallest set of links with 3·n = 2·p (statically determinate) that "
            "is attached to what is left; the textbook detaches them starting from the farthest "
            "from the driver, the solvers run them in the reverse order."
        ),
        "no_groups": "There are no groups: the driver(s) and the ground are the whole mechanism.",
        "group": "Group {i}: {label}",
        "group_links": "links {links}: n = {n}",
        "group_pairs": "pairs: {pairs}: p = {p}",
        "outer": "outer",
        "inner": "inner",
        "check": "3·n = 2·p:",
        "class_dyad": "class II: a dyad (2 links, 3 pairs); order {order}; kind {kind}",
        "class_base": (
            "class {cls}: link {link} is a base link with {k} inner pairs and there is no "
            "longer closed contour; order {order}"
        ),
        "class_contour": "class {cls}: a closed contour of {k} inner pairs; order {order}",
        "attached": "attached to link(s) {links}",
        "remains": (
            "What remains is the driver(s) {drivers} with the ground {ground}: a class-I mechanism."
        ),
        "formula": "{k}. Structural formula and class",
        "formula_groups": "In solve order (from the driver):",
        "formula_textbook": "W = one per driver + 0 per group:",
        "class": "The mechanism is of class {cls}: the highest class of its groups.",
    },
    "vi": {
        "title": "Cấu trúc và xếp loại cơ cấu: {name}",
        "mobility": "1. Bậc tự do",
        "formula_intro": "Bậc tự do cơ cấu được tính theo công thức",
        "n": "n = {n} khâu động ({links}); giá {ground} không tính",
        "p5": "P5 = {p5} khớp thấp loại 5: {r} khớp quay (R), {p} khớp tịnh tiến (P)",
        "compound": (
            "khớp quay kép {point} nối {k} khâu ({links}): tính là {k} − 1 = {pairs} khớp quay"
        ),
        "p4": "P4 = {p4} khớp cao loại 4: {pairs}",
        "p4_none": "P4 = 0: không có khớp cao",
        "cam": "khớp cam",
        "gear": "khớp bánh răng",
        "r_none": "r_th = 0: không có ràng buộc trùng",
        "r": "r_th = {r} ràng buộc trùng:",
        "r_structural": (
            "{k} tại khớp {pair}{line}: một chuỗi con có nhiều ràng buộc hơn số khâu của nó cho "
            "phép (đếm theo cấu trúc)"
        ),
        "r_geometric": (
            "{k} tại khớp {pair}{line}: kích thước làm một ràng buộc lặp lại (hạng ma trận Jacobi "
            "tại vị trí đang xét)"
        ),
        "line": " (dòng {line})",
        "w_none": "W_th = 0: không có bậc tự do thừa",
        "w": "W_th = {w} bậc tự do thừa:",
        "w_roller": "chuyển động quay của con lăn {link} quanh trục của nó",
        "w_geometric": "khâu {link} chuyển động riêng được ({k} bậc tự do, tại vị trí đang xét)",
        "substituted": "Thay số:",
        "note": "Ghi chú: {note}",
        "replacement": "2. Thay thế khớp cao",
        "replacement_intro": (
            "Vì có khớp cao nên ta phải thay thế khớp cao thành khớp thấp (đúng tại vị trí đang "
            "xét, cho vị trí, vận tốc và gia tốc): mỗi khớp cao thành một khâu thay thế với hai "
            "khớp thấp."
        ),
        "roller": (
            "bỏ con lăn {roller} cùng khớp {pair}: chuyển động quay của nó là bậc tự do thừa; "
            "điểm tiếp xúc chuyển về tâm con lăn {axis}, một điểm của khâu {follower}"
        ),
        "replace_rr": (
            "{pair} ({what}) → khâu thay thế {v} với {new}: khớp quay tại tâm cong của hai biên "
            "dạng"
        ),
        "replace_rp": (
            "{pair} ({what}) → khâu thay thế {v} với {new}: biên dạng của khâu {flat} tại chỗ tiếp "
            "xúc là phẳng nên phía đó thay bằng khớp tịnh tiến"
        ),
        "replaced_counts": (
            "Bậc tự do cơ cấu thay thế: n = {n}, P5 = {p5}, P4 = 0; không còn bậc tự do thừa "
            "(W_th = 0):"
        ),
        "unchanged": "W không đổi.",
        "drivers": "{k}. Khâu dẫn",
        "driver": "chọn khâu {link} là khâu dẫn, nối với giá bằng khớp {pair}",
        "driver_chosen": "(không ghi khâu dẫn: chọn trong các khâu nối với giá)",
        "w_drivers": "W = {w}: cơ cấu có {w} khâu dẫn.",
        "set_aside": (
            "khâu thừa {links} (khớp {pairs}) được bỏ ra trước khi tách nhóm (ràng buộc trùng)"
        ),
        "groups": "{k}. Tách nhóm tĩnh định (nhóm Assur), bắt đầu từ nhóm xa khâu dẫn nhất",
        "groups_intro": (
            "Mỗi nhóm là tập khâu nhỏ nhất có 3·n = 2·p (nhóm tĩnh định) nối vào phần còn lại; "
            "tách nhóm từ nhóm xa khâu dẫn nhất, còn khi giải thì đi theo thứ tự ngược lại."
        ),
        "no_groups": "Không có nhóm nào: cơ cấu chỉ gồm khâu dẫn và giá.",
        "group": "Nhóm {i}: {label}",
        "group_links": "khâu {links}: n = {n}",
        "group_pairs": "khớp: {pairs}: p = {p}",
        "outer": "khớp chờ",
        "inner": "khớp trong",
        "check": "3·n = 2·p:",
        "class_dyad": "nhóm loại 2: nhóm hai khâu ba khớp; bậc {order}; dạng {kind}",
        "class_base": (
            "nhóm loại {cls}: khâu {link} là khâu cơ sở có {k} khớp trong, không có chuỗi kín dài "
            "hơn; bậc {order}"
        ),
        "class_contour": "nhóm loại {cls}: có chuỗi động kín {k} khớp trong; bậc {order}",
        "attached": "nối vào khâu {links}",
        "remains": "Còn lại khâu dẫn {drivers} và giá {ground}: cơ cấu loại 1.",
        "formula": "{k}. Công thức cấu tạo và loại cơ cấu",
        "formula_groups": "Theo thứ tự giải (từ khâu dẫn):",
        "formula_textbook": "Công thức cấu tạo cơ cấu:",
        "class": "Đây là cơ cấu loại {cls} (loại cao nhất của các nhóm).",
    },
}


# ============================================================================ mathematics
@dataclass(frozen=True, slots=True)
class Math:
    """A piece of mathematics in its plain (Unicode) and LaTeX forms.

    ``Math + str`` appends the same text to both forms (use it for digits,
    names and ASCII signs only).

    >>> (Math("ω2", r"\\omega_{2}") + " = 5").latex
    '\\\\omega_{2} = 5'
    """

    text: str
    latex: str

    def __add__(self, other: Math | str) -> Math:
        if isinstance(other, Math):
            return Math(self.text + other.text, self.latex + other.latex)
        return Math(self.text + other, self.latex + other)

    def __radd__(self, other: str) -> Math:
        return Math(other + self.text, other + self.latex)


def math_join(parts: Iterable[Math | str], sep: Math | str = "") -> Math:
    """Join pieces of mathematics with ``sep``.

    >>> math_join([Math("a", "a"), Math("β", r"\\beta")], " + ").text
    'a + β'
    """
    out = Math("", "")
    for k, part in enumerate(parts):
        if k:
            out = out + sep
        out = out + part
    return out


def subscript(name: str, sub: str) -> Math:
    """``name`` with subscript ``sub``: ``P5`` for digits as the textbook writes it.

    >>> subscript("ω", "2").text, subscript("l", "BC").text, subscript("ω", "v1").latex
    ('ω2', 'l_BC', '\\\\omega_{v1}')
    """
    greek = {"ω": r"\omega", "ε": r"\varepsilon", "φ": r"\varphi", "Σ": r"\Sigma"}
    head = greek.get(name, name)
    joined = name + sub if (sub.isdigit() and name in greek) else f"{name}_{sub}"
    return Math(joined, f"{head}_{{{sub}}}")


def number(x: float, zero: float = 1e-9) -> str:
    """``x`` with 6 significant digits, ``0`` for anything smaller than ``zero`` in size.

    >>> number(0.30000000000000004), number(-1e-15), number(70.71067811865)
    ('0.3', '0', '70.7107')
    """
    if not math.isfinite(x):
        return str(x)
    if abs(x) <= zero:
        return "0"
    text = f"{x:.6g}"
    return "0" if text in ("-0", "0") else text


_LATEX_MATH = {
    "·": r" \cdot ",
    "−": "-",
    "²": "^2",
    "⇒": r"\;\Rightarrow\;",
    "→": r"\to ",
    "⊥": r"\perp ",
    "∥": r"\parallel ",
    "×": r"\times ",
    "Σ": r"\sum ",
    "°": r"^\circ",
    "✓": r"\ \checkmark",
}


def formula(template: str, **fields: Math | str | float) -> Math:
    r"""Mathematics from a template: its text as written, in LaTeX with the symbols translated.

    Fields are :class:`Math` (inserted in each form), floats (:func:`number`) or text.

    >>> f = formula("{w}·{l} = {x} ⇒ ok", w=subscript("ω", "1"), l=subscript("l", "AB"), x=2.0)
    >>> print(f.text)
    ω1·l_AB = 2 ⇒ ok
    >>> print(f.latex)
    \omega_{1} \cdot l_{AB} = 2 \;\Rightarrow\; ok
    """
    text, latex = [], []
    for literal, name, _, _ in string.Formatter().parse(template):
        if literal:
            text.append(literal)
            latex.append("".join(_LATEX_MATH.get(ch, ch) for ch in literal))
        if name is None:
            continue
        value = fields[name]
        if isinstance(value, Math):
            text.append(value.text)
            latex.append(value.latex)
        else:
            shown = number(value) if isinstance(value, float) else str(value)
            text.append(shown)
            latex.append(shown)
    return Math("".join(text), "".join(latex))


# ============================================================================ documents
Segment = str | Math


def _segments(template: str, fields: Mapping[str, object]) -> list[Segment]:
    out: list[Segment] = []
    for literal, name, spec, _ in string.Formatter().parse(template):
        if literal:
            out.append(literal)
        if name is None:
            continue
        value = fields[name]
        if isinstance(value, Math):
            out.append(value)
        elif isinstance(value, list):
            out.extend(value)
        else:
            out.append(format(value, spec) if spec else str(value))
    return out


class Doc:
    """A worked solution as blocks: title, headings, paragraphs, items, display equations.

    ``say(key, **fields)`` fills the phrase ``key`` of ``phrases[lang]``;
    fields may be prose (str, numbers), :class:`Math` or lists of segments.
    """

    def __init__(self, phrases: Mapping[str, Mapping[str, str]], lang: str):
        self.phrases = phrases
        self.lang = lang
        self.blocks: list[tuple[str, object, int]] = []

    def say(self, key: str, **fields: object) -> list[Segment]:
        """The phrase ``key`` in the document's language, as segments."""
        return _segments(self.phrases[self.lang][key], fields)

    def word(self, key: str) -> str:
        """The phrase ``key`` as plain text (no fields)."""
        return self.phrases[self.lang][key]

    def title(self, *segments: Segment) -> None:
        self.blocks.append(("title", list(segments), 0))

    def heading(self, *segments: Segment) -> None:
        self.blocks.append(("heading", list(segments), 0))

    def subheading(self, *segments: Segment) -> None:
        self.blocks.append(("subheading", list(segments), 0))

    def para(self, *segments: Segment) -> None:
        self.blocks.append(("para", list(segments), 0))

    def item(self, *segments: Segment, level: int = 0) -> None:
        self.blocks.append(("item", list(segments), level))

    def equation(self, expression: Math) -> None:
        self.blocks.append(("equation", expression, 0))


def _flat(segments: Sequence[Segment]) -> list[Segment]:
    out: list[Segment] = []
    for s in segments:
        if isinstance(s, list):
            out.extend(_flat(s))
        else:
            out.append(s)
    return out


_LATEX_PROSE = {
    "\\": r"\textbackslash{}",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "#": r"\#",
    "%": r"\%",
    "_": r"\_",
    "^": r"\^{}",
    "~": r"\~{}",
    "→": r"$\to$",
    "⇒": r"$\Rightarrow$",
    "⊥": r"$\perp$",
    "∥": r"$\parallel$",
    "ω": r"$\omega$",
    "ε": r"$\varepsilon$",
    "τ": r"$\tau$",
    "Σ": r"$\Sigma$",
    "·": r"$\cdot$",
    "²": r"$^2$",
    "−": "-",
    "°": r"$^\circ$",
    "✓": r"$\checkmark$",
    "≈": r"$\approx$",
    "×": r"$\times$",
}


def _prose(text: str, fmt: str) -> str:
    if fmt == "latex":
        return "".join(_LATEX_PROSE.get(ch, ch) for ch in text)
    if fmt == "markdown":
        return text.replace("*", r"\*").replace("_", r"\_")
    return text


def _merged(segments: Sequence[Segment]) -> list[Segment]:
    """Adjacent mathematics joined (``$a$$b$`` would read as display math in Markdown)."""
    out: list[Segment] = []
    for s in _flat(segments):
        if isinstance(s, Math) and out and isinstance(out[-1], Math):
            out[-1] = out[-1] + s
        elif isinstance(s, str) and not s:
            continue
        else:
            out.append(s)
    return out


def _inline(segments: Sequence[Segment], fmt: str) -> str:
    out = []
    for s in _merged(segments):
        if isinstance(s, Math):
            out.append(s.text if fmt == "text" else f"${s.latex.strip()}$")
        else:
            out.append(_prose(s, fmt))
    return "".join(out)


def render(doc: Doc, fmt: str = "text") -> str:
    """The document as ``text``, ``markdown`` or ``latex``.

    >>> d = Doc({"en": {}}, "en")
    >>> d.heading("Velocities"); d.equation(Math("v_C = v_B", r"\\vec{v}_{C} = \\vec{v}_{B}"))
    >>> print(render(d, "latex"))
    \\subsection*{Velocities}
    \\[ \\vec{v}_{C} = \\vec{v}_{B} \\]
    <BLANKLINE>
    """
    check_options("en", fmt)
    lines: list[str] = []
    open_items = 0  # LaTeX itemize depth
    previous = ""

    def close_items(depth: int) -> None:
        nonlocal open_items
        while open_items > depth:
            open_items -= 1
            lines.append("  " * open_items + r"\end{itemize}")

    for kind, content, level in doc.blocks:
        if fmt == "latex" and kind != "item":
            close_items(0)
        if kind == "equation":
            assert isinstance(content, Math)
            if fmt == "text":
                lines.append("      " + content.text)
            elif fmt == "markdown":
                if previous and lines and lines[-1] != "":
                    lines.append("")
                lines.append(f"$${content.latex.strip()}$$")
                lines.append("")
            else:
                lines.append(rf"\[ {content.latex.strip()} \]")
            previous = kind
            continue
        text = _inline(content, fmt)  # type: ignore[arg-type]
        if fmt == "text":
            if kind == "title":
                lines += [text, "=" * min(len(text), 100)]
            elif kind == "heading":
                lines += ["", text]
            elif kind == "subheading":
                lines.append("  " + text)
            elif kind == "para":
                lines += textwrap.wrap(text, 100, initial_indent="  ", subsequent_indent="  ")
            else:
                lines.append("    " + "  " * level + "- " + text)
        elif fmt == "markdown":
            if kind == "item":
                if previous not in ("item", "") and lines and lines[-1] != "":
                    lines.append("")
                lines.append("  " * level + "- " + text)
            else:
                if lines and lines[-1] != "":
                    lines.append("")
                prefix = {"title": "# ", "heading": "## ", "subheading": "### ", "para": ""}[kind]
                lines.append(prefix + text)
                lines.append("")
        else:
            if kind == "item":
                close_items(level + 1)
                while open_items < level + 1:
                    lines.append("  " * open_items + r"\begin{itemize}")
                    open_items += 1
                lines.append("  " * open_items + r"\item " + text)
            else:
                command = {
                    "title": r"\section*{%s}",
                    "heading": r"\subsection*{%s}",
                    "subheading": r"\subsubsection*{%s}",
                    "para": "%s\n",
                }[kind]
                lines.append(command % text)
        previous = kind
    if fmt == "latex":
        close_items(0)
    while lines and lines[-1] == "":
        lines.pop()
    return "\n".join(lines) + "\n"


def check_options(lang: str, fmt: str) -> None:
    """Raise ValueError for a language or format the explanations do not know.

    >>> check_options("fr", "text")
    Traceback (most recent call last):
    ...
    ValueError: unknown language 'fr': use one of en, vi
    """
    if lang not in LANGUAGES:
        raise ValueError(f"unknown language {lang!r}: use one of {', '.join(LANGUAGES)}")
    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}: use one of {', '.join(FORMATS)}")


# ============================================================================ structure
def _w_general(lang: str) -> Math:
    r = "r" if lang == "en" else "r_th"
    r_latex = "r" if lang == "en" else r"r_{th}"
    return Math(
        f"W = 3·n − (2·P5 + P4) + {r} − W_th",
        rf"W = 3 \cdot n - (2 \cdot P_5 + P_4) + {r_latex} - W_{{th}}",
    )


def _w_formula(mob: Mobility, lang: str) -> Math:
    general = _w_general(lang)
    numbers = Math(
        f"3·{mob.n} − (2·{mob.P5} + {mob.P4}) + {mob.r} − {mob.W_passive} = {mob.W}",
        rf"3 \cdot {mob.n} - (2 \cdot {mob.P5} + {mob.P4}) + {mob.r} - {mob.W_passive}"
        rf" = {mob.W}",
    )
    return general + " = " + numbers


def _pair_label(m: Mechanism, kind: PairKind, links: tuple[str, str], point: str | None) -> str:
    return f"{links[0]}–{links[1]} {kind.value}" + (f" {point}" if point else "")


def _counts(doc: Doc, report: StructuralReport) -> None:
    m, mob = report.mechanism, report.mobility
    doc.heading(doc.word("mobility"))
    doc.para(doc.word("formula_intro"), ":")
    doc.equation(_w_general(doc.lang))
    doc.item(*doc.say("n", n=mob.n, links=", ".join(m.moving_links), ground=m.ground))
    n_r = sum(1 for p in m.pairs if p.kind is PairKind.R)
    n_p = sum(1 for p in m.pairs if p.kind is PairKind.P)
    doc.item(*doc.say("p5", p5=mob.P5, r=n_r, p=n_p))
    for hinge in m.compound_hinges.values():
        k = len(hinge.links)
        doc.item(
            *doc.say("compound", point=hinge.point, k=k, links=", ".join(hinge.links), pairs=k - 1),
            level=1,
        )
    highs = [p for p in m.pairs if p.kind is PairKind.H]
    if highs:
        labels = ", ".join(f"{p.label} ({doc.word('gear' if p.gear else 'cam')})" for p in highs)
        doc.item(*doc.say("p4", p4=mob.P4, pairs=labels))
    else:
        doc.item(doc.word("p4_none"))
    if mob.redundant:
        doc.item(*doc.say("r", r=mob.r))
        for x in mob.redundant:
            line = doc.say("line", line=x.line_no) if x.line_no else ""
            key = "r_structural" if x.source == "structural" else "r_geometric"
            doc.item(*doc.say(key, k=x.constraints, pair=x.label, line=line), level=1)
    else:
        doc.item(doc.word("r_none"))
    if mob.passive:
        doc.item(*doc.say("w", w=mob.W_passive))
        for x in mob.passive:
            if x.source == "roller":
                doc.item(*doc.say("w_roller", link=x.link), level=1)
            else:
                doc.item(*doc.say("w_geometric", link=x.link, k=x.dof), level=1)
    else:
        doc.item(doc.word("w_none"))
    doc.para(doc.word("substituted"))
    doc.equation(_w_formula(mob, doc.lang))
    for note in mob.notes:
        doc.para(*doc.say("note", note=note))


def _replacements(doc: Doc, report: StructuralReport) -> None:
    doc.heading(doc.word("replacement"))
    doc.para(doc.word("replacement_intro"))
    for rep in report.replacements:
        if rep.roller is not None:
            r = rep.roller
            doc.item(
                *doc.say(
                    "roller",
                    roller=r.roller,
                    pair=r.removed_pairs[0].label,
                    axis=r.axis,
                    follower=r.follower,
                )
            )
        new = ", ".join(p.label for p in rep.new_pairs)
        what = doc.word("gear" if rep.pair.gear else "cam")
        if rep.scheme == "R–R":
            doc.item(
                *doc.say("replace_rr", pair=rep.pair.label, what=what, v=rep.virtual_link, new=new)
            )
        else:
            flat = next(p for p in rep.new_pairs if p.kind is PairKind.P).other(rep.virtual_link)
            doc.item(
                *doc.say(
                    "replace_rp",
                    pair=rep.pair.label,
                    what=what,
                    v=rep.virtual_link,
                    new=new,
                    flat=flat,
                )
            )
    rm = report.replaced_mobility
    doc.para(*doc.say("replaced_counts", n=rm.n, p5=rm.P5))
    doc.equation(_w_formula(rm, doc.lang))
    doc.para(doc.word("unchanged"))


def _driver_pair(m: Mechanism, link: str) -> str:
    for p in m.pairs_of(link):
        if p.other(link) == m.ground and p.kind is not PairKind.H:
            return p.label
    for h in m.compound_hinges.values():
        if link in h.links and m.ground in h.links:
            return f"{m.ground}–{link} R {h.point}"
    return "?"


def _class_line(doc: Doc, g: AssurGroup) -> list[Segment]:
    if len(g.links) == 2:
        return doc.say("class_dyad", order=g.order, kind=g.kind or "?")
    joints: dict[str, set[str]] = {}
    for k, p in enumerate(g.internal_pairs):
        key = f"R {p.point}" if p.kind is PairKind.R and p.point else f"#{k}"
        joints.setdefault(key, set()).update(p.links)
    degree = {x: sum(1 for j in joints.values() if x in j) for x in g.links}
    base = max(g.links, key=lambda x: degree[x])
    cls = roman(g.assur_class) if doc.lang == "en" else str(g.assur_class)
    if degree[base] >= g.assur_class:
        return doc.say("class_base", cls=cls, link=base, k=degree[base], order=g.order)
    return doc.say("class_contour", cls=cls, k=g.assur_class, order=g.order)


def _groups(doc: Doc, report: StructuralReport, k: int) -> None:
    doc.heading(*doc.say("groups", k=k))
    doc.para(doc.word("groups_intro"))
    if not report.groups:
        doc.para(doc.word("no_groups"))
    for i, g in enumerate(report.detach_order, start=1):
        doc.subheading(*doc.say("group", i=i, label=g.label))
        n, p = len(g.links), len(g.pairs)
        doc.item(*doc.say("group_links", links=", ".join(g.links), n=n))
        pairs = ", ".join(
            f"{_pair_label(report.replaced, gp.kind, gp.links, gp.point)} "
            f"({doc.word('outer' if gp.external else 'inner')})"
            for gp in g.pairs
        )
        doc.item(*doc.say("group_pairs", pairs=pairs, p=p))
        ok = "✓" if 3 * n == 2 * p else "✗"
        doc.item(
            doc.word("check") + " ",
            Math(
                f"3·{n} = 2·{p} = {3 * n} {ok}",
                rf"3 \cdot {n} = 2 \cdot {p} = {3 * n}" + (r"\ \checkmark" if ok == "✓" else ""),
            ),
        )
        doc.item(*_class_line(doc, g))
        doc.item(*doc.say("attached", links=", ".join(g.known_links)))
    doc.para(*doc.say("remains", drivers=", ".join(report.drivers), ground=report.replaced.ground))


def explain_structure(report: StructuralReport, lang: str = "en", fmt: str = "text") -> str:
    """The structural analysis of ``report`` as a worked solution.

    Parameters
    ----------
    report : StructuralReport
        From :func:`structure.report.analyze`.
    lang : {"en", "vi"}
        English or Vietnamese (the source's vocabulary).
    fmt : {"text", "markdown", "latex"}
        Plain text, Markdown with LaTeX mathematics, or a LaTeX fragment.

    Returns
    -------
    str
        The counts and ``W`` with numbers, the corrections and where they come
        from, the replacements, the driver(s), the groups from the farthest
        (links, pairs, ``3n = 2p``, class, order, kind), the structural formula
        and the mechanism's class.

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> lines = ["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 P C angle=0"]
    >>> r = analyze(parse_edgelist(lines))
    >>> print(explain_structure(r).splitlines()[-1])
      The mechanism is of class II: the highest class of its groups.
    """
    check_options(lang, fmt)
    doc = Doc(PHRASES, lang)
    m = report.mechanism
    name = m.name or m.source
    doc.title(*doc.say("title", name=name))
    _counts(doc, report)
    k = 2
    if report.replacements:
        _replacements(doc, report)
        k = 3
    doc.heading(*doc.say("drivers", k=k))
    for link in report.drivers:
        doc.item(*doc.say("driver", link=link, pair=_driver_pair(report.replaced, link)))
    if report.drivers_chosen:
        doc.item(doc.word("driver_chosen"))
    doc.para(*doc.say("w_drivers", w=report.mobility.W))
    d = report.decomposition
    if d.removed_links or d.removed_pairs:
        pairs = ", ".join(report.replaced.pair(p).label for p in d.removed_pairs)
        doc.item(*doc.say("set_aside", links=", ".join(d.removed_links) or "–", pairs=pairs))
    _groups(doc, report, k + 1)
    doc.heading(*doc.say("formula", k=k + 2))
    doc.para(doc.word("formula_groups"))
    parts = report.formula.split(" → ")
    doc.equation(Math(report.formula, r" \to ".join(rf"\text{{{x}}}" for x in parts)))
    doc.para(doc.word("formula_textbook"))
    doc.equation(Math(report.textbook_formula, report.textbook_formula))
    cls = roman(report.mechanism_class) if lang == "en" else str(report.mechanism_class)
    doc.para(*doc.say("class", cls=cls))
    return render(doc, fmt)
