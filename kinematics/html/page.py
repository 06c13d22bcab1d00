"""The report page: one self-contained HTML document, its stylesheet and script inline.

:func:`report_page` puts together the sections of a
:class:`~kinematics.html.contents.ReportContents` — the mechanism and its
graph, the structural analysis, the kinematics and forces at the pose, the
whole cycle, the gear train and the worked solution — with the stylesheet
(``report.css``, a print stylesheet for A4 included) and the animation's
script (``report.js``) inline: the file needs no network and opens from
disk. A section that does not apply says so in one line. The document is
well-formed XML as well as HTML5.
"""

from __future__ import annotations

from collections.abc import Callable
from html import escape
from importlib.resources import files

from structure.errors import MechanismError
from structure.explain import LANGUAGES, explain_structure

from ..explain import explain_forces, explain_kinematics
from ..figures import sweep_figure
from .animation import animation_html
from .camdesign import cams_html
from .contents import ReportContents, part_note
from .cycle import stretch_text
from .dynamics import dynamics_html
from .gearing import gears_html
from .markup import element, note
from .phrases import say
from .pose import forces_html, kinematics_html
from .structural import mechanism_html, structure_html
from .svg import figure_svg
from .synthesis import synthesis_html

__all__ = ["SECTIONS", "report_page"]


def _cycle_html(contents: ReportContents, lang: str) -> str:
    """The animation over the cycle and the plots over it (or the note why there is none)."""
    cycle, plan = contents.cycle, contents.plan
    if cycle is None or plan is None:
        return part_note(contents, "cycle", lang)
    parts = [element("h3", escape(say(lang, "h_animation")))]
    count = len(cycle.sweep.inputs)
    parts.append(element("p", escape(say(lang, "animation_help", count=count))))
    animation = animation_html(contents.report, plan, cycle, lang)
    if not cycle.complete:
        parts.append(note(stretch_text(plan, cycle, lang), "partial"))
    parts.append(animation)
    caption = say(lang, "h_plots")
    parts.append(element("h3", escape(caption)))
    svg = figure_svg(sweep_figure(cycle.sweep, plan), "fig-cycle", caption, tight=False)
    parts.append(element("figure", svg))
    return "".join(parts)


def _demoted(fragment: str) -> str:
    """A worked solution's headings two levels down, under the page's own."""
    for level in (4, 3, 2):
        fragment = fragment.replace(f"<h{level}>", f"<h{level + 2}>")
        fragment = fragment.replace(f"</h{level}>", f"</h{level + 2}>")
    return fragment


def _worked_html(contents: ReportContents, lang: str) -> str:
    """The worked solutions: structure, then velocities and accelerations, then forces."""
    report, plan = contents.report, contents.plan
    parts = [element("h3", escape(say(lang, "h_worked_structure")))]
    parts.append(_demoted(explain_structure(report, lang, "html")))
    parts.append(element("h3", escape(say(lang, "h_worked_kinematics"))))
    if plan is None or contents.state is None:
        parts.append(part_note(contents, "pose", lang))
    else:
        parts.append(
            _explained(lambda: explain_kinematics(report, plan, contents.state, lang, "html"), lang)
        )
    parts.append(element("h3", escape(say(lang, "h_worked_forces"))))
    if plan is None or contents.forces is None:
        parts.append(part_note(contents, "forces", lang))
    else:
        parts.append(
            _explained(lambda: explain_forces(report, plan, contents.forces, lang, "html"), lang)
        )
    return "".join(parts)


def _explained(explain: Callable[[], str], lang: str) -> str:
    """A worked solution's fragment, demoted; a mechanism error becomes its note."""
    try:
        return _demoted(explain())
    except MechanismError as exc:
        return note(say(lang, "unsolved", reason=str(exc)), "unsolved")


def _gears_section(contents: ReportContents, lang: str) -> str:
    """The gear train, or the note: no gears, or the error."""
    if contents.train is None:
        return part_note(contents, "gears", lang)
    return gears_html(contents.train, contents.mechanism, lang)


#: the page's sections in order: id, title phrase, the function that writes the body
SECTIONS: tuple[tuple[str, str, Callable[[ReportContents, str], str]], ...] = (
    ("mechanism", "s_mechanism", mechanism_html),
    ("structure", "s_structure", structure_html),
    ("kinematics", "s_kinematics", kinematics_html),
    ("forces", "s_forces", forces_html),
    ("cycle", "s_cycle", _cycle_html),
    ("gears", "s_gears", _gears_section),
    ("cams", "s_cams", cams_html),
    ("dynamics", "s_dynamics", dynamics_html),
    ("synthesis", "s_synthesis", synthesis_html),
    ("worked", "s_worked", _worked_html),
)


def _asset(name: str) -> str:
    """A file shipped beside this module (the stylesheet, the script)."""
    return files(__package__).joinpath(name).read_text(encoding="utf-8")


def report_page(contents: ReportContents, lang: str = "en") -> str:
    """The whole report as one HTML document.

    Parameters
    ----------
    contents : ReportContents
        From :func:`kinematics.html.contents.gather`.
    lang : {"en", "vi"}
        The language of the titles, notes and worked solutions.

    Returns
    -------
    str
        ``<!DOCTYPE html>`` and one ``<html>`` element: no external resource, every
        figure an inline SVG, every formula MathML; one ``<section class="part">``
        per entry of :data:`SECTIONS`, with that ``id``.

    Raises
    ------
    ValueError
        An unknown ``lang``.
    """
    if lang not in LANGUAGES:
        raise ValueError(f"unknown language {lang!r}: use one of {', '.join(LANGUAGES)}")
    m = contents.mechanism
    name = m.name or m.source
    title = say(lang, "page_title", name=name)
    toc = "".join(
        element("li", element("a", escape(say(lang, key)), href=f"#{sid}"))
        for sid, key, _ in SECTIONS
    )
    nav = element(
        "nav", element("h2", escape(say(lang, "contents"))) + element("ul", toc), class_="contents"
    )
    header = element(
        "header",
        element("h1", escape(title)) + element("p", escape(say(lang, "made_by", source=m.source))),
    )
    body = [header, nav]
    for sid, key, write in SECTIONS:
        body.append(
            element(
                "section",
                element("h2", escape(say(lang, key))) + write(contents, lang),
                id=sid,
                class_="part",
            )
        )
    script = f"<script>//<![CDATA[\n{_asset('report.js')}//]]>\n</script>"
    head = (
        '<meta charset="utf-8"/>'
        '<meta name="viewport" content="width=device-width, initial-scale=1"/>'
        '<meta name="generator" content="assur report"/>'
        + element("title", escape(title))
        + element("style", "\n" + _asset("report.css"))
    )
    return (
        "<!DOCTYPE html>\n"
        + f'<html lang="{lang}">'
        + element("head", head)
        + element("body", "\n".join(body) + script)
        + "</html>\n"
    )
