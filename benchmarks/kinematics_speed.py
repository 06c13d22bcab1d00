"""How fast the public sweep solves a crank turn, next to a hand-written solver and pylinkage.

For the four-bar (``fixtures/fourbar.edges``, coupler point M) and Jansen's
leg (``fixtures/jansen.edges``, foot F), one crank turn of N poses
(N = 10^3, 10^4, 10^5 by default) is timed side by side in one process:

* **ours**: ``kinematics.sweep(plan, inputs)``, then every named point's
  position, velocity and acceleration read out of the result (the plan is
  made once, outside the timing): what a user calls.
* **ours pos**: ``sweep(plan, inputs, rates=False)``, every named point's
  position (before that path existed: the full sweep, positions read out).
* **hand**: a minimal closed-form numpy solver of the same linkage, written in
  this file (crank, circle–circle intersections with the sketch's assembly
  mode, rigid points as linear combinations), vectorised over the poses:
  positions, velocities and accelerations of every pin and of the coupler
  point / foot; **hand pos** the same, positions only.
* **pylinkage** (only if it is installed; it is not a dependency of assur):
  ``Linkage.step_fast`` (numba, positions only) and
  ``Linkage.step_fast_with_kinematics`` (numba, positions + velocities +
  accelerations of every joint), over the same poses.

Times are medians over interleaved rounds (one run of each per round), so the
noise of a shared machine falls on all alike; the load average is printed
before and after. Before any timing, ours and hand are cross-checked:
positions, velocities and accelerations of every named point agree to 1e-9
relative (the largest difference over the largest magnitude of that
quantity); pylinkage is compared with ours too (reported, not a gate).

The eight-bar with a class III triad (``fixtures/eightbar_triad.edges``, its
triad solved by Newton) and the four-bar are timed in the same run over 10^4
poses (``--triad-poses``), both through ``sweep()`` with every joint read out,
twice: interleaved, and back to back (each mechanism's sweeps in a block, so
that each meets the memory its own last sweep left); the goal holds the worse
of the two ratios.

Goals: at N = 10^5, ours within 1.5x of the hand-written solver (with rates,
and positions only), and at least 2x faster than pylinkage (with numba) for
positions + velocities + accelerations; the eight-bar within 10x of the
four-bar per pose. The verdicts, each with its ratio, are printed last.

``--profile`` prints the cProfile top functions of ours at the largest N.

Exit status: 0 all goals met, 1 ours and hand disagree (or a solve failed),
2 agreement fine but a speed goal failed.

Usage::

    python benchmarks/kinematics_speed.py [--sizes 1000 10000 100000]
        [--rounds R] [--triad-poses 10000] [--profile] [--no-pylinkage]
"""

from __future__ import annotations

import argparse
import cProfile
import inspect
import io
import math
import os
import pstats
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from kinematics.solvers.plan import SolvePlan, make_plan  # noqa: E402
from kinematics.solvers.sweep import sweep  # noqa: E402
from structure.readwrite.edgelist import read_edgelist  # noqa: E402
from structure.report import analyze  # noqa: E402

FIXTURES = ROOT / "fixtures"
GOAL_HAND = 1.5  # ours / hand at N = 10^5, at most
GOAL_PEER = 2.0  # pylinkage (pos + vel + acc) / ours at N = 10^5, at least
GOAL_TRIAD = 10.0  # eight-bar (class III triad) / four-bar, per pose, at most
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


def _ground(p: np.ndarray, rates: bool = True) -> Kin:
    return (float(p[0]), float(p[1]), 0.0, 0.0, 0.0, 0.0) if rates else (float(p[0]), float(p[1]))


def _crank(
    pivot: np.ndarray, tip: np.ndarray, phi: np.ndarray, omega: float, rates: bool = True
) -> Kin:
    """The crank tip turned by ``phi`` about ``pivot``; constant ω, so a = −ω² r."""
    c, s = np.cos(phi), np.sin(phi)
    dx, dy = tip - pivot
    rx, ry = c * dx - s * dy, s * dx + c * dy
    if not rates:
        return (pivot[0] + rx, pivot[1] + ry)
    w2 = omega * omega
    return (pivot[0] + rx, pivot[1] + ry, -omega * ry, omega * rx, -w2 * rx, -w2 * ry)


