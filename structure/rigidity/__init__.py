"""The constraint system of a mechanism and its rank: generic, at the sketch, near it.

``constraints`` builds the rows and unknowns (pins as points), ``rank`` finds
redundant constraints and free motions, ``matching`` gives the block-triangular
(Dulmage–Mendelsohn) order, ``regularity`` tells a singular sketch from a regular one.
"""

from .constraints import *  # noqa: F403
from .matching import *  # noqa: F403
from .rank import *  # noqa: F403
from .regularity import *  # noqa: F403
