"""The kinetostatics worked solution: the reactions group by group, the balancing moment.

:func:`explain_forces` writes the kinetostatics from the farthest group back:
for each group the equilibrium equations in the order the textbook solves
them (moments about the inner pin for the tangential components, the group's
force balance for the normal ones, then a link's balance for the inner
reaction), then the driver's balancing moment from ``ΣM_A = 0`` and its check
by virtual power.

Every number comes from the actual solve (:func:`~kinematics.kinetostatics.forces.solve_forces`),
so the explanation agrees with ``assur forces``; the steps recompute each
unknown from its own equation, which checks the solve.

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.solvers.plan import make_plan
>>> from kinematics.kinetostatics.forces import solve_forces
>>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0", "point B 0.1 0 on=1",
...                     "force 1 B 0 -100"])
>>> r = analyze(m); plan = make_plan(r)
>>> "M_cb = −ΣP·v/ω1 = −(-10)/1 = 10" in explain_forces(r, plan, solve_forces(plan))
True
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from structure.assur import AssurGroup, GroupPair
from structure.explain.document import (
    Doc,
    Math,
    check_options,
    formula,
    math_join,
    number,
    render,
    subscript,
)
from structure.model import Load, PairKind
from structure.report import StructuralReport

from ..cams.contact import contact_at
from ..kinetostatics.forces import ForceSolution, Reaction
from ..kinetostatics.polygons import Dyad, dyad_of, link_rates, point_at
from ..solvers.plan import DriverStep, GroupStep, SolvePlan
from ..solvers.solve import KinematicState, solve_pose
from .cam import CAM_PHRASES
from .context import NamedPoint, SolutionContext, cross, turned_left, turning_rates, vector_length
from .notation import (
    POWER_EQUATION,
    components_text,
    direction_text,
    length_symbol,
    load_sum,
    moment_of,
    moment_sum,
    number_math,
    omega_symbol,
    pair_subscript,
    parenthesized,
    power_term,
    quantity,
    reaction_symbol,
    reaction_vector,
    scalar_symbol,
    vector_symbol,
    with_numbers,
)
from .phrases import PHRASES

__all__ = ["explain_forces"]


@dataclass(frozen=True)
class _KnownLoad:
    """A known load on a link: a force at a point and/or a moment, and its power."""

    label: Math
    link: str
    force: np.ndarray
    at: np.ndarray
    moment: float = 0.0
    power: tuple[Math, float] | None = None  # "P_3·v_M3 = … = −707 W" and its value


def _moment_about(loads: Sequence[_KnownLoad], o: np.ndarray) -> float:
    return sum((cross(x.at - o, x.force) + x.moment for x in loads), 0.0)


def _resultant(loads: Sequence[_KnownLoad]) -> np.ndarray:
    return sum((x.force for x in loads), np.zeros(2))


def _applied_loads(ctx: SolutionContext, velocities: SolutionContext) -> list[_KnownLoad]:
    """The loads of the file and the inertia loads, listed; power at ``velocities``' motion."""
    doc = ctx.doc
    gravity = np.zeros(2)
    for load in ctx.mechanism.loads:
        if load.kind == "gravity":
            gravity = np.array(load.values, dtype=float)
    out: list[_KnownLoad] = []
    count: dict[tuple[str, str], int] = {}
    inertia_tag = "qt" if doc.lang == "vi" else "in"

    def symbol(letter: str, link: str, sup: str = "") -> Math:
        count[letter + sup, link] = count.get((letter + sup, link), 0) + 1
        k = count[letter + sup, link]
        return scalar_symbol(letter, link if k == 1 else f"{link},{k}", sup)

    def force(label: Math, link: str, point: str, f: np.ndarray, key: str) -> None:
        v = point_at(velocities.plan, velocities.state, link, point)[1]
        dot = math_join(
            [formula("{f}·{v}", f=parenthesized(f[i]), v=parenthesized(v[i])) for i in (0, 1)],
            " + ",
        )
        power = formula(
            "{s}·{v} = {d} = {p}",
            s=label,
            v=vector_symbol("v", point),
            d=dot,
            p=quantity(float(f @ v), "W"),
        )
        where = point_at(ctx.plan, ctx.state, link, point)[0]
        out.append(_KnownLoad(label, link, f, where, 0.0, (power, float(f @ v))))
        fx, fy = number(f[0], 1e-6), number(f[1], 1e-6)
        doc.item(*doc.say(key, sym=label, point=point, link=link, fx=fx, fy=fy))

    def moment(label: Math, link: str, value: float, key: str) -> None:
        w = turning_rates(velocities, link)[0]
        power = power_term(label, omega_symbol(link), value, w)
        out.append(_KnownLoad(label, link, np.zeros(2), np.zeros(2), value, (power, value * w)))
        doc.item(*doc.say(key, sym=label, link=link, value=number(value, 1e-6)))

    for load in ctx.mechanism.loads:
        link, point = load.link, load.point or ""
        if load.kind == "force":
            force(symbol("P", link), link, point, np.array(load.values, dtype=float), "load_force")
        elif load.kind == "moment":
            moment(symbol("M", link), link, float(load.values[0]), "load_moment")
        elif load.kind == "mass":
            mass, inertia = (float(x) for x in load.values)
            if vector_length(gravity) > 0:
                force(symbol("G", link), link, point, mass * gravity, "load_weight")
            inertia_force = -mass * point_at(ctx.plan, ctx.state, link, point)[2]
            force(symbol("P", link, inertia_tag), link, point, inertia_force, "load_inertia")
            if inertia:
                inertia_moment = -inertia * turning_rates(ctx, link)[1]
                label = symbol("M", link, inertia_tag)
                moment(label, link, inertia_moment, "load_inertia_m")
    return out


