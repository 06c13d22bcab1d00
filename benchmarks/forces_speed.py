"""Kinetostatics over a sweep: time per pose of the reactions relative to the kinematics alone.

For the four-bar of problem 3.4 (a force on the rocker) with masses on every link, the
kinematic sweep (``solve_poses``: positions, velocities, accelerations) and the force sweep
(``forces_over``: inertia loads, every reaction, the balancing moment and the virtual-power
check at every pose) are timed side by side over N = 10^3, 10^4, 10^5 poses of one crank turn.

Usage::

    python benchmarks/forces_speed.py [--sizes 1000 10000 100000]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kinematics.forces import forces_over
from kinematics.plan import make_plan
from kinematics.solve import solve_poses
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


def best(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000])
    args = parser.parse_args(argv)
    plan = make_plan(analyze(parse_edgelist(FOURBAR.strip().splitlines())))
    print(
        f"{'N':>8} {'kinematics us/pose':>20} {'+ forces us/pose':>18} {'forces/kinematics':>18}"
        f" {'max power residual':>19}"
    )
    for n in args.sizes:
        inputs = np.linspace(0.0, 2 * np.pi, n, endpoint=False)[:, None]
        repeat = 5 if n <= 10_000 else 2
        t_kin = best(lambda inputs=inputs: solve_poses(plan, inputs), repeat)
        motion = solve_poses(plan, inputs)
        t_force = best(lambda motion=motion: forces_over(plan, motion), repeat)
        result = forces_over(plan, motion)
        print(
            f"{n:>8} {t_kin / n * 1e6:>20.3f} {t_force / n * 1e6:>18.3f} "
            f"{t_force / t_kin:>17.2f}x {result.power_residual.max():>19.2e}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
