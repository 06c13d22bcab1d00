"""Formulas of φ and ω (structure.formulas): parsed, never evaluated by Python, within limits."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from structure.errors import StatementError
from structure.formulas import MAX_DEPTH, MAX_LENGTH, read_formula


@pytest.mark.parametrize(
    ("text", "phi", "omega", "expected"),
    [
        ("1+2*3", 0.0, 0.0, 7.0),
        ("2^3^2", 0.0, 0.0, 512.0),  # right-associative, as in mathematics
        ("2**3", 0.0, 0.0, 8.0),
        ("-2^2", 0.0, 0.0, -4.0),  # the sign binds looser than the power
        ("2^-1", 0.0, 0.0, 0.5),
        ("(1+2)*(3-4)/2", 0.0, 0.0, -1.5),
        ("25000-7500*sin(3*phi)", math.pi / 6, 0.0, 17500.0),
        ("40*(1-omega/150)", 0.0, 75.0, 20.0),
        ("step(phi-pi)", 4.0, 0.0, 1.0),
        ("step(phi-pi)", 3.0, 0.0, 0.0),
        ("max(phi,omega)+min(1,2)", 2.0, 3.0, 4.0),
        ("abs(-3)+sqrt(16)+exp(0)+log(1)+cos(0)+tan(0)", 0.0, 0.0, 9.0),
        (" 1 + phi ", 2.0, 0.0, 3.0),  # JSON may hold spaces
        ("1e3*.5", 0.0, 0.0, 500.0),
    ],
)
def test_values(text: str, phi: float, omega: float, expected: float) -> None:
    assert float(read_formula(text).evaluate(phi, omega)) == pytest.approx(expected, rel=1e-15)


def test_it_broadcasts_over_poses() -> None:
    f = read_formula("phi*omega")
    assert f.evaluate(np.array([1.0, 2.0]), 3.0).tolist() == [3.0, 6.0]
    assert read_formula("7").evaluate(np.zeros(3), 0.0).tolist() == [7.0, 7.0, 7.0]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("", "cannot be empty"),
        ("2*", "unexpected end"),
        ("2 3", "unexpected '3'"),
        ("__import__(1)", "unknown function '__import__'"),
        ("open('f')", 'unexpected "\'"'),
        ("x+1", "unknown name 'x'"),
        ("sin(1,2)", "sin takes 1 argument"),
        ("max(1)", "max takes 2 arguments"),
        ("1;2", "unexpected ';'"),
        ("(1+2", "unexpected end"),
        ("1e999", "not a finite number"),
        ("phi.real", "unexpected '.'"),
    ],
)
def test_bad_formulas_are_named(text: str, said: str) -> None:
    with pytest.raises(StatementError, match=r"formula|empty") as info:
        read_formula(text)
    assert said in str(info.value)


def test_limits_bound_the_work() -> None:
    with pytest.raises(StatementError, match="longer than"):
        read_formula("1+" * MAX_LENGTH + "1")
    with pytest.raises(StatementError, match="deeper than"):
        read_formula("(" * (MAX_DEPTH + 1) + "1" + ")" * (MAX_DEPTH + 1))
    with pytest.raises(StatementError, match="deeper than"):
        read_formula("-" * (MAX_DEPTH + 5) + "1")


def test_a_formula_that_is_not_finite_somewhere_says_so_by_its_value() -> None:
    values = read_formula("1/phi").evaluate(np.array([0.0, 1.0]), 0.0)
    assert not np.isfinite(values[0]) and values[1] == 1.0


_ATOMS = {"phi": 0.7, "omega": 3.1, "pi": math.pi, "2": 2.0, "0.5": 0.5, "3e-2": 0.03}
_FUNCTIONS = {
    "sin": math.sin,
    "cos": math.cos,
    "abs": abs,
    "step": lambda x: 1.0 if x >= 0 else 0.0,
    "sqrt": lambda x: math.sqrt(x) if x >= 0 else math.nan,
}
_OPERATORS = {
    "+": lambda a, b: a + b,
    "-": lambda a, b: a - b,
    "*": lambda a, b: a * b,
    "/": lambda a, b: a / b if b else math.nan,
}


def _power(a: float, b: float) -> float:
    try:
        value = a**b
    except (OverflowError, ZeroDivisionError):
        return math.nan
    return math.nan if isinstance(value, complex) else value


@st.composite
def _formulas(draw, depth: int = 3) -> tuple[str, float]:
    """A formula's text and its value at φ = 0.7, ω = 3.1, worked out beside it."""
    if depth == 0 or draw(st.booleans()):
        atom = draw(st.sampled_from(sorted(_ATOMS)))
        return atom, _ATOMS[atom]
    kind = draw(st.sampled_from(["bin", "neg", "call", "paren"]))
    text, value = draw(_formulas(depth - 1))
    if kind == "neg":  # a sign binds looser than a power: bracket what follows it
        return f"-({text})", -value
    if kind == "call":
        name = draw(st.sampled_from(sorted(_FUNCTIONS)))
        return f"{name}({text})", _FUNCTIONS[name](value)
    if kind == "paren":
        return f"({text})", value
    op = draw(st.sampled_from(["+", "-", "*", "/", "^"]))
    right, other = draw(_formulas(depth - 1))
    if op == "^":
        return f"({text})^({right})", _power(value, other)
    if op in "*/":  # the grammar's precedence is the test's: bracket the operands
        return f"({text}){op}({right})", _OPERATORS[op](value, other)
    return f"{text}{op}({right})", _OPERATORS[op](value, other)


@settings(max_examples=100, deadline=None)
@given(_formulas())
def test_any_formula_of_the_grammar_reads_and_has_its_value(case: tuple[str, float]) -> None:
    text, expected = case
    got = float(read_formula(text).evaluate(0.7, 3.1))
    if math.isfinite(expected) and abs(expected) < 1e100:
        assert got == pytest.approx(expected, rel=1e-9, abs=1e-12)
