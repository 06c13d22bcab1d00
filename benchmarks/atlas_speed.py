"""How fast the atlas is: chain enumeration, canonical labelling, classification.

Sections (each prints its figures and the goal of the issue):

* **enumerate**: the non-isomorphic 1-DOF chains of each link count, checked
  against the published counts (1, 2, 16, 230, 6856 for 4-12 links);
* **canonical**: the canonical labelling of the 12-link chains (or the largest
  enumerated) by structure.canonical (pure Python, what the atlas uses), by
  pynauty when it is installed, and by networkx (WL-hash buckets and VF2 for the
  isomorphism classes, VF2 for the automorphisms), the fallback the issue names;
* **ten**: the 10-link atlas with every labelled ground and driver choice
  classified, in one process and with ``jobs=2`` (goal: at most 30 s);
* **dask** (``--dask``): the same job on a Dask LocalCluster of two worker processes
  (goal: at most 1.5 times the ``jobs=2`` time);
* **twelve** (``--twelve``): the 12-link atlas, 6856 chains enumerated and every
  distinct mechanism classified with ``jobs=2`` (goal: at most 15 min), and what
  14 links would cost at the same rate.

Wall times depend on what else runs on the machine; CPU times (``process_time``)
are given for the single-process runs.

Usage::

    python benchmarks/atlas_speed.py [--links 4 6 8 10 12] [--dask] [--twelve] [--jobs 2]
"""

from __future__ import annotations

import argparse
import resource
import sys
import time
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import networkx as nx
from networkx.algorithms.isomorphism import GraphMatcher

from structure.atlas import atlas, labelled_count, mechanism_choices
from structure.canonical import canonical_form
from structure.chains import KinematicChain, enumerate_chains
from structure.parallel import ordered_map

PUBLISHED = {4: 1, 6: 2, 8: 16, 10: 230, 12: 6856, 14: 318162}
GOAL_TEN = 30.0  # s, 10-link atlas, every labelled choice classified
GOAL_TWELVE = 900.0  # s, 12-link atlas enumerated and classified
GOAL_DASK = 1.5  # Dask LocalCluster time / jobs=2 time


def _cpu() -> float:
    """CPU seconds of this process and of its finished children (pool or Dask workers)."""
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + children.ru_utime + children.ru_stime


def _timed(function, *args, **kwargs):
    """``(result, wall seconds, CPU seconds of every process)``."""
    wall, cpu = time.perf_counter(), _cpu()
    result = function(*args, **kwargs)
    return result, time.perf_counter() - wall, _cpu() - cpu


def enumerate_section(counts: list[int]) -> dict[int, tuple[KinematicChain, ...]]:
    print("## enumerate (1-DOF, no rigid subchain)")
    found = {}
    for n in counts:
        chains, wall, cpu = _timed(enumerate_chains, n)
        check = "ok" if PUBLISHED.get(n) == len(chains) else f"PUBLISHED {PUBLISHED.get(n)}"
        print(f"  {n:2d} links: {len(chains):6d} chains in {wall:7.2f} s (cpu {cpu:.2f} s) {check}")
        found[n] = chains
    return found


def _adjacency(chain: KinematicChain) -> list[dict[int, int]]:
    adjacency: list[dict[int, int]] = [{} for _ in range(chain.links)]
    for i, j in chain.joints:
        adjacency[i][j] = adjacency[j][i] = 1
    return adjacency


def canonical_section(chains: tuple[KinematicChain, ...]) -> None:
    n = chains[0].links
    print(f"## canonical labelling of the {len(chains)} chains of {n} links")
    adjacency = [_adjacency(c) for c in chains]
    _, wall, _ = _timed(lambda: [canonical_form(n, a) for a in adjacency])
    per = wall / len(chains) * 1e6
    print(f"  structure.canonical (pure Python): {wall:6.2f} s, {per:6.0f} µs per chain")
    try:
        import pynauty  # optional, only measured
    except ImportError:
        print("  pynauty: not installed (pip install pynauty builds nauty from source)")
    else:

        def with_pynauty() -> None:
            for a in adjacency:
                graph = pynauty.Graph(n, adjacency_dict={v: list(a[v]) for v in range(n)})
                pynauty.certificate(graph)
                pynauty.autgrp(graph)

        _, wall, _ = _timed(with_pynauty)
        per = wall / len(chains) * 1e6
        print(f"  pynauty certificate + autgrp:      {wall:6.2f} s, {per:6.0f} µs per chain")
    graphs = [nx.Graph(list(c.joints)) for c in chains]
    warnings.filterwarnings("ignore", message="The hashes produced", category=UserWarning)

    def networkx_classes() -> None:
        buckets: dict[str, list[nx.Graph]] = {}
        for g in graphs:
            bucket = buckets.setdefault(nx.weisfeiler_lehman_graph_hash(g, iterations=3), [])
            if not any(nx.is_isomorphic(g, h) for h in bucket):
                bucket.append(g)

    _, wall, _ = _timed(networkx_classes)
    per = wall / len(chains) * 1e6
    print(f"  networkx WL hash + VF2 classes:    {wall:6.2f} s, {per:6.0f} µs per chain")
    _, wall, _ = _timed(
        lambda: [sum(1 for _ in GraphMatcher(g, g).isomorphisms_iter()) for g in graphs]
    )
    per = wall / len(chains) * 1e6
    print(f"  networkx VF2 automorphisms:        {wall:6.2f} s, {per:6.0f} µs per chain")