def _comma_separated(items: Iterable[list]) -> list:
    """The items (each a list of segments) one after the other, separated by ``, ``."""
    out: list = []
    for item in items:
        out += [", ", *item] if out else item
    return out


def _reaction_between(
    solution: ForceSolution, a: str, b: str, point: str | None, kind: str
) -> tuple[np.ndarray, float, Reaction] | None:
    """The force and couple that ``a`` exerts on ``b`` at ``point``, and the reaction."""
    for r in solution.reactions:
        if r.kind != kind or set(r.links) != {a, b}:
            continue
        if point and r.point and r.point != point:
            continue
        if r.links == (a, b):
            return np.asarray(r.force), r.couple, r
        return -np.asarray(r.force), -r.couple, r
    return None


def _acts_at(ctx: SolutionContext, r: Reaction) -> NamedPoint:
    """Where a reaction acts: its pin, or for a slide its point on ``links[1]``.

    A designed cam's contact force acts where the contact is at the pose (on its profile).
    """
    name = r.point or ""
    cam = next((c for c in ctx.plan.cams if r.kind == "H" and set(r.links) == {c.cam, c.follower}),
               None)  # fmt: skip
    if cam is not None:
        turned = ctx.state.links[cam.cam].angle if cam.cam in ctx.state.links else 0.0
        return NamedPoint(name, contact_at(cam, np.array([turned]))[0])
    if r.kind == "P" and ctx.mechanism.coordinates(name) is not None:
        return ctx.slide_point(name, r.links[1])
    named = ctx.state.points.get(name)
    return NamedPoint(name, np.zeros(2) if named is None else np.asarray(named.position))


def _carried_reactions(
    ctx: SolutionContext, solution: ForceSolution, link: str, farther: set[str]
) -> list[_KnownLoad]:
    """The reactions of the groups already solved (farther out) on ``link``."""
    out = []
    designed = {frozenset((c.cam, c.follower)) for c in ctx.plan.cams}
    for r in solution.reactions:
        contact = r.kind == "H" and frozenset(r.links) in designed  # a designed cam's force
        if (r.kind not in ("R", "P") and not contact) or link not in r.links:
            continue
        other = r.links[0] if r.links[1] == link else r.links[1]
        if other not in farther:
            continue
        sign = 1.0 if r.links[1] == link else -1.0
        at = _acts_at(ctx, r).xy
        force = sign * np.asarray(r.force)
        out.append(_KnownLoad(reaction_symbol(other, link), link, force, at, sign * r.couple))
    return out


def _known_loads(ctx: SolutionContext, link: str, loads: Sequence[_KnownLoad]) -> None:
    doc = ctx.doc
    parts = _comma_separated([x.label] for x in loads)
    doc.item(*doc.say("f_known", link=link, list=parts or [doc.word("f_none")]))


def _show_reaction(
    ctx: SolutionContext, solution: ForceSolution, a: str, b: str, point: str, kind: str
) -> None:
    doc = ctx.doc
    found = _reaction_between(solution, a, b, point, kind)
    if found is None:
        return
    f, c, r = found
    extra: list = []
    if kind == "P":
        about = _acts_at(ctx, r).name
        extra = doc.say("f_reaction_p", point=about, value=number(c, 1e-6))
    doc.item(
        *doc.say(
            "f_reaction",
            sym=reaction_symbol(a, b),
            point=point,
            fx=number(f[0], 1e-6),
            fy=number(f[1], 1e-6),
            mag=number(vector_length(f), 1e-6),
            angle=direction_text(f, 1e-6),
        ),
        *extra,
    )


def _step_title(doc: Doc, head: list, gives: Sequence[Math]) -> list:
    """An equation's name and the unknowns it gives: ``ΣF = 0 on link 2; gives R_32``."""
    if not gives:
        return head
    return [*head, "; ", *doc.say("f_gives", what=_comma_separated([sym] for sym in gives))]


