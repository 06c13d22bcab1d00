"""Text in, text out: the edge-list grammar, the JSON form, and the report's text and JSON."""

from .edgelist import *  # noqa: F403
from .jsonformat import *  # noqa: F403
from .reports import *  # noqa: F403
