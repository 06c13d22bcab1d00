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
    "AssemblyModeError",
    "BaseCircleError",
    "BranchChangeError",
    "CamGeometryError",
    "DynamicsError",
    "ExactTimeoutError",
    "IndeterminateError",
    "InfeasibleDesignError",
    "IntegrationError",
    "NoSteadyRunningError",
    "SingularPoseError",
    "StallError",
    "SweepSizeError",
    "SynthesisError",
    "TravelError",
    "UndercutError",
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


class ExactTimeoutError(MechanismError):
    """An exact answer (``--exact``) ran past its time limit.

    ``stage`` names what it was working on (a group such as ``'group II(2,3)'``),
    ``limit`` the limit in seconds.
    """

    def __init__(self, message: str, stage: str = "", limit: float = 0.0):
        self.stage = stage
        self.limit = limit
        super().__init__(message)


class SweepSizeError(SizeError):
    """A sweep asks for more poses than fit in the memory a sweep may take."""


class CamGeometryError(MechanismError, ValueError):
    """A cam design whose geometry cannot be made, or a sketch that disagrees with it."""


class BaseCircleError(CamGeometryError):
    """The base circle too small (the follower too far) for any profile: says what to change."""


class UndercutError(CamGeometryError):
    """The profile loops or has a cusp (a roller too large for the pitch curve's convex radius,
    a flat face on a profile of negative radius): it cannot be cut or followed."""


class DynamicsError(MechanismError):
    """The machine's motion over its cycle cannot be found (one driver, masses, a whole turn)."""


class NoSteadyRunningError(DynamicsError):
    """The drive and the loads admit no steady running: the machine runs away or stops."""


class StallError(NoSteadyRunningError):
    """The drive is too weak: the machine stops at ``phi`` (rad from the sketch).

    ``shortfall`` is by how much the drive's torque falls short of the loads'
    (N·m, reduced to the driver), as the message explains.
    """

    def __init__(self, message: str, phi: float, shortfall: float):
        self.phi = phi
        self.shortfall = shortfall
        super().__init__(message)


class IntegrationError(DynamicsError):
    """An integration of the equation of motion that is stiff, diverges or takes too long."""


class TravelError(MechanismError):
    """The drivers cannot move a mechanism from its sketch either way: nothing to sweep."""


class AssemblyModeError(MechanismError, ValueError):
    """An assembly mode asked for that a group does not have at the sketch's inputs."""


class SynthesisError(MechanismError):
    """A synthesis problem that has no answer as posed: too few or too many targets, a
    function undefined on its range, targets that fix no linkage (the message says which)."""


class InfeasibleDesignError(SynthesisError):
    """No candidate design met the constraints within the search budget.

    ``rejections`` counts the candidates each constraint rejected (its name ->
    count), so the message can say which one rejected most.
    """

    def __init__(self, message: str, rejections: dict[str, int] | None = None):
        self.rejections = dict(rejections or {})
        super().__init__(message)
