"""One verdict on every statement, whichever reader made it, and on the whole mechanism.

The edge-list grammar and the JSON reader turn their text into typed values
and build each statement through :func:`~structure.model.make_pair`,
:func:`~structure.model.make_point`, :func:`~structure.model.make_load` and
:func:`~structure.model.make_driver`, which ask the checks below: the two
readers refuse the same content for the same reason. Each check raises a
:class:`~structure.errors.StatementError` with the reason, or returns.
:func:`check_finite` gives the same verdict on a result before it is printed or written:
no NaN or infinity.
:func:`validated` then checks a whole mechanism's topology and raises one
:class:`~structure.errors.EdgeListError` listing every problem.

>>> check_pair("P", "3", "0", {"angle": 90.0})
<PairKind.P: 'P'>
>>> check_pair("R", "1", "2", {"angle": 90.0})
Traceback (most recent call last):
...
structure.errors.StatementError: unknown option 'angle' for a R pair (allowed: circle)
>>> check_load("mass", "2", "S", (-1.0, 0.1))
Traceback (most recent call last):
...
structure.errors.StatementError: mass and moment of inertia cannot be negative
"""

from __future__ import annotations

import itertools
import math
import numbers
import re
from collections.abc import Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from .errors import (
    EdgeListError,
    EdgeListProblem,
    NotFiniteError,
    NumberError,
    StatementError,
    clipped,
)
from .kinds import LoadKind, PairKind
from .utils import UnionFind, count_components

if TYPE_CHECKING:  # the model builds on these checks: only its types are needed here
    from .cams import CamRef
    from .model import Mechanism

__all__ = [
    "DRIVER_KEYS",
    "LOAD_KINDS",
    "MAX_MAGNITUDE",
    "PAIR_OPTIONS",
    "as_title",
    "check_driver",
    "check_driver_option",
    "check_finite",
    "check_load",
    "check_magnitude",
    "check_name",
    "check_pair",
    "check_pair_links",
    "check_pair_option",
    "check_pair_point",
    "check_point",
    "check_title",
    "load_kind",
    "pair_kind",
    "tooth_number",
    "validated",
]

#: motion keys accepted on a ``driver`` line (rad/s, rad/s², m/s, m/s²)
DRIVER_KEYS = ("omega", "epsilon", "v", "a")

#: the options each kind of pair takes, as the keys of the edge-list format
PAIR_OPTIONS: Mapping[PairKind, tuple[str, ...]] = {
    PairKind.R: ("circle",),
    PairKind.P: ("angle", "span", "friction"),
    PairKind.H: ("flat", "roller", "centers", "normal", "z", "internal", "module"),
}

#: load statements: the role of their point and the numbers after link (and
#: point) in the edge-list line; :class:`~structure.kinds.LoadKind` says the same
LOAD_KINDS: Mapping[LoadKind, tuple[str | None, int]] = {
    LoadKind.FORCE: ("point", 2),
    LoadKind.MOMENT: (None, 1),
    LoadKind.MASS: ("point", 2),
    LoadKind.GRAVITY: (None, 2),
    LoadKind.BALANCE: ("point", 0),  # balance LINK POINT angle=DEG
}

_GEAR_OPTIONS = ("z", "internal", "module")

#: what a length-like option of a pair is, said when its value is refused
_PAIR_MEASURES = {
    "span": "the distance between the slide's two contact points (metres), > 0",
    "friction": "the Coulomb friction coefficient of the slide, >= 0",
    "circle": "the friction-circle radius of the pin (metres), >= 0",
}


#: the largest magnitude of a number in a description (coordinates, loads, speeds, options):
#: far inside the float range (about 1.8e308), so that the squares and products the solvers
#: form stay finite; a value beyond it is refused at the reader with :func:`check_magnitude`
MAX_MAGNITUDE = 1e150


def check_magnitude(*values: float) -> None:
    """Each finite value is within ±:data:`MAX_MAGNITUDE`; raise NumberError if not.

    >>> check_magnitude(1.0, -1e150)
    >>> check_magnitude(1e308)
    Traceback (most recent call last):
    ...
    structure.errors.NumberError: 1e+308 is beyond ±1e+150, the largest magnitude as...
    """
    for value in values:
        if abs(value) > MAX_MAGNITUDE:
            raise NumberError(
                f"{value:.6g} is beyond ±{MAX_MAGNITUDE:g}, the largest magnitude assur takes "
                "(so that squares and products of the values stay finite)"
            )


