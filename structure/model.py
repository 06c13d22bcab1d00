"""The kinematic graph: links are nodes, kinematic pairs are edges.

A :class:`Mechanism` is immutable. It wraps a frozen networkx ``MultiGraph``
whose nodes are link names and whose edges are :class:`Pair` records (keyed by
the pair's id, stored in the edge attribute ``pair``), plus the points of the
sketch. Revolute pairs that name the same point form one compound hinge: a
hinge joining k links is k - 1 pairs. Every transformation returns a new
Mechanism; nothing here computes anything beyond validation.

>>> m = Mechanism.from_pairs([("0", "1", "R", "A"), ("1", "2", "R", "B"),
...                           ("2", "3", "R", "C"), ("3", "0", "R", "D")],
...                          drivers=["1"], name="four-bar")
>>> m.moving_links
('1', '2', '3')
>>> [p.label for p in m.pairs][:2]
['0–1 R A', '1–2 R B']
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from enum import Enum
from functools import cached_property
from types import MappingProxyType
from typing import Any

import networkx as nx

from .errors import EdgeListError, EdgeListProblem

__all__ = [
    "DRIVER_KEYS",
    "LOAD_KINDS",
    "Driver",
    "GroundJoint",
    "Hinge",
    "Load",
    "Mechanism",
    "Pair",
    "PairKind",
    "PointDef",
    "pair_from_tokens",
    "validated",
]

#: motion keys accepted on a ``driver`` line (rad/s, rad/s², m/s, m/s²)
DRIVER_KEYS = ("omega", "epsilon", "v", "a")


def number_text(value: float) -> str:
    """Shortest text that reads back as the same float (``'0'`` for 0.0)."""
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


class PairKind(Enum):
    """Kind of a kinematic pair.

    ``R`` revolute and ``P`` prismatic are lower pairs of class 5 (P5, two
    constraints each); ``H`` is a higher pair of class 4 (P4, one constraint):
    a cam contact or a gear mesh.
    """

    R = "R"
    P = "P"
    H = "H"

    @property
    def constraints(self) -> int:
        """Number of scalar constraints the pair imposes in the plane."""
        return 1 if self is PairKind.H else 2


@dataclass(frozen=True, slots=True)
class Pair:
    """One kinematic pair between links ``a`` and ``b``.

    Parameters
    ----------
    id : int
        1-based position of the pair in its mechanism.
    kind : PairKind
    a, b : str
        The two links it joins.
    point : str or None
        R: the hinge point (pairs naming the same point form one compound
        hinge). P: a point of the slide line. H: the contact point.
    angle_deg : float or None
        P only: direction of the slide line, degrees counter-clockwise, as
        written in the file (``angle`` gives it in radians).
    span : float or None
        P only: distance between the slide's two contact points, centred on
        ``point`` (the kinetostatics then splits the reaction between them).
    friction : float or None
        P only: Coulomb friction coefficient of the slide.
    circle : float or None
        R only: friction-circle radius of the pin (metres).
    gear, teeth, internal, module
        H only: a gear mesh (``gear``), the tooth numbers of ``a`` and ``b``
        (``z=20,60``; None for an unknown ``?``), the link with internal
        teeth and the module (metres).
    flat : str or None
        H only: the link whose profile is a straight line at the contact.
    roller : str or None
        H only: the link that is a roller on this contact.
    centers : tuple of (str or None) or None
        H only: centres of curvature of the profiles of ``a`` and ``b``.
    normal_deg : float or None
        H only: direction of the common normal at the contact, degrees
        (``normal`` gives it in radians).
    line_no : int
        Line of the description it came from (0 when built in Python).
    """

    id: int
    kind: PairKind
    a: str
    b: str
    point: str | None = None
    angle_deg: float | None = None
    flat: str | None = None
    roller: str | None = None
    centers: tuple[str | None, str | None] | None = None
    normal_deg: float | None = None
    line_no: int = field(default=0, compare=False)
    span: float | None = None
    friction: float | None = None
    circle: float | None = None
    gear: bool = False
    teeth: tuple[int | None, int | None] | None = None
    internal: str | None = None
    module: float | None = None

    @property
    def angle(self) -> float | None:
        """Slide direction of a P pair in radians."""
        return None if self.angle_deg is None else math.radians(self.angle_deg)

    @property
    def normal(self) -> float | None:
        """Contact normal of an H pair in radians."""
        return None if self.normal_deg is None else math.radians(self.normal_deg)

    @property
    def links(self) -> tuple[str, str]:
        return (self.a, self.b)

    def other(self, link: str) -> str:
        """The link at the other end of the pair."""
        return self.b if link == self.a else self.a

    @property
    def label(self) -> str:
        """Short human statement, e.g. ``'1–2 R B'``."""
        return f"{self.a}–{self.b} {self.kind.value}" + (f" {self.point}" if self.point else "")

    @property
    def statement(self) -> str:
        """The pair's canonical edge-list line, e.g. ``'3 0 P C angle=30'``."""
        tokens = [self.a, self.b, self.kind.value]
        if self.point is not None:
            tokens.append(self.point)
        if self.gear:
            tokens.append("gear")
        if self.teeth is not None:
            tokens.append("z=" + ",".join("?" if t is None else str(t) for t in self.teeth))
        if self.internal is not None:
            tokens.append(f"internal={self.internal}")
        if self.module is not None:
            tokens.append(f"module={number_text(self.module)}")
        if self.angle_deg is not None:
            tokens.append(f"angle={number_text(self.angle_deg)}")
        if self.flat is not None:
            tokens.append(f"flat={self.flat}")
        if self.roller is not None:
            tokens.append(f"roller={self.roller}")
        if self.centers is not None:
            tokens.append("centers=" + ",".join(c or "" for c in self.centers))
        for key, value in (
            ("normal", self.normal_deg),
            ("span", self.span),
            ("friction", self.friction),
            ("circle", self.circle),
        ):
            if value is not None:
                tokens.append(f"{key}={number_text(value)}")
        return " ".join(tokens)

    def center_of(self, link: str) -> str | None:
        """Centre of curvature of ``link``'s profile at this higher pair."""
        if self.centers is None:
            return None
        return self.centers[0] if link == self.a else self.centers[1]

    def __repr__(self) -> str:
        return f"Pair({self.id}, {self.label!r})"


