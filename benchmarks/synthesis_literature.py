"""The literature's four-bar path problems: published designs beside ours (the README's table).

For each of the five problems of ``tests/kinematics/synthesis/test_literature.py`` (their
statement and sources are there), prints the published designs' Σ of squared distances as
scored by our closed forms, whether each meets our rules (a crank that turns fully, a
transmission angle of at least 30° over the turn, links within a ratio of 10), and our
seeded searches under our rules and under the literature's looser ones (no transmission
bound, a ratio of 100): Σ, the largest distance, the transmission angles, the seconds.

Usage::

    python benchmarks/synthesis_literature.py [--jobs 2] [--seed 0] [--cases 1 2 3 4 5]
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kinematics.synthesis.linkages import grashof_kind, is_crank
from kinematics.synthesis.path import PathProblem, synthesize_path
from tests.kinematics.synthesis.test_literature import (
    CASE2_OTHERS,
    HCDJ,
    PROBLEMS,
    RULES,
    published_sum,
)


def rules_met(design: list[float]) -> str:
    """Whether a published design meets our default rules, and if not, which it breaks."""
    d, a, b, c = (np.array([v]) for v in design[:4])
    broken = []
    if not is_crank(d, a, b, c)[0]:
        broken.append(f"no crank ({grashof_kind(d, a, b, c)[0]})")
    else:
        narrow = math.acos(max(-1, min(1, (b * b + c * c - (d - a) ** 2)[0] / (2 * b * c)[0])))
        wide = math.acos(max(-1, min(1, (b * b + c * c - (d + a) ** 2)[0] / (2 * b * c)[0])))
        worst = math.degrees(min(narrow, math.pi - wide))
        if worst < 30:
            broken.append(f"μ {worst:.1f}°")
    ratio = max(design[:4]) / min(design[:4])
    if ratio > 10:
        broken.append(f"ratio {ratio:.0f}")
    return "meets ours" if not broken else ", ".join(broken)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--cases", type=int, nargs="*", default=sorted(PROBLEMS))
    args = parser.parse_args(argv)
    load = os.getloadavg()
    print(f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; jobs {args.jobs}")
    for case in args.cases:
        print(f"case {case}")
        published = {"HCDJ (Nguyen-Van et al. 2022)": HCDJ[case]}
        if case == 2:
            published.update(CASE2_OTHERS)
        for name, design in published.items():
            value = published_sum(case, design)
            print(f"  published {name}: Σ {value:.4g}; {rules_met(design)}")
        for rules in ("ours", "loose"):
            started = time.perf_counter()
            problem = PathProblem(**PROBLEMS[case], **RULES[rules], seed=args.seed)
            design = synthesize_path(problem, jobs=args.jobs)
            seconds = time.perf_counter() - started
            low, high = design.transmission_deg
            print(
                f"  ours, {rules} rules: Σ {design.error_sum_squares:.4g}, largest "
                f"{design.error_max:.3g}, μ {low:.1f}°..{high:.1f}°, {design.grashof}, "
                f"{seconds:.1f} s"
            )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
