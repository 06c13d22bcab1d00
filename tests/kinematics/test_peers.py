"""Peers as oracles: the same linkages solved by code that is not ours.

* **pylinkage** (optional, never a dependency of assur): each fixture's
  ``.edges`` file is read by a small parser written here (not
  ``structure.edgelist``) and turned into pylinkage components (``Ground``,
  ``Crank``, ``RRRDyad``, ``RRPDyad``, ``FixedDyad``) from its sketch
  coordinates. pylinkage steps the crank through one turn; our point positions
  agree with its joints to 1e-9 of the sketch's size at every step, and (from
  its numba path ``step_fast_with_kinematics``) so do velocities and
  accelerations, to 1e-9 of their largest magnitude.
* **closed form, no pylinkage**: the four-bar and the crank–slider written out
  here from the loop equations (complex numbers for the four-bar, the rod's
  angle to the slide for the crank–slider), positions, velocities and
  accelerations over a full turn, agree with ours to 1e-9.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

from kinematics.solvers.plan import make_plan
from kinematics.solvers.solve import solve_poses
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
RTOL = 1e-9


# ---------------------------------------------------------------------------
# an independent reader of the .edges files (sketch geometry only)
# ---------------------------------------------------------------------------


@dataclass
class Sketch:
    ground: str = "0"
    driver: str = ""
    omega: float = 0.0
    epsilon: float = 0.0
    xy: dict[str, np.ndarray] = field(default_factory=dict)
    on: dict[str, list[str]] = field(default_factory=dict)  # link -> point names (pins, markers)
    revolute: list[tuple[str, str, str]] = field(default_factory=list)  # (a, b, point)
    prismatic: list[tuple[str, str, str, float]] = field(default_factory=list)  # + angle (deg)

    @property
    def size(self) -> float:
        pts = np.array(list(self.xy.values()))
        return float(np.max(np.ptp(pts, axis=0)))

    def links_of(self, point: str) -> list[str]:
        return [link for link, names in self.on.items() if point in names]


def read_sketch(path: Path) -> Sketch:
    s = Sketch()

    def carry(link: str, point: str) -> None:
        names = s.on.setdefault(link, [])
        if point not in names:
            names.append(point)

    for raw in path.read_text().splitlines():
        words = raw.split("#", 1)[0].split()
        if not words or words[0] == "name":
            continue
        if words[0] == "ground":
            s.ground = words[1]
        elif words[0] == "driver":
            s.driver = words[1]
            opts = dict(w.split("=", 1) for w in words[2:])
            s.omega = float(opts.get("omega", 0.0))
            s.epsilon = float(opts.get("epsilon", 0.0))
        elif words[0] == "point":
            s.xy[words[1]] = np.array([float(words[2]), float(words[3])])
            for w in words[4:]:
                if w.startswith("on="):
                    carry(w[3:], words[1])
        else:
            a, b, kind, point = words[:4]
            if kind == "R":
                s.revolute.append((a, b, point))
                carry(a, point)
                carry(b, point)
            elif kind == "P":
                opts = dict(w.split("=", 1) for w in words[4:])
                s.prismatic.append((a, b, point, float(opts["angle"])))
            else:
                raise ValueError(f"{path.name}: pair kind {kind} not handled by this reader")
    return s


# ---------------------------------------------------------------------------
# the converter to pylinkage
# ---------------------------------------------------------------------------


class NotDyadic(Exception):
    """pylinkage's components cannot place these points (no dyad-by-dyad order)."""


def _dist(s: Sketch, p: str, q: str) -> float:
    return float(np.hypot(*(s.xy[q] - s.xy[p])))


def _angle(s: Sketch, p: str, q: str) -> float:
    d = s.xy[q] - s.xy[p]
    return math.atan2(float(d[1]), float(d[0]))


