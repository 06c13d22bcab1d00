"""Sweeps: the kinematics over a list of inputs (a whole crank turn by default).

Each pose starts Newton from the previous one, so the assembly mode of the
sketch is kept by continuity; a pose that cannot be assembled or a dead centre
stops the sweep with the error naming the group and the input, never a NaN.
Results are numpy arrays, one row per pose, ready to plot or export.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0.1 0", "point C 0.3 0.3", "point D 0.4 0"])
>>> s = sweep(make_plan(analyze(m)), steps=8)
>>> s.links["3"]["omega"].shape, round(float(s.inputs[1, 0]), 6)
((8,), 0.785398)
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from functools import partial

import numpy as np

from structure.errors import EdgeListError, EdgeListProblem
from structure.readwrite.textfile import MAX_FILE_BYTES, open_user_file

from ..kinetostatics.forces import forces_over
from ..results.state import Motion
from .dyads import PointLayout, laid_out
from .memory import BYTES_PER_POSE_ITEM, check_poses, memory_limit, pose_bytes
from .plan import SolvePlan
from .planar import cross, norm, rotate_many, units
from .solve import solve_poses
from .travel import cycle_inputs

__all__ = [
    "BYTES_PER_POSE_ITEM",
    "Sweep",
    "memory_limit",
    "parse_inputs",
    "read_inputs",
    "sweep",
    "transmission_angle",
]


class _LazyMapping(Mapping):
    """A read-only mapping whose content ``load()`` makes the first time it is read."""

    __slots__ = ("_data", "_load")

    def __init__(self, load: Callable[[], dict]) -> None:
        self._load = load
        self._data: dict | None = None

    def _items(self) -> dict:
        if self._data is None:
            self._data = self._load()
        return self._data

    def __getitem__(self, key: str):
        return self._items()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._items())

    def __len__(self) -> int:
        return len(self._items())

    def __repr__(self) -> str:
        return repr(self._items())


class _LazyValues(Mapping):
    """A read-only mapping of fixed keys, each value made by its own function when first read."""

    __slots__ = ("_makers", "_values")

    def __init__(self, makers: dict[str, Callable[[], np.ndarray]]) -> None:
        self._makers = makers
        self._values: dict[str, np.ndarray] = {}

    def __getitem__(self, key: str) -> np.ndarray:
        value = self._values.get(key)
        if value is None:
            value = self._values[key] = self._makers[key]()
        return value

    def __iter__(self) -> Iterator[str]:
        return iter(self._makers)

    def __len__(self) -> int:
        return len(self._makers)

    def __repr__(self) -> str:
        return repr({k: self[k] for k in self._makers})


@dataclass(frozen=True)
class Sweep:
    """Arrays over the poses of a sweep.

    ``inputs`` has shape (poses, drivers); ``links[name]`` holds ``angle``,
    ``omega``, ``epsilon`` (shape (poses,)); ``points[name]`` holds
    ``position``, ``velocity``, ``acceleration`` (shape (poses, 2));
    ``balancing`` the balancing moment (or force) when the file has loads;
    ``transmission[group]`` the transmission angle of each dyad, rad: RRR at
    the middle pin, in [0, π]; RRP the rod against the slide's normal, RPR,
    PRP, RPP as in :func:`_prismatic_transmission`, in [0, π/2]; 0 (or π) is a
    dead centre.

    The points' arrays are views into one block laid out once (a point on the
    ground: read-only constants); the links' angles and rates, the
    transmission angles and the balancing are computed when first read. A
    sweep of positions only (``sweep(..., rates=False)``) has ``position`` and
    ``angle`` alone, and no balancing.
    """

    inputs: np.ndarray
    links: Mapping[str, Mapping[str, np.ndarray]]
    points: Mapping[str, Mapping[str, np.ndarray]]
    transmission: Mapping[str, np.ndarray]
    balancing: Mapping[str, np.ndarray] = field(default_factory=dict)

    def as_dict(self) -> dict[str, np.ndarray]:
        """Flat ``{column name: array}``, e.g. ``'3.omega'``, ``'C.velocity.x'``."""
        out: dict[str, np.ndarray] = {}
        for k in range(self.inputs.shape[1]):
            out[f"input{k + 1}"] = self.inputs[:, k]
        for name, values in self.links.items():
            for key, arr in values.items():
                out[f"{name}.{key}"] = arr
        for name, values in self.points.items():
            for key, arr in values.items():
                out[f"{name}.{key}.x"] = arr[:, 0]
                out[f"{name}.{key}.y"] = arr[:, 1]
        for name, arr in self.transmission.items():
            out[f"transmission {name}"] = arr
        for name, arr in self.balancing.items():
            out[f"balancing {name}"] = arr
        return out

    def to_csv(self) -> str:
        """The sweep as CSV text, one row per pose, SI units and radians."""
        columns = self.as_dict()
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        writer.writerow(columns)
        for row in zip(*columns.values(), strict=True):
            writer.writerow([repr(float(x)) for x in row])
        return buffer.getvalue()


def transmission_angle(b: np.ndarray, c: np.ndarray, d: np.ndarray) -> float:
    """Angle at the middle pin ``c`` between ``c − b`` and ``c − d`` (rad, in [0, π]).

    >>> round(math.degrees(transmission_angle(np.array([0, 0]), np.array([1, 1]),
    ...                                       np.array([2, 0]))), 6)
    90.0
    """
    u, v = c - b, c - d
    cos = float(u @ v) / (float(norm(u)) * float(norm(v)))
    return math.acos(max(-1.0, min(1.0, cos)))


def _directions(v: np.ndarray) -> np.ndarray:
    """Each row of ``v`` (N, 2) divided by its length (no product of two lengths: any unit)."""
    return v / norm(v)[:, None]


def _between(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The angle between the rows of ``u`` and ``v`` (N, 2), in [0, π], to rounding at any angle.

    ``atan2(|u × v|, u · v)``: unlike the arccosine of the dot product, as
    exact near 0° and 180° as near 90°.
    """
    return np.arctan2(np.abs(cross(u, v)), np.einsum("ij,ij->i", u, v))


