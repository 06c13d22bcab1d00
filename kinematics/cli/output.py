"""What every command prints: JSON, the title lines, vectors, the error line and its exit code.

Exit codes: :data:`EXIT_OK` (0), :data:`EXIT_MECHANISM` (1, a bad file or an impossible
mechanism), :data:`EXIT_USAGE` (2, a usage error).
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable

from structure.errors import MechanismError

__all__ = [
    "EXIT_MECHANISM",
    "EXIT_OK",
    "EXIT_USAGE",
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


def print_json(data: object) -> None:
    """Print ``data`` as one indented JSON object (UTF-8 kept as is)."""
    print(json.dumps(data, indent=2, ensure_ascii=False))


def title_lines(mechanism, suffix: str = "") -> list[str]:
    """The first lines of a text answer: the mechanism's name and file, then a blank line."""
    return [f"{mechanism.name or 'mechanism'}  ({mechanism.source}){suffix}", ""]


def write_lines(lines: Iterable[str]) -> None:
    """Write the lines of a text answer to stdout, each ended by a newline."""
    sys.stdout.write("\n".join(lines) + "\n")


def fail(message: str, code: int = EXIT_MECHANISM) -> int:
    """Write ``error: message`` to stderr and give back the exit ``code``."""
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