def to_pylinkage(pl, s: Sketch, steps: int):
    """``(linkage, crank, names)``: one component per point of the sketch, in solve order.

    Ground pins become ``Ground``; the driver's other point a ``Crank`` turning
    2π/steps per step from its sketch angle; then, until every point is placed,
    a point on a link with two placed points is a ``FixedDyad``, one on two
    links each with a placed point an ``RRRDyad`` (started at the sketch, so
    pylinkage keeps the sketch's assembly mode by proximity), and the pin of a
    link sliding on the frame an ``RRPDyad`` on the line through its sketch
    position along the slide.
    """
    anchor: dict[str, object] = {}
    parts: list[object] = []
    names: list[str] = []

    def add(name: str, part: object, handle: object | None = None) -> None:
        anchor[name] = part if handle is None else handle
        parts.append(part)
        names.append(name)

    for name in s.on.get(s.ground, []):
        add(name, pl.Ground(*map(float, s.xy[name]), name=name))
    pivot = next(p for a, b, p in s.revolute if {a, b} == {s.driver, s.ground})
    crank = None
    for name in s.on[s.driver]:
        if name in anchor:
            continue
        if crank is None:
            crank = pl.Crank(
                anchor[pivot], _dist(s, pivot, name), 2 * math.pi / steps,
                _angle(s, pivot, name), name=name,
            )  # fmt: skip
            add(name, crank, crank.output)
        else:
            add(name, pl.FixedDyad(anchor[pivot], crank.output, _dist(s, pivot, name),
                                   _angle(s, pivot, name) - _angle(s, pivot, crank.name),
                                   name=name))  # fmt: skip
    slides = {  # a link sliding on the frame -> the slide direction (rad)
        (a if b == s.ground else b): math.radians(angle)
        for a, b, _, angle in s.prismatic
        if s.ground in (a, b)
    }
    pending = [p for p in s.xy if p not in anchor]
    while pending:
        for p in pending:
            placed = {L: [k for k in s.on[L] if k in anchor and k != p] for L in s.links_of(p)}
            x, y = map(float, s.xy[p])
            rigid = next((ks for ks in placed.values() if len(ks) >= 2), None)
            if rigid is not None:
                k1, k2 = rigid[:2]
                add(p, pl.FixedDyad(anchor[k1], anchor[k2], _dist(s, k1, p),
                                    _angle(s, k1, p) - _angle(s, k1, k2), name=p))  # fmt: skip
                break
            with_one = [(L, ks[0]) for L, ks in placed.items() if ks]
            if len(with_one) >= 2:
                (_, k1), (_, k2) = with_one[:2]
                add(p, pl.RRRDyad(anchor[k1], anchor[k2], _dist(s, k1, p), _dist(s, k2, p),
                                  x=x, y=y, name=p))  # fmt: skip
                break
            slider = next((L for L in s.links_of(p) if L in slides), None)
            if slider is not None and with_one:
                (_, k), t = with_one[0], slides[slider]
                line1 = pl.Ground(x, y, name=f"{p}'")
                line2 = pl.Ground(x + math.cos(t), y + math.sin(t), name=f'{p}"')
                parts.extend([line1, line2])
                names.extend([line1.name, line2.name])
                add(p, pl.RRPDyad(anchor[k], line1, line2, _dist(s, k, p), x=x, y=y, name=p))
                break
        else:
            raise NotDyadic(
                f"no dyad places any of {sorted(pending)}: they must be solved together "
                "(a class III group), which pylinkage's components cannot express"
            )
        pending = [p for p in s.xy if p not in anchor]
    return pl.Linkage(parts, name=s.driver), crank, names


# ---------------------------------------------------------------------------
# ours, at the inputs pylinkage visits
# ---------------------------------------------------------------------------


def ours(fixture: str, inputs: np.ndarray):
    plan = make_plan(analyze(read_edgelist(FIXTURES / f"{fixture}.edges")))
    motion = solve_poses(plan, inputs[:, None])
    return plan, motion


def rel(got: np.ndarray, want: np.ndarray) -> float:
    scale = float(np.max(np.abs(want)))
    return float(np.max(np.abs(got - want))) / (scale if scale > 0 else 1.0)


PEER_CASES = [
    pytest.param("fourbar", True, id="four-bar"),
    pytest.param("crank_slider", True, id="crank-slider"),
    pytest.param("jansen", True, id="jansen"),
    pytest.param("klann", True, id="klann"),
    pytest.param("watt_sixbar", True, id="watt-sixbar"),
    pytest.param("stephenson_sixbar", False, id="stephenson-sixbar"),
    pytest.param("stephenson_sixbar_dyads", True, id="stephenson-sixbar-dyads"),
]
STEPS = 360  # crank angles 1°, 2°, …, 360° from the sketch

STEPHENSON = (
    "pylinkage cannot express the Stephenson six-bar driven at link 1: it is a class III "
    "triad (pins Q23, Q34, Q35 unknown together), pylinkage's components place one joint "
    "from two known ones, MechanismBuilder.build() reports it under-constrained and "
    "solver.solve._solve_triad takes exactly 2 internal nodes (pylinkage 1.3)"
)


