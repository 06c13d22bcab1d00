"""Worked solutions: the document engine, its phrases and the structural analysis written out.

:mod:`~structure.explain.document` builds and renders a worked solution
(text, Markdown, LaTeX); :mod:`~structure.explain.phrases` holds the
structural sentences in English and Vietnamese;
:mod:`~structure.explain.structural` writes the structural analysis
(:func:`explain_structure`). :mod:`kinematics.explain` writes the
kinematics and the forces with the same engine.
"""

from .document import (
    FORMATS,
    LANGUAGES,
    Doc,
    Math,
    Segment,
    check_options,
    formula,
    math_join,
    number,
    render,
    subscript,
)
from .phrases import PHRASES
from .structural import explain_structure

__all__ = [
    "FORMATS",
    "LANGUAGES",
    "PHRASES",
    "Doc",
    "Math",
    "Segment",
    "check_options",
    "explain_structure",
    "formula",
    "math_join",
    "number",
    "render",
    "subscript",
]