@dataclass(frozen=True, slots=True)
class PointDef:
    """Coordinates of a named point at the sketch pose (metres).

    ``on`` names the link the point is fixed to when it is a marker, not a
    pair location. ``exact`` keeps a coordinate written as an exact
    expression (``0.2*sqrt(3)``) as text; plain decimals need none.
    """

    name: str
    x: float
    y: float
    on: str | None = None
    line_no: int = field(default=0, compare=False)
    exact: tuple[str | None, str | None] = (None, None)

    @property
    def statement(self) -> str:
        """The canonical ``point`` line (exact expressions kept as written)."""
        on = f" on={self.on}" if self.on is not None else ""
        x = self.exact[0] or number_text(self.x)
        y = self.exact[1] or number_text(self.y)
        return f"point {self.name} {x} {y}{on}"


#: load statements and the numbers each takes after its link (and point)
LOAD_KINDS = {
    "force": ("point", 2),  # force LINK POINT fx fy (N, world frame)
    "moment": (None, 1),  # moment LINK M (N·m, counter-clockwise positive)
    "mass": ("point", 2),  # mass LINK m J S  (kg, kg·m² about the centre of mass S)
    "gravity": (None, 2),  # gravity gx gy (m/s²), no link
    "balance": ("point", 0),  # balance LINK POINT angle=DEG: a balancing force, not a moment
}


