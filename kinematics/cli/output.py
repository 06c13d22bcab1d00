r"""What every command prints and writes: JSON, text, warnings, the error line and its exit code.

Exit codes: :data:`EXIT_OK` (0), :data:`EXIT_MECHANISM` (1, a bad file or an impossible
mechanism), :data:`EXIT_USAGE` (2, a usage error), :data:`EXIT_BUG` (3, a bug in assur).
No NaN or infinity is ever printed: :func:`~structure.validation.check_finite` refuses a
result that holds one, and JSON is written with ``allow_nan=False`` (a strict parser reads it).

The helpers every command (and every new one) uses:

* **printing**: :func:`write_lines`, :func:`write_stdout`, :func:`print_json`,
  :func:`warn`, :func:`fail` pass what they print through :func:`printable`, so that
  a control character or a terminal escape sequence in a name (of the mechanism, a
  link, a point, a file) is shown escaped (``\x1b``), never sent to the terminal;
  :func:`escaped` wraps a stream for output written piece by piece (a table on stdout);
* **outputs**: :func:`check_outputs` refuses an output file that is one of the
  command's inputs, or two outputs that are one file (same resolved path or same
  inode), before any work; the file itself is written whole or not at all through
  :mod:`structure.readwrite.atomic` (``atomic_file``, ``atomic_path``, ``write_text``);
* **sizes**: :func:`structure.limits.check_size` bounds an option that sets a size by the
  memory it would take; :func:`input_limit` is the ``--max-file-size`` of a command.

>>> check_finite({"reactions": [{"force": [1.0, float("nan")]}]})
Traceback (most recent call last):
...
structure.errors.NotFiniteError: reactions[0].force[1] is not finite: the result ov...
>>> print(printable("crank\x1b[2J"))
crank\x1b[2J
"""

from __future__ import annotations

import argparse
import json
import os
import re
import stat
import sys
from collections.abc import Iterable, Mapping
from typing import IO

from structure.errors import MechanismError, UsageError, clipped
from structure.readwrite.textfile import MAX_FILE_BYTES
from structure.validation import check_finite

__all__ = [
    "EXIT_BUG",
    "EXIT_MECHANISM",
    "EXIT_OK",
    "EXIT_USAGE",
    "check_finite",
    "check_outputs",
    "escaped",
    "fail",
    "failed",
    "input_limit",
    "note",
    "print_json",
    "printable",
    "title_lines",
    "vector",
    "warn",
    "write_lines",
    "write_stdout",
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


# ------------------------------------------------------------------ what reaches the terminal
#: characters never printed as they are: the C0 controls but the newline, DEL, the C1
#: controls (U+009B is an escape sequence's start on some terminals), the marks and
#: overrides that reorder text on screen, the line and paragraph separators
_UNPRINTABLE = re.compile(
    "[\x00-\x09\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028-\u202e\u2066-\u2069]"
)


_SHORT = {"\t": "\\t", "\r": "\\r"}


def _text_escape(found: re.Match[str]) -> str:
    char = found.group()
    code = ord(char)
    return _SHORT.get(char) or (f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}")


def _json_escape(found: re.Match[str]) -> str:
    return f"\\u{ord(found.group()):04x}"


def printable(text: str, *, json_text: bool = False) -> str:
    r"""``text`` with its control characters escaped, for a terminal.

    Text gets Python's escapes (``\x1b``, ``\t``, ``\u202e``); the newline is kept.
    ``json_text`` is for JSON text (whose strings :func:`json.dumps` has escaped
    below U+0020 already): the rest become JSON escapes (``\u009b``), so the
    JSON still reads back to the same strings.

    >>> print(printable("a\tb\u202ec\x1b[0m"))
    a\tb\u202ec\x1b[0m
    >>> print(printable('"\x9b"', json_text=True))
    "\u009b"
    """
    if _UNPRINTABLE.search(text) is None:
        return text
    return _UNPRINTABLE.sub(_json_escape if json_text else _text_escape, text)


class _Escaped:
    """A text stream that writes :func:`printable` text to another."""

    def __init__(self, stream: IO[str], json_text: bool) -> None:
        self._stream = stream
        self._json = json_text

    def write(self, text: str) -> int:
        self._stream.write(printable(text, json_text=self._json))
        return len(text)

    def __getattr__(self, name: str) -> object:  # flush, fileno, isatty, ...
        return getattr(self._stream, name)


def escaped(stream: IO[str], *, json_text: bool = False) -> IO[str]:
    """``stream`` with everything written to it made :func:`printable` (JSON text or not).

    For output written piece by piece to stdout (a table, a streamed JSON answer);
    a file the user asked for (``--output``) is written as it is.
    """
    return _Escaped(stream, json_text)  # type: ignore[return-value]


def print_json(data: object) -> None:
    """Print ``data`` as one indented JSON object (UTF-8 kept as is), never NaN or infinity.

    Raises
    ------
    NotFiniteError
        When ``data`` holds a NaN or an infinity.
    """
    check_finite(data)
    text = json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False)
    sys.stdout.write(printable(text, json_text=True) + "\n")


