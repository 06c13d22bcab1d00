"""The kinematic graph: links are nodes, kinematic pairs are edges.

A :class:`Mechanism` is immutable. It wraps a frozen networkx ``MultiGraph``
whose nodes are link names and whose edges are :class:`Pair` records (keyed by
the pair's id, stored in the edge attribute ``pair``), plus the points of the
sketch. Revolute pairs that name the same point form one compound hinge: a
hinge joining k links is k - 1 pairs. Every transformation returns a new
Mechanism; nothing here computes anything beyond validation.

The statements are built from Python values by :func:`make_pair`,
:func:`make_point`, :func:`make_load` and :func:`make_driver`, with the checks
of :mod:`structure.validation` that both readers share. ``PairKind``,
``LoadKind``, ``validated``, ``DRIVER_KEYS`` and ``LOAD_KINDS`` are defined in
:mod:`structure.kinds` and :mod:`structure.validation` and importable from
here as before.

>>> m = Mechanism.from_pairs([("0", "1", "R", "A"), ("1", "2", "R", "B"),
...                           ("2", "3", "R", "C"), ("3", "0", "R", "D")],
...                          drivers=["1"], name="four-bar")
>>> m.moving_links
('1', '2', '3')
>>> [p.label for p in m.pairs][:2]
['0–1 R A', '1–2 R B']
"""

from __future__ import annotations

import itertools
import math
import operator
from array import array
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import FrozenInstanceError, InitVar, dataclass, field
from functools import cached_property
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from .errors import EdgeListError, EdgeListProblem, StatementError
from .kinds import LoadKind, PairKind
from .utils import slot_setters
from .validation import (
    DRIVER_KEYS,
    LOAD_KINDS,
    check_driver,
    check_load,
    check_pair,
    check_pair_point,
    check_point,
    validated,
)

if TYPE_CHECKING:
    import networkx as nx

    from .cams import CamRef
    from .cycle import CycleLoad

__all__ = [
    "DRIVER_KEYS",
    "LOAD_KINDS",
    "Driver",
    "GroundJoint",
    "Hinge",
    "Load",
    "LoadKind",
    "Mechanism",
    "Pair",
    "PairKind",
    "PointDef",
    "Target",
    "make_driver",
    "make_load",
    "make_pair",
    "make_point",
    "make_target",
    "validated",
]


def number_text(value: float) -> str:
    """Shortest text that reads back as the same float (``'0'`` for 0.0)."""
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


