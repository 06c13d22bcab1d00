"""Force polygons of each Assur group and driver, and the applied loads on the mechanism.

:func:`force_polygon` — for each Assur group (and each driver) the forces on
it drawn head to tail, a closed polygon: ``Annotation`` arrows with gid
``force:<key>`` (``load:<link>:<point>``, ``weight:<link>``,
``inertia:<link>``, ``reaction:<from>-><on>:<point>``, ``balance:<link>``),
the scale ``μ_F = 10 N/unit`` in the title; :func:`draw_loads` draws the
applied forces on the mechanism (gid ``load:<link>:<point>``) and
:func:`polygon_entries` lists the panels, for
:func:`kinematics.figures.sheets.forces_sheet`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ..kinetostatics.forces import ForceSolution
from ..solvers.plan import SolvePlan
from ..solvers.solve import KinematicState, solve_pose
from .style import drawing_unit, length, nice_scale, place, point_xy, state_poses

__all__ = ["draw_loads", "force_polygon", "polygon_entries"]


@dataclass(frozen=True)
class _Force:
    key: str  # the arrow's gid is 'force:<key>'
    label: str
    vector: np.ndarray
    kind: str  # 'load', 'weight', 'inertia', 'reaction', 'balance' or 'rest'


_FORCE_COLOURS = {
    "load": "tab:red",
    "weight": "tab:green",
    "inertia": "tab:orange",
    "reaction": "tab:blue",
    "balance": "black",
    "rest": "0.5",
}


def _pair_label(a: str, b: str) -> str:
    return f"R{a}{b}" if len(a) == 1 and len(b) == 1 else f"R{a},{b}"


def _forces_on(
    plan: SolvePlan,
    solution: ForceSolution,
    links: set[str],
    state: KinematicState | None,
    with_balance: bool,
) -> list[_Force]:
    """The external forces on the set ``links``: loads, inertia, reactions (and balancing force).

    A reaction counts when it joins a link of the set to one outside it; what
    the outside link exerts on the set is ``force`` or ``−force`` by the
    reaction's orientation. A higher pair's contact force is carried by its
    virtual link's pairs, so its own entry is skipped; the labels name the
    real links in contact.
    """
    out: list[_Force] = []
    _add_loads(out, plan, links, state)
    _add_reactions(out, plan, solution, links)
    if with_balance:
        _add_balancing(out, plan, solution, links)
    total = sum((f.vector for f in out), np.zeros(2))
    biggest = max((length(f.vector) for f in out), default=0.0)
    if length(total) > 1e-7 * biggest:
        _add(out, "rest", "rest (friction)", -total, "rest")
    return out


def _add(out: list[_Force], key: str, label: str, vector, kind: str) -> None:
    """Append a force to ``out``, its key made unique (``key#2``, ``key#3``, ...)."""
    keys = {f.key for f in out}
    base, k = key, 1
    while key in keys:
        k += 1
        key = f"{base}#{k}"
    out.append(_Force(key, label, np.asarray(vector, dtype=float), kind))


def _add_loads(
    out: list[_Force], plan: SolvePlan, links: set[str], state: KinematicState | None
) -> None:
    """The applied forces, weights and inertia forces (at ``state``, else the sketch's pose)."""
    m = plan.mechanism
    gravity = np.zeros(2)
    for load in m.loads:
        if load.kind == "gravity":
            gravity = np.array(load.values, dtype=float)
    for load in m.loads:
        if load.link not in links:
            continue
        if load.kind == "force":
            _add(out, f"load:{load.link}:{load.point}", f"P{load.link}", load.values, "load")
        elif load.kind == "mass":
            mass = load.values[0]
            if np.any(gravity):
                _add(out, f"weight:{load.link}", f"G{load.link}", mass * gravity, "weight")
            if state is None:
                state = solve_pose(plan)
            ls = state.links.get(load.link)
            c = point_xy(m, load.point)
            if ls is None or c is None:
                continue
            theta, omega, eps = float(ls.q[2]), float(ls.qd[2]), float(ls.qdd[2])
            rc = place({load.link: np.array([0.0, 0.0, theta])}, load.link, c)
            a_s = np.asarray(ls.qdd[:2], dtype=float) + eps * np.array([-rc[1], rc[0]])
            a_s = a_s - omega**2 * rc
            _add(out, f"inertia:{load.link}", f"Φ{load.link}", -mass * a_s, "inertia")


def _add_reactions(
    out: list[_Force], plan: SolvePlan, solution: ForceSolution, links: set[str]
) -> None:
    """What the links outside ``links`` exert on it, labelled by the real links in contact."""
    contact = {v: (a, b) for v, a, b, _ in plan.contacts}

    def real(name: str, partner: str) -> str:
        if name in contact:
            a, b = contact[name]
            return b if partner == a else a
        return name

    for r in solution.reactions:
        if r.kind == "H":
            continue
        a, b = r.links
        if (a in links) == (b in links):
            continue
        if b in links:
            source, target, force = a, b, np.asarray(r.force, dtype=float)
        else:
            source, target, force = b, a, -np.asarray(r.force, dtype=float)
        label = _pair_label(real(source, target), real(target, source))
        _add(out, f"reaction:{source}->{target}:{r.point}", label, force, "reaction")


def _add_balancing(
    out: list[_Force], plan: SolvePlan, solution: ForceSolution, links: set[str]
) -> None:
    """The balancing force on ``links``: a ``balance`` load's, or along a sliding driver."""
    m = plan.mechanism
    if solution.balancing_force is not None:
        balance = next((x for x in m.loads if x.kind == "balance"), None)
        if balance is not None and balance.link in links:
            _add(out, f"balance:{balance.link}", "P_cb", solution.balancing_force, "balance")
    for d in plan.drivers:  # a sliding driver's balancing "moment" is a force along its slide
        if d.kind == "P" and d.link in links and d.link in solution.balancing_moment:
            push = solution.balancing_moment[d.link] * np.asarray(d.direction, dtype=float)
            _add(out, f"balance:{d.link}", "P_cb", push, "balance")


def _draw_forces(ax: Axes, forces: list[_Force], scale: float | None, what: str, note: str) -> None:
    """The forces head to tail from the origin, to scale, their sizes below the axes."""
    biggest = max((length(f.vector) for f in forces), default=0.0)
    shown = [f for f in forces if length(f.vector) > 1e-9 * biggest]
    if scale is None:
        scale = nice_scale(biggest / 100.0) if biggest > 0 else 1.0
    if not scale > 0:
        raise ValueError(f"scale must be positive, got {scale}")
    tail = np.zeros(2)
    corners = [tail]
    extent = biggest / scale or 1.0
    for f in shown:
        tip = tail + f.vector / scale
        c = _FORCE_COLOURS[f.kind]
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(float(tail[0]), float(tail[1])),
            arrowprops={"arrowstyle": "-|>", "color": c, "lw": 1.6, "shrinkA": 0, "shrinkB": 0},
            gid=f"force:{f.key}",
        )
        d = tip - tail
        n = np.array([-d[1], d[0]]) / (np.hypot(*d) or 1.0) * 0.04 * extent
        mid = (tail + tip) / 2 + n
        ax.text(
            float(mid[0]),
            float(mid[1]),
            f.label,
            color=c,
            fontsize=10,
            ha="center",
            va="center",
            gid=f"label:{f.key}",
        )
        tail = tip
        corners.append(tip)
    ax.plot([0.0], [0.0], "o", color="black", ms=4, gid="start")
    sizes = [f"{f.label} = {float(np.hypot(*f.vector)):.4g} N" for f in shown]
    rows = [", ".join(sizes[i : i + 3]) for i in range(0, len(sizes), 3)]
    ax.set_xlabel("\n".join(rows), fontsize=9)
    ax.xaxis.label.set_gid("table")
    pts = np.array(corners)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.12 * max(float((hi - lo).max()), extent)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.axhline(0.0, color="0.85", lw=0.6, zorder=0)
    ax.axvline(0.0, color="0.85", lw=0.6, zorder=0)
    title = f"Forces on {what}, μ_F = {scale:.6g} N/unit"
    ax.set_title(title + (f"\n{note}" if note else ""), fontsize=10)


