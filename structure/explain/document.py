"""The document engine of the worked solutions: blocks of prose and mathematics, rendered.

A worked solution is built once as a :class:`Doc` (title, headings, paragraphs,
bullet items, display equations) whose mathematics (:class:`Math`) carries a
plain (Unicode) and a LaTeX form, and rendered by :func:`render` as ``text``,
``markdown`` (with ``$…$`` / ``$$…$$`` LaTeX mathematics), ``latex`` (a
fragment: ``\\section*``, ``itemize``, ``\\[ … \\]``; it needs ``amsmath`` and
``amssymb``, and Vietnamese text needs ``\\usepackage[vietnamese]{babel}``) or
``html`` (a fragment to embed in a page: its formulas are presentation MathML,
written from their LaTeX by :mod:`structure.explain.mathml`).
:mod:`structure.explain.structural` and :mod:`kinematics.explain` write their
solutions with it.

>>> d = Doc({"en": {"hello": "Hello {name}"}}, "en")
>>> d.title(*d.say("hello", name="world")); d.equation(formula("{w} = 2", w=subscript("ω", "1")))
>>> print(render(d, "markdown"))
# Hello world
<BLANKLINE>
$$\\omega_{1} = 2$$
<BLANKLINE>
"""

from __future__ import annotations

import math
import string
import textwrap
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from html import escape

from .mathml import latex_to_mathml

__all__ = [
    "FORMATS",
    "LANGUAGES",
    "Doc",
    "Math",
    "Segment",
    "check_options",
    "formula",
    "math_join",
    "number",
    "render",
    "subscript",
]

#: output formats and languages the explanations accept
FORMATS = ("text", "markdown", "latex", "html")
LANGUAGES = ("en", "vi")


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


def _flattened(segments: Sequence[Segment]) -> list[Segment]:
    out: list[Segment] = []
    for s in segments:
        if isinstance(s, list):
            out.extend(_flattened(s))
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
    if fmt == "html":
        return escape(text, quote=False)
    if fmt == "latex":
        return "".join(_LATEX_PROSE.get(ch, ch) for ch in text)
    if fmt == "markdown":
        return text.replace("*", r"\*").replace("_", r"\_")
    return text


def _merged(segments: Sequence[Segment]) -> list[Segment]:
    """Adjacent mathematics joined (``$a$$b$`` would read as display math in Markdown)."""
    out: list[Segment] = []
    for s in _flattened(segments):
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
            out.append(_inline_math(s, fmt))
        else:
            out.append(_prose(s, fmt))
    return "".join(out)


def _inline_math(expression: Math, fmt: str) -> str:
    if fmt == "text":
        return expression.text
    if fmt == "html":
        return latex_to_mathml(expression.latex.strip())
    return f"${expression.latex.strip()}$"


Block = tuple[str, object, int]  # kind, content (segments or Math), item level


def _text_lines(blocks: Sequence[Block]) -> list[str]:
    """Plain text: the title underlined, paragraphs wrapped at 100, items indented by level."""
    lines: list[str] = []
    for kind, content, level in blocks:
        if kind == "equation":
            assert isinstance(content, Math)
            lines.append("      " + content.text)
            continue
        text = _inline(content, "text")  # type: ignore[arg-type]
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
    return lines


_MARKDOWN_PREFIX = {"title": "# ", "heading": "## ", "subheading": "### ", "para": ""}


def _markdown_lines(blocks: Sequence[Block]) -> list[str]:
    """Markdown: ``#`` headings, ``-`` items, ``$$…$$`` display equations, blank lines between."""
    lines: list[str] = []
    previous = ""
    for kind, content, level in blocks:
        if kind == "equation":
            assert isinstance(content, Math)
            if previous and lines and lines[-1] != "":
                lines.append("")
            lines += [f"$${content.latex.strip()}$$", ""]
        elif kind == "item":
            if previous not in ("item", "") and lines and lines[-1] != "":
                lines.append("")
            lines.append("  " * level + "- " + _inline(content, "markdown"))  # type: ignore[arg-type]
        else:
            if lines and lines[-1] != "":
                lines.append("")
            text = _inline(content, "markdown")  # type: ignore[arg-type]
            lines += [_MARKDOWN_PREFIX[kind] + text, ""]
        previous = kind
    return lines


_LATEX_COMMAND = {
    "title": r"\section*{%s}",
    "heading": r"\subsection*{%s}",
    "subheading": r"\subsubsection*{%s}",
    "para": "%s\n",
}


def _latex_lines(blocks: Sequence[Block]) -> list[str]:
    """A LaTeX fragment: starred sections, nested ``itemize``, ``\\[ … \\]`` equations."""
    lines: list[str] = []
    depth = 0  # itemize environments open
    for kind, content, level in blocks:
        target = level + 1 if kind == "item" else 0
        while depth > target:
            depth -= 1
            lines.append("  " * depth + r"\end{itemize}")
        if kind == "equation":
            assert isinstance(content, Math)
            lines.append(rf"\[ {content.latex.strip()} \]")
            continue
        text = _inline(content, "latex")  # type: ignore[arg-type]
        if kind != "item":
            lines.append(_LATEX_COMMAND[kind] % text)
            continue
        while depth < target:
            lines.append("  " * depth + r"\begin{itemize}")
            depth += 1
        lines.append("  " * depth + r"\item " + text)
    while depth > 0:
        depth -= 1
        lines.append("  " * depth + r"\end{itemize}")
    return lines


