"""Read and write pyslvs mechanism expressions and Pyslvs-UI project files.

A pyslvs expression lists the joints of a mechanism, each with its kind, an
optional slot angle and colour, its sketch coordinates and the links it
joins; the link named ``ground`` is the frame::

    M[
      J[R, color[Green], P[0, 0], L[ground, crank]],
      J[R, color[Green], P[10, 25], L[crank, rod]],
      J[RP, A[0], color[Blue], P[70, 0], L[ground, rod]]
    ]

It is read by a small recursive-descent parser (never ``eval``) and mapped
onto the model as pyslvs solves it (``pyslvs/bfgs.pyx``, ``expression.pyx``):

* ``R``: a pin at the point; a joint of k links is a compound hinge of k - 1
  revolute pairs (all to the ground when the ground is one of them);
* ``P``: a prismatic pair: the slot is on the first link, the second slides
  along it without turning; ``A[deg]`` is the slot's direction at the sketch,
  as our ``angle=``. Three or more links would weld the sliders together,
  which the model has no pair for: an error;
* ``RP``: a pin in a slot: the slot is on the first link, the other links are
  pinned to a slider block that slides in it. The block becomes a link named
  ``block_J<i>``, pinned (R) to them and sliding (P) in the slot;
* a joint on one link is a marker on it, on no link a point of the ground.

The i-th joint (from 0, as pyslvs numbers them) is the point ``J<i>``.
Coordinates are taken as written (pyslvs has no unit; its editor shows
millimetres). Driving links are not part of an expression: a project's input
pairs ``(b, d)`` name the link that joints ``b`` and ``d`` share; an input
whose two joints are the same names none and is skipped, as pyslvs's own
solver skips it.

A Pyslvs-UI project (``.pyslvs``) is YAML with the expression under
``mechanism`` and the input pairs under ``input``; reading one needs PyYAML
(the ``pyslvs`` extra), writing one does not.

>>> m = mechanism_from_expression(
...     "M[J[R, P[0, 0], L[ground, L1]], J[R, P[1, 1], L[L1, L2]],"
...     " J[RP, A[0], P[3, 0], L[ground, L2]]]", inputs=[(0, 1)])
>>> [p.statement for p in m.pairs]
['ground L1 R J0', 'L1 L2 R J1', 'ground block_J2 P J2 angle=0', 'L2 block_J2 R J2']
>>> m.driver_links
('L1',)
>>> print(mechanism_to_expression(m))
M[
  J[R, P[0, 0], L[ground, L1]],
  J[R, P[1, 1], L[L1, L2]],
  J[RP, A[0], P[3, 0], L[ground, L2]]
]
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import EdgeListError, EdgeListProblem, NumberError, StatementError, clipped
from ..model import (
    Driver,
    Mechanism,
    Pair,
    PairKind,
    PointDef,
    make_point,
    number_text,
    validated,
)
from ..validation import as_title, check_magnitude
from .omissions import Holds, left_out, renames
from .textfile import MAX_FILE_BYTES, read_text

__all__ = [
    "JOINT_KINDS",
    "PYSLVS_HOLDS",
    "PyslvsJoint",
    "format_expression",
    "looks_like_expression",
    "mechanism_from_expression",
    "mechanism_from_joints",
    "mechanism_to_expression",
    "mechanism_to_joints",
    "parse_expression",
    "parse_pyslvs",
    "pyslvs_inputs",
    "pyslvs_left_out",
    "pyslvs_link_names",
    "pyslvs_project",
    "read_pyslvs",
]

#: the joint kinds of pyslvs: pin, prismatic, pin in a slot
JOINT_KINDS = ("R", "P", "RP")
#: pyslvs's name of the frame
FRAME = "ground"

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_NUMBER = re.compile(r"[+-]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?")
_SPACE = re.compile(r"\s+")
_EXPRESSION_START = re.compile(r"M\s*\[")


@dataclass(frozen=True, slots=True)
class PyslvsJoint:
    """One joint of a pyslvs expression.

    ``kind`` is ``R``, ``P`` or ``RP``; ``links`` the links it joins (for P and
    RP the first carries the slot); ``angle`` the slot direction in degrees
    (P and RP only); ``colour`` as written (a name or ``(r, g, b)``).
    """

    kind: str
    links: tuple[str, ...]
    x: float
    y: float
    angle: float | None = None
    colour: str | None = None
    line_no: int = field(default=0, compare=False)

    @property
    def expression(self) -> str:
        """The joint's text, ``J[R, color[Red], P[0, 5], L[ground, crank]]``."""
        parts = [self.kind]
        if self.angle is not None:
            parts.append(f"A[{number_text(self.angle)}]")
        if self.colour is not None:
            parts.append(f"color[{self.colour}]")
        parts.append(f"P[{number_text(self.x)}, {number_text(self.y)}]")
        parts.append(f"L[{', '.join(self.links)}]")
        return f"J[{', '.join(parts)}]"


