"""Positions, velocities and accelerations, group by group from the drivers, for many poses.

Each link's state is ``(x, y, θ)``: the displacement and rotation of its frame
from the sketch pose (where every link is at ``(0, 0, 0)``); the results are
the types of :mod:`kinematics.results.state`. For every pose the drivers are placed
from their input; then each Assur group, in solve order, is

* positioned: dyads in closed form, vectorised over all poses, with the
  sketch's assembly mode (the sign of the square root; :mod:`kinematics.solvers.dyads`),
  class III triads of revolute pairs through one unknown, their base link's
  angle, with their rates in closed form (:mod:`kinematics.solvers.triads`), other
  groups by Newton's method on their own equations, following the inputs from
  the sketch (:mod:`kinematics.solvers.newton`);
* given its velocities from ``J_g·q̇_g = −J_k·q̇_k`` (``k``: the known links its
  external pairs touch) and its accelerations from
  ``J_g·q̈_g = −J_k·q̈_k − (dJ/dt)·q̇``, as batched linear solves (RRR and RRP
  dyads get theirs in closed form with their positions).

A group that cannot be assembled raises :class:`AssemblyError`; one whose
Jacobian loses rank (a dead centre) raises :class:`SingularPoseError`. Both
name the group and the input; nothing is returned as NaN.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> m = parse_edgelist(["driver 1 omega=20", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 0.1", "point C 0.4 0.1", "point D 0.4 -0.3"])
>>> state = solve_pose(make_plan(analyze(m)))
>>> round(state.links["3"].omega, 12), abs(round(state.links["2"].omega, 12))
(5.0, 0.0)
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from types import MappingProxyType

import numpy as np

from structure.errors import MechanismError

from ..cams.contact import solve_cam_step
from ..errors import (
    DEAD_CENTRE,
    AssemblyError,
    AssemblyModeError,
    BranchChangeError,
    SingularPoseError,
)
from ..results.state import KinematicState, LinkState, Motion, PointState
from . import branches, dyads, triads
from .equations import equation_point, group_system
from .frames import Frame, LinkTable
from .modes import STARTS, Mode, group_solutions
from .newton import (
    CONTINUATION_STEP,
    angle_rows,
    densified,
    follow,
    needs_continuation,
    scaled_jacobian,
)
from .paths import Watch
from .plan import GroupStep, SolvePlan, in_unit, single_mode_kinds, working_unit

# the errors and the state types are defined in kinematics.errors and kinematics.results.state;
# they stay importable from here
__all__ = [
    "AssemblyError",
    "KinematicState",
    "LinkState",
    "Motion",
    "PointState",
    "SingularPoseError",
    "assembly_modes",
    "solve_pose",
    "solve_poses",
]


def _place_drivers(
    plan: SolvePlan, inputs: np.ndarray, frames: dict[str, Frame], tables: tuple
) -> None:
    """Each driver's frame: a crank turned by its input about its pivot, a slider moved along."""
    for k, d in enumerate(plan.drivers):
        value = inputs[:, k]
        if d.kind == "R":
            px, py = float(d.pivot[0]), float(d.pivot[1])
            frames[d.link] = Frame(
                d.pivot.copy(), px, py, 0.0, 0.0, 0.0, 0.0,
                np.cos(value), np.sin(value), float(d.speed), float(d.acceleration), value,
            )  # fmt: skip
        else:  # the input, speed and acceleration in metres, the frame in the plan's unit
            ux, uy = float(d.direction[0]) / plan.unit, float(d.direction[1]) / plan.unit
            v, a = float(d.speed), float(d.acceleration)
            frames[d.link] = Frame(
                np.zeros(2), value * ux, value * uy, v * ux, v * uy, a * ux, a * uy,
                1.0, 0.0, 0.0, 0.0, 0.0,
            )  # fmt: skip
        for table in tables:
            table.declare(d.link)


