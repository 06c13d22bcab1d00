"""The kinematic graph: links as nodes, pairs as edges, coloured by Assur group.

:func:`draw_graph` — one node per link (``Circle``, the ground a hatched
square, gid ``node:<link>``, coloured as in
:func:`kinematics.figures.mechanism.draw_mechanism`, drivers black, virtual
links dashed), one edge per pair (``FancyArrowPatch``, gid ``edge:<pair id>``,
parallel pairs bowed apart, the pairs of a replacement dashed) labelled with
its kind and point.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import networkx as nx
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch, Rectangle

from structure.model import Pair
from structure.report import StructuralReport

from .style import OTHER_COLOUR, figure_axes, palette, virtual_links

__all__ = ["draw_graph"]


def _graph_layout(graph: nx.MultiGraph, ground: str) -> dict[str, np.ndarray]:
    """Node positions (about [-1, 1]²), turned so that the ground is at the bottom."""
    simple = nx.Graph(graph)
    if simple.number_of_nodes() < 2:
        return {n: np.zeros(2) for n in simple}
    try:
        if simple.number_of_nodes() > 200:
            raise ImportError  # Kamada–Kawai is quadratic: springs for big graphs
        pos = nx.kamada_kawai_layout(simple)
    except ImportError:  # it needs scipy
        pos = nx.spring_layout(simple, seed=1)
    xy = {n: np.asarray(p, dtype=float) for n, p in pos.items()}
    centre = np.mean(list(xy.values()), axis=0)
    down = xy[ground] - centre if ground in xy else np.zeros(2)
    if np.hypot(*down) > 1e-9:
        turn = -math.pi / 2 - math.atan2(down[1], down[0])
        c, s = math.cos(turn), math.sin(turn)
        rot = np.array([[c, -s], [s, c]])
        xy = {n: rot @ (p - centre) for n, p in xy.items()}
    return xy


def draw_graph(report: StructuralReport, ax: Axes | None = None) -> Figure:
    """The kinematic graph: links as nodes, pairs as edges, coloured by Assur group.

    The nodes are coloured as in :func:`draw_mechanism` (the same legend), the
    drivers black, the ground a hatched square; each pair is an edge labelled
    with its kind and point (parallel pairs bowed apart). The virtual links of
    a higher-pair replacement and their two pairs are dashed, beside the
    higher pair they stand for.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis; no coordinates are needed.
    ax : Axes, optional
        Draw on these axes instead of a new figure.

    Returns
    -------
    Figure
    """
    fig, ax = figure_axes(ax, (6.5, 5.5))
    m = report.mechanism
    colour, handles = palette(report)
    virtual = virtual_links(report)
    drivers = set(report.drivers)
    edges = [(p, False) for p in m.pairs]
    edges += [(p, True) for r in report.replacements for p in r.new_pairs]
    graph = nx.MultiGraph()
    graph.add_nodes_from(m.links)
    graph.add_nodes_from(r.virtual_link for r in report.replacements)
    graph.add_edges_from((p.a, p.b, p.id) for p, _ in edges)
    pos = _graph_layout(graph, m.ground)
    rank = {n: i for i, n in enumerate(graph.nodes)}
    points = np.array(list(pos.values()))
    r = _node_radius(points)
    spots = [*points, *_draw_edges(ax, edges, pos, rank)]
    for n in graph.nodes:
        c = colour.get(n, OTHER_COLOUR)
        if n == m.ground:
            _draw_ground_node(ax, n, pos[n], r)
        else:
            _draw_link_node(ax, n, pos[n], r, c, virtual=n in virtual, driver=n in drivers)

    spread = np.array(spots)
    lo, hi = spread.min(axis=0) - 2 * r, spread.max(axis=0) + 2 * r
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal", adjustable="box")
    ax.set_axis_off()
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.0, 1.0), fontsize=8)
    title = f"Kinematic graph of {m.name}" if m.name else "Kinematic graph"
    ax.set_title(f"{title}\n{report.formula}", fontsize=10)
    return fig


def _node_radius(points: np.ndarray) -> float:
    """The nodes' radius: 0.085, or less where two nodes are close."""
    gaps = [
        float(np.hypot(*(points[i] - points[j])))
        for i in range(len(points))
        for j in range(i + 1, len(points))
    ]
    return min(0.085, 0.3 * min(gaps)) if gaps else 0.085


