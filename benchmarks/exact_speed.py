"""How long the exact answers (``--exact``) take: every fixture, kinematics and forces.

Issue 22, item 15: every fixture's exact answer in at most 5 s. For each
fixture (and the two test inputs of the issue, a four-bar with a √3
coordinate and a five-bar with √3 and √7) this times, in one process, the
exact kinematics (:func:`~kinematics.solvers.exact.solve_exact`) and the exact
forces (:func:`~kinematics.solvers.exact.forces_exact`) after the plan is made:
the best of ``--rounds`` runs (sympy caches what it can between them, so the first run is
also printed). A fixture the solvers refuse (no coordinates, over-constrained)
prints its error. A run past ``--limit`` seconds is stopped by an alarm.

The same script times an older tree: ``--tree PATH`` imports ``kinematics`` and
``structure`` from there (its solvers may have no ``timeout``).

Usage::

    python benchmarks/exact_speed.py [--rounds 3] [--limit 300] [--tree PATH] [FILE ...]
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent.parent
GOAL = 5.0  # s, each fixture's exact answer
EXTRA = sorted((HERE / "tests" / "kinematics" / "solvers" / "data").glob("*.edges"))


class _Late(Exception):
    pass


def _ring(signum, frame):
    raise _Late


def _timed(function, plan, limit: float) -> float | str:
    signal.signal(signal.SIGALRM, _ring)
    signal.setitimer(signal.ITIMER_REAL, limit)
    start = time.perf_counter()
    try:
        function(plan)
    except _Late:
        return f"> {limit:g} s"
    except Exception as exc:  # a refusal is a result here
        return f"{type(exc).__name__}"
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--limit", type=float, default=300.0)
    parser.add_argument("--tree", type=Path, default=HERE)
    args = parser.parse_args()
    sys.path.insert(0, str(args.tree.resolve()))
    from kinematics.solvers.exact import forces_exact, solve_exact
    from kinematics.solvers.plan import make_plan
    from structure import analyze, read_edgelist

    files = args.files or [*sorted((HERE / "fixtures").glob("*.edges")), *EXTRA]
    worst = 0.0
    print(f"{'file':42s} {'kinematics':>22s} {'forces':>22s}   (first run / best of rounds, s)")
    for path in files:
        try:
            plan = make_plan(analyze(read_edgelist(path)))
        except Exception as exc:  # no coordinates: no exact answer
            print(f"{path.name:42s} {type(exc).__name__}")
            continue
        cells = []
        for function in (solve_exact, forces_exact):
            runs = [_timed(function, plan, args.limit) for _ in range(args.rounds)]
            if isinstance(runs[0], str):
                cells.append(runs[0])
                continue
            worst = max(worst, runs[0])
            cells.append(f"{runs[0]:.3f} / {min(runs):.3f}")
        print(f"{path.name:42s} {cells[0]:>22s} {cells[1]:>22s}")
    print(f"slowest first run: {worst:.3f} s (goal: at most {GOAL:g} s)")


if __name__ == "__main__":
    main()