def solve_poses(
    plan: SolvePlan,
    inputs: np.ndarray,
    guess: Mapping[str, np.ndarray] | None = None,
    *,
    rates: bool = True,
) -> Motion:
    """Positions, velocities and accelerations for every row of ``inputs`` (N, drivers).

    Rows are driver rotations (rad) or displacements (m) from the sketch.
    Groups solved by Newton follow the inputs from the sketch on, with
    intermediate poses where consecutive rows are far apart, so that they keep
    the sketch's assembly mode. ``guess`` holds link poses (3,) to start Newton
    from at the first row instead (no intermediate poses are added then).
    With ``rates`` false only the positions are solved: the motion's ``qd`` and
    ``qdd`` are empty then.

    Consecutive rows are a path: a dyad whose joint jumps between two rows as
    far as its other assembly mode lies is followed with finer steps
    (:mod:`kinematics.solvers.branches`), so that it never changes mode unnoticed.

    Raises
    ------
    AssemblyError
        A group does not close at some input (a closed-form dyad names the
        whole stretch of rows where it does not, and the dead points at its ends).
    BranchChangeError
        A dyad would change its assembly mode between two rows (at a change
        point, named).
    SingularPoseError
        A group is at a dead centre (or another singular pose) at some input.
    MechanismError
        Inputs away from the sketch for a mechanism with a cam without a profile
        (its replacement is instantaneous); gear meshes roll (``plan.rolling``);
        a cam with a profile (a ``cam`` statement) moves its follower by its
        program, the replacement rebuilt at every pose.
    """
    inputs = np.atleast_2d(np.asarray(inputs, dtype=float))
    if inputs.shape[1] != len(plan.drivers):
        inputs = inputs.reshape(-1, len(plan.drivers))
    unit = working_unit(plan)
    if unit != plan.unit:
        return _solved_in(in_unit(plan, unit), inputs, guess, rates)
    if len(plan.modes) > len(plan.starts):
        plan = _with_starts(plan)
    if plan.higher_pairs and np.any(inputs != 0):
        if plan.rolling is None:
            raise MechanismError(
                "the higher pair(s) "
                + ", ".join(plan.higher_pairs)
                + " are replaced by virtual links that hold at the sketch pose only; away "
                "from the sketch a cam needs its profile (a 'cam CAM LINK FILE' statement "
                "naming its program, see assur cam), a gear mesh z=za,zb and a carrier: solve "
                "at the sketch pose"
            )
        # gear meshes roll: their virtual links give way to the rolling constraints
        plan = dataclasses.replace(plan, steps=plan.rolling, higher_pairs=())
    return _through(plan, inputs, guess, rates, None)


def _with_starts(plan: SolvePlan) -> SolvePlan:
    """The plan with the poses of the assembly modes its groups are asked for, at the sketch.

    Group by group in solve order, the plan up to the group is solved at the
    sketch's inputs (the groups before it in the modes asked for), and the
    group's solutions there found (:func:`~kinematics.solvers.modes.group_solutions`).

    Raises
    ------
    AssemblyModeError
        A group has fewer modes than the one asked for.
    """
    starts: dict[str, Mapping[str, np.ndarray]] = dict(plan.starts)
    for i, step in enumerate(plan.steps):
        mode = plan.modes.get(step.label)
        if mode is None or step.label in starts:
            continue
        found = _solutions_at_sketch(plan, i, starts)
        if mode >= len(found):
            raise AssemblyModeError(_too_few(step.label, len(found), mode))
        starts[step.label] = found[mode]
    return dataclasses.replace(plan, starts=MappingProxyType(starts))


def _solutions_at_sketch(plan: SolvePlan, i: int, starts: Mapping) -> list[dict[str, np.ndarray]]:
    """The solutions of step ``i`` at the sketch's inputs, the steps before it in their modes."""
    step = plan.steps[i]
    part = dataclasses.replace(
        plan, steps=plan.steps[: i + 1], modes=MappingProxyType({}), starts=MappingProxyType(starts)
    )
    motion = _solve_poses(part, np.zeros((1, len(plan.drivers))), None, False)
    touched = {link for eq in step.equations for link in (eq.a, eq.b, eq.carrier) if link}
    known = {
        link: np.asarray(motion.q[link][0], dtype=float)
        for link in touched - set(step.links)
        if link in motion.q
    }
    first = {link: np.asarray(motion.q[link][0], dtype=float) for link in step.links}
    return group_solutions(step, part, known, first)


