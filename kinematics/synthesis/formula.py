"""A function of x read from text, safely: ``log10(x)``, ``x**2 + 1``, ``sin(pi*x/4)``.

The text is parsed by Python's :mod:`ast` (parsing only: nothing is run) and
every node is checked against a short list: numbers, the variable ``x``, the
constants ``pi`` and ``e``, ``+ - * / **`` (``^`` is ``**``), and the
functions of :data:`FUNCTIONS`. The tree is then evaluated by walking it with
numpy, never with ``eval``. A function undefined somewhere on its range is
a :class:`~kinematics.errors.SynthesisError` naming where.

>>> f = read_function("log10(x)")
>>> [round(float(v), 6) for v in f(np.array([1.0, 10.0]))]
[0.0, 1.0]
>>> read_function("__import__('os')")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
kinematics.errors.SynthesisError: cannot read the function "__import__('os')": only ...
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import SynthesisError

__all__ = ["FUNCTIONS", "MAX_LENGTH", "Function", "check_defined", "read_function"]

#: the longest text read, in characters
MAX_LENGTH = 200
#: the deepest nesting of operations
_MAX_DEPTH = 40

#: the functions a text may call
FUNCTIONS: dict[str, Callable[[np.ndarray], np.ndarray]] = {
    "sin": np.sin,
    "cos": np.cos,
    "tan": np.tan,
    "asin": np.arcsin,
    "acos": np.arccos,
    "atan": np.arctan,
    "sinh": np.sinh,
    "cosh": np.cosh,
    "tanh": np.tanh,
    "exp": np.exp,
    "log": np.log,
    "ln": np.log,
    "log10": np.log10,
    "log2": np.log2,
    "sqrt": np.sqrt,
    "abs": np.abs,
}
_CONSTANTS = {"pi": np.pi, "e": np.e}
_BINARY = {
    ast.Add: np.add,
    ast.Sub: np.subtract,
    ast.Mult: np.multiply,
    ast.Div: np.divide,
    ast.Pow: np.power,
}


@dataclass(frozen=True)
class Function:
    """A function of x as written (``text``), callable on numpy arrays."""

    text: str
    tree: ast.expr

    def __call__(self, x: np.ndarray) -> np.ndarray:
        with np.errstate(all="ignore"):
            value = _evaluate(self.tree, np.asarray(x, dtype=float))
        return np.broadcast_to(np.asarray(value, dtype=float), np.shape(x))


def _refuse(text: str, why: str) -> SynthesisError:
    return SynthesisError(
        f"cannot read the function {text!r}: {why} (write it of x with numbers, pi, e, "
        f"+ - * / ** and {', '.join(sorted(FUNCTIONS))})"
    )


def read_function(text: str) -> Function:
    """The function written in ``text``, checked node by node (see the module's text).

    Raises
    ------
    SynthesisError
        Text too long, bad syntax, or a name, call or operation not on the lists.
    """
    if len(text) > MAX_LENGTH:
        raise _refuse(text[:40] + "…", f"longer than {MAX_LENGTH} characters")
    try:
        tree = ast.parse(text.strip().replace("^", "**"), mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise _refuse(text, "it is not an expression") from None
    _check(tree, text, 0)
    return Function(text, tree)


def _check(node: ast.AST, text: str, depth: int) -> None:
    if depth > _MAX_DEPTH:
        raise _refuse(text, "nested too deeply")
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise _refuse(text, f"{node.value!r} is not a number")
        return
    if isinstance(node, ast.Name):
        if node.id != "x" and node.id not in _CONSTANTS:
            raise _refuse(text, f"unknown name {node.id!r}")
        return
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
        _check(node.operand, text, depth + 1)
        return
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        _check(node.left, text, depth + 1)
        _check(node.right, text, depth + 1)
        return
    if isinstance(node, ast.Call):
        name = node.func.id if isinstance(node.func, ast.Name) else None
        if name not in FUNCTIONS or len(node.args) != 1 or node.keywords:
            raise _refuse(text, "only one-argument calls of the listed functions")
        _check(node.args[0], text, depth + 1)
        return
    raise _refuse(text, f"{type(node).__name__} is not allowed")


def _evaluate(node: ast.AST, x: np.ndarray) -> np.ndarray:
    if isinstance(node, ast.Constant):
        return np.float64(node.value)
    if isinstance(node, ast.Name):
        return x if node.id == "x" else np.float64(_CONSTANTS[node.id])
    if isinstance(node, ast.UnaryOp):
        value = _evaluate(node.operand, x)
        return -value if isinstance(node.op, ast.USub) else value
    if isinstance(node, ast.BinOp):
        return _BINARY[type(node.op)](_evaluate(node.left, x), _evaluate(node.right, x))
    assert isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
    return FUNCTIONS[node.func.id](_evaluate(node.args[0], x))


def check_defined(f: Function, x0: float, x1: float, samples: int = 2001) -> None:
    """Refuse a function that is not finite (undefined, infinite) somewhere on [x0, x1].

    Raises
    ------
    SynthesisError
        Naming the first x sampled where it is not defined.
    """
    xs = np.linspace(x0, x1, samples)
    values = f(xs)
    bad = ~np.isfinite(values)
    if bad.any():
        where = float(xs[int(np.argmax(bad))])
        raise SynthesisError(
            f"the function {f.text!r} is not defined on the whole range [{x0:g}, {x1:g}]: "
            f"it has no finite value at x = {where:.6g}; choose a range where it is defined"
        )
