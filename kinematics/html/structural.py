"""The report's first two sections: the mechanism drawn with its graph, and its structure.

:func:`mechanism_html` draws the mechanism at the sketch pose (its Assur
groups coloured and named in the legend, its loads) and its kinematic
graph; :func:`structure_html` writes the counts, W with the numbers put in,
the redundant constraints and passive freedoms with their origin, the
higher pairs replaced, the groups in solve order and the structural
formula, every number from :func:`structure.report.report_to_dict` (the
JSON of ``assur classify``).
"""

from __future__ import annotations

from collections.abc import Mapping
from html import escape
from typing import Any

from matplotlib.colors import to_hex

from structure.explain.mathml import latex_to_mathml

from ..figures import draw_graph, draw_mechanism
from ..figures.forces import draw_loads
from ..figures.style import palette
from .contents import ReportContents, part_note
from .markup import element, table
from .phrases import say
from .svg import figure_svg

__all__ = ["mechanism_html", "structure_html", "w_latex"]


def mechanism_html(contents: ReportContents, lang: str) -> str:
    """The mechanism at the sketch pose (or the note why not) and its kinematic graph."""
    parts = [element("h3", escape(say(lang, "h_drawing")))]
    if contents.state is None or contents.plan is None:
        parts.append(part_note(contents, "pose", lang))
    else:
        fig = draw_mechanism(contents.report, contents.plan, contents.state)
        if contents.mechanism.loads:
            draw_loads(fig.axes[0], contents.plan, contents.state)
        svg = figure_svg(fig, "fig-mechanism", say(lang, "h_drawing"), tight=False)
        parts.append(element("figure", svg))
    caption = say(lang, "h_graph")
    parts.append(element("h3", escape(caption)))
    parts.append(element("figure", figure_svg(draw_graph(contents.report), "fig-graph", caption)))
    return "".join(parts)


def w_latex(data: Mapping[str, Any]) -> str:
    r"""``W = 3n − (2P5 + P4) + r − W_th`` with the numbers of ``report_to_dict`` put in.

    >>> w_latex({"n": 3, "P5": 4, "P4": 0, "redundant": 0, "passive": 0, "W": 1})
    'W = 3n - (2P_{5} + P_{4}) + r_{th} - W_{th} = 3\\cdot 3 - (2\\cdot 4 + 0) + 0 - 0 = 1'
    """
    return (
        r"W = 3n - (2P_{5} + P_{4}) + r_{th} - W_{th} = "
        rf"3\cdot {data['n']} - (2\cdot {data['P5']} + {data['P4']}) + "
        rf"{data['redundant']} - {data['passive']} = {data['W']}"
    )


def _tied(value: object, path: str, tag: str = "td") -> str:
    """A value from the classify JSON, tied to its path."""
    return element(
        tag, escape(str(value)), data_source="classify", data_path=path, data_value=str(value)
    )


def _counts(contents: ReportContents, lang: str) -> str:
    """The counts table (as given, and after replacement when higher pairs were replaced).

    The counts after replacement are the classify JSON's ``replaced`` (n, P5, P4, W); its
    r_th and W_th, which the JSON leaves out, come from the same analysis.
    """
    data = contents.structure
    replaced = contents.report.replaced_mobility if data["replacements"] else None
    headings = [say(lang, "quantity"), say(lang, "meaning"), say(lang, "given")]
    if replaced is not None:
        headings.append(say(lang, "after_replacement"))
    rows = []
    for symbol, key, meaning in (
        ("n", "n", "q_n"),
        ("P5", "P5", "q_p5"),
        ("P4", "P4", "q_p4"),
        ("r_th", "redundant", "q_r"),
        ("W_th", "passive", "q_w_th"),
        ("W", "W", "q_w"),
    ):
        row = [escape(symbol), escape(say(lang, meaning)), _tied(data[key], key)]
        if replaced is not None and key in data["replaced"]:
            row.append(_tied(data["replaced"][key], f"replaced/{key}"))
        elif replaced is not None:
            row.append(str(replaced.r if key == "redundant" else replaced.W_passive))
        rows.append(row)
    formula = element("div", latex_to_mathml(w_latex(data), display=True), class_="formula")
    return table(headings, rows) + formula


