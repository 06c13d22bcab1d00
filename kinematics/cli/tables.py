"""What the long-running commands share: where to run, where the table goes, a progress bar.

``--jobs``, ``--scheduler`` and ``--dask-local`` choose local processes or a Dask
cluster; ``--format`` and ``--output`` the table; the progress bar (tqdm, the
optional ``progress`` extra) shows on a terminal only and stays quiet when
standard error is piped.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from typing import IO, Any

__all__ = ["check_run_options", "open_output", "progress_bar"]


def check_run_options(args: argparse.Namespace) -> str | None:
    """The usage problem of the run options, or None."""
    if args.jobs < 1 or args.dask_local < 0:
        return "--jobs must be at least 1 and --dask-local at least 0"
    if args.scheduler and args.dask_local:
        return "--scheduler and --dask-local exclude each other"
    if args.format == "parquet" and not args.output:
        return "Parquet is a binary file: give --output FILE"
    return None


def open_output(path: str | None, fmt: str, append: bool = False) -> IO[Any]:
    """The handle the table goes to: stdout, or ``path`` (binary for Parquet)."""
    if path is None:
        return sys.stdout
    if fmt == "parquet":
        return open(path, "wb")  # closed by the caller
    return open(path, "a" if append else "w", encoding="utf-8", newline="")


def progress_bar(total: int, unit: str) -> tuple[Callable[[int], None] | None, Callable[[], None]]:
    """``(update, close)`` of a progress bar on a terminal; ``(None, no-op)`` otherwise.

    ``update(done)`` sets the count done. tqdm is the optional ``progress`` extra,
    imported on use; on a terminal without it a line says how to get the bar.
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
