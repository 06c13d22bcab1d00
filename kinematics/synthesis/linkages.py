"""Linkages as vectors of numbers: their points over many designs and inputs at once, and as files.

A design is one row of numbers (:data:`PARAMETERS` names them for each
:class:`Linkage`); :func:`linkage_poses` places every pin and the coupler
point ``P`` of many designs at many crank angles at once with numpy, each
dyad by the closed form of the solvers (:mod:`kinematics.solvers.dyads`):
the joint of the dyad from pin X (lengths ``l1``) to pin Y (``l2``) lies at
the height ``h = √(l1² − along²)`` over XY, on the side ``sign`` (the sign of
``(Y − X) × (joint − X)``, the side the sketch fixes in the solvers). The
assembly mode is kept by that sign at every input; where ``h²`` falls to
zero the two modes meet (a change point or a dead point of the dyad), and
below it the dyad cannot close. :func:`design_mechanism` writes a design as a
:class:`~structure.model.Mechanism` at the crank angle of its first target,
with ``P`` a marker on its link, for the solvers to check.

Linkages:

* ``fourbar``: ground pivots A (crank 1) and D (rocker 3), coupler 2 from B
  to C, ``P`` on the coupler. Parameters: A, the ground's angle θ0 and
  length d (D = A + d·u(θ0)), crank a, coupler b, rocker c, ``P`` as (p, q)
  in the coupler's frame (origin B, x along BC), the crank's world angle
  φ1 at the first target, the dyad's side.

The six-bars add a dyad 4–5 (E–F, F–G or F–H) to that four-bar and carry
``P`` on link 4, as (p, q) in its frame (origin E, x along EF). They are
named after the inversions of Watt's chain (the two ternary links jointed)
and Stephenson's chain (the two ternary links apart): Watt I has a binary
ground, Watt II a ternary one; Stephenson I has a binary ground jointed to
both ternary links, Stephenson II a binary ground jointed to one, and
Stephenson III a ternary ground (pyslvs's examples, ``pyslvs/example.py`` of
KmolYuan/pyslvs, draw all five so; Plecnik and McCarthy, "Numerical
synthesis of six-bar linkages for mechanical computation", call Svoboda's
"double three-bar", two four-bars in series, a Watt II):

* ``watt1`` (Watt I): the dyad joins the ternary coupler 2 (B, C, E) to the
  ternary rocker 3 (D, C, H); ground A–D binary. E as (ex, ey) in the
  coupler's frame (origin B, x along BC), H as (hx, hy) in the rocker's
  (origin D, x along DC).
* ``watt2`` (Watt II: two four-bars in series): the ternary rocker 3 (D, C,
  E) drives the dyad to a third ground pivot G (gx, gy); E in the rocker's
  frame.
* ``stephenson3`` (Stephenson III): the ternary coupler 2 (B, C, E) drives
  the dyad to a third ground pivot G; the ground (A, D, G) is the ternary link
  not jointed to the coupler. E in the coupler's frame.

>>> x = np.array([[0, 0, 0, 4, 1, 4, 3, 2, 1, 0, 1]], dtype=float)  # a crank–rocker
>>> poses = linkage_poses(Linkage.FOURBAR, x, np.array([[0.0, np.pi / 2]]))
>>> poses.points["B"][0].round(12).tolist()
[[1.0, 0.0], [0.0, 1.0]]
>>> str(grashof_kind(np.array([4.0]), np.array([1.0]), np.array([4.0]), np.array([3.0]))[0])
'crank-rocker'
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from structure.kinds import TextEnum
from structure.model import Mechanism, Target, make_point, make_target
from structure.validation import validated

__all__ = [
    "LENGTHS",
    "PARAMETERS",
    "WORLD_POINTS",
    "Linkage",
    "LinkagePoses",
    "coupler_frame",
    "design_mechanism",
    "grashof_kind",
    "is_crank",
    "link_lengths",
    "linkage_poses",
    "place",
    "target_records",
]


class Linkage(TextEnum):
    """The linkages a path can be synthesised with (see the module's text)."""

    FOURBAR = "fourbar"
    WATT1 = "watt1"
    WATT2 = "watt2"
    STEPHENSON3 = "stephenson3"


_FOURBAR = ("ax", "ay", "theta0", "d", "a", "b", "c", "p", "q", "phi1", "side")
_TO_GROUND = (*_FOURBAR[:7], "ex", "ey", "gx", "gy", "e", "f", "p", "q", "phi1", "side", "side2")
_TO_ROCKER = (*_FOURBAR[:7], "ex", "ey", "hx", "hy", "e", "f", "p", "q", "phi1", "side", "side2")

#: the names of each linkage's parameters, in the order of a design's row
PARAMETERS: dict[Linkage, tuple[str, ...]] = {
    Linkage.FOURBAR: _FOURBAR,
    Linkage.WATT1: _TO_ROCKER,
    Linkage.WATT2: _TO_GROUND,
    Linkage.STEPHENSON3: _TO_GROUND,
}

#: the lengths among the parameters (they scale with the targets, the angles do not)
LENGTHS = frozenset(
    ("ax", "ay", "d", "a", "b", "c", "p", "q", "ex", "ey", "gx", "gy", "hx", "hy", "e", "f")
)

#: the parameters that are points of the plane (x, y): they move with the frame
WORLD_POINTS = (("ax", "ay"), ("gx", "gy"))


def place(linkage: Linkage, x: np.ndarray, z: np.ndarray, w: np.ndarray) -> np.ndarray:
    """The designs ``x`` moved by the similarity ``u ↦ z·u + w`` of the plane (complex z, w).

    A point u = x + iy of every design goes to ``z·u + w`` (one z and w per
    design): its pivots move so, its lengths grow by ``|z|``, its angles (the
    ground's θ0 and the crank's φ1) turn by ``arg z``. The sides (assembly
    modes) stay, since a similarity keeps the sense of every turn.

    >>> x = np.array([[0, 0, 0, 4, 1, 4, 3, 2, 1, 0, 1]], dtype=float)
    >>> place(Linkage.FOURBAR, x, np.array([2j]), np.array([1 + 0j]))[0].round(12).tolist()
    [1.0, 0.0, 1.570796326795, 8.0, 2.0, 8.0, 6.0, 4.0, 2.0, 1.570796326795, 1.0]
    """
    names = PARAMETERS[linkage]
    out = np.array(x, dtype=float, copy=True)
    z = np.asarray(z, dtype=complex)
    w = np.asarray(w, dtype=complex)
    scale, turn = np.abs(z), np.angle(z)
    moved: set[str] = set()
    for px, py in WORLD_POINTS:
        if px in names:
            i, j = names.index(px), names.index(py)
            u = z * (out[:, i] + 1j * out[:, j]) + w
            out[:, i], out[:, j] = u.real, u.imag
            moved.update((px, py))
    for k, name in enumerate(names):
        if name in moved:
            continue
        if name in LENGTHS:
            out[:, k] *= scale
        elif name in ("theta0", "phi1"):
            out[:, k] += turn
    return out


@dataclass(frozen=True)
class LinkagePoses:
    """Points of many designs at many inputs: each array has shape (designs, inputs, 2).

    ``points`` maps A, B, C, D (E, F, G) and P to their positions; ``heights``
    holds each dyad's ``h²`` (shape (designs, inputs)): the square of its
    joint's height over the line of its outer pins; ``transmission`` each
    dyad's transmission angle (rad, in [0, π]).
    """

    points: dict[str, np.ndarray]
    heights: tuple[np.ndarray, ...]
    transmission: tuple[np.ndarray, ...]


def _column(x: np.ndarray, linkage: Linkage, name: str) -> np.ndarray:
    return x[:, PARAMETERS[linkage].index(name), None]


def _side(value: np.ndarray) -> np.ndarray:
    return np.where(value >= 0.0, 1.0, -1.0)


def _joint(x0, y0, x1, y1, l1, l2, side):
    """The dyad's joint from pins (x0, y0), (x1, y1), lengths l1, l2 on ``side``; and h²."""
    ex, ey = x1 - x0, y1 - y0
    d2 = ex * ex + ey * ey
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / np.sqrt(d2)
        along = (d2 + l1 * l1 - l2 * l2) * 0.5 * inv
        h2 = l1 * l1 - along * along
        h = np.sqrt(np.maximum(h2, 0.0))
        ux, uy = ex * inv, ey * inv
    jx = x0 + along * ux - side * h * uy
    jy = y0 + along * uy + side * h * ux
    return jx, jy, np.where(np.isfinite(h2), h2, -np.inf)


def _angle_at(px, py, jx, jy, qx, qy):
    """The angle at the joint j between j→p and j→q (rad, in [0, π])."""
    ux, uy, vx, vy = px - jx, py - jy, qx - jx, qy - jy
    with np.errstate(divide="ignore", invalid="ignore"):
        cos = (ux * vx + uy * vy) / np.sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy))
    return np.arccos(np.clip(np.nan_to_num(cos), -1.0, 1.0))


