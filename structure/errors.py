"""The exception tree of the structural analyzer.

Every error the library raises on bad input or an impossible mechanism derives
from :class:`MechanismError`; the command line catches exactly that class and
prints its message without a traceback.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

__all__ = [
    "DecompositionError",
    "EdgeListError",
    "EdgeListProblem",
    "MechanismError",
    "MobilityError",
    "StatementError",
]


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
            return f"line {self.line_no}: {self.reason}: {self.line.strip()!r}"
        return self.reason


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


class StatementError(MechanismError, ValueError):
    """One statement (a pair, a point, a load, a driver) that cannot be built.

    ``reason`` says what is wrong, without saying where: the reader that
    made the statement files it under its line (or JSON path) as an
    :class:`EdgeListProblem`.
    """

    def __init__(self, reason: str):
        self.reason = reason
        super().__init__(reason)


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
