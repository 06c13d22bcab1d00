"""Velocity and acceleration polygons: each point's vector from the pole, each dyad's terms.

:func:`velocity_polygon`, :func:`acceleration_polygon` — the pole (``p``,
``π``) at the origin, each point's vector as an ``Annotation`` arrow with
gid ``arrow:<name>`` (``.xyann`` the pole, ``.xy`` the tip, in drawing
units), its lower-case label a ``Text`` with gid ``label:<name>``; the title
states the scale, ``μ_v = 0.02 (m/s)/unit``. Each dyad's vector equations
(:mod:`kinematics.kinetostatics.polygons`) are drawn head to tail from the known points'
images: relative velocities ``rel:v_CB``, ``rel:v_B3B2``; normal,
tangential, Coriolis and relative accelerations ``comp:a^n_CB``,
``comp:a^t_CB``, ``comp:a^k_B3B2``, ``comp:a^r_B3B2`` (a zero one is a
circle ``Line2D``), each labelled by a ``Text`` with the same gid; the
point between two components is a dot ``node:n_CB`` or ``node:k_B3B2``.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from structure.model import PairKind

from ..kinetostatics.polygons import Term, point_motion, vector_equations
from ..solvers.plan import SolvePlan
from ..solvers.solve import KinematicState
from .style import figure_axes, length, nice_scale

__all__ = ["acceleration_polygon", "velocity_polygon"]


@dataclass(frozen=True, eq=False)
class _Component:
    """A term of a dyad's vector equation drawn head to tail (physical units)."""

    gid: str  # 'rel:v_CB', 'comp:a^n_CB', 'comp:a^t_CB', 'comp:a^k_B3B2', 'comp:a^r_B3B2'
    text: str  # its label
    tail: np.ndarray
    vector: np.ndarray
    sup: str  # '', 'n', 'τ', 'k', 'r'


@dataclass
class _Construction:
    """What a polygon draws beyond the points' own vectors from the pole."""

    images: dict[str, np.ndarray] = field(default_factory=dict)  # points no plan point is
    components: list[_Component] = field(default_factory=list)
    nodes: list[tuple[str, str, np.ndarray]] = field(default_factory=list)  # gid, text, where
    links: list[tuple[str, list[np.ndarray]]] = field(default_factory=list)  # similar figures


_COMPONENT_STYLE = {  # colour, legend entry (plain text: mathtext is slow to lay out)
    "": ("tab:green", "relative velocity"),
    "n": ("tab:purple", "normal, ω²·l toward the pin"),
    "τ": ("tab:green", "tangential, ε·l"),
    "k": ("tab:orange", "Coriolis, 2·ω·v_rel"),
    "r": ("tab:brown", "relative, along the guide"),
}
_PLAIN_SUB = re.compile(r"[A-Za-z0-9()',.]+")


def _term_text(term: Term) -> str:
    """``$a^{\\tau}_{CB}$`` (mathtext); the plain ``a^τ_C*`` for names mathtext would misread."""
    if not _PLAIN_SUB.fullmatch(term.sub):
        return term.key
    sup = {"τ": r"\tau"}.get(term.sup, term.sup)
    top = f"^{{{sup}}}" if sup else ""
    return f"${term.letter}{top}_{{{term.sub}}}$"


def _term_gid(term: Term) -> str:
    prefix = "rel" if term.letter == "v" else "comp"
    return f"{prefix}:{term.key.replace('τ', 't')}"