def _is_finite(value: Any) -> bool:
    """A real number (not a bool) that is finite."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return False
    try:
        return math.isfinite(value)
    except OverflowError:  # an int too large for a float
        return False


# ----------------------------------------------------------------------------- names
#: a link or point name: one word of the edge list, which ``#`` (a comment), ``=`` (an
#: option) and ``,`` (a list of names in an option) would cut
_NAME = re.compile(r"[^\s#=,]+")


def check_name(name: Any, what: str = "name") -> None:
    """``name`` is a name the edge list holds: one word, without ``#``, ``=`` or ``,``.

    Every reader builds its names through the model's builders, which ask this, so
    a name read from JSON can be written to the edge list and read back.

    >>> check_name("crank_2")
    >>> check_name("slider block", "link")
    Traceback (most recent call last):
    ...
    structure.errors.StatementError: link name 'slider block' is not one word: a name has no...
    """
    if not isinstance(name, str) or _NAME.fullmatch(name) is None:
        raise StatementError(
            f"{what} name {clipped(str(name))!r} is not one word: a name has no spaces or line "
            "breaks, no '#', '=' or ','"
        )


def check_title(title: str) -> None:
    """A mechanism's name (its title) is one line without ``#``, and no space at its ends.

    >>> check_title("four-bar #2")
    Traceback (most recent call last):
    ...
    structure.errors.StatementError: the name 'four-bar #2' cannot be written on a 'name' lin...
    """
    if "#" in title or len(title.splitlines()) > 1 or title != title.strip():
        raise StatementError(
            f"the name {clipped(title)!r} cannot be written on a 'name' line: one line, no '#', "
            "no space at its ends"
        )


def as_title(text: str) -> str:
    r"""``text`` (a file's stem, a name another format gave) made a name :func:`check_title`
    takes: its spaces and line breaks one space each, no space at its ends, ``#`` as ``＃``.

    >>> as_title("  four-bar\n#2 ")
    'four-bar ＃2'
    """
    return " ".join(text.split()).replace("#", "\uff03")


# ----------------------------------------------------------------------------- pairs
_PAIR_LETTERS = {kind.value: kind for kind in PairKind}


def pair_kind(kind: PairKind | str) -> PairKind:
    """The :class:`PairKind` of ``kind`` (a member or its letter)."""
    if isinstance(kind, PairKind):
        return kind
    found = _PAIR_LETTERS.get(kind) if isinstance(kind, str) else None
    if found is None:
        raise StatementError(f"unknown pair kind {kind!r} (use R, P or H)")
    return found


def check_pair_links(a: str, b: str) -> None:
    """A pair joins two different links."""
    if a == b:
        raise StatementError(f"pair joins link {a} to itself")


def tooth_number(value: Any) -> Any:
    """A tooth number as written, read as the model takes it (both readers use this).

    ``"?"`` is None (unknown); digits, as a number or as text, an int; anything
    else comes back unchanged for :func:`check_pair` to refuse with its reason.

    >>> tooth_number("24"), tooth_number(24), tooth_number("?"), tooth_number("2.5")
    (24, 24, None, '2.5')
    """
    text = str(value)
    if text == "?":
        return None
    if text.isdigit():
        try:
            return int(text)
        except ValueError:  # a digit that is no decimal digit (²)
            return value
    return value


def check_pair_option(kind: PairKind, key: str) -> None:
    """``key`` is an option of a ``kind`` pair (see :data:`PAIR_OPTIONS`)."""
    allowed = PAIR_OPTIONS[kind]
    if key not in allowed:
        names = ", ".join(allowed) or "none"
        raise StatementError(f"unknown option {key!r} for a {kind.value} pair (allowed: {names})")


def check_pair(
    kind: PairKind | str, a: str, b: str, options: Mapping[str, Any], *, gear: bool = False
) -> PairKind:
    """Check a pair's kind, links and options; return its kind.

    ``options`` maps the edge-list keys to typed values: ``angle``,
    ``normal``, ``span``, ``friction``, ``circle``, ``module`` numbers;
    ``flat``, ``roller``, ``internal`` link names; ``centers`` two point
    names (or None); ``z`` two tooth numbers (positive int or None). ``gear``
    marks an H pair as a gear mesh. The first problem found is raised, in the
    order the edge-list reader has always reported them.
    """
    kind = pair_kind(kind)
    check_pair_links(a, b)
    check_name(a, "link")
    check_name(b, "link")
    if a == "name":
        raise StatementError(
            "a pair's first link cannot be named 'name' (a line that starts with 'name' is the "
            "title): give the links the other way round"
        )
    if not options and not gear:
        return kind
    _check_option_keys(kind, options, gear)
    _check_pair_numbers(options)
    for key in ("flat", "roller", "internal"):
        if options.get(key) is not None:
            check_name(options[key], "link")
    if "centers" in options:
        _check_centers(options["centers"])
    if gear or any(key in options for key in _GEAR_OPTIONS):
        _check_gear(a, b, options, gear)
    return kind


def check_pair_point(kind: PairKind | str, point: str) -> None:
    """A pair's point is a name; a higher pair's is not ``gear`` (the word of a gear mesh)."""
    check_name(point, "point")
    if point == "gear" and pair_kind(kind) is PairKind.H:
        raise StatementError(
            "a higher pair's point cannot be named 'gear' (the word that makes it a gear mesh)"
        )


def _check_option_keys(kind: PairKind, options: Mapping[str, Any], gear: bool) -> None:
    """Each option is one the kind takes, in the order given; an empty text is no value.

    ``gear`` is a word of the line, not an option: on a pair other than H it
    is refused where the edge list has always placed it, after ``centers``
    and before the gear's own options.
    """
    stray_gear = gear and kind is not PairKind.H
    for key, value in options.items():
        if stray_gear and key in _GEAR_OPTIONS:
            break
        if isinstance(value, str) and not value:
            raise StatementError(f"unexpected token '{key}=' (options are key=value)")
        check_pair_option(kind, key)
    if stray_gear:
        raise StatementError("unexpected token 'gear' (options are key=value)")


def _check_pair_numbers(options: Mapping[str, Any]) -> None:
    for key in ("angle", "normal"):
        if key in options and not _is_finite(options[key]):
            raise StatementError("angle and normal must be finite numbers of degrees")
        if key in options:
            check_magnitude(options[key])
    for key, meaning in _PAIR_MEASURES.items():
        if key not in options:
            continue
        value = options[key]
        if not _is_finite(value) or value < 0 or (key == "span" and value == 0):
            raise StatementError(f"{key}= is {meaning}")
        check_magnitude(value)


def _check_centers(centers: Any) -> None:
    if (
        not isinstance(centers, (tuple, list))
        or len(centers) != 2
        or not any(c not in (None, "") for c in centers)
    ):
        raise StatementError(
            "centers=O1,O2 names the centres of curvature on a and b (one may be empty)"
        )
    for centre in centers:
        if centre not in (None, ""):
            check_name(centre, "point")


def _is_teeth(teeth: Any) -> bool:
    return (
        isinstance(teeth, (tuple, list))
        and len(teeth) == 2
        and all(
            t is None or (isinstance(t, numbers.Integral) and not isinstance(t, bool) and t > 0)
            for t in teeth
        )
    )


def _check_gear(a: str, b: str, options: Mapping[str, Any], gear: bool) -> None:
    if not gear:
        raise StatementError("z=, internal= and module= belong to a gear mesh: write 'gear'")
    if "z" in options and not _is_teeth(options["z"]):
        raise StatementError(
            "z=za,zb gives the tooth numbers of a and b (positive integers or ?)"
        )
    internal = options.get("internal")
    if internal is not None and internal not in (a, b):
        raise StatementError(f"internal={internal} is not one of the pair's links {a}, {b}")
    if "module" in options and not (_is_finite(options["module"]) and options["module"] > 0):
        raise StatementError("module= is the gear module in metres")
    if "module" in options:
        check_magnitude(options["module"])


# ------------------------------------------------------------------ points, loads, drivers
def check_point(name: str, x: Any, y: Any, on: str | None = None) -> None:
    """A point's name (and its link's) is a name, its coordinates finite numbers (metres)."""
    check_name(name, "point")
    if on is not None:
        check_name(on, "link")
    if not (_is_finite(x) and _is_finite(y)):
        raise StatementError(
            "point coordinates must be finite numbers (metres) or exact expressions "
            "such as 0.2*sqrt(3)"
        )
    check_magnitude(x, y)


def load_kind(kind: LoadKind | str) -> LoadKind:
    """The :class:`LoadKind` of ``kind`` (a member or its word)."""
    if isinstance(kind, LoadKind):
        return kind
    try:
        return LoadKind(kind)
    except ValueError:
        words = ", ".join(k.value for k in LoadKind)
        raise StatementError(f"unknown load {kind!r} (use {words})") from None


def check_load(
    kind: LoadKind | str, link: str, point: str | None, values: Sequence[Any]
) -> LoadKind:
    """Check a load's shape and numbers; return its kind.

    Gravity names no link (``""``), the other loads theirs (an unknown link
    is :func:`validated`'s to report); a force, a mass and a balance name a
    point; the number of values is :attr:`LoadKind.n_values`, each finite; a
    mass and its moment of inertia are not negative.
    """
    kind = load_kind(kind)
    if link:
        check_name(link, "link")
    if point is not None:
        check_name(point, "point")
    usage = f"expected '{kind.usage}'"
    if (
        (link and not kind.takes_link)
        or (point is not None) != kind.takes_point
        or len(values) != kind.n_values
    ):
        raise StatementError(usage)
    if not all(_is_finite(v) for v in values):
        raise StatementError(
            f"{usage}: numbers must be finite (or exact expressions like 500*sqrt(2))"
        )
    check_magnitude(*values)
    if kind is LoadKind.MASS and min(values) < 0:
        raise StatementError("mass and moment of inertia cannot be negative")
    return kind


def check_driver_option(key: str) -> None:
    """``key`` is one of :data:`DRIVER_KEYS`."""
    if key not in DRIVER_KEYS:
        raise StatementError(f"unknown driver option {key!r} (use {', '.join(DRIVER_KEYS)})")


def check_driver(link: str, motion: Iterable[tuple[str, Any]]) -> None:
    """A driver's link is a name; its motion known keys (:data:`DRIVER_KEYS`), finite numbers."""
    check_name(link, "link")
    for key, value in motion:
        check_driver_option(key)
        if not _is_finite(value):
            raise StatementError(f"driver option {key} needs a finite number, not {value!r}")
        check_magnitude(value)


# ----------------------------------------------------------------------------- topology
def validated(m: Mechanism, ground_line: int = 0) -> Mechanism:
    """Check a mechanism's topology; raise one EdgeListError listing every problem.

    Checks: at least one pair; ``flat=`` and ``roller=`` that name links of
    their own pair; compound hinges whose pairs connect all their links
    without a cycle; every link connected to the ground; drivers that exist,
    are named once and are joined to the ground; loads and points on links
    of the mechanism; finite coordinates. ``ground_line`` is the line of the
    ``ground`` statement, if any.

    Raises
    ------
    EdgeListError
        Every problem found, in file order (problems of the whole
        description last).
    """
    if not m.pairs:
        problem = EdgeListProblem(0, "", "no kinematic pairs: the description is empty")
        raise EdgeListError(m.source, [problem])
    problems = [
        *_pair_role_problems(m),
        *_hinge_problems(m),
        *_connection_problems(m, ground_line),
        *_driver_problems(m),
        *_load_problems(m),
        *_cycle_load_problems(m),
        *_point_problems(m),
        *_cam_problems(m),
    ]
    if problems:
        # file order; problems of the whole file (line 0) last
        problems.sort(key=lambda q: (q.line_no == 0, q.line_no))
        raise EdgeListError(m.source, problems)
    return m


def _pair_role_problems(m: Mechanism) -> Iterable[EdgeListProblem]:
    """``flat=`` and ``roller=`` name links of their own pair, and not the same one."""
    for p in m.pairs_with_options():
        if p.flat is None and p.roller is None:
            continue
        for role, link in (("flat", p.flat), ("roller", p.roller)):
            if link is not None and link not in (p.a, p.b):
                reason = f"{role}={link} is not one of the pair's links {p.a}, {p.b}"
                yield EdgeListProblem(p.line_no, p.statement, reason)
        if p.flat is not None and p.flat == p.roller:
            reason = f"link {p.flat} cannot be both flat and the roller"
            yield EdgeListProblem(p.line_no, p.statement, reason)


def _pieces(nodes: Iterable[str], edges: Iterable[tuple[str, str]]) -> list[set[str]]:
    """Connected pieces of a small graph, in the order of their first node."""
    pieces = UnionFind(nodes)
    for a, b in edges:
        pieces.union(a, b)
    return list(pieces.to_sets())


def _hinge_problems(m: Mechanism) -> Iterable[EdgeListProblem]:
    """The pairs at one point connect all its links, and close no cycle."""
    hinges = m.shared_hinges
    if not hinges:
        return
    # the hinges' pairs' link numbers, read from the mechanism's tables, not from the records
    ids = itertools.chain.from_iterable(h.pairs for h in hinges)
    numbered = m.pair_ends()[m.pair_positions(ids)]
    ends = iter(zip(numbered[:, 0].tolist(), numbered[:, 1].tolist(), strict=True))
    pair = m.pair
    for h in hinges:
        joints = list(itertools.islice(ends, len(h.pairs)))
        links = set(itertools.chain.from_iterable(joints))
        if len(joints) == len(links) - 1 and count_components(links, joints) == 1:
            continue  # the usual hinge: its pairs are a tree over its links
        ends_named = [(q.a, q.b) for q in map(pair, h.pairs)]
        parts = _pieces(h.links, ends_named)
        if len(parts) > 1:
            first = m.pair(h.pairs[0])
            text = " | ".join(",".join(sorted(c)) for c in parts)
            reason = f"the pairs at point {h.point} do not connect its links ({text})"
            yield EdgeListProblem(first.line_no, first.statement, reason)
        elif len(h.pairs) != len(h.links) - 1:
            last = m.pair(h.pairs[-1])
            reason = (
                f"the pairs at point {h.point} close a cycle: a hinge of {len(h.links)} "
                f"links has {len(h.links) - 1} pairs, {len(h.pairs)} are listed"
            )
            yield EdgeListProblem(last.line_no, last.statement, reason)


def _connection_problems(m: Mechanism, ground_line: int) -> Iterable[EdgeListProblem]:
    """The ground is joined to some link, and every link is connected to the ground."""
    if next(m.pairs_of(m.ground), None) is None:
        reason = f"the ground {m.ground} is joined to no link"
        yield EdgeListProblem(ground_line, f"ground {m.ground}", reason)
        return
    loose = m.links_off_ground()
    if loose:
        first = next(p for p in m.pairs if p.a in loose or p.b in loose)
        reason = f"link(s) not connected to the ground {m.ground}: {', '.join(loose)}"
        yield EdgeListProblem(first.line_no, first.statement, reason)


def _driver_problems(m: Mechanism) -> Iterable[EdgeListProblem]:
    """Drivers named once, links of the mechanism other than the ground, joined to it."""
    seen: set[str] = set()
    for d in m.drivers:
        if d.link in seen:
            yield EdgeListProblem(d.line_no, d.statement, f"driver {d.link} is named twice")
        seen.add(d.link)
        if d.link == m.ground:
            reason = f"the ground {d.link} cannot be a driver"
        elif not m.has_link(d.link):
            reason = f"driver {d.link} is not a link of the mechanism"
        elif not m.joined(d.link, m.ground):
            reason = f"driver {d.link} is not joined to the ground {m.ground}"
        else:
            reason = ""
        if reason:
            yield EdgeListProblem(d.line_no, d.statement, reason)
        for key, _ in d.motion:
            if key not in DRIVER_KEYS:
                reason = f"unknown driver option {key!r} (use {', '.join(DRIVER_KEYS)})"
                yield EdgeListProblem(d.line_no, "", reason)


def _load_problems(m: Mechanism) -> Iterable[EdgeListProblem]:
    """Loads on links of the mechanism; only a balance may name the ground."""
    for load in m.loads:
        if load.kind is LoadKind.GRAVITY:
            continue
        if not m.has_link(load.link):
            reason = f"{load.kind} on unknown link {load.link}"
            yield EdgeListProblem(load.line_no, load.statement, reason)
        elif load.link == m.ground and load.kind is not LoadKind.BALANCE:
            reason = f"a {load.kind} on the ground does nothing"
            yield EdgeListProblem(load.line_no, load.statement, reason)


def _cycle_load_problems(m: Mechanism) -> Iterable[EdgeListProblem]:
    """Loads over the cycle on moving links; one drive, on a driver when drivers are named."""
    drive_line: int | None = None
    for load in m.cycle_loads:
        if not m.has_link(load.link):
            reason = f"{load.kind} on unknown link {load.link}"
        elif load.link == m.ground:
            reason = f"a {load.kind} on the ground does nothing"
        elif load.kind != "drive":
            reason = ""
        elif drive_line is not None:
            where = f" on line {drive_line}" if drive_line else ""
            reason = f"the drive is already given{where}: a machine has one drive"
        elif m.drivers and load.link not in m.driver_links:
            drivers = ", ".join(m.driver_links)
            reason = f"the drive acts on a driver: {load.link} is not one ({drivers})"
        else:
            reason = ""
        if load.kind == "drive" and drive_line is None:
            drive_line = load.line_no
        if reason:
            yield EdgeListProblem(load.line_no, load.statement, reason)


def _point_problems(m: Mechanism) -> Iterable[EdgeListProblem]:
    """Finite coordinates, and markers fixed to links of the mechanism."""
    for p in m.points.values():
        if not (math.isfinite(p.x) and math.isfinite(p.y)):
            reason = f"point {p.name} has non-finite coordinates"
            yield EdgeListProblem(p.line_no, p.statement, reason)
        if p.on is not None and not m.has_link(p.on):
            reason = f"point {p.name} is fixed to unknown link {p.on}"
            yield EdgeListProblem(p.line_no, p.statement, reason)


# ----------------------------------------------------------------------------- results
def _cam_problems(m: Mechanism) -> Iterable[EdgeListProblem]:
    """Each ``cam`` statement names a higher pair whose cam turns about the ground, and a
    follower that moves as its program says (slides or swings on the ground, with the contact
    its spec names)."""
    seen: set[frozenset[str]] = set()
    for ref in m.cams:
        reason = _cam_reason(m, ref)
        key = frozenset((ref.cam, ref.other))
        if reason is None and key in seen:
            reason = f"a second cam statement for the pair {ref.cam}–{ref.other}"
        seen.add(key)
        if reason is not None:
            yield EdgeListProblem(ref.line_no, ref.statement, reason)


def _cam_reason(m: Mechanism, ref: CamRef) -> str | None:
    """Why a ``cam`` statement does not fit the mechanism, or None."""
    for link in (ref.cam, ref.other):
        if not m.has_link(link):
            return f"link {link} is not a link of the mechanism"
    contacts = [
        p for p in m.pairs_of(ref.cam) if p.kind is PairKind.H and p.other(ref.cam) == ref.other
    ]
    if len(contacts) != 1 or contacts[0].gear:
        return (
            f"the cam statement needs one higher pair (not a gear mesh) between {ref.cam} and "
            f"{ref.other}: {len(contacts)} found"
        )
    pair = contacts[0]
    joint = m.ground_joint(ref.cam)
    if joint is None or joint.kind is not PairKind.R:
        return f"cam {ref.cam} must turn about a pivot on the ground ({m.ground})"
    contact = ref.spec.follower.contact.value
    follower = ref.other
    if contact == "roller":
        if pair.roller != ref.other:
            return f"the spec has a roller: the pair needs roller={ref.other}"
        pins = [p for p in m.pairs_of(ref.other) if p.id != pair.id and p.kind is PairKind.R]
        if len(pins) != 1:
            return f"roller {ref.other} must be pinned to its follower by one R pair"
        follower = pins[0].other(ref.other)
    elif contact == "flat" and pair.flat != ref.other:
        return f"the spec has a flat-faced follower: the pair needs flat={ref.other}"
    elif contact == "knife" and (pair.flat is not None or pair.roller is not None):
        return "the spec has a knife-edge follower: the pair takes neither flat= nor roller="
    joint = m.ground_joint(follower)
    wanted = PairKind.P if ref.spec.follower.translating else PairKind.R
    if joint is None or joint.kind is not wanted or follower in m.driver_links:
        how = "slide on" if wanted is PairKind.P else "swing about a pivot on"
        motion = ref.spec.follower.motion.value
        return f"the {motion} follower {follower} must {how} the ground ({m.ground}), undriven"
    return None


def _non_finite(data: object, path: str = "") -> str | None:
    """The path (``reactions[0].force[1]``) of the first NaN or infinity in ``data``, or None."""
    if isinstance(data, float):
        return None if math.isfinite(data) else path or "the result"
    if isinstance(data, np.ndarray):
        if data.dtype.kind not in "fc" or np.isfinite(data).all():
            return None
        return path or "the result"
    if isinstance(data, Mapping):
        items: Iterable[tuple[str, object]] = (
            (f"{path}.{key}" if path else str(key), value) for key, value in data.items()
        )
    elif isinstance(data, (list, tuple)):
        items = ((f"{path}[{k}]", value) for k, value in enumerate(data))
    else:
        return None
    for where, value in items:
        found = _non_finite(value, where)
        if found is not None:
            return found
    return None


def check_finite(data: object) -> None:
    """Raise :class:`NotFiniteError` naming the first NaN or infinity in ``data``.

    ``data`` is a result as plain data: dicts, lists, floats and numpy arrays.
    """
    where = _non_finite(data)
    if where is not None:
        raise NotFiniteError(
            f"{clipped(where)} is not finite: the result overflowed "
            "(the values of the file are too large)"
        )
