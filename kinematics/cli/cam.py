"""``assur cam SPEC.json``: a cam designed from its follower's motion, checked and written out.

Prints the design's summary (the program's table with each segment's peaks,
the continuity at each join, the peaks, the pressure angle, the radii of
curvature, undercut, the flat face's width, the smallest base circle, the
force closure); ``--json`` the same as data (the issue's contract keys);
``--explain`` the worked solution of the checks (English or Vietnamese).
``--plot`` draws the SVAJ diagrams beside the profile; ``--profile`` writes
the profile as DXF, SVG or CSV; ``-o`` writes the mechanism (JSON with the
program inline, or an edge list with the program beside it) for the other
commands. Exit codes: 0, 1 a bad spec or an impossible cam (named), 2 usage.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import tempfile
from pathlib import Path

from structure.cams import cam_spec_to_dict
from structure.errors import MechanismError, UsageError
from structure.readwrite.camfile import read_cam_spec
from structure.readwrite.edgelist import write_edgelist
from structure.readwrite.jsonformat import mechanism_to_json

from ..cams.design import CamDesign, make_design
from ..cams.export import PROFILE_SUFFIXES, write_profile
from ..cams.mechanism import cam_mechanism
from ..cams.summary import CONVENTIONS, CamReport, cam_report, cam_report_to_dict
from ..explain.cam import explain_cam
from .output import EXIT_OK, EXIT_USAGE, check_finite, fail, failed, print_json, write_lines
from .plotting import check_plot, load_drawing

__all__ = ["MAX_SAMPLES", "run_cam"]

#: the most samples a design is checked on (the arrays are a few per sample)
MAX_SAMPLES = 1_000_000
#: the mechanism files ``-o`` writes
MECHANISM_SUFFIXES = (".json", ".edges")


def _check_outputs(args: argparse.Namespace) -> None:
    """Refuse bad output names before any work; never write over the spec itself."""
    check_plot(args.plot)
    spec = Path(args.file).resolve()
    for path in [*(args.profile or []), *([args.output] if args.output else [])]:
        if Path(path).resolve() == spec:
            raise UsageError(f"{path} is the spec being read: write to another file")
    for path in args.profile or []:
        if Path(path).suffix.lower() not in PROFILE_SUFFIXES:
            raise UsageError(f"--profile {path}: use .dxf, .svg or .csv")
    if args.output and Path(args.output).suffix.lower() not in MECHANISM_SUFFIXES:
        raise UsageError(f"-o {args.output}: write the mechanism as .json or .edges")


def _write_text(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file renamed over it (no half file)."""
    handle, temporary = tempfile.mkstemp(dir=path.parent or ".", prefix=f".{path.name}.")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(text)
        os.replace(temporary, path)
    except OSError as exc:
        Path(temporary).unlink(missing_ok=True)
        raise MechanismError(f"cannot write {path}: {exc.strerror or exc}") from exc


def _write_mechanism(design: CamDesign, path: Path, at: float) -> list[str]:
    """``-o``: the mechanism as JSON (the program inline) or an edge list and its program."""
    if path.suffix.lower() == ".json":
        _write_text(path, mechanism_to_json(cam_mechanism(design, at_deg=at)) + "\n")
        return [f"wrote {path}"]
    program = path.with_name(path.stem + ".cam.json")
    mechanism = cam_mechanism(design, at_deg=at, program=program.name)
    _write_text(program, json.dumps(cam_spec_to_dict(design.spec), indent=2) + "\n")
    _write_text(path, write_edgelist(mechanism))
    return [f"wrote {path} and its program {program}"]