def _peer(fixture: str, expressible: bool):
    pl = pytest.importorskip("pylinkage")
    sketch = read_sketch(FIXTURES / f"{fixture}.edges")
    if not expressible:
        with pytest.raises(NotDyadic):
            to_pylinkage(pl, sketch, STEPS)
        pytest.skip(STEPHENSON)
    linkage, crank, names = to_pylinkage(pl, sketch, STEPS)
    inputs = np.arange(1, STEPS + 1) * (2 * math.pi / STEPS)  # pylinkage reports after a step
    plan, motion = ours(fixture, inputs)
    return pl, sketch, linkage, crank, names, plan, motion


@pytest.mark.parametrize(("fixture", "expressible"), PEER_CASES)
def test_positions_agree_with_pylinkage(fixture, expressible):
    _, sketch, linkage, _, names, plan, motion = _peer(fixture, expressible)
    trajectory = np.array(list(linkage.step(iterations=STEPS)), dtype=float)  # (steps, parts, 2)
    compared = [n for n in names if n in plan.points]
    assert set(compared) == set(sketch.xy), "every point of the sketch is compared"
    worst = 0.0
    for name in compared:
        link, c = plan.points[name]
        position = motion.point(link, c)[0]
        dev = float(np.max(np.abs(position - trajectory[:, names.index(name)]))) / sketch.size
        worst = max(worst, dev)
        assert dev <= RTOL, f"{fixture} point {name}: {dev:.2e} of the sketch size"
    print(f"{fixture}: max |ours − pylinkage| / size = {worst:.1e} over {len(compared)} points")


@pytest.mark.parametrize(("fixture", "expressible"), PEER_CASES)
def test_velocities_and_accelerations_agree_with_pylinkage(fixture, expressible):
    _, sketch, linkage, crank, names, plan, motion = _peer(fixture, expressible)
    linkage.set_input_velocity(crank, sketch.omega, sketch.epsilon)
    pos, vel, acc = linkage.step_fast_with_kinematics(iterations=STEPS)
    compared = [n for n in names if n in plan.points]
    theirs = {
        what: np.stack([arr[:, names.index(n)] for n in compared])
        for what, arr in (("position", pos), ("velocity", vel), ("acceleration", acc))
    }
    mine = {
        what: np.stack([motion.point(*plan.points[n])[k] for n in compared])
        for k, what in enumerate(("position", "velocity", "acceleration"))
    }
    for what in theirs:
        dev = rel(mine[what], theirs[what])
        assert dev <= RTOL, f"{fixture} {what}: {dev:.2e} relative"


# ---------------------------------------------------------------------------
# closed-form oracles without pylinkage
# ---------------------------------------------------------------------------

TURN = np.linspace(0.0, 2 * math.pi, 720, endpoint=False)


def _c(v: np.ndarray) -> complex:
    return complex(float(v[0]), float(v[1]))


def _xy(z: np.ndarray) -> np.ndarray:
    return np.column_stack([z.real, z.imag])


def fourbar_closed_form(s: Sketch, phi: np.ndarray) -> dict:
    """Loop A + a·e^{iθ2} + b·e^{iθ3} = D + c·e^{iθ4}, solved for θ3, θ4 and their rates."""
    A, B0, C0, D, M0 = (_c(s.xy[k]) for k in "ABCDM")
    a, b, c = abs(B0 - A), abs(C0 - B0), abs(C0 - D)
    w, e = s.omega, s.epsilon
    sigma = math.copysign(1.0, ((D - B0).conjugate() * (C0 - B0)).imag)  # C left/right of BD
    th2 = np.angle(B0 - A) + phi
    B = A + a * np.exp(1j * th2)
    span = np.abs(D - B)
    beta = np.arccos((b * b + span * span - c * c) / (2 * b * span))  # angle DBC
    th3 = np.angle(D - B) + sigma * beta
    C = B + b * np.exp(1j * th3)
    th4 = np.angle(C - D)
    # a·ω2·e^{iθ2} + b·ω3·e^{iθ3} − c·ω4·e^{iθ4} = 0, projected across θ4 and θ3
    w3 = -a * w * np.sin(th2 - th4) / (b * np.sin(th3 - th4))
    w4 = a * w * np.sin(th2 - th3) / (c * np.sin(th4 - th3))
    # b·α3·e^{iθ3} − c·α4·e^{iθ4} = i·K with K the known terms
    K = (
        -1j * a * e * np.exp(1j * th2)
        - a * w**2 * np.exp(1j * th2)
        - b * w3**2 * np.exp(1j * th3)
        + c * w4**2 * np.exp(1j * th4)
    )
    e3 = (K * np.exp(-1j * th4)).real / (b * np.sin(th3 - th4))
    e4 = -(K * np.exp(-1j * th3)).real / (c * np.sin(th4 - th3))
    M = B + (M0 - B0) * np.exp(1j * (th3 - np.angle(C0 - B0)))
    vB, aB = 1j * w * (B - A), (1j * e - w * w) * (B - A)
    out = {"B": (B, vB, aB)}
    for name, P in (("C", C), ("M", M)):
        out[name] = (P, vB + 1j * w3 * (P - B), aB + (1j * e3 - w3 * w3) * (P - B))
    out = {k: tuple(_xy(z) for z in v) for k, v in out.items()}
    th30, th40 = np.angle(C0 - B0), np.angle(C0 - D)
    out["links"] = {"2": (th3 - th30, w3, e3), "3": (th4 - th40, w4, e4)}
    return out