# ---------------------------------------------------------------- the parser
@dataclass(frozen=True, slots=True)
class _Token:
    kind: str  # "name", "number", or the punctuation itself: [ ] , ( )
    text: str
    offset: int


class _SyntaxProblem(Exception):
    def __init__(self, offset: int, reason: str):
        self.offset = offset
        self.reason = reason
        super().__init__(reason)


def _skip_comment(text: str, pos: int) -> int:
    """The offset after the comment at ``pos``: ``# ...`` to the line end, ``#[ ... #]``."""
    if text.startswith("#[", pos):
        end = text.find("#]", pos + 2)
        if end < 0:
            raise _SyntaxProblem(pos, "comment '#[' is not closed by '#]'")
        pos = end + 2
    end = text.find("\n", pos)
    return len(text) if end < 0 else end


def _tokens(text: str) -> list[_Token]:
    out: list[_Token] = []
    pos = 0
    while pos < len(text):
        char = text[pos]
        if char.isspace():
            pos = _SPACE.match(text, pos).end()  # type: ignore[union-attr]
        elif char == "#":
            pos = _skip_comment(text, pos)
        elif char in "[],()":
            out.append(_Token(char, char, pos))
            pos += 1
        elif (found := _NAME.match(text, pos)) is not None:
            out.append(_Token("name", found.group(), pos))
            pos = found.end()
        elif (found := _NUMBER.match(text, pos)) is not None:
            out.append(_Token("number", found.group(), pos))
            pos = found.end()
        else:
            raise _SyntaxProblem(pos, f"unexpected character {char!r}")
    return out