def ten_section(chains, jobs: int, dask: bool) -> None:
    labelled = sum(labelled_count(c) for c in chains)
    print(f"## 10-link atlas, every labelled choice classified ({labelled} mechanisms)")
    rows, wall, cpu = _timed(lambda: list(atlas(10, labelled=True, chains=chains)))
    assert len(rows) == labelled
    print(f"  jobs 1: {wall:6.2f} s (cpu {cpu:.2f} s, {labelled / cpu:.0f} mechanisms/cpu-s)")
    local, wall_jobs, cpu_jobs = _timed(
        lambda: list(atlas(10, labelled=True, chains=chains, jobs=jobs))
    )
    assert local == rows
    verdict = "met" if wall_jobs <= GOAL_TEN else f"MISSED by {wall_jobs - GOAL_TEN:.1f} s"
    print(
        f"  jobs {jobs}: {wall_jobs:6.2f} s (cpu of all processes {cpu_jobs:.2f} s; "
        f"goal {GOAL_TEN:.0f} s: {verdict})"
    )
    if dask:
        on_dask, wall_dask, cpu_dask = _timed(
            lambda: list(atlas(10, labelled=True, chains=chains, dask_local=2))
        )
        assert on_dask == rows
        _dask_verdict(wall_dask, cpu_dask, wall_jobs, jobs)


def _dask_verdict(wall_dask: float, cpu_dask: float, wall_jobs: float, jobs: int) -> None:
    """Print the Dask time against the local processes', with and without its start-up."""
    _, start_up, _ = _timed(lambda: list(ordered_map(enumerate_chains, [4], dask_local=2)))
    ratio = wall_dask / wall_jobs
    verdict = "met" if ratio <= GOAL_DASK else "MISSED"
    print(
        f"  Dask LocalCluster (2 workers): {wall_dask:6.2f} s (cpu {cpu_dask:.2f} s), "
        f"{ratio:.2f}x jobs {jobs} (goal {GOAL_DASK}x: {verdict}); same rows, same order"
    )
    print(
        f"  of which start-up and shutdown (cluster, worker imports): {start_up:.2f} s; "
        f"without it {(wall_dask - start_up) / wall_jobs:.2f}x"
    )


def twelve_section(jobs: int, dask: bool) -> None:
    print("## 12-link atlas: enumerate and classify every distinct mechanism")
    start, cpu = time.perf_counter(), _cpu()
    chains = enumerate_chains(12)
    enumerated = time.perf_counter() - start
    distinct = sum(len(mechanism_choices(c)) for c in chains)
    labelled = sum(labelled_count(c) for c in chains)
    print(
        f"  {len(chains)} chains enumerated in {enumerated:.1f} s: {distinct} distinct "
        f"mechanisms ({labelled} labelled choices)"
    )
    count = 0
    classes: dict[int | None, int] = {}
    rows = []
    for row in atlas(12, chains=chains, jobs=jobs):
        count += 1
        classes[row.mechanism_class] = classes.get(row.mechanism_class, 0) + 1
        if dask:
            rows.append(row)
    total, cpu = time.perf_counter() - start, _cpu() - cpu
    verdict = "met" if total <= GOAL_TWELVE else f"MISSED by {total - GOAL_TWELVE:.0f} s"
    print(f"  classified {count} mechanisms, total {total:.0f} s with jobs {jobs}, cpu of all "
          f"processes {cpu:.0f} s (goal {GOAL_TWELVE:.0f} s: {verdict})")  # fmt: skip
    print("  by class: " + ", ".join(f"{k}: {v}" for k, v in sorted(classes.items())))
    if dask:
        wall_jobs = total - enumerated
        on_dask, wall_dask, cpu_dask = _timed(lambda: list(atlas(12, chains=chains, dask_local=2)))
        assert on_dask == rows
        _dask_verdict(wall_dask, cpu_dask, wall_jobs, jobs)
    per = cpu / count
    # 14 links: 318162 chains of 19 pins, 38 labelled choices each; the share of distinct
    # ones is taken from 12 links (fewer symmetric chains at 14: an upper bound), the
    # cost of one mechanism scaled by its pins (19 / 16)
    mechanisms = 318162 * 38 * distinct / labelled
    estimate = mechanisms * per * 19 / 16
    print(
        f"  {per * 1000:.1f} ms per mechanism per core; 14 links (318162 chains, at most "
        f"{mechanisms / 1e6:.1f} million distinct mechanisms) would take about "
        f"{estimate / 3600:.0f} core-hours"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--links", type=int, nargs="+", default=[4, 6, 8, 10, 12])
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--dask", action="store_true", help="also run the 10-link job on Dask")
    parser.add_argument("--twelve", action="store_true", help="classify the 12-link atlas")
    args = parser.parse_args()
    found = enumerate_section(args.links)
    canonical_section(found[max(found)])
    if 10 in found:
        ten_section(found[10], args.jobs, args.dask)
    if args.twelve:
        twelve_section(args.jobs, args.dask)


if __name__ == "__main__":
    main()