def run_cam(args: argparse.Namespace) -> int:
    """Design, check and write out the cam of ``args.file``; returns the exit code."""
    if not 16 <= args.samples <= MAX_SAMPLES:
        return fail(f"--samples must be between 16 and {MAX_SAMPLES}", EXIT_USAGE)
    try:
        _check_outputs(args)
        design = make_design(read_cam_spec(args.file))
        report = cam_report(design, args.samples)
        data = cam_report_to_dict(report)
        check_finite(data)
        written: list[str] = []
        if args.plot:
            load_drawing().save_cam_sheet(design, args.plot, min(args.samples, 3600))
            written.append(f"wrote {args.plot}")
        for path in args.profile or []:
            write_profile(design, path, max(args.samples, 720))
            written.append(f"wrote {path}")
        if args.output:
            written += _write_mechanism(design, Path(args.output), args.at)
    except UsageError as exc:
        return fail(str(exc), EXIT_USAGE)
    except MechanismError as exc:
        return failed(exc, args.json)
    if args.json:
        print_json(data)
    elif args.explain:
        sys.stdout.write(explain_cam(report, args.lang, args.explain))
    else:
        write_lines(_summary(args.file, report))
    if written:
        sys.stderr.write("\n".join(written) + "\n")
    return EXIT_OK


def _g(x: float | None, unit: str = "") -> str:
    if x is None:
        return "none"
    return f"{x:.6g}{(' ' + unit) if unit else ''}"


def _summary(source: str, report: CamReport) -> list[str]:
    """The text answer of ``assur cam``."""
    design = report.design
    spec, layout = design.spec, design.layout
    f = spec.follower
    unit = design.lift_unit
    rate = "rad" if not design.translating else "m"
    sense = "counter-clockwise" if layout.sense > 0 else "clockwise"
    out = [f"{spec.name or 'disc cam'}  ({source})", ""]
    if f.translating:
        where = f"axis at x = {layout.axis:+g} m" if f.contact.value != "flat" else "flat face"
        follower = f"translating {f.contact.value} follower, offset {f.offset:g} m ({where})"
    else:
        follower = (
            f"oscillating {f.contact.value} follower, pivot ({f.pivot[0]:g}, {f.pivot[1]:g}) m"
            + (f", arm {f.arm:g} m" if f.arm else "")
        )
    if layout.roller_radius:
        follower += f", roller {layout.roller_radius:g} m"
    out.append(f"Follower: {follower}")
    out.append(
        f"Base circle {spec.base_radius:g} m, prime circle {layout.prime:g} m; the cam turns "
        f"{sense} at {abs(spec.omega):g} rad/s"
    )
    out.append("")
    out.append(
        f"Program (s in {unit}; v, a, j at {abs(spec.omega):g} rad/s in {rate}/s, {rate}/s², "
        f"{rate}/s³):"
    )
    out.append("  #  law                  from →   to      lift      v max      a max      j max")
    for x in report.segments:
        out.append(
            f"  {x.index + 1:<2} {x.law.value:<20} {x.start_deg:>4g}° → {x.end_deg:>4g}°"
            f" {x.lift:>+9.4g} {x.v:>10.4g} {x.a:>10.4g} {x.j:>10.4g}"
        )
    out.append("")
    out.append("Joins (order of continuity; an acceleration jump is an infinite jerk):")
    names = {x.index: x.law.value for x in report.segments}
    for join in report.joins:
        what = {
            -1: "the displacement jumps",
            0: "the velocity jumps: infinite acceleration",
            1: "the acceleration jumps: INFINITE JERK",
            2: "the jerk jumps (finite)",
            3: "s, v, a, j continuous",
        }[join.order]
        out.append(
            f"  {join.at_deg:g}°: {names[join.before]} → {names[join.after]}: {join.name}, {what}"
        )
    if report.infinite_jerk_at:
        at = ", ".join(f"{x:g}°" for x in report.infinite_jerk_at)
        out.append(
            f"  The fundamental law of cam design (s, v, a continuous) is broken at {at}: "
            "use laws that match the acceleration at those joins (e.g. cycloidal beside a dwell)"
        )
    out.append("")
    pv, pa, pj = (report.peaks[k] for k in "vaj")
    out.append(
        f"Peaks: v {pv.value:.6g} {rate}/s at {pv.at_deg:g}°, a {pa.value:.6g} {rate}/s² at "
        f"{pa.at_deg:g}°, j {pj.value:.6g} {rate}/s³ at {pj.at_deg:g}° (largest finite)"
    )
    checks = report.checks
    verdict = "ok" if checks.pressure_ok else "TOO LARGE"
    out.append(
        f"Pressure angle: largest {checks.pressure.value:+.4f}° at {checks.pressure.at_deg:g}° "
        f"(limit {checks.limit:g}°: {verdict})"
    )
    out.append("Radius of curvature (smallest convex; smallest concave):")
    if checks.pitch_min is not None:
        out.append(f"  pitch curve: {_radius(checks.pitch_min)}; {_radius(checks.pitch_concave)}")
    out.append(f"  profile: {_radius(checks.profile_min)}; {_radius(checks.profile_concave)}")
    if checks.undercut:
        where = ", ".join(f"{a:g}°–{b:g}°" for a, b in checks.undercut_at)
        out.append(f"Undercut: YES at {where}: the profile loops (or has a cusp) there")
    else:
        out.append("Undercut: none")
    if checks.face is not None:
        out.append(
            f"Flat face: the contact runs from {checks.face[0]:+.6g} to {checks.face[1]:+.6g} m "
            f"along the face: at least {checks.face_width:.6g} m wide"
        )
    base = report.base
    if base.base_radius is None:
        out.append(f"Smallest base circle for {base.limit:g}° and no undercut: none reachable")
    else:
        line = (
            f"Smallest base circle for {base.limit:g}° and no undercut: {base.base_radius:.6g} m "
            f"(set by the {base.bound})"
        )
        if base.best_offset is not None:
            line += (
                f"; with the best offset {base.best_offset:.6g} m, {base.best_base_radius:.6g} m"
            )
        out.append(line)
    out.extend(_closure_lines(report))
    out.append("")
    out.append("Conventions:")
    for key in ("offset", "pressure_angle", "curvature", "oscillating", "load"):
        if key == "offset" and not f.translating:
            continue
        if key == "oscillating" and f.translating:
            continue
        out.append(f"  {key.replace('_', ' ')}: {CONVENTIONS[key]}")
    return out


