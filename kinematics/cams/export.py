"""The cam's profile out to CAD and data tools: DXF, SVG and CSV, in the cam's own frame.

The profile is drawn as the cam stands at the program's angle 0 (its own frame:
the centre at the origin, metres), from :func:`~kinematics.cams.profile.cam_geometry`
at ``samples`` angles over the turn (the closed form, not a fit):

* DXF (ezdxf, the ``dxf`` extra, imported when asked for): the profile as a
  closed ``LWPOLYLINE`` on layer ``CAM_PROFILE``; the pitch curve on
  ``CAM_PITCH``, the base and prime circles as ``CIRCLE`` s on ``CAM_CIRCLES``, the
  centre as a ``POINT`` on ``CAM_CENTRE``;
* SVG: the same as paths, in millimetres (y up, as in the design);
* CSV: one row per angle, ``theta_deg, x, y`` of the profile and ``pitch_x,
  pitch_y`` of the pitch curve (empty for a flat face), metres.

A profile that loops or has a cusp cannot be cut: :class:`UndercutError`.

>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> design = make_design(cam_spec_from_dict({"base_radius": 0.04,
...     "follower": {"motion": "translating", "contact": "flat"},
...     "segments": [{"law": "dwell", "angle": 360}]}))
>>> profile_csv(design, 4).splitlines()[:2]
['theta_deg,x,y,pitch_x,pitch_y', '0,0,0.04,,']
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from structure.errors import MechanismError

from ..errors import UndercutError
from .checks import cam_angles, check_cam
from .design import CamDesign
from .profile import CamGeometry, cam_geometry

__all__ = ["PROFILE_SUFFIXES", "profile_csv", "profile_dxf", "profile_svg", "write_profile"]

#: the files the profile is written to, by suffix
PROFILE_SUFFIXES = (".dxf", ".svg", ".csv")


def _geometry(design: CamDesign, samples: int) -> CamGeometry:
    """The profile at the program's angle 0 (the cam's frame), checked to be cuttable."""
    checks = check_cam(design, samples)
    if checks.undercut:
        where = ", ".join(f"{a:g}°–{b:g}°" for a, b in checks.undercut_at[:3])
        raise UndercutError(
            f"the profile loops or has a cusp at {where}: it cannot be cut; make the base "
            "circle larger or the roller smaller (assur cam gives the smallest base circle)"
        )
    return cam_geometry(design, cam_angles(samples))


def _number(x: float) -> str:
    text = f"{x:.12g}"
    return "0" if text in ("-0", "0") else text


def profile_csv(design: CamDesign, samples: int = 720) -> str:
    """The profile (and the pitch curve) at ``samples`` angles, as CSV text (metres)."""
    g = _geometry(design, samples)
    rows = ["theta_deg,x,y,pitch_x,pitch_y"]
    for k, theta in enumerate(np.degrees(g.theta)):
        x, y = g.profile[k]
        pitch = ("", "") if g.pitch is None else tuple(_number(v) for v in g.pitch[k])
        rows.append(",".join([_number(theta), _number(x), _number(y), *pitch]))
    return "\n".join(rows) + "\n"


def profile_svg(design: CamDesign, samples: int = 720) -> str:
    """The profile, pitch curve, base and prime circles as an SVG drawing in millimetres."""
    g = _geometry(design, samples)
    layout = design.layout
    mm = 1000.0
    reach = float(np.max(np.hypot(*g.profile.T)))
    if g.pitch is not None:
        reach = max(reach, float(np.max(np.hypot(*g.pitch.T))))
    half = reach * mm * 1.08
    size = f'width="{2 * half:.3f}mm" height="{2 * half:.3f}mm"'
    box = f'viewBox="{-half:.3f} {-half:.3f} {2 * half:.3f} {2 * half:.3f}"'

    def path(points: np.ndarray) -> str:
        xy = [f"{x * mm:.4f},{-y * mm:.4f}" for x, y in points]  # y up, as in the design
        return "M " + " L ".join(xy) + " Z"

    stroke = max(half / 400.0, 0.01)
    parts = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" {size} {box}>',
        f"  <title>{_escape(design.spec.name or 'disc cam')}: profile</title>",
        f'  <path id="profile" d="{path(g.profile)}" fill="none" stroke="black" '
        f'stroke-width="{stroke:.4f}"/>',
    ]
    if g.pitch is not None:
        parts.append(
            f'  <path id="pitch" d="{path(g.pitch)}" fill="none" stroke="grey" '
            f'stroke-width="{stroke / 2:.4f}" stroke-dasharray="{4 * stroke:.3f}"/>'
        )
    for name, radius in (("base", layout.base_radius), ("prime", layout.prime)):
        if name == "prime" and radius == layout.base_radius:
            continue
        parts.append(
            f'  <circle id="{name}" cx="0" cy="0" r="{radius * mm:.4f}" fill="none" '
            f'stroke="grey" stroke-width="{stroke / 2:.4f}" stroke-dasharray="{stroke:.3f}"/>'
        )
    parts.append(f'  <circle id="centre" cx="0" cy="0" r="{2 * stroke:.4f}" fill="black"/>')
    parts.append("</svg>")
    return "\n".join(parts) + "\n"


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def profile_dxf(design: CamDesign, samples: int = 720):
    """The profile as an ezdxf drawing (see the module for its layers).

    Raises
    ------
    MechanismError
        ezdxf is not installed.
    UndercutError
        The profile loops or has a cusp.
    """
    g = _geometry(design, samples)
    try:
        import ezdxf
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise MechanismError("DXF export needs ezdxf: pip install 'assur[dxf]'") from exc
    doc = ezdxf.new("R2010", setup=True)
    for name, colour in (
        ("CAM_PROFILE", 7),
        ("CAM_PITCH", 8),
        ("CAM_CIRCLES", 8),
        ("CAM_CENTRE", 1),
    ):
        doc.layers.add(name, color=colour)
    space = doc.modelspace()
    space.add_lwpolyline(
        [tuple(map(float, p)) for p in g.profile], close=True, dxfattribs={"layer": "CAM_PROFILE"}
    )
    if g.pitch is not None:
        space.add_lwpolyline(
            [tuple(map(float, p)) for p in g.pitch],
            close=True,
            dxfattribs={"layer": "CAM_PITCH", "linetype": "DASHED"},
        )
    for radius in sorted({design.layout.base_radius, design.layout.prime}):
        space.add_circle((0.0, 0.0), radius, dxfattribs={"layer": "CAM_CIRCLES"})
    space.add_point((0.0, 0.0), dxfattribs={"layer": "CAM_CENTRE"})
    return doc


def write_profile(design: CamDesign, path: str | os.PathLike[str], samples: int = 720) -> Path:
    """Write the profile to ``path`` as its suffix says (.dxf, .svg, .csv).

    Raises
    ------
    MechanismError
        An unknown suffix, ezdxf missing for DXF, or the file cannot be written.
    UndercutError
        The profile loops or has a cusp.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in PROFILE_SUFFIXES:
        raise MechanismError(
            f"cannot write the profile to {path}: use .dxf, .svg or .csv, not "
            f"{suffix or '(no extension)'!r}"
        )
    try:
        if suffix == ".dxf":
            profile_dxf(design, samples).saveas(path)
        else:
            writer = profile_svg if suffix == ".svg" else profile_csv
            path.write_text(writer(design, samples), encoding="utf-8")
    except OSError as exc:
        raise MechanismError(f"cannot write {path}: {exc.strerror or exc}") from exc
    return path
