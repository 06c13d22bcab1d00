"""How fast the kinematics solve a crank turn, next to a hand-written solver and pylinkage.

For the four-bar (``fixtures/fourbar.edges``, coupler point M) and Jansen's
leg (``fixtures/jansen.edges``, foot F), one crank turn of N poses
(N = 10^3, 10^4, 10^5 by default) is timed side by side in one process:

* **ours**: ``kinematics.solve.solve_poses`` plus ``Motion.point`` for the
  coupler point / foot. The solve finds every pin's position, velocity and
  acceleration and keeps each link's motion as a frame; a link's angle θ,
  ω and ε are computed from it when first read (the angle needs an
  ``arctan2``, about 30 ns per link and pose). The plan is made once, outside
  the timing.
* **ours all**: the same, then every link's ``q, qd, qdd`` (N, 3) arrays
  (angles included) and every named point's position, velocity and
  acceleration read out: everything the hand solver gives and more.
* **hand**: a minimal closed-form numpy solver of the same linkage, written in
  this file (crank, circle–circle intersections with the sketch's assembly
  mode, rigid points as linear combinations), vectorised over the poses:
  positions, velocities and accelerations of every pin and of the coupler
  point / foot.
* **pylinkage** (only if it is installed; it is not a dependency of assur):
  ``Linkage.step_fast`` (numba, positions only) and
  ``Linkage.step_fast_with_kinematics`` (numba, positions + velocities +
  accelerations of every joint), over the same poses.

Time per pose is the best of a few runs. Before any timing, ours and hand are
cross-checked at every N: positions, velocities and accelerations of every
named point agree to 1e-9 relative (the largest difference over the largest
magnitude of that quantity); pylinkage is compared with ours too (reported,
not a gate).

Goals: at N = 10^5, ours within 1.5x of the hand-written solver, and at least
2x faster than pylinkage (with numba) for positions + velocities +
accelerations.

The eight-bar with a class III triad (``fixtures/eightbar_triad.edges``,
solved by Newton per pose) is timed over 10^4 poses (``--triad-poses``).

``--profile`` prints the cProfile top functions of ours at the largest N.

Exit status: 0 all goals met, 1 ours and hand disagree (or a solve failed),
2 agreement fine but a speed goal failed.

Usage::

    python benchmarks/kinematics_speed.py [--sizes 1000 10000 100000]
        [--repeat R] [--triad-poses 10000] [--profile] [--no-pylinkage]
"""

from __future__ import annotations

import argparse
import cProfile
import io
import math
import pstats
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from kinematics.plan import SolvePlan, make_plan  # noqa: E402
from kinematics.solve import solve_poses  # noqa: E402
from structure.readwrite.edgelist import read_edgelist  # noqa: E402
from structure.report import analyze  # noqa: E402

FIXTURES = ROOT / "fixtures"
GOAL_HAND = 1.5  # ours / hand at N = 10^5, at most
GOAL_PEER = 2.0  # pylinkage (pos + vel + acc) / ours at N = 10^5, at least
RTOL = 1e-9

try:  # an optional peer, installed in the benchmark environment only
    import pylinkage as pl
except ImportError:  # pragma: no cover - depends on the environment
    pl = None


def _plan(name: str) -> SolvePlan:
    return make_plan(analyze(read_edgelist(FIXTURES / f"{name}.edges")))


# ---------------------------------------------------------------------------
# (b) the hand-written closed-form solver
# ---------------------------------------------------------------------------
# A point is a tuple of (N,) arrays (x, y, vx, vy, ax, ay); a ground point
# has scalars for x, y and 0 for the rest.

Kin = tuple


def _ground(p: np.ndarray) -> Kin:
    return (float(p[0]), float(p[1]), 0.0, 0.0, 0.0, 0.0)


def _crank(pivot: np.ndarray, tip: np.ndarray, phi: np.ndarray, omega: float) -> Kin:
    """The crank tip turned by ``phi`` about ``pivot``; constant ω, so a = −ω² r."""
    c, s = np.cos(phi), np.sin(phi)
    dx, dy = tip - pivot
    rx, ry = c * dx - s * dy, s * dx + c * dy
    w2 = omega * omega
    return (pivot[0] + rx, pivot[1] + ry, -omega * ry, omega * rx, -w2 * rx, -w2 * ry)


