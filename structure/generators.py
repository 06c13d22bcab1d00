"""Random planar mechanisms built from Assur groups, for testing and benchmarks.

A mechanism is grown the way the textbook forms one: start with the ground
``0`` and a driver ``1`` (an R pair to the ground), then repeatedly attach a
random Assur group by its external pairs to links that are already known (the
ground, the driver, links of earlier groups), until there are about
``n_links`` moving links. The groups attached are minimal by construction, so
a correct decomposition must find exactly them.

Group kinds (names accepted in ``kinds``):

``RRR``, ``RRP``, ``RPR``, ``PRP``, ``RPP``
    The five dyads (2 links, 3 pairs), letters external–middle–external.
``triad``
    Class III, order 3: a ternary base link and three binary leads; the
    internal pairs are R, each lead's external pair is R (P with
    probability 0.2).
``class4``
    Class IV, order 2: four links in a ring of four internal R pairs, the
    external pairs on two opposite links (R, or P with probability 0.2).

Links are named ``0`` (ground), ``1`` (driver), ``2``, ``3``, ... in order of
creation. Every R pair names its point (``J1``, ``J2``, ...); every P pair a
point (``S1``, ...) and an ``angle=``. With probability ``compound`` an
external R pair reuses a pin point already on the known link, so compound
hinges appear; two external pairs of one group never share a point (that
would lock two group links together at one pin, a degenerate chain). There is
no geometry (no ``point`` lines): the result is structure only.

Known links are picked half the time uniformly among all known links and
half the time among the eight most recently created ones, so both bushy and
deep dependency graphs occur.

>>> m, groups = random_mechanism_with_groups(9, seed=1)
>>> len(m.moving_links), sum(len(g) for g in groups)
(9, 8)
>>> from structure import analyze
>>> r = analyze(m)
>>> r.mobility.W, {frozenset(g) for g in groups} == {frozenset(g.links) for g in r.groups}
(1, True)
"""

from __future__ import annotations

import random
from collections.abc import Iterable

from .kinds import DyadKind, PairKind
from .model import Driver, Mechanism, Pair

__all__ = ["GROUP_KINDS", "random_mechanism", "random_mechanism_with_groups"]

#: every group kind the generator knows, with its number of links: the five
#: dyads (:class:`~structure.kinds.DyadKind`, by their letters), a triad, a class IV group
GROUP_KINDS = {**{kind.value: 2 for kind in DyadKind}, "triad": 4, "class4": 4}

_SLIDER_SHARE = 0.2  # chance that an external pair of a triad / class IV group is P
_RECENT = 8  # window of recent links for the "deep" choice of a known link

_R, _P = PairKind.R, PairKind.P
_SLIDE_ANGLES = 1801  # distinct slide angles at 0.1 degree: 0.0, 0.1, ..., 180.0


class _Builder:
    """Mutable state of one generation run."""

    def __init__(self, rng: random.Random, compound: float) -> None:
        self.rng = rng
        self.compound = compound
        self.pairs: list[Pair] = []
        self.known: list[str] = ["0"]
        self.r_points: dict[str, list[str]] = {"0": []}
        self.n_links = 1  # next link name
        self.n_r = 0  # R point counter
        self.n_p = 0  # P point counter
        self.slide_angles: set[float] = set()  # no two slides parallel: generic geometry

    # ------------------------------------------------------------- helpers
    def new_link(self) -> str:
        name = str(self.n_links)
        self.n_links += 1
        self.r_points[name] = []
        return name

    def pick_known(self) -> str:
        rng, known = self.rng, self.known
        if rng.random() < 0.5:
            return known[rng.randrange(len(known))]
        return known[max(0, len(known) - 1 - rng.randrange(_RECENT))]

    def _add(self, kind: PairKind, a: str, b: str, point: str, angle: float | None) -> None:
        if self.rng.random() < 0.5:
            a, b = b, a
        self.pairs.append(
            Pair(id=len(self.pairs) + 1, kind=kind, a=a, b=b, point=point, angle_deg=angle)
        )

    def internal(self, kind: PairKind, a: str, b: str) -> None:
        """A fresh pair between two links of the group being built."""
        if kind is _R:
            self.n_r += 1
            point = f"J{self.n_r}"
            self.r_points[a].append(point)
            self.r_points[b].append(point)
            self._add(_R, a, b, point, None)
        else:
            self._slider(a, b)

    def _slider(self, a: str, b: str) -> None:
        self.n_p += 1
        angle = round(self.rng.uniform(0.0, 180.0), 1)
        # parallel slides would make a singular sketch; past the 1801 angles of 0.0..180.0
        # a repeat is unavoidable (and harmless: a large mechanism's rank is generic)
        while angle in self.slide_angles and len(self.slide_angles) < _SLIDE_ANGLES:
            angle = round(self.rng.uniform(0.0, 180.0), 1)
        self.slide_angles.add(angle)
        self._add(_P, a, b, f"S{self.n_p}", angle)

    def external(self, kind: PairKind, link: str, known: str, used: set[str]) -> None:
        """An external pair from group link ``link`` to the known link ``known``.

        ``used`` holds the points of the group's earlier external pairs; an R
        pair never reuses one of them.
        """
        if kind is _P:
            self._slider(link, known)
            return
        point = None
        if self.compound and self.rng.random() < self.compound:
            choices = self.r_points[known]  # the ground's list grows long: no copies
            for _ in range(4):  # `used` holds at most 3 points
                if not choices:
                    break
                candidate = choices[self.rng.randrange(len(choices))]
                if candidate not in used:
                    point = candidate
                    break
        if point is None:
            self.n_r += 1
            point = f"J{self.n_r}"
            self.r_points[known].append(point)
        used.add(point)
        self.r_points[link].append(point)
        self._add(_R, link, known, point, None)

    def ext_kind(self) -> PairKind:
        return _P if self.rng.random() < _SLIDER_SHARE else _R

    # -------------------------------------------------------------- groups
    def dyad(self, letters: str) -> tuple[str, ...]:
        if letters[0] != letters[2] and self.rng.random() < 0.5:
            letters = letters[::-1]  # RRP / PRR, RPP / PPR
        a, b = self.new_link(), self.new_link()
        used: set[str] = set()
        ka, kb = self.pick_known(), self.pick_known()
        self.external(PairKind(letters[0]), a, ka, used)
        self.internal(PairKind(letters[1]), a, b)
        self.external(PairKind(letters[2]), b, kb, used)
        return (a, b)

    def triad(self) -> tuple[str, ...]:
        base = self.new_link()
        leads = [self.new_link() for _ in range(3)]
        used: set[str] = set()
        for lead in leads:
            self.internal(_R, base, lead)
            self.external(self.ext_kind(), lead, self.pick_known(), used)
        return (base, *leads)

    def class4(self) -> tuple[str, ...]:
        ring = [self.new_link() for _ in range(4)]
        used: set[str] = set()
        for i in range(4):
            self.internal(_R, ring[i], ring[(i + 1) % 4])
        self.external(self.ext_kind(), ring[0], self.pick_known(), used)
        self.external(self.ext_kind(), ring[2], self.pick_known(), used)
        return tuple(ring)