def _too_few(label: str, count: int, mode: int) -> str:
    """The message for a mode a group does not have."""
    if count == 1:
        return (
            f"group {label} has a single assembly mode at the sketch's inputs (its closure "
            f"equations have one solution there, found from {STARTS} starts of Newton's "
            "method), so there is no other to choose: leave it out of --flip"
        )
    return (
        f"group {label} has {count} assembly modes at the sketch's inputs, 0 to {count - 1} "
        f"(see --modes), so there is no mode {mode}"
    )


def assembly_modes(plan: SolvePlan) -> dict[str, tuple[Mode, ...]]:
    """Every group's assembly modes at the sketch's inputs, the groups before it as planned.

    A dyad has two (0, the sketch's, and 1), a PRP or RPP dyad one; the other
    groups' are found by :func:`~kinematics.solvers.modes.group_solutions`.
    Mode 0 is the one the solve takes by itself; ``make_plan(report,
    flip=[f"{label}={k}"])`` asks for mode k.
    """
    unit = working_unit(plan)
    if unit != plan.unit:  # found in a unit near the sketch's size, given back in metres
        found = assembly_modes(in_unit(plan, unit))
        per = np.array([unit, unit, 1.0])
        return {
            label: tuple(
                Mode(
                    m.index,
                    MappingProxyType({k: v * per for k, v in m.poses.items()}),
                    MappingProxyType({k: v * unit for k, v in m.pins.items()}),
                )
                for m in modes
            )
            for label, modes in found.items()
        }
    plan = _with_starts(plan) if len(plan.modes) > len(plan.starts) else plan
    out: dict[str, tuple[Mode, ...]] = {}
    for i, step in enumerate(plan.steps):
        if step.group is None:
            continue
        if step.kind is None:
            found = _solutions_at_sketch(plan, i, plan.starts)
        else:
            base = dataclasses.replace(plan, flip=plan.flip - {step.label})
            ways = [base]
            if step.kind not in single_mode_kinds:
                ways.append(dataclasses.replace(base, flip=base.flip | {step.label}))
            found = []
            for way in ways:
                part = dataclasses.replace(way, steps=way.steps[: i + 1])
                motion = _solve_poses(part, np.zeros((1, len(plan.drivers))), None, False)
                found.append({link: np.asarray(motion.q[link][0]) for link in step.links})
        out[step.label] = tuple(
            Mode(k, MappingProxyType(poses), MappingProxyType(_named_pins(plan, step, poses)))
            for k, poses in enumerate(found)
        )
    return out


def _named_pins(plan: SolvePlan, step: GroupStep, poses: Mapping[str, np.ndarray]) -> dict:
    """The named points of a group's pairs, where the links' ``poses`` put them (m)."""
    out = {}
    for eq in step.equations:
        name = equation_point(plan.mechanism, eq) if eq.kind in ("HINGE", "SLIDE") else None
        link = eq.a if eq.a in poses else eq.b
        if name is None or link not in poses:
            continue
        x, y, theta = (float(v) for v in poses[link])
        c, s = np.cos(theta), np.sin(theta)
        px, py = float(eq.point[0]), float(eq.point[1])
        out[name] = np.array([x + c * px - s * py, y + s * px + c * py])
    return out


def _followed(
    plan: SolvePlan,
    inputs: np.ndarray,
    guess: Mapping[str, np.ndarray] | None,
    rates: bool,
    origin: np.ndarray | None,
) -> Motion:
    """:func:`_checked`, Newton's groups followed through intermediate poses from ``origin``.

    ``origin`` is where the path starts (the sketch when None, else a pose
    whose links' poses ``guess`` holds); without an origin, a guess starts
    Newton at the first row with no intermediate poses.
    """
    if needs_continuation(plan) and (guess is None or origin is not None):
        dense, picks = densified(plan, inputs, origin)
        if len(dense) > len(inputs):
            return _picked(_checked(plan, dense, guess, rates, origin), inputs, picks)
    return _checked(plan, inputs, guess, rates, origin)


def _picked(motion: Motion, inputs: np.ndarray, picks: np.ndarray) -> Motion:
    """The motion at the rows ``picks`` only (the ``inputs``), as plain arrays."""
    return Motion(
        inputs,
        MappingProxyType({k: v[picks] for k, v in motion.q.items()}),
        MappingProxyType({k: v[picks] for k, v in motion.qd.items()}),
        MappingProxyType({k: v[picks] for k, v in motion.qdd.items()}),
    )