def _angles(b: np.ndarray, c: np.ndarray, d: np.ndarray) -> np.ndarray:
    return _between(_directions(c - b), _directions(c - d))


def _rrr_pins(plan: SolvePlan) -> dict[str, tuple[str, str, str]]:
    """Point names (external, middle, external) of each RRR dyad with named pins."""
    out = {}
    for step in plan.steps:
        g = step.group
        if g is None or g.kind != "RRR":
            continue
        ext = [p.point for p in g.external_pairs]
        mid = [p.point for p in g.internal_pairs]
        if len(ext) == 2 and len(mid) == 1 and all(x in plan.points for x in (*ext, *mid)):
            out[g.label] = (ext[0], mid[0], ext[1])  # type: ignore[assignment]
    return out


def sweep(
    plan: SolvePlan, inputs: np.ndarray | None = None, steps: int = 360, *, rates: bool = True
) -> Sweep:
    """Solve every pose of ``inputs`` (shape (poses,) or (poses, drivers)).

    By default the drivers go through one cycle from the sketch in ``steps``
    equal steps (:func:`~kinematics.solvers.travel.cycle_inputs`): a turning
    driver one turn (several drivers at the ratio of the speeds the file
    gives them, each a whole number of turns), a sliding driver alone its
    stroke, from one dead point to the other (a little short of each). With
    ``rates`` false only the positions are solved (points' ``position``, links'
    ``angle``); a dyad's joint is then the closed form's own value, which the
    full sweep's (carried through a link's frame, as it always was) matches to
    rounding.

    Raises
    ------
    SweepSizeError
        The poses would take more memory than a sweep may (:func:`memory_limit`).
    TravelError
        A sliding driver that cannot move from the sketch (no stroke to sweep).
    AssemblyError, SingularPoseError
        At the first pose that cannot be solved, naming it (a branch change
        is a :class:`~kinematics.errors.BranchChangeError`).
    """
    if inputs is None:
        _check_size(plan, steps, rates)
        inputs = cycle_inputs(plan, steps)
    inputs = np.asarray(inputs, dtype=float)
    if inputs.ndim == 1:
        inputs = inputs[:, None]
    _check_size(plan, inputs.shape[0], rates)
    layout = _layout(plan, inputs, rates)
    with laid_out(layout):  # the solve writes the named pins and joints into their rows
        motion = solve_poses(plan, inputs, rates=rates)
    points = _point_block(plan, motion, layout)
    keys = ("angle", "omega", "epsilon") if rates else ("angle",)
    links = {
        name: _LazyValues({key: partial(_link_column, motion, name, key) for key in keys})
        for name in plan.mechanism.moving_links
        if name in motion.q
    }
    transmission = _LazyMapping(partial(_transmission, plan, motion, points))
    balancing: Mapping[str, np.ndarray] = (
        _LazyMapping(partial(_balancing, plan, motion)) if rates else {}
    )
    return Sweep(inputs, links, points, transmission, balancing)


