"""Worked solutions: the structural analysis written out step by step, as the textbook does.

:func:`explain_structure` turns a :class:`~structure.report.StructuralReport`
into the steps of a chapter-1 answer: the counts, the formula
``W = 3·n − (2·P5 + P4) + r − W_th`` with numbers, where each correction comes
from, the higher-pair replacements, the Assur groups as they are detached
from the farthest, the driver(s), the structural formula and the class.

The solution is written as a :class:`~structure.explain.document.Doc` and
rendered in any of :data:`FORMATS`; its sentences, in English and Vietnamese,
are :data:`~structure.explain.phrases.PHRASES`. The document engine's names
(:class:`Math`, :class:`Doc`, :func:`render`, ...) are importable from here
too, as they were before the engine had its own module.

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> r = analyze(parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"]))
>>> text = explain_structure(r)
>>> "W = 3·n − (2·P5 + P4) + r − W_th = 3·3 − (2·4 + 0) + 0 − 0 = 1" in text
True
>>> "Công thức cấu tạo" in explain_structure(r, lang="vi")
True
"""

from __future__ import annotations

from ..assur import AssurGroup, roman
from ..mobility import Mobility
from ..model import Mechanism, PairKind
from ..report import StructuralReport
from .document import (
    Doc,
    Math,
    Segment,
    check_options,
    render,
)
from .phrases import PHRASES

__all__ = ["explain_structure"]


def _mobility_formula(lang: str) -> Math:
    r = "r" if lang == "en" else "r_th"
    r_latex = "r" if lang == "en" else r"r_{th}"
    return Math(
        f"W = 3·n − (2·P5 + P4) + {r} − W_th",
        rf"W = 3 \cdot n - (2 \cdot P_5 + P_4) + {r_latex} - W_{{th}}",
    )


def _mobility_with_numbers(mob: Mobility, lang: str) -> Math:
    general = _mobility_formula(lang)
    numbers = Math(
        f"3·{mob.n} − (2·{mob.P5} + {mob.P4}) + {mob.r} − {mob.W_passive} = {mob.W}",
        rf"3 \cdot {mob.n} - (2 \cdot {mob.P5} + {mob.P4}) + {mob.r} - {mob.W_passive}"
        rf" = {mob.W}",
    )
    return general + " = " + numbers


def _pair_label(m: Mechanism, kind: PairKind, links: tuple[str, str], point: str | None) -> str:
    return f"{links[0]}–{links[1]} {kind.value}" + (f" {point}" if point else "")


def _counts(doc: Doc, report: StructuralReport) -> None:
    m, mob = report.mechanism, report.mobility
    doc.heading(doc.word("mobility"))
    doc.para(doc.word("formula_intro"), ":")
    doc.equation(_mobility_formula(doc.lang))
    doc.item(*doc.say("n", n=mob.n, links=", ".join(m.moving_links), ground=m.ground))
    n_r = sum(1 for p in m.pairs if p.kind is PairKind.R)
    n_p = sum(1 for p in m.pairs if p.kind is PairKind.P)
    doc.item(*doc.say("p5", p5=mob.P5, r=n_r, p=n_p))
    for hinge in m.compound_hinges.values():
        k = len(hinge.links)
        doc.item(
            *doc.say("compound", point=hinge.point, k=k, links=", ".join(hinge.links), pairs=k - 1),
            level=1,
        )
    highs = [p for p in m.pairs if p.kind is PairKind.H]
    if highs:
        labels = ", ".join(f"{p.label} ({doc.word('gear' if p.gear else 'cam')})" for p in highs)
        doc.item(*doc.say("p4", p4=mob.P4, pairs=labels))
    else:
        doc.item(doc.word("p4_none"))
    if mob.redundant:
        doc.item(*doc.say("r", r=mob.r))
        for x in mob.redundant:
            line = doc.say("line", line=x.line_no) if x.line_no else ""
            key = "r_structural" if x.source == "structural" else "r_geometric"
            doc.item(*doc.say(key, k=x.constraints, pair=x.label, line=line), level=1)
    else:
        doc.item(doc.word("r_none"))
    if mob.passive:
        doc.item(*doc.say("w", w=mob.W_passive))
        for x in mob.passive:
            if x.source == "roller":
                doc.item(*doc.say("w_roller", link=x.link), level=1)
            else:
                doc.item(*doc.say("w_geometric", link=x.link, k=x.dof), level=1)
    else:
        doc.item(doc.word("w_none"))
    doc.para(doc.word("substituted"))
    doc.equation(_mobility_with_numbers(mob, doc.lang))
    for note in mob.notes:
        doc.para(*doc.say("note", note=note))


def _replacements(doc: Doc, report: StructuralReport) -> None:
    doc.heading(doc.word("replacement"))
    doc.para(doc.word("replacement_intro"))
    for rep in report.replacements:
        if rep.roller is not None:
            r = rep.roller
            doc.item(
                *doc.say(
                    "roller",
                    roller=r.roller,
                    pair=r.removed_pairs[0].label,
                    axis=r.axis,
                    follower=r.follower,
                )
            )
        new = ", ".join(p.label for p in rep.new_pairs)
        what = doc.word("gear" if rep.pair.gear else "cam")
        if rep.scheme == "R–R":
            doc.item(
                *doc.say("replace_rr", pair=rep.pair.label, what=what, v=rep.virtual_link, new=new)
            )
        else:
            flat = next(p for p in rep.new_pairs if p.kind is PairKind.P).other(rep.virtual_link)
            doc.item(
                *doc.say(
                    "replace_rp",
                    pair=rep.pair.label,
                    what=what,
                    v=rep.virtual_link,
                    new=new,
                    flat=flat,
                )
            )
    rm = report.replaced_mobility
    doc.para(*doc.say("replaced_counts", n=rm.n, p5=rm.P5))
    doc.equation(_mobility_with_numbers(rm, doc.lang))
    doc.para(doc.word("unchanged"))


