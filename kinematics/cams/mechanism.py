"""A cam design as a mechanism, ready for ``classify``, ``kinematics``, ``sweep``, ``forces``.

:func:`cam_mechanism` writes the design's cam and follower as links and pairs
in the design's own frame (the cam's centre ``O`` at the origin, a translating
follower along +y), the sketch at the program's angle ``at``: the cam ``1``
turning about ``O`` (the driver, at the spec's ω), the follower ``2`` on its
guide (a slide through ``F``) or pivot ``Q``, a roller ``3`` on the axis ``A``,
the higher pair at the contact ``K`` with the profile's centre of curvature
``C`` (its replacement at the sketch), and the ``cam`` statement that gives
the pair the design's profile for the whole cycle. The follower's mass (or
inertia) and load become ``mass`` and ``force`` (or ``moment``) statements; the
spring, whose force depends on the pose, has no statement of the format and
stays in the design (:mod:`kinematics.cams.closure`).

>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> design = make_design(cam_spec_from_dict({"base_radius": 0.04, "omega": 10,
...     "follower": {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
...     "segments": [{"law": "cycloidal", "lift": 0.02, "angle": 180},
...                  {"law": "cycloidal", "lift": -0.02, "angle": 180}]}))
>>> m = cam_mechanism(design)
>>> [p.statement for p in m.pairs]
['0 1 R O', '0 2 P F angle=90', '2 3 R A', '1 3 H K roller=3 centers=C,A']
"""

from __future__ import annotations

import math

import numpy as np

from structure.cams import CamRef, FollowerContact
from structure.model import (
    Mechanism,
    make_driver,
    make_load,
    make_pair,
    make_point,
)
from structure.validation import validated

from ..errors import CamGeometryError
from .design import CamDesign
from .profile import cam_geometry

__all__ = ["cam_mechanism"]


def _xy(v: np.ndarray) -> tuple[float, float]:
    # a clean zero rather than −0.0 or 1e-18 noise in the written file
    return tuple(float(0.0 if abs(c) < 1e-15 else c) for c in v)  # type: ignore[return-value]


def cam_mechanism(
    design: CamDesign,
    *,
    at_deg: float = 0.0,
    program: str | None = None,
    name: str | None = None,
    source: str = "<cam>",
) -> Mechanism:
    """The mechanism of ``design``: cam, follower (and roller), the cam statement, the loads.

    ``program`` is the file the edge list's ``cam`` statement will name (None:
    the spec is held inline, as the JSON form writes it).

    Raises
    ------
    CamGeometryError
        The profile is straight at the contact at ``at_deg`` (its centre of
        curvature at infinity): choose another angle for the sketch.
    """
    spec = design.spec
    layout = design.layout
    g = cam_geometry(design, np.array([math.radians(at_deg)]))
    radius = (g.profile_radius if layout.flat else g.pitch_radius)[0]
    if not np.isfinite(radius) or not np.all(np.isfinite(g.centre)):
        raise CamGeometryError(
            f"the profile is straight at the contact at {at_deg:g}°: its centre of curvature is "
            "at infinity; draw the sketch at another angle (at=)"
        )
    contact = g.contact[0]
    point = g.point[0]
    centre = g.centre[0]
    roller = spec.follower.contact is FollowerContact.ROLLER
    flat = spec.follower.contact is FollowerContact.FLAT
    points = {"O": (0.0, 0.0), "K": _xy(contact), "C": _xy(centre)}
    pairs = [make_pair(1, "R", "0", "1", "O")]
    if design.translating:
        reach = layout.prime + 2.0 * (design.program.scale + layout.roller_radius)
        points["F"] = _xy(np.array([layout.axis, max(point[1], contact[1]) + 0.25 * reach]))
        pairs.append(make_pair(2, "P", "0", "2", "F", angle=90))
    else:
        points["Q"] = _xy(np.asarray(layout.pivot, dtype=float))
        pairs.append(make_pair(2, "R", "0", "2", "Q"))
    if roller:
        points["A"] = _xy(point)  # not "P": a point named R, P or H would read as a pair kind
        pairs.append(make_pair(3, "R", "2", "3", "A"))
        pairs.append(make_pair(4, "H", "1", "3", "K", roller="3", centers=("C", "A")))
        other = "3"
    elif flat:
        pairs.append(make_pair(3, "H", "1", "2", "K", flat="2", centers=("C", None)))
        other = "2"
    else:
        pairs.append(make_pair(3, "H", "1", "2", "K", centers=("C", "K")))
        other = "2"
    loads = []
    where = "A" if roller else "K"
    if design.translating:
        if spec.follower_mass:
            loads.append(make_load("mass", "2", where, (spec.follower_mass, 0.0)))
        if spec.load:
            loads.append(make_load("force", "2", where, (0.0, -spec.load)))
    else:
        if spec.follower_inertia:
            loads.append(make_load("mass", "2", "Q", (0.0, spec.follower_inertia)))
        if spec.load:
            loads.append(make_load("moment", "2", None, (-layout.swing * spec.load,)))
    mechanism = Mechanism(
        tuple(pairs),
        "0",
        (make_driver("1", (("omega", spec.omega),)),),
        {key: make_point(key, *xy) for key, xy in points.items()},
        name if name is not None else (spec.name or "disc cam"),
        source,
        tuple(loads),
        (CamRef("1", other, spec, program, at_deg),),
    )
    return validated(mechanism)
