"""The report's cam section: each designed cam's SVAJ diagrams, profile, checks and worked solution.

For every ``cam`` statement of the mechanism, :func:`cams_html` runs what
``assur cam`` runs (:func:`kinematics.cams.summary.cam_report`) and writes the
SVAJ diagrams beside the profile (an inline SVG), a table of the checks (the
pressure angle, the radii of curvature, undercut, the flat face's width, the
smallest base circle, the force closure), the continuity at each join, and
the worked solution of the checks, in the page's language. The numbers are
those of ``assur cam --json`` (each cell names its path there).
"""

from __future__ import annotations

from html import escape

from structure.errors import MechanismError

from ..cams.design import make_design
from ..cams.summary import CamReport, cam_report
from ..explain.cam import explain_cam
from ..figures.cam import cam_sheet
from .contents import ReportContents
from .markup import element, note, number_cell, table
from .phrases import say
from .svg import figure_svg

__all__ = ["cams_html"]

_WORDS = {
    "en": {
        "cam_head": "Cam {cam}–{other}: {name}",
        "cam_figure": "SVAJ diagrams at the cam's speed, and the profile at θ = 0",
        "cam_checks": "Checks over the cycle",
        "cam_joins": "Continuity at the joins",
        "cam_worked": "Worked solution of the checks",
        "quantity": "Quantity",
        "value": "Value",
        "at": "At θ (°)",
        "pressure": "largest pressure angle (°), limit {limit}°",
        "pitch_min": "smallest convex radius of the pitch curve (m)",
        "profile_min": "smallest convex radius of the profile (m)",
        "undercut": "undercut",
        "yes": "yes, at {at}",
        "no": "none",
        "face": "flat face's width (m)",
        "base": "smallest base circle for the limit, no undercut (m)",
        "jump": "jump speed (rad/s)",
        "never": "never",
        "contact": "largest contact force (N)",
        "torque": "largest camshaft torque (N·m)",
        "join": "Join (°)",
        "order": "Continuity",
        "what": "What jumps",
        "nothing": "nothing up to the jerk",
        "infinite": "the acceleration: infinite jerk",
    },
    "vi": {
        "cam_head": "Cam {cam}–{other}: {name}",
        "cam_figure": "Đồ thị s, v, a, j theo góc quay cam và biên dạng cam tại θ = 0",
        "cam_checks": "Kiểm tra trên cả chu kỳ",
        "cam_joins": "Tính liên tục tại các điểm nối",
        "cam_worked": "Lời giải chi tiết",
        "quantity": "Đại lượng",
        "value": "Giá trị",
        "at": "Tại θ (°)",
        "pressure": "góc áp lực lớn nhất (°), giới hạn {limit}°",
        "pitch_min": "bán kính cong lồi nhỏ nhất của biên dạng lý thuyết (m)",
        "profile_min": "bán kính cong lồi nhỏ nhất của biên dạng thực (m)",
        "undercut": "cắt lẹm",
        "yes": "có, tại {at}",
        "no": "không",
        "face": "bề rộng đáy bằng (m)",
        "base": "bán kính vòng cơ sở nhỏ nhất thỏa giới hạn, không cắt lẹm (m)",
        "jump": "vận tốc góc tách cần (rad/s)",
        "never": "không tách",
        "contact": "lực tiếp xúc lớn nhất (N)",
        "torque": "mômen trên trục cam lớn nhất (N·m)",
        "join": "Điểm nối (°)",
        "order": "Liên tục",
        "what": "Đại lượng nhảy bậc",
        "nothing": "không có (tới độ giật)",
        "infinite": "gia tốc: độ giật vô cùng lớn",
    },
}


def _word(lang: str, key: str, **fields: object) -> str:
    return _WORDS[lang][key].format(**fields)


def _cell(value: float | None, path: str) -> str:
    if value is None:
        return element("td", "—")
    return number_cell(value, "assur cam --json", path.split("/"))