def polygon_entries(plan: SolvePlan, solution: ForceSolution) -> list[tuple[str, set[str], str]]:
    """The panels of the force polygons: each group in solve order, then each driver.

    Returns
    -------
    list of (str, set of str, str)
        ``(label, links, note)``: ``'II(2,3)'`` or ``'I(1)'``, the links whose
        forces it sums, and a driver's balancing moment or force (else ``''``).
    """
    entries = [(s.label, set(s.links), "") for s in plan.steps if s.group is not None]
    for d in plan.drivers:
        note = ""
        if d.link in solution.balancing_moment and d.kind == "P":
            value = solution.balancing_moment[d.link]
            note = f"balancing force P_cb = {value:.6g} N along the slide"
        elif d.link in solution.balancing_moment:
            note = f"balancing moment M_cb = {solution.balancing_moment[d.link]:.6g} N·m"
        elif solution.balancing_force is not None:
            note = f"balancing force P_cb = {float(np.hypot(*solution.balancing_force)):.6g} N"
        entries.append((f"I({d.link})", {d.link}, note))
    return entries


def force_polygon(
    plan: SolvePlan,
    solution: ForceSolution,
    group_label: str | None = None,
    *,
    ax: Axes | None = None,
    scale: float | None = None,
    state: KinematicState | None = None,
) -> Figure:
    """Force polygon of each Assur group and of each driver, to scale.

    For a group: its applied loads, its inertia loads (−m·a_S, with the weight
    m·g apart) and the reactions at its outer pairs (including those of the
    groups attached to it), head to tail from the origin; they add up to
    zero, so the polygon closes. For a driver (``'I(1)'``): the same with the
    reaction of the frame and the balancing force, the balancing moment in
    the title.

    Parameters
    ----------
    plan : SolvePlan
    solution : ForceSolution
        From :func:`kinematics.kinetostatics.forces.solve_forces` at the sketch pose (or at
        the pose of ``state``).
    group_label : str, optional
        One group (``'II(2,3)'``) or driver (``'I(1)'``); all of them by default.
    ax : Axes, optional
        Draw one polygon on these axes (``group_label`` is then required
        unless there is only one).
    scale : float, optional
        μ_F in N per drawing unit; a round number by default.
    state : KinematicState, optional
        The pose of ``solution`` for inertia loads (default: the sketch pose).

    Returns
    -------
    Figure

    Raises
    ------
    ValueError
        ``group_label`` names no group or driver, or ``scale`` is not positive.

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.solvers.plan import make_plan
    >>> from kinematics.kinetostatics.forces import solve_forces
    >>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0", "point B 0.1 0",
    ...                     "force 1 B 0 -100"])
    >>> plan = make_plan(analyze(m))
    >>> ax = force_polygon(plan, solve_forces(plan), "I(1)").axes[0]
    >>> ax.get_title().splitlines()
    ['Forces on driver 1, μ_F = 1 N/unit', 'balancing moment M_cb = 10 N·m']
    """
    entries = _chosen_entries(plan, solution, group_label)
    if ax is not None and len(entries) != 1:
        raise ValueError("drawing on given axes needs one group_label")
    fig, axes = (ax.figure, [ax]) if ax is not None else _grid(len(entries))
    for (label, links, note), target in zip(entries, axes, strict=False):
        is_driver = label.startswith("I(")
        forces = _forces_on(plan, solution, links, state, with_balance=is_driver)
        what = f"driver {label[2:-1]}" if is_driver else label
        _draw_forces(target, forces, scale, what, note)
    if ax is None:
        fig.tight_layout()
    return fig