class _NumberedSteps:
    """Numbered equilibrium equations: what each one is and gives, then the equation."""

    def __init__(self, doc: Doc):
        self.doc = doc
        self.count = 0

    def __call__(self, what: list, equation: Math) -> None:
        self.count += 1
        self.doc.item(*self.doc.say("f_step", k=self.count, what=what))
        self.doc.equation(equation)


def _moment_step(
    ctx: SolutionContext,
    link: str,
    about: NamedPoint,
    loads: Sequence[_KnownLoad],
    gives: Sequence[Math],
) -> tuple[float, list]:
    """The known loads' moment about ``about`` and the words of ``ΣM_about(link) = 0``."""
    doc = ctx.doc
    value = _moment_about(loads, about.xy)
    head = [
        *doc.say("f_moment", sum=moment_sum(about.name), link=link),
        "; ",
        scalar_symbol("M", about.name),
        ": ",
        *doc.say("f_sum_moments", link=link, point=about.name),
        " = ",
        quantity(value, "N·m", 1e-6),
    ]
    return value, _step_title(doc, head, gives)


def _tangential_component(
    ctx: SolutionContext,
    steps: _NumberedSteps,
    link: str,
    known: str,
    base: NamedPoint,
    pin: NamedPoint,
    loads: Sequence[_KnownLoad],
) -> np.ndarray:
    """ΣM_pin(link) = 0 gives the component of R_known,link at ``base`` ⊥ base–pin."""
    length = vector_length(pin.xy - base.xy)
    rt_sym = reaction_symbol(known, link, "τ")
    moment, what = _moment_step(ctx, link, pin, loads, [rt_sym])
    rt = moment / length
    b, c = base.name, pin.name
    m_pin, l_bc = scalar_symbol("M", c), length_symbol(b, c)
    numbers = [number_math(moment, 1e-6), length]
    ratio = with_numbers("{0}/{1}", [m_pin, l_bc], numbers, quantity(rt, "N", 1e-6))
    steps(what, formula("−{r}·{l} + {m} = 0 ⇒ {r} = {q}", r=rt_sym, l=l_bc, m=m_pin, q=ratio))
    ctx.doc.para(
        *ctx.doc.say(
            "f_tangent",
            rt=Math("R^τ", r"R^{\tau}"),
            rn=Math("R^n", "R^{n}"),
            perp=Math(f"⊥{b}{c}", rf"\perp {b}{c}"),
            par=Math(f"∥{b}{c}", rf"\parallel {b}{c}"),
            line=b + c,
            a=b,
            b=c,
        )
    )
    return rt * turned_left((pin.xy - base.xy) / length)


def _components_along(a: np.ndarray, b: np.ndarray, rhs: np.ndarray) -> tuple[float, float]:
    """``x·a + y·b = rhs``."""
    det = cross(a, b)
    if abs(det) <= 1e-12:
        return math.nan, math.nan
    return cross(rhs, b) / det, cross(a, rhs) / det


def _force_balance(terms: Sequence[Math], loads: Math, found: Sequence[tuple[Math, float]]) -> Math:
    """``R^n_12 + R^τ_12 + … + ΣP = 0 ⇒ R^n_12 = …, …``."""
    values = [formula("{s} = {v}", s=s, v=quantity(v, "N", 1e-6)) for s, v in found]
    lhs = math_join([*terms, loads], " + ")
    return formula("{lhs} = 0 ⇒ {values}", lhs=lhs, values=math_join(values, ", "))


def _reaction_offset(
    ctx: SolutionContext, point: str, couple: float, nvec: np.ndarray, u: np.ndarray
) -> None:
    """Where the guide's reaction acts: x = M/N along the guide from its point."""
    doc = ctx.doc
    if vector_length(nvec) <= 1e-9 * max(1.0, abs(couple)):
        if abs(couple) > 1e-9:
            doc.para(*doc.say("f_couple", value=number(couple, 1e-6)))
        return
    doc.para(*doc.say("f_offset", x=number(couple / cross(u, nvec), 1e-9), point=point))