_HTML_TAG = {"title": "h2", "heading": "h3", "subheading": "h4", "para": "p"}


def _html_lines(blocks: Sequence[Block], lang: str) -> list[str]:
    """An HTML fragment: one ``section``, headings, paragraphs, nested lists, MathML formulas."""
    lines = [f'<section class="worked-solution" lang="{escape(lang)}">']
    open_items: list[int | None] = []  # per open list: the line of its open item, if any
    for kind, content, level in blocks:
        target = level + 1 if kind == "item" else 0
        while len(open_items) > target:
            _close_html_list(lines, open_items)
        if kind == "equation":
            assert isinstance(content, Math)
            lines.append(latex_to_mathml(content.latex.strip(), display=True))
            continue
        text = _inline(content, "html")  # type: ignore[arg-type]
        if kind != "item":
            lines.append(f"<{_HTML_TAG[kind]}>{text}</{_HTML_TAG[kind]}>")
            continue
        if len(open_items) == target:
            _close_html_item(lines, open_items)
        while len(open_items) < target:
            if open_items and open_items[-1] is None:  # a list nested with no item to hold it
                open_items[-1] = len(lines)
                lines.append("  " * (2 * len(open_items) - 1) + "<li>")
            lines.append("  " * 2 * len(open_items) + "<ul>")
            open_items.append(None)
        open_items[-1] = len(lines)
        lines.append("  " * (2 * len(open_items) - 1) + f"<li>{text}")
    while open_items:
        _close_html_list(lines, open_items)
    lines.append("</section>")
    return lines


def _close_html_item(lines: list[str], open_items: list[int | None]) -> None:
    """End the innermost list's open item: on its own line when a list was nested in it."""
    opened = open_items[-1]
    if opened is None:
        return
    if opened == len(lines) - 1:
        lines[-1] += "</li>"
    else:
        lines.append("  " * (2 * len(open_items) - 1) + "</li>")
    open_items[-1] = None


def _close_html_list(lines: list[str], open_items: list[int | None]) -> None:
    _close_html_item(lines, open_items)
    open_items.pop()
    lines.append("  " * 2 * len(open_items) + "</ul>")


_RENDERERS: dict[str, Callable[[Doc], list[str]]] = {
    "text": lambda doc: _text_lines(doc.blocks),
    "markdown": lambda doc: _markdown_lines(doc.blocks),
    "latex": lambda doc: _latex_lines(doc.blocks),
    "html": lambda doc: _html_lines(doc.blocks, doc.lang),
}


def render(doc: Doc, fmt: str = "text") -> str:
    """The document as ``text``, ``markdown``, ``latex`` or ``html``.

    Parameters
    ----------
    doc : Doc
        The worked solution.
    fmt : {"text", "markdown", "latex", "html"}
        The output format: plain text; Markdown with ``$…$`` LaTeX mathematics; a
        LaTeX fragment; an HTML fragment (one ``<section class="worked-solution">``
        with headings ``h2``–``h4``, paragraphs and nested lists, every formula a
        presentation-MathML ``<math>`` element, all text escaped, no script).

    Returns
    -------
    str
        The rendered document, ending with one newline.

    Raises
    ------
    ValueError
        An unknown ``fmt``.

    Examples
    --------
    >>> d = Doc({"en": {}}, "en")
    >>> d.heading("Velocities"); d.equation(Math("v_C = v_B", r"\\vec{v}_{C} = \\vec{v}_{B}"))
    >>> print(render(d, "latex"))
    \\subsection*{Velocities}
    \\[ \\vec{v}_{C} = \\vec{v}_{B} \\]
    <BLANKLINE>
    >>> from structure.explain.mathml import MATHML_NAMESPACE
    >>> d = Doc({"en": {}}, "en")
    >>> d.para("if ", Math("x", "x"), " < 1:"); d.item("a & b"); d.item("nested", level=1)
    >>> d.equation(Math("x = 1", "x = 1"))
    >>> print(render(d, "html").replace(f' xmlns="{MATHML_NAMESPACE}"', ""))
    <section class="worked-solution" lang="en">
    <p>if <math><mi>x</mi></math> &lt; 1:</p>
    <ul>
      <li>a &amp; b
        <ul>
          <li>nested</li>
        </ul>
      </li>
    </ul>
    <math display="block"><mi>x</mi><mo>=</mo><mn>1</mn></math>
    </section>
    <BLANKLINE>
    """
    check_options("en", fmt)
    lines = _RENDERERS[fmt](doc)
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
