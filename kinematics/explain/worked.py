"""The worked solutions' former single module: the same names, now from their own modules.

:func:`explain_kinematics` is in :mod:`kinematics.explain.velocities`,
:func:`explain_forces` in :mod:`kinematics.explain.kinetostatics`,
:data:`PHRASES` in :mod:`kinematics.explain.phrases` and :func:`angle_of` in
:mod:`kinematics.explain.notation`; this module keeps
``from kinematics.explain.worked import ...`` working.
"""

from .kinetostatics import explain_forces
from .notation import angle_of
from .phrases import PHRASES
from .velocities import explain_kinematics

__all__ = ["PHRASES", "angle_of", "explain_forces", "explain_kinematics"]
