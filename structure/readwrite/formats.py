"""Read or write a mechanism in the format its file name says (and, where two share one, its text).

Reading, by extension:

* ``.json``: our JSON form, or pylinkage's JSON (a mechanism or linkage: an
  object with a list of ``joints``);
* ``.pyslvs``: a Pyslvs-UI project (YAML with the expression under
  ``mechanism``), or a bare pyslvs expression ``M[...]``;
* any other (``.edges``, ``.txt``, none): a pyslvs expression when the text
  starts with ``M[`` (after comments), else the edge list.

Writing, by extension: ``.edges`` the edge list, ``.json`` our JSON form,
``.pyslvs`` a Pyslvs-UI project. Edge list and JSON round-trip losslessly;
:func:`mechanism_left_out` says, a line per kind, what another format leaves out
(a pyslvs project has no loads, ...). A file is written whole or not at all
(:mod:`structure.readwrite.atomic`).

>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> (folder / "arm.txt").write_text("M[J[R, P[0, 0], L[ground, L1]], J[R, P[1, 0], L[L1]]]")
53
>>> m = read_mechanism(folder / "arm.txt")
>>> print(mechanism_text(m, ".edges"), end="")
name arm
ground ground
ground L1 R J0
point J0 0 0
point J1 1 0 on=L1
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from ..errors import MechanismError
from ..model import Mechanism
from ..utils import paused_gc
from ..validation import as_title
from .atomic import write_text
from .edgelist import parse_edgelist, write_edgelist
from .jsonformat import decode_json, mechanism_from_dict, mechanism_to_json
from .pylinkage import is_pylinkage, mechanism_from_pylinkage
from .pyslvs import looks_like_expression, parse_pyslvs, pyslvs_left_out, pyslvs_project
from .textfile import MAX_FILE_BYTES, read_text

__all__ = [
    "READ_SUFFIXES",
    "WRITE_SUFFIXES",
    "mechanism_left_out",
    "mechanism_text",
    "parse_mechanism",
    "read_mechanism",
    "write_mechanism",
]


def _json(text: str, source: str, name: str) -> Mechanism:
    data = decode_json(text, source)
    if is_pylinkage(data):
        mechanism = mechanism_from_pylinkage(data, source)
        return mechanism if mechanism.name else mechanism.evolve(name=name)
    return mechanism_from_dict(data, source)


def _pyslvs(text: str, source: str, name: str) -> Mechanism:
    return parse_pyslvs(text, source, name)


def _text(text: str, source: str, name: str) -> Mechanism:
    if looks_like_expression(text):
        return parse_pyslvs(text, source, name)
    with paused_gc():
        return parse_edgelist(text.splitlines(), source)


_READERS: dict[str, Callable[[str, str, str], Mechanism]] = {
    ".json": _json,
    ".pyslvs": _pyslvs,
}

#: extensions read by their own reader; any other is an edge list or a pyslvs expression
READ_SUFFIXES = (".edges", *_READERS)

_WRITERS: dict[str, Callable[[Mechanism], str]] = {
    ".edges": write_edgelist,
    ".json": lambda mechanism: mechanism_to_json(mechanism) + "\n",
    ".pyslvs": pyslvs_project,
}

#: extensions :func:`write_mechanism` writes
WRITE_SUFFIXES = tuple(_WRITERS)

#: what each format that cannot hold everything leaves out (the others hold it all)
_LEFT_OUT: dict[str, Callable[[Mechanism], tuple[str, ...]]] = {".pyslvs": pyslvs_left_out}


def parse_mechanism(text: str, suffix: str = ".edges", source: str = "<string>") -> Mechanism:
    """Parse ``text`` as the format of a file ending in ``suffix`` (see the module).

    Raises
    ------
    EdgeListError
        On any problem in the text.
    """
    name = as_title(Path(source).stem) if source and not source.startswith("<") else ""
    return _READERS.get(suffix.lower(), _text)(text, source, name)


def read_mechanism(path: str | os.PathLike[str], max_bytes: int = MAX_FILE_BYTES) -> Mechanism:
    """Read a mechanism file (UTF-8) in the format its extension and text say.

    A pyslvs expression, which has no title, is named after the file. Only a
    regular file of at most ``max_bytes`` is read (:func:`~.textfile.read_text`).

    Raises
    ------
    EdgeListError
        On any problem in the file, or when it cannot be read.
    """
    path = Path(path)
    text = read_text(path, max_bytes)
    return parse_mechanism(text, path.suffix, str(path))


def mechanism_text(mechanism: Mechanism, suffix: str) -> str:
    """The text of ``mechanism`` in the format of extension ``suffix``.

    Raises
    ------
    MechanismError
        An extension with no mechanism writer.
    EdgeListError
        A mechanism the format cannot hold (a cam in pyslvs, ...).
    """
    writer = _WRITERS.get(suffix.lower())
    if writer is None:
        raise MechanismError(
            f"no mechanism format has the extension {suffix or '(none)'!r}: "
            f"use {', '.join(WRITE_SUFFIXES)}"
        )
    return writer(mechanism)


def mechanism_left_out(mechanism: Mechanism, suffix: str) -> tuple[str, ...]:
    """What a file of extension ``suffix`` leaves out of ``mechanism``, a line per kind.

    Empty for the edge list and the JSON form, which hold everything.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["0 1 R A", "point A 0 0", "moment 1 5"])
    >>> mechanism_left_out(m, ".json"), mechanism_left_out(m, ".pyslvs")[0]
    ((), 'pyslvs projects hold no loads: 1 moment statement left out')
    """
    lines = _LEFT_OUT.get(suffix.lower())
    return () if lines is None else lines(mechanism)


def write_mechanism(mechanism: Mechanism, path: str | os.PathLike[str]) -> Path:
    """Write ``mechanism`` to ``path`` in the format of its extension (UTF-8), whole or not at all.

    What the format leaves out is not said here: ask :func:`mechanism_left_out`.

    Raises
    ------
    MechanismError
        An unknown extension, or the file cannot be written.
    EdgeListError
        A mechanism the format cannot hold.
    """
    path = Path(path)
    return write_text(path, mechanism_text(mechanism, path.suffix))