class _ExpressionParser:
    """Recursive descent over the tokens of ``M[J[...], ...]``."""

    def __init__(self, text: str):
        self.text = text
        self.tokens = _tokens(text)
        self.index = 0

    def _peek(self) -> _Token | None:
        return self.tokens[self.index] if self.index < len(self.tokens) else None

    def _fail(self, wanted: str) -> _SyntaxProblem:
        token = self._peek()
        if token is None:
            return _SyntaxProblem(len(self.text), f"expected {wanted} but the text ends")
        return _SyntaxProblem(token.offset, f"expected {wanted} but found {token.text!r}")

    def _take(self, kind: str, text: str | None = None) -> _Token | None:
        token = self._peek()
        if token is not None and token.kind == kind and (text is None or token.text == text):
            self.index += 1
            return token
        return None

    def _expect(self, kind: str, wanted: str, text: str | None = None) -> _Token:
        token = self._take(kind, text)
        if token is None:
            raise self._fail(wanted)
        return token

    def _open(self, tag: str) -> _Token:
        """``TAG[``: a tag name directly followed by its bracket."""
        token = self._expect("name", f"'{tag}['", tag)
        self._expect("[", f"'[' after {tag}")
        return token

    def _number(self, what: str) -> float:
        token = self._expect("number", what)
        value = float(token.text)
        if not math.isfinite(value):
            raise _SyntaxProblem(
                token.offset, f"{what} {clipped(token.text)} is not a finite number"
            )
        try:
            check_magnitude(value)
        except NumberError as exc:
            raise _SyntaxProblem(token.offset, f"{what}: {exc.reason}") from None
        return value

    def mechanism(self) -> list[tuple[int, PyslvsJoint]]:
        """The joints, each with the offset where it starts."""
        self._open("M")
        joints = []
        while self._take("]") is None:
            joints.append(self._joint())
            if self._take(",") is None:
                self._expect("]", "',' or ']' after a joint")
                break
        if self._peek() is not None:
            raise self._fail("the end after the mechanism's ']'")
        return joints

    def _joint(self) -> tuple[int, PyslvsJoint]:
        start = self._open("J").offset
        kind = self._expect("name", "a joint kind (R, P or RP)")
        if kind.text not in JOINT_KINDS:
            raise _SyntaxProblem(kind.offset, f"unknown joint kind {kind.text!r} (use R, P or RP)")
        angle = colour = None
        self._expect(",", f"',' after the joint kind {kind.text}")
        tag = self._peek()
        if tag is not None and tag.kind == "name" and tag.text == "A":
            self._open("A")
            angle = self._number("the slot angle (degrees)")
            self._expect("]", "']' after the angle")
            self._expect(",", "',' after A[...]")
        tag = self._peek()
        if tag is not None and tag.kind == "name" and tag.text == "color":
            colour = self._colour()
            self._expect(",", "',' after color[...]")
        self._open("P")
        x = self._number("the x coordinate")
        self._expect(",", "',' between x and y")
        y = self._number("the y coordinate")
        self._expect("]", "']' after the coordinates")
        self._expect(",", "',' after P[x, y]")
        links = self._links()
        self._expect("]", "']' closing the joint")
        return start, PyslvsJoint(kind.text, links, x, y, angle, colour)

    def _colour(self) -> str:
        self._open("color")
        name = self._take("name")
        if name is not None:
            self._expect("]", "']' after the colour")
            return name.text
        self._expect("(", "a colour name or (r, g, b)")
        values = [self._expect("number", "a colour component").text]
        for _ in range(2):
            self._expect(",", "',' between colour components")
            values.append(self._expect("number", "a colour component").text)
        self._expect(")", "')' after (r, g, b)")
        self._expect("]", "']' after the colour")
        return f"({', '.join(values)})"

    def _links(self) -> tuple[str, ...]:
        self._open("L")
        names: list[str] = []
        while self._take("]") is None:
            names.append(self._expect("name", "a link name or ']'").text)
            if self._take(",") is None:
                self._expect("]", "',' or ']' after a link name")
                break
        return tuple(names)


def _line_of(text: str, offset: int) -> tuple[int, str, int]:
    """1-based line number, the line's text and the 1-based column of ``offset``."""
    line_no = text.count("\n", 0, offset) + 1
    start = text.rfind("\n", 0, offset) + 1
    end = text.find("\n", offset)
    return line_no, text[start : len(text) if end < 0 else end], offset - start + 1


def parse_expression(text: str, source: str = "<pyslvs>") -> tuple[PyslvsJoint, ...]:
    """The joints of a pyslvs expression ``M[J[...], ...]``, in order.

    Raises
    ------
    EdgeListError
        A syntax error, with its line and column; an R joint with an angle, a
        P or RP joint without one; a link named twice in a joint.
    """
    try:
        raw = _ExpressionParser(text).mechanism()
    except _SyntaxProblem as problem:
        line_no, line, column = _line_of(text, problem.offset)
        reason = f"column {column}: {problem.reason}"
        raise EdgeListError(source, [EdgeListProblem(line_no, line, reason)]) from None
    joints: list[PyslvsJoint] = []
    problems: list[EdgeListProblem] = []
    for index, (start, joint) in enumerate(raw):
        line_no, line, _ = _line_of(text, start)
        why = _joint_problem(joint)
        if why:
            problems.append(EdgeListProblem(line_no, line, f"joint J{index}: {why}"))
        joints.append(dataclasses.replace(joint, line_no=line_no))
    if problems:
        raise EdgeListError(source, problems)
    return tuple(joints)


