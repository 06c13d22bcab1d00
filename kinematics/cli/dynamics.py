"""``assur dynamics`` and ``assur balance``: the machine's motion, its flywheel, its shaking.

``dynamics`` reduces the machine to its driver (J_r, M_r over the cycle), finds
its steady running, the flywheel for ``--delta``, the start-up and the run-down,
and the shaking force and moment; as text, JSON (``--json``), figures
(``--plot``) or the worked solution (``--explain``). ``balance`` adds the
counterweights that balance the shaking force and writes the balanced
mechanism (``-o``).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
from pathlib import Path

import numpy as np

from structure.errors import MechanismError, StatementError, UsageError
from structure.readwrite.edgelist import read_edgelist
from structure.readwrite.formats import WRITE_SUFFIXES, mechanism_text
from structure.report import analyze

from ..dynamics.analysis import MachineDynamics, dynamics_to_dict, machine_dynamics
from ..dynamics.balancing import Balanced, balance, balanced_to_dict
from ..dynamics.loads import FROM_FILE, law_text, parse_drive
from ..dynamics.machine import MAX_POSES
from ..explain.dynamics import explain_dynamics
from .output import EXIT_OK, check_finite, failed, print_json, title_lines, vector, write_lines
from .plotting import check_plot, load_drawing

__all__ = ["run_balance", "run_dynamics"]


def _options(args: argparse.Namespace):
    """The checked ``--delta``, ``--drive``, ``--omega`` and ``--steps``.

    Raises
    ------
    UsageError
        A value out of its range, or a ``--drive`` that is no law.
    """
    delta = getattr(args, "delta", 0.02)
    if not 0 < delta < 2 or not math.isfinite(delta):
        raise UsageError(f"--delta is a coefficient of speed fluctuation in (0, 2), not {delta:g}")
    omega = args.omega
    if omega is not None and (not omega > 0 or not math.isfinite(omega) or omega > 1e150):
        raise UsageError(f"--omega is a mean speed in rad/s, a positive number, not {omega:g}")
    steps = getattr(args, "steps", 360)
    if not 16 <= steps <= MAX_POSES:
        raise UsageError(f"--steps is the poses per turn, from 16 to {MAX_POSES}, not {steps}")
    drive = FROM_FILE
    if getattr(args, "drive", None) is not None:
        try:
            drive = parse_drive(args.drive)
        except StatementError as exc:
            raise UsageError(
                f"--drive {args.drive!r}: {exc.reason} (a number, motor=M0,W0, "
                "table=DEG:VALUE,..., formula=EXPRESSION or none)"
            ) from None
    return delta, omega, steps, drive


def run_dynamics(args: argparse.Namespace) -> int:
    """The dynamics of ``args.file``'s machine; returns the exit code."""
    delta, omega, steps, drive = _options(args)
    try:
        check_plot(args.plot)
        report = analyze(read_edgelist(args.file))
        result = machine_dynamics(report, drive=drive, delta=delta, speed=omega, steps=steps)
        data = dynamics_to_dict(result)
        check_finite(data)
    except MechanismError as exc:
        return failed(exc, args.json)
    if args.plot:
        try:
            load_drawing().save_dynamics_sheet(result, args.plot)
        except MechanismError as exc:
            return failed(exc, args.json)
    if args.json:
        print_json(data)
    elif args.explain:
        sys.stdout.write(explain_dynamics(result, args.lang, args.explain))
    else:
        write_lines(dynamics_lines(result))
    return EXIT_OK


# ------------------------------------------------------------------ the text answer
def _at(phi: np.ndarray, values: np.ndarray, pick, unit: str = "") -> str:
    k = int(pick(values))
    unit = f" {unit}" if unit else ""
    return f"{values[k] + 0.0:.6g}{unit} at {math.degrees(float(phi[k])) % 360:.4g}°"


def _rpm(omega: float) -> str:
    return f"{omega:.6g} rad/s ({omega * 30 / math.pi:.4g} rpm)"