def _chosen_entries(
    plan: SolvePlan, solution: ForceSolution, group_label: str | None
) -> list[tuple[str, set[str], str]]:
    """The panel of ``group_label``, or every panel (:func:`polygon_entries`)."""
    entries = polygon_entries(plan, solution)
    if group_label is None:
        return entries
    chosen = [e for e in entries if e[0] == group_label]
    if not chosen:
        known = ", ".join(e[0] for e in entries)
        raise ValueError(f"no group or driver {group_label!r}: they are {known}")
    return chosen


def _grid(count: int) -> tuple[Figure, list[Axes]]:
    """A new figure with ``count`` axes, at most three to a row."""
    cols = min(count, 3)
    rows = math.ceil(count / cols)
    fig = Figure(figsize=(6.2 * cols, 5.0 * rows))
    FigureCanvasAgg(fig)
    axes = list(np.atleast_1d(fig.subplots(rows, cols)).ravel())
    for extra in axes[count:]:
        fig.delaxes(extra)
    return fig, axes


def draw_loads(ax: Axes, plan: SolvePlan, state: KinematicState) -> None:
    """The applied forces on the mechanism: an arrow ending at each load's point (gid ``load:``)."""
    m = plan.mechanism
    poses = state_poses(state)
    unit = drawing_unit(plan.length)  # the mechanism's drawing unit (kinematics.figures.scene)
    forces = [x for x in m.loads if x.kind == "force" and point_xy(m, x.point) is not None]
    biggest = max((length(x.values) for x in forces), default=0.0)
    if biggest <= 0:
        return
    reach = 0.25 * (plan.length or 1.0) / unit
    for load in forces:
        tip = place(poses, load.link, point_xy(m, load.point)) / unit
        tail = tip - np.asarray(load.values, dtype=float) / biggest * reach
        ax.annotate(
            "",
            xy=(float(tip[0]), float(tip[1])),
            xytext=(float(tail[0]), float(tail[1])),
            arrowprops={"arrowstyle": "-|>", "color": _FORCE_COLOURS["load"], "lw": 1.8},
            gid=f"load:{load.link}:{load.point}",
            zorder=8,
        )
        ax.text(
            float(tail[0]),
            float(tail[1]),
            f"P{load.link}",
            color=_FORCE_COLOURS["load"],
            fontsize=10,
            ha="center",
            va="bottom",
            gid=f"load:{load.link}:{load.point}",
        )
