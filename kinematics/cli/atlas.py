"""``assur atlas``: the chains of a link count and DOF, and every mechanism of each, classified.

``assur atlas --links 10 --dof 1 --format jsonl`` writes one JSON object per distinct
mechanism (chain code, ground, driver, groups, class, multiplicity, ...);
``--labelled`` one per labelled choice; ``--summary`` the table of chains and
mechanisms per link count and class; ``--count`` only the chain counts. Long runs
write to ``--output FILE`` chain by chain and continue with ``--resume``.
"""

from __future__ import annotations

import argparse
import contextlib
import os
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from structure.atlas import (
    ATLAS_COLUMNS,
    atlas,
    atlas_row_dict,
    atlas_summary,
    completed_chains,
    format_summary,
    row_mechanism,
)
from structure.chains import (
    CHAIN_BYTES,
    KinematicChain,
    count_chains,
    enumerate_chains,
    estimated_chains,
    joint_count,
)
from structure.errors import MechanismError, SizeError, clipped
from structure.limits import check_size, memory_limit
from structure.parallel import MissingExtraError
from structure.readwrite.atomic import partial_path, write_text
from structure.readwrite.edgelist import write_edgelist
from structure.readwrite.table import open_table, read_table_lines
from structure.readwrite.textfile import opened

from .output import EXIT_OK, EXIT_USAGE, fail, write_stdout
from .tables import check_run_options, check_workers, open_output, progress_bar

__all__ = ["run"]


def _link_counts(text: str, dof: int) -> list[int] | str:
    """The link counts of ``--links``, or the usage problem."""
    try:
        if "-" in text:
            low, high = (int(x) for x in text.split("-", 1))
            if high - low > _MAX_SPAN:
                return (
                    f"--links {text}: a range spans at most {_MAX_SPAN} link counts (the "
                    "chains grow about fifty-fold every two links)"
                )
            counts = [n for n in range(low, high + 1) if _has_chains(n, dof)]
        else:
            counts = list(dict.fromkeys(int(x) for x in text.split(",")))
    except ValueError:
        return f"--links {text!r}: give N, a range N-M or a list N,M,..."
    for n in counts:
        if not _has_chains(n, dof):
            return f"no chain of {n} links with F = {dof}: 3(N - 1) - F must be even and >= 2N"
    if not counts:
        return f"--links {text}: no link count in it has chains with F = {dof}"
    return counts


#: the widest range ``--links`` takes (the chains of a count grow fifty-fold every two links)
_MAX_SPAN = 100


def _has_chains(links: int, dof: int) -> bool:
    try:
        joint_count(links, dof)
    except ValueError:
        return False
    return dof >= 1


#: memory one row of the atlas takes when ``--summary`` keeps the rows (measured with
#: tracemalloc: the 4,506 rows of 10 links, 4.6 kB each), and the mechanisms of a chain, at
#: most about (12 links: 195,816 for 6,856 chains, 29 each; 14 links: at most 34)
_ROW_BYTES = 4600
_ROWS_PER_CHAIN = 40


def _check_atlas_size(args: argparse.Namespace, counts: Sequence[int]) -> None:
    """Refuse an atlas whose chains (and rows, for ``--summary``) would not fit in memory.

    Raises
    ------
    SizeError
        Naming the memory, and the largest link count that fits.
    """
    per_chain = CHAIN_BYTES + (_ROWS_PER_CHAIN * _ROW_BYTES if args.summary else 0)

    def chains(n: int) -> int:
        return estimated_chains(n, args.dof, degenerate=args.degenerate)

    need = sum(chains(n) for n in counts)
    fit = _largest(args.dof, max(counts), lambda n: chains(n) * per_chain <= memory_limit())
    ask = f"ask for at most {fit} links" if fit else f"no chain of F = {args.dof} fits"
    check_size(
        need,
        per_chain,
        f"the atlas of --links {clipped(args.links)} ({_chain_number(need)} chains"
        + (" and their rows for --summary)" if args.summary else ")"),
        ask + (" (or leave out --summary: the rows go to --output)" if args.summary else ""),
    )