def _draw_edges(
    ax: Axes,
    edges: list[tuple[Pair, bool]],
    pos: Mapping[str, np.ndarray],
    rank: Mapping[str, int],
) -> list[np.ndarray]:
    """Each pair an edge labelled with its kind and point, parallel ones bowed apart.

    Returns the labels' places (to fit the axes).
    """
    bundles: dict[tuple[str, str], list[tuple[Pair, bool]]] = {}
    for p, dashed in edges:
        a, b = sorted((p.a, p.b), key=rank.__getitem__)
        bundles.setdefault((a, b), []).append((p, dashed))
    spots = []
    for (a, b), bundle in bundles.items():
        start, end = pos[a], pos[b]
        normal = np.array([end[1] - start[1], start[0] - end[0]])
        for i, (p, dashed) in enumerate(bundle):
            rad = 0.35 * (i - (len(bundle) - 1) / 2)
            ax.add_patch(
                FancyArrowPatch(
                    tuple(start),
                    tuple(end),
                    arrowstyle="-",
                    connectionstyle=f"arc3,rad={rad}",
                    color="0.45" if dashed else "0.15",
                    lw=1.4,
                    ls="--" if dashed else "-",
                    shrinkA=0,
                    shrinkB=0,
                    gid=f"edge:{p.id}",
                    zorder=1,
                )
            )
            mid = (start + end) / 2 + 0.5 * rad * normal
            spots.append(mid)
            ax.text(
                float(mid[0]),
                float(mid[1]),
                p.kind.value + (f" {p.point}" if p.point else ""),
                fontsize=7,
                ha="center",
                va="center",
                gid=f"edge:{p.id}",
                zorder=2,
                bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.85},
            )
    return spots


def _draw_ground_node(ax: Axes, node: str, xy: np.ndarray, r: float) -> None:
    """The ground: a hatched square, its name in black on white."""
    x, y = (float(v) for v in xy)
    ax.add_patch(
        Rectangle(
            (x - r, y - r),
            2 * r,
            2 * r,
            facecolor="white",
            edgecolor="black",
            hatch="////",
            lw=1.5,
            gid=f"node:{node}",
            zorder=3,
        )
    )
    _node_label(ax, node, x, y, "black")


def _draw_link_node(
    ax: Axes, node: str, xy: np.ndarray, r: float, c: str, *, virtual: bool, driver: bool
) -> None:
    """A link: a disc in its colour (a driver's edged thick), a virtual link a dashed ring."""
    x, y = (float(v) for v in xy)
    if virtual:
        patch = Circle(
            (x, y), r, facecolor="white", edgecolor=c, lw=1.8, ls="--", gid=f"node:{node}", zorder=3
        )
    else:
        patch = Circle(
            (x, y),
            r,
            facecolor=c,
            edgecolor="black",
            lw=2.5 if driver else 1,
            gid=f"node:{node}",
            zorder=3,
        )
    ax.add_patch(patch)
    _node_label(ax, node, x, y, c if virtual else "white")


def _node_label(ax: Axes, node: str, x: float, y: float, ink: str) -> None:
    """The node's name in ``ink`` (black ink on a white box)."""
    ax.text(
        x,
        y,
        node,
        color=ink,
        fontsize=9,
        fontweight="bold",
        ha="center",
        va="center",
        gid=f"node:{node}",
        zorder=4,
        bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none"} if ink == "black" else None,
    )
