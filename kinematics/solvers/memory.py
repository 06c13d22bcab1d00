"""How much memory a solve over many poses may take, and the check that refuses more.

A sweep's results and its solve's temporaries grow with the poses and with
the named points and links; a path followed from the sketch through far-apart
inputs adds intermediate poses (one per continuation step). Either is refused
before it is made when it would not fit in half of this machine's memory,
with a message that names the poses and what to ask for instead.

>>> from structure import analyze, parse_edgelist
>>> from kinematics import make_plan
>>> plan = make_plan(analyze(parse_edgelist(["driver 1", "0 1 R A", "point A 0 0"])))
>>> check_poses(plan, 1000, rates=True)
>>> pose_bytes(plan, rates=False) < pose_bytes(plan, rates=True)
True
"""

from __future__ import annotations

from structure.limits import check_size, memory_limit

from ..errors import SweepSizeError
from .plan import SolvePlan

__all__ = ["BYTES_PER_POSE_ITEM", "check_poses", "memory_limit", "pose_bytes"]

#: bytes per pose a sweep's results and the solve's temporaries take, per named point and link
#: (measured: 90–320 with rates; a third of it for positions only)
BYTES_PER_POSE_ITEM = 320


def pose_bytes(plan: SolvePlan, rates: bool = True) -> int:
    """The memory one pose of ``plan`` takes, with rates or positions only."""
    items = len(plan.points) + len(plan.mechanism.moving_links)
    return BYTES_PER_POSE_ITEM * max(items, 1) // (1 if rates else 3)


def check_poses(
    plan: SolvePlan, poses: int, rates: bool, *, what: str = "", advice: str = ""
) -> None:
    """Refuse ``poses`` poses of ``plan`` when they would not fit in :func:`memory_limit`.

    ``what`` names the poses in the message (default: a sweep of them),
    ``advice`` what to change (default: fewer steps); the message is
    :func:`structure.limits.check_size`'s, as for every option that sets a size.

    Raises
    ------
    SweepSizeError
        Naming the poses, the memory they would take and the limit.
    """
    check_size(
        poses,
        pose_bytes(plan, rates),
        what or f"a sweep of {poses} poses",
        advice
        or "ask for at most {fit} poses (steps=, --steps on the command line), or sweep the "
        "inputs in parts",
        error=SweepSizeError,
    )