def dynamics_lines(result: MachineDynamics) -> list[str]:
    """The text answer of ``assur dynamics``."""
    machine = result.machine
    props = machine.properties
    phi = props.phi
    out = title_lines(result.report.mechanism)
    out.append(f"Driver {machine.driver}; φ is its rotation from the sketch, counter-clockwise.")
    for note in result.notes:
        out.append(f"Note: {note}")
    out.append("")
    out.append("Reduced inertia J_r(φ) = Σ (m·v_S² + J_S·ω²)/ω1² (kg·m²):")
    out.append(
        f"  min {_at(phi, props.inertia, np.argmin)}, max {_at(phi, props.inertia, np.argmax)}, "
        f"mean {float(np.mean(props.inertia[:-1])):.6g}"
    )
    if props.shares:
        shares = ", ".join(
            f"link {link} {float(np.mean(v[:-1])):.6g}" for link, v in props.shares.items()
        )
        out.append(f"  mean share by link: {shares}")
    out.append(
        f"  dJ_r/dφ from the accelerations: from {float(np.min(props.slope)) + 0.0:.6g} to "
        f"{float(np.max(props.slope)) + 0.0:.6g} kg·m²/rad"
    )
    out.append("")
    out.append("Reduced moment M_r(φ, ω) (N·m, reduced to the driver):")
    for term in machine.terms:
        law = f": {law_text(term.law)}" if term.law is not None else ""
        out.append(f"  - {term.label}{law}")
    if not machine.terms:
        out.append("  - no drive and no load")
    moment = result.moment
    speed = (
        "the steady running's" if result.steady is not None else f"{result.speed or 0:.6g} rad/s"
    )
    out.append(
        f"  at {speed} speed: min {_at(phi, moment, np.argmin)}, max {_at(phi, moment, np.argmax)}"
    )
    if result.inertia_torque is not None:
        w, e, torque = result.inertia_torque
        out.append("")
        out.append(
            f"Inertia torque of the links at the file's ω = {w:.6g} rad/s, ε = {e:.6g} rad/s²: "
            f"−(J_r·ε + ½·J_r'·ω²) from {float(np.min(torque)) + 0.0:.6g} to "
            f"{float(np.max(torque)) + 0.0:.6g} N·m (the motor supplies its opposite)"
        )
    steady = result.steady
    if steady is not None:
        how = "closed form and one root" if steady.method == "energy" else "shooting one turn"
        out.append("")
        out.append(f"Steady running (the periodic motion, found directly: {how}):")
        out.append(
            f"  ω_m = (ω_max + ω_min)/2 = {_rpm(steady.omega_mean)}; the time mean 2π/T = "
            f"{steady.omega_time_mean:.6g} rad/s; a turn takes T = {steady.period:.6g} s"
        )
        out.append(
            f"  ω_max = {_at(steady.phi, steady.omega, np.argmax, 'rad/s')}, ω_min = "
            f"{_at(steady.phi, steady.omega, np.argmin, 'rad/s')}"
        )
        out.append(
            f"  δ = (ω_max − ω_min)/ω_m = {steady.delta:.6g} "
            f"(over the time mean: {steady.delta_time_mean:.6g})"
        )
        if result.drive_power is not None:
            out.append(f"  the drive's mean power: {result.drive_power:.6g} W")
    wheel = result.flywheel
    if wheel is not None:
        out.append("")
        out.append(f"Flywheel for δ = {wheel.delta_goal:g} at ω_m = {wheel.omega_mean:.6g} rad/s:")
        if wheel.needed:
            check = f" (check: steady running with it gives δ = {wheel.steady.delta:.6g})" if (
                wheel.steady is not None
            ) else ""  # fmt: skip
            out.append(
                f"  exact, Wittenbauer's energy–inertia diagram: J_F = {wheel.exact:.6g} kg·m²"
                f"{check}"
            )
        else:
            out.append(
                f"  none is needed: the machine's own inertia keeps δ at {wheel.steady.delta:.6g}"
                if wheel.steady is not None
                else "  none is needed"
            )
        out.append(
            f"  approximate, ΔE_max/(δ·ω_m²) = {wheel.energy_swing:.6g}/({wheel.delta_goal:g}·"
            f"{wheel.omega_mean:.6g}²) = {wheel.approximate:.6g} kg·m²; less the mechanism's "
            f"mean J_r: {wheel.approximate_less_mean:.6g} kg·m²"
        )
        out.append(
            "  The approximate formula takes the machine as one constant inertia and the swing "
            "of the loads' energy alone; the exact one lets J_r(φ) store and give back the "
            "links' own kinetic energy over the turn."
        )
    if result.start is not None:
        run = result.start
        reached = "within 0.1% of steady running" if run.ending == "steady" else "still short"
        out.append("")
        out.append(
            f"Start-up from rest: {reached} after {run.duration:.6g} s ({len(run.turns)} turns)"
        )
    if result.stop is not None:
        run = result.stop
        out.append("")
        if run.ending == "stopped":
            out.append(
                f"Run-down with the drive off: stops after {run.duration:.6g} s, "
                f"{float(run.phi[-1] - run.phi[0]) / (2 * math.pi):.4g} turns "
                f"(at φ = {math.degrees(float(run.phi[-1])) % 360:.4g}°)"
            )
        elif run.ending == "slowed":
            out.append(
                f"Run-down with the drive off: below 0.1% of its speed after {run.duration:.6g} s"
                f", {float(run.phi[-1] - run.phi[0]) / (2 * math.pi):.4g} turns"
            )
        else:
            out.append(f"Run-down with the drive off: still turning after {run.duration:.6g} s")
    shaken = result.shaking
    if shaken is not None:
        about = shaken.about_name or vector(shaken.about)
        out.append("")
        out.append(
            f"Shaking on the frame at {shaken.omega:.6g} rad/s: force up to "
            f"{shaken.force_max:.6g} N, moment about {about} up to {shaken.moment_max:.6g} N·m"
        )
    return out


