"""Worked solutions: the document engine and the structural analysis written out."""

from .structural import *  # noqa: F403
