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

from structure.errors import MechanismError

__all__ = ["PLOT_FORMATS", "check_plot", "load_drawing"]

#: the figure formats ``--plot`` writes, by file suffix
PLOT_FORMATS = (".png", ".svg", ".pdf")


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