#: the options of a pair other than its slide angle, in the order of :class:`Pair`'s fields,
#: with their defaults: most pairs of a large file have none of them (see :class:`Pair`)
_RARE_OPTIONS = (
    ("flat", None),
    ("roller", None),
    ("centers", None),
    ("normal_deg", None),
    ("span", None),
    ("friction", None),
    ("circle", None),
    ("gear", False),
    ("teeth", None),
    ("internal", None),
    ("module", None),
)
_NO_RARE_OPTIONS = tuple(default for _, default in _RARE_OPTIONS)


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

    Notes
    -----
    A large file is mostly pairs with no option but the slide angle, so the
    record stores ``id``, ``kind``, ``a``, ``b``, ``point``, ``angle_deg``,
    ``line_no`` and one field for all the other options (None when none is
    given: 96 bytes a pair instead of 176, issue 11). Those options are still
    parameters of the constructor and of :func:`dataclasses.replace`, read as
    attributes, and compared and hashed as before.
    """

    id: int
    kind: PairKind
    a: str
    b: str
    point: str | None = None
    angle_deg: float | None = None
    flat: InitVar[str | None] = None
    roller: InitVar[str | None] = None
    centers: InitVar[tuple[str | None, str | None] | None] = None
    normal_deg: InitVar[float | None] = None
    line_no: int = field(default=0, compare=False)
    span: InitVar[float | None] = None
    friction: InitVar[float | None] = None
    circle: InitVar[float | None] = None
    gear: InitVar[bool] = False
    teeth: InitVar[tuple[int | None, int | None] | None] = None
    internal: InitVar[str | None] = None
    module: InitVar[float | None] = None
    #: the options of :data:`_RARE_OPTIONS` in that order, or None when all are defaults
    _rare_options: tuple[Any, ...] | None = field(init=False, repr=False)

    def __init__(
        self,
        id: int,
        kind: PairKind,
        a: str,
        b: str,
        point: str | None = None,
        angle_deg: float | None = None,
        flat: str | None = None,
        roller: str | None = None,
        centers: tuple[str | None, str | None] | None = None,
        normal_deg: float | None = None,
        line_no: int = 0,
        span: float | None = None,
        friction: float | None = None,
        circle: float | None = None,
        gear: bool = False,
        teeth: tuple[int | None, int | None] | None = None,
        internal: str | None = None,
        module: float | None = None,
    ) -> None:
        # the dataclass's own __init__ written out, faster (see _fill_pair); the options but
        # the angle go to one field, None for the many pairs that have none
        rare = (flat, roller, centers, normal_deg, span, friction, circle, gear, teeth,
                internal, module)
        rare_options = None if rare == _NO_RARE_OPTIONS else rare
        _fill_pair(self, id, kind, a, b, point, angle_deg, line_no, rare_options)

    @classmethod
    def plain(
        cls,
        id: int,
        kind: PairKind,
        a: str,
        b: str,
        point: str | None = None,
        angle_deg: float | None = None,
        line_no: int = 0,
    ) -> Pair:
        """The same as ``Pair(id, kind, a, b, point, angle_deg, line_no=line_no)``, faster.

        The readers' way to build the plain pairs of a large file: a call of
        the class with keywords costs half as much again as the record.
        """
        pair = object.__new__(cls)
        _fill_pair(pair, id, kind, a, b, point, angle_deg, line_no, None)
        return pair

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


def _rare_option(position: int, name: str, default: Any) -> property:
    """The property that reads option ``name`` of a :class:`Pair` from its ``_rare_options``."""

    def read(pair: Pair) -> Any:
        rare = pair._rare_options
        return default if rare is None else rare[position]

    read.__name__ = name
    read.__doc__ = f"The pair's ``{name}`` ({default} when not given)."
    return property(read)


# set after the class is made: a dataclass takes a class attribute of a parameter's name
# for its default, and these parameters are InitVars whose values the properties read
for _position, (_name, _default) in enumerate(_RARE_OPTIONS):
    setattr(Pair, _name, _rare_option(_position, _name, _default))
del _position, _name, _default

_RARE_NAMES = frozenset(name for name, _ in _RARE_OPTIONS)
_RARE_OPTIONS_OF = operator.attrgetter("_rare_options")
_FIELDS_SETATTR, _FIELDS_DELATTR = Pair.__setattr__, Pair.__delattr__


def _frozen_setattr(pair: Pair, name: str, value: Any) -> None:
    """Refuse to set an option read through a property, as the frozen fields are refused."""
    if name in _RARE_NAMES:
        raise FrozenInstanceError(f"cannot assign to field {name!r}")
    _FIELDS_SETATTR(pair, name, value)


def _frozen_delattr(pair: Pair, name: str) -> None:
    """Refuse to delete an option read through a property, as the frozen fields are refused."""
    if name in _RARE_NAMES:
        raise FrozenInstanceError(f"cannot delete field {name!r}")
    _FIELDS_DELATTR(pair, name)


Pair.__setattr__ = _frozen_setattr  # type: ignore[method-assign]
Pair.__delattr__ = _frozen_delattr  # type: ignore[method-assign]

#: the setters of the slots of :class:`Pair`, in the order :func:`_fill_pair` unpacks them
_PAIR_SETTERS = slot_setters(
    Pair, ("id", "kind", "a", "b", "point", "angle_deg", "line_no", "_rare_options")
)


def _fill_pair(
    pair: Pair,
    id: int,
    kind: PairKind,
    a: str,
    b: str,
    point: str | None,
    angle_deg: float | None,
    line_no: int,
    rare_options: tuple[Any, ...] | None,
) -> None:
    """Set the fields of a new :class:`Pair` through its slots' setters.

    A frozen record refuses ``pair.x = value``; the slots' own setters are
    twice as fast as the ``object.__setattr__`` a dataclass's ``__init__``
    calls, and a large file has 10^6 pairs.
    """
    set_id, set_kind, set_a, set_b, set_point, set_angle, set_line, set_rare = _PAIR_SETTERS
    set_id(pair, id)
    set_kind(pair, kind)
    set_a(pair, a)
    set_b(pair, b)
    set_point(pair, point)
    set_angle(pair, angle_deg)
    set_line(pair, line_no)
    set_rare(pair, rare_options)


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


@dataclass(frozen=True, slots=True)
class Target:
    """A point the marker ``P`` is to pass through: a design target, kept for the figures.

    Written by the dimensional synthesis (``assur synthesize``) beside its
    design. ``input_deg`` is the driver's rotation from the sketch (degrees)
    at which ``P`` should be there (prescribed timing), ``angle_deg`` the
    orientation of ``P``'s link there (a pose of motion generation); either
    may be None.

    >>> Target("T1", 0.5, 1.0, input_deg=30.0).statement
    'target T1 0.5 1 input=30'
    """

    name: str
    x: float
    y: float
    input_deg: float | None = None
    angle_deg: float | None = None
    line_no: int = field(default=0, compare=False)

    @property
    def statement(self) -> str:
        """The canonical ``target`` line."""
        words = ["target", self.name, number_text(self.x), number_text(self.y)]
        if self.input_deg is not None:
            words.append(f"input={number_text(self.input_deg)}")
        if self.angle_deg is not None:
            words.append(f"angle={number_text(self.angle_deg)}")
        return " ".join(words)


@dataclass(frozen=True, slots=True)
class Load:
    """A load statement: ``force``, ``moment``, ``mass``, ``gravity`` or ``balance``.

    ``kind`` is a :class:`~structure.kinds.LoadKind` (a word given here is
    turned into one). ``values`` holds its numbers in the order of the
    statement (``fx, fy``; ``M``; ``m, J``; ``gx, gy``; the direction in
    degrees for ``balance``). :func:`make_load` builds one with its checks.
    """

    kind: LoadKind
    link: str
    point: str | None
    values: tuple[float, ...]
    line_no: int = field(default=0, compare=False)
    exact: tuple[str | None, ...] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.kind, LoadKind):
            object.__setattr__(self, "kind", LoadKind(self.kind))

    def text(self, k: int) -> str:
        """The ``k``-th number as written (an exact expression) or as its shortest decimal."""
        written = self.exact[k] if k < len(self.exact) else None
        return written or number_text(self.values[k])

    @property
    def statement(self) -> str:
        """The canonical load line."""
        numbers = [self.text(k) for k in range(len(self.values))]
        word = self.kind.value
        if self.kind is LoadKind.GRAVITY:
            return "gravity " + " ".join(numbers)
        head = [word, self.link] + ([self.point] if self.point else [])
        if self.kind is LoadKind.BALANCE:
            return " ".join([*head, f"angle={numbers[0]}"])
        if self.kind is LoadKind.MASS:
            return " ".join([word, self.link, *numbers, self.point or ""]).strip()
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


# ----------------------------------------------------------------------------- builders
_NUMBER_FIELDS = {
    "angle": "angle_deg",
    "normal": "normal_deg",
    "span": "span",
    "friction": "friction",
    "circle": "circle",
    "module": "module",
}


def make_pair(
    pair_id: int,
    kind: PairKind | str,
    a: str,
    b: str,
    point: str | None = None,
    *,
    gear: bool = False,
    line_no: int = 0,
    **options: Any,
) -> Pair:
    """Build a :class:`Pair` from Python values, with the checks every reader shares.

    Parameters
    ----------
    pair_id : int
        1-based position of the pair in its mechanism.
    kind : PairKind or str
        The kind or its letter (``"R"``, ``"P"``, ``"H"``).
    a, b : str
        The two links it joins.
    point : str or None
        The hinge point (R), a point of the slide line (P), the contact (H).
    gear : bool
        H only: the pair is a gear mesh (the ``gear`` word of a line).
    line_no : int
        Line of the description it comes from (0 when built in Python).
    **options
        The edge-list options with typed values: ``angle``, ``normal``
        (degrees), ``span``, ``friction``, ``circle``, ``module`` (numbers);
        ``flat``, ``roller``, ``internal`` (link names); ``centers`` (two
        point names, one may be None); ``z`` (two tooth numbers, None for an
        unknown one). None is the same as leaving the option out.

    Raises
    ------
    StatementError
        An unknown kind, a pair from a link to itself, an option the kind
        does not take, a value out of its range
        (:func:`~structure.validation.check_pair`).

    >>> make_pair(1, "P", "3", "0", "C", angle=30).statement
    '3 0 P C angle=30'
    >>> make_pair(2, PairKind.H, "1", "2", "K", gear=True, z=(20, None)).teeth
    (20, None)
    """
    given = {key: value for key, value in options.items() if value is not None} if options else {}
    kind = check_pair(kind, a, b, given, gear=gear)
    if point is not None:
        check_pair_point(kind, point)
    if not given and not gear:
        return Pair.plain(pair_id, kind, a, b, point, line_no=line_no)
    return Pair(pair_id, kind, a, b, point, line_no=line_no, gear=bool(gear), **_pair_fields(given))


def _pair_fields(options: Mapping[str, Any]) -> dict[str, Any]:
    """The :class:`Pair` fields of checked options (numbers as floats, ``z`` as ``teeth``)."""
    fields: dict[str, Any] = {}
    for key, value in options.items():
        if key in _NUMBER_FIELDS:
            fields[_NUMBER_FIELDS[key]] = float(value)
        elif key == "centers":
            fields["centers"] = tuple(c or None for c in value)
        elif key == "z":
            fields["teeth"] = tuple(None if t is None else int(t) for t in value)
        else:  # flat, roller, internal: link names
            fields[key] = value
    return fields


def _pair_from_item(item: Sequence[Any], pair_id: int) -> Pair:
    """A pair from ``(a, b, kind[, point][, options])`` (see :meth:`Mechanism.from_pairs`)."""
    options: Mapping[str, Any] = {}
    if item and isinstance(item[-1], Mapping):
        item, options = item[:-1], item[-1]
    if len(item) < 3:
        raise StatementError("a pair needs at least 'a b KIND'")
    if len(item) > 4:
        raise StatementError("a pair is (a, b, kind[, point][, options])")
    kind = item[2] if isinstance(item[2], PairKind) else str(item[2])
    point = None if len(item) < 4 or item[3] is None else str(item[3])
    named = {key: _names_as_text(key, value) for key, value in options.items()}
    return make_pair(pair_id, kind, str(item[0]), str(item[1]), point, **named)


def _names_as_text(key: str, value: Any) -> Any:
    """An option naming links or points, its names as strings (numbers name links too)."""
    if value is None:
        return None
    if key in ("flat", "roller", "internal"):
        return str(value)
    if key == "centers" and isinstance(value, (tuple, list)):
        return tuple(None if c is None else str(c) for c in value)
    return value


def make_point(
    name: str,
    x: float,
    y: float,
    on: str | None = None,
    *,
    line_no: int = 0,
    exact: tuple[str | None, str | None] = (None, None),
) -> PointDef:
    """Build a :class:`PointDef`, with the checks every reader shares.

    Raises
    ------
    StatementError
        A coordinate that is not a finite number.
    """
    check_point(name, x, y, on)
    return PointDef(name, float(x), float(y), on, line_no, exact)


def make_target(
    name: str,
    x: float,
    y: float,
    input_deg: float | None = None,
    angle_deg: float | None = None,
    *,
    line_no: int = 0,
) -> Target:
    """Build a :class:`Target`, with the checks of a point's coordinates for all its numbers.

    Raises
    ------
    StatementError
        A coordinate, input or angle that is not a finite number within the limits.
    """
    check_point(name, x, y)
    for value in (input_deg, angle_deg):
        if value is not None:
            check_point(name, value, 0.0)
    return Target(
        name,
        float(x),
        float(y),
        None if input_deg is None else float(input_deg),
        None if angle_deg is None else float(angle_deg),
        line_no,
    )


def make_load(
    kind: LoadKind | str,
    link: str,
    point: str | None,
    values: Sequence[float],
    *,
    line_no: int = 0,
    exact: tuple[str | None, ...] = (),
) -> Load:
    """Build a :class:`Load`, with the checks every reader shares.

    ``link`` is ``""`` for gravity; ``point`` is None for a moment or gravity.

    Raises
    ------
    StatementError
        An unknown kind, a link or point the kind does not take (or lacks),
        the wrong number of values, a value that is not finite, a negative
        mass or moment of inertia (:func:`~structure.validation.check_load`).

    >>> make_load("mass", "2", "S2", (3, 0.1)).statement
    'mass 2 3 0.1 S2'
    """
    kind = check_load(kind, link, point, values)
    return Load(kind, link, point, tuple(float(v) for v in values), line_no, exact)


def make_driver(
    link: str, motion: Iterable[tuple[str, float]] = (), *, line_no: int = 0
) -> Driver:
    """Build a :class:`Driver`, with the checks every reader shares.

    Raises
    ------
    StatementError
        A motion key other than ``omega``, ``epsilon``, ``v``, ``a``, or a
        value that is not a finite number.
    """
    motion = tuple(motion)
    check_driver(link, motion)
    return Driver(link, tuple((key, float(value)) for key, value in motion), line_no)


def _freeze_graph(pairs: Iterable[Pair], links: Iterable[str]) -> nx.MultiGraph:
    import networkx as nx

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
    #: the ``cam`` statements: the higher pairs whose cam has a profile (:mod:`structure.cams`)
    cams: tuple[CamRef, ...] = ()
    #: the drive and the loads over the cycle (``drive``, ``cycle`` lines: :mod:`structure.cycle`)
    cycle_loads: tuple[CycleLoad, ...] = ()
    targets: tuple[Target, ...] = ()
    links: tuple[str, ...] = field(init=False, repr=False, compare=False)
    shared_hinges: tuple[Hinge, ...] = field(init=False, repr=False, compare=False)
    compound_hinges: Mapping[str, Hinge] = field(init=False, repr=False, compare=False)
    _by_id: dict[int, Pair] = field(init=False, repr=False, compare=False)
    _links: _LinkIndex = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        # one record per pair, no more: a large file's memory is its pairs (issue 11)
        object.__setattr__(self, "points", MappingProxyType(dict(self.points)))
        pairs = self.pairs
        index = _link_index(pairs, self.ground)
        object.__setattr__(self, "_links", index)
        object.__setattr__(self, "links", index.links)
        in_place = all(map(operator.eq, map(_PAIR_ID, pairs), range(1, len(pairs) + 1)))
        object.__setattr__(self, "_by_id", {} if in_place else {p.id: p for p in pairs})
        shared = _shared_hinges(pairs)
        object.__setattr__(self, "shared_hinges", shared)
        compound = {h.point: h for h in shared if len(h.links) > 2}
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
        built by :func:`make_pair`: ``kind`` is a :class:`PairKind` or its
        letter, names are turned into strings, and ``options`` is a dict with
        the same keys as the edge-list format and typed values (``angle`` in
        degrees, ``flat``, ``roller``, ``centers`` as a pair of names,
        ``normal``, ``z`` as a pair of tooth numbers, ``gear=True``, ...).

        Raises
        ------
        EdgeListError
            Every pair that cannot be built (its reason prefixed by
            ``pair i:``), or any problem :func:`validated` finds.

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
            try:
                built.append(_pair_from_item(item, i))
            except StatementError as exc:
                text = " ".join(map(str, item))
                problems.append(EdgeListProblem(0, text, f"pair {i}: {exc.reason}"))
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
            "cams": self.cams,
            "cycle_loads": self.cycle_loads,
            "targets": self.targets,
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

    def has_link(self, link: str) -> bool:
        """True when ``link`` is a link of the mechanism (the ground included)."""
        return link in self._links.number

    def joined(self, a: str, b: str) -> bool:
        """True when some pair joins links ``a`` and ``b``, or they share a compound hinge."""
        if any(p.other(a) == b for p in self.pairs_of(a)):
            return True
        return any(a in h.links and b in h.links for h in self.compound_hinges.values())

    def connected_to_ground(self) -> set[str]:
        """The links reachable from the ground through pairs."""
        reached = _reached(self._links, self._links.number[self.ground])
        return {link for link, hit in zip(self.links, reached, strict=True) if hit}

    def links_off_ground(self) -> list[str]:
        """The links that no chain of pairs joins to the ground, in order (none: connected).

        >>> Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R")]).links_off_ground()
        []
        """
        reached = _reached(self._links, self._links.number[self.ground])
        if 0 not in reached:  # one pass in C
            return []
        return list(itertools.compress(self.links, map(operator.not_, reached)))

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
        to_ground = [p for p in self.pairs_of(link) if p.other(link) == self.ground]
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

    @cached_property
    def moving_links(self) -> tuple[str, ...]:
        """Links other than the ground, in order of first appearance (made once)."""
        return tuple(link for link in self.links if link != self.ground)

    def pairs_of(self, link: str) -> Iterator[Pair]:
        """The pairs that touch ``link``, in file order."""
        index = self._links
        k = index.number.get(link)
        if k is None:
            return iter(())
        return map(self.pairs.__getitem__, index.incident[index.offsets[k] : index.offsets[k + 1]])

    def pair_ends(self) -> np.ndarray:
        """The positions in :attr:`links` (the ground 0) of each pair's links ``a``, ``b``.

        One row per pair, in file order (a read-only view, made without a
        pass over the pairs: the numbers were found when the links were).

        >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "0", "P")])
        >>> m.pair_ends().tolist()
        [[0, 1], [1, 2], [2, 0]]
        """
        return np.frombuffer(self._links.ends, dtype=np.intc).reshape(-1, 2)

    def link_number(self, link: str) -> int:
        """The position of ``link`` in :attr:`links` (the ground 0); KeyError if it is none.

        >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "0", "P")])
        >>> m.link_number("2")
        2
        """
        return self._links.number[link]

    def link_numbers(self, links: Iterable[str]) -> np.ndarray:
        """The positions in :attr:`links` (the ground 0) of ``links``, as an int32 array.

        >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "0", "P")])
        >>> m.link_numbers(["2", "0"]).tolist()
        [2, 0]
        """
        return np.fromiter(map(self._links.number.__getitem__, links), np.intc)

    def incidence(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The pairs at each link as flat arrays: ``(offsets, pairs, others)``.

        The pairs at link ``k`` (its number in :attr:`links`), in file order
        as :meth:`pairs_of` gives them, are at ``offsets[k]:offsets[k + 1]``:
        ``pairs`` holds each one's position in :attr:`pairs`, ``others`` the
        number of the link at its other end.

        >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "R"), ("2", "0", "P")])
        >>> [a.tolist() for a in m.incidence()]
        [[0, 2, 4, 6], [0, 2, 0, 1, 1, 2], [1, 2, 0, 2, 1, 0]]
        """
        index = self._links
        return (
            np.frombuffer(index.offsets, dtype=np.intc),
            np.frombuffer(index.incident, dtype=np.intc),
            np.frombuffer(index.neighbours, dtype=np.intc),
        )

    def pair_positions(self, pair_ids: Iterable[int]) -> np.ndarray:
        """The positions in :attr:`pairs` of the pairs with ids ``pair_ids``, as an int64 array.

        >>> m = Mechanism.from_pairs([Pair(7, PairKind.R, "0", "1"), Pair(3, PairKind.R, "1", "0")])
        >>> m.pair_positions([3, 7]).tolist()
        [1, 0]
        >>> m.pair_positions([4])
        Traceback (most recent call last):
        KeyError: 4
        """
        wanted = np.fromiter(pair_ids, np.int64)
        ids = self.pair_ids()
        if not self._by_id:  # every id is its pair's position
            positions = wanted - 1
        else:
            by_id = np.argsort(ids, kind="stable")
            positions = by_id[np.searchsorted(ids, wanted, sorter=by_id) % len(ids)]
        unknown = (positions < 0) | (positions >= len(self.pairs))
        unknown[~unknown] |= ids[positions[~unknown]] != wanted[~unknown]
        if unknown.any():
            raise KeyError(int(wanted[unknown][0]))
        return positions

    def at_compound_hinge(self) -> np.ndarray:
        """For each pair, whether it is one of the R pairs of a compound hinge (a bool array).

        Found from the hinges' own lists of pairs, without a pass over the records.
        """
        flags = np.zeros(len(self.pairs), dtype=bool)
        hinges = self.compound_hinges.values()
        flags[self.pair_positions(itertools.chain.from_iterable(h.pairs for h in hinges))] = True
        return flags

    def pair_ids(self) -> np.ndarray:
        """The id of each pair, in file order, as an int32 array."""
        if not self._by_id:  # every id is its position
            return np.arange(1, len(self.pairs) + 1, dtype=np.int32)
        return np.fromiter(map(_PAIR_ID, self.pairs), np.int32, len(self.pairs))

    def pairs_with_options(self) -> Iterator[Pair]:
        """The pairs that have an option other than the slide angle, in file order.

        One pass in C: the checks of those options skip the many plain pairs.

        >>> m = Mechanism.from_pairs([("0", "1", "R"), ("1", "2", "H", "K", {"roller": "2"}),
        ...                           ("2", "0", "R")])
        >>> [p.id for p in m.pairs_with_options()]
        [2]
        """
        return filter(_RARE_OPTIONS_OF, self.pairs)

    def pair(self, pair_id: int) -> Pair:
        """The pair with id ``pair_id``."""
        if self._by_id:
            return self._by_id[pair_id]
        try:  # every id is its pair's position (the usual case): no table is kept
            position = operator.index(pair_id)
        except TypeError:
            raise KeyError(pair_id) from None
        if not 0 < position <= len(self.pairs):
            raise KeyError(pair_id)
        return self.pairs[position - 1]

    @cached_property
    def hinges(self) -> tuple[Hinge, ...]:
        """Every revolute joint as a :class:`Hinge`: each unnamed pin, then each named point.

        Built on first use (a large mechanism's analysis needs only
        :attr:`shared_hinges`).
        """
        return _hinges(self.pairs)

    def coordinates(self, point: str) -> tuple[float, float] | None:
        p = self.points.get(point)
        return None if p is None else (p.x, p.y)

    def __repr__(self) -> str:
        title = f" {self.name!r}" if self.name else ""
        return f"<Mechanism{title}: {len(self.moving_links)} moving links, {len(self.pairs)} pairs>"


