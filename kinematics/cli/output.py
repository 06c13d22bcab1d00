"""What every command prints: JSON, the title lines, vectors, the error line and its exit code.

Exit codes: :data:`EXIT_OK` (0), :data:`EXIT_MECHANISM` (1, a bad file or an impossible
mechanism), :data:`EXIT_USAGE` (2, a usage error), :data:`EXIT_BUG` (3, a bug in assur).
No NaN or infinity is ever printed: :func:`~structure.validation.check_finite` refuses a
result that holds one, and JSON is written with ``allow_nan=False`` (a strict parser reads it).

>>> check_finite({"reactions": [{"force": [1.0, float("nan")]}]})
Traceback (most recent call last):
...
structure.errors.NotFiniteError: reactions[0].force[1] is not finite: the result ov...
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable

from structure.errors import MechanismError, clipped
from structure.validation import check_finite

__all__ = [
    "EXIT_BUG",
    "EXIT_MECHANISM",
    "EXIT_OK",
    "EXIT_USAGE",
    "check_finite",
    "fail",
    "failed",
    "print_json",
    "title_lines",
    "vector",
    "write_lines",
]

#: the command ran and printed its answer
EXIT_OK = 0
#: a mechanism error: a bad file, an impossible mechanism, a file that cannot be written
EXIT_MECHANISM = 1
#: a usage error: bad options or option values
EXIT_USAGE = 2
#: a bug in assur (an exception that is no :class:`MechanismError`): please report it
EXIT_BUG = 3

#: the longest line of an error message written (a message may quote what the user wrote)
_MESSAGE_WIDTH = 1000


def print_json(data: object) -> None:
    """Print ``data`` as one indented JSON object (UTF-8 kept as is), never NaN or infinity.

    Raises
    ------
    NotFiniteError
        When ``data`` holds a NaN or an infinity.
    """
    check_finite(data)
    print(json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False))


def title_lines(mechanism, suffix: str = "") -> list[str]:
    """The first lines of a text answer: the mechanism's name and file, then a blank line."""
    return [f"{mechanism.name or 'mechanism'}  ({mechanism.source}){suffix}", ""]


def write_lines(lines: Iterable[str]) -> None:
    """Write the lines of a text answer to stdout, each ended by a newline."""
    sys.stdout.write("\n".join(lines) + "\n")


def fail(message: str, code: int = EXIT_MECHANISM) -> int:
    """Write ``error: message`` to stderr and give back the exit ``code``.

    Each line of the message is cut at 1000 characters.
    """
    if len(message) > _MESSAGE_WIDTH:
        message = "\n".join(clipped(line, _MESSAGE_WIDTH) for line in message.split("\n"))
    sys.stderr.write(f"error: {message}\n")
    return code


def failed(exc: MechanismError, as_json: bool) -> int:
    """Report a mechanism error (JSON on stdout when asked, text on stderr); exit code 1."""
    if as_json:
        print_json({"error": str(exc)})
    return fail(str(exc))


def vector(value: object) -> str:
    """A 2-D vector as ``(x, y)``, six significant digits each.

    >>> vector((1.0, -0.25))
    '(1, -0.25)'
    """
    x, y = value  # type: ignore[misc]
    return f"({x:.6g}, {y:.6g})"