def _radius(x) -> str:
    return "none" if x is None else f"{x.value:.6g} m at {x.at_deg:g}°"


def _closure_lines(report: CamReport) -> list[str]:
    closure = report.closure
    design = report.design
    spec = design.spec
    force = "N·m" if not design.translating else "N"
    out = [""]
    out.append(
        f"Force closure at {abs(spec.omega):g} rad/s (mass or inertia, load, spring as given):"
    )
    out.append(
        f"  contact force: largest {closure.peak_contact.value:.6g} N at "
        f"{closure.peak_contact.at_deg:g}°; camshaft torque: largest "
        f"{closure.peak_torque.value:.6g} N·m at {closure.peak_torque.at_deg:g}°"
    )
    if closure.lost_at:
        where = ", ".join(f"{a:g}°–{b:g}°" for a, b in closure.lost_at)
        out.append(f"  CONTACT LOST at {where}: the follower jumps off the cam")
    jump = closure.jump_speed
    if jump is None:
        out.append("  jump speed: none (the follower never leaves the cam)")
    elif jump == 0.0:
        out.append("  jump speed: 0 (the spring and load pull the follower off even at rest)")
    else:
        rpm = jump * 60.0 / (2.0 * math.pi)
        out.append(f"  jump speed: {jump:.6g} rad/s ({rpm:.6g} rev/min)")
    out.append(
        f"  to keep contact up to {closure.up_to:g} rad/s: preload ≥ {closure.preload_needed:.6g} "
        f"{force} with the given rate; rate ≥ {_g(closure.rate_needed)} "
        f"{force}/{'rad' if not design.translating else 'm'} with the given preload"
    )
    return out