def _rrr(p: Kin, r1: float, q: Kin, r2: float, sign: float) -> Kin:
    """The pin at distance r1 from ``p`` and r2 from ``q`` on the side ``sign``."""
    px, py = p[:2]
    qx, qy = q[:2]
    ex, ey = qx - px, qy - py
    d2 = ex * ex + ey * ey
    d = np.sqrt(d2)
    a = (r1 * r1 - r2 * r2 + d2) / (2.0 * d)
    h = sign * np.sqrt(r1 * r1 - a * a)
    cx = px + (a * ex - h * ey) / d
    cy = py + (a * ey + h * ex) / d
    if len(p) == 2:  # positions only
        return (cx, cy)
    pvx, pvy, pax, pay = p[2:]
    qvx, qvy, qax, qay = q[2:]
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
    for i in range(0, len(p), 2):
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


def hand_fourbar(plan: SolvePlan, rates: bool = True) -> Callable[[np.ndarray], dict[str, Kin]]:
    """The four-bar A-B-C-D with coupler point M, from the sketch coordinates."""
    s = {k: v[1] for k, v in plan.points.items()}
    omega = plan.drivers[0].speed
    a, b, c, d, m = (s[k] for k in "ABCDM")
    bc, dc = float(np.hypot(*(c - b))), float(np.hypot(*(c - d)))
    sign = _side(b, d, c)
    alpha, beta = _coefficients(b, c, m)
    ga, gd = _ground(a, rates), _ground(d, rates)

    def solve(phi: np.ndarray) -> dict[str, Kin]:
        pb = _crank(a, b, phi, omega, rates)
        pc = _rrr(pb, bc, gd, dc, sign)
        return {"A": ga, "D": gd, "B": pb, "C": pc, "M": _rigid(pb, pc, alpha, beta)}

    return solve


def hand_jansen(plan: SolvePlan, rates: bool = True) -> Callable[[np.ndarray], dict[str, Kin]]:
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
    go, gz = _ground(o, rates), _ground(z, rates)

    def solve(phi: np.ndarray) -> dict[str, Kin]:
        pm = _crank(o, m, phi, omega, rates)
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


def interleaved(fns: dict[str, Callable[[], object]], rounds: int) -> dict[str, float]:
    """The median time of each function over ``rounds`` rounds, one run of each per round.

    Running them in turn spreads the machine's noise (other processes on the
    shared cores) over all of them alike; the median drops the outliers.
    """
    times: dict[str, list[float]] = {k: [] for k in fns}
    for _ in range(rounds):
        for name, fn in fns.items():
            t = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - t)
    return {k: float(np.median(v)) for k, v in times.items()}


def max_rel(ours: np.ndarray, ref: np.ndarray) -> float:
    scale = float(np.max(np.abs(ref)))
    diff = float(np.max(np.abs(ours - ref)))
    return diff / scale if scale > 0 else diff


def _supports_positions_only() -> bool:
    """Whether ``sweep`` has its positions-only path (``rates=False``)."""
    return "rates" in inspect.signature(sweep).parameters


def sweep_every_joint(plan: SolvePlan, inputs: np.ndarray, rates: bool) -> list[np.ndarray]:
    """The public sweep, then every named point's arrays read out (what the hand solver gives)."""
    if rates:
        result = sweep(plan, inputs)
        keys = ("position", "velocity", "acceleration")
    elif _supports_positions_only():
        result = sweep(plan, inputs, rates=False)
        keys = ("position",)
    else:  # before the positions-only path: the full sweep is what a user had
        result = sweep(plan, inputs)
        keys = ("position",)
    return [result.points[name][key] for name in plan.points for key in keys]


@dataclass
class Row:
    linkage: str
    n: int
    ours: float  # sweep(), pos + vel + acc of every joint
    hand: float
    ours_pos: float  # sweep(rates=False), positions of every joint
    hand_pos: float
    pl_pos: float | None = None
    pl_pva: float | None = None
    dev_hand: float = 0.0
    dev_pl: float | None = None
    notes: list[str] = field(default_factory=list)