def _joint_problem(joint: PyslvsJoint) -> str:
    if joint.kind == "R" and joint.angle is not None:
        return "an R joint takes no slot angle A[...]"
    if joint.kind != "R" and joint.angle is None:
        return f"a {joint.kind} joint needs its slot angle A[degrees]"
    twice = sorted({name for name in joint.links if joint.links.count(name) > 1})
    if twice:
        return f"link {twice[0]} is named twice"
    return ""


def format_expression(joints: Iterable[PyslvsJoint]) -> str:
    """The expression of ``joints``, one joint a line; parsing it gives the same joints."""
    lines = [f"  {joint.expression}" for joint in joints]
    if not lines:
        return "M[]"
    return "M[\n" + ",\n".join(lines) + "\n]"


# -------------------------------------------------------- joints -> mechanism
def _block_name(point: str, taken: set[str]) -> str:
    name = f"block_{point}"
    while name in taken:
        name += "_"
    taken.add(name)
    return name


def _hinge_pairs(links: Sequence[str], point: str, line_no: int, first_id: int) -> list[Pair]:
    """The revolute pairs of a hinge of ``links`` at ``point``: from the ground, else the first."""
    hub = FRAME if FRAME in links else links[0]
    others = [link for link in links if link != hub]
    return [
        Pair(first_id + k, PairKind.R, hub, link, point, line_no=line_no)
        for k, link in enumerate(others)
    ]


def _joint_pairs(
    index: int, joint: PyslvsJoint, first_id: int, taken: set[str]
) -> tuple[list[Pair], str | None]:
    """The pairs of one joint (a block link is added for RP), or why it cannot be modelled."""
    point = f"J{index}"
    links = joint.links
    if len(links) < 2:
        return [], None
    if joint.kind == "R":
        return _hinge_pairs(links, point, joint.line_no, first_id), None
    if joint.kind == "P":
        if len(links) > 2:
            return [], (
                f"a P joint of {len(links)} links welds {', '.join(links[1:])} together as "
                "one slider; the model has no welded pair: make them one link"
            )
        slide = Pair(
            first_id, PairKind.P, links[0], links[1], point, joint.angle, line_no=joint.line_no
        )
        return [slide], None
    block = _block_name(point, taken)
    slide = Pair(first_id, PairKind.P, links[0], block, point, joint.angle, line_no=joint.line_no)
    pins = [*links[1:], block]
    if FRAME in pins:
        pins.remove(FRAME)
        pins.insert(0, FRAME)
    return [slide, *_hinge_pairs(pins, point, joint.line_no, first_id + 1)], None


def _points(joints: Sequence[PyslvsJoint], problems: list[EdgeListProblem]) -> dict[str, PointDef]:
    """The points ``J<i>`` of the joints, each checked as every reader's (:func:`make_point`)."""
    points: dict[str, PointDef] = {}
    for index, joint in enumerate(joints):
        name = f"J{index}"
        on = None
        if len(joint.links) == 1:
            on = joint.links[0]
        elif not joint.links:
            on = FRAME
        try:
            points[name] = make_point(name, joint.x, joint.y, on, line_no=joint.line_no)
        except StatementError as exc:
            problems.append(
                EdgeListProblem(joint.line_no, joint.expression, f"joint J{index}: {exc.reason}")
            )
    return points


