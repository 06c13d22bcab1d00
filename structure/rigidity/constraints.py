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
from array import array
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from enum import Enum
from operator import attrgetter

import numpy as np

from ..errors import EdgeListError, EdgeListProblem
from ..kinds import PairKind
from ..model import Mechanism
from ..utils import FlatSequence, Ragged, int_array

__all__ = [
    "ROW_CODE",
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


@dataclass(frozen=True, slots=True, eq=False)
class ConstraintSystem:
    """Rows and unknowns of a mechanism's constraint equations, as flat arrays.

    The unknown blocks are numbered by the moving links (``links``): link
    ``i`` has its position at ``2i`` and its angle at ``2i + 1``; compound
    pins (``pins``) follow. Row block ``r`` touches the unknown blocks
    ``adj[adj_start[r]:adj_start[r + 1]]`` (``row_adj[r]``, in the order the
    matching should try them); ``row_size[r]`` is its number of scalar rows,
    ``row_pair[r]`` the pair id it comes from (0 for drivers), ``row_link[r]``
    the link it belongs to (pin rows, drivers) or ``""``. Flat arrays, not a
    tuple per row: a large mechanism has hundreds of thousands of rows.
    """

    mechanism: Mechanism
    links: tuple[str, ...]
    pins: tuple[str, ...]
    row_kind: tuple[RowKind, ...]
    row_size: array
    adj_start: array
    adj: array
    row_pair: array
    row_link: tuple[str, ...]
    n_pair_rows: int
    # the link and pin indexes, made on first use (the large paths never ask for them), and
    # the row codes (made by the numpy layout)
    _indexes: dict = field(default_factory=dict, repr=False)

    @property
    def unknowns(self) -> Sequence[Unknown]:
        """Each unknown block as an :class:`Unknown` (made on access)."""
        return _Unknowns(self.links, self.pins)

    @property
    def row_adj(self) -> Sequence[tuple[int, ...]]:
        """The unknown blocks each row block touches, as tuples (made on access)."""
        return Ragged(self.adj, self.adj_start)

    @property
    def pos(self) -> Mapping[str, int]:
        """The position unknown of each moving link (made on first use)."""
        return self._numbered("pos", self.links, 0, 2)

    @property
    def ang(self) -> Mapping[str, int]:
        """The angle unknown of each moving link (made on first use)."""
        return self._numbered("ang", self.links, 1, 2)

    @property
    def pin(self) -> Mapping[str, int]:
        """The unknown of each compound pin, by its point (made on first use)."""
        return self._numbered("pin", self.pins, 2 * len(self.links), 1)

    def _numbered(self, key: str, names: Sequence[str], first: int, step: int) -> dict[str, int]:
        """``{names[k]: first + step * k}``, kept in the indexes under ``key``."""
        found = self._indexes.get(key)
        if found is None:
            numbers = range(first, first + step * len(names), step)
            found = self._indexes[key] = dict(zip(names, numbers, strict=True))
        return found

    def unknown_kind(self, u: int) -> str:
        """``'pos'``, ``'ang'`` or ``'pin'``: what unknown block ``u`` is."""
        if u >= 2 * len(self.links):
            return "pin"
        return "ang" if u & 1 else "pos"

    @property
    def n_unknowns(self) -> int:
        """Number of unknown blocks."""
        return 2 * len(self.links) + len(self.pins)

    def row_codes(self) -> np.ndarray:
        """Each row's kind as its position in :class:`RowKind` (numpy, for the large paths).

        Made once (read-only): the rank and the group plan both read it.
        """
        codes = self._indexes.get("codes")
        if codes is None:
            codes = self._indexes["codes"] = _codes_of(self.row_kind)
        return codes

    def unknown_size(self, u: int) -> int:
        """The size of unknown block ``u``: 1 for an angle, 2 for a position or a pin."""
        return 1 if u & 1 and u < 2 * len(self.links) else 2

    def unknown_sizes(self) -> list[int]:
        """The size of each unknown block (2, 1 for each link; 2 for each pin)."""
        return [2, 1] * len(self.links) + [2] * len(self.pins)

    @property
    def n_scalar_unknowns(self) -> int:
        return 3 * len(self.links) + 2 * len(self.pins)

    def scalar_offsets(self) -> tuple[np.ndarray, np.ndarray]:
        """Offsets of each unknown block and each row block in scalar numbering."""
        uo = np.fromiter(itertools.accumulate(self.unknown_sizes(), initial=0), int)
        ro = np.fromiter(itertools.accumulate(self.row_size, initial=0), int)
        return uo, ro

    def with_rows(
        self,
        kinds: Sequence[RowKind],
        sizes: Sequence[int],
        adjs: Sequence[tuple[int, ...]],
        links: Sequence[str],
    ) -> ConstraintSystem:
        """The same system with extra (driver or probe) rows appended."""
        adj = self.adj + array("i", itertools.chain.from_iterable(adjs))
        adj_start = (
            self.adj_start
            + array("q", itertools.accumulate((len(a) for a in adjs), initial=len(self.adj)))[1:]
        )
        return ConstraintSystem(
            self.mechanism,
            self.links,
            self.pins,
            self.row_kind + tuple(kinds),
            self.row_size + array("b", sizes),
            adj_start,
            adj,
            self.row_pair + array("i", [0]) * len(kinds),
            self.row_link + tuple(links),
            self.n_pair_rows,
            _extended_indexes(self._indexes, kinds),
        )


def _codes_of(kinds: Sequence[RowKind]) -> np.ndarray:
    """:meth:`ConstraintSystem.row_codes` of the row kinds ``kinds``."""
    objects = np.array(kinds, dtype=object)
    codes = np.zeros(len(objects), dtype=np.int8)
    for code, kind in enumerate(_KINDS[1:], start=1):
        codes[objects == kind] = code
    codes.setflags(write=False)
    return codes


def _extended_indexes(indexes: dict, kinds: Sequence[RowKind]) -> dict:
    """A system's indexes for the same system with rows of ``kinds`` appended.

    The link and pin indexes stay as they are; the row codes, if made, grow.
    """
    out = dict(indexes)
    codes = out.get("codes")
    if codes is not None:
        out["codes"] = np.concatenate([codes, _codes_of(kinds)])
        out["codes"].setflags(write=False)
    return out


class _Unknowns(FlatSequence):
    """The unknown blocks of a system as :class:`Unknown` records, made on access."""

    __slots__ = ("_links", "_pins")

    def __init__(self, links: tuple[str, ...], pins: tuple[str, ...]):
        self._links, self._pins = links, pins

    def __len__(self) -> int:
        return 2 * len(self._links) + len(self._pins)

    def _item(self, u: int) -> Unknown:
        n = 2 * len(self._links)
        if u >= n:
            return Unknown("pin", self._pins[u - n], 2)
        if u & 1:
            return Unknown("ang", self._links[u >> 1], 1)
        return Unknown("pos", self._links[u >> 1], 2)


_KINDS = tuple(RowKind)
#: each row kind's code in :meth:`ConstraintSystem.row_codes`
ROW_CODE = {kind: k for k, kind in enumerate(_KINDS)}


def constraint_system(mechanism: Mechanism, drivers: Sequence[str] = ()) -> ConstraintSystem:
    """Build the constraint system of ``mechanism`` with driver rows for ``drivers``.

    >>> from structure import Mechanism
    >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "3", "R"),
    ...                           ("3", "0", "R")])
    >>> s = constraint_system(m, ["1"])
    >>> s.n_scalar_unknowns, sum(s.row_size)
    (9, 9)
    """
    links = mechanism.moving_links
    pins = _compound_rows(mechanism, 2 * len(links))
    build = _system_by_numpy if len(mechanism.pairs) >= _NUMPY_PAIRS else _system_by_rows
    system = build(mechanism, links, pins)
    if not drivers:
        return system
    return system.with_rows(*zip(*(_driver_row(system, d) for d in drivers), strict=True))


#: from this many pairs on, the rows are laid out by numpy (below, one by one in Python,
#: which costs less for the small mechanisms of a batch)
_NUMPY_PAIRS = 256


def _newest_first(a: int, b: int) -> tuple[int, ...]:
    """The placement unknowns of links numbered ``a`` and ``b`` (-1: the ground), newest first.

    Newest first: the matching then stays local to the group being added.
    """
    hi, lo = (a, b) if a > b else (b, a)
    return (2 * hi + 1, 2 * hi, 2 * lo + 1, 2 * lo) if lo >= 0 else (2 * hi + 1, 2 * hi)


def _system_by_rows(
    mechanism: Mechanism, links: tuple[str, ...], pins: _PinRows
) -> ConstraintSystem:
    """The pair rows laid out one by one (a small mechanism's)."""
    compound = mechanism.compound_hinges
    number = {link: i for i, link in enumerate(links)}
    number[mechanism.ground] = -1
    rows: list[tuple[int, RowKind, int, int, tuple[int, ...], str]] = []
    for position, p in enumerate(mechanism.pairs):
        key = position * _ROW_STRIDE
        a, b = number[p.a], number[p.b]
        if p.kind is _R:
            if p.point is None or p.point not in compound:
                rows.append((key, _HINGE, 2, p.id, _newest_first(a, b), ""))
        elif p.kind is _P:
            angles = tuple(2 * x + 1 for x in sorted((a, b), reverse=True) if x >= 0)
            rows.append((key, _SLIDE_ANGLE, 1, p.id, angles, ""))
            rows.append((key + 1, _SLIDE, 1, p.id, _newest_first(a, b), ""))
        else:
            rows.append((key, _CONTACT, 1, p.id, _newest_first(a, b), ""))
    rows += zip(pins.key, itertools.repeat(_PIN), itertools.repeat(2), pins.pair, pins.adj,
                pins.links)  # fmt: skip
    rows.sort(key=lambda row: row[0])
    adjs = [row[4] for row in rows]
    return ConstraintSystem(
        mechanism,
        links,
        pins.pins,
        tuple(row[1] for row in rows),
        array("b", [row[2] for row in rows]),
        array("q", itertools.accumulate(map(len, adjs), initial=0)),
        array("i", itertools.chain.from_iterable(adjs)),
        array("i", [row[3] for row in rows]),
        tuple(row[5] for row in rows),
        len(rows),
    )


def _system_by_numpy(
    mechanism: Mechanism, links: tuple[str, ...], pins: _PinRows
) -> ConstraintSystem:
    """The pair rows laid out by numpy (a large mechanism's): one column per field."""
    rows = _pair_rows(mechanism)
    count = len(pins.key)
    pin_adj = np.full((count, 4), -1, dtype=np.int32)
    for k, adj in enumerate(pins.adj):
        pin_adj[k, : len(adj)] = adj
    order = np.argsort(
        np.concatenate([rows.key, np.array(pins.key, dtype=np.int64)]), kind="stable"
    )
    touched = np.concatenate([rows.adj, pin_adj])[order]
    del pin_adj
    present = touched >= 0
    adj_start = np.zeros(len(order) + 1, dtype=np.int64)
    np.cumsum(present.sum(axis=1), out=adj_start[1:])
    codes = np.concatenate([rows.kind, np.full(count, ROW_CODE[_PIN], dtype=np.int8)])[order]
    codes.setflags(write=False)
    row_link = [""] * len(order)
    for position in np.flatnonzero(order >= len(rows.key)).tolist():
        row_link[position] = pins.links[int(order[position]) - len(rows.key)]
    sizes = np.concatenate([rows.size, np.full(count, 2, dtype=np.int8)])
    pairs = np.concatenate([rows.pair, np.array(pins.pair, dtype=np.int32)])
    return ConstraintSystem(
        mechanism,
        links,
        pins.pins,
        tuple(map(_KINDS.__getitem__, codes.tolist())),
        int_array(sizes[order], "b"),
        int_array(adj_start, "q"),
        int_array(touched[present], "i"),
        int_array(pairs[order], "i"),
        tuple(row_link),
        len(order),
        {"codes": codes},
    )


@dataclass(frozen=True, slots=True)
class _Rows:
    """Row blocks as numpy columns, before they are put in order.

    ``key`` orders them (the pair's position, then the row's place in it);
    ``adj`` holds up to four unknowns per row (-1 past its end).
    """

    key: np.ndarray
    kind: np.ndarray
    size: np.ndarray
    pair: np.ndarray
    adj: np.ndarray


#: rows one pair can give (a compound pin gives one per link; see _compound_rows)
_ROW_STRIDE = 1 << 20


def _pair_rows(mechanism: Mechanism) -> _Rows:
    """The rows of every pair but the R pairs at a compound pin.

    Newest unknowns first in each row: the matching then stays local to the
    group being added.
    """
    pairs = mechanism.pairs
    n = len(pairs)
    # one pass in C per field (map, attrgetter): a large mechanism has 10^5 pairs
    kinds = np.array(list(map(attrgetter("kind"), pairs)), dtype=object)
    kind = np.where(kinds == _P, 1, np.where(kinds == _H, 2, 0)).astype(np.int8)
    if mechanism.compound_hinges:
        kind[mechanism.at_compound_hinge()] = 3  # R pairs at a compound pin
    # the system numbers links as the mechanism does, less the ground (-1)
    ends = mechanism.pair_ends()
    hi, lo = ends.max(axis=1) - 1, ends.min(axis=1) - 1
    ids = mechanism.pair_ids()
    plain = np.flatnonzero(kind < 3)  # hinges, contacts and the slide rows of P pairs
    slides = np.flatnonzero(kind == _KIND_OF[_P])
    # up to four unknowns per row (int32: a large mechanism has 10^5 rows), -1 past the end
    adj = np.full((len(plain) + len(slides), 4), -1, dtype=np.int32)
    on_ground = lo < 0
    adj[: len(plain), 0] = 2 * hi[plain] + 1
    adj[: len(plain), 1] = 2 * hi[plain]
    adj[: len(plain), 2] = np.where(on_ground, -1, 2 * lo + 1)[plain]
    adj[: len(plain), 3] = np.where(on_ground, -1, 2 * lo)[plain]
    adj[len(plain) :, 0] = 2 * hi[slides] + 1
    adj[len(plain) :, 1] = np.where(on_ground, -1, 2 * lo + 1)[slides]
    del hi, lo, on_ground
    position = np.arange(n, dtype=np.int64) * _ROW_STRIDE
    row_kind = np.array([ROW_CODE[_HINGE], ROW_CODE[_SLIDE], ROW_CODE[_CONTACT]], dtype=np.int8)
    return _Rows(
        key=np.concatenate([position[plain] + (kind[plain] == 1), position[slides]]),
        kind=np.concatenate(
            [row_kind[kind[plain]], np.full(len(slides), ROW_CODE[_SLIDE_ANGLE], dtype=np.int8)]
        ),
        size=np.concatenate(
            [np.where(kind[plain] == 0, 2, 1).astype(np.int8), np.ones(len(slides), np.int8)]
        ),
        pair=np.concatenate([ids[plain], ids[slides]]),
        adj=adj,
    )


_KIND_OF = {_R: 0, _P: 1, _H: 2}


@dataclass(frozen=True, slots=True)
class _PinRows:
    """The rows of the links at compound pins, and the pins that are unknowns.

    ``key[k]`` places row ``k`` among the pair rows (its pin's first R pair);
    ``adj[k]`` its unknowns, newest first.
    """

    key: list[int]
    pair: list[int]
    adj: list[tuple[int, ...]]
    links: list[str]
    pins: tuple[str, ...]


def _compound_rows(mechanism: Mechanism, pins_start: int) -> _PinRows:
    """Two rows per link at each compound pin, where the pin's first R pair is.

    The pin is an unknown (numbered in the order of its first pair, from
    ``pins_start`` on) unless the ground is there. The links at each pin and
    the first of its pairs each touches are read from the pairs' link numbers
    (:meth:`~structure.model.Mechanism.pair_ends`), not from their records.
    """
    compound = mechanism.compound_hinges
    out = _PinRows([], [], [], [], ())
    if not compound:
        return out
    ids = list(itertools.chain.from_iterable(h.pairs for h in compound.values()))
    positions = mechanism.pair_positions(ids)
    ends_at = mechanism.pair_ends()[positions]
    ends = zip(ids, positions.tolist(), ends_at[:, 0].tolist(), ends_at[:, 1].tolist(), strict=True)
    names = mechanism.links
    pins: list[str] = []
    keys, pair_ids, adjs, links = out.key, out.pair, out.adj, out.links
    for h in compound.values():  # in the order of their first pairs
        at_pin = list(itertools.islice(ends, len(h.pairs)))
        first_pair: dict[int, int] = {}  # each link's number (the ground 0): its first pair
        for pid, _, a, b in at_pin:
            first_pair.setdefault(a, pid)
            first_pair.setdefault(b, pid)
        pin: tuple[int, ...] = ()
        if 0 not in first_pair:
            pin = (pins_start + len(pins),)
            pins.append(h.point)
        key = at_pin[0][1] * _ROW_STRIDE  # where the pin's first pair is
        for k, pid in first_pair.items():
            if k:  # the system numbers links as the mechanism does, less the ground
                keys.append(key)
                key += 1
                pair_ids.append(pid)
                adjs.append((*pin, 2 * k - 1, 2 * k - 2))
                links.append(names[k])
    return _PinRows(keys, pair_ids, adjs, links, tuple(pins))


def _driver_row(system: ConstraintSystem, link: str) -> tuple[RowKind, int, tuple[int, ...], str]:
    m = system.mechanism
    joint = m.ground_joint(link)
    if joint is not None and joint.kind is _R:
        return _DRIVER, 1, (2 * system.links.index(link) + 1,), link
    if joint is not None:
        return _DRIVER, 1, (2 * system.links.index(link),), link
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
        if system.row_size[r] == system.unknown_size(u):
            return [(k, uo[u] + k, 1.0) for k in range(system.row_size[r])]
        # one generic combination of the block's coordinates
        return [(0, uo[u] + k, 1.0 + 0.37 * k) for k in range(system.unknown_size(u))]
    if kind is _DRIVER:
        u = system.row_adj[r][0]
        if system.unknown_kind(u) == "ang":
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