def _through(
    plan: SolvePlan,
    inputs: np.ndarray,
    guess: Mapping[str, np.ndarray] | None,
    rates: bool,
    origin: np.ndarray | None,
) -> Motion:
    """:func:`_followed`, on through a change point where the rest of the mechanism decides.

    At a change point of a closed-form dyad the linkage may go on in either
    assembly mode, unless the rest of it allows one only (a parallelogram
    with a third parallel crank: the crank holds it a parallelogram). Each
    mode is tried a little way past the change point; when exactly one
    solves, the inputs after the change point are solved in it, from there
    on (and so on at the next one). Otherwise the change point stops the solve.
    """
    try:
        return _followed(plan, inputs, guess, rates, origin)
    except BranchChangeError as exc:
        dyads.layout_discarded()
        split = _first_split(plan, inputs, guess, origin, exc)
        if split is None:
            raise
        k, point, ahead = split
        before = _followed(plan, inputs[:k], guess, rates, origin) if k else None
        start = _last_poses(before) if before is not None else guess
        options = branches.either_mode(plan, exc.group)
        modes = [option for option in options if _goes_on(option, ahead, start, point)]
        if len(modes) != 1:
            raise
        after = _through(modes[0], inputs[k:], start, rates, point)
        return _joined(inputs, before, after)


def _first_split(
    plan: SolvePlan,
    inputs: np.ndarray,
    guess: Mapping[str, np.ndarray] | None,
    origin: np.ndarray | None,
    error: BranchChangeError,
):
    """:func:`~kinematics.solvers.branches.split_at` at the first change point along the path.

    The error names a change point, not always the first one the path meets
    (a long step may pass several); the way up to just short of it is solved
    again, positions only, until no change point comes before.
    """
    for _ in range(64):
        split = branches.split_at(plan, inputs, origin, error)
        if split is None:
            return None
        k, point, _ = split
        before = inputs[k - 1] if k else (np.zeros_like(point) if origin is None else origin)
        short = point + CONTINUATION_STEP * 1e-3 * (before - point) / max(
            float(np.max(np.abs(before - point) / plan.driver_scale)), 1e-300
        )
        try:
            _followed(plan, np.vstack([inputs[:k], short[None, :]]), guess, False, origin)
        except BranchChangeError as earlier:
            error = earlier
            continue
        return split
    return None


def _goes_on(plan: SolvePlan, ahead: np.ndarray, start, origin: np.ndarray) -> bool:
    """Whether ``plan`` solves the poses ``ahead`` (just past a change point at ``origin``)."""
    try:
        _followed(plan, ahead, start, False, origin)
    except (AssemblyError, SingularPoseError):
        return False
    return True


def _last_poses(motion: Motion) -> dict[str, np.ndarray]:
    """Every link's pose at the motion's last row (where to start Newton beyond it)."""
    return {link: np.array(q[-1], dtype=float) for link, q in motion.q.items()}


def _joined(inputs: np.ndarray, before: Motion | None, after: Motion) -> Motion:
    """The motions of two stretches of ``inputs`` (the first may be None), one after the other."""
    if before is None:
        return Motion(inputs, after.q, after.qd, after.qdd)

    def joined(a: Mapping[str, np.ndarray], b: Mapping[str, np.ndarray]) -> MappingProxyType:
        return MappingProxyType({k: np.concatenate([a[k], b[k]]) for k in b if k in a})

    return Motion(
        inputs, *(joined(getattr(before, k), getattr(after, k)) for k in ("q", "qd", "qdd"))
    )


def _solved_in(
    plan: SolvePlan, inputs: np.ndarray, guess: Mapping[str, np.ndarray] | None, rates: bool
) -> Motion:
    """:func:`solve_poses` of a plan measured in a unit of its own, the motion back in metres.

    The links' displacements and their rates are multiplied by ``plan.unit``
    (a power of two: exact); angles, ω and ε are the same in any unit. The
    inputs are a copy, so that the solve writes nothing into a sweep's layout
    (which wants metres).
    """
    unit = plan.unit
    if guess is not None:
        per = np.array([unit, unit, 1.0])
        guess = {link: np.asarray(value, dtype=float) / per for link, value in guess.items()}
    motion = solve_poses(plan, inputs.copy(), guess, rates=rates)

    def metres(table: Mapping[str, np.ndarray]) -> MappingProxyType:
        out = {}
        for link, value in table.items():
            value = np.array(value, dtype=float)
            value[:, :2] *= unit
            out[link] = value
        return MappingProxyType(out)

    return Motion(inputs, metres(motion.q), metres(motion.qd), metres(motion.qdd))


