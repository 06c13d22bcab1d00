"""Reading a file the user names: regular files only, under a size limit, errors named.

Every reader of a user file (the edge list, JSON, pyslvs, pylinkage, the
``--inputs`` poses, a report's input, the rows an atlas resumes from, the
files of a batch) opens it through :func:`open_user_file` or :func:`read_text`,
so that

* a missing file, a directory, a file that is not UTF-8 get the same one-line
  :class:`~structure.errors.EdgeListError` (never an ``OSError`` or a
  ``UnicodeDecodeError``);
* only a regular file is read: a FIFO (which would wait for a writer for ever),
  a device (``/dev/zero`` never ends), a socket is refused before it is read,
  a symbolic link judged by what it points to;
* a file larger than ``max_bytes`` (:data:`MAX_FILE_BYTES` unless raised:
  ``--max-file-size`` on the command line) is refused by its size, before it is
  read, with the limit and the option in the message.

:func:`file_problem` gives the same verdict as text without raising (a batch
lists a skipped entry with it and goes on).

A new reader (a CSV of targets, ...) reads through :func:`read_text`, or
:func:`open_user_file` to stream lines, and takes ``max_bytes`` from its caller.

>>> read_text("no/such/file.edges")
Traceback (most recent call last):
...
structure.errors.EdgeListError: no/such/file.edges: cannot read: No such file or directory
>>> file_problem("/dev/null")
'not a regular file (a character device): assur reads regular files only'
"""

from __future__ import annotations

import io
import os
import stat
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import IO

from ..errors import EdgeListError, EdgeListProblem
from ..limits import memory_text

__all__ = [
    "MAX_FILE_BYTES",
    "MAX_FILE_OPTION",
    "file_problem",
    "open_user_file",
    "opened",
    "read_text",
    "readable_bytes",
]

#: the largest file read unless the caller raises the limit (bytes): a 10^6-line edge list is
#: about 26 MB and takes about 1 GB to analyse, so the default keeps a run near that
MAX_FILE_BYTES = 32_000_000

#: the most bytes read at a time (a file is read in pieces, never more than it holds)
_CHUNK = 1 << 22

#: the command-line option that raises the limit, named in the message of a file too large
MAX_FILE_OPTION = "--max-file-size"

_KINDS = (
    (stat.S_ISDIR, "a directory"),
    (stat.S_ISFIFO, "a FIFO"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


def readable_bytes(max_bytes: int) -> int:
    """``max_bytes`` as a count one read can take (a larger limit is no limit: the most).

    >>> readable_bytes(10**30) == sys.maxsize - 1
    True
    """
    return max(0, min(int(max_bytes), sys.maxsize - 1))


def _kind_problem(mode: int) -> str | None:
    """Why a file of ``mode`` is not read, or None for a regular file."""
    if stat.S_ISREG(mode):
        return None
    kind = next((name for test, name in _KINDS if test(mode)), "a special file")
    if kind == "a directory":
        return "cannot read: Is a directory"
    return f"not a regular file ({kind}): assur reads regular files only"


def _size_problem(size: int, max_bytes: int) -> str | None:
    """Why a file of ``size`` bytes is not read, or None."""
    if size <= max_bytes:
        return None
    return (
        f"the file is {memory_text(size)}, more than the {memory_text(max_bytes)} assur reads "
        f"(raise the limit with {MAX_FILE_OPTION}, or max_bytes= in Python)"
    )


def file_problem(path: str | os.PathLike[str], max_bytes: int = MAX_FILE_BYTES) -> str | None:
    """Why ``path`` would not be read (missing, not a regular file, too large), or None.

    The file is not opened: a FIFO or a device is judged by :func:`os.stat` alone.
    """
    try:
        info = os.stat(path)
    except OSError as exc:
        return f"cannot read: {exc.strerror or exc}"
    except ValueError as exc:  # a NUL in the name
        return f"cannot read: {exc}"
    return _kind_problem(info.st_mode) or _size_problem(info.st_size, max_bytes)


def _refused(path: str | os.PathLike[str], reason: str) -> EdgeListError:
    return EdgeListError(str(path), [EdgeListProblem(0, "", reason)])


@contextmanager
def opened(path: str | os.PathLike[str]) -> Iterator[None]:
    """Turn an OSError or a UnicodeDecodeError raised inside into an EdgeListError on ``path``."""
    try:
        yield
    except OSError as exc:
        raise _refused(path, f"cannot read: {exc.strerror or exc}") from exc
    except UnicodeDecodeError as exc:
        raise _refused(path, "not a UTF-8 text file") from exc


@contextmanager
def open_user_file(
    path: str | os.PathLike[str], max_bytes: int = MAX_FILE_BYTES, *, binary: bool = False
) -> Iterator[IO]:
    """A regular file of at most ``max_bytes``, open for reading (UTF-8 text, a BOM dropped).

    The file is checked by its name first (a FIFO is never opened), then opened
    without blocking and checked again by its descriptor (it may have been
    replaced in between). Errors while reading inside the ``with`` are named too
    (:func:`opened`). A regular file that grows while it is read is not cut.

    Raises
    ------
    EdgeListError
        The file is missing, no regular file, larger than ``max_bytes``, or not UTF-8.
    """
    problem = file_problem(path, max_bytes)
    if problem is not None:
        raise _refused(path, problem)
    with opened(path):
        flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
        descriptor = os.open(path, flags)
        try:
            info = os.fstat(descriptor)
            problem = _kind_problem(info.st_mode) or _size_problem(info.st_size, max_bytes)
        except OSError:
            os.close(descriptor)
            raise
        if problem is not None:
            os.close(descriptor)
            raise _refused(path, problem)
        raw = os.fdopen(descriptor, "rb")
        handle: IO = raw if binary else io.TextIOWrapper(raw, encoding="utf-8-sig")
        with handle:
            yield handle


def read_text(path: str | os.PathLike[str], max_bytes: int = MAX_FILE_BYTES) -> str:
    """The text of a UTF-8 file (a byte-order mark dropped), or an EdgeListError saying why not.

    At most ``max_bytes`` are read, even from a file that grows meanwhile.
    """
    max_bytes = readable_bytes(max_bytes)
    chunks: list[bytes] = []
    total = 0
    with open_user_file(path, max_bytes, binary=True) as handle:
        while total <= max_bytes and (chunk := handle.read(min(_CHUNK, max_bytes + 1 - total))):
            chunks.append(chunk)
            total += len(chunk)
    data = b"".join(chunks)
    problem = _size_problem(len(data), max_bytes)
    if problem is not None:
        raise _refused(path, problem)
    with opened(path):
        return data.decode("utf-8-sig")
