"""The report: one self-contained HTML page of everything assur finds for a mechanism.

:func:`gather` collects the answers (:mod:`~kinematics.html.contents`),
:func:`report_page` writes the page (:mod:`~kinematics.html.page`): inline
SVG figures (:mod:`~kinematics.html.svg`), MathML formulas, the cycle's
animation driven by a small inline script (:mod:`~kinematics.html.animation`,
``report.js``), a print stylesheet (``report.css``), in English or
Vietnamese (:mod:`~kinematics.html.phrases`). Imports matplotlib.
"""

from .contents import Note, ReportContents, gather
from .page import SECTIONS, report_page

__all__ = ["SECTIONS", "Note", "ReportContents", "gather", "report_page"]
