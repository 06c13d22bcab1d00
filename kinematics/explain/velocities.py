"""The kinematics worked solution: velocities and accelerations, group by group.

:func:`explain_kinematics` writes, group by group in solve order, the
relative-velocity and relative-acceleration vector equations the textbook
draws as polygons (``v_C = v_B + v_CB = v_D + v_CD``; for a slider on a
moving guide the relative velocity along the guide and the Coriolis term
``a^k = 2·ω×v_rel``), with what is known of each term (direction ``⊥BC`` or
``∥`` the guide, magnitude ``ω1·l_AB = 20·0.1 = 2 m/s``) and what is not
(``?``), then the values the solve found. Groups that are not dyads (triads
and higher) are solved as a whole: their equations and unknowns are listed.

Every number comes from the actual solve (:func:`~kinematics.solvers.solve.solve_pose`),
so the explanation agrees with ``assur kinematics``.

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.solvers.plan import make_plan
>>> from kinematics.solvers.solve import solve_pose
>>> m = parse_edgelist(["driver 1 omega=20", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 0.1", "point C 0.4 0.1", "point D 0.4 -0.3"])
>>> r = analyze(m); plan = make_plan(r)
>>> text = explain_kinematics(r, plan, solve_pose(plan))
>>> "v_C = v_B + v_CB = v_D + v_CD" in text, "ω1·l_AB = 20·0.1 = 2 m/s" in text
(True, True)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from structure.explain.document import Doc, Math, check_options, formula, math_join, number, render
from structure.model import PairKind
from structure.report import StructuralReport

from ..kinetostatics.polygons import (
    Dyad,
    Side,
    VectorEquation,
    coriolis,
    point_at,
    point_label,
    point_motion,
    relative_label,
    slide_direction,
    vector_equations,
)
from ..solvers.plan import GroupStep, SolvePlan
from ..solvers.solve import KinematicState
from .cam import explain_cam_step
from .context import SolutionContext, turning_rates, vector_length
from .notation import (
    ZERO,
    direction_text,
    epsilon_symbol,
    length_symbol,
    number_math,
    omega_symbol,
    parallel_to,
    perpendicular_to,
    quantity,
    scalar_symbol,
    times_length,
    toward,
    vector_symbol,
    with_numbers,
)
from .phrases import PHRASES

__all__ = ["explain_kinematics"]


def _known_motion(
    ctx: SolutionContext, x: str, k: str, label: str, order: int, where: np.ndarray | None = None
) -> list:
    """What is known of the velocity (order 1) or acceleration (2) of point ``x`` of link ``k``.

    ``where`` is the point's position when it is not a point of ``k`` in the sketch (the
    point of a guide under a slider).
    """
    doc = ctx.doc
    if k == ctx.ground:
        return [ZERO, " ", doc.word("on_ground")]
    pivot = ctx.pivot.get(k)
    if pivot == x:
        return [ZERO, f" ({doc.word('on_ground')})"]
    where = point_at(ctx.plan, ctx.state, k, x)[0] if where is None else where
    v, a = point_motion(ctx.plan, ctx.state, k, where)
    if pivot is not None:
        length = vector_length(where - point_at(ctx.plan, ctx.state, k, pivot)[0])
        w, e = turning_rates(ctx, k)
        if order == 1:
            speed = times_length(omega_symbol(k), w, pivot, x, length, "m/s")
            return [formula("{p}, {t}", p=perpendicular_to(pivot, x), t=speed)]
        sub = x + pivot
        normal = times_length(omega_symbol(k), w, pivot, x, length, "m/s²", square=True)
        tangential = times_length(epsilon_symbol(k), e, pivot, x, length, "m/s²")
        return [
            formula(
                "{an} ({to}) = {n}", an=scalar_symbol("a", sub, "n"), to=toward(x, pivot), n=normal
            ),
            "; ",
            formula(
                "{at} ({p}) = {t} ⇒ |{lab}| = {size}",
                at=scalar_symbol("a", sub, "τ"),
                p=perpendicular_to(pivot, x),
                t=tangential,
                lab=vector_symbol("a", label),
                size=quantity(vector_length(a), "m/s²"),
            ),
        ]
    vec, unit = (v, "m/s") if order == 1 else (a, "m/s²")
    if k in ctx.slide:
        _, name = ctx.guide(ctx.slide[k])
        return [formula("{p}, {v}", p=parallel_to(name), v=quantity(vector_length(vec), unit))]
    label_k = ctx.solved_in.get(k, k)
    return doc.say(
        "from_group",
        label=label_k,
        mag=quantity(vector_length(vec), unit),
        angle=direction_text(vec),
    )


def _guide_motion(ctx: SolutionContext, d: Dyad, side: Side, order: int) -> list:
    """What is known of the guide's point at X (through the pin at X for a slide inside)."""
    label = point_label(d.x, side.guide_link)
    if side.guide_link == d.la:
        head = ctx.doc.say("same_pin", p=d.x, la=d.la, k=side.known)
        return [*head, *_known_motion(ctx, d.x, side.known, label, order, d.where)]
    return _known_motion(ctx, d.x, side.guide_link, label, order, d.where)