def _checked(
    plan: SolvePlan,
    inputs: np.ndarray,
    guess: Mapping[str, np.ndarray] | None,
    rates: bool,
    origin: np.ndarray | None = None,
) -> Motion:
    """:func:`_solve_poses` over a path of inputs, with no silent change of assembly mode.

    The steps the closed-form dyads watch are looked into with finer steps
    (:func:`kinematics.solvers.branches.confirm_branches`); a path with steps coarser
    than the continuation step is first checked on intermediate poses, positions
    only, from its origin on (the sketch, when None; else a change point, which
    is not solved itself). A path from the sketch that starts away from it is
    looked into from the sketch to its first row too. A single pose keeps the
    sketch's mode without a path to check.
    """
    positions = _positions_of(plan, guess if origin is not None else None)
    watch: list = Watch()
    motion = _precise_errors(
        plan, inputs, lambda found: _solve_poses(plan, inputs, guess, rates, found), watch
    )
    if len(inputs) < 2 and origin is None:
        return motion
    start = np.zeros(inputs.shape[1]) if origin is None else origin
    path = inputs
    if _largest_step(plan, inputs, start) > CONTINUATION_STEP and len(
        dense := densified(plan, inputs, origin)[0]
    ) > len(inputs):
        path, watch = dense, Watch()
        _precise_errors(plan, dense, lambda found: positions(dense, found), watch)
    if watch:
        branches.confirm_branches(plan, path, watch, positions)
    if origin is None and np.any(path[0] != 0.0):  # the step from the sketch, looked into too
        head = np.vstack([np.zeros((1, path.shape[1])), path[:2]])
        watch = Watch()
        _precise_errors(plan, head, lambda found: positions(head, found), watch)
        if watch:
            branches.confirm_branches(plan, head, watch, positions)
    return motion


def _largest_step(plan: SolvePlan, inputs: np.ndarray, start: np.ndarray) -> float:
    """The largest step between rows (and from ``start`` to the first), in units of scale."""
    scale = plan.driver_scale
    first = float(np.max(np.abs(inputs[0] - start) / scale))
    steps = np.abs(np.diff(inputs, axis=0))
    return max(first, float(np.max(steps / scale)) if steps.size else 0.0)


def _positions_of(plan: SolvePlan, guess: Mapping[str, np.ndarray] | None = None):
    """``solve(rows, watch, groups)``: the plan's positions at ``rows``, watched steps to ``watch``.

    With ``groups`` (labels), only the steps up to the last of them are solved;
    ``guess`` starts Newton at the first row.
    """

    def positions(rows: np.ndarray, watch: list | None, groups=None) -> Motion:
        part = plan
        if groups:
            last = max(i for i, step in enumerate(plan.steps) if step.label in groups)
            part = dataclasses.replace(plan, steps=plan.steps[: last + 1])
        return _solve_poses(part, rows, guess, False, watch)

    return positions


def _precise_errors(plan: SolvePlan, inputs: np.ndarray, solve, watch: list) -> Motion:
    """``solve(watch)``, its errors made precise along the path of ``inputs``.

    A group solved before the one that failed may have changed its assembly
    mode on the way: that is looked into first. A closed-form dyad that does
    not close names the whole stretch of inputs and its dead points; a dead
    centre inside a path that goes on through it is a change point
    (:class:`~kinematics.errors.BranchChangeError`).
    """
    try:
        return solve(watch)
    except MechanismError as exc:
        if len(inputs) > 1 and watch:
            branches.confirm_branches(plan, inputs, watch, _positions_of(plan))
        if isinstance(exc, SingularPoseError) and exc.dead_centre and exc.indices is not None:
            k = int(exc.indices[0])
            if branches.is_change_point(inputs, k):
                raise branches.change_point(plan, exc.group, inputs[k]) from None
        if type(exc) is AssemblyError and exc.indices is not None:
            raise branches.unassembled_range(plan, inputs, exc, _positions_of(plan)) from None
        raise