def _rrr(p: Kin, r1: float, q: Kin, r2: float, sign: float) -> Kin:
    """The pin at distance r1 from ``p`` and r2 from ``q`` on the side ``sign``."""
    px, py, pvx, pvy, pax, pay = p
    qx, qy, qvx, qvy, qax, qay = q
    ex, ey = qx - px, qy - py
    d2 = ex * ex + ey * ey
    d = np.sqrt(d2)
    a = (r1 * r1 - r2 * r2 + d2) / (2.0 * d)
    h = sign * np.sqrt(r1 * r1 - a * a)
    cx = px + (a * ex - h * ey) / d
    cy = py + (a * ey + h * ex) / d
    # (c − p)·(v_c − v_p) = 0 and (c − q)·(v_c − v_q) = 0, by Cramer's rule
    ux, uy, wx, wy = cx - px, cy - py, cx - qx, cy - qy
    det = ux * wy - uy * wx
    b1 = ux * pvx + uy * pvy
    b2 = wx * qvx + wy * qvy
    vx = (b1 * wy - b2 * uy) / det
    vy = (ux * b2 - wx * b1) / det
    # (c − p)·(a_c − a_p) + |v_c − v_p|² = 0, the same for q
    rpx, rpy, rqx, rqy = vx - pvx, vy - pvy, vx - qvx, vy - qvy
    b1 = ux * pax + uy * pay - (rpx * rpx + rpy * rpy)
    b2 = wx * qax + wy * qay - (rqx * rqx + rqy * rqy)
    return (cx, cy, vx, vy, (b1 * wy - b2 * uy) / det, (ux * b2 - wx * b1) / det)


def _side(p: np.ndarray, q: np.ndarray, c: np.ndarray) -> float:
    """The sketch's assembly mode of the pin ``c`` over the base ``p``→``q``."""
    e, w = q - p, c - p
    return float(np.sign(e[0] * w[1] - e[1] * w[0]))


def _rigid(p: Kin, q: Kin, alpha: float, beta: float) -> Kin:
    """The point p + α(q − p) + β·J(q − p): linear in p and q, so in their rates too."""
    out = []
    for i in (0, 2, 4):
        dx, dy = q[i] - p[i], q[i + 1] - p[i + 1]
        out += [p[i] + alpha * dx - beta * dy, p[i + 1] + alpha * dy + beta * dx]
    return tuple(out)


def _coefficients(p: np.ndarray, q: np.ndarray, f: np.ndarray) -> tuple[float, float]:
    e, w = q - p, f - p
    e2 = float(e @ e)
    return float(e @ w) / e2, float(e[0] * w[1] - e[1] * w[0]) / e2


def _as_arrays(points: dict[str, Kin], n: int) -> dict[str, tuple[np.ndarray, ...]]:
    """``{name: (position, velocity, acceleration)}``, each (N, 2)."""
    out = {}
    for name, k in points.items():
        cols = [np.broadcast_to(np.asarray(x, dtype=float), (n,)) for x in k]
        out[name] = tuple(np.column_stack(cols[i : i + 2]) for i in (0, 2, 4))
    return out


def hand_fourbar(plan: SolvePlan) -> Callable[[np.ndarray], dict[str, Kin]]:
    """The four-bar A-B-C-D with coupler point M, from the sketch coordinates."""
    s = {k: v[1] for k, v in plan.points.items()}
    omega = plan.drivers[0].speed
    a, b, c, d, m = (s[k] for k in "ABCDM")
    bc, dc = float(np.hypot(*(c - b))), float(np.hypot(*(c - d)))
    sign = _side(b, d, c)
    alpha, beta = _coefficients(b, c, m)
    ga, gd = _ground(a), _ground(d)

    def solve(phi: np.ndarray) -> dict[str, Kin]:
        pb = _crank(a, b, phi, omega)
        pc = _rrr(pb, bc, gd, dc, sign)
        return {"A": ga, "D": gd, "B": pb, "C": pc, "M": _rigid(pb, pc, alpha, beta)}

    return solve


