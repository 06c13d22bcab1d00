"""The structural constraint system of a mechanism: unknowns, rows, Jacobians.

Unknowns come in blocks: the position (x, y) and the angle θ of each moving
link, and the position of each compound hinge's pin (a point shared by three
or more links; two-link hinges are eliminated, which changes no block
structure). Rows come from pairs and drivers:

===========================  ======  ==========================================
source                       size    unknowns touched
===========================  ======  ==========================================
two-link hinge (R pair)      2       pos, θ of both links
link at a compound pin       2       pos, θ of the link, the pin (if not ground)
P pair, angle row            1       θ of both links
P pair, slide row            1       pos, θ of both links
H pair (contact normal)      1       pos, θ of both links
driver on an R pair          1       θ of the driver
driver on a P pair           1       pos of the driver
===========================  ======  ==========================================

The ground has no unknowns. :func:`jacobian` evaluates the rows at a
realization: :func:`random_realization` gives a generic one (any placement is
a valid pose of *some* mechanism with this topology, so its rank is the
generic rank with probability 1), :func:`sketch_realization` the file's pose.
"""

from __future__ import annotations

import functools
import itertools
import math
import random
import zlib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from enum import Enum

import numpy as np

from ..errors import EdgeListError, EdgeListProblem
from ..kinds import PairKind
from ..model import Hinge, Mechanism

__all__ = [
    "ConstraintSystem",
    "MissingGeometry",
    "Realization",
    "RowKind",
    "Unknown",
    "constraint_system",
    "jacobian",
    "random_realization",
    "row_entries",
    "sketch_problems",
    "sketch_realization",
]


class RowKind(Enum):
    HINGE = "hinge"  # two-link hinge, 2 rows
    PIN = "pin"  # one link at a compound pin, 2 rows
    SLIDE_ANGLE = "slide angle"
    SLIDE = "slide"
    CONTACT = "contact"
    DRIVER = "driver"
    PROBE = "probe"  # a coordinate fixed to expose free motion


# module-level aliases: enum attribute lookups are slow in the hot loops below
_HINGE, _PIN, _SLIDE_ANGLE, _SLIDE, _CONTACT, _DRIVER, _PROBE = RowKind
_R, _P, _H = PairKind


@dataclass(frozen=True, slots=True)
class Unknown:
    """A block of unknowns: ``kind`` is ``'pos'`` (2), ``'ang'`` (1) or ``'pin'`` (2)."""

    kind: str
    owner: str  # link name, or hinge point for a pin
    size: int


@dataclass(frozen=True, slots=True)
class ConstraintSystem:
    """Rows and unknowns of a mechanism's constraint equations, as index lists.

    ``row_adj[r]`` lists the unknown blocks row block ``r`` touches, in the
    order the matching should try them; ``row_size[r]`` its number of scalar
    rows; ``row_pair[r]`` the pair id it comes from (0 for drivers);
    ``row_link[r]`` the link it belongs to (pin rows, drivers) or ``""``.
    """

    mechanism: Mechanism
    unknowns: tuple[Unknown, ...]
    row_kind: tuple[RowKind, ...]
    row_size: tuple[int, ...]
    row_adj: tuple[tuple[int, ...], ...]
    row_pair: tuple[int, ...]
    row_link: tuple[str, ...]
    pos: dict[str, int]
    ang: dict[str, int]
    pin: dict[str, int]
    n_pair_rows: int

    @property
    def n_scalar_unknowns(self) -> int:
        return sum(u.size for u in self.unknowns)

    def scalar_offsets(self) -> tuple[np.ndarray, np.ndarray]:
        """Offsets of each unknown block and each row block in scalar numbering."""
        uo = np.array([0, *itertools.accumulate(u.size for u in self.unknowns)], dtype=int)
        ro = np.array([0, *itertools.accumulate(self.row_size)], dtype=int)
        return uo, ro

    def with_rows(
        self,
        kinds: Sequence[RowKind],
        sizes: Sequence[int],
        adjs: Sequence[tuple[int, ...]],
        links: Sequence[str],
    ) -> ConstraintSystem:
        """The same system with extra (driver or probe) rows appended."""
        return ConstraintSystem(
            self.mechanism,
            self.unknowns,
            self.row_kind + tuple(kinds),
            self.row_size + tuple(sizes),
            self.row_adj + tuple(adjs),
            self.row_pair + (0,) * len(kinds),
            self.row_link + tuple(links),
            self.pos,
            self.ang,
            self.pin,
            self.n_pair_rows,
        )