def _solve_poses(
    plan: SolvePlan,
    inputs: np.ndarray,
    guess: Mapping[str, np.ndarray] | None,
    rates: bool = True,
    watch: list | None = None,
) -> Motion:
    """Every group in turn, for every pose; the rates only with ``rates``.

    The steps where a closed-form dyad may have changed its assembly mode are
    appended to ``watch``.
    """
    n = inputs.shape[0]
    ground = plan.mechanism.ground
    frames: dict[str, Frame] = {}
    q, qd, qdd = tables = tuple(LinkTable(frames, order, n) for order in ("q", "qd", "qdd"))
    _place_drivers(plan, inputs, frames, tables)
    pins = dyads.PinCache()
    for step in plan.steps:
        if step.cam is not None:  # a designed cam: its program places the follower
            solve_cam_step(step.cam, tables, inputs, rates, plan.driver_kinds)
            continue
        # looked up on the module at call time, so a test can switch a closed form off
        if dyads.frame_dyad(step, plan, frames, tables, pins, inputs, rates, watch):
            continue
        mode = plan.starts.get(step.label, {})
        if not mode and not (guess and any(link in guess for link in step.links)):
            suspect = triads.frame_triad(step, plan, frames, tables, pins, inputs, rates)
            if suspect is not None:
                if suspect.any():
                    _screen(step, plan, q, inputs, np.flatnonzero(suspect))
                continue
        if not dyads.place_dyad(step, plan, q, inputs):
            start = {
                link: np.array(
                    guess[link] if guess and link in guess else mode.get(link, np.zeros(3)),
                    dtype=float,
                )
                for link in step.links
            }
            follow(step, plan, q, inputs, start)
        if rates:
            _rates(step, plan, tables, inputs)
    zero = np.zeros((n, 3))
    q.setdefault(ground, zero)
    if not rates:
        empty: Mapping[str, np.ndarray] = MappingProxyType({})
        # positions only: the joints as the closed forms found them (the full solve carries
        # them through their links' frames, as it always has: the two agree to rounding)
        return Motion(inputs, q, empty, empty, MappingProxyType(frames), dict(pins))
    for table in (qd, qdd):
        table.setdefault(ground, zero)
    return Motion(inputs, q, qd, qdd, MappingProxyType(frames), pins.on_frames())


def _rates(step: GroupStep, plan: SolvePlan, tables: tuple, inputs: np.ndarray) -> None:
    """A placed group's velocities and accelerations from its Jacobian, for every pose.

    ``J_g·q̇_g = −J_k·q̇_k`` and ``J_g·q̈_g = −J_k·q̈_k − (dJ/dt)·q̇``, as batched
    linear solves (least squares for a redundant link's consistent rows, in the
    sketch's unit of length, :func:`~kinematics.solvers.newton.scaled_jacobian`, so that
    the answer does not depend on the unit). The dead-centre test is on that
    scaled Jacobian too.

    Raises
    ------
    SingularPoseError
        The group's Jacobian loses rank at some pose (a dead centre).
    """
    q, qd, qdd = tables
    n = inputs.shape[0]
    _, jac, known_v, _ = group_system(step.links, step.equations, q, qd, n)
    angles = angle_rows(step.equations)
    scaled = scaled_jacobian(jac, plan.length, angles)
    if step.group is not None:
        _no_dead_centre(step, plan, _conditioning(scaled), inputs)
    z_dot = _rate_solve(jac, scaled, plan.length, angles, -known_v[..., None])[..., 0]
    for i, link in enumerate(step.links):
        qd[link] = z_dot[:, 3 * i : 3 * i + 3]
    _, _, known_a, _ = group_system(step.links, step.equations, q, qdd, n)
    _, _, _, bias = group_system(step.links, step.equations, q, qd, n)
    z_ddot = _rate_solve(jac, scaled, plan.length, angles, (-known_a - bias)[..., None])[..., 0]
    for i, link in enumerate(step.links):
        qdd[link] = z_ddot[:, 3 * i : 3 * i + 3]


def _no_dead_centre(step: GroupStep, plan: SolvePlan, ratio: np.ndarray, inputs: np.ndarray):
    """Raise at the first of ``inputs`` whose Jacobian's σ_min/σ_max ``ratio`` is a dead centre."""
    if (ratio <= DEAD_CENTRE).any():
        k = int(np.argmax(ratio <= DEAD_CENTRE))
        raise SingularPoseError.at(
            step.label, inputs[k], f"σ_min/σ_max = {ratio[k]:.2g}", plan.driver_kinds
        )


