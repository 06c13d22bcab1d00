"""Everything the cam command reports about a design, as data: the checks, the closure, the JSON.

:func:`cam_report` runs every check of a design once (the program's joins and
peaks, the pressure angle, the radii of curvature, undercut, the face's
width, the smallest base circle, the force closure) and keeps them in a
:class:`CamReport`; :func:`cam_report_to_dict` gives its JSON form, whose keys
are the ``assur cam --json`` contract (issue 23): ``segments``, ``samples``,
``peak``, ``pressure_angle``, ``curvature``, ``undercut``, ``continuity``,
``profile``, ``contact_force``, ``jump_speed``, and more besides.

>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> report = cam_report(make_design(cam_spec_from_dict({"base_radius": 0.04, "omega": 10,
...     "follower": {"motion": "translating", "contact": "knife"},
...     "segments": [{"law": "cycloidal", "lift": 0.01, "angle": 180},
...                  {"law": "cycloidal", "lift": -0.01, "angle": 180}]})), 36)
>>> data = cam_report_to_dict(report)
>>> sorted(data["peak"]), data["pressure_angle"]["limit_deg"], len(data["samples"]["s"])
(['a', 'j', 'v'], 30.0, 36)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from structure.cams import FollowerContact, MotionLaw

from .checks import BaseCircle, CamChecks, Extreme, cam_angles, check_cam, smallest_base_circle
from .closure import Closure, force_closure
from .design import CamDesign
from .program import Join, Peak, continuity, peaks, time_values

__all__ = ["CONVENTIONS", "CamReport", "SegmentPeaks", "cam_report", "cam_report_to_dict"]

#: the conventions the outputs use, said with them (where textbooks differ)
CONVENTIONS = {
    "angles": "degrees; θ is the cam's turn in its own sense (the sign of omega), from 0",
    "offset": (
        "a positive offset puts a translating follower's axis on the side that lowers the "
        "pressure angle of a rise: x = +offset for a counter-clockwise cam with the follower "
        "moving along +y, x = −offset for a clockwise one"
    ),
    "pressure_angle": (
        "the angle between the common normal and the way the follower's point moves as it "
        "rises; positive where the normal leans back against the cam's turning "
        "(tan φ = (s' − ε)/(√(R_p² − ε²) + s) for a translating roller)"
    ),
    "curvature": (
        "radii positive where the cam is convex; the smallest convex and concave (as a "
        "positive number) are given apart; a roller undercuts where the pitch curve's convex "
        "radius is at most its radius, a flat face where R_b + s + s'' ≤ 0"
    ),
    "oscillating": (
        "lifts in degrees; the roller sits on the side of the line from the cam's centre to "
        "the pivot from which the cam's surface turns toward the pivot (the arm is pushed on "
        "the rise); a positive lift swings it away from the cam's centre"
    ),
    "load": "the load presses the follower onto the cam (N, or N·m about the pivot)",
}


@dataclass(frozen=True, slots=True)
class SegmentPeaks:
    """One segment of the program: where it runs and its largest v, a, j (time, at ω)."""

    index: int
    law: MotionLaw
    start_deg: float
    end_deg: float
    lift: float
    v: float
    a: float
    j: float


@dataclass(frozen=True)
class CamReport:
    """A design's checks, all at once (see :func:`cam_report`)."""

    design: CamDesign
    samples: int
    segments: tuple[SegmentPeaks, ...]
    joins: tuple[Join, ...]
    peaks: dict[str, Peak]
    checks: CamChecks
    base: BaseCircle
    closure: Closure

    @property
    def infinite_jerk_at(self) -> tuple[float, ...]:
        """The joins (degrees) where the acceleration jumps: an infinite jerk."""
        return tuple(j.at_deg for j in self.joins if j.infinite_jerk)


def _segment_peaks(design: CamDesign) -> tuple[SegmentPeaks, ...]:
    out = []
    program = design.program
    w = abs(design.omega)
    for piece in program.pieces:
        _, s1, s2, s3 = piece.values(np.array(piece.candidates()))  # the piece's own values
        v, a, j = s1 * w, s2 * w**2, s3 * w**3
        out.append(
            SegmentPeaks(
                piece.index,
                piece.law,
                round(math.degrees(piece.start), 9),
                round(math.degrees(piece.end), 9),
                float(program.to_file_units(np.array([piece.lift]))[0]),
                *(float(np.max(np.abs(value))) for value in (v, a, j)),
            )
        )
    return tuple(out)


def cam_report(design: CamDesign, samples: int = 360) -> CamReport:
    """Every check of ``design`` on ``samples`` angles over the turn (refined where it counts)."""
    return CamReport(
        design,
        samples,
        _segment_peaks(design),
        continuity(design.program),
        peaks(design.program, design.omega, cam_angles(samples)),
        check_cam(design, samples),
        smallest_base_circle(design, samples),
        force_closure(design, samples),
    )


