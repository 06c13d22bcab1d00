"""Reading and writing mechanisms: the edge-list grammar and the JSON form."""

from .edgelist import *  # noqa: F403
from .jsonformat import *  # noqa: F403