def constraint_system(mechanism: Mechanism, drivers: Sequence[str] = ()) -> ConstraintSystem:
    """Build the constraint system of ``mechanism`` with driver rows for ``drivers``.

    >>> from structure import Mechanism
    >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "3", "R"),
    ...                           ("3", "0", "R")])
    >>> s = constraint_system(m, ["1"])
    >>> s.n_scalar_unknowns, sum(s.row_size)
    (9, 9)
    """
    rows = _Rows(mechanism)
    compound = dict(mechanism.compound_hinges)  # a plain dict: looked up once per pair
    done_points: set[str] = set()
    body = rows.body
    for p in mechanism.pairs:
        if p.kind is _R:
            h = compound.get(p.point) if p.point is not None else None
            if h is None:
                rows.add(_HINGE, 2, body(p.b) + body(p.a), p.id)
            elif h.point not in done_points:
                done_points.add(h.point)
                rows.add_compound_hinge(h)
        elif p.kind is _P:
            angles = tuple(rows.ang[x] for x in (p.b, p.a) if x != rows.ground)
            rows.add(_SLIDE_ANGLE, 1, angles, p.id)
            rows.add(_SLIDE, 1, body(p.b) + body(p.a), p.id)
        else:
            rows.add(_CONTACT, 1, body(p.b) + body(p.a), p.id)
    system = rows.system()
    if not drivers:
        return system
    return system.with_rows(*zip(*(_driver_row(system, d) for d in drivers), strict=True))


class _Rows:
    """The unknowns and the pair rows of a constraint system, while it is being built."""

    def __init__(self, mechanism: Mechanism) -> None:
        self.mechanism = mechanism
        self.ground = mechanism.ground
        self.unknowns: list[Unknown] = []
        self.pos: dict[str, int] = {}
        self.ang: dict[str, int] = {}
        self.pin: dict[str, int] = {}
        for link in mechanism.moving_links:
            self.pos[link] = len(self.unknowns)
            self.unknowns.append(Unknown("pos", link, 2))
            self.ang[link] = len(self.unknowns)
            self.unknowns.append(Unknown("ang", link, 1))
        self.kinds: list[RowKind] = []
        self.sizes: list[int] = []
        self.adjs: list[tuple[int, ...]] = []
        self.pair_of: list[int] = []
        self.link_of: list[str] = []

    def body(self, link: str) -> tuple[int, ...]:
        """The unknowns of a link's placement (none for the ground)."""
        return () if link == self.ground else (self.pos[link], self.ang[link])

    def add(
        self, kind: RowKind, size: int, adj: tuple[int, ...], pair_id: int, link: str = ""
    ) -> None:
        self.kinds.append(kind)
        self.sizes.append(size)
        # newest unknowns first: the matching then stays local to the group being added
        self.adjs.append(tuple(sorted(adj, reverse=True)))
        self.pair_of.append(pair_id)
        self.link_of.append(link)

    def add_compound_hinge(self, h: Hinge) -> None:
        """Two rows per link at the pin; the pin is an unknown unless the ground is there."""
        first_pair: dict[str, int] = {}
        for pid in h.pairs:
            for link in self.mechanism.pair(pid).links:
                first_pair.setdefault(link, pid)
        if self.ground in h.links:
            for link in h.links:
                if link != self.ground:
                    self.add(_PIN, 2, self.body(link), first_pair[link], link)
            return
        pin = self.pin[h.point] = len(self.unknowns)
        self.unknowns.append(Unknown("pin", h.point, 2))
        for link in h.links:
            self.add(_PIN, 2, (pin, *self.body(link)), first_pair[link], link)

    def system(self) -> ConstraintSystem:
        return ConstraintSystem(
            self.mechanism,
            tuple(self.unknowns),
            tuple(self.kinds),
            tuple(self.sizes),
            tuple(self.adjs),
            tuple(self.pair_of),
            tuple(self.link_of),
            self.pos,
            self.ang,
            self.pin,
            len(self.kinds),
        )