def _normal_acceleration(ctx: SolutionContext, d: Dyad, side: Side, length: float) -> Math:
    """The normal acceleration of X about a pin side's base: ``C→B, ω2²·l_BC = …``."""
    w = turning_rates(ctx, side.link)[0]
    normal = times_length(omega_symbol(side.link), w, side.base, d.x, length, "m/s²", square=True)
    return formula("{to}, {n}", to=toward(d.x, side.base), n=normal)


def _vector_equation(ctx: SolutionContext, eq: VectorEquation) -> tuple[Math, list[list]]:
    """The vector equation (of velocities or accelerations) and what is known of its terms.

    Each way to X is its known point's vector, then the terms of
    :func:`~kinematics.kinetostatics.polygons.vector_equations`: one known (``a^n``, ``a^k``)
    for accelerations, and last the one whose size is unknown (``⊥`` the arm
    or ``∥`` the guide).
    """
    d, order = eq.dyad, eq.order
    letter = "v" if order == 1 else "a"
    lhs = vector_symbol(letter, eq.x)
    chains = {c.side: c for c in eq.chains}
    sums: list[Math] = []
    items: list[list] = []
    for side in d.sides:
        if side.kind == "G":
            items.append([lhs, ": ", formula("{p}, ?", p=parallel_to(ctx.guide(side.pair)[1]))])
            continue
        chain = chains[side]
        base = vector_symbol(letter, chain.start)
        terms = [vector_symbol(t.letter, t.sub, t.sup) for t in chain.terms]
        sums.append(math_join([base, *terms], " + "))
        if side.kind == "R":
            items.append([base, ": ", *_known_motion(ctx, side.base, side.known, side.base, order)])
            unknown = perpendicular_to(side.base, d.x)
            if order == 2:
                length = vector_length(d.where - chain.start_where)
                items.append([terms[0], ": ", _normal_acceleration(ctx, d, side, length)])
        else:
            items.append([base, ": ", *_guide_motion(ctx, d, side, order)])
            unknown = parallel_to(ctx.guide(side.pair)[1])
            if order == 2:
                items.append([terms[0], ": ", *_coriolis_term(ctx, d, side)])
        items.append([terms[-1], ": ", formula("{p}, ?", p=unknown)])
    return (math_join([lhs, *sums], " = ") if sums else lhs), items


def _coriolis_term(ctx: SolutionContext, d: Dyad, side: Side) -> list:
    wg, vrel, ak = coriolis(ctx.plan, ctx.state, d, side)
    sub = relative_label(d, side)
    symbols = [omega_symbol(side.guide_link), scalar_symbol("v", sub)]
    value = with_numbers(
        "2·{0}·{1}", symbols, [abs(wg), vector_length(vrel)], quantity(vector_length(ak), "m/s²")
    )
    if vector_length(ak) <= 1e-9:
        return [value]
    turned = ctx.doc.say(
        "coriolis", vrel=vector_symbol("v", sub), w=omega_symbol(side.guide_link), value=value
    )
    return [*turned, " (", *ctx.doc.say("at", angle=direction_text(ak)), ")"]


