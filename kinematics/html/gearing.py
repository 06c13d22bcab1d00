"""The report's gear-train section: meshes, Willis relations, exact speed ratios and torques.

:func:`train_summary` solves what ``assur gears`` solves (without losses):
the exact speed ratios (:func:`kinematics.gears.speed_ratios`), or with
several inputs each link's speed as a relation in theirs (and the speeds
when the driver lines give them), the balancing moment on each input by
power, the inertia reduced to the inputs (when the file has masses) and the
planets' force balance (when every mesh has a module); :func:`gears_html`
writes them, each Willis relation as a MathML formula, the numbers tied to
the paths of ``assur gears --json``.
"""

from __future__ import annotations

from dataclasses import dataclass
from html import escape
from typing import Any

import numpy as np

from structure.errors import MechanismError
from structure.explain.mathml import latex_to_mathml
from structure.meshes import Mesh, meshes
from structure.model import Mechanism

from ..gears.trains import (
    TrainForces,
    TrainRatios,
    balancing_moments,
    inertia_matrix,
    input_speeds,
    link_speeds,
    relation_text,
    speed_ratios,
    speed_relations,
    train_forces,
)
from .markup import element, note, number_cell, table
from .phrases import say

__all__ = ["TrainSummary", "gears_html", "train_summary", "willis_latex"]


@dataclass(frozen=True)
class TrainSummary:
    """A gear train's answers; the optional ones are ``None`` where they do not apply.

    ``moments`` holds the balancing moment on each input (sympy numbers, by
    power); ``inertia`` the inertia reduced to the single input (a sympy
    number) or to several (a sympy Matrix); ``speeds`` every link's speed
    when a train with several inputs has them all given (``omega=``).
    """

    ratios: TrainRatios
    moments: dict[str, Any] | None
    inertia: Any
    forces: TrainForces | None  # the planets' force balance (module= on every mesh)
    speeds: dict[str, Any] | None = None

    @property
    def single(self) -> bool:
        return len(self.ratios.inputs) == 1

    @property
    def moment(self) -> Any:
        """The balancing moment on the single input (sympy), or None."""
        if self.moments is None or not self.single:
            return None
        return self.moments[self.ratios.inputs[0]]


def train_summary(mechanism: Mechanism) -> TrainSummary | None:
    """The train's ratios and torques, or ``None`` when the mechanism has no gear mesh.

    Raises
    ------
    MechanismError
        A mesh without tooth numbers, or inputs that do not fix the train.
    """
    if not meshes(mechanism):
        return None
    ratios = speed_ratios(mechanism)
    single = len(ratios.inputs) == 1
    moments = balancing_moments(mechanism, ratios)
    inertia = None
    if any(x.kind == "mass" for x in mechanism.loads):
        matrix = inertia_matrix(mechanism, ratios)
        inertia = matrix[0, 0] if single else matrix
    given = input_speeds(mechanism, ratios)
    speeds = link_speeds(ratios, given) if given is not None and not single else None
    forces = None
    if moments is not None and all(m.pair.module for m in ratios.meshes):
        try:
            forces = train_forces(mechanism, ratios)
        except MechanismError:
            forces = None  # not a single-carrier planetary train: power only
    return TrainSummary(ratios, moments, inertia, forces, speeds)


def _teeth(ratios: TrainRatios, mesh: Mesh) -> tuple[int | None, int | None]:
    """The mesh's tooth numbers, those found from coaxiality filled in."""
    za = mesh.za if mesh.za is not None else ratios.teeth_found.get((mesh.pair.id, 1))
    zb = mesh.zb if mesh.zb is not None else ratios.teeth_found.get((mesh.pair.id, 2))
    return za, zb


def _speed(link: str, ground: str) -> str:
    """``\\omega_{link}``, or 0 for the ground."""
    return "0" if link == ground else rf"\omega_{{{link}}}"


def willis_latex(mesh: Mesh, teeth: tuple[int | None, int | None], ground: str) -> str:
    r"""One mesh's Willis relation with its numbers, as LaTeX.

    >>> from structure import parse_edgelist
    >>> m = parse_edgelist(["0 1 R A", "0 2 R B", "1 2 H gear z=20,40"])
    >>> willis_latex(meshes(m)[0], (20, 40), "0")
    '\\frac{\\omega_{1}}{\\omega_{2}} = -\\frac{z_{2}}{z_{1}} = -\\frac{40}{20}'
    """
    sign = "" if mesh.internal else "-"
    a, b = _speed(mesh.a, ground), _speed(mesh.b, ground)
    if mesh.carrier != ground:
        c = _speed(mesh.carrier, ground)
        a, b = f"{a} - {c}", f"{b} - {c}"
    za, zb = (str(z) if z is not None else "?" for z in teeth)
    return (
        rf"\frac{{{a}}}{{{b}}} = {sign}\frac{{z_{{{mesh.b}}}}}{{z_{{{mesh.a}}}}}"
        rf" = {sign}\frac{{{zb}}}{{{za}}}"
    )


