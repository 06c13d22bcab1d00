"""The report's dynamics section: steady running, flywheel and shaking, and its worked solution.

:func:`dynamics_html` solves what ``assur dynamics FILE`` solves (with its
defaults: δ = 0.02, 360 poses a turn, the file's drive), shows its main numbers
tied to the paths of ``assur dynamics --json`` (``data-source="dynamics"``),
its figures (J_r, M_r, ω, the runs, Wittenbauer's diagram, the shaking) and
its worked solution. A mechanism with no mass data says so in one line; one
whose dynamics cannot be found, in one line with the reason.
"""

from __future__ import annotations

from html import escape

from structure.errors import MechanismError

from ..dynamics.analysis import MachineDynamics, machine_dynamics
from ..explain.dynamics import explain_dynamics
from ..figures.dynamics import dynamics_sheet
from .contents import ReportContents
from .markup import element, note, number_cell, table
from .phrases import say
from .svg import figure_svg

__all__ = ["dynamics_html"]

_PHRASES: dict[str, dict[str, str]] = {
    "en": {
        "no_masses": "Not applicable: the file gives no masses (mass lines).",
        "h_numbers": "The machine reduced to its driver",
        "h_figures": "Over the cycle",
        "h_worked": "Worked solution: the reduced inertia and the flywheel",
        "quantity": "quantity",
        "value": "value",
        "J_min": "reduced inertia J_r, least (kg·m²)",
        "J_max": "reduced inertia J_r, largest (kg·m²)",
        "J_mean": "reduced inertia J_r, mean (kg·m²)",
        "omega_mean": "mean speed ω_m = (ω_max + ω_min)/2 (rad/s)",
        "omega_time_mean": "mean speed over time 2π/T (rad/s)",
        "delta": "coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m",
        "delta_goal": "δ asked of the flywheel",
        "J_exact": "flywheel, exact (Wittenbauer) (kg·m²)",
        "J_approx": "flywheel, approximate ΔE_max/(δ·ω_m²) (kg·m²)",
        "start": "start-up from rest to steady running (s)",
        "stop": "run-down with the drive off (s)",
        "force_max": "largest shaking force (N)",
        "moment_max": "largest shaking moment (N·m)",
        "figure": "J_r, M_r, ω over the cycle, the runs, Wittenbauer's diagram, the shaking",
    },
    "vi": {
        "no_masses": "Không áp dụng: tệp không cho khối lượng (dòng mass).",
        "h_numbers": "Máy thu gọn về khâu dẫn",
        "h_figures": "Trong một chu kỳ",
        "h_worked": "Lời giải: mômen quán tính thu gọn và bánh đà",
        "quantity": "đại lượng",
        "value": "giá trị",
        "J_min": "mômen quán tính thu gọn J_td, nhỏ nhất (kg·m²)",
        "J_max": "mômen quán tính thu gọn J_td, lớn nhất (kg·m²)",
        "J_mean": "mômen quán tính thu gọn J_td, trung bình (kg·m²)",
        "omega_mean": "vận tốc góc trung bình ω_tb = (ω_max + ω_min)/2 (rad/s)",
        "omega_time_mean": "vận tốc góc trung bình theo thời gian 2π/T (rad/s)",
        "delta": "hệ số chuyển động không đều δ = (ω_max − ω_min)/ω_tb",
        "delta_goal": "δ yêu cầu khi tính bánh đà",
        "J_exact": "bánh đà, chính xác (Wittenbauer) (kg·m²)",
        "J_approx": "bánh đà, gần đúng ΔE_max/(δ·ω_tb²) (kg·m²)",
        "start": "mở máy từ đứng yên đến chuyển động bình ổn (s)",
        "stop": "dừng máy khi ngắt động cơ (s)",
        "force_max": "lực rung lớn nhất (N)",
        "moment_max": "mômen rung lớn nhất (N·m)",
        "figure": (
            "J_td, M_td, ω trong một chu kỳ, mở máy và dừng máy, đồ thị Wittenbauer, lực rung"
        ),
    },
}


def _say(lang: str, key: str) -> str:
    return _PHRASES[lang][key]


def _rows(result: MachineDynamics, lang: str) -> list[list[str]]:
    """The main numbers, each tied to its path in ``assur dynamics --json``."""
    props = result.machine.properties
    rows = []

    def row(key: str, value: float, *path: object) -> None:
        rows.append([escape(_say(lang, key)), number_cell(float(value), "dynamics", path)])

    row("J_min", float(props.inertia.min()), "reduced_inertia", "min")
    row("J_max", float(props.inertia.max()), "reduced_inertia", "max")
    row("J_mean", float(props.inertia[:-1].mean()), "reduced_inertia", "mean")
    if result.steady is not None:
        row("omega_mean", result.steady.omega_mean, "steady", "omega_mean")
        row("omega_time_mean", result.steady.omega_time_mean, "steady", "omega_time_mean")
        row("delta", result.steady.delta, "steady", "delta")
    if result.flywheel is not None:
        row("delta_goal", result.flywheel.delta_goal, "flywheel", "delta_goal")
        row("J_exact", result.flywheel.exact, "flywheel", "J_exact")
        row("J_approx", result.flywheel.approximate, "flywheel", "J_approx")
    if result.start is not None:
        row("start", result.start.duration, "start_up", "time")
    if result.stop is not None:
        row("stop", result.stop.duration, "run_down", "time")
    if result.shaking is not None:
        row("force_max", result.shaking.force_max, "shaking", "force_max")
        row("moment_max", result.shaking.moment_max, "shaking", "moment_max")
    return rows


def _demoted(fragment: str) -> str:
    """The worked solution's headings two levels down, under the page's own."""
    for level in (4, 3, 2):
        fragment = fragment.replace(f"<h{level}>", f"<h{level + 2}>")
        fragment = fragment.replace(f"</h{level}>", f"</h{level + 2}>")
    return fragment


def dynamics_html(contents: ReportContents, lang: str) -> str:
    """The dynamics section's body: numbers, figures and the worked solution, or one note."""
    if not any(x.kind == "mass" for x in contents.mechanism.loads):
        return note(_say(lang, "no_masses"), "no_masses")
    try:
        result = machine_dynamics(contents.report)
    except MechanismError as exc:
        return note(say(lang, "unsolved", reason=str(exc)), "unsolved")
    parts = [element("h3", escape(_say(lang, "h_numbers")))]
    parts += [element("p", escape(text), class_="dynamics-note") for text in result.notes]
    parts.append(table([_say(lang, "quantity"), _say(lang, "value")], _rows(result, lang)))
    parts.append(element("h3", escape(_say(lang, "h_figures"))))
    caption = _say(lang, "figure")
    svg = figure_svg(dynamics_sheet(result), "fig-dynamics", caption, tight=False)
    parts.append(element("figure", svg))
    parts.append(element("h3", escape(_say(lang, "h_worked"))))
    parts.append(_demoted(explain_dynamics(result, lang, "html")))
    return "".join(parts)