def _slide_moment(
    ctx: SolutionContext,
    steps: _NumberedSteps,
    link: str,
    known: str,
    s: NamedPoint,
    about: NamedPoint,
    loads: Sequence[_KnownLoad],
    nvec: np.ndarray,
    u: np.ndarray,
    extra: tuple[Math, float] | None = None,
) -> None:
    """ΣM_about(link) = 0 gives the moment of the guide's reaction about its point ``s``."""
    msym = scalar_symbol("M", pair_subscript(known, link))
    moment, what = _moment_step(ctx, link, about, loads, [msym])
    value = -(cross(s.xy - about.xy, nvec) + moment + (extra[1] if extra else 0.0))
    terms = [msym]
    if s.name != about.name:
        arm = f"{about.name}{s.name}"
        terms.append(Math(f"{arm}×", rf"\vec{{{arm}}} \times ") + reaction_vector(known, link))
    if extra is not None:
        terms.append(extra[0])
    terms.append(scalar_symbol("M", about.name))
    lhs = math_join(terms, " + ")
    steps(what, formula("{lhs} = 0 ⇒ {m} = {v}", lhs=lhs, m=msym, v=quantity(value, "N·m", 1e-6)))
    _reaction_offset(ctx, s.name, value, nvec, u)


def _link_balance(
    steps: _NumberedSteps, link: str, sources: tuple[str, str], rest: np.ndarray, gives: str
) -> None:
    """ΣF = 0 on ``link``: ``R_a,link + ΣP_link + R_b,link = 0`` gives ``R_gives,link``.

    ``sources`` are the links ``a``, ``b`` whose reactions on ``link`` enter; ``rest``
    is the known part of the sum, ``ΣP_link`` and the other reaction.
    """
    doc = steps.doc
    a, b = sources
    sym = reaction_vector(gives, link)
    lhs = math_join([reaction_vector(a, link), load_sum(link), reaction_vector(b, link)], " + ")
    what = _step_title(doc, doc.say("f_force_link", link=link), [sym])
    steps(what, formula("{lhs} = 0 ⇒ {r} = {v}", lhs=lhs, r=sym, v=components_text(-rest, "N")))


def _dyad_forces(
    ctx: SolutionContext, g: AssurGroup, d: Dyad, loads: Mapping[str, list[_KnownLoad]]
) -> None:
    """The textbook's equations of a dyad, each solved for its unknowns with numbers."""
    doc = ctx.doc
    steps = _NumberedSteps(doc)
    (mid,) = g.internal_pairs
    ext = {p.links[0]: p for p in g.external_pairs}
    forces = {x: _resultant(loads[x]) for x in g.links}
    if mid.kind is PairKind.R:
        _pin_dyad_forces(ctx, steps, g, ext, ctx.pin(mid.point or "?"), loads, forces)
        return
    la, lb = d.la, d.lhs_link or ""
    u, name = ctx.guide(mid.pair)
    nn = turned_left(u)
    n_sym = reaction_symbol(la, lb)
    doc.para(*doc.say("f_slide", sym=n_sym, guide=name))
    b, s = ctx.pin(ext[la].point or "?"), ctx.slide_at(mid.pair)
    src_a = ext[la].links[1]
    if ext[lb].kind is PairKind.R:  # RPR: moments about the block's pin, then the other pivot
        p_d = ctx.pin(ext[lb].point or "?")
        m_b, m_d = scalar_symbol("M", b.name), scalar_symbol("M", p_d.name)
        mb, what = _moment_step(ctx, la, b, loads[la], [])
        inner = moment_of(b.name, lb, la)
        steps(
            what, formula("{i} + {m} = 0 ⇒ {i} = {v}", i=inner, m=m_b, v=quantity(-mb, "N·m", 1e-6))
        )
        md, what = _moment_step(ctx, lb, p_d, loads[lb], [n_sym])
        lever = cross(b.xy - p_d.xy, nn)
        doc.para(*doc.say("f_lever", sym=n_sym, point=b.name, about=p_d.name, h=number(lever)))
        value = -(mb + md) / lever if abs(lever) > 1e-12 else math.nan
        found = quantity(value, "N", 1e-6)
        solved = formula(
            "−({b} + {d})/{h} = {v}",
            b=parenthesized(mb),
            d=parenthesized(md),
            h=parenthesized(lever),
            v=found,
        )
        steps(what, formula("{n}·h + {b} + {d} = 0 ⇒ {n} = {s}", n=n_sym, b=m_b, d=m_d, s=solved))
        nvec = value * nn
        _reaction_offset(ctx, s.name, mb - cross(s.xy - b.xy, nvec), nvec, u)
        _link_balance(steps, la, (src_a, lb), forces[la] - nvec, gives=src_a)
        src_b = ext[lb].links[1]
        _link_balance(steps, lb, (src_b, la), forces[lb] + nvec, gives=src_b)
        return
    e = ext[lb]  # RPP: the inner slide and the outer guide carry the forces on lb
    ue, name_e = ctx.guide(e.pair)
    ne = turned_left(ue)
    e_sym = reaction_symbol(e.links[1], lb)
    doc.para(*doc.say("f_slide", sym=e_sym, guide=name_e))
    x_mid, x_ext = _components_along(nn, ne, -forces[lb])
    terms = [reaction_vector(la, lb), reaction_vector(e.links[1], lb)]
    what = _step_title(doc, doc.say("f_force_link", link=lb), [n_sym, e_sym])
    steps(what, _force_balance(terms, load_sum(lb), [(n_sym, x_mid), (e_sym, x_ext)]))
    nvec = x_mid * nn
    _link_balance(steps, la, (src_a, lb), forces[la] - nvec, gives=src_a)
    couple_sym = scalar_symbol("M", pair_subscript(la, lb))
    mb, what = _moment_step(ctx, la, b, loads[la], [couple_sym])
    couple = mb - cross(s.xy - b.xy, nvec)
    steps(what, formula("{c} = {v}", c=couple_sym, v=quantity(couple, "N·m", 1e-6)))
    _reaction_offset(ctx, s.name, couple, nvec, u)
    se = ctx.slide_at(e.pair)
    extra = (moment_of(se.name, la, lb), couple + cross(s.xy - se.xy, nvec))
    _slide_moment(ctx, steps, lb, e.links[1], se, se, loads[lb], x_ext * ne, ue, extra)


