"""Formulas of the driver's angle and speed: a load over the cycle written as an expression.

A formula such as ``25000-7500*sin(3*phi)`` or ``-0.5*omega^2`` is read by a
small recursive-descent parser (never ``eval``) into a tree of nodes, and
evaluated with numpy over many poses at once. Its variables are ``phi``, the
driver's rotation from the sketch within the turn (rad, in [0, 2π)), and
``omega``, the driver's angular velocity (rad/s); ``pi`` is π. Operators:
``+ - * /``, ``^`` (or ``**``) for powers, parentheses; functions: ``sin``,
``cos``, ``tan``, ``exp``, ``log``, ``sqrt``, ``abs``, ``step`` (1 where its
argument is ≥ 0, else 0: a load that acts over part of the turn), ``min`` and
``max`` of two values.

The text is checked as :mod:`structure.expressions` checks an exact number:
at most :data:`MAX_LENGTH` characters and :data:`MAX_DEPTH` levels of nesting,
so that no text can exhaust the stack, the memory or the time.

>>> f = read_formula("25000-7500*sin(3*phi)")
>>> float(f.evaluate(0.5235987755982988, 0.0))   # φ = 30°: sin(90°) = 1
17500.0
>>> f.uses_omega, read_formula("40*(1-omega/150)").uses_omega
(False, True)
>>> read_formula("2*phi+")
Traceback (most recent call last):
...
structure.errors.StatementError: formula '2*phi+': unexpected end
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from .errors import StatementError, clipped

__all__ = ["FUNCTIONS", "MAX_DEPTH", "MAX_LENGTH", "VARIABLES", "Formula", "read_formula"]

#: the longest formula read, in characters
MAX_LENGTH = 1000
#: the deepest nesting of brackets, signs, powers and calls
MAX_DEPTH = 100
#: the names a formula may use as variables
VARIABLES = ("phi", "omega")
_CONSTANTS = {"pi": math.pi}


def _step(x: np.ndarray) -> np.ndarray:
    return np.where(x >= 0, 1.0, 0.0)


def _scalar_step(x: float) -> float:
    return 1.0 if x >= 0 else 0.0


#: name -> the function of floats, for one value at a time (a domain error gives NaN)
_SCALAR_FUNCTIONS: dict[str, Callable[..., float]] = {
    "sin": math.sin,
    "cos": math.cos,
    "tan": math.tan,
    "exp": math.exp,
    "log": math.log,
    "sqrt": math.sqrt,
    "abs": abs,
    "step": _scalar_step,
    "min": min,
    "max": max,
}
_SCALAR_BINARY: dict[str, Callable[[float, float], float]] = {
    "+": float.__add__,
    "-": float.__sub__,
    "*": float.__mul__,
    "/": float.__truediv__,
    "^": float.__pow__,
}

#: name -> (number of arguments, the numpy function)
FUNCTIONS: dict[str, tuple[int, Callable[..., np.ndarray]]] = {
    "sin": (1, np.sin),
    "cos": (1, np.cos),
    "tan": (1, np.tan),
    "exp": (1, np.exp),
    "log": (1, np.log),
    "sqrt": (1, np.sqrt),
    "abs": (1, np.abs),
    "step": (1, _step),
    "min": (2, np.minimum),
    "max": (2, np.maximum),
}

_TOKEN = re.compile(
    r"\s*(?:(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|([A-Za-z_]\w*)|(\*\*|[-+*/^(),]))"
)
_BINARY = {
    "+": np.add,
    "-": np.subtract,
    "*": np.multiply,
    "/": np.divide,
    "^": np.power,
}

#: a node of the tree: ("num", value) | ("var", name) | ("neg", node)
#: | ("bin", op, left, right) | ("call", name, args)
Node = tuple


def _tokens(text: str) -> list[tuple[str, str, int]]:
    """``(kind, text, position)`` of each token: num, name or op; anything else is an error."""
    if len(text) > MAX_LENGTH:
        raise StatementError(f"formula {clipped(text)!r} is longer than {MAX_LENGTH} characters")
    out = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            if not text[pos:].strip():
                break
            bad = text[pos:].lstrip()[0]
            raise StatementError(f"formula {clipped(text)!r}: unexpected {bad!r}")
        number, name, op = m.groups()
        if number:
            out.append(("num", number, m.start(1)))
        elif name:
            out.append(("name", name, m.start(2)))
        else:
            out.append(("op", "^" if op == "**" else op, m.start(3)))
        pos = m.end()
    return out


class _Parser:
    """Recursive descent: sum := product (± product)*; product := unary (*/ unary)*;
    unary := ± unary | power; power := atom (^ unary)?; atom := number | name | call | (sum)."""

    def __init__(self, text: str):
        self.text = text
        self.tokens = _tokens(text)
        self.i = 0
        self.depth = 0
        self.names: set[str] = set()

    def fail(self, what: str = "") -> StatementError:
        tok = self.tokens[self.i] if self.i < len(self.tokens) else None
        where = "unexpected end" if tok is None else f"unexpected {tok[1]!r} at {tok[2]}"
        return StatementError(f"formula {clipped(self.text)!r}: {what or where}")

    def peek_op(self, *ops: str) -> str | None:
        tok = self.tokens[self.i] if self.i < len(self.tokens) else None
        if tok is not None and tok[0] == "op" and tok[1] in ops:
            return tok[1]
        return None

    def take(self, op: str) -> None:
        if self.peek_op(op) is None:
            raise self.fail()
        self.i += 1

    def parse(self) -> Node:
        if not self.tokens:
            raise StatementError("a formula cannot be empty")
        node = self.sum()
        if self.i != len(self.tokens):
            raise self.fail()
        return node

    def sum(self) -> Node:
        node = self.product()
        while (op := self.peek_op("+", "-")) is not None:
            self.i += 1
            node = ("bin", op, node, self.product())
        return node

    def product(self) -> Node:
        node = self.unary()
        while (op := self.peek_op("*", "/")) is not None:
            self.i += 1
            node = ("bin", op, node, self.unary())
        return node

    def unary(self) -> Node:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise self.fail(f"nests deeper than {MAX_DEPTH} levels")
        try:
            if (op := self.peek_op("+", "-")) is not None:
                self.i += 1
                inner = self.unary()
                return ("neg", inner) if op == "-" else inner
            return self.power()
        finally:
            self.depth -= 1

    def power(self) -> Node:
        node = self.atom()
        if self.peek_op("^") is not None:
            self.i += 1
            node = ("bin", "^", node, self.unary())
        return node

    def atom(self) -> Node:
        if self.i >= len(self.tokens):
            raise self.fail()
        kind, text, _ = self.tokens[self.i]
        if kind == "num":
            self.i += 1
            value = float(text)
            if not math.isfinite(value):
                raise self.fail(f"{text!r} is not a finite number")
            return ("num", value)
        if kind == "name":
            self.i += 1
            if self.peek_op("(") is not None:
                return self.call(text)
            if text in VARIABLES:
                self.names.add(text)
                return ("var", text)
            if text in _CONSTANTS:
                return ("num", _CONSTANTS[text])
            raise self.fail(
                f"unknown name {text!r} (variables: phi, omega; constant: pi; "
                f"functions: {', '.join(FUNCTIONS)})"
            )
        if self.peek_op("(") is not None:
            self.i += 1
            node = self.sum()
            self.take(")")
            return node
        raise self.fail()

    def call(self, name: str) -> Node:
        if name not in FUNCTIONS:
            raise self.fail(f"unknown function {name!r} (use {', '.join(FUNCTIONS)})")
        count = FUNCTIONS[name][0]
        self.take("(")
        args = [self.sum()]
        while self.peek_op(",") is not None:
            self.i += 1
            args.append(self.sum())
        self.take(")")
        if len(args) != count:
            raise self.fail(f"{name} takes {count} argument{'s' if count > 1 else ''}")
        return ("call", name, tuple(args))


def _evaluate(node: Node, phi: np.ndarray, omega: np.ndarray) -> np.ndarray:
    kind = node[0]
    if kind == "num":
        return node[1]
    if kind == "var":
        return phi if node[1] == "phi" else omega
    if kind == "neg":
        return np.negative(_evaluate(node[1], phi, omega))
    if kind == "bin":
        left = _evaluate(node[2], phi, omega)
        return _BINARY[node[1]](left, _evaluate(node[3], phi, omega))
    function = FUNCTIONS[node[1]][1]
    return function(*(_evaluate(arg, phi, omega) for arg in node[2]))


def _scalar(node: Node, phi: float, omega: float) -> float:
    kind = node[0]
    if kind == "num":
        return node[1]
    if kind == "var":
        return phi if node[1] == "phi" else omega
    if kind == "neg":
        return -_scalar(node[1], phi, omega)
    if kind == "bin":
        left = _scalar(node[2], phi, omega)
        return _SCALAR_BINARY[node[1]](left, _scalar(node[3], phi, omega))
    return float(_SCALAR_FUNCTIONS[node[1]](*(_scalar(arg, phi, omega) for arg in node[2])))


@dataclass(frozen=True, slots=True)
class Formula:
    """A formula of ``phi`` and ``omega`` as written, and its parsed tree.

    Two formulas are equal when their texts are.
    """

    text: str
    tree: Node = field(compare=False, repr=False)
    uses_omega: bool = field(compare=False, default=False)

    def evaluate(self, phi: np.ndarray | float, omega: np.ndarray | float) -> np.ndarray:
        """The formula's value at every ``phi`` (rad) and ``omega`` (rad/s), broadcast.

        Where the value is not finite (a division by zero, the logarithm of a
        negative number) it is NaN or infinite: the caller checks and names the pose.
        """
        phi = np.asarray(phi, dtype=float)
        omega = np.asarray(omega, dtype=float)
        with np.errstate(all="ignore"):
            value = _evaluate(self.tree, phi, omega)
        return np.broadcast_to(np.asarray(value, dtype=float), np.broadcast(phi, omega).shape)

    def value(self, phi: float, omega: float) -> float:
        """The formula at one ``phi`` and ``omega``, with floats (fast); NaN where not defined."""
        try:
            result = _scalar(self.tree, float(phi), float(omega))
        except (ValueError, ZeroDivisionError, OverflowError, TypeError):
            return math.nan  # a complex power gives NotImplemented, then a TypeError
        return result if isinstance(result, float) else math.nan


def read_formula(text: str) -> Formula:
    """Parse a formula of ``phi`` and ``omega`` (see the module's docstring).

    Raises
    ------
    StatementError
        Bad syntax, an unknown name or function, the wrong number of
        arguments, too long or too deep a text.
    """
    parser = _Parser(text)
    tree = parser.parse()
    return Formula(text, tree, "omega" in parser.names)
