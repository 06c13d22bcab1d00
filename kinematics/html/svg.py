"""A matplotlib figure as an inline ``<svg>`` element: no XML prologue, ids unique in the page.

:func:`figure_svg` saves a figure to SVG in memory and makes it fit to sit
inside an HTML page beside others: the XML declaration, the DOCTYPE, the
metadata and the figure's own global ``<style>`` are dropped (the page's
stylesheet has the rule), every ``id`` gets the figure's prefix (and a count
where matplotlib repeats a gid) and every reference to one (``url(#…)``,
``xlink:href="#…"``) follows, so that two figures never share an id. The
``<svg>`` scales to the width of its column, at most its natural size.

>>> from matplotlib.figure import Figure
>>> fig = Figure(figsize=(2, 1)); ax = fig.add_subplot(); _ = ax.plot([0, 1], gid="line")
>>> svg = figure_svg(fig, "demo", "a line")
>>> svg.startswith('<svg class="figure" id="demo"'), 'id="demo-line"' in svg, "<?xml" in svg
(True, True, False)
"""

from __future__ import annotations

import io
import re
from html import escape

from matplotlib import rc_context
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

__all__ = ["figure_svg"]

_ID = re.compile(r'\bid="([^"]*)"')
_REFERENCE = re.compile(r'(url\(#|href="#)([^)"]*)')
_SIZE = re.compile(r'<svg\b([^>]*?) width="([\d.]+)pt" height="([\d.]+)pt"')
#: what matplotlib writes before and around the drawing that a page does not want
_DROPPED = (
    re.compile(r"\A.*?(?=<svg\b)", re.S),  # the XML declaration and the DOCTYPE
    re.compile(r"\s*<metadata>.*?</metadata>", re.S),
    re.compile(r'\s*<style type="text/css">.*?</style>', re.S),
)


def _unique_ids(svg: str, prefix: str) -> str:
    """Every id prefixed; a repeated id (matplotlib repeats gids) counted; references follow."""
    first: dict[str, str] = {}
    seen: dict[str, int] = {}

    def rename(match: re.Match[str]) -> str:
        old = match.group(1)
        seen[old] = seen.get(old, 0) + 1
        new = f"{prefix}-{old}" if seen[old] == 1 else f"{prefix}-{old}-{seen[old]}"
        first.setdefault(old, new)
        return f'id="{new}"'

    svg = _ID.sub(rename, svg)
    return _REFERENCE.sub(
        lambda m: m.group(1) + first.get(m.group(2), f"{prefix}-{m.group(2)}"), svg
    )


def figure_svg(fig: Figure, prefix: str, label: str, tight: bool = True) -> str:
    """The figure as an ``<svg>`` element to inline in an HTML page.

    Parameters
    ----------
    fig : Figure
        A matplotlib figure (any canvas; an Agg canvas is attached when it has none).
    prefix : str
        Unique in the page: the ``id`` of the ``<svg>`` and the prefix of every id inside.
    label : str
        What the figure shows, for readers that cannot see it (``aria-label``).
    tight : bool
        Crop to what is drawn (matplotlib's ``bbox_inches="tight"``, which draws the figure
        twice); ``False`` for a figure whose artists all lie inside it, to save that time.

    Returns
    -------
    str
        ``<svg class="figure" id="prefix" role="img" aria-label="…" …>…</svg>``, well-formed
        XML, as wide as its column up to its natural width, with the same output for the
        same figure (no date, fixed hash salt).
    """
    if fig.canvas is None or not hasattr(fig.canvas, "print_figure"):
        FigureCanvasAgg(fig)
    buffer = io.StringIO()
    with rc_context({"svg.hashsalt": prefix, "svg.fonttype": "path"}):
        fig.savefig(
            buffer, format="svg", bbox_inches="tight" if tight else None, metadata={"Date": None}
        )
    svg = buffer.getvalue()
    for pattern in _DROPPED:
        svg = pattern.sub("", svg, count=1)
    svg = _unique_ids(svg, prefix)
    svg = _SIZE.sub(
        lambda m: (
            f'<svg class="figure" id="{escape(prefix)}" role="img" aria-label="{escape(label)}"'
            f'{m.group(1)} width="100%" style="max-width: {float(m.group(2)):.1f}pt"'
        ),
        svg,
        count=1,
    )
    return svg.strip()