def _driver_row(system: ConstraintSystem, link: str) -> tuple[RowKind, int, tuple[int, ...], str]:
    m = system.mechanism
    joint = m.ground_joint(link)
    if joint is not None and joint.kind is _R:
        return _DRIVER, 1, (system.ang[link],), link
    if joint is not None:
        return _DRIVER, 1, (system.pos[link],), link
    raise EdgeListError(
        m.source,
        [EdgeListProblem(0, "", f"driver {link} is not joined to the ground by an R or P pair")],
    )


# --------------------------------------------------------------------------- numbers
@dataclass(frozen=True, slots=True)
class Realization:
    """Numbers that place a constraint system: one entry per row block.

    ``origin[link]`` is the link's reference point, ``point[r]`` the location
    of row block ``r`` (pin or contact), ``direction[r]`` the unit slide
    direction of a P row, the contact normal of an H row or the slide of a
    P driver.
    """

    origin: Mapping[str, tuple[float, float]]
    point: Sequence[tuple[float, float] | None]
    direction: Sequence[tuple[float, float] | None]


@functools.lru_cache(maxsize=1 << 16)
def _generic_draw(seed: int, kind: str, key: tuple) -> tuple[float, float]:
    """The random pair (a unit direction, or a point in [-1, 1]²) for ``key``.

    A function of its arguments alone, so it is remembered: mechanisms share
    link names, pin names and row numbers, and seeding a generator costs more
    than the numbers it draws.
    """
    rng = random.Random(zlib.crc32(repr((seed, kind, key)).encode()))
    if kind == "direction":
        t = rng.uniform(0.0, 2.0 * math.pi)
        return (math.cos(t), math.sin(t))
    return (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))


class _GenericTable(Sequence):
    """Random numbers drawn on demand, the same for the same key.

    A generic realization only needs the rows that are actually evaluated
    (one block per pattern), so nothing is drawn for the others.
    """

    def __init__(self, seed: int, keys: Sequence[tuple], kind: str):
        self._seed = seed
        self._keys = keys
        self._kind = kind
        self._cache: dict[tuple, tuple[float, float]] = {}

    def __len__(self) -> int:
        return len(self._keys)

    def value(self, key: tuple) -> tuple[float, float]:
        found = self._cache.get(key)
        if found is None:
            found = self._cache[key] = _generic_draw(self._seed, self._kind, key)
        return found

    def __getitem__(self, r):  # type: ignore[override]
        if isinstance(r, slice):
            return [self.value(k) for k in self._keys[r]]
        return self.value(self._keys[r])


class _GenericOrigins(dict):
    """Link origins drawn on demand (the ground's is the origin)."""

    def __init__(self, seed: int, ground: str):
        super().__init__({ground: (0.0, 0.0)})
        self._table = _GenericTable(seed, (), "origin")

    def __missing__(self, link: str) -> tuple[float, float]:
        value = self._table.value(("link", link))
        self[link] = value
        return value


class _RowKeys(Sequence):
    """The key of each row's random point: rows at one pin or of one P pair share it."""

    def __init__(self, system: ConstraintSystem):
        self._system = system

    def __len__(self) -> int:
        return len(self._system.row_kind)

    def __getitem__(self, r):  # type: ignore[override]
        if isinstance(r, slice):
            return [self[i] for i in range(*r.indices(len(self)))]
        system = self._system
        kind = system.row_kind[r]
        if kind is _PIN:
            return ("pin", system.mechanism.pair(system.row_pair[r]).point)
        if kind is _SLIDE or kind is _SLIDE_ANGLE:
            return ("pair", system.row_pair[r])
        return ("row", r)


def random_realization(system: ConstraintSystem, seed: int = 20261121) -> Realization:
    """A generic placement: random link origins, pin points and directions.

    The numbers are drawn on demand from ``seed`` and each row's key, so the
    same system and seed always give the same realization.
    """
    keys = _RowKeys(system)
    return Realization(
        _GenericOrigins(seed, system.mechanism.ground),
        _GenericTable(seed, keys, "point"),
        _GenericTable(seed, keys, "direction"),
    )