def _checks_table(report: CamReport, lang: str) -> str:
    checks, closure, base = report.checks, report.closure, report.base
    rows = [
        [
            escape(_word(lang, "pressure", limit=f"{checks.limit:g}")),
            _cell(checks.pressure.value, "pressure_angle/max_deg"),
            _cell(checks.pressure.at_deg, "pressure_angle/at_deg"),
        ]
    ]
    for key, found in (("pitch_min", checks.pitch_min), ("profile_min", checks.profile_min)):
        if found is not None:
            rows.append(
                [
                    escape(_word(lang, key)),
                    _cell(found.value, f"curvature/{key}/radius"),
                    _cell(found.at_deg, f"curvature/{key}/at_deg"),
                ]
            )
    where = ", ".join(f"{a:g}°–{b:g}°" for a, b in checks.undercut_at)
    verdict = _word(lang, "yes", at=where) if checks.undercut else _word(lang, "no")
    rows.append([escape(_word(lang, "undercut")), escape(verdict), ""])
    if checks.face_width is not None:
        rows.append([escape(_word(lang, "face")), _cell(checks.face_width, "face/width"), ""])
    rows.append([escape(_word(lang, "base")), _cell(base.base_radius, "base_circle/smallest"), ""])
    jump = closure.jump_speed
    rows.append(
        [
            escape(_word(lang, "jump")),
            _cell(jump, "jump_speed") if jump is not None else escape(_word(lang, "never")),
            "",
        ]
    )
    rows.append(
        [
            escape(_word(lang, "contact")),
            _cell(closure.peak_contact.value, "contact_force/max/value"),
            _cell(closure.peak_contact.at_deg, "contact_force/max/at_deg"),
        ]
    )
    rows.append(
        [
            escape(_word(lang, "torque")),
            _cell(closure.peak_torque.value, "camshaft_torque/max/value"),
            _cell(closure.peak_torque.at_deg, "camshaft_torque/max/at_deg"),
        ]
    )
    headings = [_word(lang, "quantity"), _word(lang, "value"), _word(lang, "at")]
    return table(headings, rows, _word(lang, "cam_checks"))


def _joins_table(report: CamReport, lang: str) -> str:
    rows = []
    for join in report.joins:
        jumped = [("s", "v", "a", "j")[order] for order, *_ in join.jumps]
        what = _word(lang, "infinite") if join.infinite_jerk else ", ".join(jumped)
        rows.append(
            [escape(f"{join.at_deg:g}"), escape(join.name), escape(what or _word(lang, "nothing"))]
        )
    headings = [_word(lang, "join"), _word(lang, "order"), _word(lang, "what")]
    return table(headings, rows, _word(lang, "cam_joins"))


def _demoted(fragment: str) -> str:
    """A worked solution's headings three levels down, under the cam's own."""
    for level in (4, 3, 2, 1):
        fragment = fragment.replace(f"<h{level}>", f"<h{min(level + 3, 6)}>")
        fragment = fragment.replace(f"</h{level}>", f"</h{min(level + 3, 6)}>")
    return fragment


def cams_html(contents: ReportContents, lang: str) -> str:
    """The cam section: each designed cam's figure, checks, joins and worked solution."""
    cams = contents.mechanism.cams
    if not cams:
        return note(say(lang, "no_cams"), "no_cams")
    parts = []
    for k, ref in enumerate(cams):
        title = _word(lang, "cam_head", cam=ref.cam, other=ref.other, name=ref.spec.name or "")
        parts.append(element("h3", escape(title.rstrip(": "))))
        try:
            design = make_design(ref.spec)
            report = cam_report(design, 360)
        except MechanismError as exc:
            parts.append(note(say(lang, "unsolved", reason=str(exc)), "unsolved"))
            continue
        caption = _word(lang, "cam_figure")
        svg = figure_svg(cam_sheet(design, 360), f"fig-cam-{k}", caption, tight=True)
        parts.append(element("figure", svg + element("figcaption", escape(caption))))
        parts.append(_checks_table(report, lang))
        parts.append(_joins_table(report, lang))
        parts.append(element("h4", escape(_word(lang, "cam_worked"))))
        parts.append(_demoted(explain_cam(report, lang, "html")))
    return "".join(parts)
