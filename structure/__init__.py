"""Structural analysis of planar mechanisms (the ``assur`` project).

Text -> :class:`Mechanism` -> :class:`StructuralReport` (Assur groups in solve
order) -> the solvers of the ``kinematics`` package.

>>> import structure
>>> m = structure.parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D"])
>>> report = structure.analyze(m)
>>> report.formula, report.groups[0].kind
('I(1) → II(2,3)', <DyadKind.RRR: 'RRR'>)
>>> print(structure.format_report(report).splitlines()[-1].strip())
1 = 1 + 0
"""

from .assur import *  # noqa: F403
from .cams import *  # noqa: F403
from .deprecation import alias_moved_modules
from .errors import *  # noqa: F403
from .generators import *  # noqa: F403
from .kinds import *  # noqa: F403
from .mobility import *  # noqa: F403
from .model import *  # noqa: F403
from .readwrite.edgelist import *  # noqa: F403
from .readwrite.jsonformat import *  # noqa: F403
from .readwrite.reports import *  # noqa: F403
from .replacement import *  # noqa: F403
from .report import *  # noqa: F403
from .validation import *  # noqa: F403

alias_moved_modules(
    {
        "structure.edgelist": "structure.readwrite.edgelist",
        "structure.jsonformat": "structure.readwrite.jsonformat",
        "structure.constraints": "structure.rigidity.constraints",
        "structure.rank": "structure.rigidity.rank",
        "structure.dulmage_mendelsohn": "structure.rigidity.matching",
        "structure.regularity": "structure.rigidity.regularity",
    }
)