def hand_jansen(plan: SolvePlan) -> Callable[[np.ndarray], dict[str, Kin]]:
    """Jansen's leg: O, Z ground; M crank; A, C, E circle–circle; D on ZA; F on CE."""
    s = {k: v[1] for k, v in plan.points.items()}
    omega = plan.drivers[0].speed
    o, z, m, a, c, d, e, f = (s[k] for k in "OZMACDEF")

    def dist(p: np.ndarray, q: np.ndarray) -> float:
        return float(np.hypot(*(q - p)))

    ma, za, mc, zc, de, ce = dist(m, a), dist(z, a), dist(m, c), dist(z, c), dist(d, e), dist(c, e)
    sa, sc, se = _side(m, z, a), _side(m, z, c), _side(d, c, e)
    d_ab = _coefficients(z, a, d)
    f_ab = _coefficients(c, e, f)
    go, gz = _ground(o), _ground(z)

    def solve(phi: np.ndarray) -> dict[str, Kin]:
        pm = _crank(o, m, phi, omega)
        pa = _rrr(pm, ma, gz, za, sa)
        pc = _rrr(pm, mc, gz, zc, sc)
        pd = _rigid(gz, pa, *d_ab)
        pe = _rrr(pd, de, pc, ce, se)
        pf = _rigid(pc, pe, *f_ab)
        return {"O": go, "Z": gz, "M": pm, "A": pa, "C": pc, "D": pd, "E": pe, "F": pf}

    return solve


# ---------------------------------------------------------------------------
# (c) pylinkage models of the same linkages, built from the sketch coordinates
# ---------------------------------------------------------------------------


def _pl_helpers(plan: SolvePlan):
    s = {k: v[1] for k, v in plan.points.items()}

    def dist(p: str, q: str) -> float:
        return float(np.hypot(*(s[q] - s[p])))

    def angle(p: str, q: str) -> float:
        return math.atan2(float(s[q][1] - s[p][1]), float(s[q][0] - s[p][0]))

    def rrr(p, pn: str, q, qn: str, name: str):
        x, y = s[name]
        return pl.RRRDyad(p, q, dist(pn, name), dist(qn, name), x=x, y=y, name=name)

    def rigid(p, pn: str, q, qn: str, name: str):
        return pl.FixedDyad(p, q, dist(pn, name), angle(pn, name) - angle(pn, qn), name=name)

    def ground(name: str):
        return pl.Ground(float(s[name][0]), float(s[name][1]), name=name)

    def crank(pivot, pn: str, name: str, n: int):
        return pl.Crank(pivot, dist(pn, name), 2 * math.pi / n, angle(pn, name), name=name)

    return s, rrr, rigid, ground, crank


def pl_fourbar(plan: SolvePlan, n: int):
    _, rrr, rigid, ground, crank = _pl_helpers(plan)
    a, d = ground("A"), ground("D")
    b = crank(a, "A", "B", n)
    c = rrr(b.output, "B", d, "D", "C")
    m = rigid(b.output, "B", c, "C", "M")
    return pl.Linkage([a, d, b, c, m], name="four-bar"), b, ["A", "D", "B", "C", "M"]


def pl_jansen(plan: SolvePlan, n: int):
    _, rrr, rigid, ground, crank = _pl_helpers(plan)
    o, z = ground("O"), ground("Z")
    m = crank(o, "O", "M", n)
    a = rrr(m.output, "M", z, "Z", "A")
    c = rrr(m.output, "M", z, "Z", "C")
    d = rigid(z, "Z", a, "A", "D")
    e = rrr(d, "D", c, "C", "E")
    f = rigid(c, "C", e, "E", "F")
    names = ["O", "Z", "M", "A", "C", "D", "E", "F"]
    return pl.Linkage([o, z, m, a, c, d, e, f], name="Jansen"), m, names


# ---------------------------------------------------------------------------
# timing
# ---------------------------------------------------------------------------


def best_of(fn: Callable[[], object], repeat: int) -> float:
    best = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def max_rel(ours: np.ndarray, ref: np.ndarray) -> float:
    scale = float(np.max(np.abs(ref)))
    diff = float(np.max(np.abs(ours - ref)))
    return diff / scale if scale > 0 else diff


@dataclass
class Row:
    linkage: str
    n: int
    ours: float
    hand: float
    ours_all: float = 0.0
    pl_pos: float | None = None
    pl_pva: float | None = None
    dev_hand: float = 0.0
    dev_pl: float | None = None
    notes: list[str] = field(default_factory=list)


@dataclass
class Case:
    name: str
    fixture: str
    point: str  # the coupler point / foot timed through Motion.point
    hand: Callable
    peer: Callable


CASES = (
    Case("four-bar", "fourbar", "M", hand_fourbar, pl_fourbar),
    Case("Jansen", "jansen", "F", hand_jansen, pl_jansen),
)


