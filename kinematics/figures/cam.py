"""Cam figures: the SVAJ diagrams and the profile, on one sheet.

:func:`cam_sheet` draws, for a :class:`~kinematics.cams.design.CamDesign`,
the displacement, velocity, acceleration and jerk against the cam angle at the
spec's speed (one axes each, the joins where the acceleration jumps marked as
infinite jerk) beside the cam: its profile, the pitch curve, the base and
prime circles, and the follower at the program's angle 0. Every artist has a
gid (``svaj:s``, ``svaj:v``, ``svaj:a``, ``svaj:j``, ``join:<deg>``, ``profile``,
``pitch``, ``base``, ``prime``, ``follower``, ``pressure``) so that a figure
can be read back.

>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> design = make_design(cam_spec_from_dict({"base_radius": 0.04, "omega": 10,
...     "follower": {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
...     "segments": [{"law": "harmonic", "lift": 0.02, "angle": 180},
...                  {"law": "harmonic", "lift": -0.02, "angle": 180}]}))
>>> fig = cam_sheet(design, 90)
>>> sorted(x.get_gid() for ax in fig.axes for x in ax.lines if x.get_gid())[:4]
['base', 'follower', 'join:0', 'join:180']
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Polygon

from ..cams.checks import cam_angles
from ..cams.design import CamDesign
from ..cams.profile import cam_geometry
from ..cams.program import continuity, program_values

__all__ = ["cam_sheet", "profile_axes", "svaj_axes"]

_TITLES = {
    "s": ("displacement s", "{unit}"),
    "v": ("velocity v", "{unit}/s"),
    "a": ("acceleration a", "{unit}/s²"),
    "j": ("jerk j", "{unit}/s³"),
}


def svaj_axes(design: CamDesign, axes: list[Axes], samples: int = 720) -> None:
    """Draw s, v, a, j against the cam angle (degrees) on four ``axes``, joins marked."""
    program = design.program
    theta = np.linspace(0.0, 2.0 * math.pi, samples + 1)
    theta[-1] = np.nextafter(theta[-1], 0.0)  # the last segment's end, not the first's start
    s, s1, s2, s3 = program_values(program, theta)
    w = abs(design.omega)
    # a swinging follower's values in degrees, as the files give its lifts
    scale = math.degrees(1.0) if not design.translating else 1.0
    unit = "deg" if not design.translating else "m"
    values = {"s": s * scale, "v": s1 * w * scale, "a": s2 * w**2 * scale, "j": s3 * w**3 * scale}
    degrees = np.degrees(theta)
    joins = continuity(program)
    for ax, (key, value) in zip(axes, values.items(), strict=True):
        # break the line at each join so that a jump is drawn as one, not as a steep slope
        y = value.copy()
        for join in joins:
            k = int(np.searchsorted(degrees, join.at_deg))
            if 0 < k < len(y) and any(order <= "svaj".index(key) for order, *_ in join.jumps):
                y[k - 1] = np.nan
        ax.plot(degrees, y, color="tab:blue", lw=1.2, gid=f"svaj:{key}")
        title, units = _TITLES[key]
        ax.set_ylabel(f"{title} ({units.format(unit=unit)})")
        ax.axhline(0.0, color="0.7", lw=0.6)
        ax.set_xlim(0.0, 360.0)
        ax.grid(True, lw=0.3, alpha=0.6)
        for join in joins:
            infinite = join.infinite_jerk and key == "j"
            ax.axvline(
                join.at_deg,
                color="tab:red" if infinite else "0.6",
                lw=1.0 if infinite else 0.5,
                ls="-" if infinite else ":",
                gid=f"join:{join.at_deg:g}" if key == "s" else None,
            )
            if infinite:
                ax.annotate(
                    "∞",
                    (join.at_deg, 0.0),
                    color="tab:red",
                    ha="center",
                    va="bottom",
                    fontsize=11,
                )
    axes[-1].set_xlabel("cam angle θ (°)")
    axes[0].set_title(f"SVAJ at ω = {design.omega:g} rad/s (∞: the acceleration jumps)")


def profile_axes(design: CamDesign, ax: Axes, samples: int = 720) -> None:
    """Draw the cam at the program's angle 0: profile, pitch curve, circles, the follower."""
    g = cam_geometry(design, cam_angles(samples))
    layout = design.layout
    ax.add_patch(
        Polygon(g.profile, closed=True, facecolor="0.88", edgecolor="black", lw=1.4, gid="profile")
    )
    if g.pitch is not None:
        closed = np.vstack([g.pitch, g.pitch[:1]])
        ax.plot(*closed.T, color="tab:blue", lw=0.8, ls="--", gid="pitch", label="pitch curve")
    for name, radius in (("base", layout.base_radius), ("prime", layout.prime)):
        if name == "prime" and radius == layout.base_radius:
            continue
        t = np.linspace(0.0, 2.0 * math.pi, 241)
        ax.plot(radius * np.cos(t), radius * np.sin(t), color="0.5", lw=0.6, ls=":", gid=name,
                label=f"{name} circle")  # fmt: skip
    ax.plot([0.0], [0.0], "k+", ms=10)
    _follower(design, ax)
    ax.set_aspect("equal")
    ax.set_title(f"profile at θ = 0 (cam turns {'ccw' if layout.sense > 0 else 'cw'})")
    ax.legend(loc="lower left", fontsize=7, frameon=False)
    ax.autoscale_view()