def _pin_dyad_forces(
    ctx: SolutionContext,
    steps: _NumberedSteps,
    g: AssurGroup,
    ext: Mapping[str, GroupPair],
    pin: NamedPoint,
    loads: Mapping[str, list[_KnownLoad]],
    forces: Mapping[str, np.ndarray],
) -> None:
    """RRR, RRP, PRP: tangential components, the group's force balance, the inner pin."""
    doc = ctx.doc
    tangent = {
        link: _tangential_component(
            ctx, steps, link, e.links[1], ctx.pin(e.point or "?"), pin, loads[link]
        )
        for link, e in ext.items()
        if e.kind is PairKind.R
    }
    rest = forces[g.links[0]] + forces[g.links[1]] + sum(tangent.values(), np.zeros(2))
    unknown: list[tuple[Math, np.ndarray]] = []
    terms: list[Math] = []
    for link in g.links:
        e, src = ext[link], ext[link].links[1]
        if e.kind is PairKind.R:
            n = pin.xy - ctx.pin(e.point or "").xy
            unknown.append((reaction_symbol(src, link, "n"), n / vector_length(n)))
            terms += [reaction_vector(src, link, "n"), reaction_vector(src, link, "τ")]
        else:
            u, name = ctx.guide(e.pair)
            unknown.append((reaction_symbol(src, link), turned_left(u)))
            terms.append(reaction_vector(src, link))
            doc.para(*doc.say("f_slide", sym=reaction_symbol(src, link), guide=name))
    (s1, d1), (s2, d2) = unknown
    x1, x2 = _components_along(d1, d2, -rest)
    what = _step_title(doc, [doc.word("f_force_group")], [s1, s2])
    steps(what, _force_balance(terms, load_sum(), [(s1, x1), (s2, x2)]))
    outer = {g.links[0]: x1 * d1, g.links[1]: x2 * d2}
    for link, t in tangent.items():
        outer[link] = outer[link] + t
    first = next((x for x in g.links if ext[x].kind is PairKind.R), g.links[0])
    other = g.links[1] if first == g.links[0] else g.links[0]
    src = ext[first].links[1]
    _link_balance(steps, first, (src, other), outer[first] + forces[first], gives=other)
    for link, e in ext.items():
        if e.kind is PairKind.P:
            u, s = ctx.guide(e.pair)[0], ctx.slide_at(e.pair)
            _slide_moment(ctx, steps, link, e.links[1], s, pin, loads[link], outer[link], u)


def _group_forces(
    ctx: SolutionContext,
    solution: ForceSolution,
    step: GroupStep,
    applied: Sequence[_KnownLoad],
    farther: set[str],
    whole: bool,
) -> None:
    doc = ctx.doc
    g = step.group
    loads = {
        link: [x for x in applied if x.link == link]
        + _carried_reactions(ctx, solution, link, farther)
        for link in step.links
    }
    for link in step.links:
        _known_loads(ctx, link, loads[link])
    if step.cam is not None:  # a designed cam's follower: the contact's replacement at the pose
        cam = step.cam
        doc.para(
            *Doc(CAM_PHRASES, doc.lang).say(
                "cam_f_group", follower=cam.follower, cam=cam.cam, guide=cam.guide.point or "?"
            )
        )
        doc.para(doc.word("f_found"))
        guide = cam.guide
        _show_reaction(ctx, solution, guide.a, guide.b, guide.point or "", guide.kind.value)
        _show_reaction(ctx, solution, cam.cam, cam.follower, cam.contact_point or "", "H")
        return
    pairs = list(g.pairs) if g is not None else []
    listing = _comma_separated(
        [reaction_symbol(p.links[1], p.links[0]), f" ({p.point})"] for p in pairs
    )
    if listing:
        doc.para(*doc.say("f_unknowns", list=listing))
    d = None if whole else dyad_of(ctx.plan, ctx.state, g)
    if g is not None and d is not None:
        _dyad_forces(ctx, g, d, loads)
    elif g is not None:
        doc.para(*doc.say("f_generic", eqs=3 * len(g.links), n=len(g.links)))
    doc.para(doc.word("f_found"))
    for p in pairs:
        _show_reaction(ctx, solution, p.links[1], p.links[0], p.point or "", p.kind.value)
    if g is None:
        for r in solution.reactions:
            if step.redundant_link in r.links and r.kind in ("R", "P"):
                _show_reaction(ctx, solution, r.links[0], r.links[1], r.point or "", r.kind)


