"""One function over many items, in order: in this process, in local processes, or on Dask.

:func:`ordered_map` yields ``function(item)`` for every item in the items' order,
whatever runs them: the calling process (``jobs=1``), a pool of ``jobs`` local
processes, or a Dask cluster (``scheduler="tcp://HOST:PORT"``, or ``dask_local=N``
for a LocalCluster of N worker processes started here). Items travel in chunks;
``function`` and the items must pickle (a module-level function and plain data).
:func:`local_cluster` starts a LocalCluster that several jobs can share.

Dask is the optional ``dask`` extra (``pip install 'assur[dask]'``): it is imported
only when asked for, so that ``import structure`` stays light, and its absence is
:class:`MissingExtraError` with the command to install it.
"""

from __future__ import annotations

import contextlib
import itertools
import multiprocessing
import re
from collections import deque
from collections.abc import Callable, Iterable, Iterator, Sequence, Sized
from typing import Any, TypeVar

from .errors import MechanismError, UsageError, clipped

__all__ = [
    "SCHEDULER_FORM",
    "Counted",
    "MissingExtraError",
    "check_scheduler",
    "local_cluster",
    "ordered_map",
]

Item = TypeVar("Item")
Result = TypeVar("Result")


#: chunks in flight per Dask worker: enough that no worker waits while the client
#: takes the results in order
_IN_FLIGHT = 32

#: chunks in flight per local worker process
_IN_FLIGHT_LOCAL = 4

#: tasks per Dask worker when the number of items is known: few large tasks (each
#: task costs the scheduler and the network a round trip), yet enough of them that
#: a worker slowed by other work does not hold up the end of the job
_TASKS_PER_WORKER = 8

#: seconds to wait for a new LocalCluster's workers before submitting work
_WORKER_WAIT = 60


class MissingExtraError(ImportError):
    """An optional dependency is not installed; the message says how to install it."""


#: the form of a Dask scheduler's address, as the messages name it
SCHEDULER_FORM = "tcp://HOST:PORT (or tls://, ws://, wss://, ucx://; HOST:PORT means tcp://)"

_SCHEDULER = re.compile(
    r"(?:(?P<scheme>tcp|tls|ws|wss|ucx)://)?"
    r"(?P<host>\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9](?:[A-Za-z0-9._-]{0,252}))"
    r":(?P<port>[0-9]{1,5})/?"
)


def check_scheduler(address: str) -> str:
    """The address of a Dask scheduler as given, or a UsageError naming the form expected.

    >>> check_scheduler("tcp://10.0.0.5:8786")
    'tcp://10.0.0.5:8786'
    >>> check_scheduler("garbage")
    Traceback (most recent call last):
    ...
    structure.errors.UsageError: --scheduler 'garbage' is not a Dask scheduler's address: giv...
    """
    found = _SCHEDULER.fullmatch(address)
    if found is None or not 0 < int(found.group("port")) < 65536:
        raise UsageError(
            f"--scheduler {clipped(address)!r} is not a Dask scheduler's address: give "
            f"{SCHEDULER_FORM}, e.g. tcp://10.0.0.5:8786"
        )
    return address


class Counted(Iterable[Item]):
    """Items taken one by one (made lazily), with their number known beforehand.

    :func:`ordered_map` sizes its Dask tasks by the number of items; a lazy
    iterable wrapped in this keeps that without making its items first.

    >>> items = Counted((k * k for k in range(3)), 3)
    >>> len(items), list(items)
    (3, [0, 1, 4])
    """

    def __init__(self, items: Iterable[Item], length: int) -> None:
        self._items = items
        self._length = length

    def __iter__(self) -> Iterator[Item]:
        return iter(self._items)

    def __len__(self) -> int:
        return self._length


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
        Items sent to a worker at a time. On Dask, when ``items`` has a length,
        the chunks are larger if that makes about eight per worker.

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
            # a window of chunks in flight, not ``imap`` (whose feeder takes every item at
            # once): items made lazily (files read as they are taken) stay few in memory
            window: deque = deque()
            for part in _chunks(items, chunk):
                window.append(pool.apply_async(_apply_chunk, (function, part)))
                if len(window) >= _IN_FLIGHT_LOCAL * jobs:
                    yield from window.popleft().get()
            while window:
                yield from window.popleft().get()
    else:
        for item in items:
            yield function(item)


def _distributed() -> Any:
    """The ``dask.distributed`` module (the optional ``dask`` extra, imported on use)."""
    try:
        import dask.distributed as distributed  # optional extra, imported on use
    except ImportError as exc:
        raise MissingExtraError(
            "running on Dask needs dask[distributed]: pip install 'assur[dask]'"
        ) from exc
    return distributed


@contextlib.contextmanager
def local_cluster(workers: int) -> Iterator[str]:
    """A Dask LocalCluster of ``workers`` single-threaded processes: its scheduler's address.

    Every worker is up when the address is given (otherwise the first one would
    take all the first tasks); the cluster is closed on exit.

    Raises
    ------
    MissingExtraError
        Dask not installed.
    """
    distributed = _distributed()
    cluster = distributed.LocalCluster(
        n_workers=workers,
        threads_per_worker=1,
        processes=True,
        host="127.0.0.1",
        dashboard_address="127.0.0.1:0",
    )
    try:
        with distributed.Client(cluster) as client:
            client.wait_for_workers(workers, timeout=_WORKER_WAIT)
        yield cluster.scheduler_address
    finally:
        cluster.close()


def _chunk_size(items: Iterable[Any], chunk: int, workers: int) -> int:
    """``chunk``, or larger to make about :data:`_TASKS_PER_WORKER` tasks per worker."""
    if not isinstance(items, Sized):
        return chunk
    return max(chunk, -(-len(items) // (workers * _TASKS_PER_WORKER)))


def _dask_map(
    function: Callable[[Any], Any],
    items: Iterable[Any],
    scheduler: str | None,
    dask_local: int,
    chunk: int,
) -> Iterator[Any]:
    if not scheduler:
        with local_cluster(dask_local) as address:
            yield from _dask_map(function, items, address, 0, chunk)
        return
    check_scheduler(scheduler)
    distributed = _distributed()
    try:
        client = distributed.Client(scheduler)
    except (OSError, TimeoutError) as exc:
        raise MechanismError(
            f"cannot reach the Dask scheduler at {scheduler}: {exc}; is it running, and is "
            "the address its own (dask scheduler prints it)?"
        ) from exc
    try:
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        window: deque = deque()
        for part in _chunks(items, _chunk_size(items, chunk, workers)):
            window.append(client.submit(_apply_chunk, function, part, pure=False))
            if len(window) >= _IN_FLIGHT * workers:
                yield from window.popleft().result()
        while window:
            yield from window.popleft().result()
    finally:
        client.close()
