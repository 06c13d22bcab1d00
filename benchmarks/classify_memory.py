"""Peak memory of ``assur classify`` on a large edge list (issue 11: 10^6 lines in at most 1 GB).

A random mechanism (every group kind, some compound hinges) of about
``--lines`` edge-list lines is written to a temporary file; then
``python -m kinematics classify FILE`` (text, and ``--json``) runs in a child
process each, and the child's peak resident set (``getrusage`` of the child)
is printed with the file's size. Not a timed test: a measurement.

Usage::

    python benchmarks/classify_memory.py [--lines 1000000] [--seed 1] [--file PATH]
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from structure.generators import random_mechanism_with_groups  # noqa: E402
from structure.readwrite.edgelist import write_edgelist  # noqa: E402

GOAL_MB = 1024.0  # at 10^6 lines
LINES_PER_LINK = 1.5  # the generator writes about 1.5 pair lines per moving link


def _child_peak(argv: list[str]) -> tuple[float, float, int]:
    """Peak RSS (MB) and wall time (s) of one child process, and its exit code."""
    code = (
        "import resource, runpy, sys\n"
        f"sys.argv = {['assur', *argv]!r}\n"
        "try:\n"
        "    runpy.run_module('kinematics', run_name='__main__')\n"
        "except SystemExit as exc:\n"
        "    rc = exc.code or 0\n"
        "else:\n"
        "    rc = 0\n"
        "sys.stdout.flush()\n"
        "peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss\n"
        "sys.stderr.write(f'PEAK {peak}\\n')\n"
        "sys.exit(rc)\n"
    )
    start = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        check=False,
    )
    wall = time.perf_counter() - start
    peak_kb = max(
        (int(line.split()[1]) for line in done.stderr.splitlines() if line.startswith("PEAK ")),
        default=0,
    )
    if peak_kb == 0:  # the child died before reporting: fall back on the children's maximum
        peak_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return peak_kb / 1024.0, wall, done.returncode


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--file", help="an existing edge list (skips the generation)")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        path = args.file
        if path is None:
            links = int(args.lines / LINES_PER_LINK) | 1
            mechanism, _ = random_mechanism_with_groups(links, seed=args.seed, compound=0.2)
            path = os.path.join(tmp, "large.edges")
            Path(path).write_text(write_edgelist(mechanism))
            del mechanism
        size = os.path.getsize(path)
        with open(path, encoding="utf-8") as fh:
            lines = sum(1 for _ in fh)
        print(f"file: {lines} lines, {size / 2**20:.1f} MB")
        worst = 0.0
        for mode in ([], ["--json"]):
            peak, wall, rc = _child_peak(["classify", *mode, path])
            worst = max(worst, peak)
            label = " ".join(["classify", *mode])
            print(f"{label:18s} peak {peak:8.1f} MB  {peak * 2**20 / lines:7.0f} B/line  "
                  f"{wall:6.1f} s  exit {rc}")  # fmt: skip
    goal = GOAL_MB * lines / 1_000_000
    verdict = "meets" if worst <= goal else "misses"
    print(f"peak {worst:.1f} MB for {lines} lines: {verdict} the goal of {goal:.0f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
