"""Figures of a machine's dynamics: J_r(φ), M_r(φ), ω(φ), ω(t), Wittenbauer's diagram, shaking.

Each function draws on its own :class:`~matplotlib.figure.Figure` (Agg canvas)
or on axes it is given, and names its artists by gid:

* :func:`inertia_figure` — ``inertia:J``, ``inertia:dJ`` (J_r and its slope);
* :func:`moment_figure` — ``moment:total``, ``moment:drive``, ``moment:loads``;
* :func:`speed_figure` — ``omega:steady``, ``omega:max``, ``omega:min``, ``omega:mean``;
* :func:`runs_figure` — ``run:start-up``, ``run:run-down`` (ω against time);
* :func:`energy_inertia_figure` — ``wittenbauer:curve``, ``tangent:max``,
  ``tangent:min``, ``wittenbauer:origin``;
* :func:`shaking_figure` — ``shaking:before`` (and ``shaking:after``): the tip of
  the shaking force over the cycle in a polar plot;
* :func:`dynamics_sheet` — all of them; :func:`balance_sheet` — the shaking
  before and after a balance, and the driving torque.

The angles are the driver's rotation from the sketch in degrees.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

if TYPE_CHECKING:  # annotations only: drawing needs the results, not the solvers
    from ..dynamics.analysis import MachineDynamics
    from ..dynamics.balancing import Balanced
    from ..dynamics.flywheel import Flywheel
    from ..dynamics.shaking import Shaking

__all__ = [
    "balance_sheet",
    "dynamics_sheet",
    "energy_inertia_figure",
    "inertia_figure",
    "moment_figure",
    "runs_figure",
    "shaking_figure",
    "speed_figure",
]

_ANGLE = "driver angle φ from the sketch (°)"


def _axes(ax: Axes | None, polar: bool = False) -> tuple[Figure, Axes]:
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=(6.0, 4.2))
    FigureCanvasAgg(fig)
    return fig, fig.add_subplot(projection="polar" if polar else None)


def _finish(ax: Axes, title: str, ylabel: str, xlabel: str = _ANGLE) -> None:
    ax.set_title(title, fontsize=10)
    ax.set_xlabel(xlabel, fontsize=8)
    ax.set_ylabel(ylabel, fontsize=8)
    ax.grid(True, lw=0.4, alpha=0.6)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)


def inertia_figure(result: MachineDynamics, ax: Axes | None = None) -> Figure:
    """J_r(φ) (left axis) and dJ_r/dφ (right axis)."""
    fig, ax = _axes(ax)
    props = result.machine.properties
    x = np.degrees(props.phi)
    ax.plot(x, props.inertia, lw=1.6, color="C0", label="J_r", gid="inertia:J")
    slope = ax.twinx()
    slope.plot(x, props.slope, lw=1.0, ls="--", color="C1", label="dJ_r/dφ", gid="inertia:dJ")
    slope.set_ylabel("dJ_r/dφ (kg·m²/rad)", fontsize=8, color="C1")
    _finish(ax, "Reduced moment of inertia J_r(φ)", "J_r (kg·m²)")
    ax.legend(ax.get_lines() + slope.get_lines(), ["J_r", "dJ_r/dφ"], fontsize=7, loc="upper right")
    return fig


def moment_figure(result: MachineDynamics, ax: Axes | None = None) -> Figure:
    """M_r(φ) of the drive, of the loads and in all, at the running speed."""
    fig, ax = _axes(ax)
    x = np.degrees(result.machine.properties.phi)
    if result.machine.drive is not None:
        ax.plot(x, result.drive_moment, lw=1.0, color="C2", label="drive", gid="moment:drive")
    ax.plot(x, result.load_moment, lw=1.0, color="C3", label="loads", gid="moment:loads")
    ax.plot(x, result.moment, lw=1.6, color="k", label="M_r", gid="moment:total")
    ax.axhline(0, color="0.5", lw=0.6)
    _finish(ax, "Reduced moment M_r(φ, ω)", "M_r (N·m)")
    return fig


def speed_figure(result: MachineDynamics, ax: Axes | None = None) -> Figure:
    """ω(φ) of the steady running, with ω_max, ω_min and ω_m = (ω_max + ω_min)/2."""
    fig, ax = _axes(ax)
    steady = result.steady
    if steady is None:
        ax.text(0.5, 0.5, "no steady running", ha="center", va="center", transform=ax.transAxes)
        _finish(ax, "Steady running ω(φ)", "ω (rad/s)")
        return fig
    x = np.degrees(steady.phi)
    ax.plot(x, steady.omega, lw=1.6, color="C0", label="ω(φ)", gid="omega:steady")
    for value, name, style in (
        (steady.omega_max, "max", ":"),
        (steady.omega_min, "min", ":"),
        (steady.omega_mean, "mean", "--"),
    ):
        ax.axhline(value, color="0.4", lw=0.8, ls=style, gid=f"omega:{name}")
    if result.flywheel is not None and result.flywheel.steady is not None:
        wheel = result.flywheel.steady
        ax.plot(
            np.degrees(wheel.phi),
            wheel.omega,
            lw=1.2,
            color="C2",
            label=f"with the flywheel (δ = {wheel.delta:.3g})",
            gid="omega:flywheel",
        )
    _finish(
        ax,
        f"Steady running ω(φ): ω_m = {steady.omega_mean:.4g} rad/s, δ = {steady.delta:.3g}",
        "ω (rad/s)",
    )
    return fig


def runs_figure(result: MachineDynamics, ax: Axes | None = None) -> Figure:
    """ω(t) of the start-up from rest and of the run-down with the drive off."""
    fig, ax = _axes(ax)
    drawn = False
    offset = 0.0
    for run in (result.start, result.stop):
        if run is None:
            continue
        ax.plot(run.t + offset, run.omega, lw=1.2, label=run.kind, gid=f"run:{run.kind}")
        offset += float(run.t[-1])
        drawn = True
    if not drawn:
        ax.text(
            0.5, 0.5, "no start-up or run-down", ha="center", va="center", transform=ax.transAxes
        )
    _finish(ax, "Start-up from rest, then run-down", "ω (rad/s)", "time t (s)")
    return fig


def energy_inertia_figure(wheel: Flywheel, ax: Axes | None = None) -> Figure:
    """Wittenbauer's diagram: W(φ) against J_r(φ), the tangents and the true origin.

    The view is the curve's; the tangents run through it toward the true
    origin (−J_F, −E0), which is marked when it is in view and named when not.
    """
    fig, ax = _axes(ax)
    ax.plot(
        wheel.inertia,
        wheel.work,
        lw=1.6,
        color="C0",
        label="W(φ) vs J_r(φ)",
        gid="wittenbauer:curve",
    )
    j0, e0 = wheel.origin
    low, high = float(np.min(wheel.inertia)), float(np.max(wheel.inertia))
    span_j = (high - low) or max(abs(high), 1e-12)
    bottom, top = float(np.min(wheel.work)), float(np.max(wheel.work))
    span_w = (top - bottom) or max(abs(top), 1.0)
    view_j = (low - 0.4 * span_j, high + 0.4 * span_j)
    view_w = (bottom - 0.3 * span_w, top + 0.3 * span_w)
    reach = np.array([min(j0, view_j[0]), view_j[1]])
    for (slope, angle, _), name in zip(wheel.tangents, ("max", "min"), strict=True):
        ax.plot(
            reach,
            e0 + slope * (reach - j0),
            lw=0.9,
            ls="--",
            label=f"slope ω_{name}²/2 (touches at {math.degrees(angle) % 360:.0f}°)",
            gid=f"tangent:{name}",
        )
    ax.plot([j0], [e0], "ko", ms=4, gid="wittenbauer:origin")
    inside = view_j[0] <= j0 <= view_j[1] and view_w[0] <= e0 <= view_w[1]
    where = "" if inside else " (off the view)"
    ax.text(
        0.02,
        0.02,
        f"true origin (−J_F, −E0) = ({j0:.4g}, {e0:.4g}){where}; J_F = {wheel.exact:.4g} kg·m²",
        transform=ax.transAxes,
        fontsize=7,
    )
    ax.set_xlim(*view_j)
    ax.set_ylim(*view_w)
    _finish(
        ax,
        f"Energy–inertia diagram (Wittenbauer), δ = {wheel.delta_goal:g}",
        "W = ΔE (J)",
        "J_r (kg·m²)",
    )
    return fig


def shaking_figure(before: Shaking, after: Shaking | None = None, ax: Axes | None = None) -> Figure:
    """The shaking force's tip over the cycle in polar coordinates (angle, magnitude)."""
    fig, ax = _axes(ax, polar=True)
    for found, name in ((before, "before"), (after, "after")):
        if found is None:
            continue
        angle = np.arctan2(found.force[:, 1], found.force[:, 0])
        label = "shaking force" if after is None else f"{name} (max {found.force_max:.4g} N)"
        ax.plot(angle, found.magnitude, lw=1.3, label=label, gid=f"shaking:{name}")
    ax.set_title(f"Shaking force on the frame at {before.omega:.4g} rad/s (N)", fontsize=10)
    ax.legend(fontsize=7, loc="lower left")
    return fig


