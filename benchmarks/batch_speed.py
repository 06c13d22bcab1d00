"""How fast many mechanisms are classified: one process, local processes, Dask.

The job: the fixtures (``fixtures/*.edges``, sketches of 3 to 11 moving links,
cams, gears and sliders included) repeated ``--copies`` times, read once into
memory (:func:`structure.batch.batch_items`), then classified
(:func:`structure.batch.classify_batch`: parse and analyze, a row each):

* in one process: mechanisms per CPU second (the per-core rate; goal: at least
  1,000), the median of ``--repeat`` runs;
* with ``--jobs`` local processes (the pool's start-up, a fork, is in its time);
* on a Dask LocalCluster of two worker processes (goal: the job takes at most 1.5
  times the ``--jobs 2`` time), with the same rows in the same order. The cluster
  is started once and its workers warmed by a two-item job: that start-up is
  timed apart, then the job is timed on the running cluster, ``--repeat`` times
  interleaved with the ``--jobs`` runs; the ratio printed is the median of the
  rounds' ratios. A figure with the start-up added is printed too.

Machines shared with other work give noisy absolute times: trust the medians and
the ratios of interleaved runs.

Usage::

    python benchmarks/batch_speed.py [--copies 40] [--jobs 2] [--repeat 5] [--no-dask]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from structure.batch import BatchItem, batch_items, classify_batch  # noqa: E402
from structure.parallel import local_cluster  # noqa: E402

GOAL_RATE = 1000.0  # mechanisms per second per core
GOAL_DASK = 1.5  # Dask LocalCluster time / jobs=2 time


def _load() -> str:
    return "load average " + ", ".join(f"{x:.2f}" for x in os.getloadavg())


def _one_process(items: list[BatchItem], repeat: int) -> list[dict]:
    rates, walls = [], []
    for _ in range(repeat):
        wall, cpu = time.perf_counter(), time.process_time()
        rows = list(classify_batch(items))
        walls.append(time.perf_counter() - wall)
        rates.append(len(items) / (time.process_time() - cpu))
    rate = statistics.median(rates)
    verdict = "met" if rate >= GOAL_RATE else f"MISSED by {GOAL_RATE - rate:.0f}/s"
    print(
        f"  one process: {statistics.median(walls):.2f} s (median of {repeat}), "
        f"{rate:.0f} mechanisms per CPU second (runs: {', '.join(f'{r:.0f}' for r in rates)}; "
        f"goal {GOAL_RATE:.0f}/s per core: {verdict})"
    )
    return rows


def _timed(items: list[BatchItem], **where: object) -> tuple[float, list[dict]]:
    start = time.perf_counter()
    rows = list(classify_batch(items, **where))  # type: ignore[arg-type]
    return time.perf_counter() - start, rows


def _on_dask(items: list[BatchItem], rows: list[dict], jobs: int, repeat: int) -> None:
    start = time.perf_counter()
    with local_cluster(2) as address:
        _timed(items[:2], scheduler=address)  # the workers import assur
        start_up = time.perf_counter() - start
        local, dask = [], []
        for _ in range(repeat):
            wall, local_rows = _timed(items, jobs=jobs)
            assert local_rows == rows
            local.append(wall)
            wall, dask_rows = _timed(items, scheduler=address)
            assert dask_rows == rows
            dask.append(wall)
    ratios = [d / j for d, j in zip(dask, local, strict=True)]
    ratio = statistics.median(ratios)
    verdict = "met" if ratio <= GOAL_DASK else "MISSED"
    print(
        f"  jobs {jobs}: {statistics.median(local):.2f} s, "
        f"{len(items) / statistics.median(local):.0f} mechanisms/s (median of {repeat})"
    )
    print(
        f"  Dask LocalCluster (2 workers), the job on the running cluster: "
        f"{statistics.median(dask):.2f} s (median of {repeat}); same rows, same order"
    )
    print(
        f"  Dask / jobs {jobs}, median of {repeat} interleaved rounds: {ratio:.2f}x "
        f"(rounds: {', '.join(f'{r:.2f}' for r in ratios)}; goal {GOAL_DASK}x: {verdict})"
    )
    print(
        f"  cluster start-up, timed apart (2 worker processes, their imports): "
        f"{start_up:.2f} s; one job with it: "
        f"{(start_up + statistics.median(dask)) / statistics.median(local):.2f}x jobs {jobs}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--copies", type=int, default=40)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--no-dask", action="store_true")
    args = parser.parse_args()
    files = sorted(str(p) for p in (ROOT / "fixtures").glob("*.edges"))
    items = list(batch_items(files)) * args.copies
    print(f"## {len(items)} mechanisms ({len(files)} fixtures x {args.copies}); {_load()}")
    list(classify_batch(items[: len(files)]))  # imports and first calls, not timed
    rows = _one_process(items, args.repeat)
    if args.no_dask:
        wall, local_rows = _timed(items, jobs=args.jobs)
        assert local_rows == rows
        print(f"  jobs {args.jobs}: {wall:.2f} s, {len(items) / wall:.0f} mechanisms/s")
    else:
        _on_dask(items, rows, args.jobs, args.repeat)
    print(f"  ({_load()} at the end)")


if __name__ == "__main__":
    main()