def pyslvs_inputs(
    joints: Sequence[PyslvsJoint], inputs: Iterable[Sequence[int]], source: str = "<pyslvs>"
) -> tuple[str, ...]:
    """The driving links that pyslvs input pairs ``(base joint, driven joint)`` name.

    Each names the one link the two joints share; a pair of the same joint
    names none and is skipped (pyslvs's solver skips it too).

    Raises
    ------
    EdgeListError
        A joint index out of range, joints that share no link or several.
    """
    drivers: list[str] = []
    problems: list[EdgeListProblem] = []
    for number, pair in enumerate(inputs, start=1):
        where = f"input {number} {tuple(pair)}"
        if len(pair) < 2 or not all(isinstance(k, int) and not isinstance(k, bool) for k in pair):
            problems.append(EdgeListProblem(0, "", f"{where}: expected two joint numbers"))
            continue
        base, driven = pair[0], pair[1]
        if not (0 <= base < len(joints) and 0 <= driven < len(joints)):
            problems.append(
                EdgeListProblem(0, "", f"{where}: there are joints J0 to J{len(joints) - 1} only")
            )
            continue
        if base == driven:
            continue
        shared = [link for link in joints[base].links if link in joints[driven].links]
        if len(shared) != 1:
            why = "share no link" if not shared else f"share links {', '.join(shared)}"
            problems.append(EdgeListProblem(0, "", f"{where}: J{base} and J{driven} {why}"))
        elif shared[0] not in drivers:
            drivers.append(shared[0])
    if problems:
        raise EdgeListError(source, problems)
    return tuple(drivers)


def mechanism_from_joints(
    joints: Sequence[PyslvsJoint],
    inputs: Iterable[Sequence[int]] = (),
    source: str = "<pyslvs>",
    name: str = "",
) -> Mechanism:
    """The validated mechanism of pyslvs joints (see the module for the mapping).

    Raises
    ------
    EdgeListError
        A joint the model cannot express (a P joint of three or more links),
        a bad input pair, or any problem :func:`~structure.model.validated`
        finds (a link not connected to the ground, ...).
    """
    problems: list[EdgeListProblem] = []
    pairs: list[Pair] = []
    taken = {link for joint in joints for link in joint.links}
    for index, joint in enumerate(joints):
        made, why = _joint_pairs(index, joint, len(pairs) + 1, taken)
        if why:
            problems.append(
                EdgeListProblem(joint.line_no, joint.expression, f"joint J{index}: {why}")
            )
        pairs.extend(made)
    points = _points(joints, problems)
    if problems:
        raise EdgeListError(source, problems)
    drivers = tuple(Driver(link) for link in pyslvs_inputs(joints, inputs, source))
    mechanism = Mechanism(tuple(pairs), FRAME, drivers, points, name, source)
    return validated(mechanism)


def mechanism_from_expression(
    text: str, source: str = "<pyslvs>", inputs: Iterable[Sequence[int]] = (), name: str = ""
) -> Mechanism:
    """Parse a pyslvs expression into a validated mechanism.

    ``inputs`` are pyslvs input pairs ``(base joint, driven joint)``; they
    name the drivers (see :func:`pyslvs_inputs`).

    Raises
    ------
    EdgeListError
        See :func:`parse_expression` and :func:`mechanism_from_joints`.
    """
    return mechanism_from_joints(parse_expression(text, source), inputs, source, name)


# -------------------------------------------------------- mechanism -> joints
def pyslvs_link_names(mechanism: Mechanism) -> dict[str, str]:
    """Each link's name in pyslvs.

    The ground is ``ground``; a name that is not an identifier, or is
    ``ground`` without being the ground, gets an ``L`` in front (``1`` becomes
    ``L1``); others are kept.

    >>> from structure import parse_edgelist
    >>> pyslvs_link_names(parse_edgelist(["0 1 R A", "1 ground R B", "ground 0 R C"]))
    {'0': 'ground', '1': 'L1', 'ground': 'Lground'}
    """
    out = {mechanism.ground: FRAME}
    taken = {FRAME}
    for link in mechanism.moving_links:
        name = link if _NAME.fullmatch(link) and link != FRAME else None
        if name is None:
            name = "L" + re.sub(r"\W", "_", link)
        while name in taken:
            name += "_"
        taken.add(name)
        out[link] = name
    return out


