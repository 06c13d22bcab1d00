"""Writing a file whole or not at all: a temporary file in the same directory, renamed over it.

Every file assur writes (a mechanism, a table, a drawing, a page, an animation)
goes through :func:`atomic_file` (a handle to write to) or :func:`atomic_path`
(a path for a writer that opens the file itself: matplotlib, ezdxf, pyarrow,
Pillow). The temporary file sits in the target's directory, hidden, with the
target's extension (writers that choose the format by it still do); when the
block ends without an error it is flushed to disk and renamed over the target in
one step, so a crash, an interrupt or a full disk leaves the old file or none,
never half a file. On an error it is removed.

The target keeps its permissions when it exists, and a new one gets the usual
ones (``0o666`` less the umask). A symbolic link is written through (the file
it points to is replaced). A target that exists and is no regular file
(``/dev/null``, ``/dev/stdout``, a FIFO) is written directly: it cannot be
replaced, and a half write there leaves no file behind.

An ``OSError`` while writing becomes a :class:`~structure.errors.MechanismError`
``cannot write PATH: REASON`` (the command line's exit code 1).

>>> import tempfile, pathlib
>>> target = pathlib.Path(tempfile.mkdtemp()) / "m.edges"
>>> with atomic_file(target) as handle:
...     _ = handle.write("0 1 R A\\n")
>>> target.read_text(), sorted(p.name for p in target.parent.iterdir())
('0 1 R A\\n', ['m.edges'])
"""

from __future__ import annotations

import os
import stat
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import IO

from ..errors import MechanismError

__all__ = ["atomic_file", "atomic_path", "partial_path", "write_text"]


def _target(path: str | os.PathLike[str]) -> Path:
    """The file that will be replaced: ``path``, or what it points to when it is a link."""
    path = Path(path)
    return Path(os.path.realpath(path)) if path.is_symlink() else path


def _special(path: Path) -> bool:
    """``path`` exists and is no regular file (a device, a FIFO): written in place."""
    try:
        return not stat.S_ISREG(os.stat(path).st_mode)
    except OSError:
        return False


def partial_path(path: str | os.PathLike[str]) -> Path:
    """The fixed name a long run writes before it is complete: ``OUT.partial`` beside ``OUT``.

    :func:`atomic_file` with ``partial=True`` writes there, so that a run that
    stops can be continued from it (``assur atlas --resume``).

    >>> partial_path("runs/atlas.jsonl").as_posix()
    'runs/.atlas.jsonl.partial'
    """
    target = _target(path)
    return target.with_name(f".{target.name}.partial")


def _temporary(target: Path) -> tuple[Path, int]:
    """A new hidden file beside ``target`` with its extension, and its open descriptor."""
    mode = 0o666  # a new file: the umask decides, as for any other file
    with suppress(OSError):
        mode = stat.S_IMODE(os.stat(target).st_mode)
    for _ in range(100):
        name = f".{target.stem}.{os.urandom(4).hex()}.tmp{target.suffix}"
        temporary = target.with_name(name)
        try:
            descriptor = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, mode)
        except FileExistsError:
            continue
        if mode != 0o666:
            os.chmod(descriptor, mode)
        return temporary, descriptor
    raise FileExistsError(f"no free temporary name beside {target}")  # pragma: no cover


def _cannot_write(path: str | os.PathLike[str], exc: OSError) -> MechanismError:
    return MechanismError(f"cannot write {path}: {exc.strerror or exc}")


def _replace(temporary: Path, target: Path) -> None:
    """Flush ``temporary`` to disk and rename it over ``target``."""
    with open(temporary, "rb+") as handle:
        os.fsync(handle.fileno())
    os.replace(temporary, target)


def _discard(temporary: Path) -> None:
    with suppress(OSError):
        os.unlink(temporary)


@contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary path to write in full; renamed over ``path`` when the block ends well.

    For writers that open the file themselves (``fig.savefig(tmp)``,
    ``doc.saveas(tmp)``). The temporary file exists (empty) when the block starts.

    Raises
    ------
    MechanismError
        The file cannot be written (no directory, no permission, disk full, ...).
    """
    target = _target(path)
    if _special(target):
        with _named_errors(path):
            yield target
        return
    with _named_errors(path):
        temporary, descriptor = _temporary(target)
        os.close(descriptor)
        try:
            yield temporary
            _replace(temporary, target)
        except BaseException:
            _discard(temporary)
            raise


@contextmanager
def atomic_file(
    path: str | os.PathLike[str],
    mode: str = "w",
    *,
    encoding: str | None = "utf-8",
    newline: str | None = None,
    partial: bool = False,
) -> Iterator[IO]:
    """An open file to write ``path``'s whole content to; renamed over ``path`` at the end.

    ``mode`` is ``"w"`` (text, ``encoding``) or ``"wb"``; ``"a"``/``"ab"`` with
    ``partial=True`` continue the :func:`partial_path` file of an interrupted run.
    With ``partial=True`` the file is written at :func:`partial_path` (kept when
    the block fails, for a later run to continue) instead of a fresh temporary name.

    Raises
    ------
    MechanismError
        The file cannot be written (no directory, no permission, disk full, ...).
    """
    binary = "b" in mode
    target = _target(path)
    options = {} if binary else {"encoding": encoding, "newline": newline}
    if _special(target):
        with _named_errors(path), open(target, mode, **options) as handle:
            yield handle
        return
    with _named_errors(path):
        if partial:
            temporary = partial_path(target)
            handle = open(temporary, mode, **options)  # noqa: SIM115 - closed below
        else:
            if "a" in mode:
                raise ValueError("appending needs partial=True")
            temporary, descriptor = _temporary(target)
            handle = os.fdopen(descriptor, mode, **options)
        try:
            with handle:
                yield handle
            _replace(temporary, target)
        except BaseException:
            if not partial:
                _discard(temporary)
            raise


@contextmanager
def _named_errors(path: str | os.PathLike[str]) -> Iterator[None]:
    """An OSError inside becomes ``cannot write PATH: REASON`` (a closed stdout stays itself)."""
    try:
        yield
    except BrokenPipeError:
        raise
    except OSError as exc:
        raise _cannot_write(path, exc) from exc


def write_text(path: str | os.PathLike[str], text: str, encoding: str = "utf-8") -> Path:
    """Write ``text`` to ``path`` whole or not at all (:func:`atomic_file`); returns the path.

    Raises
    ------
    MechanismError
        The file cannot be written.
    """
    with atomic_file(path, "w", encoding=encoding) as handle:
        handle.write(text)
    return Path(path)