def dynamics_sheet(result: MachineDynamics) -> Figure:
    """J_r, M_r, ω(φ), ω(t), Wittenbauer's diagram and the shaking on one sheet."""
    fig = Figure(figsize=(16.0, 9.0))
    FigureCanvasAgg(fig)
    grid = fig.add_gridspec(2, 3)
    inertia_figure(result, fig.add_subplot(grid[0, 0]))
    moment_figure(result, fig.add_subplot(grid[0, 1]))
    speed_figure(result, fig.add_subplot(grid[0, 2]))
    runs_figure(result, fig.add_subplot(grid[1, 0]))
    wittenbauer = fig.add_subplot(grid[1, 1])
    if result.flywheel is not None:
        energy_inertia_figure(result.flywheel, wittenbauer)
    else:
        wittenbauer.text(
            0.5,
            0.5,
            "no flywheel (no steady running)",
            ha="center",
            va="center",
            transform=wittenbauer.transAxes,
        )
        wittenbauer.set_axis_off()
    if result.shaking is not None:
        shaking_figure(result.shaking, ax=fig.add_subplot(grid[1, 2], projection="polar"))
    else:
        empty = fig.add_subplot(grid[1, 2])
        empty.text(
            0.5,
            0.5,
            "no shaking forces (no running speed or no sketch)",
            ha="center",
            va="center",
            transform=empty.transAxes,
        )
        empty.set_axis_off()
    name = result.report.mechanism.name or result.report.mechanism.source
    fig.suptitle(f"Machine dynamics: {name}", fontsize=12)
    fig.tight_layout()
    return fig


def balance_sheet(result: Balanced) -> Figure:
    """The shaking force before and after (polar), and the driving torque before and after."""
    fig = Figure(figsize=(12.0, 5.0))
    FigureCanvasAgg(fig)
    shaking_figure(result.before, result.after, fig.add_subplot(1, 2, 1, projection="polar"))
    ax = fig.add_subplot(1, 2, 2)
    x = np.degrees(result.before.phi)
    ax.plot(x, result.torque_before, lw=1.3, label="before", gid="torque:before")
    ax.plot(x, result.torque_after, lw=1.3, label="after", gid="torque:after")
    _finish(ax, f"Driving torque at {result.before.omega:.4g} rad/s", "M (N·m)")
    fig.suptitle(f"Balance: {result.method}", fontsize=12)
    fig.tight_layout()
    return fig
