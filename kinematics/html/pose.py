"""The report's kinematics and forces at the sketch pose: tables, polygons to scale, the checks.

:func:`kinematics_html` writes the drivers, each link's angle, ω and ε and
each point's position, velocity and acceleration, with the velocity and
acceleration polygons; :func:`forces_html` the joint reactions in the order
solved, the balancing moment (or force), the virtual-power check and the
force polygon of each group and driver. The numbers are those of
``assur kinematics --json`` and ``assur forces --json``, each table cell
tied to its path there.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from html import escape
from typing import Any

import numpy as np

from structure.explain.mathml import latex_to_mathml

from ..figures import acceleration_polygon, force_polygon, velocity_polygon
from ..figures.forces import polygon_entries
from .contents import ReportContents, part_note
from .markup import element, format_number, number_cell, table
from .phrases import say
from .svg import figure_svg

__all__ = ["forces_html", "kinematics_html"]


def _figure(svg: str, caption: str) -> str:
    """A ``<figure>`` with its caption (a force polygon's group or driver)."""
    return element("figure", svg + element("figcaption", escape(caption)))


def _drivers(contents: ReportContents, lang: str) -> str:
    """One line per driver: its speed and acceleration, and whether the file gave them."""
    lines = []
    for d in contents.plan.drivers:  # type: ignore[union-attr]
        key = "driver_r" if d.kind == "R" else "driver_p"
        text = say(
            lang,
            key,
            link=d.link,
            pivot=d.point or "?",
            speed=format_number(d.speed),
            acc=format_number(d.acceleration),
        )
        lines.append(element("li", escape(text + ("" if d.speed_given else say(lang, "assumed")))))
    return element("ul", "".join(lines))


def _link_rows(data: Mapping[str, Any]) -> list[list[str]]:
    """Each link's angle turned, ω and ε, tied to ``links/<name>/…``."""
    return [
        [escape(name)]
        + [
            number_cell(values[key], "kinematics", ("links", name, key))
            for key in ("angle", "omega", "epsilon")
        ]
        for name, values in data["links"].items()
    ]


def _point_rows(data: Mapping[str, Any]) -> list[list[str]]:
    """Each point's link, position, velocity and acceleration with their magnitudes."""
    rows = []
    for name, values in data["points"].items():
        row = [escape(name), escape(values["link"])]
        for key in ("position", "velocity", "acceleration"):
            row += [
                number_cell(values[key][i], "kinematics", ("points", name, key, i)) for i in (0, 1)
            ]
            if key != "position":
                size = format_number(float(np.hypot(*values[key])))
                row.append(element("td", escape(size), class_="num"))
        rows.append(row)
    return rows


def kinematics_html(contents: ReportContents, lang: str) -> str:
    """Drivers, links and points at the sketch pose, the velocity and acceleration polygons."""
    if contents.kinematics is None or contents.plan is None or contents.state is None:
        return part_note(contents, "pose", lang)
    data = contents.kinematics
    parts = [element("h3", escape(say(lang, "h_drivers"))), _drivers(contents, lang)]
    parts.append(element("h3", escape(say(lang, "h_links"))))
    headings = [say(lang, "link"), say(lang, "angle_turned"), "ω (rad/s)", "ε (rad/s²)"]
    parts.append(table(headings, _link_rows(data)))
    parts.append(element("h3", escape(say(lang, "h_points"))))
    headings = [say(lang, "point"), say(lang, "on_link"), "x (m)", "y (m)"]
    headings += ["v_x (m/s)", "v_y (m/s)", "|v| (m/s)", "a_x (m/s²)", "a_y (m/s²)", "|a| (m/s²)"]
    parts.append(element("div", table(headings, _point_rows(data)), class_="wide"))
    plan, state = contents.plan, contents.state
    for key, draw, prefix in (
        ("h_velocity_polygon", velocity_polygon, "fig-velocity"),
        ("h_acceleration_polygon", acceleration_polygon, "fig-acceleration"),
    ):
        caption = say(lang, key)
        parts.append(element("h3", escape(caption)))
        parts.append(element("figure", figure_svg(draw(plan, state), prefix, caption)))
    return "".join(parts)


def _reaction_rows(data: Mapping[str, Any]) -> list[list[str]]:
    """Each reaction: point, which link on which, kind, force components, magnitude, couple."""
    rows = []
    for k, r in enumerate(data["reactions"]):
        path = ("reactions", k)
        row = [escape(r["point"] or "?"), escape(" → ".join(r["links"])), escape(r["kind"])]
        row += [number_cell(r["force"][i], "forces", (*path, "force", i)) for i in (0, 1)]
        row.append(number_cell(r["magnitude"], "forces", (*path, "magnitude")))
        row.append(number_cell(r["couple"], "forces", (*path, "couple")) if "couple" in r else "")
        rows.append(row)
    return rows


def _balancing_lines(contents: ReportContents, lang: str) -> list[str]:
    """The balancing moment(s) or force(s), friction, compound pins: list items."""
    solution, data = contents.forces, contents.forces_dict
    assert solution is not None and data is not None
    single = len(solution.balancing_moment) == 1
    out = []
    for link, value in solution.balancing_moment.items():
        key = "balancing_slide" if link in solution.balancing_slide_force else "balancing_moment"
        text = say(lang, key, link=link, value=format_number(value))
        path = "balancing_moment" if single else f"balancing_moment/{link}"
        out.append(
            element(
                "li", escape(text), data_source="forces", data_path=path, data_value=repr(value)
            )
        )
    if solution.balancing_force is not None:
        fx, fy = (format_number(v) for v in solution.balancing_force)
        out.append(element("li", escape(say(lang, "balancing_force", fx=fx, fy=fy))))
    if solution.friction_loss is not None:
        text = say(lang, "friction_loss", value=format_number(solution.friction_loss))
        out.append(element("li", escape(text)))
    for point, forces in solution.pin_forces.items():
        pushes = ", ".join(
            f"{link}: ({format_number(f[0])}, {format_number(f[1])})" for link, f in forces.items()
        )
        out.append(element("li", escape(say(lang, "compound_pin", point=point, forces=pushes))))
    return out


def _power_latex(contents: ReportContents) -> str:
    r"""``Σ P·v + Σ M·ω + M_cb·ω_1 = 0``, one balancing term per driver (``P_cb·v`` on a slide)."""
    terms = [
        rf"M_{{cb}}\,\omega_{{{d.link}}}" if d.kind == "R" else rf"P_{{cb}}\,v_{{{d.link}}}"
        for d in contents.plan.drivers  # type: ignore[union-attr]
    ]
    return (
        r"\sum \vec{P}_{i}\cdot \vec{v}_{i} + \sum M_{i}\,\omega_{i} + "
        + " + ".join(terms)
        + " = 0"
    )


def forces_html(contents: ReportContents, lang: str) -> str:
    """Reactions, balancing, the virtual-power check and the force polygons (or the note)."""
    solution, data, plan = contents.forces, contents.forces_dict, contents.plan
    if solution is None or data is None or plan is None:
        return part_note(contents, "forces", lang)
    parts = [element("h3", escape(say(lang, "h_reactions", order=" → ".join(data["order"]))))]
    headings = [say(lang, "point"), say(lang, "acting"), say(lang, "kind")]
    headings += ["F_x (N)", "F_y (N)", "|F| (N)", say(lang, "couple")]
    parts.append(element("div", table(headings, _reaction_rows(data)), class_="wide"))
    parts.append(element("h3", escape(say(lang, "h_balancing"))))
    parts.append(element("ul", "".join(_balancing_lines(contents, lang))))
    parts.append(element("h3", escape(say(lang, "h_power"))))
    parts.append(
        element("div", latex_to_mathml(_power_latex(contents), display=True), class_="formula")
    )
    residual = data["power_residual"]
    shown = f"{residual:.2e}" if math.isfinite(residual) else "—"
    parts.append(
        element(
            "p",
            escape(say(lang, "power_check", value=shown)),
            data_source="forces",
            data_path="power_residual",
            data_value=repr(residual),
        )
    )
    caption = say(lang, "h_force_polygons")
    parts.append(element("h3", escape(caption)))
    for k, (label, _, _) in enumerate(polygon_entries(plan, solution)):
        fig = force_polygon(plan, solution, label, state=contents.state)
        parts.append(_figure(figure_svg(fig, f"fig-forces-{k}", f"{caption}: {label}"), label))
    return "".join(parts)
