"""Disc cams designed from their follower's motion: laws, program, profile, checks, closure.

A :class:`~structure.cams.CamSpec` (read by :func:`structure.readwrite.camfile.read_cam_spec`)
becomes a :class:`CamDesign` (:func:`make_design`); :func:`cam_report` runs every check of
``assur cam``; :func:`cam_mechanism` writes the design as a mechanism whose ``cam`` statement
the solvers run through its whole cycle (:mod:`kinematics.cams.contact`).
"""

from .checks import *  # noqa: F403
from .closure import *  # noqa: F403
from .design import *  # noqa: F403
from .export import *  # noqa: F403
from .laws import *  # noqa: F403
from .mechanism import *  # noqa: F403
from .profile import *  # noqa: F403
from .program import *  # noqa: F403
from .summary import *  # noqa: F403