def _partners(mechanism: Mechanism, link: str) -> set[str]:
    """The links pinned (R) to ``link``, through its own pairs or a compound hinge."""
    out = {p.other(link) for p in mechanism.pairs_of(link) if p.kind is PairKind.R}
    for hinge in mechanism.compound_hinges.values():
        if link in hinge.links:
            out.update(hinge.links)
    out.discard(link)
    return out


def _blocks(mechanism: Mechanism) -> dict[str, Pair]:
    """Slider blocks written as RP joints, each with its P pair.

    A block is a non-driving link with one P pair and R pairs all at the P
    pair's point, nothing else on it, and no other block pinned to it.
    """
    out: dict[str, Pair] = {}
    drivers = set(mechanism.driver_links)
    markers = {p.on for p in mechanism.points.values() if p.on is not None}
    for link in mechanism.moving_links:
        if link in drivers or link in markers:
            continue
        pairs = list(mechanism.pairs_of(link))
        slides = [p for p in pairs if p.kind is PairKind.P]
        pins = [p for p in pairs if p.kind is PairKind.R]
        if len(slides) != 1 or not pins or len(slides) + len(pins) != len(pairs):
            continue
        slide = slides[0]
        if slide.point is None or any(p.point != slide.point for p in pins):
            continue
        partners = _partners(mechanism, link)
        if slide.other(link) in partners:
            continue  # pinned and sliding on the same link: not a pin in a slot
        if partners & set(out) or any(link in _partners(mechanism, block) for block in out):
            continue  # two blocks pinned together: the first one only
        out[link] = slide
    return out


def _coordinates(mechanism: Mechanism, pair: Pair) -> tuple[float, float]:
    """The sketch coordinates of ``pair``'s point (and a P pair's angle is given)."""
    xy = mechanism.coordinates(pair.point) if pair.point is not None else None
    why = ""
    if xy is None:
        why = "a pyslvs joint needs coordinates: give the pair a point with a 'point' line"
    elif pair.kind is PairKind.P and pair.angle_deg is None:
        why = "a pyslvs slider joint needs the slide's direction: give the pair angle="
    if why:
        raise EdgeListError(mechanism.source, [EdgeListProblem(pair.line_no, pair.statement, why)])
    return xy  # type: ignore[return-value]


def mechanism_to_joints(mechanism: Mechanism) -> tuple[tuple[PyslvsJoint, ...], tuple]:
    """The pyslvs joints of ``mechanism`` and its input pairs (for its rotating drivers).

    Revolute pairs at one point become one R joint, a slider block pinned at
    the point of its slide one RP joint, other prismatic pairs P joints,
    markers joints on one link; links are renamed where pyslvs needs a name
    (``1`` becomes ``L1``; the ground is ``ground``).

    Raises
    ------
    EdgeListError
        A higher pair (pyslvs has none), a pair without coordinates.
    """
    joints, _, inputs = _joints_of(mechanism)
    return joints, inputs


def _joints_of(mechanism: Mechanism) -> tuple[tuple[PyslvsJoint, ...], tuple[str, ...], tuple]:
    """The joints, the point each is written from (``J<i>`` on reading), the input pairs."""
    higher = [p for p in mechanism.pairs if p.kind is PairKind.H]
    if higher:
        raise EdgeListError(
            mechanism.source,
            [
                EdgeListProblem(p.line_no, p.statement, "pyslvs has no higher pair (cam, gear)")
                for p in higher
            ],
        )
    names = pyslvs_link_names(mechanism)
    blocks = _blocks(mechanism)
    joints: list[PyslvsJoint] = []
    points: list[str] = []
    where: dict[str, int] = {}  # point -> joint index of its R joint
    for hinge in mechanism.hinges:
        links = [link for link in hinge.links if link not in blocks]
        if len(links) < 2 or any(link in blocks for link in hinge.links):
            continue
        x, y = _coordinates(mechanism, mechanism.pair(hinge.pairs[0]))
        where[hinge.point] = len(joints)
        joints.append(PyslvsJoint("R", _ordered(links, mechanism.ground, names), x, y))
        points.append(hinge.point)
    for pair in mechanism.pairs:
        if pair.kind is not PairKind.P:
            continue
        x, y = _coordinates(mechanism, pair)
        block = next((b for b, slide in blocks.items() if slide is pair), None)
        points.append(pair.point or "")
        if block is None:
            # a prismatic pair is symmetric: the slot on the ground, when it is one of them
            links = _ordered(pair.links, mechanism.ground, names)
            joints.append(PyslvsJoint("P", links, x, y, pair.angle_deg))
            continue
        hinge = next(h for h in mechanism.hinges if block in h.links and h.point == pair.point)
        pins = [names[link] for link in hinge.links if link != block]
        where[hinge.point] = len(joints)
        links = (names[pair.other(block)], *pins)
        joints.append(PyslvsJoint("RP", links, x, y, pair.angle_deg))
    for point in mechanism.points.values():
        if point.on is not None and point.name not in where:
            on = (names[point.on],) if point.on in names else ()
            joints.append(PyslvsJoint("R", on, point.x, point.y))
            points.append(point.name)
    return tuple(joints), tuple(points), _inputs(mechanism, joints, names)


