"""Kinetostatics over a sweep: time per pose of the reactions relative to the kinematics alone.

For the four-bar of problem 3.4 (a force on the rocker) with masses on every link, over
N = 10^3, 10^4, 10^5 poses of one crank turn, two things a user calls are timed side by side:

* **kinematics**: ``sweep(plan, inputs)`` (no loads in the plan, so no forces), then every
  named point's position, velocity and acceleration and every link's ω and ε read out;
* **forces**: ``forces_over(plan, solve_poses(plan, inputs))`` from the same inputs: the
  positions and rates it needs, the inertia loads, every reaction, the balancing moment and
  the virtual-power check at every pose.

Times are medians of interleaved rounds; the ratio forces/kinematics at the largest N is
printed last (goal: at most 2x).

Usage::

    python benchmarks/forces_speed.py [--sizes 1000 10000 100000] [--rounds R]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kinematics.forces import forces_over
from kinematics.plan import make_plan
from kinematics.solve import solve_poses
from kinematics.sweep import sweep
from structure.readwrite.edgelist import parse_edgelist
from structure.report import analyze

FOURBAR = """
name four-bar with a load and masses
driver 1 omega=10
0 1 R A
1 2 R B
2 3 R C
3 0 R D
point A 0 0
point B 0.05 0.0866025403784
point C 0.333074 0.29244
point D 0.4 0
point S1 0.025 0.0433 on=1
point S2 0.19 0.19 on=2
point S3 0.37 0.15 on=3
force 3 S3 0 -1000
mass 1 0.5 0.0004 S1
mass 2 2.0 0.02 S2
mass 3 1.5 0.01 S3
gravity 0 -9.81
"""
GOAL = 2.0  # forces over a sweep / the kinematics, at most


def interleaved(fns: dict, rounds: int) -> dict[str, float]:
    """The median time of each function over ``rounds`` rounds, one run of each per round."""
    times: dict[str, list[float]] = {k: [] for k in fns}
    for _ in range(rounds):
        for name, fn in fns.items():
            start = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - start)
    return {k: float(np.median(v)) for k, v in times.items()}


def kinematics(plan, inputs: np.ndarray) -> list:
    """The public sweep, every named point's and link's arrays read out."""
    result = sweep(plan, inputs)
    points = [result.points[p][k] for p in result.points for k in result.points[p]]
    return points + [result.links[x][k] for x in result.links for k in ("omega", "epsilon")]


def _load() -> str:
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - platform
        return "?"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000])
    parser.add_argument("--rounds", type=int, default=None, help="interleaved rounds (9/7/5)")
    args = parser.parse_args(argv)
    plan = make_plan(analyze(parse_edgelist(FOURBAR.strip().splitlines())))
    loadless = [
        x
        for x in FOURBAR.strip().splitlines()
        if x.split()[:1] not in (["force"], ["mass"], ["gravity"])
    ]
    bare = make_plan(analyze(parse_edgelist(loadless)))
    print(f"goal: forces over a sweep <= {GOAL:g}x the kinematics; load {_load()}")
    print(
        "medians of interleaved rounds; kinematics = sweep() with every point and link read "
        "out, forces = forces_over(plan, solve_poses(plan, inputs))"
    )
    print(
        f"{'N':>8} {'kinematics us/pose':>20} {'forces us/pose':>16} {'forces/kinematics':>18}"
        f" {'max power residual':>19}"
    )
    ratio = 0.0
    for n in args.sizes:
        inputs = np.linspace(0.0, 2 * np.pi, n, endpoint=False)[:, None]
        rounds = args.rounds or (9 if n <= 1000 else 7 if n <= 10_000 else 5)
        fns = {
            "kinematics": lambda inputs=inputs: kinematics(bare, inputs),
            "forces": lambda inputs=inputs: forces_over(plan, solve_poses(plan, inputs)),
        }
        for fn in fns.values():
            fn()
        t = interleaved(fns, rounds)
        result = forces_over(plan, solve_poses(plan, inputs))
        ratio = t["forces"] / t["kinematics"]
        print(
            f"{n:>8} {t['kinematics'] / n * 1e6:>20.3f} {t['forces'] / n * 1e6:>16.3f} "
            f"{ratio:>17.2f}x {result.power_residual.max():>19.2e}"
        )
    print(f"load average after the run: {_load()}")
    met = ratio <= GOAL
    print(
        f"forces/kinematics at N = {args.sizes[-1]}: {ratio:.2f}x (<= {GOAL:g}x) "
        f"{'met' if met else 'FAILED'}"
    )
    return 0 if met else 2


if __name__ == "__main__":
    sys.exit(main())
