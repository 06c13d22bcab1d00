"""Sweep plots: the points' paths, ω, ε, speed, acceleration, μ and balancing against the input.

:func:`sweep_figure` — point paths and ω, ε, \\|v\\|, \\|a\\|, transmission
angle and balancing moment against the input, each a ``Line2D`` with gid
``path:<point>``, ``omega:<link>``, ``epsilon:<link>``, ``speed:<point>``,
``accel:<point>``, ``transmission:<group>``, ``balancing:<name>``. A quantity far
from 1 in its SI unit (a mechanism 1e-302 m across) is drawn in a power of 1000 of
that unit, named on its axis (``|v| (10⁻³⁰³ m/s)``), as matplotlib cannot draw it
in SI units.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ..solvers.plan import SolvePlan
from ..solvers.sweep import Sweep
from .style import drawing_unit, unit_text

__all__ = ["sweep_figure"]


def _unit_of(*arrays: np.ndarray) -> float:
    """The unit the values of ``arrays`` are drawn in (:func:`~.style.drawing_unit`)."""
    finite = [np.abs(a[np.isfinite(a)]) for a in arrays]
    biggest = max((float(a.max()) for a in finite if a.size), default=0.0)
    return drawing_unit(biggest)


def _input_axis(result: Sweep, plan: SolvePlan | None) -> tuple[np.ndarray, str]:
    """The first input in degrees (a rotation) or metres (a slide), and its axis label."""
    x = np.asarray(result.inputs[:, 0], dtype=float)
    name = plan.drivers[0].link if plan is not None and plan.drivers else "1"
    if plan is not None and plan.drivers and plan.drivers[0].kind == "P":
        unit = _unit_of(x)
        return x / unit, f"driver {name}: displacement from the sketch ({unit_text(unit)})"
    return np.degrees(x), f"driver {name}: rotation from the sketch (°)"


def sweep_figure(result: Sweep, plan: SolvePlan | None = None) -> Figure:
    """The sweep's curves against the input: paths, ω, ε, \\|v\\|, \\|a\\|, μ, balancing.

    Panels: the points' paths in the plane (coupler curves; the fixed points
    as dots), each link's ω and ε, each moving point's speed and acceleration
    magnitude, each dyad's transmission angle (degrees) and, when the file has
    loads, the balancing moment (or force), all against the first input in
    degrees (metres for a sliding driver, when ``plan`` says so).

    Parameters
    ----------
    result : Sweep
        From :func:`kinematics.solvers.sweep.sweep`.
    plan : SolvePlan, optional
        Names the driver and tells a rotation from a slide.

    Returns
    -------
    Figure

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.solvers.plan import make_plan
    >>> from kinematics.solvers.sweep import sweep
    >>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
    ...                     "point A 0 0", "point B 0.1 0", "point C 0.3 0.3", "point D 0.4 0"])
    >>> fig = sweep_figure(sweep(make_plan(analyze(m)), steps=12))
    >>> sorted(ln.get_gid() for ln in fig.axes[1].lines)
    ['omega:1', 'omega:2', 'omega:3']
    """
    x, xlabel = _input_axis(result, plan)
    panels = 7 if result.balancing else 6
    cols = 4 if result.balancing else 3
    fig = Figure(figsize=(4.6 * cols, 8.0))
    FigureCanvasAgg(fig)
    axes = list(fig.subplots(2, cols).ravel())
    for extra in axes[panels:]:
        fig.delaxes(extra)
    paths, omega, epsilon, speed, accel, trans = axes[:6]
    moving = _draw_paths(paths, result)
    _draw_link_rates(omega, epsilon, x, result)
    _draw_point_rates(speed, accel, x, result, moving)
    _draw_transmission(trans, x, result)
    chosen = [omega, epsilon, speed, accel, trans]
    if result.balancing:
        _draw_balancing(axes[6], x, result)
        chosen.append(axes[6])
    for ax in chosen:
        ax.set_xlabel(xlabel, fontsize=8)
        ax.grid(True, lw=0.4, alpha=0.6)
        if ax.lines:
            ax.legend(fontsize=7, ncol=2 if len(ax.lines) > 6 else 1)
    if paths.lines and moving:
        paths.legend(fontsize=7, ncol=2 if len(moving) > 6 else 1)
    fig.tight_layout()
    return fig


def _draw_paths(ax: Axes, result: Sweep) -> list[str]:
    """Each moving point's path in the plane, each fixed point a triangle; the moving points."""
    positions = {n: np.asarray(v["position"], dtype=float) for n, v in result.points.items()}
    reach = np.array([p for v in positions.values() for p in v]) if positions else np.zeros((1, 2))
    unit = _unit_of(reach)
    positions = {n: p / unit for n, p in positions.items()}
    size = float(np.ptp(reach / unit, axis=0).max()) or 1.0
    moving = [n for n, p in positions.items() if float(np.ptp(p, axis=0).max()) > 1e-9 * size]
    for name in moving:
        p = positions[name]
        ax.plot(p[:, 0], p[:, 1], lw=1.3, label=name, gid=f"path:{name}")
    for name, p in positions.items():
        if name not in moving:
            ax.plot(p[:1, 0], p[:1, 1], "k^", ms=5, gid=f"fixed:{name}")
            ax.annotate(name, (float(p[0, 0]), float(p[0, 1])), fontsize=7)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title("Paths of the points (coupler curves)", fontsize=10)
    ax.set_xlabel(f"x ({unit_text(unit)})")
    ax.set_ylabel(f"y ({unit_text(unit)})")
    return moving