def _construction(
    plan: SolvePlan, state: KinematicState, order: int, vectors: Mapping[str, np.ndarray]
) -> _Construction:
    """The dyads' relative terms head to tail, the points they need, the links' images."""
    out = _Construction()
    pts = {n: ps for n, ps in state.points.items() if n in vectors}
    # the largest of each kind: what "the same" is measured against (0 when all are 0)
    size = max((length(ps.position) for ps in pts.values()), default=0.0)
    speed = max((length(ps.velocity) for ps in pts.values()), default=0.0)
    accel = max((length(ps.acceleration) for ps in pts.values()), default=0.0)

    derived: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}  # where, v, a

    def image(label: str, link: str, where: np.ndarray) -> str:
        """The name of the point of ``link`` at ``where``: a plan point's, else ``label``."""
        v, a = point_motion(plan, state, link, where)

        def same(p: np.ndarray, pv: np.ndarray, pa: np.ndarray) -> bool:
            return bool(
                length(p - where) <= 1e-9 * size
                and length(pv - v) <= 1e-9 * speed
                and length(pa - a) <= 1e-9 * accel
            )

        for name, ps in pts.items():
            if same(ps.position, ps.velocity, ps.acceleration):
                return name
        for name, known in derived.items():
            if same(*known):
                return name
        name = label
        while name in vectors or name in derived:
            name += "'"
        derived[name] = (where, v, a)
        out.images[name] = v if order == 1 else a
        return name

    for eq in vector_equations(plan, state, order):
        image(eq.x, eq.x_link, eq.dyad.where)
        for chain in eq.chains:
            image(chain.start, chain.start_link, chain.start_where)
            at = chain.origin
            small = 1e-9 * (speed if order == 1 else accel)
            nonzero = all(length(t.vector) > small for t in chain.terms)
            for k, term in enumerate(chain.terms):
                out.components.append(
                    _Component(_term_gid(term), _term_text(term), at, term.vector, term.sup)
                )
                at = at + term.vector
                if k + 1 < len(chain.terms) and nonzero:
                    mark = "n" if term.sup == "n" else "k"
                    out.nodes.append((f"node:{mark}_{term.sub}", mark, at))

    # similar figures: the images of the points of each link that carries a marker
    m = plan.mechanism
    for link in m.moving_links:
        markers = [n for n, p in m.points.items() if p.on == link and n in pts]
        if not markers:
            continue
        pins = [p.point for p in m.pairs_of(link) if p.kind is PairKind.R and p.point in pts]
        names = list(dict.fromkeys([*pins, *markers]))
        corners = [point_motion(plan, state, link, pts[n].position)[order - 1] for n in names]
        if len(corners) >= 2:
            out.links.append((link, corners))
    return out


def _polygon(
    vectors: Mapping[str, np.ndarray],
    ax: Axes | None,
    scale: float | None,
    pole: str,
    symbol: str,
    unit: str,
    what: str,
    colour: str,
    extra: _Construction | None = None,
) -> Figure:
    """The polygon of ``vectors`` from ``pole`` and the construction ``extra``, to scale."""
    fig, ax = figure_axes(ax, (6.0, 6.0))
    extra = extra or _Construction()
    vectors = {n: np.asarray(v, dtype=float) for n, v in vectors.items()}
    vectors.update({n: np.asarray(v, dtype=float) for n, v in extra.images.items()})
    derived = set(extra.images)
    corners_phys = [*vectors.values()]
    corners_phys += [c.tail + c.vector for c in extra.components] + [n[2] for n in extra.nodes]
    biggest = max((length(v) for v in corners_phys), default=0.0)
    absolute = max((length(v) for v in vectors.values()), default=0.0)
    shown = {n: v for n, v in vectors.items() if length(v) > 1e-9 * absolute}
    if scale is None:
        scale = nice_scale(biggest / 100.0) if biggest > 0 else 1.0
    if not scale > 0:
        raise ValueError(f"scale must be positive, got {scale}")
    tips = {n: v / scale for n, v in shown.items()}
    extent = max((float(np.abs(v).max()) for v in corners_phys), default=0.0) / scale or 1.0
    nudge = 0.03 * extent

    _draw_pole_vectors(ax, tips, derived, pole, colour, nudge, extent)
    corners = [np.zeros(2), *tips.values()]
    corners += _draw_components(ax, extra, scale, absolute, nudge)
    for link, images in extra.links:
        xy = np.array(images) / scale
        if len(xy) > 2:
            xy = np.vstack([xy, xy[:1]])
        ax.plot(xy[:, 0], xy[:, 1], ls=":", color="0.5", lw=1.0, zorder=1, gid=f"image:{link}")
    if extra.components:
        _component_legend(ax, extra, pole, colour)
    _fit_to_corners(ax, np.array(corners), extent)
    ax.set_title(f"{what}, {symbol} = {scale:.6g} {unit}/unit")
    return fig