@dataclass
class Case:
    name: str
    fixture: str
    hand: Callable
    peer: Callable


CASES = (
    Case("four-bar", "fourbar", hand_fourbar, pl_fourbar),
    Case("Jansen", "jansen", hand_jansen, pl_jansen),
)


def _deviation(result, ref: dict, keys: tuple[str, ...]) -> float:
    dev = 0.0
    for name, want in ref.items():
        for key, w in zip(keys, want, strict=False):
            dev = max(dev, max_rel(result.points[name][key], w))
    return dev


def _peer_runs(case: Case, plan: SolvePlan, n: int, phi: np.ndarray):
    """pylinkage's two runs (positions; with rates) and its deviation from ours."""
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
    later = sweep(plan, (phi + 2 * math.pi / n)[:, None])
    dev = 0.0
    for j, name in enumerate(names):
        got = later.points[name]
        for key, want in zip(
            ("position", "velocity", "acceleration"), (pos, vel, acc), strict=True
        ):
            dev = max(dev, max_rel(got[key], want[:, j]))
    return pl_pos, pl_pva, dev


def measure(case: Case, plan: SolvePlan, n: int, rounds: int, use_peer: bool) -> Row:
    phi = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    inputs = phi[:, None]
    hand, hand_p = case.hand(plan), case.hand(plan, rates=False)
    keys = ("position", "velocity", "acceleration")
    # cross-check first: every named point, positions / velocities / accelerations
    ref = _as_arrays(hand(phi), n)
    dev = _deviation(sweep(plan, inputs), ref, keys)
    if _supports_positions_only():
        ref_p = {k: (v[0],) for k, v in ref.items()}
        dev = max(dev, _deviation(sweep(plan, inputs, rates=False), ref_p, keys[:1]))
    fns: dict[str, Callable[[], object]] = {
        "ours": lambda: sweep_every_joint(plan, inputs, True),
        "hand": lambda: hand(phi),
        "ours_pos": lambda: sweep_every_joint(plan, inputs, False),
        "hand_pos": lambda: hand_p(phi),
    }
    dev_pl = None
    if use_peer:
        pl_pos, pl_pva, dev_pl = _peer_runs(case, plan, n, phi)
        fns["pl_pos"], fns["pl_pva"] = pl_pos, pl_pva
    for fn in fns.values():  # warm up (allocator, caches)
        fn()
    t = {k: v / n for k, v in interleaved(fns, rounds).items()}
    return Row(
        case.name, n, t["ours"], t["hand"], t["ours_pos"], t["hand_pos"],
        t.get("pl_pos"), t.get("pl_pva"), dev, dev_pl,
    )  # fmt: skip


def back_to_back(fns: dict[str, Callable[[], object]], runs: int) -> dict[str, float]:
    """The median time of each function over ``runs`` runs made one after another, in a block.

    Unlike :func:`interleaved`, each function's runs follow each other, so each
    one meets the memory its own previous run left (freed pages the allocator
    kept, or gave back to the system and must fault in again): what a user
    sweeping one mechanism over and over pays.
    """
    out = {}
    for name, fn in fns.items():
        times = []
        for _ in range(runs):
            t = time.perf_counter()
            fn()
            times.append(time.perf_counter() - t)
        out[name] = float(np.median(times))
    return out


@dataclass
class TriadTimes:
    """Per-pose times of the eight-bar and the four-bar, interleaved and back to back (s)."""

    eightbar: float
    fourbar: float
    eightbar_blocks: float
    fourbar_blocks: float
    labels: str

    @property
    def ratio(self) -> float:
        """The worse of the two eight-bar/four-bar ratios (the one the goal is held to)."""
        return max(self.eightbar / self.fourbar, self.eightbar_blocks / self.fourbar_blocks)