def measure(case: Case, plan: SolvePlan, n: int, repeat: int, use_peer: bool) -> Row:
    phi = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    inputs = phi[:, None]
    link, c = plan.points[case.point]
    hand = case.hand(plan)

    def ours():
        motion = solve_poses(plan, inputs)
        return motion, motion.point(link, c)

    def hand_run():
        return hand(phi)

    # cross-check first (every named point, positions / velocities / accelerations)
    motion, _ = ours()
    ref = _as_arrays(hand_run(), n)
    dev = 0.0
    for name, (p_ref, v_ref, a_ref) in ref.items():
        plink, pc = plan.points[name]
        for got, want in zip(motion.point(plink, pc), (p_ref, v_ref, a_ref), strict=True):
            dev = max(dev, max_rel(got, want))
    row = Row(case.name, n, 0.0, 0.0, dev_hand=dev)

    def ours_all():
        motion = solve_poses(plan, inputs)
        for table in (motion.q, motion.qd, motion.qdd):
            for name in table:
                table[name]
        return [motion.point(*plan.points[name]) for name in ref]

    # Rounds of repeated runs of each, best over all: at 10^5 poses the time
    # depends on which pages the allocator hands out (fresh pages fault), and a
    # solver run right after the other inherits the other's heap.
    row.ours = row.hand = row.ours_all = math.inf
    for _ in range(3):
        row.ours = min(row.ours, best_of(ours, repeat) / n)
        row.hand = min(row.hand, best_of(hand_run, repeat) / n)
        row.ours_all = min(row.ours_all, best_of(ours_all, repeat) / n)

    if use_peer:
        linkage, crank, names = case.peer(plan, n)
        linkage.set_input_velocity(crank, plan.drivers[0].speed, plan.drivers[0].acceleration)
        sketch = linkage.get_coords()
        linkage.compile()

        def pl_pos():
            linkage.set_coords(sketch)
            return linkage.step_fast(iterations=n)

        def pl_pva():
            linkage.set_coords(sketch)
            return linkage.step_fast_with_kinematics(iterations=n)

        pl_pos()  # numba compile (or cache load) outside the timing
        pos, vel, acc = pl_pva()
        # pylinkage reports the pose after each step: inputs (k + 1)·2π/n
        m2 = solve_poses(plan, (phi + 2 * math.pi / n)[:, None])
        dpl = 0.0
        for j, name in enumerate(names):
            plink, pc = plan.points[name]
            for got, want in zip(
                m2.point(plink, pc), (pos[:, j], vel[:, j], acc[:, j]), strict=True
            ):
                dpl = max(dpl, max_rel(got, want))
        row.dev_pl = dpl
        row.pl_pos = best_of(pl_pos, repeat) / n
        row.pl_pva = best_of(pl_pva, repeat) / n
    return row


def profile_ours(plan: SolvePlan, point: str, n: int, top: int = 15) -> str:
    inputs = np.linspace(0.0, 2 * math.pi, n, endpoint=False)[:, None]
    link, c = plan.points[point]
    prof = cProfile.Profile()
    prof.enable()
    motion = solve_poses(plan, inputs)
    motion.point(link, c)
    prof.disable()
    out = io.StringIO()
    pstats.Stats(prof, stream=out).sort_stats("tottime").print_stats(top)
    return out.getvalue()