class MissingGeometry(Exception):
    """Raised by :func:`sketch_realization` with the reasons the sketch is incomplete.

    ``problems`` holds them with their lines, ``reasons`` as text.
    """

    def __init__(self, problems: Sequence[EdgeListProblem]):
        self.problems = tuple(problems)
        self.reasons = tuple(f"line {p.line_no}: {p.reason}" for p in self.problems)
        super().__init__("; ".join(self.reasons))


def sketch_problems(mechanism: Mechanism) -> list[EdgeListProblem]:
    """What is missing for the sketch to fix the geometry, when some of it is given.

    Empty when no pair's point has coordinates (a purely structural
    description) or when the sketch is complete.
    """
    if not mechanism.points:
        return []
    located = any(
        p.point is not None and mechanism.coordinates(p.point) is not None for p in mechanism.pairs
    )
    if not located:
        return []
    try:
        sketch_realization(constraint_system(mechanism))
    except MissingGeometry as exc:
        return list(exc.problems)
    return []


def _contact_normal(mechanism: Mechanism, pair_id: int) -> tuple[float, float] | None:
    p = mechanism.pair(pair_id)
    if p.normal is not None:
        return (math.cos(p.normal), math.sin(p.normal))
    xy = mechanism.coordinates
    if p.centers is None:
        return None
    ca, cb = (None if c is None else xy(c) for c in p.centers)
    k = xy(p.point) if p.point else None
    if ca is not None and cb is not None:
        vx, vy = cb[0] - ca[0], cb[1] - ca[1]
    elif ca is not None and k is not None:
        vx, vy = k[0] - ca[0], k[1] - ca[1]
    elif cb is not None and k is not None:
        vx, vy = k[0] - cb[0], k[1] - cb[1]
    else:
        return None
    norm = math.hypot(vx, vy)
    return None if norm == 0 else (vx / norm, vy / norm)


def sketch_realization(system: ConstraintSystem) -> Realization:
    """The realization given by the file's ``point`` coordinates.

    Every link's reference point is the origin (any choice gives the same
    rank). Raises :class:`MissingGeometry` naming what is missing.
    """
    m = system.mechanism
    missing: list[EdgeListProblem] = []
    points: list[tuple[float, float] | None] = []
    dirs: list[tuple[float, float] | None] = []
    for r, kind in enumerate(system.row_kind):
        point = direction = None
        if kind in (_DRIVER, _PROBE):
            link = system.row_link[r]
            for p in m.pairs_of(link):
                if p.other(link) == m.ground and p.kind is _P and p.angle is not None:
                    direction = (math.cos(p.angle), math.sin(p.angle))
            points.append(None)
            dirs.append(direction)
            continue
        pair = m.pair(system.row_pair[r])
        if pair.point is None:
            missing.append(
                EdgeListProblem(
                    pair.line_no, pair.label, "the pair names no point, but the sketch is used"
                )
            )
        elif m.coordinates(pair.point) is None:
            missing.append(
                EdgeListProblem(
                    pair.line_no,
                    pair.label,
                    f"point {pair.point} has no coordinates (other points are given, "
                    "so the sketch is used)",
                )
            )
        else:
            point = m.coordinates(pair.point)
        if kind in (_SLIDE, _SLIDE_ANGLE):
            if pair.angle is None:
                if kind is _SLIDE:
                    missing.append(
                        EdgeListProblem(pair.line_no, pair.label, "P pair needs angle= in a sketch")
                    )
            else:
                direction = (math.cos(pair.angle), math.sin(pair.angle))
        elif kind is _CONTACT:
            direction = _contact_normal(m, pair.id)
            if direction is None:
                missing.append(
                    EdgeListProblem(
                        pair.line_no,
                        pair.label,
                        "H pair needs centers= with coordinates or normal= to fix its normal",
                    )
                )
        points.append(point)
        dirs.append(direction)
    if missing:
        raise MissingGeometry(list(dict.fromkeys(missing)))
    origin = dict.fromkeys(m.links, (0.0, 0.0))
    return Realization(origin, tuple(points), tuple(dirs))