#: what a Pyslvs-UI project keeps of a mechanism: its joints, slot angles and rotating inputs
PYSLVS_HOLDS = Holds(
    "pyslvs projects",
    title=False,
    loads=False,
    motion=False,
    options=frozenset({"angle"}),
    exact=False,
    free_points=False,
)


def pyslvs_left_out(mechanism: Mechanism) -> tuple[str, ...]:
    """What a Pyslvs-UI project of ``mechanism`` leaves out or renames, a line per kind.

    Loads, driver motion, the name, pair options but the slot angle, exact
    expressions, points that are no joint, drivers that are no rotating input;
    links renamed as identifiers and points renumbered ``J<i>`` (see
    :func:`~structure.readwrite.omissions.left_out`).

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "point A 0 0", "point B 1 0 on=1"])
    >>> for line in pyslvs_left_out(m):
    ...     print(line)
    pyslvs projects hold no driver motion: omega of driver 1 left out
    pyslvs projects name things their own way: link 0 → ground, link 1 → L1, point A → J0, ...

    Raises
    ------
    EdgeListError
        A mechanism pyslvs cannot hold at all (see :func:`mechanism_to_joints`).
    """
    joints, points, inputs = _joints_of(mechanism)
    names = pyslvs_link_names(mechanism)
    lines = list(left_out(mechanism, PYSLVS_HOLDS))
    driven = {
        link for base, other in inputs for link in joints[base].links if link in joints[other].links
    }
    dropped = [link for link in mechanism.driver_links if names[link] not in driven]
    if dropped:
        plural = "s" if len(dropped) > 1 else ""
        lines.append(
            f"pyslvs projects drive by turning a link pinned to the ground only: driver{plural} "
            f"{', '.join(dropped)} left out"
        )
    renamed = {f"link {old}": new for old, new in names.items()}
    renamed.update({f"point {old}": f"J{k}" for k, old in enumerate(points) if old})
    lines.extend(renames(PYSLVS_HOLDS.format, renamed))
    return tuple(lines)


def _ordered(links: Sequence[str], ground: str, names: dict[str, str]) -> tuple[str, ...]:
    ordered = sorted(links, key=lambda link: link != ground)
    return tuple(names[link] for link in ordered)


def _inputs(mechanism: Mechanism, joints: Sequence[PyslvsJoint], names: dict[str, str]) -> tuple:
    """Input pairs (ground pivot joint, another joint of the driver) of the rotating drivers."""
    out = []
    for link in mechanism.driver_links:
        name = names[link]
        on = [k for k, joint in enumerate(joints) if name in joint.links]
        base = next((k for k in on if joints[k].kind == "R" and FRAME in joints[k].links), None)
        driven = next((k for k in on if k != base), None)
        if base is not None and driven is not None:
            out.append((base, driven))
    return tuple(out)


