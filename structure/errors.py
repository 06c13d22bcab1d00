"""The exception tree of the structural analyzer.

Every error the library raises on bad input or an impossible mechanism derives
from :class:`MechanismError`; the command line catches exactly that class and
prints its message without a traceback.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

__all__ = [
    "QUOTE_WIDTH",
    "REASON_WIDTH",
    "CamProgramError",
    "DecompositionError",
    "EdgeListError",
    "EdgeListProblem",
    "MechanismError",
    "MobilityError",
    "NotFiniteError",
    "NumberError",
    "SizeError",
    "StatementError",
    "UsageError",
    "clipped",
]

#: a message quotes at most this many characters of a line or a value the user wrote
QUOTE_WIDTH = 80
#: a reason is cut at this many characters (it may quote a token of the line)
REASON_WIDTH = 400


def clipped(text: str, width: int = QUOTE_WIDTH) -> str:
    """``text`` cut to its first ``width`` characters and ``…`` when longer (for messages)."""
    return text if len(text) <= width else text[:width] + "…"


class MechanismError(Exception):
    """Base class of every error about a mechanism or its description."""


@dataclass(frozen=True, slots=True)
class EdgeListProblem:
    """One problem found in a mechanism description.

    ``line_no`` is 1-based; 0 means the problem belongs to the whole file.
    """

    line_no: int
    line: str
    reason: str

    def __str__(self) -> str:
        if self.line_no:
            return f"line {self.line_no}: {self.reason_text}: {clipped(self.line.strip())!r}"
        return self.reason_text

    @property
    def reason_text(self) -> str:
        """The reason as printed: cut at :data:`REASON_WIDTH` (it may quote a long token)."""
        return clipped(self.reason, REASON_WIDTH)


class EdgeListError(MechanismError, ValueError):
    """A mechanism description that cannot be read.

    All problems of a file are gathered and raised once; ``problems`` holds
    them in file order, ``source`` names the file (or ``<string>``).
    The first problem is also available as ``line_no``, ``line`` and ``reason``.
    """

    #: at most this many problems are spelled out in the message
    MAX_SHOWN = 20

    def __init__(self, source: str, problems: Sequence[EdgeListProblem]):
        if not problems:
            raise ValueError("EdgeListError needs at least one problem")
        self.source = source
        self.problems = tuple(problems)
        first = self.problems[0]
        self.line_no, self.line, self.reason = first.line_no, first.line, first.reason
        super().__init__(str(self))

    def __str__(self) -> str:
        shown = [f"{self.source}: {p}" for p in self.problems[: self.MAX_SHOWN]]
        hidden = len(self.problems) - len(shown)
        if hidden:
            shown.append(f"{self.source}: ... and {hidden} more problems")
        return "\n".join(shown)


class CamProgramError(EdgeListError):
    """A cam design that cannot be read: its spec or its follower program is wrong.

    The segments do not add up to 360°, the program does not bring the
    follower home, a law is unknown, a polynomial's conditions do not fix it,
    a value is out of its range; each problem under its JSON path, saying what
    to change (see :mod:`structure.cams`).
    """


class StatementError(MechanismError, ValueError):
    """One statement (a pair, a point, a load, a driver) that cannot be built.

    ``reason`` says what is wrong, without saying where: the reader that
    made the statement files it under its line (or JSON path) as an
    :class:`EdgeListProblem`.
    """

    def __init__(self, reason: str):
        self.reason = reason
        super().__init__(reason)


class NumberError(StatementError):
    """A number or exact expression that cannot be read, or is beyond the limits assur takes.

    Raised for bad syntax, nesting deeper than the parser allows, numbers with
    too many digits or too large an exponent, non-finite values and values
    beyond the largest magnitude (see :mod:`structure.expressions` and
    :mod:`structure.validation`). It is a ``ValueError`` too.
    """


class UsageError(MechanismError):
    """An option value the command line cannot take (exit status 2, not 1)."""


class SizeError(MechanismError):
    """A size asked for (poses, frames, links, processes, a file) would take more memory than
    assur may take; the message names the memory and the largest size that fits
    (:func:`structure.limits.check_size`)."""


class NotFiniteError(MechanismError):
    """A computed result is not finite: the input values are too large for floating point.

    Raised instead of printing or writing NaN or infinity.
    """


class MobilityError(MechanismError):
    """The mobility does not allow the requested analysis.

    Raised for W <= 0 or W different from the number of drivers, or a driver
    whose motion is already fixed by the other pairs. ``mobility`` holds the
    :class:`~structure.mobility.Mobility` record that was computed, so a
    caller can still print the counts.
    """

    def __init__(self, message: str, mobility: object | None = None):
        self.mobility = mobility
        super().__init__(message)


class DecompositionError(MechanismError):
    """The links could not be split into Assur groups.

    ``links`` holds the links that were left unassigned.
    """

    def __init__(self, message: str, links: Sequence[str] = ()):
        self.links = tuple(links)
        super().__init__(message)
