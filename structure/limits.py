"""How much memory a run may take, and the bound every option that sets a size is held to.

An option that sets a size (poses of a sweep, frames of an animation, link counts
of an atlas, worker processes, poses in an ``--inputs`` file) costs memory in
proportion to it. :func:`check_size` refuses a size whose estimate is beyond
:func:`memory_limit` (half of this machine's memory) before any work, with one
message that names the memory it would take, the memory allowed and the largest
size that fits: the same words for every option, as ``sweep --steps`` has them.

A new option that sets a size calls :func:`check_size` with its count, the bytes
each unit takes (measured, with the measurement cited where the constant is
defined) and how to ask for less.

>>> check_size(10, 100, "a sweep of 10 poses", "ask for fewer poses")
>>> check_size(10**12, 100, "a sweep of 10^12 poses", "ask for at most {fit} poses",
...            limit=10**9)
Traceback (most recent call last):
...
structure.errors.SizeError: a sweep of 10^12 poses would take about 100 TB of memory, more th...
"""

from __future__ import annotations

import os

from .errors import SizeError

__all__ = ["check_size", "memory_limit", "memory_text"]


def memory_limit() -> int:
    """The memory a run may take (bytes): half of this machine's (4 GiB where it cannot be read)."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2
    except (ValueError, OSError, AttributeError):  # pragma: no cover - platform
        return 4 * 2**30


def memory_text(size: float) -> str:
    """Bytes as a message writes them: ``'1.5 GB'``, ``'100 TB'``, ``'320 MB'``.

    >>> memory_text(1.5e9), memory_text(3.2e8), memory_text(1e14)
    ('1.5 GB', '320 MB', '100 TB')
    """
    for unit, scale in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if size >= scale:
            return f"{size / scale:.3g} {unit}"
    return f"{size:.3g} bytes"


def check_size(
    count: int,
    bytes_each: float,
    what: str,
    ask: str,
    *,
    fixed: float = 0.0,
    limit: int | None = None,
    error: type[SizeError] = SizeError,
) -> None:
    """Refuse ``count`` units of ``bytes_each`` (plus ``fixed``) beyond the memory allowed.

    Parameters
    ----------
    count
        The size asked for (poses, frames, processes, ...).
    bytes_each
        The memory one unit takes (bytes).
    what
        The size as the message names it: ``"a sweep of 30000000 poses"``.
    ask
        What to do instead; ``{fit}`` in it becomes the largest count that fits.
    fixed
        Memory taken whatever the count (bytes).
    limit
        The memory allowed; :func:`memory_limit` when not given.
    error
        The :class:`SizeError` subclass to raise (a sweep's own, ...).

    Raises
    ------
    SizeError
        ``"<what> would take about X of memory, more than the Y a run may take (half of
        this machine's): <ask>"``.
    """
    allowed = memory_limit() if limit is None else limit
    need = fixed + count * bytes_each
    if need <= allowed:
        return
    fit = max(int((allowed - fixed) // bytes_each), 0) if bytes_each > 0 else count
    raise error(
        f"{what} would take about {memory_text(need)} of memory, more than the "
        f"{memory_text(allowed)} a run may take (half of this machine's): " + ask.format(fit=fit)
    )