def _along_guide(ctx: SolutionContext, sym: Math, value: float, u: np.ndarray, unit: str) -> list:
    direction = u * (1.0 if value >= 0 else -1.0)
    return [
        formula("{s} = {v}", s=sym, v=quantity(abs(value), unit)),
        ", ",
        *ctx.doc.say("along", angle=direction_text(direction)),
    ]


def _solved_terms(ctx: SolutionContext, eq: VectorEquation) -> list[list]:
    """The unknown magnitudes the equation gives, and the rates of the links."""
    doc = ctx.doc
    d, order = eq.dyad, eq.order
    unit, rate_unit = ("m/s", "rad/s") if order == 1 else ("m/s²", "rad/s²")
    letter = "v" if order == 1 else "a"
    chains = {c.side: c for c in eq.chains}
    out: list[list] = []
    for side in d.sides:
        link = side.link
        if side.kind == "G":
            u = slide_direction(ctx.plan, ctx.state, side.pair)
            own = point_motion(ctx.plan, ctx.state, link, d.where)[order - 1]
            out.append(_along_guide(ctx, scalar_symbol(letter, eq.x), float(own @ u), u, unit))
            if order == 1:
                out.append(doc.say("slides_ground", w=omega_symbol(link), link=link))
            continue
        chain = chains[side]
        last = chain.terms[-1]  # the term of unknown size: v_CB, a^τ_CB, v_B3B2, a^r_B3B2
        sym = scalar_symbol(last.letter, last.sub, last.sup)
        if side.kind == "P":
            u = slide_direction(ctx.plan, ctx.state, side.pair)
            out.append(_along_guide(ctx, sym, float(last.vector @ u), u, unit))
            continue
        rate = turning_rates(ctx, link)[order - 1]
        length = vector_length(d.where - chain.start_where)
        value = abs(rate) * length
        ratio = with_numbers(
            "{0}/{1}",
            [sym, length_symbol(side.base, d.x)],
            [value, length],
            quantity(rate, rate_unit),
        )
        r_sym = omega_symbol(link) if order == 1 else epsilon_symbol(link)
        equation = formula(
            "{s} = {v} ⇒ {r} = {q}", s=sym, v=quantity(value, unit), r=r_sym, q=ratio
        )
        out.append([equation, ctx.sense(rate)])
    for link in d.links:
        partner = _turns_with(d, link)
        if partner is None or partner == ctx.ground:
            continue
        if order == 1:
            value = number_math(turning_rates(ctx, link)[0])
            out.append(
                doc.say("same_angle", w=omega_symbol(link), wk=omega_symbol(partner), value=value)
            )
        else:
            value = number_math(turning_rates(ctx, link)[1])
            out.append(
                doc.say(
                    "same_angle_e", e=epsilon_symbol(link), ek=epsilon_symbol(partner), value=value
                )
            )
    if not any(s.kind == "G" for s in d.sides):
        out.append(
            [
                formula(
                    "{s} = {v}",
                    s=scalar_symbol(letter, eq.x),
                    v=quantity(vector_length(eq.value), unit),
                ),
                ", ",
                *doc.say("at", angle=direction_text(eq.value)),
            ]
        )
    return out


def _turns_with(d: Dyad, link: str) -> str | None:
    """The link whose rotation ``link`` shares through a prismatic pair (no pin side of its own)."""
    if any(s.kind == "R" and s.link == link for s in d.sides):
        return None
    for side in d.sides:
        if side.kind in ("P", "G") and side.link == link:
            return side.guide_link
    return d.lhs_link if link == d.la else None