@dataclass(frozen=True, slots=True)
class Load:
    """A load statement: ``force``, ``moment``, ``mass``, ``gravity`` or ``balance``.

    ``values`` holds its numbers in the order of the statement (``fx, fy``;
    ``M``; ``m, J``; ``gx, gy``; the direction in degrees for ``balance``).
    """

    kind: str
    link: str
    point: str | None
    values: tuple[float, ...]
    line_no: int = field(default=0, compare=False)
    exact: tuple[str | None, ...] = ()

    def text(self, k: int) -> str:
        """The ``k``-th number as written (an exact expression) or as its shortest decimal."""
        written = self.exact[k] if k < len(self.exact) else None
        return written or number_text(self.values[k])

    @property
    def statement(self) -> str:
        """The canonical load line."""
        numbers = [self.text(k) for k in range(len(self.values))]
        if self.kind == "gravity":
            return "gravity " + " ".join(numbers)
        head = [self.kind, self.link] + ([self.point] if self.point else [])
        if self.kind == "balance":
            return " ".join([*head, f"angle={numbers[0]}"])
        if self.kind == "mass":
            return " ".join([self.kind, self.link, *numbers, self.point or ""]).strip()
        return " ".join([*head, *numbers])


@dataclass(frozen=True, slots=True)
class Driver:
    """A driving link and its prescribed motion (``omega``, ``epsilon``, ``v``, ``a``)."""

    link: str
    motion: tuple[tuple[str, float], ...] = ()
    line_no: int = field(default=0, compare=False)

    @property
    def statement(self) -> str:
        """The canonical ``driver`` line."""
        return " ".join(["driver", self.link, *(f"{k}={number_text(v)}" for k, v in self.motion)])


@dataclass(frozen=True, slots=True)
class Hinge:
    """A revolute joint as a point: the links that meet at it and its pairs.

    A hinge of k links carries k - 1 revolute pairs.
    """

    point: str
    links: tuple[str, ...]
    pairs: tuple[int, ...]


@dataclass(frozen=True, slots=True)
class GroundJoint:
    """How a link is jointed to the ground, if it can drive: pinned (R) or sliding (P).

    ``pair`` is the R or P pair with the ground, or None when the link shares
    a compound hinge with the ground; ``point`` is the pivot of an R joint, or
    a point of the slide line of a P pair.
    """

    kind: PairKind
    pair: Pair | None
    point: str | None


def _freeze_graph(pairs: Iterable[Pair], links: Iterable[str]) -> nx.MultiGraph:
    g = nx.MultiGraph()
    g.add_nodes_from(links)
    g.add_edges_from((p.a, p.b, p.id, {"pair": p}) for p in pairs)
    return nx.freeze(g)


