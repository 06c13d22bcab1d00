"""Kinetostatics over a sweep: time per pose of the reactions relative to the kinematics alone.

For the four-bar of problem 3.4 (a force on the rocker), the offset crank-slider and Jansen's
leg (fixtures), each with a mass and a force on every moving link, over N = 10^3, 10^4, 10^5
poses of one crank turn, three things are timed side by side, interleaved:

* **kinematics**: ``sweep(plan, inputs)`` (no loads in the plan, so no forces), then every
  named point's position, velocity and acceleration and every link's ω and ε read out;
* **forces**: ``forces_over(plan, motion)`` alone, the motion solved beforehand;
* **solve+forces**: ``forces_over(plan, solve_poses(plan, inputs))`` from the same inputs:
  the positions and rates it needs, the inertia loads, every reaction, the balancing moment
  and the virtual-power check at every pose.

Times are medians of interleaved rounds; the worst ratio (solve+forces)/kinematics at the
largest N is printed last (goal: at most 2x).

Usage::

    python benchmarks/forces_speed.py [--sizes 1000 10000 100000] [--rounds R]
                                      [--mechanisms four-bar crank-slider Jansen]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kinematics.kinetostatics.forces import forces_over
from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_poses
from kinematics.solvers.sweep import sweep
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
FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
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


def _loaded(name: str) -> list[str]:
    """A fixture's lines with a mass and a force at a pin of every moving link, and gravity."""
    lines = (FIXTURES / f"{name}.edges").read_text().splitlines()
    mechanism = parse_edgelist(lines)
    extra = ["gravity 0 -9.81"]
    for k, link in enumerate(sorted(mechanism.moving_links)):
        point = next(p.point for p in mechanism.pairs_of(link) if p.point)
        extra.append(f"mass {link} {1.0 + 0.1 * k} {0.01 * (k + 1)} {point}")
        extra.append(f"force {link} {point} {10.0 * k} {-50.0 - k}")
    return lines + extra


def mechanisms() -> dict[str, list[str]]:
    """The benchmarked mechanisms' lines, loads included."""
    return {
        "four-bar": FOURBAR.strip().splitlines(),
        "crank-slider": _loaded("crank_slider"),
        "Jansen": _loaded("jansen"),
    }


def _load() -> str:
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - platform
        return "?"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000])
    parser.add_argument("--rounds", type=int, default=None, help="interleaved rounds (9/7/5)")
    parser.add_argument("--mechanisms", nargs="+", default=["four-bar", "crank-slider", "Jansen"])
    args = parser.parse_args(argv)
    print(f"goal: forces over a sweep <= {GOAL:g}x the kinematics; load {_load()}")
    print(
        "medians of interleaved rounds; kinematics = sweep() with every point and link read "
        "out, forces = forces_over(plan, motion), solve+forces = "
        "forces_over(plan, solve_poses(plan, inputs))"
    )
    print(
        f"{'mechanism':>13} {'N':>7} {'kinematics us':>14} {'forces us':>10} "
        f"{'solve+forces us':>16} {'forces/kin':>11} {'(solve+forces)/kin':>19} {'residual':>9}"
    )
    last: dict[str, float] = {}
    texts = mechanisms()
    for name in args.mechanisms:
        lines = texts[name]
        plan = make_plan(analyze(parse_edgelist(lines)))
        loadless = [x for x in lines if x.split()[:1] not in (["force"], ["mass"], ["gravity"])]
        bare = make_plan(analyze(parse_edgelist(loadless)))
        for n in args.sizes:
            inputs = np.linspace(0.0, 2 * np.pi, n, endpoint=False)[:, None]
            rounds = args.rounds or (9 if n <= 1000 else 7 if n <= 10_000 else 5)
            motion = solve_poses(plan, inputs)
            fns = {
                "kinematics": lambda inputs=inputs, bare=bare: kinematics(bare, inputs),
                "forces": lambda plan=plan, motion=motion: forces_over(plan, motion),
                "solve+forces": lambda inputs=inputs, plan=plan: forces_over(
                    plan, solve_poses(plan, inputs)
                ),
            }
            for fn in fns.values():
                fn()
            t = interleaved(fns, rounds)
            result = forces_over(plan, solve_poses(plan, inputs))
            ratio = t["solve+forces"] / t["kinematics"]
            last[name] = ratio
            us = {k: v / n * 1e6 for k, v in t.items()}
            print(
                f"{name:>13} {n:>7} {us['kinematics']:>14.3f} {us['forces']:>10.3f} "
                f"{us['solve+forces']:>16.3f} {t['forces'] / t['kinematics']:>10.2f}x "
                f"{ratio:>18.2f}x {result.power_residual.max():>9.1e}"
            )
    print(f"load average after the run: {_load()}")
    worst = max(last, key=last.__getitem__)
    met = last[worst] <= GOAL
    print(
        f"worst (solve+forces)/kinematics at N = {args.sizes[-1]}: {last[worst]:.2f}x ({worst}, "
        f"<= {GOAL:g}x) {'met' if met else 'FAILED'}"
    )
    return 0 if met else 2


if __name__ == "__main__":
    sys.exit(main())