def _screen(step: GroupStep, plan: SolvePlan, q, inputs: np.ndarray, rows: np.ndarray) -> None:
    """A closed-form triad's suspect ``rows`` screened as :func:`_rates` screens every pose.

    Raises
    ------
    SingularPoseError
        The group's scaled Jacobian loses rank at one of the rows.
    """
    touched = {link for eq in step.equations for link in (eq.a, eq.b)}
    part = {link: q[link][rows] for link in touched if link in q}
    _, jac, _, _ = group_system(step.links, step.equations, part, {}, len(rows))
    scaled = scaled_jacobian(jac, plan.length, angle_rows(step.equations))
    _no_dead_centre(step, plan, _conditioning(scaled), inputs[rows])


def _conditioning(jac: np.ndarray) -> np.ndarray:
    """σ_min/σ_max of each pose's Jacobian (N, m, k).

    For square Jacobians ``1/(‖J‖_F·‖J⁻¹‖_F)`` is a lower bound of it, within a
    factor m: only the poses it flags get a singular value decomposition, which
    costs several times an inverse.
    """
    ratio = np.ones(jac.shape[0])
    suspect = np.ones(jac.shape[0], dtype=bool)
    if jac.shape[1] == jac.shape[2]:
        try:
            inv = np.linalg.inv(jac)
        except np.linalg.LinAlgError:  # some pose exactly singular
            inv = None
        if inv is not None:
            bound = 1.0 / (np.linalg.norm(jac, axis=(1, 2)) * np.linalg.norm(inv, axis=(1, 2)))
            suspect = ~(bound > DEAD_CENTRE)  # NaN (an overflowed inverse) is suspect too
    if suspect.any():
        s = np.linalg.svd(jac[suspect], compute_uv=False)
        ratio[suspect] = s[:, -1] / s[:, 0]
    return ratio


def _rate_solve(
    jac: np.ndarray, scaled: np.ndarray, length: float, angles: np.ndarray, rhs: np.ndarray
) -> np.ndarray:
    """Batched ``jac·z = rhs``, its ``angles`` rows (and those of ``rhs``) × ``length``.

    A square system is then solved as it stands: every row is a length, and
    the column scaling of ``scaled`` would not change the pivots. A redundant
    link's consistent, overdetermined rows go by least squares through
    ``scaled`` (``jac`` in the sketch's unit of length), the θ entries of the
    answer divided by ``length``. Either way the rows weigh alike in any unit.
    """
    rhs = rhs.copy()
    rhs[:, angles] *= length
    if jac.shape[1] == jac.shape[2]:
        if angles.any():
            jac = jac.copy()
            jac[:, angles, :] *= length
        return np.linalg.solve(jac, rhs)
    out = np.linalg.pinv(scaled) @ rhs
    out[:, 2::3] /= length
    return out


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.flags.writeable = False
    return a


def solve_pose(
    plan: SolvePlan,
    inputs: tuple[float, ...] | None = None,
    guess: Mapping[str, np.ndarray] | None = None,
) -> KinematicState:
    """Positions, velocities and accelerations at one input (default: the sketch).

    Raises
    ------
    AssemblyError
        A group does not close at this input.
    SingularPoseError
        A group is at a dead centre.
    """
    inputs = tuple(0.0 for _ in plan.drivers) if inputs is None else tuple(inputs)
    motion = solve_poses(plan, np.array([inputs], dtype=float).reshape(1, -1), guess)
    m = plan.mechanism
    links = {
        link: LinkState(
            _frozen(motion.q[link][0]), _frozen(motion.qd[link][0]), _frozen(motion.qdd[link][0])
        )
        for link in m.moving_links
        if link in motion.q
    }
    points = {}
    for name, (link, c) in plan.points.items():
        if link not in motion.q:  # on a virtual link, which a rolling gear mesh does without
            continue
        x, v, a = motion.point(link, c)
        points[name] = PointState(link, _frozen(x[0]), _frozen(v[0]), _frozen(a[0]))
    return KinematicState(MappingProxyType(links), MappingProxyType(points), inputs)