def measure_triad(n: int, rounds: int) -> TriadTimes:
    """Per-pose time of the eight-bar with a class III triad and of the four-bar, same run.

    Timed twice: interleaved (one sweep of each per round) and back to back
    (``rounds`` sweeps of the eight-bar, then as many of the four-bar, twice
    over, the medians of each mechanism's sweeps).
    """
    plans = {"eightbar": _plan("eightbar_triad"), "fourbar": _plan("fourbar")}
    inputs = np.linspace(0.0, 2 * math.pi, n, endpoint=False)[:, None]
    fns = {k: (lambda p=p: sweep_every_joint(p, inputs, True)) for k, p in plans.items()}
    for fn in fns.values():
        fn()
    t = interleaved(fns, rounds)
    blocks = [back_to_back(fns, rounds) for _ in range(2)]
    b = {k: float(np.median([x[k] for x in blocks])) for k in fns}
    labels = ", ".join(s.label for s in plans["eightbar"].steps)
    return TriadTimes(
        t["eightbar"] / n, t["fourbar"] / n, b["eightbar"] / n, b["fourbar"] / n, labels
    )


def profile_ours(plan: SolvePlan, n: int, top: int = 15) -> str:
    inputs = np.linspace(0.0, 2 * math.pi, n, endpoint=False)[:, None]
    prof = cProfile.Profile()
    prof.enable()
    sweep_every_joint(plan, inputs, True)
    prof.disable()
    out = io.StringIO()
    pstats.Stats(prof, stream=out).sort_stats("tottime").print_stats(top)
    return out.getvalue()


def _us(t: float | None) -> str:
    return "—" if t is None else f"{t * 1e6:.3f}"


def _ratio(a: float | None, b: float | None, width: int) -> str:
    return "—".rjust(width) if a is None or b is None else f"{a / b:>{width - 1}.2f}x"


def _preamble(use_peer: bool, no_peer_flag: bool) -> None:
    print(
        f"goals at N = 10^5: sweep() <= {GOAL_HAND:g}x the hand-written numpy solver (pos+vel+acc, "
        f"and positions only); pylinkage (numba, pos+vel+acc) >= {GOAL_PEER:g}x sweep(); "
        f"eight-bar (class III triad) <= {GOAL_TRIAD:g}x the four-bar per pose"
    )
    print(f"numpy {np.__version__}, python {sys.version.split()[0]}, load {_load()}")
    if pl is None:
        print("pylinkage is not installed: its columns are skipped (pip install pylinkage numba)")
    elif no_peer_flag:
        print("pylinkage skipped (--no-pylinkage)")
    else:
        try:
            import numba

            fast = f"numba {numba.__version__}"
        except ImportError:
            fast = "NO numba: pylinkage falls back to pure Python"
        print(f"pylinkage {pl.__version__} ({fast})")
    print(
        "ours = kinematics.sweep() then every named point's position, velocity and acceleration "
        "read out; ours pos = sweep(rates=False), every position; hand = closed form, every pin "
        "and point (hand pos: positions only); pl pos = step_fast; pl pva = "
        "step_fast_with_kinematics. Times: medians of interleaved rounds, us per pose."
    )
    print()


def _load() -> str:
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - platform
        return "?"


def _print_row(row: Row, header_width: int) -> None:
    print(
        f"{row.linkage:<9} {row.n:>7} {_us(row.ours):>8} {_us(row.hand):>8} "
        f"{_us(row.ours_pos):>8} {_us(row.hand_pos):>8} {_us(row.pl_pos):>8} "
        f"{_us(row.pl_pva):>8} {_ratio(row.ours, row.hand, 10)} "
        f"{_ratio(row.ours_pos, row.hand_pos, 10)} {_ratio(row.pl_pva, row.ours, 10)} "
        f"{row.dev_hand:>9.1e} "
        + ("—".rjust(9) if row.dev_pl is None else f"{row.dev_pl:>9.1e}")
        + ("  MISMATCH" if not row.dev_hand <= RTOL else ""),
        flush=True,
    )


