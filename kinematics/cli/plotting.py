"""The ``--plot`` and ``animate`` outputs, checked cheaply; matplotlib loaded only to draw.

matplotlib is the optional ``plot`` extra: :func:`load_drawing` imports
:mod:`kinematics.cli.drawing` (and so matplotlib and the solvers) only when a
command draws, so that ``assur classify FILE`` starts without them and a missing
matplotlib is a plain mechanism error, not a traceback.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from types import ModuleType

from structure.errors import MechanismError, UsageError

__all__ = [
    "ANIMATION_FORMATS",
    "PLOT_FORMATS",
    "check_animation",
    "check_plot",
    "load_drawing",
]

#: the figure formats ``--plot`` writes, by file suffix
PLOT_FORMATS = (".png", ".svg", ".pdf")

#: the animation formats, by file suffix, with the frame rates each can play (frames/s): a
#: GIF's frame delay is a whole number of hundredths of a second, at most 655.35 s, and
#: viewers slow delays under 0.02 s down to 0.1 s
ANIMATION_FORMATS = {".gif": (1 / 655.35, 50.0), ".mp4": (0.01, 240.0)}


def check_plot(path: str | None) -> None:
    """Refuse a --plot file of an unsupported format before any work is done.

    Raises
    ------
    MechanismError
        When ``path`` is given and its suffix is not one of :data:`PLOT_FORMATS`.
    """
    if path is not None and Path(path).suffix.lower() not in PLOT_FORMATS:
        raise MechanismError(
            f"cannot plot to {path}: unsupported figure format "
            f"{Path(path).suffix or '(none)'!r}, use .png, .svg or .pdf"
        )


def check_animation(path: str, fps: float) -> None:
    """Refuse an animation of an unknown format, or a frame rate it cannot play, before work.

    Raises
    ------
    MechanismError
        An extension other than .gif or .mp4 (as :func:`check_plot` says of a figure's).
    UsageError
        ``fps`` outside the format's range (exit status 2).
    """
    suffix = Path(path).suffix.lower()
    if suffix not in ANIMATION_FORMATS:
        raise MechanismError(
            f"unsupported animation format {suffix or '(none)'!r} for {path}: "
            "use .gif (or .mp4 with ffmpeg)"
        )
    low, high = ANIMATION_FORMATS[suffix]
    if not low <= fps <= high:
        raise UsageError(
            f"--fps {fps:g}: a {suffix[1:].upper()} plays {low:.3g} to {high:g} frames per "
            "second" + (" (its frame delays are whole hundredths of a second)"
                        if suffix == ".gif" else "")
        )  # fmt: skip


def load_drawing(needs: str = "--plot") -> ModuleType:
    """The :mod:`kinematics.cli.drawing` module, imported now (it imports matplotlib).

    The one deferred import besides the command dispatch, for the optional extra.

    Raises
    ------
    MechanismError
        When matplotlib is not installed: ``needs`` (the option or command) names who needs it.
    """
    try:
        return importlib.import_module(f"{__package__}.drawing")
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise MechanismError(f"{needs} needs matplotlib: pip install 'assur[plot]'") from exc
