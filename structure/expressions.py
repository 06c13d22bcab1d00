"""Exact numbers in the edge-list format: ``0.2*sqrt(3)``, ``1/3``, ``-sqrt(2)/2``.

A coordinate or a driver's speed may be written as an arithmetic expression
of decimal numbers with ``+ - * /``, parentheses and ``sqrt( )``, without
spaces. It is read by a small recursive-descent parser (never ``eval``) into
both a float and an exact sympy number, so that the exact solvers can answer
``50*sqrt(2)`` rather than ``70.71``.

>>> read_number("0.2*sqrt(3)")
(0.34641016151377546, 'sqrt(3)/5')
>>> read_number("12.5")
(12.5, '25/2')
>>> read_number("2**3")
Traceback (most recent call last):
...
ValueError: unexpected '*' at 2 in '2**3'
"""

from __future__ import annotations

import math
import re

import sympy

__all__ = ["exact_float", "exact_value", "read_number"]

_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|(sqrt)|(.))")


def _tokens(text: str) -> list[tuple[str, str, int]]:
    out = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:  # pragma: no cover - the pattern matches any character
            raise ValueError(f"cannot read {text!r}")
        number, name, other = m.groups()
        start = m.start(1) if number else m.start(2) if name else m.start(3)
        if number:
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

    def _peek(self) -> tuple[str, str, int] | None:
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def _fail(self) -> ValueError:
        tok = self._peek()
        if tok is None:
            return ValueError(f"unexpected end of {self.text!r}")
        return ValueError(f"unexpected {tok[1]!r} at {tok[2]} in {self.text!r}")

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
                    raise ValueError(f"division by zero in {self.text!r}")
                value = value / divisor
            else:
                return value

    def _factor(self) -> sympy.Expr:
        if self._take("-"):
            return -self._factor()
        if self._take("+"):
            return self._factor()
        tok = self._peek()
        if tok is None:
            raise self._fail()
        if tok[0] == "num":
            self.i += 1
            return sympy.Rational(tok[1])
        if tok[0] == "sqrt":
            self.i += 1
            if not self._take("("):
                raise self._fail()
            inner = self._sum()
            if not self._take(")"):
                raise self._fail()
            if inner.is_negative:
                raise ValueError(f"square root of a negative number in {self.text!r}")
            return sympy.sqrt(inner)
        if self._take("("):
            inner = self._sum()
            if not self._take(")"):
                raise self._fail()
            return inner
        raise self._fail()


def exact_value(text: str) -> sympy.Expr:
    """The exact value of a number written in the format (raises ValueError).

    >>> exact_value("-sqrt(2)/2")
    -sqrt(2)/2
    """
    return _Parser(text).parse()


def read_number(text: str) -> tuple[float, str]:
    """``(float value, exact value as text)`` of a number of the format.

    Raises
    ------
    ValueError
        Anything but a finite arithmetic expression of decimals, ``sqrt``,
        ``+ - * /`` and parentheses.
    """
    exact = _Parser(text).parse()
    value = float(exact)
    if not math.isfinite(value):
        raise ValueError(f"{text!r} is not finite")
    return value, str(exact)


def exact_float(value: float) -> sympy.Rational:
    """The exact rational a float stands for in a file: its shortest decimal text.

    >>> exact_float(0.1)
    1/10
    """
    return sympy.Rational(repr(float(value)))
