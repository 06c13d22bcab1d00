"""The ``assur`` command line, the one place that parses argv and prints."""

from .main import main

__all__ = ["main"]
