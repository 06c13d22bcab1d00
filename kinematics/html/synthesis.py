"""The report's synthesis section: a design's targets over the path of its marker P.

A mechanism written by ``assur synthesize`` keeps its targets (``target``
lines) and its coupler point as the marker ``P``; this section draws them
(:func:`kinematics.figures.synthesis.target_figure`) and lists each target
with the distance from ``P`` at its input (timed targets), or from the path
of ``P`` (untimed), as the solvers place it. A file without targets gets its
one-line note.
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from structure.errors import MechanismError

from ..figures.synthesis import coupler_curve, target_figure
from ..synthesis.defects import points_at
from .contents import ReportContents
from .markup import element, format_number, note, table
from .phrases import say
from .svg import figure_svg

__all__ = ["synthesis_html"]


def _distances(contents: ReportContents) -> list[float | None]:
    """Each target's distance from P (at its input, or from P's path), or None."""
    m = contents.mechanism
    inputs, curve = coupler_curve(m)
    out: list[float | None] = []
    timed = [t for t in m.targets if t.input_deg is not None]
    reached = None
    if timed:
        crank = len(inputs) > 0 and inputs[-1] - inputs[0] >= 2 * math.pi - 1e-9
        try:
            reached = points_at(m, np.radians([t.input_deg for t in timed]), crank)
        except MechanismError:
            reached = None
    k = 0
    for t in m.targets:
        if t.input_deg is not None:
            out.append(None if reached is None else float(np.hypot(*(reached[k] - (t.x, t.y)))))
            k += 1
        elif len(curve):
            out.append(float(np.min(np.hypot(curve[:, 0] - t.x, curve[:, 1] - t.y))))
        else:
            out.append(None)
    return out


def synthesis_html(contents: ReportContents, lang: str) -> str:
    """The section's body: the figure and the table of targets, or the note why there is none."""
    m = contents.mechanism
    if not m.targets:
        return note(say(lang, "no_targets"), "no_targets")
    if "P" not in m.points or contents.plan is None:
        return note(say(lang, "unsolved", reason="the file has no marker P or no coordinates"))
    try:
        svg = figure_svg(target_figure(m), "fig-targets", say(lang, "h_targets"))
        distances = _distances(contents)
    except MechanismError as exc:
        return note(say(lang, "unsolved", reason=str(exc)), "unsolved")
    rows = []
    for t, gap in zip(m.targets, distances, strict=True):
        rows.append(
            [
                escape(t.name),
                format_number(t.x),
                format_number(t.y),
                "" if t.input_deg is None else format_number(t.input_deg),
                "" if t.angle_deg is None else format_number(t.angle_deg),
                "—" if gap is None else format_number(gap),
            ]
        )
    headings = ["target", "x", "y", "input (°)", "angle (°)", say(lang, "target_distance")]
    return (
        element("h3", escape(say(lang, "h_targets")))
        + element("figure", svg)
        + table(headings, rows)
    )
