"""The notation of the worked solutions: symbols, numbers with units, directions.

Each function returns :class:`~structure.explain.document.Math` in the
textbook's notation, in its plain and LaTeX forms: vectors (``v_CB``,
``a^τ_CB``), magnitudes and components (``R^τ_12``), rates (``ω2``, ``ε2``),
lengths (``l_AB``), directions (``⊥AB``, ``∥BC``, ``C→B``), quantities with
their units (``2 m/s``) and formulas written in symbols, then numbers, then
their value (``ω1·l_AB = 20·0.1 = 2 m/s``).

>>> print(times_length(omega_symbol("1"), 20.0, "B", "A", 0.1, "m/s").text)
ω1·l_AB = 20·0.1 = 2 m/s
>>> print(vector_symbol("a", "CB", "τ").latex)
\\vec{a}^{\\,\\tau}_{CB}
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from structure.explain.document import Math, formula, number, subscript

__all__ = [
    "POWER_EQUATION",
    "ZERO",
    "angle_of",
    "components_text",
    "direction_text",
    "epsilon_symbol",
    "length_symbol",
    "load_sum",
    "moment_of",
    "moment_sum",
    "number_math",
    "omega_symbol",
    "pair_subscript",
    "parallel_to",
    "parenthesized",
    "perpendicular_to",
    "power_term",
    "quantity",
    "reaction_symbol",
    "reaction_vector",
    "scalar_symbol",
    "segment_name",
    "times_length",
    "toward",
    "vector_symbol",
    "with_numbers",
]


#: a zero, and the virtual-power equation
ZERO = Math("0", "0")
POWER_EQUATION = Math(
    "Σ P·v + Σ M·ω + M_cb·ω1 = 0",
    r"\sum \vec{P} \cdot \vec{v} + \sum M \omega + M_{cb} \omega_1 = 0",
)

#: the LaTeX of each unit, after its number
_UNIT_LATEX = {
    "m/s": r"\ \mathrm{m/s}",
    "m/s²": r"\ \mathrm{m/s^2}",
    "rad": r"\ \mathrm{rad}",
    "rad/s": r"\ \mathrm{rad/s}",
    "rad/s²": r"\ \mathrm{rad/s^2}",
    "N": r"\ \mathrm{N}",
    "N·m": r"\ \mathrm{N \cdot m}",
    "W": r"\ \mathrm{W}",
    "m": r"\ \mathrm{m}",
}


def number_math(x: float, zero: float = 1e-9) -> Math:
    """A bare number as mathematics (see :func:`~structure.explain.document.number`)."""
    text = number(x, zero)
    return Math(text, text)


def quantity(x: float, unit: str, zero: float = 1e-9) -> Math:
    """A quantity with its unit: ``2 m/s``."""
    text = number(x, zero)
    return Math(f"{text} {unit}", text + _UNIT_LATEX[unit])


def components_text(v: np.ndarray, unit: str) -> Math:
    """A vector by its components and unit: ``(3, -4) N``."""
    x, y = number(float(v[0]), 1e-6), number(float(v[1]), 1e-6)
    return Math(f"({x}, {y}) {unit}", rf"({x},\ {y})" + _UNIT_LATEX[unit])


def parenthesized(x: float) -> Math:
    """A number in parentheses when negative: ``(-0.5)``."""
    text = number(x)
    text = f"({text})" if text.startswith("-") else text
    return Math(text, text)


def segment_name(a: str, b: str) -> str:
    """Two point names in the textbook's order (``AB``, ``BC``, ``CD``)."""
    return a + b if a <= b else b + a


def pair_subscript(a: str, b: str) -> str:
    """The subscript of two links: ``12``, or ``2,v1`` when a name is longer than a letter."""
    return a + b if len(a) == 1 and len(b) == 1 else f"{a},{b}"


_SUPERSCRIPT_LATEX = {"τ": r"\tau"}


def vector_symbol(letter: str, sub: str, sup: str = "") -> Math:
    """A vector: ``v_CB``, ``a^τ_CB`` (LaTeX ``\\vec{a}^{\\,\\tau}_{CB}``)."""
    text = f"{letter}^{sup}_{sub}" if sup else f"{letter}_{sub}"
    top = f"^{{\\,{_SUPERSCRIPT_LATEX.get(sup, sup)}}}" if sup else ""
    return Math(text, rf"\vec{{{letter}}}{top}_{{{sub}}}")


def scalar_symbol(letter: str, sub: str, sup: str = "") -> Math:
    """A magnitude or a scalar component: ``v_CB``, ``R^τ_12``."""
    text = f"{letter}^{sup}_{sub}" if sup else f"{letter}_{sub}"
    top = f"^{{{_SUPERSCRIPT_LATEX.get(sup, sup)}}}" if sup else ""
    return Math(text, rf"{letter}{top}_{{{sub}}}")


