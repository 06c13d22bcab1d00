"""The solve plan: the structural report's groups in solve order, as equations.

:func:`make_plan` turns a :class:`~structure.report.StructuralReport` (its
lower-pair mechanism, drivers and Assur groups) and the sketch coordinates
into what the solvers need: for each driver its pivot or slide, for each group
its links and the equations of its pairs. Nothing is solved here.

>>> from structure import analyze, parse_edgelist
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 1", "point C 2 1", "point D 2 0"])
>>> plan = make_plan(analyze(m))
>>> [(s.label, len(s.equations)) for s in plan.steps]
[('II(2,3)', 3)]
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from structure.assur import AssurGroup
from structure.errors import EdgeListError, EdgeListProblem, MechanismError
from structure.meshes import meshes
from structure.model import Mechanism, PairKind
from structure.report import StructuralReport

from ..cams.contact import CamContact, cam_contacts
from ..errors import AssemblyModeError
from .equations import Equation, slide_equations
from .planar import unit_from_degrees

__all__ = [
    "DriverStep",
    "GroupStep",
    "SolvePlan",
    "in_unit",
    "make_plan",
    "parse_flip",
    "single_mode_kinds",
    "working_unit",
]


@dataclass(frozen=True)
class DriverStep:
    """A driver: ``kind`` R (turns about ``pivot``) or P (slides along ``direction``)."""

    link: str
    kind: PairKind
    pivot: np.ndarray
    direction: np.ndarray
    speed: float  # ω (rad/s) or v (m/s)
    acceleration: float  # ε (rad/s²) or a (m/s²)
    speed_given: bool
    point: str | None = None  # the pivot's name (R) or a point of the slide (P)


@dataclass(frozen=True)
class GroupStep:
    """One step of the solve: an Assur group's links and the equations of its pairs.

    A link set aside as redundant by the structural analysis (a third
    parallel crank) is a step of its own with ``group`` None: its pairs give
    more equations than it has freedoms, all consistent, solved in the
    least-squares sense.
    """

    group: AssurGroup | None
    equations: tuple[Equation, ...]
    redundant_link: str = ""
    unknowns: tuple[str, ...] = ()  # the links solved, when not the group's (rolling gears)
    cam: CamContact | None = None  # a designed cam's follower, placed by its program

    @property
    def links(self) -> tuple[str, ...]:
        if self.unknowns:
            return self.unknowns
        return self.group.links if self.group is not None else (self.redundant_link,)

    @property
    def label(self) -> str:
        if self.group is None:
            return f"redundant link {self.redundant_link}"
        return self.group.label

    @property
    def kind(self) -> str | None:
        return self.group.kind if self.group is not None and not self.unknowns else None


@dataclass(frozen=True)
class SolvePlan:
    """Drivers, then groups in solve order, and the points to report.

    ``points`` maps a point name to the link that carries it and its sketch
    coordinates; ``length`` is the sketch's size (for tolerances); ``flip``
    holds the labels of the dyads to assemble in the other mode than the
    sketch's, ``modes`` the other groups' assembly modes asked for
    (:mod:`kinematics.solvers.modes`: ``{label: mode}``, mode 1 the next one
    from the sketch's) and ``starts`` their links' poses at the sketch's inputs,
    once found (:func:`kinematics.solvers.solve.solve_poses` finds them);
    ``higher_pairs`` the higher pairs replaced by virtual links,
    whose replacement holds at the sketch pose only. ``unit`` is the length,
    in metres, that one unit of the plan's coordinates stands for (1: the
    file's metres; see :func:`in_unit`); a sliding driver's inputs, speed and
    acceleration stay in metres whatever it is.
    """

    mechanism: Mechanism
    drivers: tuple[DriverStep, ...]
    steps: tuple[GroupStep, ...]
    points: Mapping[str, tuple[str, np.ndarray]]
    length: float
    flip: frozenset[str] = frozenset()
    higher_pairs: tuple[str, ...] = ()
    contacts: tuple[tuple[str, str, str, str | None], ...] = ()  # virtual, a, b, contact point
    rolling: tuple[GroupStep, ...] | None = None
    cams: tuple[CamContact, ...] = ()  # the cams with a profile: their replacement is per pose
    unit: float = 1.0
    modes: Mapping[str, int] = field(default_factory=lambda: MappingProxyType({}))
    starts: Mapping[str, Mapping[str, np.ndarray]] = field(
        default_factory=lambda: MappingProxyType({})
    )

    @property
    def driver_kinds(self) -> tuple[str, ...]:
        """Each driver's kind, 'R' (turns) or 'P' (slides): how its inputs are printed."""
        return tuple(d.kind for d in self.drivers)

    @property
    def driver_scale(self) -> np.ndarray:
        """Per driver, what one unit of input is measured against: 1 rad, or the sketch's size.

        The sketch's size in metres, as a sliding driver's inputs are.
        """
        size = self.length * self.unit
        return np.array([1.0 if d.kind == "R" else size for d in self.drivers])


def _xy(mechanism: Mechanism, name: str | None, why: str, problems: list) -> np.ndarray:
    xy = mechanism.coordinates(name) if name is not None else None
    if xy is None:
        problems.append(
            EdgeListProblem(
                0, "", f"{why}: point {name or '(unnamed)'} needs coordinates for kinematics"
            )
        )
        return np.zeros(2)
    return np.array(xy, dtype=float)


def make_plan(report: StructuralReport, flip: Iterable[str] = ()) -> SolvePlan:
    """The solve plan of a structural report whose mechanism has sketch coordinates.

    ``flip`` names groups (by label) to assemble in another mode than the
    sketch's: ``'II(2,3)'`` a dyad in its other one, ``'III(4,5,6,7)'`` a
    triad or any other group in the next one found from the sketch's,
    ``'III(4,5,6,7)=2'`` in mode 2 as
    :func:`~kinematics.solvers.solve.assembly_modes` lists them. The modes of
    the groups other than dyads are found when the plan is first solved.

    Raises
    ------
    EdgeListError
        A pair point without coordinates, or a P pair without ``angle=``.
    AssemblyModeError
        ``flip`` asks a dyad for a mode it does not have (a PRP or RPP dyad has
        only one; any other dyad two).
    ValueError
        ``flip`` names a group that is not a group of the plan, or cannot be read.
    """
    m = report.replaced
    problems: list[EdgeListProblem] = []
    motion = {d.link: dict(d.motion) for d in report.mechanism.drivers}
    drivers = tuple(
        _driver_step(m, link, motion.get(link, {}), problems) for link in report.drivers
    )
    cams = cam_contacts(report.mechanism, report.replacements) if report.mechanism.cams else ()
    steps = [_step(m, group, cams, problems) for group in report.groups]
    steps += [
        GroupStep(None, _redundant_equations(m, link, problems), link)
        for link in report.decomposition.removed_links
    ]
    if problems:
        raise EdgeListError(m.source, problems)
    dyads, modes = _check_flip(steps, flip)
    profiled = {c.virtual for c in cams}
    return SolvePlan(
        m,
        drivers,
        tuple(steps),
        MappingProxyType(_cam_points(_points(m), cams)),
        _sketch_size(m),
        dyads,
        tuple(r.pair.label for r in report.replacements if r.virtual_link not in profiled),
        _contacts(report),
        _rolling_steps(report, steps, profiled) if report.replacements else None,
        cams,
        modes=MappingProxyType(modes),
    )


def _step(m: Mechanism, group: AssurGroup, cams: tuple, problems: list) -> GroupStep:
    """A group's step; the group of a designed cam's virtual link is its follower's step."""
    cam = next((c for c in cams if c.virtual in group.links), None)
    if cam is None:
        return GroupStep(group, _group_equations(m, group, problems))
    if set(group.links) != {cam.virtual, cam.follower}:
        raise MechanismError(
            f"{cam.label}: the follower {cam.follower} must form a dyad with the cam's virtual "
            f"link (it is in group {group.label}): join it to the ground only by its guide or "
            "pivot, and drive the rest of the mechanism from it"
        )
    return GroupStep(group, (), unknowns=(cam.follower,), cam=cam)


def _cam_points(
    points: dict[str, tuple[str, np.ndarray]], cams: tuple
) -> dict[str, tuple[str, np.ndarray]]:
    """The points of a designed cam's replacement: the follower's pin stays on the follower;
    the centre of curvature at the sketch is no point of any link over a cycle."""
    for cam in cams:
        for name, (link, xy) in list(points.items()):
            if link == cam.virtual:
                points[name] = (cam.follower, xy)
        for name in (cam.pair.center_of(cam.cam),):
            if name is not None:
                points.pop(name, None)
    return points


def _driver_step(
    m: Mechanism, link: str, values: Mapping[str, float], problems: list
) -> DriverStep:
    """A driver's pivot (turning about the ground) or slide (along it), speed and acceleration."""
    joint = m.ground_joint(link)
    if joint.kind is PairKind.R:
        point = joint.point
        pivot = _xy(m, point, f"driver {link}'s pivot", problems)
        speed, acc = values.get("omega"), values.get("epsilon", 0.0)
        return DriverStep(
            link, PairKind.R, pivot, np.zeros(2), speed or 0.0, acc, speed is not None, point
        )
    p_pair = joint.pair
    if p_pair.angle_deg is None:
        problems.append(EdgeListProblem(p_pair.line_no, p_pair.statement, "needs angle="))
    direction = unit_from_degrees(p_pair.angle_deg)  # v > 0 moves the driver along angle=
    speed, acc = values.get("v"), values.get("a", 0.0)
    return DriverStep(
        link, PairKind.P, np.zeros(2), direction, speed or 0.0, acc, speed is not None, p_pair.point
    )


def _group_equations(m: Mechanism, group: AssurGroup, problems: list) -> tuple[Equation, ...]:
    """The equations of an Assur group's pairs (inner and outer), in the group's pair order."""
    equations: list[Equation] = []
    for gp in group.pairs:
        a, b = gp.links
        if gp.kind is PairKind.R:
            c = _xy(m, gp.point, f"pair {a}–{b} R", problems)
            equations.append(Equation("HINGE", a, b, c, pair=gp.pair))
            continue
        pair = m.pair(gp.pair)
        if pair.angle_deg is None:
            problems.append(EdgeListProblem(pair.line_no, pair.statement, "needs angle="))
        u = unit_from_degrees(pair.angle_deg)
        c = _xy(m, gp.point, f"pair {pair.label}", problems)
        equations.extend(slide_equations(a, b, c, u, pair.id))
    return tuple(equations)


def _redundant_equations(m: Mechanism, link: str, problems: list) -> tuple[Equation, ...]:
    """The equations of every pair of a link set aside as redundant."""
    equations: list[Equation] = []
    for pair in m.pairs_of(link):
        other = pair.other(link)
        if pair.kind is PairKind.R:
            c = _xy(m, pair.point, f"pair {pair.label}", problems)
            equations.append(Equation("HINGE", link, other, c, pair=pair.id))
        elif pair.kind is PairKind.P:
            u = unit_from_degrees(pair.angle_deg)
            c = _xy(m, pair.point, f"pair {pair.label}", problems)
            equations.extend(slide_equations(link, other, c, u, pair.id))
    return tuple(equations)


def _points(m: Mechanism) -> dict[str, tuple[str, np.ndarray]]:
    """Every named point with coordinates, and the link that carries it."""
    points: dict[str, tuple[str, np.ndarray]] = {}
    for h in m.hinges:
        xy = m.coordinates(h.point)
        if xy is not None:
            # a pin on the ground stays put; otherwise any of its links carries it
            carrier = m.ground if m.ground in h.links else h.links[0]
            points[h.point] = (carrier, np.array(xy, dtype=float))
    for p in m.pairs:
        if p.kind is PairKind.P and p.point and p.point not in points:
            xy = m.coordinates(p.point)
            if xy is not None:
                carrier = p.b if p.b != m.ground else p.a
                points[p.point] = (carrier, np.array(xy, dtype=float))
    for pt in m.points.values():
        if pt.on is not None:
            points[pt.name] = (pt.on, np.array([pt.x, pt.y]))
    return points


def _sketch_size(m: Mechanism) -> float:
    """The sketch's extent (the larger of its width and height; 1 for a single point)."""
    coords = np.array([[p.x, p.y] for p in m.points.values()]) if m.points else np.zeros((1, 2))
    span = float(np.max(np.ptp(coords, axis=0))) if len(coords) > 1 else 1.0
    return span if span > 0 else 1.0


#: dyads whose pairs place them in one way only (a linear system)
single_mode_kinds = frozenset({"PRP", "RPP"})


def parse_flip(flip: Iterable[str]) -> dict[str, int]:
    """``{group label: mode}`` from ``flip``: ``'II(2,3)'`` (mode 1) or ``'III(4,5,6,7)=2'``.

    >>> parse_flip(["II(2,3)", "III(4,5,6,7)=2"])
    {'II(2,3)': 1, 'III(4,5,6,7)': 2}

    Raises
    ------
    ValueError
        A mode that is not a whole number from 1 on, or a group named twice
        with different modes.
    """
    out: dict[str, int] = {}
    for text in flip:
        label, sep, number = str(text).partition("=")
        label = label.strip()
        mode = 1
        if sep:
            try:
                mode = int(number.strip())
            except ValueError:
                mode = 0
            if mode < 1:
                raise ValueError(
                    f"cannot read {text!r}: after '=' comes the number of an assembly mode, "
                    "1 or more (mode 0 is the sketch's, which needs no --flip), as "
                    "--modes lists them"
                )
        if out.get(label, mode) != mode:
            raise ValueError(f"group {label} is given two assembly modes, {out[label]} and {mode}")
        out[label] = mode
    return out


def _check_flip(
    steps: list[GroupStep], flip: Iterable[str]
) -> tuple[frozenset[str], dict[str, int]]:
    """The dyads to flip, and the other groups' modes, that ``flip`` asks for."""
    asked = parse_flip(flip)
    groups = {s.label: s for s in steps if s.group is not None}
    unknown = sorted(set(asked) - set(groups))
    if unknown:
        raise ValueError(
            f"cannot flip {', '.join(unknown)}: the groups are "
            f"{', '.join(groups) or 'none (the mechanism has no Assur group)'}"
        )
    dyads, modes = set(), {}
    for label, mode in asked.items():
        kind = groups[label].group.kind  # type: ignore[union-attr]
        if kind in single_mode_kinds:
            raise AssemblyModeError(
                f"group {label}, a dyad ({kind}), has a single assembly mode: its two slides "
                "and its pin place it in one way only, so there is no other to choose (leave "
                "it out of --flip)"
            )
        if kind is not None and mode != 1:
            raise AssemblyModeError(
                f"group {label}, a dyad ({kind}), has two assembly modes, 0 (the sketch's) "
                f"and 1 (the other), so there is no mode {mode} (write --flip '{label}')"
            )
        if kind is not None:
            dyads.add(label)
        else:
            modes[label] = mode
    return frozenset(dyads), modes


def _contacts(report: StructuralReport) -> tuple[tuple[str, str, str, str | None], ...]:
    """Each replaced higher pair: its virtual link, the two links it joins, its contact point."""
    return tuple(
        (
            r.virtual_link,
            r.new_pairs[0].other(r.virtual_link),
            r.new_pairs[1].other(r.virtual_link),
            r.pair.point,
        )
        for r in report.replacements
    )


def _rolling_steps(
    report: StructuralReport, steps: list[GroupStep], profiled: set[str] = frozenset()
) -> tuple[GroupStep, ...] | None:
    """The steps with each gear mesh's virtual link replaced by its rolling constraint.

    None when a higher pair is not a gear mesh with both tooth numbers.
    """
    try:
        found = {mesh.pair.id: mesh for mesh in meshes(report.mechanism)}
    except MechanismError:  # a mesh without a carrier: only the sketch pose can be solved
        return None
    rolls: dict[str, Equation] = {}
    for r in report.replacements:
        if r.virtual_link in profiled:  # a designed cam: its step follows its program
            continue
        mesh = found.get(r.pair.id)
        if mesh is None or mesh.za is None or mesh.zb is None:
            return None
        sign = -1.0 if mesh.internal else 1.0
        rolls[r.virtual_link] = Equation(
            "GEAR", mesh.a, mesh.b, pair=r.pair.id, carrier=mesh.carrier,
            ratio=sign * mesh.zb / mesh.za,
        )  # fmt: skip
    out = []
    for step in steps:
        virtual = [link for link in step.links if link in rolls]
        if not virtual:
            out.append(step)
            continue
        kept = tuple(eq for eq in step.equations if eq.a not in rolls and eq.b not in rolls)
        unknowns = tuple(link for link in step.links if link not in rolls)
        out.append(
            GroupStep(step.group, kept + tuple(rolls[v] for v in virtual), step.redundant_link,
                      unknowns)
        )  # fmt: skip
    return tuple(out)


#: the sketch sizes (m) a plan is solved at as it stands: from 2⁻⁶⁴ to 2⁶⁴ the squares and
#: products the solvers form (up to the eighth power of a length) stay normal floats
_PLAIN_SIZES = (2.0**-64, 2.0**64)


def working_unit(plan: SolvePlan) -> float:
    """The unit of length (m) to solve ``plan`` in: 1, or a power of two near its size.

    A sketch between 2⁻⁶⁴ and 2⁶⁴ m is solved as it stands; a smaller or
    larger one in the power of two nearest its size, so that no square of a
    length under- or overflows. Scaling by a power of two is exact, so the
    answers are the same numbers either way.

    >>> from structure import analyze, parse_edgelist
    >>> tiny = parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
    ...                        "point A 0 0", "point B 0 1e-300", "point C 3e-300 1e-300",
    ...                        "point D 3e-300 0"])
    >>> working_unit(make_plan(analyze(tiny))) == 2.0**-995   # 3e-300 m = 1.0045·2⁻⁹⁹⁵ m
    True
    """
    size = plan.length * plan.unit
    low, high = _PLAIN_SIZES
    if low <= size <= high or plan.cams:  # a designed cam's program is in metres
        return 1.0
    return math.ldexp(1.0, math.frexp(size)[1] - 1)


def in_unit(plan: SolvePlan, unit: float) -> SolvePlan:
    """The plan with its coordinates measured in ``unit`` metres (a power of two: exact).

    The drivers' pivots, the pairs' points, the named points and the sketch's
    size are divided by ``unit``; the sliding drivers' inputs, speeds and
    accelerations stay in metres (``plan.unit`` converts them). A plan in a
    unit already is measured in the new one.
    """
    ratio = unit / plan.unit
    if ratio == 1.0:
        return plan
    m = plan.mechanism
    points = {
        name: dataclasses.replace(p, x=p.x / ratio, y=p.y / ratio, exact=(None, None))
        for name, p in m.points.items()
    }
    mechanism = dataclasses.replace(m, points=points)
    per = np.array([ratio, ratio, 1.0])
    drivers = tuple(dataclasses.replace(d, pivot=d.pivot / ratio) for d in plan.drivers)
    return dataclasses.replace(
        plan,
        mechanism=mechanism,
        drivers=drivers,
        steps=_steps_in(plan.steps, ratio),
        points=MappingProxyType({k: (link, c / ratio) for k, (link, c) in plan.points.items()}),
        length=plan.length / ratio,
        rolling=None if plan.rolling is None else _steps_in(plan.rolling, ratio),
        unit=unit,
        starts=MappingProxyType(
            {
                label: {link: np.asarray(p, dtype=float) / per for link, p in poses.items()}
                for label, poses in plan.starts.items()
            }
        ),
    )


def _steps_in(steps: tuple[GroupStep, ...], ratio: float) -> tuple[GroupStep, ...]:
    """The steps with their equations' points divided by ``ratio`` (normals are unit vectors)."""
    return tuple(
        dataclasses.replace(
            step,
            equations=tuple(
                dataclasses.replace(eq, point=eq.point / ratio) for eq in step.equations
            ),
        )
        for step in steps
    )
