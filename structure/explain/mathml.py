r"""The worked solutions' LaTeX mathematics as presentation MathML.

:func:`latex_to_mathml` reads the LaTeX that a
:class:`~structure.explain.document.Math` carries and writes one ``<math>``
element of presentation MathML (``mi``, ``mn``, ``mo``, ``mrow``, ``msub``,
``msup``, ``msubsup``, ``mover``, ``mfrac``, ``msqrt``, ``mtext``,
``mspace``), which browsers render natively: no script, no external resource.
It knows the subset the solutions write: letters, decimal numbers (``1e-05``
included), operators, ``_`` and ``^`` scripts, braces, ``\vec``, ``\frac``,
``\sqrt``, ``\text``, ``\mathrm``, Greek letters, ``\cdot``, ``\times``,
``\sum``, arrows, ``\perp``, ``\parallel``, ``^\circ``, ``\checkmark`` and
the spacing commands. A command it does not know is shown as text, never
dropped.

>>> print(latex_to_mathml(r"\omega_{1} = 2\ \mathrm{rad}").split(">", 1)[1])
<msub><mi>ω</mi><mn>1</mn></msub><mo>=</mo><mn>2</mn><mspace width="0.25em"/><mi>rad</mi></math>
"""

from __future__ import annotations

import re
from collections.abc import Callable
from html import escape

__all__ = ["MATHML_NAMESPACE", "latex_to_mathml"]

#: the namespace of MathML, on every ``<math>`` element written
MATHML_NAMESPACE = "http://www.w3.org/1998/Math/MathML"

_TOKEN = re.compile(
    r"(?P<command>\\[A-Za-z]+)"
    r"|(?P<symbol>\\.)"
    r"|(?P<number>\d+(?:\.\d+)?(?:e[-+]?\d+)?)"
    r"|(?P<space>\s+)"
    r"|(?P<char>.)",
    re.S,
)

_LETTERS = {
    "alpha": "α",
    "beta": "β",
    "gamma": "γ",
    "delta": "δ",
    "varepsilon": "ε",
    "epsilon": "ϵ",
    "eta": "η",
    "theta": "θ",
    "lambda": "λ",
    "mu": "μ",
    "pi": "π",
    "rho": "ρ",
    "sigma": "σ",
    "tau": "τ",
    "varphi": "φ",
    "phi": "ϕ",
    "psi": "ψ",
    "omega": "ω",
    "Delta": "Δ",
    "Sigma": "Σ",
    "Phi": "Φ",
    "Omega": "Ω",
    "infty": "∞",
}

_OPERATORS = {
    "cdot": "⋅",
    "times": "×",
    "sum": "∑",
    "to": "→",
    "rightarrow": "→",
    "Rightarrow": "⇒",
    "leftarrow": "←",
    "perp": "⊥",
    "parallel": "∥",
    "approx": "≈",
    "neq": "≠",
    "leq": "≤",
    "geq": "≥",
    "pm": "±",
    "circ": "∘",
    "checkmark": "✓",
    "ldots": "…",
    "cdots": "⋯",
    "{": "{",
    "}": "}",
    "|": "‖",
}

_SPACES = {
    " ": "0.25em",
    ",": "0.1667em",
    ":": "0.2222em",
    ";": "0.2778em",
    "quad": "1em",
    "qquad": "2em",
}

#: characters written as another operator in MathML (the minus sign)
_CHARACTERS = {"-": "−", "*": "∗"}


def latex_to_mathml(latex: str, display: bool = False) -> str:
    r"""One ``<math>`` element for a piece of LaTeX mathematics.

    Parameters
    ----------
    latex : str
        Mathematics in the LaTeX subset the worked solutions write.
    display : bool
        A display (block) formula (``display="block"``) rather than one in a line.

    Returns
    -------
    str
        ``<math xmlns="http://www.w3.org/1998/Math/MathML">…</math>``; all text escaped.

    Examples
    --------
    >>> latex_to_mathml(r"\frac{1}{\sqrt{2}} < 1", display=True).startswith('<math xmlns="http')
    True
    >>> print(latex_to_mathml(r"\frac{1}{\sqrt{2}} < 1").split(">", 1)[1])
    <mfrac><mn>1</mn><msqrt><mn>2</mn></msqrt></mfrac><mo>&lt;</mo><mn>1</mn></math>
    >>> print(latex_to_mathml(r"\vec{v}_{C}").split(">", 1)[1])
    <msub><mover accent="true"><mi>v</mi><mo stretchy="false">→</mo></mover><mi>C</mi></msub></math>
    >>> print(latex_to_mathml(r"a^{\tau}_{CB}").split(">", 1)[1])
    <msubsup><mi>a</mi><mrow><mi>C</mi><mi>B</mi></mrow><mi>τ</mi></msubsup></math>
    """
    block = ' display="block"' if display else ""
    body = "".join(_Reader(latex).sequence())
    return f'<math xmlns="{MATHML_NAMESPACE}"{block}>{body}</math>'


def _row(nodes: list[str]) -> str:
    """One element for a list of them: itself when alone, else an ``mrow``."""
    return nodes[0] if len(nodes) == 1 else "<mrow>" + "".join(nodes) + "</mrow>"


def _operator(text: str) -> str:
    stretch = ' stretchy="false"' if text in "()[]|‖" else ""
    return f"<mo{stretch}>{escape(text)}</mo>"


