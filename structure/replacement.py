"""Higher-pair replacement: rollers removed, each higher pair -> virtual link + two lower pairs.

The replacement is instantaneous (valid for positions, velocities and
accelerations at the pose) and keeps the mobility: a higher pair removes one
freedom, a virtual link with two lower pairs removes 2·2 − 3 = 1.

* A roller (``roller=L``) is deleted first with its revolute pair to the
  follower; its spin was a passive freedom. The contact then acts at the
  roller's axis, a point of the follower.
* Curve–curve contact: revolute pairs at the two centres of curvature
  (``centers=O1,O2``), joined by the virtual link.
* Curve–line contact (``flat=L``): a revolute pair at the curved profile's
  centre and a prismatic pair on ``L``, parallel to its face.

Virtual links are named ``v1``, ``v2``, … after the higher pairs in file
order (with primes added if a link already has that name). Lower pairs keep
their ids; new pairs get ids after the last one.

>>> from structure import parse_edgelist
>>> m = parse_edgelist(["driver 1", "0 1 R O1", "1 2 H K centers=C1,A",
...                     "2 0 R O2"])
>>> r, reps = replace_higher_pairs(m)
>>> [p.label for p in r.pairs]
['0–1 R O1', '2–0 R O2', '1–v1 R C1', 'v1–2 R A']
>>> reps[0].virtual_link, reps[0].pair.label
('v1', '1–2 H K')
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import EdgeListError, EdgeListProblem, StatementError
from .kinds import PairKind
from .model import Mechanism, Pair
from .validation import validated

__all__ = ["Replacement", "RollerRemoval", "replace_higher_pairs"]


@dataclass(frozen=True, slots=True)
class RollerRemoval:
    """A roller deleted before replacement: its spin is one passive freedom."""

    roller: str
    follower: str
    axis: str
    removed_pairs: tuple[Pair, ...]


@dataclass(frozen=True, slots=True)
class Replacement:
    """Virtual link ``virtual_link`` with ``new_pairs`` stands for higher pair ``pair``."""

    virtual_link: str
    pair: Pair
    new_pairs: tuple[Pair, ...]
    roller: RollerRemoval | None = None

    @property
    def scheme(self) -> str:
        """``'R–R'`` or ``'R–P'``: the lower pairs that replaced the contact."""
        return "–".join(p.kind.value for p in self.new_pairs)


def _fresh(name: str, taken: set[str]) -> str:
    while name in taken:
        name += "'"
    taken.add(name)
    return name


def replace_higher_pairs(
    mechanism: Mechanism,
) -> tuple[Mechanism, tuple[Replacement, ...]]:
    """The equivalent lower-pair mechanism and the record of each replacement.

    Raises
    ------
    EdgeListError
        A roller that is a driver, or is not a binary link joined to its
        follower by one revolute pair.
    """
    highs = [p for p in mechanism.pairs if p.kind is PairKind.H]
    if not highs:
        return mechanism, ()
    taken = set(mechanism.links) | set(mechanism.points)
    contacts, rollers = _contacts(mechanism, highs, taken)
    removed_ids = {r.removed_pairs[0].id for r in rollers.values()}
    kept = [p for p in mechanism.pairs if p.kind is not PairKind.H and p.id not in removed_ids]
    next_id = max(p.id for p in mechanism.pairs) + 1
    new_pairs: list[Pair] = []
    records: list[Replacement] = []
    for k, p in enumerate(highs, start=1):
        v = _fresh(f"v{k}", taken)
        made = _virtual_pairs(mechanism, p, contacts[p.id], v, next_id, taken)
        next_id += 2
        new_pairs.extend(made)
        records.append(Replacement(v, p, made, rollers.get(p.id)))
    # a cam's profile belongs to its higher pair, which the replaced mechanism has not
    replaced = mechanism.evolve(pairs=tuple(kept + new_pairs), cams=())
    return validated(replaced), tuple(records)


#: a contact after roller removal: links a, b and the centres of curvature on each
_Contact = tuple[str, str, str | None, str | None]


def _contacts(
    mechanism: Mechanism, highs: list[Pair], taken: set[str]
) -> tuple[dict[int, _Contact], dict[int, RollerRemoval]]:
    """Each higher pair's contact, with its roller (if any) removed first.

    Raises
    ------
    EdgeListError
        A roller that is a driver or is not joined to its follower by one R pair.
    """
    problems: list[EdgeListProblem] = []
    rollers: dict[int, RollerRemoval] = {}
    contacts: dict[int, _Contact] = {}
    for p in highs:
        ca, cb = p.centers if p.centers is not None else (None, None)
        if p.roller is None:
            contacts[p.id] = (p.a, p.b, ca, cb)
            continue
        try:
            removal = _remove_roller(mechanism, p, taken)
        except StatementError as exc:
            problems.append(EdgeListProblem(p.line_no, p.label, exc.reason))
            continue
        rollers[p.id] = removal
        cam = p.other(removal.roller)
        contacts[p.id] = (cam, removal.follower, p.center_of(cam), removal.axis)
    if problems:
        raise EdgeListError(mechanism.source, problems)
    return contacts, rollers


def _remove_roller(mechanism: Mechanism, p: Pair, taken: set[str]) -> RollerRemoval:
    """Remove the roller of ``p`` with its R pair to the follower; the contact moves to its axis."""
    roller = p.roller
    assert roller is not None
    others = [q for q in mechanism.pairs_of(roller) if q.id != p.id]
    if roller in mechanism.driver_links:
        raise StatementError(f"roller {roller} is a driver")
    if len(others) != 1 or others[0].kind is not PairKind.R:
        raise StatementError(
            f"roller {roller} must be joined to its follower by exactly one R pair "
            f"besides this contact ({len(others)} other pairs found)"
        )
    axis_pair = others[0]
    follower = axis_pair.other(roller)
    axis = axis_pair.point or _fresh(f"{roller}.axis", taken)
    return RollerRemoval(roller, follower, axis, (axis_pair, p))


def _virtual_pairs(
    mechanism: Mechanism, p: Pair, contact: _Contact, v: str, next_id: int, taken: set[str]
) -> tuple[Pair, Pair]:
    """The two lower pairs that join virtual link ``v`` to the contact's links."""
    a, b, ca, cb = contact
    flat = p.flat if p.flat in (a, b) else None
    if flat is None:
        ca = ca or _fresh(f"{v}.{a}", taken)
        cb = cb or _fresh(f"{v}.{b}", taken)
        return (
            Pair(next_id, PairKind.R, a, v, ca, line_no=p.line_no),
            Pair(next_id + 1, PairKind.R, v, b, cb, line_no=p.line_no),
        )
    curved = b if flat == a else a
    center = (cb if flat == a else ca) or _fresh(f"{v}.{curved}", taken)
    angle = _face_angle(mechanism, p, center)
    r_pair = Pair(next_id, PairKind.R, curved, v, center, line_no=p.line_no)
    p_pair = Pair(next_id + 1, PairKind.P, v, flat, center, angle_deg=angle, line_no=p.line_no)
    return r_pair, p_pair


def _face_angle(mechanism: Mechanism, pair: Pair, center: str) -> float | None:
    """Direction (degrees) of the flat face: perpendicular to the contact normal."""
    if pair.normal_deg is not None:
        return pair.normal_deg + 90.0
    c = mechanism.coordinates(center)
    k = mechanism.coordinates(pair.point) if pair.point else None
    if c is None or k is None or c == k:
        return None
    return math.degrees(math.atan2(k[1] - c[1], k[0] - c[0])) + 90.0