def _group_points(ctx: SolutionContext, links: Sequence[str], pin_of: Mapping[str, str]) -> None:
    """Markers of the group's links from a pin X of theirs (v_M = v_X + v_MX); then every point."""
    doc = ctx.doc
    rows: list[list] = []
    for name, ps in ctx.state.points.items():
        if ps.link not in links:
            continue
        marker = ctx.mechanism.points.get(name)
        x = pin_of.get(ps.link)
        if marker is not None and marker.on == ps.link and x is not None and x != name:
            link = ps.link
            w, e = turning_rates(ctx, link)
            length = ctx.distance(link, x, name)
            sub, l_xm = name + x, length_symbol(x, name)
            speed = times_length(omega_symbol(link), w, x, name, length, "m/s")
            v_sum = _relative_motion("v", name, x, sub, [""])
            rows.append([formula("{s}: {p}, {t}", s=v_sum, p=perpendicular_to(x, name), t=speed)])
            a_n, a_t = scalar_symbol("a", sub, "n"), scalar_symbol("a", sub, "τ")
            v_n, v_t = quantity(w * w * length, "m/s²"), quantity(abs(e) * length, "m/s²")
            normal = formula("{n} = {w}²·{l} = {v}", n=a_n, w=omega_symbol(link), l=l_xm, v=v_n)
            tangent = formula("{t} = {e}·{l} = {v}", t=a_t, e=epsilon_symbol(link), l=l_xm, v=v_t)
            a_sum = _relative_motion("a", name, x, sub, ["n", "τ"])
            rows.append([formula("{s}: {n}, {t}", s=a_sum, n=normal, t=tangent)])
        v, a = np.asarray(ps.velocity), np.asarray(ps.acceleration)
        rows.append(
            doc.say(
                "point_value",
                name=name,
                link=ps.link,
                v=number(vector_length(v)),
                va=direction_text(v),
                a=number(vector_length(a)),
                aa=direction_text(a),
            )
        )
    if rows:
        doc.para(doc.word("points"))
        for row in rows:
            doc.item(*row)


def _relative_motion(letter: str, point: str, base: str, sub: str, sups: Sequence[str]) -> Math:
    """``v_M = v_X + v_MX``, ``a_M = a_X + a^n_MX + a^τ_MX``: a point from another of its link."""
    terms = [vector_symbol(letter, base), *(vector_symbol(letter, sub, sup) for sup in sups)]
    return formula("{p} = {t}", p=vector_symbol(letter, point), t=math_join(terms, " + "))


def _link_values(ctx: SolutionContext, links: Sequence[str]) -> None:
    doc = ctx.doc
    doc.para(doc.word("solved_links"))
    for link in links:
        if link not in ctx.state.links:
            continue
        w, e = turning_rates(ctx, link)
        doc.item(
            *doc.say(
                "link_value",
                link=link,
                w=omega_symbol(link),
                wv=number(w),
                ws=ctx.sense(w),
                e=epsilon_symbol(link),
                ev=number(e),
                es=ctx.sense(e),
            )
        )


_ORDER_WORDS = {1: ("velocities", "two_unknowns"), 2: ("accelerations", "two_unknowns_a")}


def _explain_dyad(
    ctx: SolutionContext, step: GroupStep, equations: Sequence[VectorEquation]
) -> None:
    """A dyad: its velocity, then its acceleration equation (``equations``), each solved."""
    doc = ctx.doc
    for eq in equations:
        title, closes = _ORDER_WORDS[eq.order]
        doc.para(doc.word(title))
        equation, items = _vector_equation(ctx, eq)
        doc.equation(equation)
        for row in items:
            doc.item(*row)
        doc.para(doc.word(closes))
        for row in _solved_terms(ctx, eq):
            doc.item(*row)
    _link_values(ctx, step.links)
    d = equations[0].dyad
    pins: dict[str, str] = {}
    for side in d.sides:
        if side.kind == "R":
            pins.setdefault(side.link, side.base)
    for link in step.links if d.lhs_link is None else (d.la,):
        pins.setdefault(link, d.x)  # X is a pin of these links
    _group_points(ctx, step.links, pins)