def _verdicts(rows: list[Row], triad: TriadTimes | None) -> list[str]:
    out: list[str] = []
    for r in (r for r in rows if r.n >= 99_999):
        for what, ours, hand in (
            ("pos+vel+acc", r.ours, r.hand),
            ("positions", r.ours_pos, r.hand_pos),
        ):
            ratio = ours / hand
            out.append(
                f"{r.linkage}: sweep()/hand, {what}, N = {r.n}: {ratio:.2f}x (<= {GOAL_HAND:g}x) "
                f"{'met' if ratio <= GOAL_HAND else 'FAILED'}"
            )
        if r.pl_pva is None:
            out.append(f"{r.linkage}: pylinkage goal not checked (pylinkage not run)")
        else:
            ratio = r.pl_pva / r.ours
            out.append(
                f"{r.linkage}: pylinkage/sweep() (pos+vel+acc) at N = {r.n}: {ratio:.2f}x "
                f"(>= {GOAL_PEER:g}x) {'met' if ratio >= GOAL_PEER else 'FAILED'}"
            )
    if not any(r.n >= 99_999 for r in rows):
        out.append("hand and pylinkage goals not checked: run with N = 10^5")
    if triad is not None:
        ratio = triad.ratio
        out.append(
            f"eight-bar/four-bar per pose, the worse of interleaved and back to back: "
            f"{ratio:.2f}x (<= {GOAL_TRIAD:g}x) "
            f"{'met' if ratio <= GOAL_TRIAD else 'FAILED'}"
        )
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000])
    parser.add_argument("--rounds", type=int, default=None, help="interleaved rounds (15/9/7)")
    parser.add_argument("--triad-poses", type=int, default=10000, help="0 skips the eight-bar")
    parser.add_argument("--profile", action="store_true", help="cProfile ours at the largest N")
    parser.add_argument("--no-pylinkage", action="store_true", help="skip the peer")
    args = parser.parse_args(argv)

    use_peer = pl is not None and not args.no_pylinkage
    _preamble(use_peer, args.no_pylinkage)
    header = (
        f"{'linkage':<9} {'N':>7} {'ours':>8} {'hand':>8} {'ours pos':>8} {'hand pos':>8} "
        f"{'pl pos':>8} {'pl pva':>8} {'ours/hand':>10} {'pos/hand':>10} {'pl/ours':>10} "
        f"{'dev hand':>9} {'dev pl':>9}"
    )
    print(header)
    print("-" * len(header))
    rows: list[Row] = []
    mismatch = False
    plans = {case.name: _plan(case.fixture) for case in CASES}
    for case in CASES:
        for n in args.sizes:
            rounds = args.rounds or (15 if n <= 1000 else 9 if n <= 10000 else 7)
            try:
                row = measure(case, plans[case.name], n, rounds, use_peer)
            except Exception as exc:  # a solve that fails is a finding, not a crash
                print(f"{case.name:<9} {n:>7}  FAILED: {type(exc).__name__}: {exc}")
                mismatch = True
                continue
            rows.append(row)
            mismatch |= not row.dev_hand <= RTOL
            _print_row(row, len(header))

    triad = None
    if args.triad_poses:
        n = args.triad_poses
        try:
            triad = measure_triad(n, args.rounds or 5)
            print(
                f"\neight-bar with a class III triad ({triad.labels}), {n} poses, sweep(), every "
                f"joint, medians:\n  interleaved:   eight-bar {triad.eightbar * 1e6:.3f} us "
                f"per pose, four-bar {triad.fourbar * 1e6:.3f}: "
                f"{triad.eightbar / triad.fourbar:.2f}x\n  back to back:  eight-bar "
                f"{triad.eightbar_blocks * 1e6:.3f} us per pose, four-bar "
                f"{triad.fourbar_blocks * 1e6:.3f}: "
                f"{triad.eightbar_blocks / triad.fourbar_blocks:.2f}x"
            )
        except Exception as exc:
            print(f"\neight-bar with a class III triad, {n} poses: FAILED: {exc}")
            mismatch = True

    if args.profile and rows:
        for case in CASES:
            print(f"\ncProfile of ours, {case.name}, N = {max(args.sizes)} (by own time):")
            print(profile_ours(plans[case.name], max(args.sizes)))

    print()
    agree = "agree" if not mismatch else "DISAGREE (or a solve failed)"
    print(f"cross-check ours vs hand (pos, vel, acc to {RTOL:g} relative): {agree}")
    print(f"load average after the run: {_load()}")
    verdicts = _verdicts(rows, triad)
    for v in verdicts:
        print(v)
    if mismatch:
        return 1
    return 2 if any("FAILED" in v for v in verdicts) else 0


if __name__ == "__main__":
    sys.exit(main())