_PAIR_ID = operator.attrgetter("id")


@dataclass(frozen=True, slots=True)
class _LinkIndex:
    """The pairs of each link, as flat tables over link numbers (issue 11).

    ``links`` are the link names, the ground first, then in order of first
    appearance; ``number`` maps a name to its position there. The pairs that
    touch link ``k`` are at ``offsets[k]:offsets[k + 1]``, in file order (a
    pair once at each of its ends): ``incident`` holds their positions in
    the mechanism's pairs and ``neighbours``, at the same places, the number
    of the link at each one's other end. ``ends`` holds the numbers of each
    pair's links ``a``, ``b`` in turn. Arrays of 4-byte numbers, not a tuple
    per link (nor of records: a large mechanism's records are not all
    touched to build it).
    """

    links: tuple[str, ...]
    number: dict[str, int]
    offsets: array[int]
    incident: array[int]
    neighbours: array[int]
    ends: array[int]


def _link_index(pairs: Sequence[Pair], ground: str) -> _LinkIndex:
    """Number the links in one pass over the pairs, then group the pairs' ends by link."""
    number = {ground: 0}
    ends = array("i")  # the link numbers of a, b of each pair in turn
    add_end, numbered = ends.append, number.setdefault
    for p in pairs:
        add_end(numbered(p.a, len(number)))
        add_end(numbered(p.b, len(number)))
    if len(pairs) < _NUMPY_PAIRS:
        return _link_index_by_rows(pairs, number, ends)
    end_link = np.frombuffer(ends, dtype=np.intc)
    order = np.argsort(end_link, kind="stable")  # the ends by link, each link's in file order
    offsets = np.zeros(len(number) + 1, dtype=np.intc)
    np.cumsum(np.bincount(end_link, minlength=len(number)), out=offsets[1:])
    return _LinkIndex(
        tuple(number),
        number,
        array("i", offsets.tobytes()),
        array("i", (order // 2).astype(np.intc).tobytes()),
        array("i", end_link[order ^ 1].tobytes()),  # the other end of the same pair
        ends,
    )


#: from this many pairs on, the link index is sorted by numpy (below, in Python: a small
#: mechanism is built many times over in a batch, and numpy's calls cost more than its work)
_NUMPY_PAIRS = 256


def _link_index_by_rows(
    pairs: Sequence[Pair], number: dict[str, int], ends: array[int]
) -> _LinkIndex:
    """:func:`_link_index` of a small mechanism, the same tables grouped in Python."""
    incident: list[list[int]] = [[] for _ in number]
    neighbours: list[list[int]] = [[] for _ in number]
    for k in range(len(pairs)):
        a, b = ends[2 * k], ends[2 * k + 1]
        incident[a].append(k)
        neighbours[a].append(b)
        incident[b].append(k)
        neighbours[b].append(a)
    return _LinkIndex(
        tuple(number),
        number,
        array("i", itertools.accumulate(map(len, incident), initial=0)),
        array("i", itertools.chain.from_iterable(incident)),
        array("i", itertools.chain.from_iterable(neighbours)),
        ends,
    )


def _reached(index: _LinkIndex, start: int) -> bytearray:
    """A flag per link number: 1 for the links reachable from link ``start`` through pairs."""
    offsets, neighbours = index.offsets, index.neighbours
    seen = bytearray(len(index.links))
    seen[start] = 1
    stack = [start]
    while stack:
        k = stack.pop()
        for other in neighbours[offsets[k] : offsets[k + 1]]:
            if not seen[other]:
                seen[other] = 1
                stack.append(other)
    return seen


def _shared_hinges(pairs: Iterable[Pair]) -> tuple[Hinge, ...]:
    """The hinges whose point two or more revolute pairs name, as in :func:`_hinges`."""
    first: dict[str, Pair] = {}
    several: dict[str, list[Pair]] = {}
    r_kind = PairKind.R
    for p in pairs:
        if p.kind is r_kind and p.point is not None:
            known = first.setdefault(p.point, p)
            if known is not p:
                several.setdefault(p.point, [known]).append(p)
    if not several:
        return ()
    out: list[Hinge] = []
    for point in first:  # in the order the points first appear
        group = several.get(point)
        if group is not None:
            links: dict[str, None] = {}
            for p in group:
                links.setdefault(p.a)
                links.setdefault(p.b)
            out.append(Hinge(point, tuple(links), tuple(p.id for p in group)))
    return tuple(out)


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