def _draw_link_rates(omega: Axes, epsilon: Axes, x: np.ndarray, result: Sweep) -> None:
    """Each link's ω and ε against the input."""
    links = result.links.values()
    w_unit = _unit_of(*(np.asarray(v["omega"], dtype=float) for v in links))
    e_unit = _unit_of(*(np.asarray(v["epsilon"], dtype=float) for v in links))
    for name, values in result.links.items():
        w, e = np.asarray(values["omega"], dtype=float), np.asarray(values["epsilon"], dtype=float)
        omega.plot(x, w / w_unit, lw=1.3, label=name, gid=f"omega:{name}")
        epsilon.plot(x, e / e_unit, lw=1.3, label=name, gid=f"epsilon:{name}")
    omega.set_title("Angular velocity ω", fontsize=10)
    omega.set_ylabel(f"ω ({unit_text(w_unit, 'rad/s')})")
    epsilon.set_title("Angular acceleration ε", fontsize=10)
    epsilon.set_ylabel(f"ε ({unit_text(e_unit, 'rad/s²')})")


def _draw_point_rates(
    speed: Axes, accel: Axes, x: np.ndarray, result: Sweep, moving: list[str]
) -> None:
    """Each moving point's \\|v\\| and \\|a\\| against the input."""
    sizes = {}
    for name in moving:
        v = np.asarray(result.points[name]["velocity"], dtype=float)
        a = np.asarray(result.points[name]["acceleration"], dtype=float)
        sizes[name] = (np.hypot(v[:, 0], v[:, 1]), np.hypot(a[:, 0], a[:, 1]))
    v_unit = _unit_of(*(v for v, _ in sizes.values()))
    a_unit = _unit_of(*(a for _, a in sizes.values()))
    for name, (v, a) in sizes.items():
        speed.plot(x, v / v_unit, lw=1.3, label=name, gid=f"speed:{name}")
        accel.plot(x, a / a_unit, lw=1.3, label=name, gid=f"accel:{name}")
    speed.set_title("Speed |v| of the points", fontsize=10)
    speed.set_ylabel(f"|v| ({unit_text(v_unit, 'm/s')})")
    accel.set_title("Acceleration |a| of the points", fontsize=10)
    accel.set_ylabel(f"|a| ({unit_text(a_unit, 'm/s²')})")


def _draw_transmission(ax: Axes, x: np.ndarray, result: Sweep) -> None:
    """Each dyad's transmission angle (degrees), or a note that there is none."""
    for label, mu in result.transmission.items():
        ax.plot(x, np.degrees(mu), lw=1.3, label=label, gid=f"transmission:{label}")
    if not result.transmission:
        ax.text(
            0.5,
            0.5,
            "no dyad with a transmission angle",
            ha="center",
            va="center",
            transform=ax.transAxes,
            fontsize=9,
        )
    ax.set_title("Transmission angle μ", fontsize=10)
    ax.set_ylabel("μ (°)")


def _draw_balancing(ax: Axes, x: np.ndarray, result: Sweep) -> None:
    """The balancing moment (or force) of each driver against the input."""
    unit = _unit_of(*(np.asarray(v, dtype=float) for v in result.balancing.values()))
    for name, values in result.balancing.items():
        ax.plot(x, np.asarray(values, dtype=float) / unit, lw=1.3, label=name,
                gid=f"balancing:{name}")  # fmt: skip
    ax.set_title("Balancing moment (force)", fontsize=10)
    scale = "" if unit == 1.0 else f"{unit_text(unit, '')}"
    ax.set_ylabel(f"M_cb ({scale}N·m) or P_cb ({scale}N)")
