"""The worked solution of a cam's design checks, in English and Vietnamese.

:func:`explain_cam` writes, from a :class:`~kinematics.cams.summary.CamReport`,
the steps a course takes: the follower's program segment by segment (each
law's formula, its peak factors and the peaks they give at ω), the joins and
the fundamental law of cam design, the pressure angle at its largest with
the numbers put in, the radius of curvature at its smallest, undercut, the
smallest base circle, and the force closure with the jump speed.
:func:`explain_cam_step` writes, for a kinematics worked solution, the cam's
group at the pose: the follower placed by its program and its velocity and
acceleration from the replacement rebuilt at that pose.

>>> from structure.cams import cam_spec_from_dict
>>> from kinematics.cams.design import make_design
>>> from kinematics.cams.summary import cam_report
>>> report = cam_report(make_design(cam_spec_from_dict({"base_radius": 0.04, "omega": 10,
...     "follower": {"motion": "translating", "contact": "roller", "roller_radius": 0.01},
...     "segments": [{"law": "harmonic", "lift": 0.02, "angle": 180},
...                  {"law": "harmonic", "lift": -0.02, "angle": 180}]})), 72)
>>> "tan φ = (s' − ε)/(√(R_p² − ε²) + s)" in explain_cam(report)
True
>>> "góc áp lực" in explain_cam(report, "vi")
True
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from structure.cams import FollowerContact, MotionLaw
from structure.explain.document import Doc, Math, check_options, number, render

from ..cams.contact import cam_pose, cam_rates
from ..cams.profile import cam_geometry
from ..cams.summary import CamReport

if TYPE_CHECKING:
    from ..solvers.plan import GroupStep
    from .context import SolutionContext

__all__ = ["CAM_PHRASES", "explain_cam", "explain_cam_step"]

#: the sentences of the cam's worked solution, by language (the keys start with ``cam_``)
CAM_PHRASES: dict[str, dict[str, str]] = {
    "en": {
        "cam_title": "Cam design: {name}",
        "cam_conventions": (
            "Units m, s, rad (the cam angle θ and the lifts of a swinging follower in degrees "
            "where written °). θ is the cam's turn in its own sense; s(θ) the follower's "
            "displacement, s' = ds/dθ, s'' and s''' the next derivatives; at the constant speed "
            "ω: v = s'·ω, a = s''·ω², j = s'''·ω³."
        ),
        "cam_follower_t": (
            "Follower: translating {contact}, offset ε = {offset} m; base circle R_b = {base} m, "
            "prime circle R_p = {prime} m; the cam turns {sense} at ω = {omega} rad/s."
        ),
        "cam_follower_o": (
            "Follower: oscillating {contact}, pivot ({qx}, {qy}) m{arm}; base circle R_b = "
            "{base} m, prime circle R_p = {prime} m; the cam turns {sense} at ω = {omega} rad/s."
        ),
        "cam_program": "1. The follower's program",
        "cam_segment": "Segment {k}: {law} from {start}° to {end}° (β = {beta}°), lift h = {lift}",
        "cam_dwell": "Segment {k}: dwell from {start}° to {end}°: s constant, v = a = j = 0",
        "cam_fitted": (
            "Segment {k}: a polynomial from {start}° to {end}° fitted to the boundary conditions "
            "(Norton's SVAJ method): s = Σ c_i·x^i with"
        ),
        "cam_peaks": "peaks: v = {v}, a = {a}, j = {j}",
        "cam_joins": "2. Continuity at the joins",
        "cam_join": "{at}°: {name} ({what})",
        "cam_c3": "s, v, a and j continuous",
        "cam_c2": "the jerk jumps, finitely",
        "cam_c1": "the acceleration jumps: infinite jerk",
        "cam_c0": "the velocity jumps: infinite acceleration",
        "cam_cm1": "the displacement jumps",
        "cam_law_broken": (
            "The fundamental law of cam design (s, v and a continuous over the whole cycle) is "
            "broken at {at}: there the jerk is infinite."
        ),
        "cam_law_kept": (
            "The fundamental law of cam design holds: s, v and a are continuous all round."
        ),
        "cam_pressure": "3. Pressure angle",
        "cam_pressure_t": (
            "For a translating roller (knife) follower the pressure angle is (Norton eq. 8.31):"
        ),
        "cam_pressure_flat": (
            "A flat face is always normal to its own motion: the pressure angle of a translating "
            "flat-faced follower is 0."
        ),
        "cam_pressure_o": (
            "For a swinging follower the pressure angle is the angle between the common normal n "
            "and the direction w in which the follower's point moves as it rises (⊥ the arm):"
        ),
        "cam_pressure_at": "It is largest at θ = {at}°:",
        "cam_pressure_ok": "|φ| = {phi}° ≤ {limit}°: the limit is met.",
        "cam_pressure_bad": "|φ| = {phi}° > {limit}°: too large; make the base circle larger.",
        "cam_curvature": "4. Radius of curvature and undercut",
        "cam_rho_t": (
            "The pitch curve (the roller centre's path on the cam) has the radius of curvature"
        ),
        "cam_rho_flat": "Under a flat face the profile's radius of curvature is",
        "cam_rho_o": "The pitch curve X(θ) has the radius of curvature",
        "cam_rho_at": "Smallest convex radius at θ = {at}°:",
        "cam_rho_profile": "The profile is the pitch curve moved R_f inward: ρ_profile = ρ − R_f:",
        "cam_concave": "Smallest concave radius (as a positive number): {rho} m at {at}°.",
        "cam_undercut_roller": (
            "Undercut: where the pitch curve is convex and ρ ≤ R_f = {rf} m the profile loops."
        ),
        "cam_undercut_flat": "Undercut (a cusp): where R_b + s + s'' ≤ 0.",
        "cam_undercut_none": "None here: the profile is smooth all round.",
        "cam_undercut_found": "FOUND at {at}: the cam cannot be cut as designed.",
        "cam_face": "The flat face must reach from {lo} m to {hi} m along it: width ≥ {w} m.",
        "cam_base": "5. The smallest base circle",
        "cam_base_t": (
            "With T = tan φ_max the follower's height at s = 0 must satisfy "
            "d ≥ max over θ of (|s' − ε|/T − s), and R_p = √(d² + ε²), R_b = R_p − R_f:"
        ),
        "cam_base_value": "R_b,min = {base} m (set by the {bound}).",
        "cam_base_best": "With the offset that helps most, ε = {eps} m: R_b,min = {base} m.",
        "cam_base_flat": "Under a flat face: R_b > max over θ of −(s + s'') = {base} m.",
        "cam_base_none": "No base circle meets the limit with this pivot and arm.",
        "cam_closure": "6. Force closure",
        "cam_closure_force": (
            "Along its motion the follower needs from the cam F_c = m·s''·ω² + k·s + F_0 + F "
            "(for a swinging follower the moments about its pivot); the contact force is "
            "F_c/cos φ; contact is lost where F_c < 0."
        ),
        "cam_closure_at": "At θ = {at}°, where the contact force is largest:",
        "cam_jump": "Jump speed: ω_jump² = min over s'' < 0 of (k·s + F_0 + F)/(−m·s''):",
        "cam_jump_none": "The follower never leaves the cam (no mass, or no deceleration).",
        "cam_jump_rest": "The spring and load pull the follower off the cam even at rest.",
        "cam_lost": "At ω = {omega} rad/s contact is LOST at {at}.",
        "cam_kept": "At ω = {omega} rad/s contact holds all round.",
        "cam_spring": (
            "To keep contact up to {up} rad/s: preload F_0 ≥ {f0} with the rate given, or rate "
            "k ≥ {k} with the preload given."
        ),
        # a cam's group in a kinematics solution
        "cam_step": (
            "Cam {cam} has the profile of its program: at this pose it has turned {turn}° from "
            "the sketch, the program's angle is θ = {theta}° and the follower's displacement "
            "s = {s} (placed by the program)."
        ),
        "cam_step_replaced": (
            "The higher pair is replaced at this pose: virtual link {v} from the profile's centre "
            "of curvature C (on cam {cam}, ρ = {rho} m) to the follower's point {point}; its "
            "velocity and acceleration equations along the common normal n give"
        ),
        "cam_step_flat": (
            "The higher pair is replaced at this pose: virtual link {v} pinned at the profile's "
            "centre of curvature C (on cam {cam}, ρ = {rho} m) and sliding along the face of "
            "{follower}; its equations along the face's normal give"
        ),
        "cam_step_law": "The program's law gives the same: s'·θ̇ = {v1}, s''·θ̇² + s'·θ̈ = {a1}.",
        "cam_f_group": (
            "Follower {follower} is in equilibrium under its loads, the contact force of cam "
            "{cam} along the common normal (the virtual link that replaces the contact at this "
            "pose carries it) and its guide's reaction at {guide}: three equations for the "
            "contact force's size and the guide's two unknowns (a slide's normal force and "
            "couple, or a pivot's two components)."
        ),
    },
    "vi": {
        "cam_title": "Thiết kế cơ cấu cam: {name}",
        "cam_conventions": (
            "Đơn vị m, s, rad (góc quay cam θ và góc lắc của cần lắc tính bằng độ khi viết °). "
            "θ là góc quay của cam theo chiều quay của nó; s(θ) là chuyển vị của cần, "
            "s' = ds/dθ, s'' và s''' là các đạo hàm tiếp theo; khi cam quay đều với vận tốc góc "
            "ω: v = s'·ω, a = s''·ω², j = s'''·ω³ (j: độ giật)."
        ),
        "cam_follower_t": (
            "Cần đẩy {contact}, độ lệch tâm ε = {offset} m; bán kính vòng cơ sở R_b = {base} m, "
            "vòng tròn lý thuyết R_p = {prime} m; cam quay {sense} với ω = {omega} rad/s."
        ),
        "cam_follower_o": (
            "Cần lắc {contact}, tâm lắc ({qx}, {qy}) m{arm}; bán kính vòng cơ sở R_b = {base} m, "
            "vòng tròn lý thuyết R_p = {prime} m; cam quay {sense} với ω = {omega} rad/s."
        ),
        "cam_program": "1. Quy luật chuyển động của cần",
        "cam_segment": (
            "Đoạn {k}: {law} từ {start}° đến {end}° (β = {beta}°), hành trình h = {lift}"
        ),
        "cam_dwell": "Đoạn {k}: đứng yên từ {start}° đến {end}°: s không đổi, v = a = j = 0",
        "cam_fitted": (
            "Đoạn {k}: đa thức từ {start}° đến {end}° thỏa các điều kiện biên (phương pháp "
            "SVAJ của Norton): s = Σ c_i·x^i với"
        ),
        "cam_peaks": "giá trị lớn nhất: v = {v}, a = {a}, j = {j}",
        "cam_joins": "2. Tính liên tục tại các điểm nối",
        "cam_join": "{at}°: {name} ({what})",
        "cam_c3": "s, v, a và j liên tục",
        "cam_c2": "độ giật nhảy bậc, hữu hạn",
        "cam_c1": "gia tốc nhảy bậc: độ giật vô cùng lớn (va đập mềm)",
        "cam_c0": "vận tốc nhảy bậc: gia tốc vô cùng lớn (va đập cứng)",
        "cam_cm1": "chuyển vị nhảy bậc",
        "cam_law_broken": (
            "Định luật cơ bản của thiết kế cam (s, v, a liên tục trên cả chu kỳ) bị vi phạm tại "
            "{at}: ở đó độ giật vô cùng lớn."
        ),
        "cam_law_kept": "Định luật cơ bản của thiết kế cam được thỏa: s, v, a liên tục.",
        "cam_pressure": "3. Góc áp lực",
        "cam_pressure_t": "Với cần đẩy con lăn (đầu nhọn), góc áp lực là (Norton, pt. 8.31):",
        "cam_pressure_flat": (
            "Đáy bằng luôn vuông góc với phương chuyển động của nó: góc áp lực của cần đẩy đáy "
            "bằng bằng 0."
        ),
        "cam_pressure_o": (
            "Với cần lắc, góc áp lực là góc giữa pháp tuyến chung n và phương w của vận tốc "
            "điểm tiếp xúc trên cần khi cần đi xa (⊥ tay cần):"
        ),
        "cam_pressure_at": "Góc áp lực lớn nhất tại θ = {at}°:",
        "cam_pressure_ok": "|φ| = {phi}° ≤ {limit}°: thỏa điều kiện.",
        "cam_pressure_bad": "|φ| = {phi}° > {limit}°: quá lớn; cần tăng bán kính vòng cơ sở.",
        "cam_curvature": "4. Bán kính cong và hiện tượng cắt lẹm",
        "cam_rho_t": "Biên dạng lý thuyết (quỹ đạo tâm con lăn trên cam) có bán kính cong",
        "cam_rho_flat": "Với cần đáy bằng, bán kính cong của biên dạng là",
        "cam_rho_o": "Biên dạng lý thuyết X(θ) có bán kính cong",
        "cam_rho_at": "Bán kính cong lồi nhỏ nhất tại θ = {at}°:",
        "cam_rho_profile": (
            "Biên dạng thực cách biên dạng lý thuyết R_f vào trong: ρ_thực = ρ − R_f:"
        ),
        "cam_concave": "Bán kính cong lõm nhỏ nhất (trị tuyệt đối): {rho} m tại {at}°.",
        "cam_undercut_roller": (
            "Cắt lẹm: nơi biên dạng lý thuyết lồi và ρ ≤ R_f = {rf} m, biên dạng thực tự cắt."
        ),
        "cam_undercut_flat": "Biên dạng bị nhọn (cắt lẹm): nơi R_b + s + s'' ≤ 0.",
        "cam_undercut_none": "Không có: biên dạng trơn trên cả vòng.",
        "cam_undercut_found": "CÓ tại {at}: không chế tạo được cam như đã thiết kế.",
        "cam_face": "Đáy bằng phải dài từ {lo} m đến {hi} m: bề rộng ≥ {w} m.",
        "cam_base": "5. Bán kính vòng cơ sở nhỏ nhất",
        "cam_base_t": (
            "Với T = tan φ_max, độ cao của tâm con lăn khi s = 0 phải thỏa "
            "d ≥ max theo θ của (|s' − ε|/T − s), R_p = √(d² + ε²), R_b = R_p − R_f:"
        ),
        "cam_base_value": "R_b,min = {base} m (do {bound}).",
        "cam_base_best": "Với độ lệch tâm có lợi nhất ε = {eps} m: R_b,min = {base} m.",
        "cam_base_flat": "Với cần đáy bằng: R_b > max theo θ của −(s + s'') = {base} m.",
        "cam_base_none": "Không có vòng cơ sở nào thỏa với tâm lắc và tay cần này.",
        "cam_closure": "6. Đảm bảo tiếp xúc bằng lực (lò xo)",
        "cam_closure_force": (
            "Lực cam phải tác dụng lên cần theo phương chuyển động của cần là F_c = m·s''·ω² + "
            "k·s + F_0 + F (với cần lắc: mômen đối với tâm lắc); lực tiếp xúc là F_c/cos φ; cần "
            "tách khỏi cam nơi F_c < 0."
        ),
        "cam_closure_at": "Tại θ = {at}°, nơi lực tiếp xúc lớn nhất:",
        "cam_jump": (
            "Vận tốc góc tách cần: ω_tách² = min (khi s'' < 0) của (k·s + F_0 + F)/(−m·s''):"
        ),
        "cam_jump_none": (
            "Cần không bao giờ tách khỏi cam (không có khối lượng hoặc không giảm tốc)."
        ),
        "cam_jump_rest": "Lò xo và tải kéo cần rời cam ngay cả khi đứng yên.",
        "cam_lost": "Với ω = {omega} rad/s cần TÁCH khỏi cam tại {at}.",
        "cam_kept": "Với ω = {omega} rad/s cần luôn tiếp xúc với cam.",
        "cam_spring": (
            "Để giữ tiếp xúc tới {up} rad/s: lực nén ban đầu F_0 ≥ {f0} với độ cứng đã cho, "
            "hoặc độ cứng k ≥ {k} với lực nén ban đầu đã cho."
        ),
        "cam_step": (
            "Cam {cam} có biên dạng theo quy luật chuyển động: tại vị trí này cam đã quay {turn}° "
            "so với hình vẽ, góc của quy luật θ = {theta}° và chuyển vị của cần s = {s} "
            "(đặt theo quy luật)."
        ),
        "cam_step_replaced": (
            "Thay thế khớp cao tại vị trí này: khâu ảo {v} nối tâm cong C của biên dạng (trên cam "
            "{cam}, ρ = {rho} m) với điểm {point} của cần; phương trình vận tốc và gia tốc của nó "
            "chiếu lên pháp tuyến chung n cho"
        ),
        "cam_step_flat": (
            "Thay thế khớp cao tại vị trí này: khâu ảo {v} nối bản lề tại tâm cong C của biên "
            "dạng (trên cam {cam}, ρ = {rho} m) và trượt dọc đáy của {follower}; chiếu lên pháp "
            "tuyến của đáy được"
        ),
        "cam_step_law": "Quy luật chuyển động cho cùng kết quả: s'·θ̇ = {v1}, s''·θ̇² + s'·θ̈ = {a1}.",
        "cam_f_group": (
            "Cần {follower} cân bằng dưới tác dụng của ngoại lực, lực tiếp xúc của cam {cam} theo "
            "pháp tuyến chung (do khâu ảo thay thế khớp cao tại vị trí này truyền) và phản lực "
            "của giá tại {guide}: ba phương trình cho độ lớn lực tiếp xúc và hai ẩn của giá "
            "(lực pháp tuyến và mômen của khớp tịnh tiến, hoặc hai thành phần của khớp quay)."
        ),
    },
}

_LAW_NAMES = {
    "en": {
        "uniform": "uniform velocity",
        "harmonic": "simple harmonic",
        "cycloidal": "cycloidal",
        "modified-trapezoid": "modified trapezoid",
        "modified-sine": "modified sine",
        "3-4-5": "3-4-5 polynomial",
        "4-5-6-7": "4-5-6-7 polynomial",
    },
    "vi": {
        "uniform": "vận tốc đều",
        "harmonic": "điều hòa (cosin)",
        "cycloidal": "xycloit (sin)",
        "modified-trapezoid": "hình thang cải tiến",
        "modified-sine": "sin cải tiến",
        "3-4-5": "đa thức 3-4-5",
        "4-5-6-7": "đa thức 4-5-6-7",
    },
}
_CONTACT = {
    "en": {"knife": "knife-edge", "roller": "roller", "flat": "flat-faced"},
    "vi": {"knife": "đầu nhọn", "roller": "con lăn", "flat": "đáy bằng"},
}
_SENSE = {
    "en": ("counter-clockwise", "clockwise"),
    "vi": ("ngược chiều kim đồng hồ", "cùng chiều kim đồng hồ"),
}
_BOUND = {
    "en": {"pressure angle": "pressure angle", "undercut": "undercut", "reach": "follower's reach"},
    "vi": {"pressure angle": "góc áp lực", "undercut": "cắt lẹm", "reach": "tầm với của cần"},
}
#: each law's y(x) for a unit rise, as text and LaTeX
_LAW_FORMULAS = {
    "uniform": ("y = x", r"y = x"),
    "harmonic": ("y = (1 − cos πx)/2", r"y = \frac{1 - \cos \pi x}{2}"),
    "cycloidal": ("y = x − sin(2πx)/(2π)", r"y = x - \frac{\sin 2\pi x}{2\pi}"),
    "modified-trapezoid": (
        "y'' = C_a·sin 4πx (x ≤ 1/8), C_a (to 3/8), C_a·cos 4π(x − 3/8) (to 5/8), …",
        r"y'' = C_a \sin 4\pi x\ (x \le 1/8),\ C_a\ (\le 3/8),\ C_a \cos 4\pi(x - 3/8)\ (\le 5/8),"
        r"\ \ldots",
    ),
    "modified-sine": (
        "y'' = C_a·sin 4πx (x ≤ 1/8), C_a·cos(4π/3·(x − 1/8)) (to 7/8), …",
        r"y'' = C_a \sin 4\pi x\ (x \le 1/8),\ C_a \cos\frac{4\pi}{3}(x - 1/8)\ (\le 7/8),\ \ldots",
    ),
    "3-4-5": ("y = 10x³ − 15x⁴ + 6x⁵", r"y = 10x^3 - 15x^4 + 6x^5"),
    "4-5-6-7": ("y = 35x⁴ − 84x⁵ + 70x⁶ − 20x⁷", r"y = 35x^4 - 84x^5 + 70x^6 - 20x^7"),
}


def _doc(lang: str) -> Doc:
    return Doc(CAM_PHRASES, lang)


def explain_cam(report: CamReport, lang: str = "en", fmt: str = "text") -> str:
    """The worked solution of a cam design's checks (``lang`` en or vi; ``fmt`` as render takes).

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.
    """
    check_options(lang, fmt)
    doc = _doc(lang)
    design = report.design
    spec, layout = design.spec, design.layout
    f = spec.follower
    doc.title(*doc.say("cam_title", name=spec.name or "disc cam"))
    doc.para(doc.word("cam_conventions"))
    sense = _SENSE[lang][0 if layout.sense > 0 else 1]
    contact = _CONTACT[lang][f.contact.value]
    common = dict(
        contact=contact,
        base=number(spec.base_radius),
        prime=number(layout.prime),
        sense=sense,
        omega=number(abs(spec.omega)),
    )
    if f.translating:
        doc.para(*doc.say("cam_follower_t", offset=number(f.offset), **common))
    else:
        arm = f", L = {number(f.arm)} m" if f.arm else ""
        doc.para(
            *doc.say(
                "cam_follower_o", qx=number(f.pivot[0]), qy=number(f.pivot[1]), arm=arm, **common
            )
        )
    _program(doc, report, lang)
    _joins(doc, report)
    _pressure(doc, report)
    _curvature(doc, report)
    _base(doc, report, lang)
    _closure(doc, report)
    return render(doc, fmt)


def _unit(design) -> tuple[str, str]:
    return ("°", "rad") if not design.translating else (" m", "m")


def _program(doc: Doc, report: CamReport, lang: str) -> None:
    design = report.design
    doc.heading(doc.word("cam_program"))
    lift_unit, rate = _unit(design)
    w = abs(design.omega)
    for x, piece in zip(report.segments, design.program.pieces, strict=True):
        fields = dict(k=x.index + 1, start=number(x.start_deg), end=number(x.end_deg))
        if x.law is MotionLaw.DWELL:
            doc.para(*doc.say("cam_dwell", **fields))
            continue
        beta = x.end_deg - x.start_deg
        if x.law is MotionLaw.POLYNOMIAL:
            doc.para(*doc.say("cam_fitted", **fields))
            terms = " + ".join(f"({number(c)})·x^{i}" for i, c in enumerate(piece.coefficients))
            doc.equation(Math("s = " + terms, "s = " + terms.replace("·", r" \cdot ")))
        else:
            law = _LAW_NAMES[lang][x.law.value]
            doc.para(
                *doc.say(
                    "cam_segment", law=law, beta=number(beta), lift=f"{number(x.lift)}{lift_unit}",
                    **fields,
                )
            )  # fmt: skip
            text, latex = _LAW_FORMULAS[x.law.value]
            start, span = number(x.start_deg), number(beta)
            doc.equation(
                Math(
                    f"{text},  x = (θ − {start}°)/{span}°,  s = s0 + h·y",
                    latex + rf",\quad x = \frac{{\theta - {start}^\circ}}{{{span}^\circ}},"
                    r"\quad s = s_0 + h\,y",
                )
            )
            b = math.radians(beta)
            h = abs(piece.lift)
            cv, ca, cj = (x.v * b / (h * w), x.a * b**2 / (h * w**2), x.j * b**3 / (h * w**3))
            doc.equation(
                Math(
                    f"v_max = C_v·h·ω/β = {number(cv)}·{number(h)}·{number(w)}/{number(b)} "
                    f"= {number(x.v)} {rate}/s,  a_max = C_a·h·ω²/β² = {number(ca)}·h·ω²/β² "
                    f"= {number(x.a)} {rate}/s²,  j_max = C_j·h·ω³/β³ = {number(cj)}·h·ω³/β³ "
                    f"= {number(x.j)} {rate}/s³",
                    rf"v_{{max}} = C_v \frac{{h\omega}}{{\beta}} = {number(cv)} \cdot "
                    rf"\frac{{{number(h)} \cdot {number(w)}}}{{{number(b)}}} = {number(x.v)},\quad "
                    rf"a_{{max}} = {number(ca)}\,\frac{{h\omega^2}}{{\beta^2}} = {number(x.a)},"
                    rf"\quad j_{{max}} = {number(cj)}\,\frac{{h\omega^3}}{{\beta^3}} = "
                    rf"{number(x.j)}",
                )
            )


def _joins(doc: Doc, report: CamReport) -> None:
    doc.heading(doc.word("cam_joins"))
    what = {3: "cam_c3", 2: "cam_c2", 1: "cam_c1", 0: "cam_c0", -1: "cam_cm1"}
    for join in report.joins:
        doc.item(*doc.say("cam_join", at=number(join.at_deg), name=join.name,
                          what=doc.word(what[join.order])))  # fmt: skip
    if report.infinite_jerk_at:
        at = ", ".join(f"{number(x)}°" for x in report.infinite_jerk_at)
        doc.para(*doc.say("cam_law_broken", at=at))
    else:
        doc.para(doc.word("cam_law_kept"))


def _at(report: CamReport, degrees: float):
    """The geometry at one cam angle (degrees)."""
    return cam_geometry(report.design, np.array([math.radians(degrees)]))


def _pressure(doc: Doc, report: CamReport) -> None:
    design = report.design
    checks = report.checks
    f = design.spec.follower
    doc.heading(doc.word("cam_pressure"))
    g = _at(report, checks.pressure.at_deg)
    phi = checks.pressure.value
    if f.translating and f.contact is FollowerContact.FLAT:
        doc.para(doc.word("cam_pressure_flat"))
    elif f.translating:
        doc.para(doc.word("cam_pressure_t"))
        doc.equation(
            Math(
                "tan φ = (s' − ε)/(√(R_p² − ε²) + s)",
                r"\tan\varphi = \frac{s' - \varepsilon}{\sqrt{R_p^2 - \varepsilon^2} + s}",
            )
        )
        doc.para(*doc.say("cam_pressure_at", at=number(checks.pressure.at_deg)))
        eps, d = f.offset, design.layout.rise
        s, s1 = float(g.s[0]), float(g.s1[0])
        doc.equation(
            Math(
                f"tan φ = ({number(s1)} − {number(eps)})/({number(d)} + {number(s)}) "
                f"= {number(math.tan(math.radians(phi)))} ⇒ φ = {number(phi)}°",
                rf"\tan\varphi = \frac{{{number(s1)} - {number(eps)}}}{{{number(d)} + "
                rf"{number(s)}}} = {number(math.tan(math.radians(phi)))}\;\Rightarrow\;"
                rf"\varphi = {number(phi)}^\circ",
            )
        )
    else:
        doc.para(doc.word("cam_pressure_o"))
        doc.equation(Math("cos φ = n·w", r"\cos\varphi = \mathbf{n}\cdot\mathbf{w}"))
        doc.para(*doc.say("cam_pressure_at", at=number(checks.pressure.at_deg)))
        n, w = g.normal[0], g.way[0]
        doc.equation(
            Math(
                f"n = ({number(n[0])}, {number(n[1])}), w = ({number(w[0])}, {number(w[1])}) "
                f"⇒ φ = {number(phi)}°",
                rf"\mathbf{{n}} = ({number(n[0])}, {number(n[1])}),\ \mathbf{{w}} = "
                rf"({number(w[0])}, {number(w[1])})\;\Rightarrow\;\varphi = {number(phi)}^\circ",
            )
        )
    key = "cam_pressure_ok" if checks.pressure_ok else "cam_pressure_bad"
    doc.para(*doc.say(key, phi=number(abs(phi)), limit=number(checks.limit)))


def _curvature(doc: Doc, report: CamReport) -> None:
    design = report.design
    checks = report.checks
    f = design.spec.follower
    layout = design.layout
    doc.heading(doc.word("cam_curvature"))
    if f.contact is FollowerContact.FLAT:
        doc.para(doc.word("cam_rho_flat"))
        if f.translating:
            doc.equation(Math("ρ = R_b + s + s''", r"\rho = R_b + s + s''"))
        else:
            doc.equation(
                Math(
                    "ρ = h + (h''·(α' − σ) − h'·α'')/(α' − σ)³  (h, α: the face's place)",
                    r"\rho = h + \frac{h''(\alpha' - \sigma) - h'\alpha''}{(\alpha' - \sigma)^3}",
                )
            )
        smallest = checks.profile_min
    elif f.translating:
        doc.para(doc.word("cam_rho_t"))
        doc.equation(
            Math(
                "ρ = ((d + s)² + (s' − ε)²)^(3/2) / ((d + s)² + (s' − ε)(2s' − ε) − s''·(d + s)),"
                "  d = √(R_p² − ε²)",
                r"\rho = \frac{\left((d+s)^2 + (s'-\varepsilon)^2\right)^{3/2}}{(d+s)^2 + "
                r"(s'-\varepsilon)(2s'-\varepsilon) - s''(d+s)},\quad d = \sqrt{R_p^2 - "
                r"\varepsilon^2}",
            )
        )
        smallest = checks.pitch_min
    else:
        doc.para(doc.word("cam_rho_o"))
        doc.equation(Math("ρ = |X'|³/(X' × X'')", r"\rho = \frac{|X'|^3}{X' \times X''}"))
        smallest = checks.pitch_min
    if smallest is not None:
        doc.para(*doc.say("cam_rho_at", at=number(smallest.at_deg)))
        g = _at(report, smallest.at_deg)
        if f.contact is FollowerContact.FLAT and f.translating:
            doc.equation(
                Math(
                    f"ρ = {number(layout.base_radius)} + {number(float(g.s[0]))} + "
                    f"{number(float(g.s2[0]))} = {number(smallest.value)} m",
                    rf"\rho = {number(layout.base_radius)} + {number(float(g.s[0]))} + "
                    rf"{number(float(g.s2[0]))} = {number(smallest.value)}\ \mathrm{{m}}",
                )
            )
        else:
            doc.equation(
                Math(
                    f"ρ = {number(smallest.value)} m",
                    rf"\rho = {number(smallest.value)}\ \mathrm{{m}}",
                )
            )
    if layout.roller_radius and checks.profile_min is not None:
        doc.para(doc.word("cam_rho_profile"))
        doc.equation(
            Math(
                f"ρ_profile = {number(checks.pitch_min.value)} − {number(layout.roller_radius)} "
                f"= {number(checks.profile_min.value)} m",
                rf"\rho_{{profile}} = {number(checks.pitch_min.value)} - "
                rf"{number(layout.roller_radius)} = {number(checks.profile_min.value)}"
                r"\ \mathrm{m}",
            )
        )
    concave = checks.profile_concave if f.contact is FollowerContact.FLAT else checks.pitch_concave
    if concave is not None:
        doc.para(*doc.say("cam_concave", rho=number(concave.value), at=number(concave.at_deg)))
    if f.contact is FollowerContact.ROLLER:
        doc.para(*doc.say("cam_undercut_roller", rf=number(layout.roller_radius)))
    elif f.contact is FollowerContact.FLAT:
        doc.para(doc.word("cam_undercut_flat"))
    if checks.undercut:
        at = ", ".join(f"{number(a)}°–{number(b)}°" for a, b in checks.undercut_at)
        doc.para(*doc.say("cam_undercut_found", at=at))
    elif f.contact is not FollowerContact.KNIFE:
        doc.para(doc.word("cam_undercut_none"))
    if checks.face is not None:
        doc.para(
            *doc.say(
                "cam_face", lo=number(checks.face[0]), hi=number(checks.face[1]),
                w=number(checks.face_width),
            )
        )  # fmt: skip


def _base(doc: Doc, report: CamReport, lang: str) -> None:
    base = report.base
    f = report.design.spec.follower
    doc.heading(doc.word("cam_base"))
    if base.base_radius is None:
        doc.para(doc.word("cam_base_none"))
        return
    if f.translating and f.contact is FollowerContact.FLAT:
        doc.para(*doc.say("cam_base_flat", base=number(base.base_radius)))
        return
    if f.translating:
        doc.para(doc.word("cam_base_t"))
    doc.para(*doc.say("cam_base_value", base=number(base.base_radius),
                      bound=_BOUND[lang][base.bound]))  # fmt: skip
    if base.best_offset is not None:
        doc.para(
            *doc.say("cam_base_best", eps=number(base.best_offset),
                     base=number(base.best_base_radius))
        )  # fmt: skip


def _closure(doc: Doc, report: CamReport) -> None:
    closure = report.closure
    design = report.design
    spec = design.spec
    doc.heading(doc.word("cam_closure"))
    doc.para(doc.word("cam_closure_force"))
    at = closure.peak_contact.at_deg
    k = int(np.argmin(np.abs(np.degrees(closure.theta) - at)))
    g = _at(report, at)
    mass = spec.follower_mass if design.translating else spec.follower_inertia
    rate = spec.spring.rate if spec.spring is not None else 0.0
    preload = spec.spring.preload if spec.spring is not None else 0.0
    w = abs(spec.omega)
    s, s2 = float(g.s[0]), float(g.s2[0])
    doc.para(*doc.say("cam_closure_at", at=number(at)))
    doc.equation(
        Math(
            f"F_c = {number(mass)}·{number(s2)}·{number(w)}² + {number(rate)}·{number(s)} + "
            f"{number(preload)} + {number(spec.load)} = {number(float(closure.axial[k]))}; "
            f"F_c/cos φ = {number(float(closure.contact[k]))} N",
            rf"F_c = {number(mass)} \cdot {number(s2)} \cdot {number(w)}^2 + {number(rate)} "
            rf"\cdot {number(s)} + {number(preload)} + {number(spec.load)} = "
            rf"{number(float(closure.axial[k]))};\quad F_c/\cos\varphi = "
            rf"{number(float(closure.contact[k]))}\ \mathrm{{N}}",
        )
    )
    jump = closure.jump_speed
    if jump is None:
        doc.para(doc.word("cam_jump_none"))
    elif jump == 0.0:
        doc.para(doc.word("cam_jump_rest"))
    else:
        doc.para(doc.word("cam_jump"))
        doc.equation(Math(f"ω_jump = {number(jump)} rad/s", rf"\omega_{{jump}} = {number(jump)}"))
    if closure.lost_at:
        where = ", ".join(f"{number(a)}°–{number(b)}°" for a, b in closure.lost_at)
        doc.para(*doc.say("cam_lost", omega=number(w), at=where))
    else:
        doc.para(*doc.say("cam_kept", omega=number(w)))
    unit = "N" if design.translating else "N·m"
    per = "N/m" if design.translating else "N·m/rad"
    k_text = "—" if closure.rate_needed is None else f"{number(closure.rate_needed)} {per}"
    doc.para(
        *doc.say(
            "cam_spring", up=number(closure.up_to), f0=f"{number(closure.preload_needed)} {unit}",
            k=k_text,
        )
    )  # fmt: skip


# ------------------------------------------------------------------ a cam in a kinematics solution
def explain_cam_step(ctx: SolutionContext, step: GroupStep) -> None:
    """A designed cam's group at the pose: placed by the program, rates from the replacement."""
    doc = ctx.doc
    cam = step.cam
    say = Doc(CAM_PHRASES, doc.lang).say
    turned = ctx.state.links[cam.cam].angle if cam.cam in ctx.state.links else 0.0
    pose = cam_pose(cam, np.array([turned]))
    theta = math.degrees(float(pose.theta[0])) % 360.0
    s = float(cam.design.program.to_file_units(pose.s)[0])
    unit = "°" if not cam.translating else " m"
    doc.para(*say("cam_step", cam=cam.cam, turn=number(math.degrees(turned)), theta=number(theta),
                  s=f"{number(s)}{unit}"))  # fmt: skip
    link = ctx.state.links.get(cam.cam)
    omega = np.array([link.omega if link is not None else 0.0])
    epsilon = np.array([link.epsilon if link is not None else 0.0])
    qd, qdd, _ = cam_rates(cam, pose, omega, epsilon)
    radius = 1.0 / pose.curvature[0] if pose.curvature[0] else math.inf
    rho = number(radius) if math.isfinite(radius) else "∞"
    if cam.design.layout.flat:
        doc.para(*say("cam_step_flat", v=cam.virtual, cam=cam.cam, rho=rho,
                      follower=cam.follower))  # fmt: skip
        doc.equation(
            Math(
                "(v_C1 − v_C2)·n = 0,  (a_C1 − a_C2 − 2·ω2 × v_C1C2)·n = 0",
                r"(\mathbf{v}_{C1} - \mathbf{v}_{C2})\cdot\mathbf{n} = 0,\quad "
                r"(\mathbf{a}_{C1} - \mathbf{a}_{C2} - 2\,\omega_2 \times "
                r"\mathbf{v}_{C1C2})\cdot\mathbf{n} = 0",
            )
        )
    else:
        point = cam.pair.center_of(cam.other) or cam.contact_point or "?"
        doc.para(*say("cam_step_replaced", v=cam.virtual, cam=cam.cam, rho=rho,
                      point=point))  # fmt: skip
        doc.equation(
            Math(
                "(v_P − v_C)·n = 0,  (a_P − a_C)·n = −ω_v²·ρ",
                r"(\mathbf{v}_P - \mathbf{v}_C)\cdot\mathbf{n} = 0,\quad "
                r"(\mathbf{a}_P - \mathbf{a}_C)\cdot\mathbf{n} = -\omega_v^2\,\rho",
            )
        )
    rate = "rad/s" if not cam.translating else "m/s"
    doc.equation(
        Math(
            f"q̇ = {number(float(qd[0]))} {rate},  q̈ = {number(float(qdd[0]))} {rate}²",
            rf"\dot q = {number(float(qd[0]))},\quad \ddot q = {number(float(qdd[0]))}",
        )
    )
    sense = cam.design.layout.sense
    swing = 1.0 if cam.translating else cam.design.layout.swing
    v1 = swing * float(pose.s1[0]) * sense * float(omega[0])
    a1 = swing * (float(pose.s2[0]) * float(omega[0]) ** 2
                  + float(pose.s1[0]) * sense * float(epsilon[0]))  # fmt: skip
    doc.para(*say("cam_step_law", v1=f"{number(v1)} {rate}", a1=f"{number(a1)} {rate}/s"))