# ------------------------------------------------------------------ assur balance
def _write(mechanism, path: str, source: str) -> None:
    """Write the balanced mechanism by the extension of ``path``: whole, or not at all."""
    target = Path(path)
    if target.suffix.lower() not in WRITE_SUFFIXES:
        raise UsageError(
            f"-o {path}: the balanced mechanism is written as {', '.join(WRITE_SUFFIXES)}"
        )
    if target.exists() and target.resolve() == Path(source).resolve():
        raise UsageError(f"-o {path} is the file read: write the balanced mechanism elsewhere")
    text = mechanism_text(mechanism, target.suffix)
    try:
        handle, temporary = tempfile.mkstemp(dir=target.parent or ".", suffix=".tmp")
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(text)
        os.replace(temporary, target)
    except OSError as exc:
        raise MechanismError(f"cannot write {path}: {exc.strerror or exc}") from exc


def run_balance(args: argparse.Namespace) -> int:
    """Balance ``args.file``'s shaking force; write the balanced mechanism to ``-o``."""
    if args.radius is not None and (not args.radius > 0 or not math.isfinite(args.radius)):
        raise UsageError(f"--radius is a distance in metres, positive, not {args.radius:g}")
    if not 0 <= args.fraction <= 1:
        raise UsageError(
            f"--fraction is a part of the reciprocating mass, in [0, 1], not {args.fraction:g}"
        )
    _, omega, _, _ = _options(args)
    try:
        check_plot(args.plot)
        report = analyze(read_edgelist(args.file))
        result = balance(
            report, method=args.method, omega=omega, radius=args.radius, fraction=args.fraction
        )
        data = balanced_to_dict(result)
        check_finite(data)
        if args.output:
            _write(result.mechanism, args.output, args.file)
            data["output"] = args.output
        if args.plot:
            load_drawing().save_balance_sheet(result, args.plot)
    except UsageError:
        raise
    except MechanismError as exc:
        return failed(exc, args.json)
    if args.json:
        print_json(data)
    else:
        write_lines(balance_lines(result, args.output))
    return EXIT_OK


def balance_lines(result: Balanced, output: str | None) -> list[str]:
    """The text answer of ``assur balance``."""
    out = title_lines(result.mechanism)
    names = {
        "complete": "complete shaking-force balance (Berkof–Lowen, linearly independent vectors)",
        "primary": f"primary balance of a crank–slider ({result.fraction:g} of the "
        "reciprocating mass)"
        if result.fraction is not None
        else "primary balance",
        "static": "static balance of each link pinned to the frame",
    }
    out.append(f"Method: {names[result.method]}; compared at {result.before.omega:.6g} rad/s")
    out.append("")
    if not result.counterweights:
        out.append("No counterweight is needed.")
    for w in result.counterweights:
        out.append(
            f"Counterweight on link {w.link}: {w.mass:.6g} kg at {vector(w.position)} m "
            f"({w.radius:.6g} m from {w.pivot}); point CW{w.link}, a 'mass' line"
        )
    out.append("")
    rows = (
        ("peak shaking force", "N", result.before.force_max, result.after.force_max),
        ("peak shaking moment", "N·m", result.before.moment_max, result.after.moment_max),
        (
            "peak driving torque",
            "N·m",
            float(np.max(np.abs(result.torque_before))),
            float(np.max(np.abs(result.torque_after))),
        ),
    )
    for label, unit, before, after in rows:
        out.append(f"  {label}: {before:.6g} {unit} before, {after:.6g} {unit} after")
    h, h2 = result.harmonics, result.harmonics_after
    if h is not None and h2 is not None:
        out.append(
            f"  along the slide: primary (1st harmonic) {h.primary:.6g} N → {h2.primary:.6g} N, "
            f"secondary (2nd) {h.secondary:.6g} N → {h2.secondary:.6g} N"
        )
        out.append(
            f"  (reciprocating mass {h.reciprocating:.6g} kg, rotating mass moment "
            f"{h.rotating:.6g} kg·m, crank {h.crank:.6g} m, rod {h.rod:.6g} m)"
        )
    for note in result.notes:
        out.append(f"Note: {note}")
    if output:
        out.append("")
        out.append(f"wrote {output}")
    return out
