"""``assur atlas``: the chains of a link count and DOF, and every mechanism of each, classified.

``assur atlas --links 10 --dof 1 --format jsonl`` writes one JSON object per distinct
mechanism (chain code, ground, driver, groups, class, multiplicity, ...);
``--labelled`` one per labelled choice; ``--summary`` the table of chains and
mechanisms per link count and class; ``--count`` only the chain counts. Long runs
write to ``--output FILE`` chain by chain and continue with ``--resume``.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Iterator, Sequence
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
from structure.chains import KinematicChain, count_chains, enumerate_chains, joint_count
from structure.errors import MechanismError
from structure.parallel import MissingExtraError
from structure.readwrite.edgelist import write_edgelist
from structure.readwrite.table import open_table, read_table_lines

from .tables import check_run_options, open_output, progress_bar

__all__ = ["run"]


def _link_counts(text: str, dof: int) -> list[int] | str:
    """The link counts of ``--links``, or the usage problem."""
    try:
        if "-" in text:
            low, high = (int(x) for x in text.split("-", 1))
            counts = [n for n in range(low, high + 1) if _has_chains(n, dof)]
        else:
            counts = [int(x) for x in text.split(",")]
    except ValueError:
        return f"--links {text!r}: give N, a range N-M or a list N,M,..."
    for n in counts:
        if not _has_chains(n, dof):
            return f"no chain of {n} links with F = {dof}: 3(N - 1) - F must be even and >= 2N"
    if not counts:
        return f"--links {text}: no link count in it has chains with F = {dof}"
    return counts


def _has_chains(links: int, dof: int) -> bool:
    try:
        joint_count(links, dof)
    except ValueError:
        return False
    return dof >= 1


def _usage(message: str) -> int:
    sys.stderr.write(f"error: {message}\n")
    return 2


def run(args: argparse.Namespace) -> int:
    """Run ``assur atlas``; returns the exit code (2 for a usage error)."""
    counts = _link_counts(args.links, args.dof)
    if isinstance(counts, str):
        return _usage(counts)
    if args.count:
        for n in counts:
            sys.stdout.write(_count_line(n, args.dof))
        return 0
    problem = check_run_options(args)
    if problem is None and args.resume and (not args.output or args.format == "parquet"):
        problem = "--resume needs --output FILE in jsonl or csv format"
    if problem:
        return _usage(problem)
    keep = {"degenerate": args.degenerate, "fractionated": not args.no_fractionated}
    chains = {n: enumerate_chains(n, args.dof, **keep) for n in counts}
    try:
        return _run_atlas(args, chains)
    except MissingExtraError as exc:
        return _usage(str(exc))
    except ImportError as exc:  # pyarrow for Parquet
        return _usage(str(exc))
    except BrokenPipeError:  # the reader stopped (| head): not an error
        _silence_stdout()
        return 0
    except OSError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1


def _silence_stdout() -> None:
    """Point stdout at /dev/null so that the exit's flush does not fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # pragma: no cover - stdout without a descriptor
        pass


def _count_line(links: int, dof: int) -> str:
    c = count_chains(links, dof)
    extra = f", {c.fractionated} of them fractionated" if c.fractionated else ""
    return (
        f"{links} links, F = {dof}: {c.chains} chains{extra}, {c.inversions} inversions "
        f"(ground links up to symmetry); {c.degenerate} degenerate chains left out "
        f"({c.degenerate - c.degenerate_fractionated} without a cut link, "
        f"{c.degenerate_fractionated} with one)\n"
    )


def _run_atlas(args: argparse.Namespace, chains: dict[int, Sequence[KinematicChain]]) -> int:
    tasks = [(k, c) for n in chains for k, c in enumerate(chains[n])]
    done, offset = 0, 0
    if args.resume:
        done, offset = completed_chains(args.output, args.format, tasks, labelled=args.labelled)
        with open(args.output, "ab") as handle:
            handle.truncate(offset)
    columns = list(ATLAS_COLUMNS)
    if args.write_edgelists:
        os.makedirs(args.write_edgelists, exist_ok=True)
        columns.append(("edgelist", "str"))
    to_stdout = args.output is None
    summary_rows: list[dict[str, Any]] = []
    if args.resume and args.summary and offset:
        summary_rows.extend(row for row, _ in read_table_lines(args.output, args.format))
    update, close = progress_bar(len(tasks), "chain")
    if update is not None:
        update(done)
    handle = (
        None
        if (args.summary and to_stdout)
        else open_output(args.output, args.format, append=offset > 0)
    )
    try:
        writer = (
            None if handle is None else open_table(handle, args.format, columns, header=offset == 0)
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
        if handle is not None and handle is not sys.stdout:
            handle.close()
    if args.summary:
        left_out = None
        if not args.degenerate:
            left_out = {n: count_chains(n, args.dof).degenerate for n in chains}
        sys.stdout.write(format_summary(atlas_summary(summary_rows), left_out))
    return 0


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
    Path(directory, name).write_text(text, encoding="utf-8")
    return name