def _mesh_table(mechanism: Mechanism, ratios: TrainRatios, lang: str) -> str:
    """Each mesh: pair, teeth, internal or external, carrier."""
    rows = []
    for mesh in ratios.meshes:
        za, zb = _teeth(ratios, mesh)
        kind = say(lang, "internal" if mesh.internal else "external")
        rows.append([escape(mesh.pair.label), f"{za}, {zb}", escape(kind), escape(mesh.carrier)])
    headings = [say(lang, "pair"), say(lang, "teeth"), say(lang, "kind"), say(lang, "carrier")]
    notes = [
        element(
            "p",
            escape(
                say(
                    lang,
                    "teeth_found",
                    link=mechanism.pair(pid).links[side - 1],
                    pair=mechanism.pair(pid).label,
                    z=z,
                )
            ),
        )
        for (pid, side), z in ratios.teeth_found.items()
    ]
    return table(headings, rows) + "".join(notes)


def _ratio_rows(ratios: TrainRatios) -> list[list[str]]:
    """Each link's exact ratio and its value, tied to ``speed_ratio`` of the JSON."""
    rows = []
    for link, value in ratios.ratios.items():
        path = ("speed_ratio", link)
        exact = element(
            "td", escape(str(value)), data_source="gears", data_path="/".join((*path, "exact"))
        )
        rows.append([escape(link), exact, number_cell(float(value), "gears", (*path, "float"))])
    return rows


def _relation_rows(summary: TrainSummary) -> list[list[str]]:
    """Each link's speed as a relation in the inputs' (``relations`` of the JSON), and the
    speed itself when the inputs' are given (``speeds``)."""
    rows = []
    for link, row in speed_relations(summary.ratios).items():
        if summary.speeds is None and link in summary.ratios.inputs:
            continue  # ωc = ωc says nothing
        cells = [
            escape(link),
            element(
                "td",
                escape(relation_text(link, row)),
                data_source="gears",
                data_path=f"relations/{link}/text",
            ),
        ]
        if summary.speeds is not None:
            speed = float(summary.speeds[link])
            cells.append(number_cell(speed, "gears", ("speeds", link, "float")))
        rows.append(cells)
    return rows


def _torque_lines(summary: TrainSummary, mechanism: Mechanism, lang: str) -> list[str]:
    """The balancing moment(s), the reduced inertia, the planets' pin and tooth forces."""
    out = []
    if summary.moments is not None and summary.single:
        value = f"{float(summary.moment):.6g}"
        out.append(say(lang, "train_moment", exact=summary.moment, value=value))
    elif summary.moments is not None:
        for link, moment in summary.moments.items():
            value = f"{float(moment):.6g}"
            out.append(say(lang, "train_moment_of", link=link, exact=moment, value=value))
    if summary.inertia is not None and summary.single:
        value = f"{float(summary.inertia):.6g}"
        out.append(say(lang, "train_inertia", exact=summary.inertia, value=value))
    elif summary.inertia is not None:
        rows = "; ".join(", ".join(str(v) for v in row) for row in summary.inertia.tolist())
        inputs = ", ".join(summary.ratios.inputs)
        out.append(say(lang, "train_inertia_matrix", inputs=inputs, rows=f"[{rows}]"))
    forces = summary.forces
    if forces is not None:
        for link, moment in forces.balancing_moments.items():
            text = say(lang, "train_force_moment", value=f"{moment:.6g}")
            out.append(text if summary.single else f"{link}: {text}")
        for planet, (radial, tangential) in forces.pins.items():
            out.append(
                say(
                    lang,
                    "planet_pin",
                    planet=planet,
                    radial=f"{radial + 0.0:.6g}",
                    tangential=f"{tangential + 0.0:.6g}",
                )
                + f" (|F| = {float(np.hypot(radial, tangential)):.6g} N)"
            )
        for pid, value in forces.tooth.items():
            out.append(
                say(lang, "tooth_force", pair=mechanism.pair(pid).label, value=f"{value:.6g}")
            )
    return out


def gears_html(summary: TrainSummary, mechanism: Mechanism, lang: str) -> str:
    """The gear-train section's body: meshes, Willis relations, speed ratios, torques."""
    ratios = summary.ratios
    parts = [element("h3", escape(say(lang, "h_meshes"))), _mesh_table(mechanism, ratios, lang)]
    parts.append(
        element(
            "p",
            escape(say(lang, "train_dof", dof=ratios.dof, inputs=", ".join(ratios.inputs))),
            data_source="gears",
            data_path="dof",
            data_value=str(ratios.dof),
        )
    )
    parts.append(element("h3", escape(say(lang, "h_willis"))))
    for mesh in ratios.meshes:
        latex = willis_latex(mesh, _teeth(ratios, mesh), mechanism.ground)
        parts.append(element("div", latex_to_mathml(latex, display=True), class_="formula"))
    if summary.single:
        parts.append(element("h3", escape(say(lang, "h_ratios"))))
        headings = [say(lang, "link"), say(lang, "exact"), say(lang, "value")]
        parts.append(table(headings, _ratio_rows(ratios)))
    else:
        parts.append(element("h3", escape(say(lang, "h_relations"))))
        headings = [say(lang, "link"), say(lang, "relation")]
        if summary.speeds is not None:
            headings.append(say(lang, "speed"))
        parts.append(table(headings, _relation_rows(summary)))
    parts.append(element("h3", escape(say(lang, "h_torques"))))
    lines = _torque_lines(summary, mechanism, lang)
    if lines:
        parts.append(element("ul", "".join(element("li", escape(x)) for x in lines)))
    else:
        parts.append(note(say(lang, "no_torques"), "no-torques"))
    return "".join(parts)