def _draw_pole_vectors(
    ax: Axes,
    tips: Mapping[str, np.ndarray],
    derived: set[str],
    pole: str,
    colour: str,
    nudge: float,
    extent: float,
) -> None:
    """The pole, and each point's arrow from it with its lower-case label (thin when derived)."""
    ax.plot([0.0], [0.0], "o", color="black", ms=4, gid="pole")
    ax.text(-nudge, -nudge, pole, fontsize=11, ha="right", va="top", gid="label:pole")
    placed: list[np.ndarray] = []
    for name, tip in tips.items():
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(0.0, 0.0),
            arrowprops={
                "arrowstyle": "-|>",
                "color": colour,
                "lw": 1.2 if name in derived else 2.2,
                "alpha": 0.75,
                "shrinkA": 0,
                "shrinkB": 0,
            },
            gid=f"arrow:{name}",
        )
        same = sum(1 for t in placed if length(t - tip) <= 1e-6 * extent)
        placed.append(tip)
        d = tip / (length(tip) or 1.0) * nudge * (1 + 1.5 * same)  # coincident tips
        ax.text(
            tip[0] + d[0],
            tip[1] + d[1],
            name.lower(),
            fontsize=10,
            ha="center",
            va="center",
            gid=f"label:{name}",
        )


def _component_legend(ax: Axes, extra: _Construction, pole: str, colour: str) -> None:
    """Below the axes: the absolute vectors, then each kind of component drawn."""
    handles = [Line2D([], [], color=colour, lw=2.2, alpha=0.75, label=f"absolute, from {pole}")]
    kinds = dict.fromkeys(c.sup for c in extra.components)
    for sup in kinds:
        c, entry = _COMPONENT_STYLE[sup]
        handles.append(Line2D([], [], color=c, lw=1.2, label=entry))
    ax.legend(
        handles=handles,
        loc="upper center",
        bbox_to_anchor=(0.5, -0.05),
        ncol=2,
        fontsize=7,
        frameon=False,
    )


def _fit_to_corners(ax: Axes, corners: np.ndarray, extent: float) -> None:
    """Equal-scale limits around ``corners`` (padded, not a sliver) and the axes through 0."""
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    pad = 0.12 * max(float((hi - lo).max()), extent)
    lo, hi = lo - pad, hi + pad
    span = hi - lo
    grow = np.maximum(0.6 * span.max() - span, 0.0) / 2  # not a sliver: room for the labels
    lo, hi = lo - grow, hi + grow
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal", adjustable="box")
    ax.axhline(0.0, color="0.85", lw=0.6, zorder=0)
    ax.axvline(0.0, color="0.85", lw=0.6, zorder=0)


def _draw_components(
    ax: Axes, extra: _Construction, scale: float, absolute: float, nudge: float
) -> list[np.ndarray]:
    """Each term an arrow from its tail (a dot when zero) with its label; the corners drawn."""
    corners: list[np.ndarray] = []
    labels: list[np.ndarray] = []
    longest = max((length(c.vector) for c in extra.components), default=0.0)
    zero = 1e-9 * max(absolute, longest)

    def spot(anchor: np.ndarray, away: np.ndarray) -> np.ndarray:
        """``anchor + away``, moved on by ``away`` while it sits on a label placed before.

        ``away`` is about ``nudge`` long and a label keeps 1.2·nudge clear, so each label
        placed before can hold it back a few steps at most: the steps are bounded by
        their count, whatever the numbers (issue 22: a tiny polygon looped here).
        """
        at = anchor + away
        for _ in range(4 * len(labels)):
            if not any(length(at - q) < 1.2 * nudge for q in labels):
                break
            at = at + away
        labels.append(at)
        return at

    for c in extra.components:
        colour = _COMPONENT_STYLE[c.sup][0]
        tail = c.tail / scale
        tip = (c.tail + c.vector) / scale
        corners += [tail, tip]
        if length(c.vector) <= zero:
            ax.plot([tail[0]], [tail[1]], "o", mfc="none", mec=colour, ms=5, gid=c.gid)
            at = spot(tail, np.array([1.2, -1.0]) * nudge)
            text = _zero_text(c.text)
            ax.text(*at, text, color=colour, fontsize=8, ha="left", va="center", gid=c.gid)
            continue
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(float(tail[0]), float(tail[1])),
            arrowprops={
                "arrowstyle": "-|>",
                "color": colour,
                "lw": 1.2,
                "shrinkA": 0,
                "shrinkB": 0,
            },
            gid=c.gid,
        )
        d = tip - tail
        normal = np.array([-d[1], d[0]]) / (float(np.hypot(*d)) or 1.0) * nudge
        at = spot((tail + tip) / 2, normal)
        ax.text(*at, c.text, color=colour, fontsize=9, ha="center", va="center", gid=c.gid)
    for gid, text, where in extra.nodes:
        xy = where / scale
        ax.plot([xy[0]], [xy[1]], "o", color="0.3", ms=3, gid=gid)
        at = spot(xy, np.array([-1.0, 1.0]) * 0.7 * nudge)
        ax.text(*at, text, color="0.3", fontsize=7, ha="center", va="center", gid=gid)
    return corners