def _explain_whole(ctx: SolutionContext, step: GroupStep) -> None:
    """A group solved as a whole (triads and up), or a redundant link."""
    doc = ctx.doc
    g = step.group
    pins: dict[str, str] = {}
    if g is None:
        doc.para(*doc.say("redundant", link=step.redundant_link))
    else:
        doc.para(*doc.say("generic", rows=sum(eq.size for eq in step.equations)))
        for gp in g.pairs:
            a, b = gp.links
            point = gp.point or "?"
            if gp.kind is PairKind.R:
                same = [vector_symbol("v", point_label(point, x)) for x in (a, b)]
                eq = formula("{a} = {b}", a=same[0], b=same[1])
                doc.item(*doc.say("pair_r", point=point, a=a, b=b, eq=eq))
                pins.setdefault(a, point)
            else:
                eq = formula("{a} = {b}", a=omega_symbol(a), b=omega_symbol(b))
                doc.item(*doc.say("pair_p", point=point, a=a, b=b, eq1=eq))
        doc.para(*doc.say("unknowns", links=", ".join(g.links), count=3 * len(g.links)))
    _link_values(ctx, step.links)
    _group_points(ctx, step.links, pins)


def _explain_drivers(ctx: SolutionContext) -> None:
    doc = ctx.doc
    doc.heading(doc.word("drivers"))
    for d in ctx.plan.drivers:
        extra = "" if d.speed_given else doc.word("not_given")
        if d.kind == "R":
            doc.para(
                *doc.say(
                    "driver_r",
                    link=d.link,
                    pivot=d.point or "?",
                    w=omega_symbol(d.link),
                    wv=number(d.speed),
                    e=epsilon_symbol(d.link),
                    ev=number(d.acceleration),
                ),
                extra,
            )
        else:
            doc.para(
                *doc.say(
                    "driver_p",
                    link=d.link,
                    angle=direction_text(d.direction),
                    v=number(d.speed),
                    a=number(d.acceleration),
                ),
                extra,
            )
        for name in ctx.points_of(d.link):
            if name == d.point:
                continue
            doc.item(vector_symbol("v", name), ": ", *_known_motion(ctx, name, d.link, name, 1))
            doc.item(vector_symbol("a", name), ": ", *_known_motion(ctx, name, d.link, name, 2))


def explain_kinematics(
    report: StructuralReport,
    plan: SolvePlan,
    state: KinematicState,
    lang: str = "en",
    fmt: str = "text",
) -> str:
    """The velocities and accelerations of ``state`` as the textbook's worked solution.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis the plan was made from.
    plan : SolvePlan
        From :func:`kinematics.solvers.plan.make_plan`.
    state : KinematicState
        From :func:`kinematics.solvers.solve.solve_pose` (any pose).
    lang : {"en", "vi"}
        English or Vietnamese.
    fmt : {"text", "markdown", "latex", "html"}
        Plain text, Markdown with LaTeX mathematics, a LaTeX fragment, or an
        HTML fragment with MathML formulas (see :func:`~structure.explain.document.render`).

    Returns
    -------
    str
        The drivers, then for each group in solve order its velocity and
        acceleration vector equations with what is known of each term, and
        the values solved (ω, ε of its links; v, a of its points).

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.solvers.plan import make_plan
    >>> from kinematics.solvers.solve import solve_pose
    >>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C",
    ...                     "3 0 P C angle=0", "point A 0 0", "point B 0 0.1", "point C 0.2 0"])
    >>> r = analyze(m); plan = make_plan(r)
    >>> "v_C = v_B + v_CB" in explain_kinematics(r, plan, solve_pose(plan))
    True
    """
    check_options(lang, fmt)
    doc = Doc(PHRASES, lang)
    ctx = SolutionContext.at_pose(doc, plan, state)
    m = report.mechanism
    doc.title(*doc.say("kin_title", name=m.name or m.source))
    doc.para(doc.word("conventions"))
    _explain_drivers(ctx)
    dyads: dict[str, list[VectorEquation]] = {}
    for order in (1, 2):
        for eq in vector_equations(plan, state, order):
            dyads.setdefault(eq.label, []).append(eq)
    for k, step in enumerate(plan.steps, start=2):
        kind = f" {step.kind}" if step.kind else ""
        doc.heading(
            *doc.say("group_head", k=k, label=step.label, kind=kind, links=", ".join(step.links))
        )
        if step.cam is not None:  # a designed cam: its follower moves by the program
            explain_cam_step(ctx, step)
        elif step.label in dyads:
            _explain_dyad(ctx, step, dyads[step.label])
        else:
            _explain_whole(ctx, step)
    return render(doc, fmt)