def _check_size(plan: SolvePlan, poses: int, rates: bool, what: str = "") -> None:
    """Refuse a sweep whose results would not fit in the memory a run may take."""
    check_poses(plan, poses, rates, what=what)


def _link_column(motion: Motion, link: str, key: str) -> np.ndarray:
    """A link's angle, ω or ε over the poses (the angle by ``arctan2``, when first read)."""
    if key == "angle":
        return motion.q[link][:, 2]
    return (motion.qd if key == "omega" else motion.qdd)[link][:, 2]


def _layout(plan: SolvePlan, inputs: np.ndarray, rates: bool) -> PointLayout:
    """One block for every named point off the ground: shape (points, 1 or 3, 2, poses).

    Each point's quantity is the transposed view ``block[i, k].T``, of shape
    (poses, 2), with x and y each contiguous. A row is keyed by the point's
    link and sketch coordinates, as the solve finds it.
    """
    ground = plan.mechanism.ground
    moving = [(link, c) for link, c in plan.points.values() if link != ground]
    block = np.empty((len(moving), 3 if rates else 1, 2, inputs.shape[0]))
    rows = {(link, float(c[0]), float(c[1])): i for i, (link, c) in enumerate(moving)}
    return PointLayout(block, rows, inputs)


def _point_block(
    plan: SolvePlan, motion: Motion, layout: PointLayout
) -> dict[str, dict[str, np.ndarray]]:
    """Every named point's position (velocity, acceleration), as views into ``layout``'s block.

    The rows the solve has not filled are filled here. A point on the ground
    is a read-only constant; a point on a link the solve does without (a
    rolling gear mesh's virtual link) is left out.
    """
    n = motion.inputs.shape[0]
    block = layout.block
    rates = block.shape[1] == 3
    keys = ("position", "velocity", "acceleration") if rates else ("position",)
    ground = plan.mechanism.ground
    zero = np.broadcast_to(np.zeros(2), (n, 2))
    out: dict[str, dict[str, np.ndarray]] = {}
    for name, (link, c) in plan.points.items():
        if link == ground:
            fixed = np.broadcast_to(c.astype(float), (n, 2))
            out[name] = dict(zip(keys, (fixed, zero, zero), strict=False))
            continue
        if link not in motion.q:
            continue
        i = layout.rows[(link, float(c[0]), float(c[1]))]
        if i not in layout.filled:
            layout.filled.add(i)
            _fill_point(motion, link, c, block[i], rates)
        out[name] = {key: block[i, k].T for k, key in enumerate(keys)}
    return out