def _virtual_motion(plan: SolvePlan, state: KinematicState) -> tuple[KinematicState, bool]:
    """The motion the power check uses: the real one, or one with unit driver speeds."""
    if any(abs(d.speed) > 0 for d in plan.drivers):
        return state, False
    drivers = tuple(dataclasses.replace(d, speed=1.0) for d in plan.drivers)
    return solve_pose(dataclasses.replace(plan, drivers=drivers), state.inputs), True


def _pose_text(plan: SolvePlan, inputs: Sequence[float]) -> Math:
    """The driver inputs from the sketch: ``φ1 = 0.5 rad`` (turned), ``s1 = 0.02 m`` (slid)."""
    parts = []
    for d, x in zip(plan.drivers, inputs, strict=True):
        if d.kind == "R":
            parts.append(formula("{s} = {v}", s=subscript("φ", d.link), v=quantity(x, "rad")))
        else:
            parts.append(
                formula("{s} = {v}", s=Math(f"s{d.link}", f"s_{{{d.link}}}"), v=quantity(x, "m"))
            )
    return math_join(parts, ", ")


class _DriverPower(NamedTuple):
    """A driver's balancing moment (or force) and the speed it works at, for the power check."""

    symbol: Math
    value: float
    speed_symbol: Math
    speed: float


def _driver_forces(
    ctx: SolutionContext,
    power_ctx: SolutionContext,
    solution: ForceSolution,
    drv: DriverStep,
    loads: Sequence[_KnownLoad],
) -> _DriverPower:
    """The balancing moment (or force) from the driver's equilibrium, then the ground's reaction.

    ``power_ctx`` is the motion the power check uses (see :func:`_virtual_motion`).
    """
    if drv.kind == "P":
        return _slid_driver(ctx, power_ctx, solution, drv, loads)
    doc = ctx.doc
    link = drv.link
    pivot = drv.point or "?"
    a = ctx.pin(pivot).xy if pivot in ctx.state.points else np.asarray(drv.pivot)
    ma = _moment_about(loads, a)
    doc.para(*doc.say("f_mcb", sum=moment_sum(pivot), link=link))
    sums = doc.say("f_sum_moments", link=link, point=pivot)
    doc.item(scalar_symbol("M", pivot), ": ", *sums, " = ", quantity(ma, "N·m", 1e-6))
    balance = next((x for x in ctx.mechanism.loads if x.kind == "balance" and x.link == link), None)
    if balance is not None and solution.balancing_force is not None:
        power, on_driver = _balancing_force(ctx, power_ctx, solution, balance, pivot, a, ma)
    else:
        power, on_driver = _balancing_moment(ctx, power_ctx, solution, link, pivot, ma)
    ground = -(_resultant(loads) + on_driver)
    doc.para(*doc.say("f_ground", link=link))
    doc.equation(
        formula(
            "{r} = −{p} = {v}",
            r=reaction_vector(ctx.ground, link),
            p=load_sum(link),
            v=components_text(ground, "N"),
        )
    )
    _show_reaction(ctx, solution, ctx.ground, link, pivot, "R")
    return power


def _slid_driver(
    ctx: SolutionContext,
    power_ctx: SolutionContext,
    solution: ForceSolution,
    drv: DriverStep,
    loads: Sequence[_KnownLoad],
) -> _DriverPower:
    """A sliding driver: the balancing force along its guide, then the guide's reaction."""
    doc = ctx.doc
    link = drv.link
    u = drv.direction
    along = -float(_resultant(loads) @ u)
    found = float(solution.balancing_moment.get(link, along))
    sym = scalar_symbol("F", "cb")
    doc.equation(formula("{s} + ΣP·u = 0 ⇒ {s} = {v}", s=sym, v=quantity(along, "N", 1e-6)))
    doc.item(*doc.say("f_fcb_value", sym=sym, value=number(found, 1e-6), angle=direction_text(u)))
    pid = ctx.slide.get(link)
    point = (ctx.mechanism.pair(pid).point or "") if pid else ""
    _show_reaction(ctx, solution, ctx.ground, link, point, "P")
    speed = float(link_rates(power_ctx.plan, power_ctx.state, link)[1][:2] @ u)
    return _DriverPower(sym, found, Math(f"v{link}", f"v_{{{link}}}"), speed)