def omega_symbol(link: str) -> Math:
    """The angular velocity of a link: ``ω2``."""
    return subscript("ω", link)


def epsilon_symbol(link: str) -> Math:
    """The angular acceleration of a link: ``ε2``."""
    return subscript("ε", link)


def length_symbol(a: str, b: str) -> Math:
    """The length between two points: ``l_AB``."""
    return subscript("l", segment_name(a, b))


def load_sum(link: str = "") -> Math:
    """``ΣP`` (or ``ΣP_2``): the known loads of the group (of link 2)."""
    if link:
        return Math(f"ΣP_{link}", rf"\sum \vec{{P}}_{{{link}}}")
    return Math("ΣP", r"\sum \vec{P}")


def perpendicular_to(a: str, b: str) -> Math:
    """A direction ``⊥AB``."""
    return Math(f"⊥{segment_name(a, b)}", rf"\perp {segment_name(a, b)}")


def parallel_to(name: str) -> Math:
    """A direction ``∥`` a guide or a line: ``∥BC``, ``∥x``."""
    return Math(f"∥{name}", rf"\parallel {name}")


def toward(a: str, b: str) -> Math:
    """A direction from point ``a`` to point ``b``: ``C→B``."""
    return Math(f"{a}→{b}", rf"{a} \to {b}")


def reaction_symbol(source: str, target: str, sup: str = "") -> Math:
    """``R_12``: the force link 1 exerts on link 2 (a magnitude or component)."""
    return scalar_symbol("R", pair_subscript(source, target), sup)


def reaction_vector(source: str, target: str, sup: str = "") -> Math:
    """The force vector link ``source`` exerts on link ``target``: ``R_12``."""
    return vector_symbol("R", pair_subscript(source, target), sup)


def moment_sum(point: str) -> Math:
    """The sum of moments about ``point``: ``ΣM_B``."""
    return Math(f"ΣM_{point}", rf"\sum M_{{{point}}}")


def moment_of(point: str, source: str, target: str) -> Math:
    """``M_B(R_32)``: the moment about ``point`` of the force ``source`` exerts on ``target``."""
    sub = pair_subscript(source, target)
    return Math(f"M_{point}(R_{sub})", rf"M_{{{point}}}(R_{{{sub}}})")


def with_numbers(
    template: str, symbols: Sequence[Math], values: Sequence[Math | float], result: Math
) -> Math:
    """A formula in its symbols, then in their values, then its value.

    >>> symbols = [omega_symbol("1"), length_symbol("A", "B")]
    >>> with_numbers("{0}·{1}", symbols, [20.0, 0.1], quantity(2.0, "m/s")).text
    'ω1·l_AB = 20·0.1 = 2 m/s'
    """

    def filled(items: Sequence[Math | float]) -> Math:
        return formula(template, **{str(k): x for k, x in enumerate(items)})

    return formula("{s} = {n} = {r}", s=filled(symbols), n=filled(values), r=result)


def times_length(
    rate: Math, value: float, a: str, b: str, length: float, unit: str, square: bool = False
) -> Math:
    """A rate's size times the length ``ab``: ``ω1·l_AB = 20·0.1 = 2 m/s``; ``ω3²·l_CD = …``."""
    two = "²" if square else ""
    size = value * value if square else abs(value)
    result = quantity(size * length, unit)
    return with_numbers(
        "{0}" + two + "·{1}", [rate, length_symbol(a, b)], [abs(value), length], result
    )


def power_term(sym: Math, speed_sym: Math, value: float, speed: float) -> Math:
    """The power of a load or a balancing moment: ``M_cb·ω1 = 50·10 = 500 W``."""
    speeds = [parenthesized(value), parenthesized(speed)]
    return with_numbers("{0}·{1}", [sym, speed_sym], speeds, quantity(value * speed, "W"))


def angle_of(v: np.ndarray) -> float:
    """Direction of a vector, degrees from the x axis counter-clockwise, in (−180, 180].

    >>> angle_of(np.array([-1.0, -0.0])), angle_of(np.array([0.0, 2.0]))
    (180.0, 90.0)
    """
    a = math.degrees(math.atan2(float(v[1]), float(v[0])))
    return a + 360.0 if a <= -180.0 + 1e-9 else a


def direction_text(v: np.ndarray, zero: float = 1e-9) -> str:
    """The direction in degrees, or ``–`` for a vector of size ``zero`` or less."""
    if float(np.hypot(v[0], v[1])) <= zero:
        return "–"
    return number(angle_of(v), 1e-6)
