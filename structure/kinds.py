"""The kinds of things in a mechanism: pairs, loads and dyads, as enums.

:class:`PairKind`, :class:`LoadKind` and :class:`DyadKind` are
:class:`TextEnum` s: each member is also the string it stands for, so it
prints, formats, compares, hashes and goes to JSON exactly as that string
(``LoadKind.MASS == "mass"``, ``f"{DyadKind.RRR}" == "RRR"``), and code that
still compares with the plain strings keeps working.

>>> import json
>>> kind = DyadKind("RRP")
>>> kind is DyadKind.RRP, str(kind), f"[{kind}]", json.dumps({kind: kind})
(True, 'RRP', '[RRP]', '{"RRP": "RRP"}')
>>> {"mass": 1}[LoadKind.MASS], LoadKind.MASS.n_values, LoadKind.MOMENT.takes_point
(1, 2, False)
"""

from __future__ import annotations

from enum import Enum

__all__ = ["DyadKind", "LoadKind", "PairKind", "TextEnum"]


class TextEnum(str, Enum):
    """An enum whose members are their text: ``str``, ``format``, ``==`` and ``hash`` agree.

    Only ``repr`` tells a member from its string.
    """

    def __str__(self) -> str:
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)

    __hash__ = str.__hash__


class PairKind(TextEnum):
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


class LoadKind(TextEnum):
    """Kind of a load statement of the description.

    ``FORCE`` ``force LINK POINT fx fy`` (N, world frame); ``MOMENT``
    ``moment LINK M`` (N·m, counter-clockwise positive); ``MASS``
    ``mass LINK m J S`` (kg, kg·m² about the centre of mass S); ``GRAVITY``
    ``gravity gx gy`` (m/s², no link); ``BALANCE`` ``balance LINK POINT
    angle=DEG`` (a balancing force in that direction, not a moment).
    """

    FORCE = "force"
    MOMENT = "moment"
    MASS = "mass"
    GRAVITY = "gravity"
    BALANCE = "balance"

    @property
    def takes_link(self) -> bool:
        """Whether the load names the link it acts on (every load but gravity)."""
        return self is not LoadKind.GRAVITY

    @property
    def takes_point(self) -> bool:
        """Whether the load names a point: where a force acts, a centre of mass."""
        return self in (LoadKind.FORCE, LoadKind.MASS, LoadKind.BALANCE)

    @property
    def n_values(self) -> int:
        """How many numbers the load takes (``fx fy``; ``M``; ``m J``; ``gx gy``; ``angle``)."""
        return 1 if self in (LoadKind.MOMENT, LoadKind.BALANCE) else 2

    @property
    def usage(self) -> str:
        """The statement's form in the edge-list format, e.g. ``'mass LINK m J S'``."""
        return _LOAD_USAGE[self]


_LOAD_USAGE = {
    LoadKind.FORCE: "force LINK POINT fx fy",
    LoadKind.MOMENT: "moment LINK M",
    LoadKind.MASS: "mass LINK m J S",
    LoadKind.GRAVITY: "gravity gx gy",
    LoadKind.BALANCE: "balance LINK POINT angle=DEG",
}


class DyadKind(TextEnum):
    """Kind of an Assur dyad (class II, two links, three pairs): its pairs' letters.

    The letters read the pairs external–middle–external; a dyad and its
    mirror image are one kind (``PRR`` is ``RRP``, ``PPR`` is ``RPP``).

    ``RRR`` three revolute pairs; ``RRP`` two revolute, one external slide;
    ``RPR`` a slide in the middle; ``PRP`` two external slides; ``RPP`` a
    middle and an external slide.
    """

    RRR = "RRR"
    RRP = "RRP"
    RPR = "RPR"
    PRP = "PRP"
    RPP = "RPP"

    @classmethod
    def from_letters(cls, letters: str) -> DyadKind | None:
        """The kind whose letters (in either direction) are ``letters``, or None.

        >>> DyadKind.from_letters("PRR"), DyadKind.from_letters("PPP")
        (<DyadKind.RRP: 'RRP'>, None)
        """
        return _DYAD_LETTERS.get(letters)


_DYAD_LETTERS = {
    **{kind.value: kind for kind in DyadKind},
    **{kind.value[::-1]: kind for kind in DyadKind},
}
