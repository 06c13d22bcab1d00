"""Figures (matplotlib): the mechanism, its graph, polygons, sweeps, sheets, animation."""

from .sheets import *  # noqa: F403
