"""Worked solutions of the kinematics and the kinetostatics, in the textbook's steps.

- :mod:`~kinematics.explain.phrases`: the sentences, in English and Vietnamese;
- :mod:`~kinematics.explain.notation`: symbols, numbers with units, directions;
- :mod:`~kinematics.explain.context`: what a solution knows of the mechanism at its pose;
- :mod:`~kinematics.explain.velocities`: :func:`explain_kinematics`, the velocity and
  acceleration polygons group by group;
- :mod:`~kinematics.explain.kinetostatics`: :func:`explain_forces`, the reactions from the
  farthest group back, the balancing moment and the virtual-power check.

They are written with :mod:`structure.explain.document` and rendered in any of its formats.
"""

from .kinetostatics import explain_forces
from .notation import angle_of
from .phrases import PHRASES
from .velocities import explain_kinematics

__all__ = ["PHRASES", "angle_of", "explain_forces", "explain_kinematics"]
