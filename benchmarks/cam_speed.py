"""Cam design: every check of a 3,600-sample design, timed in one process (goal: each ≤ 20 ms).

For the issue's example design (an offset roller, a cycloidal rise and a modified-trapezoid
return between dwells, a spring and a follower mass) and for an oscillating flat-faced one (a
fitted polynomial rise, a 4-5-6-7 return), each step ``assur cam`` runs is timed on N = 3,600
cam angles (0.1°), interleaved, medians of the rounds:

* **svaj**: s, v, a, j at every angle (closed form, per segment);
* **joins+peaks**: the continuity at each join and the peaks at each law's own extremes;
* **geometry**: the pitch curve, profile, normals, radii of curvature, pressure angle;
* **checks**: pressure angle (largest, refined), smallest convex and concave radii of the pitch
  curve and profile (refined), undercut, face width;
* **base circle**: the smallest base circle meeting the pressure limit with no undercut (and
  the best offset, for the roller);
* **closure**: contact force, camshaft torque, jump speed, preload and rate needed;
* **report**: all of them together, as ``assur cam`` runs them (``cam_report``);
* **json**: the report's JSON form (the contract's dict).

A baseline is timed in the same rounds, so that the figures travel between machines: one
numpy pass of ``sin`` and ``cos`` over the same N angles (``ratio`` = step / baseline). Also
timed, for the record, not against the goal: the designed cam swept as a mechanism over
3,600 poses (``sweep``: the follower placed by the program, its rates from the replacement
rebuilt at every pose).

Usage::

    python benchmarks/cam_speed.py [--samples 3600] [--rounds 15]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kinematics.cams.checks import cam_angles, check_cam, smallest_base_circle
from kinematics.cams.closure import force_closure
from kinematics.cams.design import make_design
from kinematics.cams.mechanism import cam_mechanism
from kinematics.cams.profile import cam_geometry
from kinematics.cams.program import continuity, peaks, time_values
from kinematics.cams.summary import cam_report, cam_report_to_dict
from kinematics.solvers.plan import make_plan
from kinematics.solvers.sweep import sweep
from structure.readwrite.camfile import read_cam_spec
from structure.report import analyze

FIXTURES = Path(__file__).resolve().parent.parent / "examples" / "cams"
GOAL = 0.020  # seconds, every check


def interleaved(fns: dict, rounds: int) -> dict[str, float]:
    """The median time of each function over ``rounds`` rounds, one run of each per round."""
    times: dict[str, list[float]] = {k: [] for k in fns}
    for _ in range(rounds):
        for name, fn in fns.items():
            start = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - start)
    return {k: float(np.median(v)) for k, v in times.items()}


def steps(design, samples: int) -> dict:
    """The checks of ``design`` on ``samples`` angles, each a function to time."""
    theta = cam_angles(samples)
    report = cam_report(design, samples)
    return {
        "baseline": lambda: (np.sin(theta), np.cos(theta)),
        "svaj": lambda: time_values(design.program, theta, design.omega),
        "joins+peaks": lambda: (
            continuity(design.program),
            peaks(design.program, design.omega, theta),
        ),
        "geometry": lambda: cam_geometry(design, theta),
        "checks": lambda: check_cam(design, samples),
        "base circle": lambda: smallest_base_circle(design, samples),
        "closure": lambda: force_closure(design, samples),
        "report": lambda: cam_report(design, samples),
        "json": lambda: cam_report_to_dict(report),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=3600)
    parser.add_argument("--rounds", type=int, default=15)
    args = parser.parse_args()
    worst = 0.0
    for name in ("offset_roller.json", "rocker_flat.json"):
        design = make_design(read_cam_spec(FIXTURES / name))
        found = interleaved(steps(design, args.samples), args.rounds)
        base = found.pop("baseline")
        print(f"\n{design.spec.name}: N = {args.samples} cam angles, {args.rounds} rounds")
        print(f"  {'step':<12} {'median (ms)':>12} {'× baseline':>11}")
        print(f"  {'baseline':<12} {base * 1e3:12.3f} {1.0:11.1f}")
        for step, seconds in found.items():
            print(f"  {step:<12} {seconds * 1e3:12.3f} {seconds / base:11.1f}")
            if step not in ("report", "json"):
                worst = max(worst, seconds)
        plan = make_plan(analyze(cam_mechanism(design)))
        swept = interleaved({"sweep": lambda plan=plan: sweep(plan, steps=args.samples)}, 5)
        print(f"  (the cam swept as a mechanism, {args.samples} poses: "
              f"{swept['sweep'] * 1e3:.1f} ms)")  # fmt: skip
    verdict = "met" if worst <= GOAL else "NOT met"
    print(f"\nslowest check: {worst * 1e3:.2f} ms (goal ≤ {GOAL * 1e3:.0f} ms: {verdict})")
    return 0 if worst <= GOAL else 1


if __name__ == "__main__":
    sys.exit(main())
