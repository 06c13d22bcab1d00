"""What a format cannot hold of a mechanism, said in words: an export never drops data silently.

Each format that cannot hold everything declares what it keeps in a :class:`Holds`;
:func:`left_out` compares a mechanism with it and gives one line per kind of thing
that the file will not carry, with how many and which (the command line prints
each as a warning on stderr). The edge list and the JSON form hold everything
(their round trip is lossless) and need none.

A new writer (another CAD format, a report) declares its :class:`Holds` next to
it and calls :func:`left_out`; a writer that renames (pyslvs: links as
identifiers, joints as ``J<i>``) passes its renames.

>>> from structure import parse_edgelist
>>> m = parse_edgelist(["name arm", "driver 1 omega=10", "0 1 R A", "point A 0 0",
...                     "force 1 A 0 -10", "mass 1 2 0.1 A"])
>>> for line in left_out(m, Holds("pyslvs projects", title=False, loads=False, motion=False)):
...     print(line)
pyslvs projects have no title: the name 'arm' left out
pyslvs projects hold no loads: 1 force and 1 mass statements left out
pyslvs projects hold no driver motion: omega of driver 1 left out
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from ..errors import clipped
from ..model import Mechanism

__all__ = ["Holds", "left_out", "renames"]

#: what each pair option is, in the messages
_OPTION_WORDS = {
    "angle": "slide angles",
    "flat": "flat faces",
    "roller": "rollers",
    "centers": "centres of curvature",
    "normal": "contact normals",
    "span": "slide spans",
    "friction": "friction coefficients",
    "circle": "friction circles",
    "z": "tooth numbers",
    "internal": "internal gears",
    "module": "gear modules",
}

#: a list of names in a message: at most this many, then "..."
_NAMES_SHOWN = 6


@dataclass(frozen=True, slots=True)
class Holds:
    """What a format keeps of a mechanism (everything, unless said otherwise).

    ``format`` names the format in the messages, as a plural ("pyslvs
    projects"); ``options`` are the pair options it keeps (None: all);
    ``exact`` whether it keeps exact expressions (``0.2*sqrt(3)``) as written;
    ``free_points`` whether it keeps points that are neither a pair's nor a
    marker on a link (a centre of curvature, a spare point of the frame).
    """

    format: str
    title: bool = True
    loads: bool = True
    motion: bool = True
    options: frozenset[str] | None = None
    exact: bool = True
    free_points: bool = True


def _names(names: Iterable[str]) -> str:
    listed = list(dict.fromkeys(names))
    shown = ", ".join(clipped(name, 40) for name in listed[:_NAMES_SHOWN])
    return shown + (", ..." if len(listed) > _NAMES_SHOWN else "")


def _counted(counts: Mapping[str, int], noun: str) -> str:
    """``{"force": 2, "mass": 1}`` as ``2 force and 1 mass statements`` (``noun`` singular).

    >>> _counted({"moment": 1}, "statement"), _counted({"force": 2, "mass": 1}, "statement")
    ('1 moment statement', '2 force and 1 mass statements')
    """
    parts = [f"{n} {word}" for word, n in counts.items()]
    joined = parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]
    return f"{joined} {noun}{'s' if sum(counts.values()) > 1 else ''}"


def _pair_options(mechanism: Mechanism) -> dict[str, list[str]]:
    """Each pair option given in ``mechanism``, with the labels of the pairs that have it."""
    found: dict[str, list[str]] = {}
    for p in mechanism.pairs_with_options():
        given = {
            "angle": p.angle_deg,
            "flat": p.flat,
            "roller": p.roller,
            "centers": p.centers,
            "normal": p.normal_deg,
            "span": p.span,
            "friction": p.friction,
            "circle": p.circle,
            "z": p.teeth,
            "internal": p.internal,
            "module": p.module,
        }
        for key, value in given.items():
            if value is not None:
                found.setdefault(key, []).append(p.label)
    return found


def _free_points(mechanism: Mechanism) -> list[str]:
    """Points that are neither a pair's point nor a marker on a link."""
    used = {p.point for p in mechanism.pairs if p.point is not None}
    return [
        name for name, point in mechanism.points.items() if point.on is None and name not in used
    ]


def left_out(
    mechanism: Mechanism, holds: Holds, renamed: Mapping[str, str] | None = None
) -> tuple[str, ...]:
    """One line for each kind of thing of ``mechanism`` that a file of ``holds`` leaves out.

    ``renamed`` maps names the writer changes (links, points) to their new names;
    they are said too, in one line. Empty when the file keeps everything.
    """
    fmt = holds.format
    out: list[str] = []
    if not holds.title and mechanism.name:
        out.append(f"{fmt} have no title: the name {clipped(mechanism.name)!r} left out")
    if not holds.loads and mechanism.loads:
        counts = Counter(load.kind.value for load in mechanism.loads)
        out.append(f"{fmt} hold no loads: {_counted(counts, 'statement')} left out")
    if not holds.motion:
        moving = [(d.link, [key for key, _ in d.motion]) for d in mechanism.drivers if d.motion]
        if moving:
            keys = _names(key for _, keys in moving for key in keys)
            which = _names(link for link, _ in moving)
            plural = "s" if len(moving) > 1 else ""
            out.append(f"{fmt} hold no driver motion: {keys} of driver{plural} {which} left out")
    if holds.options is not None:
        for key, pairs in _pair_options(mechanism).items():
            if key not in holds.options:
                plural = "s" if len(pairs) > 1 else ""
                what = _OPTION_WORDS.get(key, f"{key}= options")
                out.append(f"{fmt} hold no {what}: {key}= of pair{plural} {_names(pairs)} left out")
    if not holds.exact:
        exact = [
            text for point in mechanism.points.values() for text in point.exact if text is not None
        ] + [text for load in mechanism.loads for text in load.exact if text]
        if exact:
            out.append(
                f"{fmt} hold decimals only: {len(exact)} exact value(s) ({_names(exact)}) "
                "written as decimals"
            )
    if not holds.free_points:
        free = _free_points(mechanism)
        if free:
            plural = "s" if len(free) > 1 else ""
            out.append(f"{fmt} hold joints only: point{plural} {_names(free)} left out")
    out.extend(renames(fmt, renamed or {}))
    return tuple(out)


def renames(fmt: str, renamed: Mapping[str, str]) -> tuple[str, ...]:
    """The line saying which names a writer of ``fmt`` changes, or none.

    >>> renames("pyslvs projects", {"link 1": "L1", "point A": "J0"})
    ('pyslvs projects name things their own way: link 1 → L1, point A → J0',)
    """
    changed = [f"{old} → {new}" for old, new in renamed.items() if old != new]
    if not changed:
        return ()
    return (f"{fmt} name things their own way: {_names(changed)}",)