def linkage_poses(linkage: Linkage, x: np.ndarray, phi: np.ndarray) -> LinkagePoses:
    """Every point of the designs ``x`` (shape (designs, parameters)) at crank angles ``phi``.

    ``phi`` (shape (designs, inputs)) are the crank's world angles. Where a
    dyad cannot close, its ``heights`` entry is negative and its points are
    those of the nearest closing (``h`` taken as 0): look at ``heights``
    before trusting them.
    """
    x = np.atleast_2d(np.asarray(x, dtype=float))
    col = lambda name: _column(x, linkage, name)  # noqa: E731
    ax, ay, theta0, d = col("ax"), col("ay"), col("theta0"), col("d")
    a, b, c = col("a"), col("b"), col("c")
    dx, dy = ax + d * np.cos(theta0), ay + d * np.sin(theta0)
    bx, by = ax + a * np.cos(phi), ay + a * np.sin(phi)
    cx, cy, h1 = _joint(bx, by, dx, dy, b, c, _side(col("side")))
    mu1 = _angle_at(bx, by, cx, cy, dx, dy)
    shape = np.broadcast_shapes(bx.shape, dx.shape)
    full = lambda v: np.broadcast_to(v, shape)  # noqa: E731
    points = {
        "A": np.stack([full(ax), full(ay)], axis=-1),
        "B": np.stack([bx, by], axis=-1),
        "C": np.stack([cx, cy], axis=-1),
        "D": np.stack([full(dx), full(dy)], axis=-1),
    }
    p, q = col("p"), col("q")
    if linkage is Linkage.FOURBAR:
        points["P"] = _in_frame(bx, by, cx, cy, p, q, b)
        return LinkagePoses(points, (h1,), (mu1,))
    # the ternary link carrying E: the rocker (Watt II) or the coupler (Watt I, Stephenson III)
    if linkage is Linkage.WATT2:
        e_xy = _in_frame(dx, dy, cx, cy, col("ex"), col("ey"), c)
    else:
        e_xy = _in_frame(bx, by, cx, cy, col("ex"), col("ey"), b)
    ex, ey = e_xy[..., 0], e_xy[..., 1]
    if linkage is Linkage.WATT1:  # the dyad's far pin H on the rocker
        end = _in_frame(dx, dy, cx, cy, col("hx"), col("hy"), c)
        gx, gy, far = end[..., 0], end[..., 1], "H"
    else:  # on the ground
        gx, gy, far = full(col("gx")), full(col("gy")), "G"
    e, f = col("e"), col("f")
    fx, fy, h2 = _joint(ex, ey, gx, gy, e, f, _side(col("side2")))
    mu2 = _angle_at(ex, ey, fx, fy, gx, gy)
    points["E"] = e_xy
    points["F"] = np.stack([fx, fy], axis=-1)
    points[far] = np.stack([gx, gy], axis=-1)
    points["P"] = _in_frame(ex, ey, fx, fy, p, q, e)
    return LinkagePoses(points, (h1, h2), (mu1, mu2))


