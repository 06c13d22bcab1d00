"""Gear trains: meshes and Willis relations, involute geometry, the bevel differential."""

from .differential import *  # noqa: F403
from .involute import *  # noqa: F403
from .trains import *  # noqa: F403
