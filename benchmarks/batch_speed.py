"""How fast many mechanisms are classified: one process, local processes, Dask.

The job: the fixtures (``fixtures/*.edges``, sketches of 3 to 11 moving links,
cams, gears and sliders included) repeated ``--copies`` times, read once into
memory (:func:`structure.batch.batch_items`), then classified
(:func:`structure.batch.classify_batch`: parse and analyze, a row each):

* in one process: mechanisms per second of wall time and per CPU second (the
  per-core rate; goal: at least 1,000);
* with ``jobs`` local processes;
* on a Dask LocalCluster of two worker processes, start-up included (goal: at most
  1.5 times the ``jobs=2`` time), with the same rows in the same order.

Usage::

    python benchmarks/batch_speed.py [--copies 40] [--jobs 2] [--no-dask]
"""

from __future__ import annotations

import argparse
import resource
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from structure.batch import batch_items, classify_batch  # noqa: E402
from structure.chains import enumerate_chains  # noqa: E402
from structure.parallel import ordered_map  # noqa: E402

GOAL_RATE = 1000.0  # mechanisms per second per core
GOAL_DASK = 1.5  # Dask LocalCluster time / jobs=2 time


def _cpu() -> float:
    """CPU seconds of this process and of its finished children (pool or Dask workers)."""
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + children.ru_utime + children.ru_stime


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--copies", type=int, default=40)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--no-dask", action="store_true")
    args = parser.parse_args()
    files = sorted(str(p) for p in (ROOT / "fixtures").glob("*.edges"))
    items = list(batch_items(files)) * args.copies
    print(f"## {len(items)} mechanisms ({len(files)} fixtures x {args.copies})")
    wall, cpu = time.perf_counter(), time.process_time()
    rows = list(classify_batch(items))
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    rate = len(items) / cpu
    verdict = "met" if rate >= GOAL_RATE else f"MISSED by {GOAL_RATE - rate:.0f}/s"
    print(
        f"  one process: {wall:.2f} s, {len(items) / wall:.0f} mechanisms/s wall, "
        f"{rate:.0f} per CPU second (goal {GOAL_RATE:.0f}/s per core: {verdict})"
    )
    start, cpu = time.perf_counter(), _cpu()
    local = list(classify_batch(items, jobs=args.jobs))
    wall_jobs, cpu = time.perf_counter() - start, _cpu() - cpu
    assert local == rows
    print(
        f"  jobs {args.jobs}: {wall_jobs:.2f} s, {len(items) / wall_jobs:.0f} mechanisms/s "
        f"(cpu of all processes {cpu:.2f} s)"
    )
    if args.no_dask:
        return
    start, cpu = time.perf_counter(), _cpu()
    on_dask = list(classify_batch(items, dask_local=2))
    wall_dask, cpu = time.perf_counter() - start, _cpu() - cpu
    assert on_dask == rows
    ratio = wall_dask / wall_jobs
    verdict = "met" if ratio <= GOAL_DASK else "MISSED"
    print(
        f"  Dask LocalCluster (2 workers, start-up included): {wall_dask:.2f} s "
        f"(cpu {cpu:.2f} s), "
        f"{ratio:.2f}x jobs {args.jobs} (goal {GOAL_DASK}x: {verdict}); same rows, same order"
    )
    start = time.perf_counter()
    list(ordered_map(enumerate_chains, [4], dask_local=2))
    start_up = time.perf_counter() - start
    print(
        f"  of which start-up and shutdown (cluster, worker imports): {start_up:.2f} s; "
        f"without it {(wall_dask - start_up) / wall_jobs:.2f}x"
    )


if __name__ == "__main__":
    main()
