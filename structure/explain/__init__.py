"""Worked solutions: the document engine, its phrases and the structural analysis written out.

:mod:`~structure.explain.document` builds and renders a worked solution
(text, Markdown, LaTeX, and HTML whose formulas :mod:`~structure.explain.mathml`
writes as MathML); :mod:`~structure.explain.phrases` holds the structural
sentences in English and Vietnamese; :mod:`~structure.explain.structural`
writes the structural analysis (:func:`explain_structure`).
:mod:`kinematics.explain` writes the
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
from .mathml import MATHML_NAMESPACE, latex_to_mathml
from .phrases import PHRASES
from .structural import explain_structure

__all__ = [
    "FORMATS",
    "LANGUAGES",
    "MATHML_NAMESPACE",
    "PHRASES",
    "Doc",
    "Math",
    "Segment",
    "check_options",
    "explain_structure",
    "formula",
    "latex_to_mathml",
    "math_join",
    "number",
    "render",
    "subscript",
]
