"""One function over many items, in order: in this process, in local processes, or on Dask.

:func:`ordered_map` yields ``function(item)`` for every item in the items' order,
whatever runs them: the calling process (``jobs=1``), a pool of ``jobs`` local
processes, or a Dask cluster (``scheduler="tcp://HOST:PORT"``, or ``dask_local=N``
for a LocalCluster of N worker processes started here). Items travel in chunks;
``function`` and the items must pickle (a module-level function and plain data).

Dask is the optional ``dask`` extra (``pip install 'assur[dask]'``): it is imported
only when asked for, so that ``import structure`` stays light, and its absence is
:class:`MissingExtraError` with the command to install it.
"""

from __future__ import annotations

import functools
import itertools
import multiprocessing
from collections import deque
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any, TypeVar

__all__ = ["MissingExtraError", "ordered_map"]

Item = TypeVar("Item")
Result = TypeVar("Result")


#: chunks in flight per Dask worker: enough that no worker waits while the client
#: takes the results in order
_IN_FLIGHT = 32


class MissingExtraError(ImportError):
    """An optional dependency is not installed; the message says how to install it."""


def _apply_chunk(function: Callable[[Any], Any], chunk: Sequence[Any]) -> list[Any]:
    return [function(item) for item in chunk]


def _chunks(items: Iterable[Item], size: int) -> Iterator[list[Item]]:
    iterator = iter(items)
    while chunk := list(itertools.islice(iterator, size)):
        yield chunk


def ordered_map(
    function: Callable[[Item], Result],
    items: Iterable[Item],
    *,
    jobs: int = 1,
    scheduler: str | None = None,
    dask_local: int = 0,
    chunk: int = 1,
) -> Iterator[Result]:
    """``function(item)`` for every item, in the items' order.

    Parameters
    ----------
    function : callable
        A module-level function (it is pickled by name for other processes).
    items : iterable
    jobs : int
        Local processes (1: this process).
    scheduler : str, optional
        Address of a running Dask scheduler, e.g. ``"tcp://10.0.0.5:8786"``.
    dask_local : int
        Start a Dask LocalCluster with this many single-threaded worker processes.
    chunk : int
        Items sent to a worker at a time.

    Raises
    ------
    MissingExtraError
        Dask asked for but not installed.
    """
    chunk = max(1, chunk)
    if scheduler or dask_local:
        yield from _dask_map(function, items, scheduler, dask_local, chunk)
    elif jobs > 1:
        methods = multiprocessing.get_all_start_methods()
        context = multiprocessing.get_context("fork" if "fork" in methods else None)
        with context.Pool(jobs) as pool:
            calls = pool.imap(functools.partial(_apply_chunk, function), _chunks(items, chunk))
            for results in calls:
                yield from results
    else:
        for item in items:
            yield function(item)


def _dask_client(scheduler: str | None, dask_local: int) -> Any:
    """A Dask client on ``scheduler`` or on a new LocalCluster (optional ``dask`` extra)."""
    try:
        from dask.distributed import Client, LocalCluster  # optional extra, imported on use
    except ImportError as exc:
        raise MissingExtraError(
            "running on Dask needs dask[distributed]: pip install 'assur[dask]'"
        ) from exc
    if scheduler:
        return Client(scheduler)
    cluster = LocalCluster(
        n_workers=dask_local,
        threads_per_worker=1,
        processes=True,
        host="127.0.0.1",
        dashboard_address="127.0.0.1:0",
    )
    return Client(cluster)


def _dask_map(
    function: Callable[[Any], Any],
    items: Iterable[Any],
    scheduler: str | None,
    dask_local: int,
    chunk: int,
) -> Iterator[Any]:
    client = _dask_client(scheduler, dask_local)
    try:
        workers = max(1, len(client.scheduler_info().get("workers", {})), dask_local)
        window: deque = deque()
        for part in _chunks(items, chunk):
            window.append(client.submit(_apply_chunk, function, part, pure=False))
            if len(window) >= _IN_FLIGHT * workers:
                yield from window.popleft().result()
        while window:
            yield from window.popleft().result()
    finally:
        cluster = None if scheduler else client.cluster
        client.close()
        if cluster is not None:
            cluster.close()
