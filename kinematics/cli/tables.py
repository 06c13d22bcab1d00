"""What the long-running commands share: where to run, where the table goes, a progress bar.

``--jobs``, ``--scheduler`` and ``--dask-local`` choose local processes or a Dask
cluster (:func:`check_run_options`, :func:`check_workers` bound them); ``--format``
and ``--output`` the table (:func:`open_output`: the terminal, escaped, or a file
written whole or not at all); the progress bar (tqdm, the optional ``progress``
extra) shows on a terminal only and stays quiet when standard error is piped.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import IO, Any

from structure.errors import UsageError
from structure.limits import check_size
from structure.parallel import check_scheduler
from structure.readwrite.atomic import atomic_file

from .output import escaped

__all__ = [
    "DASK_WORKER_BYTES",
    "LOCAL_WORKER_BYTES",
    "check_run_options",
    "check_workers",
    "open_output",
    "progress_bar",
]

#: memory of one local worker process (measured: 75 MB peak for a process that has
#: imported the structure package and numpy and classified every fixture)
LOCAL_WORKER_BYTES = 80_000_000
#: memory of one worker of a Dask LocalCluster: a local worker and dask.distributed
#: (measured: importing dask.distributed alone peaks at 58 MB)
DASK_WORKER_BYTES = 140_000_000


def check_run_options(args: argparse.Namespace, *, table: bool = True) -> str | None:
    """The usage problem of the run options (and of the table's, with ``table``), or None."""
    if args.jobs < 1 or args.dask_local < 0:
        return "--jobs must be at least 1 and --dask-local at least 0"
    if args.scheduler and args.dask_local:
        return "--scheduler and --dask-local exclude each other"
    if args.scheduler:
        try:
            check_scheduler(args.scheduler)
        except UsageError as exc:
            return str(exc)
    if table and args.format == "parquet" and not args.output:
        return "Parquet is a binary file: give --output FILE"
    return None


def check_workers(args: argparse.Namespace) -> None:
    """Refuse more worker processes (``--jobs``, ``--dask-local``) than fit in memory.

    Raises
    ------
    SizeError
        Naming the memory the processes would take and how many fit.
    """
    check_size(
        args.jobs,
        LOCAL_WORKER_BYTES,
        f"--jobs {args.jobs} ({args.jobs} worker processes)",
        "ask for at most --jobs {fit}",
    )
    check_size(
        args.dask_local,
        DASK_WORKER_BYTES,
        f"--dask-local {args.dask_local} ({args.dask_local} Dask worker processes)",
        "ask for at most --dask-local {fit}",
    )


@contextmanager
def open_output(
    path: str | None, fmt: str, *, append: bool = False, partial: bool = False
) -> Iterator[IO[Any]]:
    """The handle the table goes to: stdout (escaped for the terminal), or ``path``.

    ``path`` is written whole or not at all (:func:`~structure.readwrite.atomic.atomic_file`;
    binary for Parquet); ``partial`` writes it through its ``.partial`` file, which a
    stopped run leaves for ``--resume`` (``append`` continues it).
    """
    if path is None:
        stream = escaped(sys.stdout, json_text=fmt == "jsonl")
        yield stream
        sys.stdout.flush()
        return
    mode = ("a" if append else "w") + ("b" if fmt == "parquet" else "")
    options = {} if fmt == "parquet" else {"encoding": "utf-8", "newline": ""}
    with atomic_file(path, mode, partial=partial or append, **options) as handle:
        yield handle


def progress_bar(
    total: int | None, unit: str
) -> tuple[Callable[[int], None] | None, Callable[[], None]]:
    """``(update, close)`` of a progress bar on a terminal; ``(None, no-op)`` otherwise.

    ``update(done)`` sets the count done; ``total`` is None when it is not known
    (JSON lines on stdin). tqdm is the optional ``progress`` extra, imported on use;
    on a terminal without it a line says how to get the bar.
    """
    if not sys.stderr.isatty():
        return None, lambda: None
    try:
        from tqdm import tqdm  # optional extra, imported on use
    except ImportError:
        sys.stderr.write("(a progress bar needs tqdm: pip install 'assur[progress]')\n")
        return None, lambda: None
    bar = tqdm(total=total, unit=unit, file=sys.stderr, dynamic_ncols=True)

    def update(done: int) -> None:
        bar.update(done - bar.n)

    return update, bar.close
