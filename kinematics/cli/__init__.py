"""The ``assur`` command line, the one place that parses argv and prints."""

from .commands import main

__all__ = ["main"]