@dataclass(frozen=True)
class Mechanism:
    """An immutable planar mechanism: links, pairs, ground, drivers, points.

    Build it with :meth:`from_pairs`, :func:`~structure.readwrite.edgelist.parse_edgelist`
    or :func:`~structure.readwrite.jsonformat.mechanism_from_dict`; each validates the
    description and raises :class:`~structure.errors.EdgeListError` listing
    every problem found.
    """

    pairs: tuple[Pair, ...]
    ground: str = "0"
    drivers: tuple[Driver, ...] = ()
    points: Mapping[str, PointDef] = field(default_factory=dict)
    name: str = ""
    source: str = "<python>"
    loads: tuple[Load, ...] = ()
    links: tuple[str, ...] = field(init=False, repr=False, compare=False)
    hinges: tuple[Hinge, ...] = field(init=False, repr=False, compare=False)
    compound_hinges: Mapping[str, Hinge] = field(init=False, repr=False, compare=False)
    _by_id: dict[int, Pair] = field(init=False, repr=False, compare=False)
    _by_link: dict[str, list[Pair]] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "points", MappingProxyType(dict(self.points)))
        seen: dict[str, None] = {self.ground: None}
        for p in self.pairs:
            seen.setdefault(p.a)
            seen.setdefault(p.b)
        links = tuple(seen)
        object.__setattr__(self, "links", links)
        object.__setattr__(self, "hinges", _hinges(self.pairs))
        object.__setattr__(self, "_by_id", {p.id: p for p in self.pairs})
        by_link: dict[str, list[Pair]] = {link: [] for link in links}
        for p in self.pairs:
            by_link[p.a].append(p)
            by_link[p.b].append(p)
        object.__setattr__(self, "_by_link", by_link)
        compound = {h.point: h for h in self.hinges if len(h.links) > 2}
        object.__setattr__(self, "compound_hinges", MappingProxyType(compound))

    # ------------------------------------------------------------------ build
    @classmethod
    def from_pairs(
        cls,
        pairs: Iterable[Any],
        *,
        ground: str = "0",
        drivers: Iterable[str | Driver] = (),
        points: Mapping[str, tuple[float, float]] | Iterable[PointDef] = (),
        name: str = "",
        source: str = "<python>",
    ) -> Mechanism:
        """Build and validate a mechanism from Python data.

        Each pair is a :class:`Pair` or a tuple ``(a, b, kind[, point][, options])``
        where ``options`` is a dict with the same keys as the edge-list format
        (``angle`` in degrees, ``flat``, ``roller``, ``centers``, ``normal``).

        >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R", "B"),
        ...                           ("2", "0", "P", "C", {"angle": 0})])
        >>> [p.kind.value for p in m.pairs]
        ['R', 'R', 'P']
        """
        problems: list[EdgeListProblem] = []
        built: list[Pair] = []
        for i, item in enumerate(pairs, start=1):
            if isinstance(item, Pair):
                built.append(item)
                continue
            item = tuple(item)
            options = item[-1] if item and isinstance(item[-1], Mapping) else {}
            head = [str(t) for t in (item[:-1] if options else item)]
            tokens = head + [f"{k}={_option_text(v)}" for k, v in options.items()]
            pair, why = pair_from_tokens(tokens, i, 0)
            if pair is None:
                problems.append(EdgeListProblem(0, " ".join(tokens), f"pair {i}: {why}"))
            else:
                built.append(pair)
        if isinstance(points, Mapping):
            pts = {k: PointDef(k, float(v[0]), float(v[1])) for k, v in points.items()}
        else:
            pts = {p.name: p for p in points}
        drv = tuple(d if isinstance(d, Driver) else Driver(str(d)) for d in drivers)
        if problems:
            raise EdgeListError(source, problems)
        return validated(cls(tuple(built), str(ground), drv, pts, name, source))

    def evolve(self, **changes: Any) -> Mechanism:
        """A new mechanism with some fields replaced (``pairs``, ``drivers``, ...)."""
        fields = {
            "pairs": self.pairs,
            "ground": self.ground,
            "drivers": self.drivers,
            "points": self.points,
            "name": self.name,
            "source": self.source,
            "loads": self.loads,
        }
        fields.update(changes)
        if "drivers" in changes:
            fields["drivers"] = tuple(
                d if isinstance(d, Driver) else Driver(str(d)) for d in fields["drivers"]
            )
        return Mechanism(**fields)

    def with_drivers(self, drivers: Iterable[str]) -> Mechanism:
        """The same mechanism with another choice of driving links."""
        old = {d.link: d for d in self.drivers}
        return validated(self.evolve(drivers=tuple(old.get(d, Driver(d)) for d in drivers)))

    # ---------------------------------------------------------------- queries
    @cached_property
    def graph(self) -> nx.MultiGraph:
        """The kinematic graph: a frozen ``MultiGraph``, links as nodes, pairs as edges.

        Each edge is keyed by the pair's id and carries it as ``pair``. Built
        on first use.
        """
        return _freeze_graph(self.pairs, self.links)

    def joined(self, a: str, b: str) -> bool:
        """True when some pair joins links ``a`` and ``b``, or they share a compound hinge."""
        if any(p.other(a) == b for p in self._by_link.get(a, ())):
            return True
        return any(a in h.links and b in h.links for h in self.compound_hinges.values())

    def connected_to_ground(self) -> set[str]:
        """The links reachable from the ground through pairs."""
        seen = {self.ground}
        stack = [self.ground]
        while stack:
            link = stack.pop()
            for p in self._by_link.get(link, ()):
                other = p.other(link)
                if other not in seen:
                    seen.add(other)
                    stack.append(other)
        return seen

    def ground_joint(self, link: str) -> GroundJoint | None:
        """How ``link`` is jointed to the ground: an R pivot first, else a P slide, else None.

        A link is pinned to the ground by an R pair with it or by a compound
        hinge it shares with it; higher pairs do not count. This is the one
        answer to "can this link drive, and about what?".

        >>> m = Mechanism.from_pairs([("0", "1", "R", "A"), ("1", "2", "R", "B"),
        ...                           ("2", "0", "P", "C", {"angle": 0})])
        >>> m.ground_joint("1").point, m.ground_joint("2").kind.value, m.ground_joint("9")
        ('A', 'P', None)
        """
        to_ground = [p for p in self._by_link.get(link, ()) if p.other(link) == self.ground]
        pin = next((p for p in to_ground if p.kind is PairKind.R), None)
        if pin is not None:
            return GroundJoint(PairKind.R, pin, pin.point)
        if link != self.ground:
            for hinge in self.compound_hinges.values():
                if link in hinge.links and self.ground in hinge.links:
                    return GroundJoint(PairKind.R, None, hinge.point)
        slide = next((p for p in to_ground if p.kind is PairKind.P), None)
        return None if slide is None else GroundJoint(PairKind.P, slide, slide.point)

    @property
    def driver_links(self) -> tuple[str, ...]:
        return tuple(d.link for d in self.drivers)

    @property
    def moving_links(self) -> tuple[str, ...]:
        """Links other than the ground, in order of first appearance."""
        return tuple(link for link in self.links if link != self.ground)

    def pairs_of(self, link: str) -> Iterator[Pair]:
        """The pairs that touch ``link``, in file order."""
        return iter(self._by_link.get(link, ()))

    def pair(self, pair_id: int) -> Pair:
        """The pair with id ``pair_id``."""
        return self._by_id[pair_id]

    def coordinates(self, point: str) -> tuple[float, float] | None:
        p = self.points.get(point)
        return None if p is None else (p.x, p.y)

    def __repr__(self) -> str:
        title = f" {self.name!r}" if self.name else ""
        return f"<Mechanism{title}: {len(self.moving_links)} moving links, {len(self.pairs)} pairs>"


