"""Tests of the exact numbers' limits (structure.expressions, issue 11)."""

from __future__ import annotations

import time

import pytest

from structure.errors import NumberError, StatementError
from structure.expressions import MAX_DEPTH, MAX_DIGITS, MAX_EXPONENT, MAX_LENGTH, read_number


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("(" * (MAX_DEPTH + 1) + "1" + ")" * (MAX_DEPTH + 1), "deeper than"),
        ("-" * (MAX_DEPTH + 1) + "1", "deeper than"),
        ("sqrt(" * (MAX_DEPTH + 1) + "2" + ")" * (MAX_DEPTH + 1), "deeper than"),
        ("1" * (MAX_DIGITS + 1), "digits"),
        (f"1e{MAX_EXPONENT + 1}", "exponent"),
        ("1e99999999", "exponent"),
        ("1e-99999999999999999999", "exponent"),
        ("1+" * MAX_LENGTH + "1", "longer than"),
        ("1e300*1e300", "not finite"),
    ],
)
def test_numbers_beyond_the_limits_are_refused_quickly(text, reason):
    read_number("1/3")  # sympy imported before the clock starts
    start = time.perf_counter()
    with pytest.raises(NumberError, match=reason) as info:
        read_number(text)
    assert time.perf_counter() - start < 5.0  # no hang (the machine may be busy)
    assert len(str(info.value)) < 200  # the text is quoted cut
    assert isinstance(info.value, (StatementError, ValueError))


@pytest.mark.parametrize(
    "text",
    [
        "(" * (MAX_DEPTH - 1) + "1" + ")" * (MAX_DEPTH - 1),
        "-" * (MAX_DEPTH - 1) + "1",
        "9" * MAX_DIGITS,
        f"1e{MAX_EXPONENT}/1e{MAX_EXPONENT - 1}",
    ],
)
def test_numbers_within_the_limits_are_read(text):
    value, _ = read_number(text)
    assert value == value  # a number, not NaN
