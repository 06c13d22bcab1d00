"""Gear meshes in the kinematic graph: which higher pairs are meshes, their carriers and teeth.

A gear mesh is a higher pair marked ``gear`` with its tooth numbers
(``2 3 H gear z=25,105 internal=3``). Its carrier is the link that holds both
gear axes: the link joined by revolute pairs (directly or through a shared
pin) to both gears; for an ordinary pair on fixed axes that is the ground. A
planet is a gear pinned to a moving carrier away from the carrier's own axis.
This is topology only; the speed ratios and forces of a train are
:mod:`kinematics.gears.trains`'.

>>> from structure import parse_edgelist
>>> m = parse_edgelist(["driver 3", "0 c R O", "0 3 R O", "c 2 R P",
...                     "2 0 H gear z=20,60", "2 3 H gear z=25,? internal=3"])
>>> [(x.a, x.b, x.za, x.zb, x.carrier, x.internal) for x in meshes(m)]
[('2', '0', 20, 60, 'c', False), ('2', '3', 25, None, 'c', True)]
>>> is_planet(m, "2", "c"), is_planet(m, "3", "c")
(True, False)
"""

from __future__ import annotations

from dataclasses import dataclass

from .errors import MechanismError
from .model import Mechanism, Pair, PairKind

__all__ = ["Mesh", "is_planet", "meshes"]


@dataclass(frozen=True)
class Mesh:
    """A gear mesh between links ``a`` and ``b`` with its carrier."""

    pair: Pair
    a: str
    b: str
    za: int | None
    zb: int | None
    carrier: str
    internal: bool


def _joined(m: Mechanism) -> dict[str, set[str]]:
    """Links joined by a revolute pair (or a shared pin point) to each link."""
    out: dict[str, set[str]] = {link: set() for link in m.links}
    for p in m.pairs:
        if p.kind is PairKind.R:
            out[p.a].add(p.b)
            out[p.b].add(p.a)
    for h in m.hinges:
        for x in h.links:
            out[x].update(y for y in h.links if y != x)
    return out


def meshes(mechanism: Mechanism) -> tuple[Mesh, ...]:
    """The gear meshes of ``mechanism`` with their carriers.

    Raises
    ------
    MechanismError
        A mesh whose carrier cannot be found (the gears' axes are on no common link)
        or is ambiguous.
    """
    joined = _joined(mechanism)
    out = []
    for p in mechanism.pairs:
        if not p.gear:
            continue
        a, b = p.a, p.b
        # a gear's axis is fixed in the links it is pinned to (and in itself)
        carriers = (joined[a] | {a}) & (joined[b] | {b})
        if len(carriers) != 1:
            raise MechanismError(
                f"{mechanism.source}: line {p.line_no}: the gear mesh {p.label} has "
                + (
                    "no carrier: its gears' axes are on no common link"
                    if not carriers
                    else f"several possible carriers ({', '.join(sorted(carriers))})"
                )
            )
        za, zb = p.teeth if p.teeth is not None else (None, None)
        out.append(Mesh(p, a, b, za, zb, carriers.pop(), p.internal is not None))
    return tuple(out)


def is_planet(mechanism: Mechanism, gear: str, carrier: str) -> bool:
    """Whether ``gear`` is pinned to ``carrier`` by a pin that is not on the ground.

    That is a planet when the carrier moves: its axis orbits the carrier's own.
    """
    ground = mechanism.ground
    return any(
        gear in h.links and carrier in h.links and ground not in h.links for h in mechanism.hinges
    )
