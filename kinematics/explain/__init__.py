"""Worked solutions of the kinematics and the kinetostatics, in the textbook's steps."""

from .worked import *  # noqa: F403