_PAIR_KEYS = {
    PairKind.R: ("circle",),
    PairKind.P: ("angle", "span", "friction"),
    PairKind.H: ("flat", "roller", "centers", "normal", "z", "internal", "module"),
}


def _angle(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(text)
    return value


def pair_from_tokens(tokens: list[str], pair_id: int, line_no: int) -> tuple[Pair | None, str]:
    """Read ``a b KIND [POINT] [key=value ...]`` into a Pair, or say what is wrong.

    Returns ``(pair, "")`` or ``(None, reason)``; never raises on bad tokens.

    >>> pair_from_tokens("3 0 P C angle=90".split(), 1, 5)[0].angle
    1.5707963267948966
    >>> pair_from_tokens("1 2 Q".split(), 1, 5)[1]
    "unknown pair kind 'Q' (use R, P or H)"
    """
    if len(tokens) < 3:
        return None, "a pair needs at least 'a b KIND'"
    a, b, kind_text = tokens[0], tokens[1], tokens[2]
    try:
        kind = PairKind(kind_text)
    except ValueError:
        return None, f"unknown pair kind {kind_text!r} (use R, P or H)"
    if a == b:
        return None, f"pair joins link {a} to itself"
    rest = tokens[3:]
    point = None
    gear = kind is PairKind.H and "gear" in rest
    if gear:
        rest = [t for t in rest if t != "gear"]
    if rest and "=" not in rest[0]:
        point, rest = rest[0], rest[1:]
    opts: dict[str, str] = {}
    for tok in rest:
        key, eq, value = tok.partition("=")
        if not eq or not key or not value:
            return None, f"unexpected token {tok!r} (options are key=value)"
        if key not in _PAIR_KEYS[kind]:
            allowed = ", ".join(_PAIR_KEYS[kind]) or "none"
            return None, f"unknown option {key!r} for a {kind.value} pair (allowed: {allowed})"
        if key in opts:
            return None, f"option {key!r} given twice"
        opts[key] = value
    fields: dict[str, Any] = {}
    try:
        if "angle" in opts:
            fields["angle_deg"] = _angle(opts["angle"])
        if "normal" in opts:
            fields["normal_deg"] = _angle(opts["normal"])
    except ValueError:
        return None, "angle and normal must be finite numbers of degrees"
    for key, meaning in (
        ("span", "the distance between the slide's two contact points (metres), > 0"),
        ("friction", "the Coulomb friction coefficient of the slide, >= 0"),
        ("circle", "the friction-circle radius of the pin (metres), >= 0"),
    ):
        if key not in opts:
            continue
        try:
            fields[key] = float(opts[key])
        except ValueError:
            return None, f"{key}= is {meaning}"
        value = fields[key]
        if not math.isfinite(value) or value < 0 or (key == "span" and value == 0):
            return None, f"{key}= is {meaning}"
    if "flat" in opts:
        fields["flat"] = opts["flat"]
    if "roller" in opts:
        fields["roller"] = opts["roller"]
    if "centers" in opts:
        parts = opts["centers"].split(",")
        if len(parts) != 2 or not any(parts):
            return (
                None,
                "centers=O1,O2 names the centres of curvature on a and b (one may be empty)",
            )
        fields["centers"] = (parts[0] or None, parts[1] or None)
    if gear or "z" in opts or "internal" in opts or "module" in opts:
        if not gear:
            return None, "z=, internal= and module= belong to a gear mesh: write 'gear'"
        fields["gear"] = True
        if "z" in opts:
            teeth = opts["z"].split(",")
            if len(teeth) != 2 or not all(t == "?" or (t.isdigit() and int(t) > 0) for t in teeth):
                return None, "z=za,zb gives the tooth numbers of a and b (positive integers or ?)"
            fields["teeth"] = tuple(None if t == "?" else int(t) for t in teeth)
        if "internal" in opts:
            if opts["internal"] not in (a, b):
                return None, f"internal={opts['internal']} is not one of the pair's links {a}, {b}"
            fields["internal"] = opts["internal"]
        if "module" in opts:
            try:
                fields["module"] = float(opts["module"])
            except ValueError:
                return None, "module= is the gear module in metres"
            if not math.isfinite(fields["module"]) or fields["module"] <= 0:
                return None, "module= is the gear module in metres"
    return Pair(pair_id, kind, a, b, point, line_no=line_no, **fields), ""


def _option_text(value: Any) -> str:
    if isinstance(value, (tuple, list)):
        return ",".join("" if v is None else str(v) for v in value)
    return str(value)


def _hinges(pairs: Iterable[Pair]) -> tuple[Hinge, ...]:
    """Group revolute pairs into hinges by point name (unnamed: one hinge each)."""
    by_point: dict[str, list[Pair]] = {}
    out: list[Hinge] = []
    for p in pairs:
        if p.kind is not PairKind.R:
            continue
        if p.point is None:
            out.append(Hinge(f"{p.a}–{p.b}#{p.id}", (p.a, p.b), (p.id,)))
        else:
            by_point.setdefault(p.point, []).append(p)
    for point, group in by_point.items():
        links: dict[str, None] = {}
        for p in group:
            links.setdefault(p.a)
            links.setdefault(p.b)
        out.append(Hinge(point, tuple(links), tuple(p.id for p in group)))
    return tuple(out)


def _pieces(nodes: Iterable[str], edges: Iterable[tuple[str, str]]) -> list[set[str]]:
    """Connected pieces of a small graph (union-find)."""
    parent = {x: x for x in nodes}

    def find(x: str) -> str:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b in edges:
        parent[find(a)] = find(b)
    pieces: dict[str, set[str]] = {}
    for x in parent:
        pieces.setdefault(find(x), set()).add(x)
    return list(pieces.values())


def validated(m: Mechanism, ground_line: int = 0) -> Mechanism:
    """Check a mechanism's topology; raise one EdgeListError listing every problem.

    Checks: at least one pair; no pair from a link to itself; compound hinges
    whose pairs connect all their links without a cycle; every link connected
    to the ground; drivers that exist and are joined to the ground; options
    that name links of their own pair.
    """
    problems: list[EdgeListProblem] = []

    def bad(line_no: int, reason: str, line: str = "") -> None:
        problems.append(EdgeListProblem(line_no, line, reason))

    first_of: dict[str, Pair] = {}
    for p in m.pairs:
        first_of.setdefault(p.a, p)
        first_of.setdefault(p.b, p)

    if not m.pairs:
        bad(0, "no kinematic pairs: the description is empty")
        raise EdgeListError(m.source, problems)
    for p in m.pairs:
        for role, link in (("flat", p.flat), ("roller", p.roller)):
            if link is not None and link not in (p.a, p.b):
                bad(
                    p.line_no,
                    f"{role}={link} is not one of the pair's links {p.a}, {p.b}",
                    p.statement,
                )
        if p.flat is not None and p.roller is not None and p.flat == p.roller:
            bad(p.line_no, f"link {p.flat} cannot be both flat and the roller", p.statement)
    for h in m.hinges:
        if len(h.pairs) < 2:
            continue
        parts = _pieces(h.links, [m.pair(i).links for i in h.pairs])
        first = m.pair(h.pairs[0])
        if len(parts) > 1:
            text = " | ".join(",".join(sorted(c)) for c in parts)
            bad(
                first.line_no,
                f"the pairs at point {h.point} do not connect its links ({text})",
                first.statement,
            )
        elif len(h.pairs) != len(h.links) - 1:
            cyc = m.pair(h.pairs[-1])
            bad(
                cyc.line_no,
                f"the pairs at point {h.point} close a cycle: a hinge of {len(h.links)} "
                f"links has {len(h.links) - 1} pairs, {len(h.pairs)} are listed",
                cyc.statement,
            )
    if not m._by_link.get(m.ground):
        bad(ground_line, f"the ground {m.ground} is joined to no link", f"ground {m.ground}")
    else:
        reach = m.connected_to_ground()
        loose = [link for link in m.links if link not in reach]
        if loose:
            first = min((first_of[x] for x in loose), key=lambda p: p.id)
            bad(
                first.line_no,
                f"link(s) not connected to the ground {m.ground}: {', '.join(loose)}",
                first.statement,
            )
    seen_drivers: set[str] = set()
    for d in m.drivers:
        if d.link in seen_drivers:
            bad(d.line_no, f"driver {d.link} is named twice", d.statement)
        seen_drivers.add(d.link)
        if d.link == m.ground:
            bad(d.line_no, f"the ground {d.link} cannot be a driver", d.statement)
        elif d.link not in m._by_link:
            bad(d.line_no, f"driver {d.link} is not a link of the mechanism", d.statement)
        elif not m.joined(d.link, m.ground):
            bad(
                d.line_no,
                f"driver {d.link} is not joined to the ground {m.ground}",
                d.statement,
            )
        for key, _ in d.motion:
            if key not in DRIVER_KEYS:
                bad(d.line_no, f"unknown driver option {key!r} (use {', '.join(DRIVER_KEYS)})")
    for load in m.loads:
        if load.kind != "gravity" and load.link not in m._by_link:
            bad(load.line_no, f"{load.kind} on unknown link {load.link}", load.statement)
        elif load.kind != "gravity" and load.link == m.ground and load.kind != "balance":
            bad(load.line_no, f"a {load.kind} on the ground does nothing", load.statement)
    for p in m.points.values():
        if not (math.isfinite(p.x) and math.isfinite(p.y)):
            bad(p.line_no, f"point {p.name} has non-finite coordinates", p.statement)
        if p.on is not None and p.on not in m._by_link:
            bad(p.line_no, f"point {p.name} is fixed to unknown link {p.on}", p.statement)
    if problems:
        # file order; problems of the whole file (line 0) last
        problems.sort(key=lambda q: (q.line_no == 0, q.line_no))
        raise EdgeListError(m.source, problems)
    return m