def _zero_text(text: str) -> str:
    """``$v_{CB}$`` → ``$v_{CB} = 0$``."""
    return text[:-1] + " = 0$" if text.endswith("$") else text + " = 0"


def velocity_polygon(
    plan: SolvePlan, state: KinematicState, ax: Axes | None = None, scale: float | None = None
) -> Figure:
    """Velocity polygon: pole p, each point's vector, each dyad's relative velocities.

    Parameters
    ----------
    plan : SolvePlan
    state : KinematicState
        A solved pose of ``plan``.
    ax : Axes, optional
        Draw on it (default: a new figure).
    scale : float, optional
        μ_v in (m/s) per drawing unit (default: a round number, ~100 units for
        the longest vector).

    Returns
    -------
    Figure

    Notes
    -----
    Each moving point's velocity is an arrow p→x (gid ``arrow:<name>``, label
    ``label:<name>``). For each dyad (class II group) the terms of its vector
    equation (:mod:`kinematics.kinetostatics.polygons`) are drawn from the known point's
    image to X's: for an RRR dyad B–C–D the arrows b→c (``rel:v_CB``, ⊥BC) and
    d→c (``rel:v_CD``, ⊥CD); for a slider, the relative sliding velocity from
    the guide point's image (``rel:v_B3B2``, ∥ the guide). The point of a
    guide or of a slotted link under X (``B3``) that no named point stands
    for is added, with its arrow from p. A zero term is a circle, its label
    ``v_CB = 0``; every label is a ``Text`` with the arrow's gid. The images
    of the points of a link with markers are joined by a dotted line (gid
    ``image:<link>``): the figure similar to the link. Triads and higher
    groups are solved as a whole: only their points' vectors are drawn.
    """
    vectors = {n: state.points[n].velocity for n in plan.points if n in state.points}
    extra = _construction(plan, state, 1, vectors)
    return _polygon(vectors, ax, scale, "p", "μ_v", "(m/s)", "Velocity polygon", "tab:blue", extra)


def acceleration_polygon(
    plan: SolvePlan, state: KinematicState, ax: Axes | None = None, scale: float | None = None
) -> Figure:
    """Acceleration polygon: pole π, each point's vector, each dyad's components head to tail.

    Parameters
    ----------
    plan : SolvePlan
    state : KinematicState
        A solved pose of ``plan``.
    ax : Axes, optional
        Draw on it (default: a new figure).
    scale : float, optional
        μ_a in (m/s²) per drawing unit (default: a round number).

    Returns
    -------
    Figure

    Notes
    -----
    Each moving point's acceleration is an arrow π→x' (gid ``arrow:<name>``).
    For each dyad, from the image of a pin B that X turns about: the normal
    component (gid ``comp:a^n_CB``, ∥CB from C to B, ω²·l_BC) to the
    intermediate point n_CB (gid ``node:n_CB``), then the tangential one
    (``comp:a^t_CB``, ⊥BC, ε·l_BC) to x'; from the image of a guide's point
    under X: the Coriolis component (``comp:a^k_B3B2``, 2·ω_guide·v_rel, the
    relative velocity turned 90° in the sense of the guide's ω) to k_B3B2,
    then the relative one (``comp:a^r_B3B2``, ∥ the guide). A zero component
    is a circle at its tail, labelled ``a^n_CB = 0``; labels are ``Text`` s
    with the arrow's gid. Triads and higher groups are solved as a whole:
    only their points' vectors are drawn.
    """
    vectors = {n: state.points[n].acceleration for n in plan.points if n in state.points}
    extra = _construction(plan, state, 2, vectors)
    return _polygon(
        vectors, ax, scale, "π", "μ_a", "(m/s²)", "Acceleration polygon", "tab:red", extra
    )