def _follower(design: CamDesign, ax: Axes) -> None:
    """The follower at the program's angle 0: roller, knife edge or face, and its stem."""
    layout = design.layout
    g = cam_geometry(design, np.array([0.0]))
    point, contact, normal = g.point[0], g.contact[0], g.normal[0]
    size = layout.prime
    colour = "tab:orange"
    if layout.flat:
        along = np.array([-normal[1], normal[0]])
        half = 0.6 * size
        face = np.array([contact - half * along, contact + half * along])
        ax.plot(*face.T, color=colour, lw=2.5, gid="follower")
        stem_from = contact
    else:
        if layout.roller_radius:
            ax.add_patch(Circle(point, layout.roller_radius, fill=False, color=colour, lw=1.5))
        ax.plot(*np.array([point, contact]).T, color=colour, lw=1.0, gid="follower")
        stem_from = point
    if design.translating:
        top = stem_from + np.array([0.0, 0.8 * size])
        ax.plot(*np.array([stem_from, top]).T, color=colour, lw=2.0)
    else:
        pivot = np.asarray(layout.pivot)
        ax.plot(*np.array([stem_from, pivot]).T, color=colour, lw=2.0)
        ax.plot(*pivot, "o", color=colour, ms=5)
    ax.annotate(
        f"φ = {math.degrees(g.pressure[0]):.1f}°",
        contact,
        xytext=(6, -12),
        textcoords="offset points",
        fontsize=8,
        gid="pressure",
    )


def cam_sheet(design: CamDesign, samples: int = 720) -> Figure:
    """The SVAJ diagrams (left) beside the profile (right), on one Agg figure."""
    fig = Figure(figsize=(13.0, 7.5))
    FigureCanvasAgg(fig)
    grid = fig.add_gridspec(4, 2, width_ratios=(1.25, 1.0), hspace=0.12, wspace=0.18)
    svaj = [fig.add_subplot(grid[k, 0]) for k in range(4)]
    for ax in svaj[1:]:
        ax.sharex(svaj[0])
    for ax in svaj[:-1]:
        ax.tick_params(labelbottom=False)
    svaj_axes(design, svaj, samples)
    profile_axes(design, fig.add_subplot(grid[:, 1]), samples)
    if design.spec.name:
        fig.suptitle(design.spec.name)
    return fig