#: CPU-seconds ``--count`` spends on a chain, degenerate ones included (measured: the 79,764
#: chains of 12 links in 5 to 14 s on this shared machine), and the most it may spend
_COUNT_SECONDS_PER_CHAIN = 1.5e-4
_COUNT_BUDGET = 86_400.0


def _count_too_long(counts: Sequence[int], dof: int) -> str | None:
    """Why counting the chains of ``counts`` would take longer than a CPU-day, or None.

    ``--count`` keeps no chain (its memory stays small) but goes through every one.
    """
    for n in counts:
        chains = estimated_chains(n, dof, degenerate=True)
        seconds = chains * _COUNT_SECONDS_PER_CHAIN
        if seconds > _COUNT_BUDGET:
            fit = _largest(
                dof, n, lambda k: estimated_chains(k, dof, degenerate=True)
                * _COUNT_SECONDS_PER_CHAIN <= _COUNT_BUDGET,
            )  # fmt: skip
            ask = f"ask for at most {fit} links" if fit else f"no chain of F = {dof} is that quick"
            return (
                f"--count for {n} links would go through {_chain_number(chains)} chains, about "
                f"{seconds / 86_400:.3g} CPU-days (more than one): {ask}"
            )
    return None


def _largest(dof: int, upto: int, fits: Callable[[int], bool]) -> int | None:
    """The largest link count up to ``upto`` with chains of ``dof`` that ``fits``, or None.

    The chains grow with the link count: counting up stops a few steps after the first
    that does not fit, however large ``upto`` is.
    """
    found = None
    for n in range(max(2, (dof + 3) // 2), upto + 1):  # fewer links have no chain of dof
        if _has_chains(n, dof):
            if not fits(n):
                return found
            found = n
    return found


def _chain_number(chains: int) -> str:
    """A number of chains as a message writes it (an estimate beyond any machine: so many)."""
    return f"about {chains:,}" if chains < 10**15 else "more than 10^15"


def run(args: argparse.Namespace) -> int:
    """Run ``assur atlas``; returns the exit code (2 for a usage error)."""
    counts = _link_counts(args.links, args.dof)
    if isinstance(counts, str):
        return fail(counts, EXIT_USAGE)
    problem = check_run_options(args, table=not args.count)
    if problem is None and args.resume and (not args.output or args.format == "parquet"):
        problem = "--resume needs --output FILE in jsonl or csv format"
    if problem:
        return fail(problem, EXIT_USAGE)
    keep = {"degenerate": args.degenerate, "fractionated": not args.no_fractionated}
    if args.count:
        problem = _count_too_long(counts, args.dof)
        if problem:
            raise SizeError(problem)
        write_stdout("".join(_count_line(n, args.dof, **keep) for n in counts))
        return EXIT_OK
    check_workers(args)
    _check_atlas_size(args, counts)
    chains = {n: enumerate_chains(n, args.dof, **keep) for n in counts}
    try:
        return _run_atlas(args, chains)
    except (MissingExtraError, ImportError) as exc:  # Dask, pyarrow for Parquet
        return fail(str(exc), EXIT_USAGE)


def _count_line(links: int, dof: int, *, degenerate: bool, fractionated: bool) -> str:
    """The counts of ``--count``: the chains the same options' rows classify, and those left out.

    Without ``--degenerate`` and ``--no-fractionated`` the chains are the
    non-degenerate ones, the degenerate ones counted apart.
    """
    c = count_chains(links, dof, degenerate=degenerate, fractionated=fractionated)
    head = f"{links} links, F = {dof}: {c.kept} chains"
    if degenerate:
        kept_degenerate = c.degenerate - (0 if fractionated else c.degenerate_fractionated)
        kept_fractionated = (c.fractionated + c.degenerate_fractionated) if fractionated else 0
        head += f" ({kept_degenerate} of them degenerate"
        head += f", {kept_fractionated} fractionated)" if kept_fractionated else ")"
    elif fractionated and c.fractionated:
        head += f", {c.fractionated} of them fractionated"
    parts = [f"{head}, {c.kept_inversions} inversions (ground links up to symmetry)"]
    if not degenerate:
        parts.append(
            f"{c.degenerate} degenerate chains left out "
            f"({c.degenerate - c.degenerate_fractionated} without a cut link, "
            f"{c.degenerate_fractionated} with one)"
        )
    if not fractionated:
        left = c.fractionated + (c.degenerate_fractionated if degenerate else 0)
        parts.append(f"{left} fractionated chains left out")
    return "; ".join(parts) + "\n"


def _resume_from(args: argparse.Namespace, tasks: list) -> tuple[int, int]:
    """Chains done and the byte offset after them, in the ``.partial`` file the run goes on in.

    The partial file a stopped run left is continued; without one, the table at
    ``--output`` (finished, or cut short by an older run) becomes it.

    Raises
    ------
    EdgeListError
        The table is no regular file (``/dev/full``) or cannot be read.
    """
    partial = partial_path(args.output)
    source = partial if partial.exists() else Path(args.output)
    done, offset = completed_chains(source, args.format, tasks, labelled=args.labelled)
    if offset == 0:
        return 0, 0
    with opened(source):
        if source != partial:
            os.replace(os.path.realpath(source), partial)
        with open(partial, "ab") as handle:
            handle.truncate(offset)
    return done, offset


def _run_atlas(args: argparse.Namespace, chains: dict[int, Sequence[KinematicChain]]) -> int:
    tasks = [(k, c) for n in chains for k, c in enumerate(chains[n])]
    done, offset = _resume_from(args, tasks) if args.resume else (0, 0)
    columns = list(ATLAS_COLUMNS)
    if args.write_edgelists:
        with opened(args.write_edgelists):
            os.makedirs(args.write_edgelists, exist_ok=True)
        columns.append(("edgelist", "str"))
    to_stdout = args.output is None
    summary_rows: list[dict[str, Any]] = []
    if args.resume and args.summary and offset:
        summary_rows.extend(
            row for row, _ in read_table_lines(partial_path(args.output), args.format)
        )
    update, close = progress_bar(len(tasks), "chain")
    if update is not None:
        update(done)
    writing = (
        contextlib.nullcontext(None)
        if (args.summary and to_stdout)
        else open_output(args.output, args.format, append=offset > 0, partial=not to_stdout)
    )
    try:
        with writing as handle:
            writer = (
                None
                if handle is None
                else open_table(handle, args.format, columns, header=offset == 0)
            )
            for row in _rows(args, chains, done, update):
                if args.write_edgelists:
                    row["edgelist"] = _write_edgelist(args.write_edgelists, row)
                if writer is not None:
                    writer.write([row])
                if args.summary:
                    summary_rows.append(row)
            if writer is not None:
                writer.close()
    finally:
        close()
    if args.summary:
        left_out = None
        if not args.degenerate:
            left_out = {n: count_chains(n, args.dof).degenerate for n in chains}
        write_stdout(format_summary(atlas_summary(summary_rows), left_out))
    return EXIT_OK


def _rows(
    args: argparse.Namespace, chains: dict[int, Sequence[KinematicChain]], done: int, update
) -> Iterator[dict[str, Any]]:
    """The rows of every link count, skipping the ``done`` chains of a resumed run."""
    before = 0
    for n, listed in chains.items():
        start = min(max(done - before, 0), len(listed))
        base = before

        def progress(count: int, base: int = base) -> None:
            if update is not None:
                update(base + count)

        for row in atlas(
            n,
            args.dof,
            labelled=args.labelled,
            start=start,
            jobs=args.jobs,
            scheduler=args.scheduler,
            dask_local=args.dask_local,
            progress=progress,
            chains=listed,
        ):
            yield atlas_row_dict(row)
        before += len(listed)


def _write_edgelist(directory: str, row: dict[str, Any]) -> str:
    """Write the row's mechanism as an edge list; returns the file's name."""
    drivers = "-".join(str(d) for d in row["drivers"])
    name = f"{row['links']}-{row['chain_index']:05d}-g{row['ground']}-d{drivers}.edges"
    try:
        text = write_edgelist(row_mechanism(row))
    except MechanismError as exc:  # pragma: no cover - rows always rebuild
        text = f"# cannot rebuild: {exc}\n"
    write_text(Path(directory, name), text)
    return name