def random_mechanism_with_groups(
    n_links: int,
    seed: int | None = None,
    *,
    kinds: Iterable[str] = tuple(GROUP_KINDS),
    compound: float = 0.0,
) -> tuple[Mechanism, list[tuple[str, ...]]]:
    """A random one-driver mechanism and the Assur groups it was built from.

    Parameters
    ----------
    n_links : int
        Wanted number of moving links (driver included), at least 1. Groups
        are only attached while they fit, so the result has ``n_links``
        moving links when ``n_links`` is odd and every kind has 2 links
        available, else a few less (each group adds an even number).
    seed : int or None
        Seed of the private random generator (``None``: unpredictable).
    kinds : iterable of str
        Group kinds to draw from, uniformly (see the module docstring).
    compound : float
        Probability, in [0, 1], that an external R pair reuses a pin point
        already on its known link (a compound hinge).

    Returns
    -------
    mechanism : Mechanism
        Ground ``0``, driver ``1``; validated, structure only (no points).
    groups : list of tuple of str
        The groups in the order they were attached, each as its links.

    Raises
    ------
    ValueError
        ``n_links < 1``, an unknown or empty ``kinds``, ``compound`` outside
        [0, 1].

    Examples
    --------
    >>> from structure import write_edgelist
    >>> m, groups = random_mechanism_with_groups(3, seed=7, kinds=("RRR",))
    >>> groups
    [('2', '3')]
    >>> print(write_edgelist(m), end="")
    name random mechanism (3 links, seed 7)
    ground 0
    driver 1
    0 1 R J1
    2 0 R J2
    3 2 R J3
    3 0 R J4
    """
    kinds = tuple(kinds)
    _check_arguments(n_links, kinds, compound)
    b = _Builder(random.Random(seed), compound)
    driver = b.new_link()
    b.n_r += 1
    b.r_points["0"].append("J1")
    b.r_points[driver].append("J1")
    b.pairs.append(Pair(id=1, kind=_R, a="0", b=driver, point="J1"))
    b.known.append(driver)
    groups = _attach_groups(b, kinds, n_links - 1)
    name = f"random mechanism ({n_links} links, seed {seed})"
    mechanism = Mechanism.from_pairs(b.pairs, drivers=[Driver(driver)], name=name)
    return mechanism, groups


def _check_arguments(n_links: int, kinds: tuple[str, ...], compound: float) -> None:
    if n_links < 1:
        raise ValueError(f"n_links must be at least 1, not {n_links}")
    if not kinds:
        raise ValueError("kinds is empty")
    unknown = [k for k in kinds if k not in GROUP_KINDS]
    if unknown:
        raise ValueError(f"unknown group kind(s) {unknown} (use {', '.join(GROUP_KINDS)})")
    if not 0.0 <= compound <= 1.0:
        raise ValueError(f"compound is a probability, not {compound}")


def _attach_groups(b: _Builder, kinds: tuple[str, ...], remaining: int) -> list[tuple[str, ...]]:
    """Attach random groups of ``kinds`` while one fits in ``remaining`` links."""
    groups: list[tuple[str, ...]] = []
    sizes = {k: GROUP_KINDS[k] for k in kinds}
    while True:
        fitting = [k for k in kinds if sizes[k] <= remaining]
        if not fitting:
            return groups
        kind = fitting[b.rng.randrange(len(fitting))]
        if kind == "triad":
            links = b.triad()
        elif kind == "class4":
            links = b.class4()
        else:
            links = b.dyad(kind)
        groups.append(links)
        b.known.extend(links)
        remaining -= len(links)


def random_mechanism(
    n_links: int,
    seed: int | None = None,
    *,
    kinds: Iterable[str] = tuple(GROUP_KINDS),
    compound: float = 0.0,
) -> Mechanism:
    """A random one-driver mechanism of about ``n_links`` moving links.

    Same arguments as :func:`random_mechanism_with_groups`, which also
    returns the groups attached.

    >>> m = random_mechanism(101, seed=3, compound=0.3)
    >>> len(m.moving_links), m.driver_links
    (101, ('1',))
    """
    return random_mechanism_with_groups(n_links, seed, kinds=kinds, compound=compound)[0]