def _balancing_force(
    ctx: SolutionContext,
    power_ctx: SolutionContext,
    solution: ForceSolution,
    balance: Load,
    pivot: str,
    a: np.ndarray,
    ma: float,
) -> tuple[_DriverPower, np.ndarray]:
    """``P_cb·h + M_A = 0``: the balancing force of a ``balance`` line, and its force."""
    doc = ctx.doc
    link = balance.link
    t = math.radians(balance.values[0])
    u = np.array([math.cos(t), math.sin(t)])
    point = balance.point or ""
    known = ctx.mechanism.coordinates(point) is not None
    at = point_at(ctx.plan, ctx.state, link, point)[0] if known else a
    lever = cross(at - a, u)
    sym = scalar_symbol("P", "cb")
    value = -ma / lever if abs(lever) > 1e-12 else math.nan
    doc.equation(
        formula(
            "{s}·h + {m} = 0, h = {h} ⇒ {s} = −{m}/h = {v}",
            s=sym,
            m=scalar_symbol("M", pivot),
            h=quantity(lever, "m"),
            v=quantity(value, "N", 1e-6),
        )
    )
    found = float(np.asarray(solution.balancing_force) @ u)
    doc.item(
        *doc.say(
            "f_pcb_value",
            sym=sym,
            value=number(found, 1e-6),
            angle=number(balance.values[0]),
            point=point,
        )
    )
    speed_sym = formula("{v}·u", v=vector_symbol("v", point))
    speed = float(point_at(power_ctx.plan, power_ctx.state, link, point)[1] @ u)
    return _DriverPower(sym, found, speed_sym, speed), found * u


def _balancing_moment(
    ctx: SolutionContext,
    power_ctx: SolutionContext,
    solution: ForceSolution,
    link: str,
    pivot: str,
    ma: float,
) -> tuple[_DriverPower, np.ndarray]:
    """``M_cb + M_A = 0``: the balancing moment on the driver (no force on it)."""
    doc = ctx.doc
    sym = scalar_symbol("M", "cb")
    m_pivot = scalar_symbol("M", pivot)
    doc.equation(
        formula("{s} + {m} = 0 ⇒ {s} = −{m} = {v}", s=sym, m=m_pivot, v=quantity(-ma, "N·m", 1e-6))
    )
    found = float(solution.balancing_moment.get(link, -ma))
    sense = doc.word("ccw" if found >= 0 else "cw")
    doc.item(*doc.say("f_mcb_value", sym=sym, value=number(found, 1e-6), sense=sense))
    speed = turning_rates(power_ctx, link)[0]
    return _DriverPower(sym, found, omega_symbol(link), speed), np.zeros(2)


def _power_check(
    ctx: SolutionContext,
    k: int,
    applied: Sequence[_KnownLoad],
    drivers: Sequence[_DriverPower],
    solution: ForceSolution,
    virtual: bool,
) -> None:
    """Σ P·v + Σ M·ω + M_cb·ω1 = 0 with every term's numbers."""
    doc = ctx.doc
    doc.heading(*doc.say("f_power", k=k))
    doc.para(doc.word("f_power_intro"))
    if virtual:
        doc.para(doc.word("f_power_virtual"))
    doc.equation(POWER_EQUATION)
    values: list[float] = []
    for load in applied:
        if load.power is not None:
            doc.item(load.power[0])
            values.append(load.power[1])
    loads_power = sum(values, 0.0)
    for driver in drivers:
        doc.item(power_term(driver.symbol, driver.speed_symbol, driver.value, driver.speed))
        values.append(driver.value * driver.speed)
    if solution.friction_loss is not None:
        doc.item(*doc.say("f_power_friction", value=number(solution.friction_loss, 1e-9)))
        values.append(-solution.friction_loss)
    total = sum(values, 0.0)
    scale = max([abs(x) for x in values] + [1e-300])
    key = "f_power_sum" if abs(total) <= 1e-6 * scale else "f_power_bad"
    doc.para(*doc.say(key, value=number(total, 1e-6 * scale)))
    if len(drivers) == 1 and abs(drivers[0].speed) > 1e-12 and solution.friction_loss is None:
        (driver,) = drivers
        value = -loads_power / driver.speed
        numbers = [parenthesized(loads_power), parenthesized(driver.speed)]
        symbols = [formula("ΣP·v"), driver.speed_symbol]
        solved = with_numbers("−{0}/{1}", symbols, numbers, number_math(value, 1e-6))
        eq = formula("{s} = {v}", s=driver.symbol, v=solved)
        doc.para(*doc.say("f_power_gives", eq=eq))