def _identifier(text: str, upright: bool) -> str:
    variant = ' mathvariant="normal"' if upright and len(text) == 1 else ""
    return f"<mi{variant}>{escape(text)}</mi>"


class _Reader:
    """A recursive-descent reader of the LaTeX tokens, writing MathML as it goes."""

    def __init__(self, latex: str) -> None:
        self.tokens = [(m.lastgroup or "char", m.group()) for m in _TOKEN.finditer(latex)]
        self.position = 0
        self.commands: dict[str, Callable[[bool], str]] = {
            "vec": self._vector,
            "frac": self._fraction,
            "sqrt": self._root,
            "text": self._text,
            "mathrm": self._upright,
            "operatorname": self._upright,
            "left": self._fence,
            "right": self._fence,
        }

    def _peek(self) -> tuple[str, str] | None:
        while self.position < len(self.tokens) and self.tokens[self.position][0] == "space":
            self.position += 1
        return self.tokens[self.position] if self.position < len(self.tokens) else None

    def _take(self) -> tuple[str, str]:
        token = self._peek()
        if token is None:
            raise ValueError("the LaTeX ends where an argument was expected")
        self.position += 1
        return token

    def sequence(self, upright: bool = False) -> list[str]:
        """Atoms with their scripts, up to a closing brace or the end."""
        nodes: list[str] = []
        while (token := self._peek()) is not None and token != ("char", "}"):
            if token in (("char", "_"), ("char", "^")):
                base = "<mrow></mrow>"
            else:
                base = self._atom(upright)
            nodes.append(self._scripts(base, upright))
        return nodes

    def _scripts(self, base: str, upright: bool) -> str:
        """``base`` with the ``_`` and ``^`` scripts that follow it (``^\\circ``: a degree)."""
        below = above = None
        while (token := self._peek()) in (("char", "_"), ("char", "^")):
            self.position += 1
            if token == ("char", "^") and self._peek() == ("command", r"\circ"):
                self.position += 1
                base = f"<mrow>{base}<mo>°</mo></mrow>"
                continue
            script = self._script(upright)
            if token == ("char", "_"):
                below = script
            else:
                above = script
        if below is not None and above is not None:
            return f"<msubsup>{base}{below}{above}</msubsup>"
        if below is not None:
            return f"<msub>{base}{below}</msub>"
        if above is not None:
            return f"<msup>{base}{above}</msup>"
        return base

    def _script(self, upright: bool) -> str:
        """A script's argument: a group or one token (one digit of a number, as LaTeX reads)."""
        kind, text = self._take()
        if kind == "number" and len(text) > 1:
            self.position -= 1
            self.tokens[self.position] = ("number", text[1:])
            return f"<mn>{text[0]}</mn>"
        self.position -= 1
        return self._atom(upright)

    def _argument(self, upright: bool = False) -> str:
        return self._atom(upright)

    def _atom(self, upright: bool) -> str:
        kind, text = self._take()
        if kind == "number":
            return f"<mn>{text}</mn>"
        if kind == "command":
            return self._command(text[1:], upright)
        if kind == "symbol":
            name = text[1:]
            if name in _SPACES:
                return f'<mspace width="{_SPACES[name]}"/>'
            return _operator(_OPERATORS.get(name, name))
        if text == "{":
            nodes = self.sequence(upright)
            if self._peek() is not None:
                self.position += 1  # the closing brace
            return _row(nodes) if nodes else "<mrow></mrow>"
        if text.isalpha():
            return _identifier(self._letters(text) if upright else text, upright)
        return _operator(_CHARACTERS.get(text, text))

    def _letters(self, first: str) -> str:
        """A run of letters (a unit's name, upright): ``rad``."""
        run = first
        while self.position < len(self.tokens):
            kind, text = self.tokens[self.position]
            if kind != "char" or not text.isalpha():
                break
            run += text
            self.position += 1
        return run

    def _command(self, name: str, upright: bool) -> str:
        if name in self.commands:
            return self.commands[name](upright)
        if name in _LETTERS:
            return _identifier(_LETTERS[name], False)
        if name in _OPERATORS:
            return _operator(_OPERATORS[name])
        if name in _SPACES:
            return f'<mspace width="{_SPACES[name]}"/>'
        return f"<mtext>\\{escape(name)}</mtext>"

    def _vector(self, upright: bool) -> str:
        arrow = '<mo stretchy="false">→</mo>'
        return f'<mover accent="true">{self._argument(upright)}{arrow}</mover>'

    def _fraction(self, upright: bool) -> str:
        top = self._argument(upright)
        return f"<mfrac>{top}{self._argument(upright)}</mfrac>"

    def _root(self, upright: bool) -> str:
        return f"<msqrt>{self._argument(upright)}</msqrt>"

    def _upright(self, upright: bool) -> str:
        return self._argument(upright=True)

    def _fence(self, upright: bool) -> str:
        """``\\left(`` and ``\\right)``: the delimiter itself."""
        return self._atom(upright)

    def _text(self, upright: bool) -> str:
        """``\\text{…}``: its characters as they are, spaces included."""
        if self._take() != ("char", "{"):
            raise ValueError(r"\text takes its text in braces")
        depth, out = 1, []
        while self.position < len(self.tokens):
            kind, text = self.tokens[self.position]
            self.position += 1
            depth += {"{": 1, "}": -1}.get(text, 0) if kind == "char" else 0
            if depth == 0:
                break
            out.append(text)
        return f"<mtext>{escape(''.join(out))}</mtext>"
