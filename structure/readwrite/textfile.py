"""Reading a mechanism file's text: what cannot be read is a named error, never an OSError.

Every reader of the project opens its files through :func:`opened` or
:func:`read_text`, so a missing file, a directory or a file that is not UTF-8
gets the same one-line :class:`~structure.errors.EdgeListError`.

>>> read_text("no/such/file.edges")
Traceback (most recent call last):
...
structure.errors.EdgeListError: no/such/file.edges: cannot read: No such file or directory
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from ..errors import EdgeListError, EdgeListProblem

__all__ = ["opened", "read_text"]


@contextmanager
def opened(path: str | os.PathLike[str]) -> Iterator[None]:
    """Turn an OSError or a UnicodeDecodeError raised inside into an EdgeListError on ``path``."""
    try:
        yield
    except OSError as exc:
        raise EdgeListError(
            str(path), [EdgeListProblem(0, "", f"cannot read: {exc.strerror}")]
        ) from exc
    except UnicodeDecodeError as exc:
        raise EdgeListError(str(path), [EdgeListProblem(0, "", "not a UTF-8 text file")]) from exc


def read_text(path: str | os.PathLike[str]) -> str:
    """The text of a UTF-8 file (a byte-order mark dropped), or an EdgeListError saying why not."""
    with opened(path):
        return Path(path).read_text(encoding="utf-8-sig")