def _introduction(ctx: SolutionContext, report: StructuralReport, solution: ForceSolution) -> None:
    """The title (with the pose when it is not the sketch's), the conventions, the order."""
    doc = ctx.doc
    m = report.mechanism
    if any(solution.inputs):
        pose = _pose_text(ctx.plan, solution.inputs)
        doc.title(*doc.say("f_title_at", name=m.name or m.source, pose=pose))
    else:
        doc.title(*doc.say("f_title", name=m.name or m.source))
    doc.para(doc.word("f_conventions"))
    doc.para(*doc.say("f_order", order=" → ".join(solution.order)))


def _load_notes(ctx: SolutionContext, applied: Sequence[_KnownLoad]) -> bool:
    """No loads, friction, over-constraint: said once; whether groups are solved as a whole."""
    doc = ctx.doc
    if not applied:
        doc.para(doc.word("no_loads"))
    whole = any(p.friction or p.circle for p in ctx.mechanism.pairs)
    if whole:
        doc.para(doc.word("f_friction"))
    if any(s.group is None for s in ctx.plan.steps):
        doc.para(doc.word("f_indeterminate"))
    return whole


def _contact_forces(ctx: SolutionContext, solution: ForceSolution) -> None:
    """The contact force of each higher pair, carried by its virtual link."""
    doc = ctx.doc
    for _, a, b, point in ctx.plan.contacts:
        for r in solution.reactions:
            if r.kind == "H" and set(r.links) == {a, b}:
                doc.para(*doc.say("f_contact", point=point or "?"))
                magnitude = f", |F| = {number(r.magnitude, 1e-6)} N"
                symbol = reaction_symbol(r.links[0], r.links[1])
                doc.item(symbol, ": ", components_text(r.force, "N"), magnitude)


def explain_forces(
    report: StructuralReport,
    plan: SolvePlan,
    solution: ForceSolution,
    lang: str = "en",
    fmt: str = "text",
) -> str:
    """The kinetostatics of ``solution`` (at its pose) as the textbook's worked solution.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis the plan was made from.
    plan : SolvePlan
        From :func:`kinematics.solvers.plan.make_plan`.
    solution : ForceSolution
        From :func:`kinematics.kinetostatics.forces.solve_forces`, at any pose: the motion
        (inertia loads, the power check) is solved at its ``inputs``.
    lang : {"en", "vi"}
        English or Vietnamese.
    fmt : {"text", "markdown", "latex", "html"}
        Plain text, Markdown with LaTeX mathematics, a LaTeX fragment, or an
        HTML fragment with MathML formulas (see :func:`~structure.explain.document.render`).

    Returns
    -------
    str
        The loads; for each group from the farthest, its equilibrium
        equations in the order solved with the unknowns each gives, and the
        reactions found; the driver's balancing moment from ``ΣM_A = 0``; the
        virtual-power check with numbers.

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.solvers.plan import make_plan
    >>> from kinematics.kinetostatics.forces import solve_forces
    >>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0", "point B 0.1 0 on=1",
    ...                     "force 1 B 0 -100"])
    >>> r = analyze(m); plan = make_plan(r)
    >>> "M_cb = −M_A = 10 N·m" in explain_forces(r, plan, solve_forces(plan))
    True
    """
    check_options(lang, fmt)
    doc = Doc(PHRASES, lang)
    state = solve_pose(plan, solution.inputs or None)
    ctx = SolutionContext.at_pose(doc, plan, state)
    virtual_state, virtual = _virtual_motion(plan, state)
    power_ctx = SolutionContext.at_pose(doc, plan, virtual_state) if virtual else ctx
    _introduction(ctx, report, solution)
    doc.heading("1. " + doc.word("loads"))
    applied = _applied_loads(ctx, power_ctx)
    whole = _load_notes(ctx, applied)
    farther: set[str] = set()
    k = 2
    for step in reversed(plan.steps):
        kind = f" {step.kind}" if step.kind else ""
        doc.heading(*doc.say("f_group", k=k, label=step.label, kind=kind))
        _group_forces(ctx, solution, step, applied, farther, whole)
        farther |= set(step.links)
        k += 1
    powers = []
    for drv in plan.drivers:
        doc.heading(*doc.say("f_driver", k=k, link=drv.link))
        k += 1
        on_driver = [x for x in applied if x.link == drv.link]
        loads = on_driver + _carried_reactions(ctx, solution, drv.link, farther)
        _known_loads(ctx, drv.link, loads)
        powers.append(_driver_forces(ctx, power_ctx, solution, drv, loads))
    _contact_forces(ctx, solution)
    _power_check(ctx, k, applied, powers, solution, virtual)
    return render(doc, fmt)