def coupler_frame(
    linkage: Linkage, poses: LinkagePoses, x: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The frame ``P`` is fixed in, as complex numbers (designs, inputs): origin and x axis.

    ``P = origin + axis·(p + iq)``: the frame of the coupler (origin B, axis
    along BC) of a four-bar, of link 4 (origin E, axis along EF) of a six-bar;
    ``axis`` has length 1.

    >>> x = np.array([[0, 0, 0, 4, 1, 4, 3, 2, 1, 0, 1]], dtype=float)
    >>> poses = linkage_poses(Linkage.FOURBAR, x, np.array([[0.0]]))
    >>> o, u = coupler_frame(Linkage.FOURBAR, poses, x)
    >>> bool(np.isclose(o + u * (2 + 1j), complex(*poses.points["P"][0, 0])).all())
    True
    """
    x = np.atleast_2d(x)
    start, end, name = ("B", "C", "b") if linkage is Linkage.FOURBAR else ("E", "F", "e")
    o = poses.points[start][..., 0] + 1j * poses.points[start][..., 1]
    t = poses.points[end][..., 0] + 1j * poses.points[end][..., 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        axis = (t - o) / x[:, PARAMETERS[linkage].index(name), None]
    return o, axis


def _in_frame(ox, oy, tx, ty, u, v, length) -> np.ndarray:
    """Point (u, v) of the frame at (ox, oy) whose x axis points at (tx, ty), ``length`` away."""
    with np.errstate(divide="ignore", invalid="ignore"):
        cos, sin = (tx - ox) / length, (ty - oy) / length
    return np.stack([ox + u * cos - v * sin, oy + u * sin + v * cos], axis=-1)


def link_lengths(linkage: Linkage, x: np.ndarray) -> np.ndarray:
    """Every link's defining lengths, shape (designs, k): ground d, a, b, c (e, f)."""
    x = np.atleast_2d(x)
    names = ("d", "a", "b", "c") if linkage is Linkage.FOURBAR else ("d", "a", "b", "c", "e", "f")
    return np.column_stack([x[:, PARAMETERS[linkage].index(n)] for n in names])


def grashof_kind(d: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """The four-bar's type by Grashof's rule with crank a, coupler b, rocker c and ground d.

    ``crank-rocker`` (a shortest), ``double-crank`` (d shortest), ``double-rocker``
    (b or c shortest: Grashof, but the input rocks), ``triple-rocker`` (not
    Grashof: s + l > p + q), ``change-point`` (s + l = p + q within round-off).
    """
    lengths = np.column_stack([d, a, b, c])
    s, l_ = lengths.min(axis=1), lengths.max(axis=1)
    total = lengths.sum(axis=1)
    slack = (total - s - l_) - (s + l_)
    tol = 1e-12 * total
    shortest = lengths.argmin(axis=1)
    kind = np.where(
        shortest == 1, "crank-rocker", np.where(shortest == 0, "double-crank", "double-rocker")
    )
    kind = np.where(slack < -tol, "triple-rocker", kind)
    return np.where(np.abs(slack) <= tol, "change-point", kind)


def is_crank(d: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Whether the input a turns fully: Grashof (strictly) with a or the ground shortest."""
    kind = grashof_kind(d, a, b, c)
    return (kind == "crank-rocker") | (kind == "double-crank")


def design_mechanism(
    linkage: Linkage,
    x: np.ndarray,
    targets: tuple[Target, ...] = (),
    name: str = "",
    source: str = "<synthesis>",
) -> Mechanism:
    """The design ``x`` (one row) as a mechanism at the crank angle φ1 of its first target.

    Link 1 is the crank (the driver), 0 the ground; the pins are named A, B,
    C, D (E, F, and G on the ground or H on the rocker) and the coupler point
    ``P`` is a marker on its link.

    >>> x = np.array([0, 0, 0, 4, 1, 4, 3, 2, 1, 0, 1], dtype=float)
    >>> m = design_mechanism(Linkage.FOURBAR, x)
    >>> m.driver_links, m.points["P"].on, m.points["B"].x
    (('1',), '2', 1.0)
    """
    x = np.asarray(x, dtype=float).reshape(1, -1)
    phi1 = x[0, PARAMETERS[linkage].index("phi1")]
    poses = linkage_poses(linkage, x, np.array([[phi1]]))
    xy = {k: v[0, 0] for k, v in poses.points.items()}
    pairs: list[tuple] = [("0", "1", "R", "A"), ("1", "2", "R", "B"), ("2", "3", "R", "C")]
    pairs.append(("3", "0", "R", "D"))
    on = "2"
    if linkage is not Linkage.FOURBAR:
        carrier = "3" if linkage is Linkage.WATT2 else "2"
        end = ("3", "H") if linkage is Linkage.WATT1 else ("0", "G")
        pairs += [(carrier, "4", "R", "E"), ("4", "5", "R", "F"), ("5", end[0], "R", end[1])]
        on = "4"
    points = [make_point(k, float(v[0]), float(v[1])) for k, v in xy.items() if k != "P"]
    points.append(make_point("P", float(xy["P"][0]), float(xy["P"][1]), on))
    m = Mechanism.from_pairs(pairs, drivers=["1"], points=points, name=name, source=source)
    return validated(m.evolve(targets=tuple(targets)))


def target_records(
    xy: np.ndarray, inputs_deg: np.ndarray | None = None, angles_deg: np.ndarray | None = None
) -> tuple[Target, ...]:
    """Targets ``T1``, ``T2``, ... from their points and, when given, inputs and angles."""
    out = []
    for k, (tx, ty) in enumerate(np.asarray(xy, dtype=float)):
        inp = None if inputs_deg is None else float(inputs_deg[k])
        ang = None if angles_deg is None else float(angles_deg[k])
        out.append(make_target(f"T{k + 1}", float(tx), float(ty), inp, ang))
    return tuple(out)
