"""Exact numbers in the edge-list format: ``0.2*sqrt(3)``, ``1/3``, ``-sqrt(2)/2``, within limits.

A coordinate or a driver's speed may be written as an arithmetic expression
of decimal numbers with ``+ - * /``, parentheses and ``sqrt( )``, without
spaces. It is read by a small recursive-descent parser (never ``eval``) into
both a float and an exact sympy number, so that the exact solvers can answer
``50*sqrt(2)`` rather than ``70.71``.

The text is checked before any exact number is built: at most
:data:`MAX_LENGTH` characters, :data:`MAX_DEPTH` levels of brackets, signs
and roots, :data:`MAX_DIGITS` digits and an exponent of at most
:data:`MAX_EXPONENT` in each decimal, so that no text can exhaust the stack,
the memory or the time. sympy is imported at the first exact value, not with
this module (``import structure`` does not import it).

>>> read_number("0.2*sqrt(3)")
(0.34641016151377546, 'sqrt(3)/5')
>>> read_number("12.5")
(12.5, '25/2')
>>> read_number("2**3")
Traceback (most recent call last):
...
structure.errors.NumberError: unexpected '*' at 2 in '2**3'
>>> read_number("1e99999999")
Traceback (most recent call last):
...
structure.errors.NumberError: '1e99999999' has an exponent beyond ±400
"""

from __future__ import annotations

import functools
import importlib
import math
import re
from types import ModuleType
from typing import TYPE_CHECKING

from .errors import NumberError, clipped

if TYPE_CHECKING:  # annotations only: sympy is imported at the first exact value
    import sympy

__all__ = [
    "MAX_DEPTH",
    "MAX_DIGITS",
    "MAX_EXPONENT",
    "MAX_LENGTH",
    "exact_float",
    "exact_value",
    "read_number",
]

#: the longest expression read, in characters
MAX_LENGTH = 1000
#: the deepest nesting of brackets, signs and square roots
MAX_DEPTH = 100
#: the most digits in one decimal number (before its exponent)
MAX_DIGITS = 100
#: the largest exponent of a decimal number, in absolute value (``1e400``)
MAX_EXPONENT = 400

_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|(sqrt)|(.))")


@functools.cache
def _sympy() -> ModuleType:
    """The sympy module, imported the first time an exact value is built."""
    return importlib.import_module("sympy")


def _check_decimal(number: str, text: str) -> None:
    """A decimal within :data:`MAX_DIGITS` digits and :data:`MAX_EXPONENT`, before sympy sees it."""
    mantissa, _, exponent = number.lower().partition("e")
    if sum(c.isdigit() for c in mantissa) > MAX_DIGITS:
        raise NumberError(f"{clipped(text)!r} has a number of more than {MAX_DIGITS} digits")
    if exponent and (len(exponent.lstrip("+-")) > 6 or abs(int(exponent)) > MAX_EXPONENT):
        raise NumberError(f"{clipped(text)!r} has an exponent beyond ±{MAX_EXPONENT}")


def _tokens(text: str) -> list[tuple[str, str, int]]:
    if len(text) > MAX_LENGTH:
        raise NumberError(f"{clipped(text)!r} is longer than {MAX_LENGTH} characters")
    out = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:  # pragma: no cover - the pattern matches any character
            raise NumberError(f"cannot read {clipped(text)!r}")
        number, name, other = m.groups()
        start = m.start(1) if number else m.start(2) if name else m.start(3)
        if number:
            _check_decimal(number, text)
            out.append(("num", number, start))
        elif name:
            out.append(("sqrt", name, start))
        elif other.strip():
            out.append(("op", other, start))
        pos = m.end()
    return out


class _Parser:
    def __init__(self, text: str):
        self.text = text
        self.tokens = _tokens(text)
        self.i = 0
        self.depth = 0
        self.sympy = _sympy()

    def _peek(self) -> tuple[str, str, int] | None:
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def _fail(self) -> NumberError:
        tok = self._peek()
        if tok is None:
            return NumberError(f"unexpected end of {clipped(self.text)!r}")
        return NumberError(f"unexpected {tok[1]!r} at {tok[2]} in {clipped(self.text)!r}")

    def _take(self, value: str) -> bool:
        tok = self._peek()
        if tok is not None and tok[0] == "op" and tok[1] == value:
            self.i += 1
            return True
        return False

    def parse(self) -> sympy.Expr:
        value = self._sum()
        if self._peek() is not None:
            raise self._fail()
        return value

    def _sum(self) -> sympy.Expr:
        value = self._product()
        while True:
            if self._take("+"):
                value = value + self._product()
            elif self._take("-"):
                value = value - self._product()
            else:
                return value

    def _product(self) -> sympy.Expr:
        value = self._factor()
        while True:
            if self._take("*"):
                value = value * self._factor()
            elif self._take("/"):
                divisor = self._factor()
                if divisor == 0:
                    raise NumberError(f"division by zero in {clipped(self.text)!r}")
                value = value / divisor
            else:
                return value

    def _factor(self) -> sympy.Expr:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise NumberError(
                f"{clipped(self.text)!r} nests brackets, signs or roots deeper than {MAX_DEPTH}"
            )
        try:
            return self._nested_factor()
        finally:
            self.depth -= 1

    def _nested_factor(self) -> sympy.Expr:
        if self._take("-"):
            return -self._factor()
        if self._take("+"):
            return self._factor()
        tok = self._peek()
        if tok is None:
            raise self._fail()
        if tok[0] == "num":
            self.i += 1
            return self.sympy.Rational(tok[1])
        if tok[0] == "sqrt":
            self.i += 1
            if not self._take("("):
                raise self._fail()
            inner = self._sum()
            if not self._take(")"):
                raise self._fail()
            if inner.is_negative:
                raise NumberError(f"square root of a negative number in {clipped(self.text)!r}")
            return self.sympy.sqrt(inner)
        if self._take("("):
            inner = self._sum()
            if not self._take(")"):
                raise self._fail()
            return inner
        raise self._fail()


def exact_value(text: str) -> sympy.Expr:
    """The exact value of a number written in the format.

    Raises
    ------
    NumberError
        As :func:`read_number` (a ``ValueError`` too).

    >>> exact_value("-sqrt(2)/2")
    -sqrt(2)/2
    """
    return _Parser(text).parse()


def read_number(text: str) -> tuple[float, str]:
    """``(float value, exact value as text)`` of a number of the format.

    Raises
    ------
    NumberError
        Anything but a finite arithmetic expression of decimals, ``sqrt``,
        ``+ - * /`` and parentheses within the limits of this module (a
        ``ValueError`` too).
    """
    exact = _Parser(text).parse()
    try:
        value = float(exact)
    except (OverflowError, TypeError):  # beyond the float range, or not a real number
        value = math.inf
    if not math.isfinite(value):
        raise NumberError(f"{clipped(text)!r} is not finite")
    return value, str(exact)


def exact_float(value: float) -> sympy.Rational:
    """The exact rational a float stands for in a file: its shortest decimal text.

    >>> exact_float(0.1)
    1/10
    """
    return _sympy().Rational(repr(float(value)))