def title_lines(mechanism, suffix: str = "") -> list[str]:
    """The first lines of a text answer: the mechanism's name and file, then a blank line."""
    return [f"{mechanism.name or 'mechanism'}  ({mechanism.source}){suffix}", ""]


def write_stdout(text: str) -> None:
    """Write a text answer to stdout as it is, but :func:`printable`."""
    sys.stdout.write(printable(text))


def write_lines(lines: Iterable[str]) -> None:
    """Write the lines of a text answer to stdout, each ended by a newline."""
    write_stdout("\n".join(lines) + "\n")


def _clipped_lines(message: str) -> str:
    if len(message) <= _MESSAGE_WIDTH:
        return message
    return "\n".join(clipped(line, _MESSAGE_WIDTH) for line in message.split("\n"))


def warn(message: str) -> None:
    """Write ``warning: message`` to stderr (what an answer or an export leaves out, ...)."""
    sys.stderr.write(printable(f"warning: {_clipped_lines(message)}") + "\n")


def note(message: str) -> None:
    """Write ``note: message`` to stderr (what an answer approximates, ...)."""
    sys.stderr.write(printable(f"note: {_clipped_lines(message)}") + "\n")


def fail(message: str, code: int = EXIT_MECHANISM) -> int:
    """Write ``error: message`` to stderr and give back the exit ``code``.

    Each line of the message is cut at 1000 characters.
    """
    sys.stderr.write(printable(f"error: {_clipped_lines(message)}") + "\n")
    return code


def failed(exc: MechanismError, as_json: bool) -> int:
    """Report a mechanism error (JSON on stdout when asked, text on stderr); exit code 1."""
    if as_json:
        print_json({"error": str(exc)})
    return fail(str(exc))


# ------------------------------------------------------------------ files read and written
def input_limit(args: argparse.Namespace) -> int:
    """The most bytes a command reads of a file: its ``--max-file-size``, or the default."""
    return getattr(args, "max_file_size", None) or MAX_FILE_BYTES


def _identities(path: str) -> set[object]:
    """What names the file ``path`` is: its resolved path, and its device and inode if it is
    there; nothing for a device or a FIFO (``/dev/null`` may be written by two outputs)."""
    try:
        info = os.stat(path)
    except (OSError, ValueError):
        return {os.path.realpath(path)}
    if not stat.S_ISREG(info.st_mode):
        return set()
    return {os.path.realpath(path), (info.st_dev, info.st_ino)}


def check_outputs(reads: Iterable[str | None], writes: Mapping[str, str | None]) -> None:
    """Refuse, before any work, an output that is a file the command reads, or two outputs
    that are one file.

    ``reads`` are the files the command reads (``None`` for an option not given);
    ``writes`` maps each output's option (``"-o"``, ``"--csv"``, ``"OUT"``) to its path.
    Two names are one file when they resolve to the same path, or are the same
    inode (a hard link, a link through another directory). A device or a FIFO
    (``/dev/null``) is never refused. A new command calls this with its own
    options as soon as they are parsed.

    Raises
    ------
    UsageError
        Naming the option, the file and what to do (exit code 2).

    >>> check_outputs(["fixtures/fourbar.edges"], {"OUT": "./fixtures/../fixtures/fourbar.edges"})
    Traceback (most recent call last):
    ...
    structure.errors.UsageError: OUT ./fixtures/../fixtures/fourbar.edges is fixtures/fourbar...
    """
    inputs = [(path, _identities(path)) for path in reads if path]
    seen: list[tuple[str, str, set[object]]] = []
    for option, path in writes.items():
        if not path:
            continue
        names = _identities(path)
        for source, known in inputs:
            if names & known:
                raise UsageError(
                    f"{option} {path} is {source}, a file this command reads: assur never "
                    "writes over its input; give the output another name"
                )
        for other, other_path, known in seen:
            if names & known:
                raise UsageError(
                    f"{other} {other_path} and {option} {path} are the same file: "
                    "give each output its own name"
                )
        seen.append((option, path, names))


# ------------------------------------------------------------------ numbers
def vector(value: object) -> str:
    """A 2-D vector as ``(x, y)``, six significant digits each.

    >>> vector((1.0, -0.25))
    '(1, -0.25)'
    """
    x, y = value  # type: ignore[misc]
    return f"({x:.6g}, {y:.6g})"