def row_entries(
    system: ConstraintSystem, realization: Realization, r: int, uo: Sequence[int]
) -> list[tuple[int, int, float]]:
    """Nonzeros ``(local_row, scalar_column, value)`` of row block ``r``.

    ``uo`` holds the scalar offset of each unknown block (from
    :meth:`ConstraintSystem.scalar_offsets`, as a list).
    """
    m = system.mechanism
    kind = system.row_kind[r]
    ground = m.ground
    origin = realization.origin
    if kind is _HINGE:  # the common case first
        cx, cy = realization.point[r]  # type: ignore[misc]
        pair = m.pair(system.row_pair[r])
        out: list[tuple[int, int, float]] = []
        for link, sign in ((pair.a, 1.0), (pair.b, -1.0)):
            if link == ground:
                continue
            ox, oy = origin[link]
            p0 = uo[system.pos[link]]
            a0 = uo[system.ang[link]]
            out += (
                (0, p0, sign),
                (1, p0 + 1, sign),
                (0, a0, -sign * (cy - oy)),
                (1, a0, sign * (cx - ox)),
            )
        return out
    out = []
    if kind is _PROBE:
        u = system.row_adj[r][0]
        if system.row_size[r] == system.unknowns[u].size:
            return [(k, uo[u] + k, 1.0) for k in range(system.row_size[r])]
        # one generic combination of the block's coordinates
        return [(0, uo[u] + k, 1.0 + 0.37 * k) for k in range(system.unknowns[u].size)]
    if kind is _DRIVER:
        u = system.row_adj[r][0]
        if system.unknowns[u].kind == "ang":
            return [(0, uo[u], 1.0)]
        dx, dy = realization.direction[r] or (1.0, 0.0)
        return [(0, uo[u], dx), (0, uo[u] + 1, dy)]
    pair = m.pair(system.row_pair[r])
    if kind is _SLIDE_ANGLE:
        return [
            (0, uo[system.ang[link]], sign)
            for link, sign in ((pair.a, 1.0), (pair.b, -1.0))
            if link != ground
        ]
    cx, cy = realization.point[r]  # type: ignore[misc]
    if kind in (_SLIDE, _CONTACT):
        dx, dy = realization.direction[r]  # type: ignore[misc]
        nx_, ny_ = (-dy, dx) if kind is _SLIDE else (dx, dy)
        for link, sign in ((pair.a, -1.0), (pair.b, 1.0)):
            if link == ground:
                continue
            ox, oy = origin[link]
            p0 = uo[system.pos[link]]
            moment = nx_ * -(cy - oy) + ny_ * (cx - ox)
            out += (
                (0, p0, sign * nx_),
                (0, p0 + 1, sign * ny_),
                (0, uo[system.ang[link]], sign * moment),
            )
        return out
    # PIN: link position + rotated offset - pin = 0
    link = system.row_link[r]
    ox, oy = origin[link]
    p0 = uo[system.pos[link]]
    a0 = uo[system.ang[link]]
    out += ((0, p0, 1.0), (1, p0 + 1, 1.0), (0, a0, -(cy - oy)), (1, a0, cx - ox))
    pin = system.pin.get(pair.point) if pair.point is not None else None
    if pin is not None:
        out += ((0, uo[pin], -1.0), (1, uo[pin] + 1, -1.0))
    return out


def jacobian(
    system: ConstraintSystem, realization: Realization, rows: Sequence[int] | None = None
) -> np.ndarray:
    """Dense Jacobian of the row blocks ``rows`` (default all), scalar columns.

    >>> from structure import Mechanism
    >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "0", "R")])
    >>> s = constraint_system(m)
    >>> J = jacobian(s, random_realization(s))
    >>> J.shape, int(np.linalg.matrix_rank(J))
    ((6, 6), 6)
    """
    offsets, _ = system.scalar_offsets()
    uo = offsets.tolist()
    rows = range(len(system.row_kind)) if rows is None else rows
    at: list[int] = []
    cols: list[int] = []
    values: list[float] = []
    start = 0
    for r in rows:
        for lr, col, value in row_entries(system, realization, r, uo):
            at.append(start + lr)
            cols.append(col)
            values.append(value)
        start += system.row_size[r]
    J = np.zeros((start, uo[-1]))
    J[at, cols] = values
    return J