def _extreme(x: Extreme | None, key: str = "radius") -> dict[str, float] | None:
    return None if x is None else {key: x.value, "at_deg": x.at_deg}


def _in_time(design: CamDesign, order: int, value: float) -> float:
    """A derivative by the cam angle of the given order, as the samples give it (time, files)."""
    if order == 0:
        return float(design.program.to_file_units(np.array([value]))[0])
    return value * abs(design.omega) ** order


def _listed(values: np.ndarray) -> list[float]:
    return np.asarray(values, dtype=float).tolist()


def cam_report_to_dict(report: CamReport) -> dict[str, Any]:
    """The JSON form of a report (the ``assur cam --json`` contract; every number finite)."""
    design = report.design
    spec = design.spec
    program = design.program
    theta = cam_angles(report.samples)
    s, v, a, j = time_values(program, theta, design.omega)
    to_file = program.to_file_units
    checks, closure, base = report.checks, report.closure, report.base
    g = checks.geometry
    unit = design.lift_unit
    rate = "rad" if not design.translating else "m"
    follower = spec.follower
    out: dict[str, Any] = {
        "name": spec.name,
        "omega": spec.omega,
        "follower": {
            "motion": follower.motion.value,
            "contact": follower.contact.value,
            "base_radius": spec.base_radius,
            "prime_radius": design.layout.prime,
        },
        "units": {
            "s": unit,
            "v": f"{rate}/s",
            "a": f"{rate}/s²",
            "j": f"{rate}/s³",
            "lengths": "m",
            "angles": "deg",
        },
        "conventions": dict(CONVENTIONS),
        "segments": [
            {
                "index": x.index,
                "law": x.law.value,
                "start_deg": x.start_deg,
                "end_deg": x.end_deg,
                "lift": x.lift,
                "peak": {"v": x.v, "a": x.a, "j": x.j},
            }
            for x in report.segments
        ],
        "samples": {
            "theta_deg": _listed(np.degrees(theta)),
            "s": _listed(to_file(s)),
            "v": _listed(v),
            "a": _listed(a),
            "j": _listed(j),
        },
        "peak": {key: {"value": p.value, "at_deg": p.at_deg} for key, p in report.peaks.items()},
        "pressure_angle": {
            "max_deg": checks.pressure.value,
            "at_deg": checks.pressure.at_deg,
            "limit_deg": checks.limit,
            "ok": checks.pressure_ok,
            "values_deg": _listed(np.degrees(g.pressure)),
        },
        "curvature": {
            "pitch_min": _extreme(checks.pitch_min),
            "profile_min": _extreme(checks.profile_min),
            "pitch_concave_min": _extreme(checks.pitch_concave),
            "profile_concave_min": _extreme(checks.profile_concave),
        },
        "undercut": {"found": checks.undercut, "at_deg": [list(x) for x in checks.undercut_at]},
        "continuity": [
            {
                "at_deg": join.at_deg,
                "before": join.before,
                "after": join.after,
                "order": join.order,
                "name": join.name,
                "infinite_jerk": join.infinite_jerk,
                # in the units of the samples: s as the files give it, v, a, j at omega
                "jumps": [
                    {
                        "quantity": "svaj"[order],
                        "left": _in_time(design, order, left),
                        "right": _in_time(design, order, right),
                    }
                    for order, left, right in join.jumps
                ],
            }
            for join in report.joins
        ],
        "profile": g.profile.tolist(),
        "pitch_curve": None if g.pitch is None else g.pitch.tolist(),
        "face": None
        if checks.face is None
        else {"min": checks.face[0], "max": checks.face[1], "width": checks.face_width},
        "base_circle": {
            "smallest": base.base_radius,
            "bound": base.bound,
            "limit_deg": base.limit,
            "best_offset": base.best_offset,
            "best_base_radius": base.best_base_radius,
        },
        "contact_force": {
            "max": {"value": closure.peak_contact.value, "at_deg": closure.peak_contact.at_deg},
            "values": _listed(closure.contact),
            "lost_at_deg": [list(x) for x in closure.lost_at],
        },
        "jump_speed": closure.jump_speed,
        "camshaft_torque": {
            "max": {"value": closure.peak_torque.value, "at_deg": closure.peak_torque.at_deg},
            "values": _listed(closure.torque),
        },
        "spring": {
            "preload_needed": closure.preload_needed,
            "rate_needed": closure.rate_needed,
            "up_to": closure.up_to,
        },
    }
    out["peak"]["j"]["infinite_at_deg"] = list(report.infinite_jerk_at)
    if follower.contact is FollowerContact.KNIFE:
        out["curvature"]["note"] = "a knife edge's profile is its pitch curve"
    return out
