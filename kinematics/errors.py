"""The kinematics' exceptions: a group that does not close, a dead centre, indeterminate reactions.

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
>>> from structure.errors import MechanismError
>>> isinstance(e, MechanismError)
True
"""

from __future__ import annotations

import numpy as np

from structure.errors import MechanismError

__all__ = [
    "DEAD_CENTRE",
    "AssemblyError",
    "IndeterminateError",
    "SingularPoseError",
    "inputs_text",
]

#: a pose is a dead centre when the sine of its transmission angle (or σ_min/σ_max of the
#: group's scaled Jacobian) falls to this; Newton stops within ~1e-7 of a double root,
#: so the test stays above that
DEAD_CENTRE = 1e-6


def inputs_text(inputs: np.ndarray) -> str:
    """The driver inputs of a pose as the messages print them (``0.1, -0.2``)."""
    return ", ".join(f"{x:.6g}" for x in np.atleast_1d(inputs))


class AssemblyError(MechanismError):
    """A group cannot be assembled at the requested input (it does not close)."""

    def __init__(self, message: str, group: str = "", pose: object = None):
        self.group = group
        self.pose = pose
        super().__init__(message)

    @classmethod
    def at(cls, group: str, inputs: np.ndarray, reason: str) -> AssemblyError:
        """The error for ``group`` at the pose of driver ``inputs``, with its reason."""
        return cls(
            f"group {group} cannot be assembled at input {inputs_text(inputs)}: {reason}",
            group,
            tuple(np.atleast_1d(inputs)),
        )


class SingularPoseError(MechanismError):
    """A group's Jacobian loses rank at the pose (a dead centre)."""

    def __init__(self, message: str, group: str = "", pose: object = None):
        self.group = group
        self.pose = pose
        super().__init__(message)

    @classmethod
    def at(cls, group: str, inputs: np.ndarray, measure: str) -> SingularPoseError:
        """The error for ``group`` at the pose of driver ``inputs``; ``measure`` says how small."""
        return cls(
            f"group {group} is at a dead centre at input {inputs_text(inputs)}: its Jacobian "
            f"loses rank ({measure}; transmission angle 0° or 180°)",
            group,
            tuple(np.atleast_1d(inputs)),
        )


class IndeterminateError(MechanismError):
    """Reactions of an over-constrained mechanism (r > 0) are statically indeterminate."""