def _us(t: float | None) -> str:
    return "—" if t is None else f"{t * 1e6:.3f}"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000])
    parser.add_argument("--repeat", type=int, default=None, help="runs per timing (default 7/5/3)")
    parser.add_argument("--triad-poses", type=int, default=10000, help="0 skips the eight-bar")
    parser.add_argument("--profile", action="store_true", help="cProfile ours at the largest N")
    parser.add_argument("--no-pylinkage", action="store_true", help="skip the peer")
    args = parser.parse_args(argv)

    use_peer = pl is not None and not args.no_pylinkage
    print(
        f"goals at N = 10^5: ours <= {GOAL_HAND:g}x the hand-written numpy solver; "
        f"pylinkage (numba, pos+vel+acc) >= {GOAL_PEER:g}x ours"
    )
    print(f"numpy {np.__version__}, python {sys.version.split()[0]}")
    if pl is None:
        print("pylinkage is not installed: its columns are skipped (pip install pylinkage numba)")
    elif args.no_pylinkage:
        print("pylinkage skipped (--no-pylinkage)")
    else:
        try:
            import numba

            fast = f"numba {numba.__version__}"
        except ImportError:
            fast = "NO numba: pylinkage falls back to pure Python"
        print(f"pylinkage {pl.__version__} ({fast})")
    print(
        "ours = solve_poses + Motion.point (coupler point / foot); ours all = that, then every "
        "link's q, qd, qdd (angles by arctan2) and every named point read out; hand = closed "
        "form, every pin + that point; pl pos = step_fast; pl pva = step_fast_with_kinematics"
    )
    print()
    header = (
        f"{'linkage':<9} {'N':>7} {'ours us':>9} {'all us':>9} {'hand us':>9} {'pl pos us':>10} "
        f"{'pl pva us':>10} {'ours/hand':>10} {'pl pva/ours':>12} {'pl pos/ours':>12} "
        f"{'dev hand':>9} {'dev pl':>9}"
    )
    print("time per pose (best of runs), deviations: max relative difference, pos/vel/acc")
    print(header)
    print("-" * len(header))

    rows: list[Row] = []
    mismatch = False
    plans = {case.name: _plan(case.fixture) for case in CASES}
    for case in CASES:
        for n in args.sizes:
            repeat = args.repeat or (7 if n <= 1000 else 5 if n <= 10000 else 3)
            try:
                row = measure(case, plans[case.name], n, repeat, use_peer)
            except Exception as exc:  # a solve that fails is a finding, not a crash
                print(f"{case.name:<9} {n:>7}  FAILED: {type(exc).__name__}: {exc}")
                mismatch = True
                continue
            rows.append(row)
            bad = not row.dev_hand <= RTOL
            mismatch |= bad
            peer_ratio = None if row.pl_pva is None else row.pl_pva / row.ours
            pos_ratio = None if row.pl_pos is None else row.pl_pos / row.ours
            print(
                f"{row.linkage:<9} {n:>7} {_us(row.ours):>9} {_us(row.ours_all):>9} "
                f"{_us(row.hand):>9} "
                f"{_us(row.pl_pos):>10} {_us(row.pl_pva):>10} {row.ours / row.hand:>9.2f}x "
                + ("{:>12}".format("—") if peer_ratio is None else f"{peer_ratio:>11.3f}x")
                + " "
                + ("{:>12}".format("—") if pos_ratio is None else f"{pos_ratio:>11.3f}x")
                + f" {row.dev_hand:>9.1e} "
                + ("{:>9}".format("—") if row.dev_pl is None else f"{row.dev_pl:>9.1e}")
                + ("  MISMATCH" if bad else ""),
                flush=True,
            )

    if args.triad_poses:
        plan = _plan("eightbar_triad")
        n = args.triad_poses
        inputs = np.linspace(0.0, 2 * math.pi, n, endpoint=False)[:, None]
        t = time.perf_counter()
        try:
            solve_poses(plan, inputs)
            dt = time.perf_counter() - t
            labels = ", ".join(s.label for s in plan.steps)
            print(
                f"\neight-bar with a class III triad ({labels}), {n} poses: "
                f"{dt:.2f} s, {dt / n * 1e6:.1f} us per pose (one run)"
            )
        except Exception as exc:
            print(f"\neight-bar with a class III triad, {n} poses: FAILED: {exc}")
            mismatch = True

    print()
    verdicts: list[str] = []
    big = [r for r in rows if r.n >= 99_999]
    for r in big:
        ratio = r.ours / r.hand
        verdicts.append(
            f"{r.linkage}: ours/hand at N = {r.n}: {ratio:.2f}x (<= {GOAL_HAND:g}x) "
            f"{'met' if ratio <= GOAL_HAND else 'FAILED'}"
        )
        if r.pl_pva is None:
            verdicts.append(f"{r.linkage}: pylinkage goal not checked (pylinkage not run)")
        else:
            ratio = r.pl_pva / r.ours
            verdicts.append(
                f"{r.linkage}: pylinkage/ours (pos+vel+acc) at N = {r.n}: {ratio:.3f}x "
                f"(>= {GOAL_PEER:g}x) {'met' if ratio >= GOAL_PEER else 'FAILED'}"
            )
    if not big:
        verdicts.append("goals not checked: run with N = 10^5")
    for v in verdicts:
        print(v)
    agree = "agree" if not mismatch else "DISAGREE (or a solve failed)"
    print(f"cross-check ours vs hand (pos, vel, acc to {RTOL:g} relative): {agree}")

    if args.profile and rows:
        n = max(args.sizes)
        for case in CASES:
            print(f"\ncProfile of ours, {case.name}, N = {n} (sorted by own time):")
            print(profile_ours(plans[case.name], case.point, n))

    if mismatch:
        return 1
    return 2 if any("FAILED" in v for v in verdicts) else 0


if __name__ == "__main__":
    sys.exit(main())