def _driver_pair(m: Mechanism, link: str) -> str:
    for p in m.pairs_of(link):
        if p.other(link) == m.ground and p.kind is not PairKind.H:
            return p.label
    for h in m.compound_hinges.values():
        if link in h.links and m.ground in h.links:
            return f"{m.ground}–{link} R {h.point}"
    return "?"


def _class_line(doc: Doc, g: AssurGroup) -> list[Segment]:
    if len(g.links) == 2:
        return doc.say("class_dyad", order=g.order, kind=g.kind or "?")
    joints: dict[str, set[str]] = {}
    for k, p in enumerate(g.internal_pairs):
        key = f"R {p.point}" if p.kind is PairKind.R and p.point else f"#{k}"
        joints.setdefault(key, set()).update(p.links)
    degree = {x: sum(1 for j in joints.values() if x in j) for x in g.links}
    base = max(g.links, key=lambda x: degree[x])
    cls = roman(g.assur_class) if doc.lang == "en" else str(g.assur_class)
    if degree[base] >= g.assur_class:
        return doc.say("class_base", cls=cls, link=base, k=degree[base], order=g.order)
    return doc.say("class_contour", cls=cls, k=g.assur_class, order=g.order)


def _groups(doc: Doc, report: StructuralReport, k: int) -> None:
    doc.heading(*doc.say("groups", k=k))
    doc.para(doc.word("groups_intro"))
    if not report.groups:
        doc.para(doc.word("no_groups"))
    for i, g in enumerate(report.detach_order, start=1):
        doc.subheading(*doc.say("group", i=i, label=g.label))
        n, p = len(g.links), len(g.pairs)
        doc.item(*doc.say("group_links", links=", ".join(g.links), n=n))
        pairs = ", ".join(
            f"{_pair_label(report.replaced, gp.kind, gp.links, gp.point)} "
            f"({doc.word('outer' if gp.external else 'inner')})"
            for gp in g.pairs
        )
        doc.item(*doc.say("group_pairs", pairs=pairs, p=p))
        ok = "✓" if 3 * n == 2 * p else "✗"
        doc.item(
            doc.word("check") + " ",
            Math(
                f"3·{n} = 2·{p} = {3 * n} {ok}",
                rf"3 \cdot {n} = 2 \cdot {p} = {3 * n}" + (r"\ \checkmark" if ok == "✓" else ""),
            ),
        )
        doc.item(*_class_line(doc, g))
        doc.item(*doc.say("attached", links=", ".join(g.known_links)))
    doc.para(*doc.say("remains", drivers=", ".join(report.drivers), ground=report.replaced.ground))


def explain_structure(report: StructuralReport, lang: str = "en", fmt: str = "text") -> str:
    """The structural analysis of ``report`` as a worked solution.

    Parameters
    ----------
    report : StructuralReport
        From :func:`structure.report.analyze`.
    lang : {"en", "vi"}
        English or Vietnamese (the source's vocabulary).
    fmt : {"text", "markdown", "latex", "html"}
        Plain text, Markdown with LaTeX mathematics, a LaTeX fragment, or an
        HTML fragment with MathML formulas (see :func:`~structure.explain.document.render`).

    Returns
    -------
    str
        The counts and ``W`` with numbers, the corrections and where they come
        from, the replacements, the driver(s), the groups from the farthest
        (links, pairs, ``3n = 2p``, class, order, kind), the structural formula
        and the mechanism's class.

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> lines = ["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 P C angle=0"]
    >>> r = analyze(parse_edgelist(lines))
    >>> print(explain_structure(r).splitlines()[-1])
      The mechanism is of class II: the highest class of its groups.
    """
    check_options(lang, fmt)
    doc = Doc(PHRASES, lang)
    m = report.mechanism
    name = m.name or m.source
    doc.title(*doc.say("title", name=name))
    _counts(doc, report)
    k = 2
    if report.replacements:
        _replacements(doc, report)
        k = 3
    doc.heading(*doc.say("drivers", k=k))
    for link in report.drivers:
        doc.item(*doc.say("driver", link=link, pair=_driver_pair(report.replaced, link)))
    if report.drivers_chosen:
        doc.item(doc.word("driver_chosen"))
    doc.para(*doc.say("w_drivers", w=report.mobility.W))
    d = report.decomposition
    if d.removed_links or d.removed_pairs:
        pairs = ", ".join(report.replaced.pair(p).label for p in d.removed_pairs)
        doc.item(*doc.say("set_aside", links=", ".join(d.removed_links) or "–", pairs=pairs))
    _groups(doc, report, k + 1)
    doc.heading(*doc.say("formula", k=k + 2))
    doc.para(doc.word("formula_groups"))
    parts = report.formula.split(" → ")
    doc.equation(Math(report.formula, r" \to ".join(rf"\text{{{x}}}" for x in parts)))
    doc.para(doc.word("formula_textbook"))
    doc.equation(Math(report.textbook_formula, report.textbook_formula))
    cls = roman(report.mechanism_class) if lang == "en" else str(report.mechanism_class)
    doc.para(*doc.say("class", cls=cls))
    return render(doc, fmt)