def _redundant(data: Mapping[str, Any], lang: str) -> str:
    """The redundant constraints and the passive freedoms, each with its origin."""
    parts = [element("h4", escape(say(lang, "h_redundant")))]
    rows = [
        [
            escape(x["pair"]),
            str(x["line"] or ""),
            str(x["constraints"]),
            escape(say(lang, x["source"])),
        ]
        for x in data["redundant_pairs"]
    ]
    headings = [say(lang, "pair"), say(lang, "line"), say(lang, "constraints"), say(lang, "origin")]
    parts.append(table(headings, rows) if rows else element("p", escape(say(lang, "none"))))
    parts.append(element("h4", escape(say(lang, "h_passive"))))
    rows = [
        [escape(x["link"]), str(x["dof"]), escape(say(lang, x["source"]))]
        for x in data["passive_links"]
    ]
    headings = [say(lang, "link"), say(lang, "freedoms"), say(lang, "origin")]
    parts.append(table(headings, rows) if rows else element("p", escape(say(lang, "none"))))
    return "".join(parts)


def _replacements(data: Mapping[str, Any], lang: str) -> str:
    """The higher pairs replaced: virtual link, scheme, new pairs, roller removed."""
    rows = [
        [
            escape(x["pair"]),
            escape(x["virtual_link"]),
            escape(x["scheme"]),
            escape(", ".join(x["new_pairs"])),
            escape(x["roller"] or "—"),
        ]
        for x in data["replacements"]
    ]
    if not rows:
        return element("p", escape(say(lang, "none")))
    headings = ["higher_pair", "virtual_link", "scheme", "new_pairs", "roller_removed"]
    return table([say(lang, h) for h in headings], rows)


def _groups(contents: ReportContents, lang: str) -> str:
    """The groups in solve order, each with its colour (as in the figures), class, order, kind."""
    colour, _ = palette(contents.report)
    rows = []
    for k, (group, data) in enumerate(
        zip(contents.report.groups, contents.structure["groups"], strict=True)
    ):
        swatch = element(
            "span", "", class_="swatch", style=f"background: {to_hex(colour[group.links[0]])}"
        )
        path = f"groups/{k}"
        rows.append(
            [
                str(k + 1),
                swatch + escape(group.label),
                escape(", ".join(data["links"])),
                _tied(data["class"], f"{path}/class"),
                _tied(data["order"], f"{path}/order"),
                escape(data["kind"] or "—"),
                escape(", ".join(data["attached_to"])),
            ]
        )
    if not rows:
        return element("p", escape(say(lang, "none")))
    keys = ["group", "links", "class", "order", "kind", "attached_to"]
    return table(["#", *(say(lang, h) for h in keys)], rows)


def structure_html(contents: ReportContents, lang: str) -> str:
    """The structural analysis: counts and W, corrections, replacements, groups, formula."""
    data = contents.structure
    parts = [element("h3", escape(say(lang, "h_counts"))), _counts(contents, lang)]
    parts.append(_redundant(data, lang))
    parts.append(element("h3", escape(say(lang, "h_replaced"))))
    parts.append(_replacements(data, lang))
    parts.append(element("h3", escape(say(lang, "h_groups"))))
    if data["drivers_chosen"]:
        parts.append(element("p", escape(say(lang, "drivers_chosen"))))
    if data["set_aside"]["links"]:
        links = ", ".join(data["set_aside"]["links"])
        parts.append(element("p", escape(say(lang, "set_aside", links=links))))
    parts.append(_groups(contents, lang))
    parts.append(element("h3", escape(say(lang, "h_formula"))))
    lines = [
        say(lang, "formula_groups", formula=data["formula"]),
        say(lang, "formula_textbook", formula=data["textbook_formula"]),
        say(lang, "mechanism_class", cls=data["mechanism_class"]),
    ]
    keys = ("formula", "textbook_formula", "mechanism_class")
    for line, key in zip(lines, keys, strict=True):
        parts.append(
            element(
                "p",
                escape(line),
                data_source="classify",
                data_path=key,
                data_value=str(data[key]),
            )
        )
    return "".join(parts)
