"""Path synthesis: candidate evaluations per second, ours against pylinkage's optimiser.

The same problem on both sides: the ten points on an ellipse of the path-synthesis literature
(x = 10 + 10·cos t, y = 10 + 8·sin t, t = 0°, 40°, ..., 360°), a four-bar with a coupler
point, and the same candidates (crank–rockers drawn around one design: ground 8, crank 2,
coupler 8, rocker 6, the coupler point 4 from B at 30° to BC). What is timed per candidate:

* **pylinkage**: what its optimisers (``pylinkage.optimization``, e.g.
  ``differential_evolution_optimization``) evaluate for each candidate through
  ``kinematic_minimization``: ``set_coords`` of the initial positions, ``set_constraints``
  of the candidate's dimensions, ``step`` through one crank turn of 96 poses (an unbuildable
  pose raises and scores infinity), then the fitness: each target's distance to the 96
  points of the coupler point's locus.
* **ours, 96 poses**: the same work vectorised over the candidates of one generation:
  :func:`~kinematics.synthesis.linkages.linkage_poses` of every candidate at the same 96
  crank angles, the dyad's closure at each (h² > 0), the same fitness.
* **ours, search**: what our search evaluates per candidate
  (:func:`kinematics.synthesis.path._evaluate`): the candidate at the ten targets' crank
  angles only, its placement and coupler point fitted in closed form, Grashof's rule and
  the exact extremes of the transmission angle in place of the 96-pose sweep.

Each round times the three on the same candidates, interleaved; the medians of the rounds
are printed, with the machine's load average. Goal: ours at least 5× pylinkage's.

Usage::

    python benchmarks/synthesis_speed.py [--candidates 225] [--rounds 7]
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kinematics.synthesis.linkages import Linkage, linkage_poses
from kinematics.synthesis.path import PathProblem, _angles, _evaluate, _full, _scale

POSES = 96
_T = np.radians(np.arange(0, 361, 40))
TARGETS = np.column_stack([10 + 10 * np.cos(_T), 10 + 8 * np.sin(_T)])
# ground d, crank a, coupler b, rocker c, coupler point: distance r from B, angle alpha to BC
BASE = np.array([8.0, 2.0, 8.0, 6.0, 4.0, math.radians(30)])


def candidates(n: int, seed: int) -> np.ndarray:
    """``n`` crank–rockers around :data:`BASE`: each number within ±10 %, but the ground (a
    pylinkage optimiser moves the links' dimensions, not the ground pivots)."""
    rng = np.random.default_rng(seed)
    factors = rng.uniform(0.9, 1.1, size=(n, len(BASE)))
    factors[:, 0] = 1.0
    return BASE * factors


# ------------------------------------------------------------------ pylinkage
def pylinkage_setup():
    """The four-bar with its coupler point as a pylinkage linkage, and its scoring function."""
    import pylinkage as pl
    from pylinkage.optimization.utils import kinematic_minimization

    o1 = pl.Ground(0.0, 0.0, name="A")
    o2 = pl.Ground(BASE[0], 0.0, name="D")
    crank = pl.Crank(anchor=o1, radius=BASE[1], angular_velocity=2 * math.pi / POSES, name="B")
    rocker = pl.RRRDyad(crank.output, o2, distance1=BASE[2], distance2=BASE[3], name="C")
    point = pl.FixedDyad(crank.output, rocker, distance=BASE[4], angle=BASE[5], name="P")
    linkage = pl.Linkage([o1, o2, crank, rocker, point], name="four-bar")
    start = tuple(linkage.get_coords())

    @kinematic_minimization
    def fitness(linkage, params, init_pos, loci):
        locus = np.array([frame[-1] for frame in loci], dtype=float)
        gaps = np.linalg.norm(locus[None, :, :] - TARGETS[:, None, :], axis=2)
        return float((gaps.min(axis=1) ** 2).sum())

    def score(dims: np.ndarray) -> float:
        # pylinkage's constraints: crank radius, the dyad's two distances, P's distance, angle
        return fitness(linkage, [dims[1], dims[2], dims[3], dims[4], dims[5]], start)

    return linkage, score


def time_pylinkage(score, dims: np.ndarray) -> tuple[float, np.ndarray]:
    started = time.perf_counter()
    values = np.array([score(row) for row in dims])
    return time.perf_counter() - started, values


# ------------------------------------------------------------------ ours
def rows(dims: np.ndarray) -> np.ndarray:
    """Our design rows (ax, ay, θ0, d, a, b, c, p, q, φ1, side) of the same candidates."""
    n = len(dims)
    p, q = dims[:, 4] * np.cos(dims[:, 5]), dims[:, 4] * np.sin(dims[:, 5])
    zero, one = np.zeros(n), np.ones(n)
    # the side pylinkage's RRRDyad picks from its initial positions: C above the line BD
    return np.column_stack([zero, zero, zero, *dims[:, :4].T, p, q, zero, one])


def time_ours_96(dims: np.ndarray) -> tuple[float, np.ndarray]:
    started = time.perf_counter()
    x = rows(dims)
    phi = np.linspace(0.0, 2 * math.pi, POSES, endpoint=False)[None, :]
    poses = linkage_poses(Linkage.FOURBAR, x, np.broadcast_to(phi, (len(x), POSES)))
    closes = poses.heights[0].min(axis=1) > 0
    locus = poses.points["P"]
    gaps = np.linalg.norm(locus[:, None, :, :] - TARGETS[None, :, None, :], axis=3)
    values = np.where(closes, (gaps.min(axis=2) ** 2).sum(axis=1), np.inf)
    return time.perf_counter() - started, values


def search_setup(n: int, seed: int):
    """One generation of our search's candidates on the same problem (no timing)."""
    s, _, _ = _scale(PathProblem(TARGETS))
    rng = np.random.default_rng(seed)
    return s, s.low + (s.high - s.low) * rng.random((n, len(s.names)))


def time_ours_search(s, z: np.ndarray) -> float:
    started = time.perf_counter()
    x = _full(s, z)
    _evaluate(s, x, _angles(s, z, x))
    return time.perf_counter() - started


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--candidates", type=int, default=225, help="per round (one generation)")
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args(argv)
    n = args.candidates
    _, score = pylinkage_setup()
    # the two agree on the same candidate (the same locus, the same fitness)
    probe = candidates(3, 99)
    _, theirs = time_pylinkage(score, probe)
    _, ours = time_ours_96(probe)
    print(f"same fitness on 3 candidates: pylinkage {theirs}, ours {ours}")
    if not np.allclose(theirs, ours, rtol=1e-9):
        print("the two evaluations disagree: the comparison is void")
        return 1
    t_py, t_96, t_search = [], [], []
    for r in range(args.rounds):
        dims = candidates(n, r)
        s, z = search_setup(n, r)
        t_py.append(time_pylinkage(score, dims)[0])
        t_96.append(time_ours_96(dims)[0])
        t_search.append(time_ours_search(s, z))
    py, o96, osearch = (n / statistics.median(t) for t in (t_py, t_96, t_search))
    load = os.getloadavg()
    print(
        f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; {n} candidates a round, "
        f"{args.rounds} rounds, medians"
    )
    print(f"pylinkage (96 poses each):        {py:12.0f} evaluations/s")
    print(f"ours, 96 poses each:              {o96:12.0f} evaluations/s  ({o96 / py:.0f}x)")
    print(f"ours, as the search evaluates:    {osearch:12.0f} evaluations/s  ({osearch / py:.0f}x)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