def mechanism_to_expression(mechanism: Mechanism) -> str:
    """The pyslvs expression of ``mechanism`` (see :func:`mechanism_to_joints`).

    Raises
    ------
    EdgeListError
        A higher pair, a pair without coordinates.
    """
    joints, _ = mechanism_to_joints(mechanism)
    return format_expression(joints)


# ------------------------------------------------------------- project files
def looks_like_expression(text: str) -> bool:
    """True when ``text`` (after comments) starts with ``M[``: a pyslvs expression."""
    body = text.lstrip("\ufeff")
    while True:
        body = body.lstrip()
        if not body.startswith("#"):
            return _EXPRESSION_START.match(body) is not None
        try:
            body = body[_skip_comment(body, 0) :]
        except _SyntaxProblem:
            return False


def _project_problem(source: str, reason: str, line_no: int = 0) -> EdgeListError:
    return EdgeListError(source, [EdgeListProblem(line_no, "", reason)])


def _project(text: str, source: str) -> dict[str, Any]:
    try:  # a Pyslvs-UI project needs a YAML parser (the ``pyslvs`` extra), imported on use
        import yaml
    except ImportError:  # pragma: no cover - depends on the environment
        raise _project_problem(
            source, "reading a Pyslvs project (YAML) needs PyYAML: pip install 'assur[pyslvs]'"
        ) from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line_no = mark.line + 1 if mark is not None else 0
        why = getattr(exc, "problem", None) or "not YAML"
        raise _project_problem(source, f"invalid Pyslvs project: {why}", line_no) from None
    except RecursionError:
        raise _project_problem(
            source, "invalid Pyslvs project: lists or mappings nested too deeply"
        ) from None
    except (ValueError, TypeError, OverflowError) as exc:  # a scalar read as a bad date, ...
        raise _project_problem(source, f"invalid Pyslvs project: {clipped(str(exc))}") from None
    if not isinstance(data, dict) or not isinstance(data.get("mechanism"), str):
        raise _project_problem(
            source,
            "neither a pyslvs expression M[...] nor a Pyslvs project with a 'mechanism' entry",
        )
    return data


def parse_pyslvs(text: str, source: str = "<pyslvs>", name: str = "") -> Mechanism:
    """A bare expression ``M[...]`` or a Pyslvs-UI project (YAML) as a mechanism.

    Raises
    ------
    EdgeListError
        Invalid YAML, a project without ``mechanism``, a bad ``input`` list,
        or any problem of the expression; PyYAML missing for a project.
    """
    if looks_like_expression(text):
        return mechanism_from_expression(text, source, name=name)
    data = _project(text, source)
    inputs = data.get("input") or []
    if not isinstance(inputs, list) or not all(isinstance(p, (list, tuple)) for p in inputs):
        raise _project_problem(source, "'input' must be a list of [base joint, driven joint]")
    return mechanism_from_expression(data["mechanism"], source, inputs, name)


def pyslvs_project(mechanism: Mechanism) -> str:
    """A Pyslvs-UI project (YAML) with the expression and the drivers' input pairs.

    Raises
    ------
    EdgeListError
        A higher pair, a pair without coordinates.
    """
    joints, inputs = mechanism_to_joints(mechanism)
    expression = "M[" + ", ".join(joint.expression for joint in joints) + "]"
    lines = ["mechanism: '" + expression.replace("'", "''") + "'"]
    if inputs:
        lines.append("input:")
        lines.extend(f"- [{base}, {driven}]" for base, driven in inputs)
    return "\n".join(lines) + "\n"


def read_pyslvs(path: str | os.PathLike[str], max_bytes: int = MAX_FILE_BYTES) -> Mechanism:
    """Read a pyslvs expression or Pyslvs-UI project file (UTF-8); named after the file.

    Raises
    ------
    EdgeListError
        On any problem in the file, or when it cannot be read.
    """
    path = Path(path)
    text = read_text(path, max_bytes)
    return parse_pyslvs(text, str(path), name=as_title(path.stem))