def crank_slider_closed_form(s: Sketch, phi: np.ndarray) -> dict:
    """The rod's angle ψ to the slide: b·sin ψ = −h_B (h: height of B over the slide line)."""
    A, B0, C0 = (_c(s.xy[k]) for k in "ABC")
    ((_, _, _, angle),) = s.prismatic
    u = complex(math.cos(math.radians(angle)), math.sin(math.radians(angle)))
    b = abs(C0 - B0)
    w, e = s.omega, s.epsilon
    sigma = math.copysign(1.0, ((C0 - B0) / u).real)  # C ahead of or behind B along u
    B = A + (B0 - A) * np.exp(1j * phi)
    vB, aB = 1j * w * (B - A), (1j * e - w * w) * (B - A)
    along = lambda z: (z / u).real  # noqa: E731 - coordinates in the slide's frame
    across = lambda z: (z / u).imag  # noqa: E731
    sin_psi = -across(B - C0) / b
    cos_psi = sigma * np.sqrt(1.0 - sin_psi**2)
    x = along(B - C0) + b * cos_psi  # slider travel from C0
    psi_d = -across(vB) / (b * cos_psi)
    x_d = along(vB) - b * sin_psi * psi_d
    psi_dd = (-across(aB) + b * sin_psi * psi_d**2) / (b * cos_psi)
    x_dd = along(aB) - b * cos_psi * psi_d**2 - b * sin_psi * psi_dd
    C = C0 + x * u
    psi0 = math.atan2(-across(B0 - C0) / b, sigma * math.sqrt(1 - (across(B0 - C0) / b) ** 2))
    out = {"B": (B, vB, aB), "C": (C, x_d * u, x_dd * u)}
    out = {k: tuple(_xy(z) for z in v) for k, v in out.items()}
    out["links"] = {"2": (np.arctan2(sin_psi, cos_psi) - psi0, psi_d, psi_dd)}
    out["slider"] = _xy(x * u), _xy(x_d * u), _xy(x_dd * u)
    return out


def _wrap(angle: np.ndarray) -> np.ndarray:
    return (angle + math.pi) % (2 * math.pi) - math.pi


@pytest.mark.parametrize(
    ("fixture", "oracle"),
    [("fourbar", fourbar_closed_form), ("crank_slider", crank_slider_closed_form)],
    ids=["four-bar", "crank-slider"],
)
def test_closed_form_positions_velocities_accelerations(fixture, oracle):
    sketch = read_sketch(FIXTURES / f"{fixture}.edges")
    want = oracle(sketch, TURN)
    plan, motion = ours(fixture, TURN)
    for name in ("B", "C", "M"):
        if name not in want:
            continue
        got = motion.point(*plan.points[name])
        for what, g, w in zip(("position", "velocity", "acceleration"), got, want[name],
                              strict=True):  # fmt: skip
            assert rel(g, w) <= RTOL, f"{fixture} {name} {what}: {rel(g, w):.2e}"
    for link, (angle, omega, epsilon) in want["links"].items():
        q, qd, qdd = motion.q[link], motion.qd[link], motion.qdd[link]
        assert np.max(np.abs(_wrap(q[:, 2] - angle))) <= RTOL * math.pi, f"link {link} angle"
        assert rel(qd[:, 2], omega) <= RTOL, f"link {link} ω"
        assert rel(qdd[:, 2], epsilon) <= RTOL, f"link {link} ε"
    if "slider" in want:
        for table, w in zip((motion.q, motion.qd, motion.qdd), want["slider"], strict=True):
            assert rel(table["3"][:, :2], w) <= RTOL, "slider travel"
            assert np.max(np.abs(table["3"][:, 2])) <= 1e-12, "the slider does not turn"
