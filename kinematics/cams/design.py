"""A cam design ready to evaluate: the spec, its program laid on the turn, the follower placed.

>>> from structure.cams import cam_spec_from_dict
>>> design = make_design(cam_spec_from_dict({"base_radius": 0.04, "omega": -5,
...     "follower": {"motion": "translating", "contact": "flat"},
...     "segments": [{"law": "cycloidal", "lift": 0.01, "angle": 180},
...                  {"law": "cycloidal", "lift": -0.01, "angle": 180}]}))
>>> design.layout.sense, design.lift_unit
(-1.0, 'm')
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from structure.cams import CamSpec

from ..errors import BaseCircleError
from .followers import FollowerLayout, follower_layout
from .program import Program, make_program, program_values

__all__ = ["CamDesign", "make_design"]


@dataclass(frozen=True)
class CamDesign:
    """A cam design: its ``spec``, the ``program`` over a turn and the follower's ``layout``."""

    spec: CamSpec
    program: Program
    layout: FollowerLayout

    @property
    def omega(self) -> float:
        return self.spec.omega

    @property
    def translating(self) -> bool:
        return self.spec.follower.translating

    @property
    def lift_unit(self) -> str:
        """The unit of the displacement in the files and outputs: m, or deg for a swinging arm."""
        return "m" if self.translating else "deg"

    @property
    def size(self) -> float:
        """The design's size (metres) for tolerances: the prime circle and the follower's reach."""
        f = self.spec.follower
        reach = 0.0 if f.translating else float(sum(abs(c) for c in f.pivot or (0.0, 0.0)))
        return self.layout.prime + reach + (0.0 if not self.translating else self.program.scale)


def make_design(spec: CamSpec) -> CamDesign:
    """The design of ``spec``: its program (polynomials fitted) and the follower placed.

    Raises
    ------
    CamProgramError
        A polynomial segment whose conditions do not fix one polynomial.
    BaseCircleError
        The follower cannot touch the base circle (see
        :func:`~kinematics.cams.followers.follower_layout`), or a translating
        follower's program takes it past the cam's centre.
    """
    program = make_program(spec)
    layout = follower_layout(spec.follower, spec.base_radius, spec.omega)
    if spec.follower.translating:
        # the follower must stay on its side of the cam's centre all round
        lowest = float(np.min(program_values(program, np.linspace(0, 2 * np.pi, 3601))[0]))
        height = layout.rise if not layout.flat else layout.base_radius
        if height + lowest <= 0.0:
            raise BaseCircleError(
                f"the program takes the follower {-lowest:g} m below its start, past the cam's "
                f"centre ({height:g} m away at s = 0): start the program at the follower's lowest "
                f"point, or make the base circle larger than {-lowest + layout.roller_radius:g} m"
            )
    return CamDesign(spec, program, layout)
