"""The kinematics' exceptions: a group that does not close, a dead centre, a branch change, more.

Each derives from :class:`structure.errors.MechanismError`, so the command line
reports it as a mechanism error (exit status 1) without a traceback. A pose
error names the group and the driver input where it happens; nothing is
returned as NaN instead.

>>> import numpy as np
>>> e = AssemblyError.at("II(2,3)", np.array([1.5]), "the dyad cannot close")
>>> str(e)
'group II(2,3) cannot be assembled at input 1.5: the dyad cannot close'
>>> e.group, [float(x) for x in e.pose]
('II(2,3)', [1.5])
>>> from structure.errors import MechanismError, SizeError
>>> isinstance(e, MechanismError)
True

With the drivers' kinds, inputs are printed in the units of the files:

>>> inputs_text(np.array([math.pi, 0.25]), ("R", "P"))
'180°, 0.25 m'
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from structure.errors import MechanismError, SizeError

__all__ = [
    "DEAD_CENTRE",
    "AssemblyError",
    "BranchChangeError",
    "IndeterminateError",
    "SingularPoseError",
    "SweepSizeError",
    "inputs_text",
]

#: a pose is a dead centre when the sine of its transmission angle (or σ_min/σ_max of the
#: group's scaled Jacobian) falls to this; Newton stops within ~1e-7 of a double root,
#: so the test stays above that
DEAD_CENTRE = 1e-6


def inputs_text(inputs: np.ndarray, kinds: Sequence[str] | None = None) -> str:
    """The driver inputs of a pose as the messages print them (``0.1, -0.2``).

    With ``kinds`` (each driver's 'R' or 'P'), a turning driver's input is
    printed in degrees and a sliding driver's in metres, the units of the files.
    """
    values = np.atleast_1d(inputs)
    if kinds is None or len(kinds) != len(values):
        return ", ".join(f"{x:.6g}" for x in values)
    return ", ".join(
        f"{_tidy(math.degrees(float(x))):.6g}°" if kind == "R" else f"{_tidy(float(x)):.6g} m"
        for x, kind in zip(values, kinds, strict=True)
    )


def _tidy(x: float) -> float:
    """``x`` without a negative zero (so that −0° prints as 0°)."""
    return x + 0.0


class AssemblyError(MechanismError):
    """A group cannot be assembled at the requested input (it does not close).

    ``indices``, when known, are the rows of the solve's inputs that cannot be
    assembled (a closed-form dyad finds them all at once).
    """

    def __init__(self, message: str, group: str = "", pose: object = None, indices: object = None):
        self.group = group
        self.pose = pose
        self.indices = indices
        super().__init__(message)

    #: what happens to the group, in the message
    happens = "cannot be assembled"

    @classmethod
    def at(
        cls, group: str, inputs: np.ndarray, reason: str, kinds: Sequence[str] | None = None
    ) -> AssemblyError:
        """The error for ``group`` at the pose of driver ``inputs``, with its reason."""
        return cls(
            f"group {group} {cls.happens} at input {inputs_text(inputs, kinds)}: {reason}",
            group,
            tuple(np.atleast_1d(inputs)),
        )


class BranchChangeError(AssemblyError):
    """A sweep would go over from one assembly mode of a group to the other between two poses.

    Raised at the change point, where the group's two assembly modes meet (its
    two circle intersections coincide) and the linkage may go on in either.
    """

    happens = "changes assembly branch"


class SingularPoseError(MechanismError):
    """A group's Jacobian loses rank at the pose (a dead centre, or another singular pose).

    ``dead_centre`` tells a dead centre (:meth:`at`) from another singular pose
    (:meth:`singular`); ``indices``, when known, are the rows of the solve's
    inputs where it happens.
    """

    def __init__(
        self,
        message: str,
        group: str = "",
        pose: object = None,
        indices: object = None,
        dead_centre: bool = True,
    ):
        self.group = group
        self.pose = pose
        self.indices = indices
        self.dead_centre = dead_centre
        super().__init__(message)

    @classmethod
    def at(
        cls, group: str, inputs: np.ndarray, measure: str, kinds: Sequence[str] | None = None
    ) -> SingularPoseError:
        """The error for ``group`` at the pose of driver ``inputs``; ``measure`` says how small."""
        return cls(
            f"group {group} is at a dead centre at input {inputs_text(inputs, kinds)}: its "
            f"Jacobian loses rank ({measure}; transmission angle 0° or 180°)",
            group,
            tuple(np.atleast_1d(inputs)),
        )

    @classmethod
    def singular(
        cls, group: str, inputs: np.ndarray, why: str, kinds: Sequence[str] | None = None
    ) -> SingularPoseError:
        """The error for ``group`` at a singular pose other than a dead centre, saying ``why``."""
        return cls(
            f"group {group} is at a singular pose at input {inputs_text(inputs, kinds)}: {why}",
            group,
            tuple(np.atleast_1d(inputs)),
            dead_centre=False,
        )


class IndeterminateError(MechanismError):
    """Reactions of an over-constrained mechanism (r > 0) are statically indeterminate."""


class SweepSizeError(SizeError):
    """A sweep asks for more poses than fit in the memory a sweep may take."""