def _fill_point(motion: Motion, link: str, c: np.ndarray, rows: np.ndarray, rates: bool) -> None:
    """Write the motion of sketch point ``c`` of ``link`` into ``rows`` (1 or 3, 2, poses)."""
    targets = tuple(rows[k // 2, k % 2] for k in range(6 if rates else 2))
    found = motion.pins.get((link, float(c[0]), float(c[1])))
    if found is not None:  # found by the solve from the link's frame: the same values
        for target, value in zip(targets, found, strict=False):
            target[...] = value
        return
    frame = motion.frames.get(link)
    if frame is not None:
        frame.point_into(c, targets)
        return
    if rates:
        x, v, a = motion.point(link, c)
        for k, value in enumerate((x, v, a)):
            rows[k] = value.T
        return
    q = motion.q[link]
    rows[0] = (q[:, :2] + rotate_many(q[:, 2], c)).T


def _transmission(plan: SolvePlan, motion: Motion, points) -> dict[str, np.ndarray]:
    """Each dyad's transmission angle over the poses (see :class:`Sweep`)."""
    out = {
        label: _angles(points[b]["position"], points[c]["position"], points[d]["position"])
        for label, (b, c, d) in _rrr_pins(plan).items()
        if all(x in points for x in (b, c, d))
    }
    out.update(_rrp_transmission(plan, motion, points))
    out.update(_prismatic_transmission(plan, motion, points))
    return out


def _balancing(plan: SolvePlan, motion: Motion) -> dict[str, np.ndarray]:
    """The balancing moment (or force) over the poses, when the file has loads."""
    profiled = {cam.virtual for cam in plan.cams}  # a designed cam's contact force is solved
    rolled = any(link not in motion.q for link, *_ in plan.contacts if link not in profiled)
    if not plan.mechanism.loads or rolled or any(s.group is None for s in plan.steps):
        return {}
    forces = forces_over(plan, motion)
    sliding = {d.link for d in plan.drivers if d.kind == "P"}
    balancing = {
        f"{'slide force' if k in sliding else 'moment'} {k}": v
        for k, v in forces.balancing_moment.items()
    }
    if forces.balancing_force is not None:
        balancing["force x"] = forces.balancing_force[:, 0]
        balancing["force y"] = forces.balancing_force[:, 1]
    return balancing


def _slide_direction(plan: SolvePlan, motion, pair_id: int, link: str) -> np.ndarray | None:
    """World direction of a prismatic pair's slide, turning with ``link`` (N, 2)."""
    pair = plan.mechanism.pair(pair_id)
    if pair.angle is None:
        return None
    theta = motion.q[link][:, 2] if link in motion.q else np.zeros(len(motion.inputs))
    return units(pair.angle + theta)


def _prismatic_transmission(plan: SolvePlan, motion, points) -> dict[str, np.ndarray]:
    """RPR, PRP and RPP dyads, in [0, π/2]; 0 is the dead centre of each.

    RPR (rocking block): 90° less the angle between the slide and the line from the
    block's pin to the slotted link's pivot. PRP and RPP: the angle between the two
    slides that meet (both angles are fixed by the guides, so only their crossing
    transmits the force).
    """
    out = {}
    for step in plan.steps:
        g = step.group
        if g is None or g.kind not in ("RPR", "PRP", "RPP"):
            continue
        (mid,) = g.internal_pairs
        ext = list(g.external_pairs)
        if g.kind == "RPR":
            u = _slide_direction(plan, motion, mid.pair, mid.links[0])
            pins = [p.point for p in ext]
            if u is None or len(pins) != 2 or not all(x in points for x in pins):
                continue
            line = points[pins[1]]["position"] - points[pins[0]]["position"]
            out[g.label] = _off_square(line, u)  # 90° less the angle between line and slide
            continue
        slides = [p for p in (*ext, mid) if p.kind.value == "P"]
        if len(slides) != 2:
            continue
        dirs = [_slide_direction(plan, motion, p.pair, p.links[0]) for p in slides]
        if any(d is None for d in dirs):
            continue
        out[g.label] = _off_square(dirs[0], _turned_left(dirs[1]))  # the angle between them
    return out


def _turned_left(u: np.ndarray) -> np.ndarray:
    """The rows of ``u`` (N, 2) turned by 90°."""
    return np.column_stack([-u[:, 1], u[:, 0]])


def _off_square(v: np.ndarray, u: np.ndarray) -> np.ndarray:
    """How far the rows of ``v`` lean from square to the unit rows ``u``: asin(|v̂·u|), in [0, π/2].

    ``atan2(|v·u|, |v × u|)``: exact to rounding at any angle, and ``v`` may
    have any length (it is not squared); 0 for ``v`` zero.
    """
    return np.arctan2(np.abs(np.einsum("ij,ij->i", v, u)), np.abs(cross(v, u)))


def _rrp_transmission(plan: SolvePlan, motion, points) -> dict[str, np.ndarray]:
    """RRP dyads: the angle between the rod and the normal to the slide, in [0, π/2].

    90° when the rod pushes along the slide, 0° at the dead centre (rod ⟂ slide).
    """
    out = {}
    for step in plan.steps:
        g = step.group
        if g is None or g.kind != "RRP":
            continue
        rod_pin = [p for p in g.external_pairs if p.kind.value == "R"]
        slide = [p for p in g.external_pairs if p.kind.value == "P"]
        (mid,) = g.internal_pairs
        if len(rod_pin) != 1 or len(slide) != 1 or mid.point not in points:
            continue
        if rod_pin[0].point not in points:
            continue
        pair = plan.mechanism.pair(slide[0].pair)
        if pair.angle is None:
            continue
        guide = slide[0].links[1]
        theta = motion.q[guide][:, 2] if guide in motion.q else np.zeros(len(motion.inputs))
        u = units(pair.angle + theta)
        rod = points[mid.point]["position"] - points[rod_pin[0].point]["position"]
        out[g.label] = _off_square(rod, u)
    return out


def parse_inputs(lines, plan: SolvePlan, source: str = "<inputs>") -> np.ndarray:
    """Driver inputs (poses, drivers) from text: one pose per line, one column per driver.

    A turning driver's column is its rotation from the sketch in degrees, a
    sliding driver's its displacement in metres. Columns are separated by
    commas or blanks; ``#`` starts a comment. A first line ``drivers 4 1``
    sets the column order; without it the columns follow the drivers' order.
    Every bad line is reported, with its number.

    >>> from structure import analyze, parse_edgelist
    >>> from kinematics import make_plan
    >>> plan = make_plan(analyze(parse_edgelist(["driver 1", "0 1 R A", "point A 0 0"])))
    >>> parse_inputs(["# crank angle", "0", "90"], plan).round(6).tolist()
    [[0.0], [1.570796]]
    """
    drivers = [d.link for d in plan.drivers]
    order = list(range(len(drivers)))
    rows: list[list[float]] = []
    problems: list[EdgeListProblem] = []
    first = True
    most = memory_limit() // pose_bytes(plan)  # more poses than a sweep of them may take
    lines = iter(lines)
    for line_no, raw in enumerate(lines, start=1):
        if len(rows) >= most:  # counted to the end, not kept: the sweep of them is refused
            poses = len(rows) + sum(1 for line in (raw, *lines) if line.split("#", 1)[0].strip())
            _check_size(plan, poses, True, f"the {poses} poses of {source}")
        text = raw.split("#", 1)[0].replace(",", " ").split()
        if not text:
            continue
        if first and text[0] == "drivers":
            first = False
            if sorted(text[1:]) != sorted(drivers):
                problems.append(
                    EdgeListProblem(
                        line_no,
                        raw.rstrip("\n"),
                        f"the drivers are {', '.join(drivers)}: name each once",
                    )
                )
            else:
                order = [text[1:].index(link) for link in drivers]
            continue
        first = False
        values = _numbers(text)
        if values is None:
            problems.append(EdgeListProblem(line_no, raw.rstrip("\n"), "not a row of numbers"))
        elif len(values) != len(drivers):
            problems.append(
                EdgeListProblem(
                    line_no,
                    raw.rstrip("\n"),
                    f"{len(values)} value(s) for {len(drivers)} driver(s) ({', '.join(drivers)})",
                )
            )
        else:
            rows.append([values[i] for i in order])
    if not rows and not problems:
        problems.append(EdgeListProblem(0, "", "no inputs: one line per pose is needed"))
    if problems:
        raise EdgeListError(source, problems)
    out = np.array(rows, dtype=float)
    for k, d in enumerate(plan.drivers):
        if d.kind == "R":
            out[:, k] = np.radians(out[:, k])
    return out


def _numbers(tokens: list[str]) -> list[float] | None:
    try:
        values = [float(t) for t in tokens]
    except ValueError:
        return None
    return values if all(math.isfinite(v) for v in values) else None


def read_inputs(path, plan: SolvePlan, max_bytes: int = MAX_FILE_BYTES) -> np.ndarray:
    """:func:`parse_inputs` of a file (an unreadable file is an :class:`EdgeListError` too).

    Only a regular file of at most ``max_bytes`` is read
    (:func:`~structure.readwrite.textfile.open_user_file`).
    """
    with open_user_file(path, max_bytes) as handle:
        return parse_inputs(handle, plan, str(path))
