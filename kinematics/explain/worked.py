"""Worked solutions of the kinematics and the kinetostatics, in the textbook's steps.

:func:`explain_kinematics` writes, group by group in solve order, the
relative-velocity and relative-acceleration vector equations the textbook
draws as polygons (``v_C = v_B + v_CB = v_D + v_CD``; for a slider on a
moving guide the relative velocity along the guide and the Coriolis term
``a^k = 2·ω×v_rel``), with what is known of each term (direction ``⊥BC`` or
``∥`` the guide, magnitude ``ω1·l_AB = 20·0.1 = 2 m/s``) and what is not
(``?``), then the values the solve found. Groups that are not dyads (triads
and higher) are solved as a whole: their equations and unknowns are listed.

:func:`explain_forces` writes the kinetostatics from the farthest group back:
for each group the equilibrium equations in the order the textbook solves
them (moments about the inner pin for the tangential components, the group's
force balance for the normal ones, then a link's balance for the inner
reaction), then the driver's balancing moment from ``ΣM_A = 0`` and its check
by virtual power.

Every number comes from the actual solve (:func:`~kinematics.solve.solve_pose`,
:func:`~kinematics.forces.solve_forces`), so the explanation agrees with
``assur kinematics`` and ``assur forces``; the force steps recompute each
unknown from its own equation, which checks the solve. Formats and languages
are those of :mod:`structure.explain`; the phrases are in :data:`PHRASES`.

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.plan import make_plan
>>> from kinematics.solve import solve_pose
>>> m = parse_edgelist(["driver 1 omega=20", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0 0.1", "point C 0.4 0.1", "point D 0.4 -0.3"])
>>> r = analyze(m); plan = make_plan(r)
>>> text = explain_kinematics(r, plan, solve_pose(plan))
>>> "v_C = v_B + v_CB = v_D + v_CD" in text, "ω1·l_AB = 20·0.1 = 2 m/s" in text
(True, True)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from structure.assur import AssurGroup, GroupPair
from structure.explain.structural import (
    Doc,
    Math,
    check_options,
    formula,
    math_join,
    number,
    render,
    subscript,
)
from structure.model import Mechanism, PairKind
from structure.report import StructuralReport

from ..forces import ForceSolution, Reaction
from ..plan import DriverStep, GroupStep, SolvePlan
from ..polygons import (
    Dyad,
    Side,
    VectorEquation,
    coriolis,
    dyad_of,
    link_rates,
    point_at,
    point_label,
    point_motion,
    relative_label,
    slide_angle,
    slide_direction,
    vector_equations,
)
from ..solve import KinematicState, solve_pose

__all__ = ["PHRASES", "angle_of", "explain_forces", "explain_kinematics"]


# ============================================================================ phrases
#: every sentence of the kinematic and force explanations, by language
PHRASES: dict[str, dict[str, str]] = {
    "en": {
        "kin_title": "Kinematics of {name}",
        "conventions": (
            "Units m, s, rad; ω and ε are positive counter-clockwise; a vector's direction is "
            "its angle from the x axis, counter-clockwise. The point of link k that coincides "
            "with X is written Xk."
        ),
        "drivers": "1. Driver(s)",
        "driver_r": "Driver {link} turns about {pivot}: {w} = {wv} rad/s, {e} = {ev} rad/s²",
        "driver_p": "Driver {link} slides along its guide ({angle}°): v = {v} m/s, a = {a} m/s²",
        "not_given": " (not given in the file: taken as 0)",
        "group_head": "{k}. Group {label}{kind}: links {links}",
        "velocities": "Velocities. Vector equation:",
        "accelerations": "Accelerations. Vector equation:",
        "two_unknowns": (
            "Two unknown magnitudes: the equation is solved (the velocity polygon closes):"
        ),
        "two_unknowns_a": (
            "Two unknown magnitudes: the equation is solved (the acceleration polygon closes):"
        ),
        "on_ground": "(on the ground)",
        "from_group": "known from {label}: {mag} at {angle}°",
        "same_pin": "(pin {p} joins link {la} to link {k}) ",
        "slides_ground": "{w} = 0: link {link} slides on the ground",
        "same_angle": "{w} = {wk} = {value} rad/s: the prismatic pair keeps their angle",
        "same_angle_e": "{e} = {ek} = {value} rad/s²",
        "ccw": "counter-clockwise",
        "cw": "clockwise",
        "along": "along the guide, toward {angle}°",
        "at": "at {angle}°",
        "coriolis": ("Coriolis: {vrel} turned 90° in the sense of {w}, {value}"),
        "points": "Points of the group:",
        "point_value": "{name} (on {link}): |v| = {v} m/s at {va}°, |a| = {a} m/s² at {aa}°",
        "generic": (
            "This group is solved as a whole: its {rows} scalar equations (two per pair: the "
            "pin's velocity is the same on both links, or no relative rotation and no motion "
            "across the slide) are solved together: positions by Newton's method, velocities by "
            "one linear solve of the group's Jacobian J·q̇ = −J_k·q̇_k, accelerations by "
            "J·q̈ = −J_k·q̈_k − J̇·q̇."
        ),
        "unknowns": "Unknowns: v_x, v_y and ω of each of the links {links} ({count} unknowns).",
        "pair_r": "pin {point} joins {a} and {b}: {eq}",
        "pair_p": "slide {point} between {a} and {b}: {eq1}, and the relative velocity ∥ the guide",
        "redundant": (
            "Link {link} is redundant (set aside by the structural analysis): its pairs give more "
            "equations than it has freedoms, all consistent; they are solved in the "
            "least-squares sense."
        ),
        "solved_links": "Solved:",
        "link_value": "link {link}: {w} = {wv} rad/s{ws}, {e} = {ev} rad/s²{es}",
        # forces
        "f_title": "Forces on {name} (kinetostatics at the sketch pose)",
        "f_title_at": "Forces on {name} (kinetostatics at {pose} from the sketch pose)",
        "f_conventions": (
            "Units N, m; moments positive counter-clockwise. R_ij is the force link i exerts on "
            "link j. The groups are detached from the farthest; each group's outer reactions "
            "are then loads on the links it hangs on."
        ),
        "f_order": "Order solved: {order}",
        "loads": "Loads",
        "no_loads": "No loads are given.",
        "load_force": "{sym} at {point} on link {link}: ({fx}, {fy}) N",
        "load_moment": "{sym} on link {link}: {value} N·m",
        "load_weight": "{sym} = m·g at {point} on link {link}: ({fx}, {fy}) N",
        "load_inertia": "{sym} = −m·a_S at {point} on link {link}: ({fx}, {fy}) N",
        "load_inertia_m": "{sym} = −J_S·ε on link {link}: {value} N·m",
        "f_group": "{k}. Group {label}{kind}",
        "f_unknowns": "Unknown reactions: {list}.",
        "f_known": "Known loads on link {link}: {list}",
        "f_none": "none",
        "f_tangent": (
            "({rt} {perp}, positive along {line} turned 90° counter-clockwise; {rn} {par}, "
            "positive from {a} to {b})"
        ),
        "f_step": "{k}) {what}:",
        "f_moment": "{sum}(link {link}) = 0",
        "f_force_group": "ΣF = 0 on the group",
        "f_force_link": "ΣF = 0 on link {link}",
        "f_gives": "gives {what}",
        "f_sum_moments": "moment of the known loads on link {link} about {point}",
        "f_slide": (
            "({sym} ⊥ the guide {guide}, positive along the guide turned 90° counter-clockwise)"
        ),
        "f_lever": "{sym} acts through {point}: its lever arm about {about} is h = {h} m",
        "f_offset": "the guide's reaction acts x = M/N = {x} m from {point} along the guide",
        "f_couple": "the guide's reaction is a pure couple {value} N·m",
        "f_found": "Reactions found:",
        "f_reaction": "{sym} at {point}: ({fx}, {fy}) N, |{sym}| = {mag} N at {angle}°",
        "f_reaction_p": "; moment about {point} {value} N·m",
        "f_generic": (
            "The group's {eqs} equilibrium equations (ΣF_x = ΣF_y = ΣM = 0 for each of its "
            "{n} links) are solved together for the {eqs} unknown reaction components (two per "
            "pair: R_x, R_y at a pin; the normal force and its moment at a slide)."
        ),
        "f_friction": (
            "Friction is present: the friction forces of the last reactions are added to the "
            "loads until the reactions stop changing; the reactions below include it."
        ),
        "f_indeterminate": (
            "The mechanism is over-constrained: these reactions are the minimum-norm ones."
        ),
        "f_driver": "{k}. Driver {link}",
        "f_mcb": "{sum}(link {link}) = 0:",
        "f_mcb_value": "balancing moment {sym} = {value} N·m ({sense})",
        "f_pcb_value": "balancing force {sym} = {value} N along {angle}° at {point}",
        "f_fcb_value": "balancing force {sym} = {value} N along the guide ({angle}°)",
        "f_ground": "ΣF = 0 on link {link} gives the reaction of the ground:",
        "f_power": "{k}. Check by virtual power",
        "f_power_intro": (
            "The power of every load and of the balancing moment adds up to zero "
            "(ideal pairs do no work):"
        ),
        "f_power_virtual": (
            "(the driver's speed is 0 here: virtual velocities for a unit speed of the driver)"
        ),
        "f_power_friction": "power lost to friction: {value} W",
        "f_power_sum": "Sum: {value} W ≈ 0 ✓",
        "f_power_bad": "Sum: {value} W (not 0: check the loads)",
        "f_power_gives": "so {eq}, as found above.",
        "f_contact": "Contact force of the higher pair at {point} (carried by the virtual link):",
    },
    "vi": {
        "kin_title": "Phân tích động học cơ cấu: {name}",
        "conventions": (
            "Đơn vị m, s, rad; ω và ε dương khi ngược chiều kim đồng hồ; phương chiều của véc tơ "
            "cho bằng góc so với trục x. Điểm của khâu k trùng với điểm X được viết Xk."
        ),
        "drivers": "1. Khâu dẫn",
        "driver_r": "Khâu dẫn {link} quay quanh {pivot}: {w} = {wv} rad/s, {e} = {ev} rad/s²",
        "driver_p": "Khâu dẫn {link} tịnh tiến theo giá dẫn ({angle}°): v = {v} m/s, a = {a} m/s²",
        "not_given": " (không cho trong đề: lấy bằng 0)",
        "group_head": "{k}. Nhóm {label}{kind}: khâu {links}",
        "velocities": "Phương trình vận tốc:",
        "accelerations": "Phương trình gia tốc:",
        "two_unknowns": "Phương trình chỉ còn 2 ẩn số giá trị; giải (vẽ họa đồ vận tốc) được:",
        "two_unknowns_a": "Phương trình chỉ còn 2 ẩn số giá trị; giải (vẽ họa đồ gia tốc) được:",
        "on_ground": "(thuộc giá)",
        "from_group": "đã biết từ nhóm {label}: {mag}, hướng {angle}°",
        "same_pin": "(khớp {p} nối khâu {la} với khâu {k}) ",
        "slides_ground": "{w} = 0: khâu {link} tịnh tiến trên giá",
        "same_angle": "{w} = {wk} = {value} rad/s: khớp tịnh tiến giữ nguyên góc giữa hai khâu",
        "same_angle_e": "{e} = {ek} = {value} rad/s²",
        "ccw": "ngược chiều kim đồng hồ",
        "cw": "cùng chiều kim đồng hồ",
        "along": "dọc theo giá trượt, hướng {angle}°",
        "at": "hướng {angle}°",
        "coriolis": "gia tốc Coriolis: chiều của {vrel} quay 90° theo chiều {w}, {value}",
        "points": "Các điểm của nhóm:",
        "point_value": "{name} (thuộc khâu {link}): |v| = {v} m/s, hướng {va}°; |a| = {a} m/s², "
        "hướng {aa}°",
        "generic": (
            "Nhóm này được giải chung: {rows} phương trình vô hướng (hai phương trình cho mỗi "
            "khớp: vận tốc của chốt như nhau trên hai khâu, hoặc không quay tương đối và không "
            "chuyển động ngang giá trượt) giải đồng thời: vị trí bằng phương pháp Newton, vận tốc "
            "bằng một lần giải hệ tuyến tính với ma trận Jacobi của nhóm J·q̇ = −J_k·q̇_k, gia tốc "
            "bằng J·q̈ = −J_k·q̈_k − J̇·q̇."
        ),
        "unknowns": "Ẩn số: v_x, v_y và ω của các khâu {links} ({count} ẩn số).",
        "pair_r": "khớp quay {point} nối khâu {a} và {b}: {eq}",
        "pair_p": (
            "khớp tịnh tiến {point} giữa khâu {a} và {b}: {eq1}, vận tốc tương đối ∥ giá trượt"
        ),
        "redundant": (
            "Khâu {link} là khâu thừa (ràng buộc trùng): các khớp của nó cho nhiều phương trình "
            "hơn số bậc tự do, nhưng tương thích; giải theo bình phương tối thiểu."
        ),
        "solved_links": "Kết quả:",
        "link_value": "khâu {link}: {w} = {wv} rad/s{ws}, {e} = {ev} rad/s²{es}",
        # forces
        "f_title": "Phân tích lực cơ cấu: {name} (tại vị trí đang xét)",
        "f_title_at": "Phân tích lực cơ cấu: {name} (tại vị trí {pose} so với hình vẽ)",
        "f_conventions": (
            "Đơn vị N, m; mômen dương khi ngược chiều kim đồng hồ. R_ij là áp lực khớp động "
            "do khâu i tác dụng lên khâu j. Tách nhóm tĩnh định bắt đầu từ nhóm xa khâu dẫn nhất, "
            "đặt lực vào các khớp chờ; áp lực tại khớp chờ của nhóm đã giải là tải trọng lên các "
            "khâu nó nối vào."
        ),
        "f_order": "Thứ tự giải: {order}",
        "loads": "Ngoại lực",
        "no_loads": "Không có ngoại lực.",
        "load_force": "{sym} tại {point} trên khâu {link}: ({fx}, {fy}) N",
        "load_moment": "{sym} trên khâu {link}: {value} N·m",
        "load_weight": "{sym} = m·g tại {point} trên khâu {link}: ({fx}, {fy}) N",
        "load_inertia": "lực quán tính {sym} = −m·a_S tại {point} trên khâu {link}: ({fx}, {fy}) N",
        "load_inertia_m": "mômen lực quán tính {sym} = −J_S·ε trên khâu {link}: {value} N·m",
        "f_group": "{k}. Nhóm {label}{kind}",
        "f_unknowns": "Ẩn số (áp lực khớp động): {list}.",
        "f_known": "Lực đã biết trên khâu {link}: {list}",
        "f_none": "không có",
        "f_tangent": (
            "({rt} {perp}, dương theo {line} quay 90° ngược chiều kim đồng hồ; {rn} {par}, "
            "dương từ {a} đến {b})"
        ),
        "f_step": "{k}) {what}:",
        "f_moment": "{sum}(khâu {link}) = 0",
        "f_force_group": "Phương trình cân bằng lực cho toàn nhóm ΣF = 0",
        "f_force_link": "Phương trình cân bằng lực riêng cho khâu {link} ΣF = 0",
        "f_gives": "cho {what}",
        "f_sum_moments": "tổng mômen của các lực đã biết trên khâu {link} đối với điểm {point}",
        "f_slide": (
            "({sym} ⊥ giá trượt {guide}, dương theo giá trượt quay 90° ngược chiều kim đồng hồ)"
        ),
        "f_lever": "{sym} đi qua {point}: cánh tay đòn đối với {about} là h = {h} m",
        "f_offset": "áp lực của giá trượt đặt cách {point} một đoạn x = M/N = {x} m dọc giá trượt",
        "f_couple": "áp lực của giá trượt là một ngẫu lực {value} N·m",
        "f_found": "Áp lực khớp động tìm được:",
        "f_reaction": "{sym} tại {point}: ({fx}, {fy}) N, |{sym}| = {mag} N, hướng {angle}°",
        "f_reaction_p": "; mômen đối với {point} {value} N·m",
        "f_generic": (
            "{eqs} phương trình cân bằng của nhóm (ΣF_x = ΣF_y = ΣM = 0 cho mỗi khâu trong {n} "
            "khâu) được giải đồng thời cho {eqs} thành phần áp lực (hai cho mỗi khớp: R_x, R_y tại "
            "khớp quay; áp lực pháp tuyến và mômen của nó tại khớp tịnh tiến)."
        ),
        "f_friction": (
            "Có ma sát: lực ma sát tính từ áp lực lần trước được cộng vào ngoại lực cho đến khi "
            "áp lực không đổi; các áp lực dưới đây đã kể đến ma sát."
        ),
        "f_indeterminate": "Cơ cấu có ràng buộc trùng: đây là nghiệm có chuẩn nhỏ nhất.",
        "f_driver": "{k}. Khâu dẫn {link}",
        "f_mcb": "{sum}(khâu {link}) = 0:",
        "f_mcb_value": "mômen cân bằng {sym} = {value} N·m ({sense})",
        "f_pcb_value": "lực cân bằng {sym} = {value} N theo hướng {angle}° tại {point}",
        "f_fcb_value": "lực cân bằng {sym} = {value} N dọc giá trượt ({angle}°)",
        "f_ground": "ΣF = 0 trên khâu {link} cho áp lực từ giá:",
        "f_power": "{k}. Nghiệm lại bằng phương pháp công suất",
        "f_power_intro": (
            "Tổng công suất của các ngoại lực và mômen cân bằng bằng không (khớp lý tưởng "
            "không sinh công):"
        ),
        "f_power_virtual": (
            "(vận tốc khâu dẫn bằng 0: dùng vận tốc khả dĩ ứng với vận tốc đơn vị của khâu dẫn)"
        ),
        "f_power_friction": "công suất mất do ma sát: {value} W",
        "f_power_sum": "Tổng: {value} W ≈ 0 ✓",
        "f_power_bad": "Tổng: {value} W (khác 0: kiểm tra lại ngoại lực)",
        "f_power_gives": "suy ra {eq}, đúng như trên.",
        "f_contact": "Lực tiếp xúc tại khớp cao {point} (truyền qua khâu thay thế):",
    },
}


# ============================================================================ mathematics
_f = formula
ZERO = Math("0", "0")
QUESTION = Math("?", "?")
POWER_EQUATION = Math(
    "Σ P·v + Σ M·ω + M_cb·ω1 = 0",
    r"\sum \vec{P} \cdot \vec{v} + \sum M \omega + M_{cb} \omega_1 = 0",
)
_UNITS = {
    "m/s": r"\ \mathrm{m/s}",
    "m/s²": r"\ \mathrm{m/s^2}",
    "rad": r"\ \mathrm{rad}",
    "rad/s": r"\ \mathrm{rad/s}",
    "rad/s²": r"\ \mathrm{rad/s^2}",
    "N": r"\ \mathrm{N}",
    "N·m": r"\ \mathrm{N \cdot m}",
    "W": r"\ \mathrm{W}",
    "m": r"\ \mathrm{m}",
}


def _num(x: float, zero: float = 1e-9) -> Math:
    text = number(x, zero)
    return Math(text, text)


def _q(x: float, unit: str, zero: float = 1e-9) -> Math:
    """A quantity with its unit: ``2 m/s``."""
    text = number(x, zero)
    return Math(f"{text} {unit}", text + _UNITS[unit])


def _xy(v: np.ndarray, unit: str) -> Math:
    x, y = number(float(v[0]), 1e-6), number(float(v[1]), 1e-6)
    return Math(f"({x}, {y}) {unit}", rf"({x},\ {y})" + _UNITS[unit])


def _paren(x: float) -> Math:
    """A number in parentheses when negative: ``(-0.5)``."""
    text = number(x)
    text = f"({text})" if text.startswith("-") else text
    return Math(text, text)


def _two(a: str, b: str) -> str:
    """Two point names in the textbook's order (``AB``, ``BC``, ``CD``)."""
    return a + b if a <= b else b + a


def _sub2(a: str, b: str) -> str:
    return a + b if len(a) == 1 and len(b) == 1 else f"{a},{b}"


_SUP = {"τ": r"\tau"}


def _vec(letter: str, sub: str, sup: str = "") -> Math:
    """A vector: ``v_CB``, ``a^τ_CB`` (LaTeX ``\\vec{a}^{\\,\\tau}_{CB}``)."""
    text = f"{letter}^{sup}_{sub}" if sup else f"{letter}_{sub}"
    top = f"^{{\\,{_SUP.get(sup, sup)}}}" if sup else ""
    return Math(text, rf"\vec{{{letter}}}{top}_{{{sub}}}")


def _mag(letter: str, sub: str, sup: str = "") -> Math:
    """A magnitude or a scalar component: ``v_CB``, ``R^τ_12``."""
    text = f"{letter}^{sup}_{sub}" if sup else f"{letter}_{sub}"
    top = f"^{{{_SUP.get(sup, sup)}}}" if sup else ""
    return Math(text, rf"{letter}{top}_{{{sub}}}")


def _w(link: str) -> Math:
    return subscript("ω", link)


def _e(link: str) -> Math:
    return subscript("ε", link)


def _l(a: str, b: str) -> Math:
    return subscript("l", _two(a, b))


def _sum(link: str = "") -> Math:
    """``ΣP`` (or ``ΣP_2``): the known loads of the group (of link 2)."""
    if link:
        return Math(f"ΣP_{link}", rf"\sum \vec{{P}}_{{{link}}}")
    return Math("ΣP", r"\sum \vec{P}")


def _with_numbers(
    template: str, symbols: Sequence[Math], values: Sequence[Math | float], result: Math
) -> Math:
    """A formula in its symbols, then in their values, then its value.

    >>> _with_numbers("{0}·{1}", [_w("1"), _l("A", "B")], [20.0, 0.1], _q(2.0, "m/s")).text
    'ω1·l_AB = 20·0.1 = 2 m/s'
    """

    def filled(items: Sequence[Math | float]) -> Math:
        return _f(template, **{str(k): x for k, x in enumerate(items)})

    return _f("{s} = {n} = {r}", s=filled(symbols), n=filled(values), r=result)


def _times_length(
    rate: Math, value: float, a: str, b: str, length: float, unit: str, square: bool = False
) -> Math:
    """A rate's size times the length ``ab``: ``ω1·l_AB = 20·0.1 = 2 m/s``; ``ω3²·l_CD = …``."""
    two = "²" if square else ""
    size = value * value if square else abs(value)
    result = _q(size * length, unit)
    return _with_numbers("{0}" + two + "·{1}", [rate, _l(a, b)], [abs(value), length], result)


def _power(sym: Math, speed_sym: Math, value: float, speed: float) -> Math:
    """The power of a load or a balancing moment: ``M_cb·ω1 = 50·10 = 500 W``."""
    speeds = [_paren(value), _paren(speed)]
    return _with_numbers("{0}·{1}", [sym, speed_sym], speeds, _q(value * speed, "W"))


def angle_of(v: np.ndarray) -> float:
    """Direction of a vector, degrees from the x axis counter-clockwise, in (−180, 180].

    >>> angle_of(np.array([-1.0, -0.0])), angle_of(np.array([0.0, 2.0]))
    (180.0, 90.0)
    """
    a = math.degrees(math.atan2(float(v[1]), float(v[0])))
    return a + 360.0 if a <= -180.0 + 1e-9 else a


def _angle(v: np.ndarray, zero: float = 1e-9) -> str:
    """The direction in degrees, or ``–`` for a vector of size ``zero`` or less."""
    if float(np.hypot(v[0], v[1])) <= zero:
        return "–"
    return number(angle_of(v), 1e-6)


def _norm(v: np.ndarray) -> float:
    return float(np.hypot(v[0], v[1]))


def _cross(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _j(v: np.ndarray) -> np.ndarray:
    """``v`` turned by +90°."""
    return np.array([-v[1], v[0]])


# ============================================================================ motion
@dataclass(frozen=True)
class _At:
    """A point as the explanation writes it, and where it is at the pose."""

    name: str
    xy: np.ndarray


@dataclass
class _Ctx:
    """The mechanism, the motion at the pose, and the lookups the notation needs."""

    doc: Doc
    plan: SolvePlan
    state: KinematicState
    m: Mechanism = field(init=False)
    ground: str = field(init=False)
    pivot: dict[str, str] = field(init=False)  # link -> its pivot on the ground
    slide: dict[str, int] = field(init=False)  # link -> its P pair with the ground
    solved_in: dict[str, str] = field(init=False)  # link -> label of the step that solved it
    slide_on: dict[int, str] = field(init=False)  # P pair -> the link its reaction acts on

    def __post_init__(self) -> None:
        self.m = self.plan.mechanism
        self.ground = self.m.ground
        self.pivot, self.slide = {}, {}
        for p in self.m.pairs:
            if self.ground not in p.links:
                continue
            other = p.other(self.ground)
            if p.kind is PairKind.R and p.point:
                self.pivot.setdefault(other, p.point)
            elif p.kind is PairKind.P:
                self.slide.setdefault(other, p.id)
        for h in self.m.compound_hinges.values():
            if self.ground in h.links:
                for x in h.links:
                    if x != self.ground:
                        self.pivot.setdefault(x, h.point)
        self.solved_in = {d.link: f"I({d.link})" for d in self.plan.drivers}
        self.slide_on = {}
        for step in self.plan.steps:
            for x in step.links:
                self.solved_in[x] = step.label
            for eq in step.equations:
                if eq.kind == "SLIDE":
                    self.slide_on[eq.pair] = eq.b  # the reaction is (eq.a, eq.b): see _reactions

    def pin(self, name: str) -> _At:
        """A pin (or another named point) where the solve put it."""
        return _At(name, np.asarray(self.state.points[name].position))

    def slide_point(self, name: str, link: str) -> _At:
        """The point ``name`` of ``link``: where a slide's reaction on ``link`` acts.

        Once the slide has moved from the sketch, its point on ``link`` has parted from
        the one named ``name``; it is written ``E3`` (the point of link 3 at E) then.
        """
        xy = point_at(self.plan, self.state, link, name)[0]
        named = self.state.points.get(name)
        if named is None or _norm(np.asarray(named.position) - xy) <= 1e-9 * (1.0 + _norm(xy)):
            return _At(name, xy)
        return _At(point_label(name, link), xy)

    def slide_at(self, pair_id: int) -> _At:
        """Where the reaction of slide ``pair_id`` acts (see :meth:`slide_point`)."""
        pair = self.m.pair(pair_id)
        return self.slide_point(pair.point or "?", self.slide_on.get(pair_id, pair.b))

    def dist(self, link: str, a: str, b: str) -> float:
        """Distance between the points ``a`` and ``b`` of ``link``."""
        pa, pb = (point_at(self.plan, self.state, link, x)[0] for x in (a, b))
        return _norm(pa - pb)

    def points_of(self, link: str) -> list[str]:
        """Named points fixed to ``link``: its pairs' points and its markers."""
        out: list[str] = []
        for p in self.m.pairs_of(link):
            if p.point and p.kind is not PairKind.H and self.m.coordinates(p.point) is not None:
                out.append(p.point)
        for h in self.m.compound_hinges.values():
            if link in h.links and self.m.coordinates(h.point) is not None:
                out.append(h.point)
        out += [p.name for p in self.m.points.values() if p.on == link]
        return list(dict.fromkeys(out))

    def guide(self, pair_id: int) -> tuple[np.ndarray, str]:
        """Unit direction of a slide at the pose and its name: ``BC``, ``x``, ``(30°)``."""
        pair = self.m.pair(pair_id)
        u = slide_direction(self.plan, self.state, pair_id)
        if pair.point is not None and self.m.coordinates(pair.point) is not None:
            turned = pair.a if pair.a != self.ground else pair.b
            s = point_at(self.plan, self.state, turned, pair.point)[0]
            for link in pair.links:
                for q in self.points_of(link):
                    d = point_at(self.plan, self.state, link, q)[0] - s
                    size = _norm(d)
                    if q != pair.point and size > 1e-9 and abs(_cross(u, d)) <= 1e-9 * size:
                        return u, _two(pair.point, q)
        folded = math.degrees(slide_angle(self.plan, self.state, pair_id)) % 180.0
        if min(folded, 180.0 - folded) <= 1e-6:
            return u, "x"
        if abs(folded - 90.0) <= 1e-6:
            return u, "y"
        return u, f"({_angle(u)}°)"

    def sense(self, value: float) -> str:
        """`` (counter-clockwise)`` or `` (clockwise)`` for a non-zero rate."""
        if abs(value) <= 1e-9:
            return ""
        return " (" + self.doc.word("ccw" if value > 0 else "cw") + ")"


def _turning(ctx: _Ctx, link: str) -> tuple[float, float]:
    """ω and ε of a link (zeros for the ground)."""
    _, qd, qdd = link_rates(ctx.plan, ctx.state, link)
    return float(qd[2]), float(qdd[2])


# ============================================================================ kinematics
def _known(
    ctx: _Ctx, x: str, k: str, label: str, order: int, where: np.ndarray | None = None
) -> list:
    """What is known of the velocity (order 1) or acceleration (2) of point ``x`` of link ``k``.

    ``where`` is the point's position when it is not a point of ``k`` in the sketch (the
    point of a guide under a slider).
    """
    doc = ctx.doc
    if k == ctx.ground:
        return [ZERO, " ", doc.word("on_ground")]
    pivot = ctx.pivot.get(k)
    if pivot == x:
        return [ZERO, f" ({doc.word('on_ground')})"]
    where = point_at(ctx.plan, ctx.state, k, x)[0] if where is None else where
    v, a = point_motion(ctx.plan, ctx.state, k, where)
    if pivot is not None:
        length = _norm(where - point_at(ctx.plan, ctx.state, k, pivot)[0])
        w, e = _turning(ctx, k)
        if order == 1:
            speed = _times_length(_w(k), w, pivot, x, length, "m/s")
            return [_f("{p}, {t}", p=_perp(pivot, x), t=speed)]
        sub = x + pivot
        normal = _times_length(_w(k), w, pivot, x, length, "m/s²", square=True)
        tangential = _times_length(_e(k), e, pivot, x, length, "m/s²")
        return [
            _f("{an} ({to}) = {n}", an=_mag("a", sub, "n"), to=_to(x, pivot), n=normal),
            "; ",
            _f(
                "{at} ({p}) = {t} ⇒ |{lab}| = {size}",
                at=_mag("a", sub, "τ"),
                p=_perp(pivot, x),
                t=tangential,
                lab=_vec("a", label),
                size=_q(_norm(a), "m/s²"),
            ),
        ]
    vec, unit = (v, "m/s") if order == 1 else (a, "m/s²")
    if k in ctx.slide:
        _, name = ctx.guide(ctx.slide[k])
        return [_f("{p}, {v}", p=_par(name), v=_q(_norm(vec), unit))]
    label_k = ctx.solved_in.get(k, k)
    return doc.say("from_group", label=label_k, mag=_q(_norm(vec), unit), angle=_angle(vec))


def _perp(a: str, b: str) -> Math:
    return Math(f"⊥{_two(a, b)}", rf"\perp {_two(a, b)}")


def _par(name: str) -> Math:
    return Math(f"∥{name}", rf"\parallel {name}")


def _to(a: str, b: str) -> Math:
    return Math(f"{a}→{b}", rf"{a} \to {b}")


def _guide_known(ctx: _Ctx, d: Dyad, side: Side, order: int) -> list:
    """What is known of the guide's point at X (through the pin at X for a slide inside)."""
    label = point_label(d.x, side.guide_link)
    if side.guide_link == d.la:
        head = ctx.doc.say("same_pin", p=d.x, la=d.la, k=side.known)
        return [*head, *_known(ctx, d.x, side.known, label, order, d.where)]
    return _known(ctx, d.x, side.guide_link, label, order, d.where)


def _normal_text(ctx: _Ctx, d: Dyad, side: Side, length: float) -> Math:
    """The normal acceleration of X about a pin side's base: ``C→B, ω2²·l_BC = …``."""
    w = _turning(ctx, side.link)[0]
    normal = _times_length(_w(side.link), w, side.base, d.x, length, "m/s²", square=True)
    return _f("{to}, {n}", to=_to(d.x, side.base), n=normal)


def _equation(ctx: _Ctx, eq: VectorEquation) -> tuple[Math, list[list]]:
    """The vector equation (of velocities or accelerations) and what is known of its terms.

    Each way to X is its known point's vector, then the terms of
    :func:`~kinematics.polygons.vector_equations`: one known (``a^n``, ``a^k``)
    for accelerations, and last the one whose size is unknown (``⊥`` the arm
    or ``∥`` the guide).
    """
    d, order = eq.dyad, eq.order
    letter = "v" if order == 1 else "a"
    lhs = _vec(letter, eq.x)
    chains = {c.side: c for c in eq.chains}
    sums: list[Math] = []
    items: list[list] = []
    for side in d.sides:
        if side.kind == "G":
            items.append([lhs, ": ", _f("{p}, ?", p=_par(ctx.guide(side.pair)[1]))])
            continue
        chain = chains[side]
        base = _vec(letter, chain.start)
        terms = [_vec(t.letter, t.sub, t.sup) for t in chain.terms]
        sums.append(math_join([base, *terms], " + "))
        if side.kind == "R":
            items.append([base, ": ", *_known(ctx, side.base, side.known, side.base, order)])
            unknown = _perp(side.base, d.x)
            if order == 2:
                length = _norm(d.where - chain.start_where)
                items.append([terms[0], ": ", _normal_text(ctx, d, side, length)])
        else:
            items.append([base, ": ", *_guide_known(ctx, d, side, order)])
            unknown = _par(ctx.guide(side.pair)[1])
            if order == 2:
                items.append([terms[0], ": ", *_coriolis_text(ctx, d, side)])
        items.append([terms[-1], ": ", _f("{p}, ?", p=unknown)])
    return (math_join([lhs, *sums], " = ") if sums else lhs), items


def _coriolis_text(ctx: _Ctx, d: Dyad, side: Side) -> list:
    wg, vrel, ak = coriolis(ctx.plan, ctx.state, d, side)
    sub = relative_label(d, side)
    symbols = [_w(side.guide_link), _mag("v", sub)]
    value = _with_numbers("2·{0}·{1}", symbols, [abs(wg), _norm(vrel)], _q(_norm(ak), "m/s²"))
    if _norm(ak) <= 1e-9:
        return [value]
    turned = ctx.doc.say("coriolis", vrel=_vec("v", sub), w=_w(side.guide_link), value=value)
    return [*turned, " (", *ctx.doc.say("at", angle=_angle(ak)), ")"]


def _along(ctx: _Ctx, sym: Math, value: float, u: np.ndarray, unit: str) -> list:
    direction = u * (1.0 if value >= 0 else -1.0)
    return [
        _f("{s} = {v}", s=sym, v=_q(abs(value), unit)),
        ", ",
        *ctx.doc.say("along", angle=_angle(direction)),
    ]


def _solved(ctx: _Ctx, eq: VectorEquation) -> list[list]:
    """The unknown magnitudes the equation gives, and the rates of the links."""
    doc = ctx.doc
    d, order = eq.dyad, eq.order
    unit, rate_unit = ("m/s", "rad/s") if order == 1 else ("m/s²", "rad/s²")
    letter = "v" if order == 1 else "a"
    chains = {c.side: c for c in eq.chains}
    out: list[list] = []
    for side in d.sides:
        link = side.link
        if side.kind == "G":
            u = slide_direction(ctx.plan, ctx.state, side.pair)
            own = point_motion(ctx.plan, ctx.state, link, d.where)[order - 1]
            out.append(_along(ctx, _mag(letter, eq.x), float(own @ u), u, unit))
            if order == 1:
                out.append(doc.say("slides_ground", w=_w(link), link=link))
            continue
        chain = chains[side]
        last = chain.terms[-1]  # the term of unknown size: v_CB, a^τ_CB, v_B3B2, a^r_B3B2
        sym = _mag(last.letter, last.sub, last.sup)
        if side.kind == "P":
            u = slide_direction(ctx.plan, ctx.state, side.pair)
            out.append(_along(ctx, sym, float(last.vector @ u), u, unit))
            continue
        rate = _turning(ctx, link)[order - 1]
        length = _norm(d.where - chain.start_where)
        value = abs(rate) * length
        ratio = _with_numbers(
            "{0}/{1}", [sym, _l(side.base, d.x)], [value, length], _q(rate, rate_unit)
        )
        r_sym = _w(link) if order == 1 else _e(link)
        equation = _f("{s} = {v} ⇒ {r} = {q}", s=sym, v=_q(value, unit), r=r_sym, q=ratio)
        out.append([equation, ctx.sense(rate)])
    for link in d.links:
        partner = _turns_with(d, link)
        if partner is None or partner == ctx.ground:
            continue
        if order == 1:
            value = _num(_turning(ctx, link)[0])
            out.append(doc.say("same_angle", w=_w(link), wk=_w(partner), value=value))
        else:
            value = _num(_turning(ctx, link)[1])
            out.append(doc.say("same_angle_e", e=_e(link), ek=_e(partner), value=value))
    if not any(s.kind == "G" for s in d.sides):
        out.append(
            [
                _f("{s} = {v}", s=_mag(letter, eq.x), v=_q(_norm(eq.value), unit)),
                ", ",
                *doc.say("at", angle=_angle(eq.value)),
            ]
        )
    return out


def _turns_with(d: Dyad, link: str) -> str | None:
    """The link whose rotation ``link`` shares through a prismatic pair (no pin side of its own)."""
    if any(s.kind == "R" and s.link == link for s in d.sides):
        return None
    for side in d.sides:
        if side.kind in ("P", "G") and side.link == link:
            return side.guide_link
    return d.lhs_link if link == d.la else None


def _group_points(ctx: _Ctx, links: Sequence[str], pin_of: Mapping[str, str]) -> None:
    """Markers of the group's links from a pin X of theirs (v_M = v_X + v_MX); then every point."""
    doc = ctx.doc
    rows: list[list] = []
    for name, ps in ctx.state.points.items():
        if ps.link not in links:
            continue
        marker = ctx.m.points.get(name)
        x = pin_of.get(ps.link)
        if marker is not None and marker.on == ps.link and x is not None and x != name:
            link = ps.link
            w, e = _turning(ctx, link)
            length = ctx.dist(link, x, name)
            sub, l_xm = name + x, _l(x, name)
            speed = _times_length(_w(link), w, x, name, length, "m/s")
            v_sum = _relative("v", name, x, sub, [""])
            rows.append([_f("{s}: {p}, {t}", s=v_sum, p=_perp(x, name), t=speed)])
            a_n, a_t = _mag("a", sub, "n"), _mag("a", sub, "τ")
            v_n, v_t = _q(w * w * length, "m/s²"), _q(abs(e) * length, "m/s²")
            normal = _f("{n} = {w}²·{l} = {v}", n=a_n, w=_w(link), l=l_xm, v=v_n)
            tangent = _f("{t} = {e}·{l} = {v}", t=a_t, e=_e(link), l=l_xm, v=v_t)
            a_sum = _relative("a", name, x, sub, ["n", "τ"])
            rows.append([_f("{s}: {n}, {t}", s=a_sum, n=normal, t=tangent)])
        v, a = np.asarray(ps.velocity), np.asarray(ps.acceleration)
        rows.append(
            doc.say(
                "point_value",
                name=name,
                link=ps.link,
                v=number(_norm(v)),
                va=_angle(v),
                a=number(_norm(a)),
                aa=_angle(a),
            )
        )
    if rows:
        doc.para(doc.word("points"))
        for row in rows:
            doc.item(*row)


def _relative(letter: str, point: str, base: str, sub: str, sups: Sequence[str]) -> Math:
    """``v_M = v_X + v_MX``, ``a_M = a_X + a^n_MX + a^τ_MX``: a point from another of its link."""
    terms = [_vec(letter, base), *(_vec(letter, sub, sup) for sup in sups)]
    return _f("{p} = {t}", p=_vec(letter, point), t=math_join(terms, " + "))


def _link_values(ctx: _Ctx, links: Sequence[str]) -> None:
    doc = ctx.doc
    doc.para(doc.word("solved_links"))
    for link in links:
        if link not in ctx.state.links:
            continue
        w, e = _turning(ctx, link)
        doc.item(
            *doc.say(
                "link_value",
                link=link,
                w=_w(link),
                wv=number(w),
                ws=ctx.sense(w),
                e=_e(link),
                ev=number(e),
                es=ctx.sense(e),
            )
        )


_ORDER_WORDS = {1: ("velocities", "two_unknowns"), 2: ("accelerations", "two_unknowns_a")}


def _explain_dyad(ctx: _Ctx, step: GroupStep, equations: Sequence[VectorEquation]) -> None:
    """A dyad: its velocity, then its acceleration equation (``equations``), each solved."""
    doc = ctx.doc
    for eq in equations:
        title, closes = _ORDER_WORDS[eq.order]
        doc.para(doc.word(title))
        equation, items = _equation(ctx, eq)
        doc.equation(equation)
        for row in items:
            doc.item(*row)
        doc.para(doc.word(closes))
        for row in _solved(ctx, eq):
            doc.item(*row)
    _link_values(ctx, step.links)
    d = equations[0].dyad
    pins: dict[str, str] = {}
    for side in d.sides:
        if side.kind == "R":
            pins.setdefault(side.link, side.base)
    for link in step.links if d.lhs_link is None else (d.la,):
        pins.setdefault(link, d.x)  # X is a pin of these links
    _group_points(ctx, step.links, pins)


def _explain_whole(ctx: _Ctx, step: GroupStep) -> None:
    """A group solved as a whole (triads and up), or a redundant link."""
    doc = ctx.doc
    g = step.group
    pins: dict[str, str] = {}
    if g is None:
        doc.para(*doc.say("redundant", link=step.redundant_link))
    else:
        doc.para(*doc.say("generic", rows=sum(eq.size for eq in step.equations)))
        for gp in g.pairs:
            a, b = gp.links
            point = gp.point or "?"
            if gp.kind is PairKind.R:
                same = [_vec("v", point_label(point, x)) for x in (a, b)]
                eq = _f("{a} = {b}", a=same[0], b=same[1])
                doc.item(*doc.say("pair_r", point=point, a=a, b=b, eq=eq))
                pins.setdefault(a, point)
            else:
                eq = _f("{a} = {b}", a=_w(a), b=_w(b))
                doc.item(*doc.say("pair_p", point=point, a=a, b=b, eq1=eq))
        doc.para(*doc.say("unknowns", links=", ".join(g.links), count=3 * len(g.links)))
    _link_values(ctx, step.links)
    _group_points(ctx, step.links, pins)


def _explain_drivers(ctx: _Ctx) -> None:
    doc = ctx.doc
    doc.heading(doc.word("drivers"))
    for d in ctx.plan.drivers:
        extra = "" if d.speed_given else doc.word("not_given")
        if d.kind == "R":
            doc.para(
                *doc.say(
                    "driver_r",
                    link=d.link,
                    pivot=d.point or "?",
                    w=_w(d.link),
                    wv=number(d.speed),
                    e=_e(d.link),
                    ev=number(d.acceleration),
                ),
                extra,
            )
        else:
            doc.para(
                *doc.say(
                    "driver_p",
                    link=d.link,
                    angle=_angle(d.direction),
                    v=number(d.speed),
                    a=number(d.acceleration),
                ),
                extra,
            )
        for name in ctx.points_of(d.link):
            if name == d.point:
                continue
            doc.item(_vec("v", name), ": ", *_known(ctx, name, d.link, name, 1))
            doc.item(_vec("a", name), ": ", *_known(ctx, name, d.link, name, 2))


def explain_kinematics(
    report: StructuralReport,
    plan: SolvePlan,
    state: KinematicState,
    lang: str = "en",
    fmt: str = "text",
) -> str:
    """The velocities and accelerations of ``state`` as the textbook's worked solution.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis the plan was made from.
    plan : SolvePlan
        From :func:`kinematics.plan.make_plan`.
    state : KinematicState
        From :func:`kinematics.solve.solve_pose` (any pose).
    lang : {"en", "vi"}
        English or Vietnamese.
    fmt : {"text", "markdown", "latex"}
        Plain text, Markdown with LaTeX mathematics, or a LaTeX fragment.

    Returns
    -------
    str
        The drivers, then for each group in solve order its velocity and
        acceleration vector equations with what is known of each term, and
        the values solved (ω, ε of its links; v, a of its points).

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.plan import make_plan
    >>> from kinematics.solve import solve_pose
    >>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C",
    ...                     "3 0 P C angle=0", "point A 0 0", "point B 0 0.1", "point C 0.2 0"])
    >>> r = analyze(m); plan = make_plan(r)
    >>> "v_C = v_B + v_CB" in explain_kinematics(r, plan, solve_pose(plan))
    True
    """
    check_options(lang, fmt)
    doc = Doc(PHRASES, lang)
    ctx = _Ctx(doc, plan, state)
    m = report.mechanism
    doc.title(*doc.say("kin_title", name=m.name or m.source))
    doc.para(doc.word("conventions"))
    _explain_drivers(ctx)
    dyads: dict[str, list[VectorEquation]] = {}
    for order in (1, 2):
        for eq in vector_equations(plan, state, order):
            dyads.setdefault(eq.label, []).append(eq)
    for k, step in enumerate(plan.steps, start=2):
        kind = f" {step.kind}" if step.kind else ""
        doc.heading(
            *doc.say("group_head", k=k, label=step.label, kind=kind, links=", ".join(step.links))
        )
        if step.label in dyads:
            _explain_dyad(ctx, step, dyads[step.label])
        else:
            _explain_whole(ctx, step)
    return render(doc, fmt)


# ============================================================================ forces
@dataclass
class _Load:
    """A known load on a link: a force at a point and/or a moment, and its power."""

    label: Math
    link: str
    force: np.ndarray
    at: np.ndarray
    moment: float = 0.0
    power: tuple[Math, float] | None = None  # "P_3·v_M3 = … = −707 W" and its value


def _moment_about(loads: Sequence[_Load], o: np.ndarray) -> float:
    return sum((_cross(x.at - o, x.force) + x.moment for x in loads), 0.0)


def _sum_force(loads: Sequence[_Load]) -> np.ndarray:
    return sum((x.force for x in loads), np.zeros(2))


def _applied_loads(ctx: _Ctx, velocities: _Ctx) -> list[_Load]:
    """The loads of the file and the inertia loads, listed; power at ``velocities``' motion."""
    doc = ctx.doc
    gravity = np.zeros(2)
    for load in ctx.m.loads:
        if load.kind == "gravity":
            gravity = np.array(load.values, dtype=float)
    out: list[_Load] = []
    count: dict[tuple[str, str], int] = {}
    inertia_tag = "qt" if doc.lang == "vi" else "in"

    def symbol(letter: str, link: str, sup: str = "") -> Math:
        count[letter + sup, link] = count.get((letter + sup, link), 0) + 1
        k = count[letter + sup, link]
        return _mag(letter, link if k == 1 else f"{link},{k}", sup)

    def force(label: Math, link: str, point: str, f: np.ndarray, key: str) -> None:
        v = point_at(velocities.plan, velocities.state, link, point)[1]
        dot = math_join([_f("{f}·{v}", f=_paren(f[i]), v=_paren(v[i])) for i in (0, 1)], " + ")
        power = _f(
            "{s}·{v} = {d} = {p}", s=label, v=_vec("v", point), d=dot, p=_q(float(f @ v), "W")
        )
        where = point_at(ctx.plan, ctx.state, link, point)[0]
        out.append(_Load(label, link, f, where, 0.0, (power, float(f @ v))))
        fx, fy = number(f[0], 1e-6), number(f[1], 1e-6)
        doc.item(*doc.say(key, sym=label, point=point, link=link, fx=fx, fy=fy))

    def moment(label: Math, link: str, value: float, key: str) -> None:
        w = _turning(velocities, link)[0]
        power = _power(label, _w(link), value, w)
        out.append(_Load(label, link, np.zeros(2), np.zeros(2), value, (power, value * w)))
        doc.item(*doc.say(key, sym=label, link=link, value=number(value, 1e-6)))

    for load in ctx.m.loads:
        link, point = load.link, load.point or ""
        if load.kind == "force":
            force(symbol("P", link), link, point, np.array(load.values, dtype=float), "load_force")
        elif load.kind == "moment":
            moment(symbol("M", link), link, float(load.values[0]), "load_moment")
        elif load.kind == "mass":
            mass, inertia = (float(x) for x in load.values)
            if _norm(gravity) > 0:
                force(symbol("G", link), link, point, mass * gravity, "load_weight")
            inertia_force = -mass * point_at(ctx.plan, ctx.state, link, point)[2]
            force(symbol("P", link, inertia_tag), link, point, inertia_force, "load_inertia")
            if inertia:
                inertia_moment = -inertia * _turning(ctx, link)[1]
                label = symbol("M", link, inertia_tag)
                moment(label, link, inertia_moment, "load_inertia_m")
    return out


def _commas(items: Iterable[list]) -> list:
    """The items (each a list of segments) one after the other, separated by ``, ``."""
    out: list = []
    for item in items:
        out += [", ", *item] if out else item
    return out


def _rsym(source: str, target: str, sup: str = "") -> Math:
    """``R_12``: the force link 1 exerts on link 2 (a magnitude or component)."""
    return _mag("R", _sub2(source, target), sup)


def _rvec(source: str, target: str, sup: str = "") -> Math:
    return _vec("R", _sub2(source, target), sup)


def _find(
    solution: ForceSolution, a: str, b: str, point: str | None, kind: str
) -> tuple[np.ndarray, float, Reaction] | None:
    """The force and couple that ``a`` exerts on ``b`` at ``point``, and the reaction."""
    for r in solution.reactions:
        if r.kind != kind or set(r.links) != {a, b}:
            continue
        if point and r.point and r.point != point:
            continue
        if r.links == (a, b):
            return np.asarray(r.force), r.couple, r
        return -np.asarray(r.force), -r.couple, r
    return None


def _acts_at(ctx: _Ctx, r: Reaction) -> _At:
    """Where a reaction acts: its pin, or for a slide its point on ``links[1]``."""
    name = r.point or ""
    if r.kind == "P" and ctx.m.coordinates(name) is not None:
        return ctx.slide_point(name, r.links[1])
    named = ctx.state.points.get(name)
    return _At(name, np.zeros(2) if named is None else np.asarray(named.position))


def _carried(ctx: _Ctx, solution: ForceSolution, link: str, farther: set[str]) -> list[_Load]:
    """The reactions of the groups already solved (farther out) on ``link``."""
    out = []
    for r in solution.reactions:
        if r.kind not in ("R", "P") or link not in r.links:
            continue
        other = r.links[0] if r.links[1] == link else r.links[1]
        if other not in farther:
            continue
        sign = 1.0 if r.links[1] == link else -1.0
        at = _acts_at(ctx, r).xy
        force = sign * np.asarray(r.force)
        out.append(_Load(_rsym(other, link), link, force, at, sign * r.couple))
    return out


def _known_loads(ctx: _Ctx, link: str, loads: Sequence[_Load]) -> None:
    doc = ctx.doc
    parts = _commas([x.label] for x in loads)
    doc.item(*doc.say("f_known", link=link, list=parts or [doc.word("f_none")]))


def _show_reaction(
    ctx: _Ctx, solution: ForceSolution, a: str, b: str, point: str, kind: str
) -> None:
    doc = ctx.doc
    found = _find(solution, a, b, point, kind)
    if found is None:
        return
    f, c, r = found
    extra: list = []
    if kind == "P":
        about = _acts_at(ctx, r).name
        extra = doc.say("f_reaction_p", point=about, value=number(c, 1e-6))
    doc.item(
        *doc.say(
            "f_reaction",
            sym=_rsym(a, b),
            point=point,
            fx=number(f[0], 1e-6),
            fy=number(f[1], 1e-6),
            mag=number(_norm(f), 1e-6),
            angle=_angle(f, 1e-6),
        ),
        *extra,
    )


def _what(doc: Doc, head: list, gives: Sequence[Math]) -> list:
    """An equation's name and the unknowns it gives: ``ΣF = 0 on link 2; gives R_32``."""
    if not gives:
        return head
    return [*head, "; ", *doc.say("f_gives", what=_commas([sym] for sym in gives))]


class _Steps:
    """Numbered equilibrium equations: what each one is and gives, then the equation."""

    def __init__(self, doc: Doc):
        self.doc = doc
        self.k = 0

    def __call__(self, what: list, equation: Math) -> None:
        self.k += 1
        self.doc.item(*self.doc.say("f_step", k=self.k, what=what))
        self.doc.equation(equation)


def _moment_sum(point: str) -> Math:
    return Math(f"ΣM_{point}", rf"\sum M_{{{point}}}")


def _moment_step(
    ctx: _Ctx, link: str, about: _At, loads: Sequence[_Load], gives: Sequence[Math]
) -> tuple[float, list]:
    """The known loads' moment about ``about`` and the words of ``ΣM_about(link) = 0``."""
    doc = ctx.doc
    value = _moment_about(loads, about.xy)
    head = [
        *doc.say("f_moment", sum=_moment_sum(about.name), link=link),
        "; ",
        _mag("M", about.name),
        ": ",
        *doc.say("f_sum_moments", link=link, point=about.name),
        " = ",
        _q(value, "N·m", 1e-6),
    ]
    return value, _what(doc, head, gives)


def _tangential(
    ctx: _Ctx, steps: _Steps, link: str, known: str, base: _At, pin: _At, loads: Sequence[_Load]
) -> np.ndarray:
    """ΣM_pin(link) = 0 gives the component of R_known,link at ``base`` ⊥ base–pin."""
    length = _norm(pin.xy - base.xy)
    rt_sym = _rsym(known, link, "τ")
    moment, what = _moment_step(ctx, link, pin, loads, [rt_sym])
    rt = moment / length
    b, c = base.name, pin.name
    m_pin, l_bc = _mag("M", c), _l(b, c)
    numbers = [_num(moment, 1e-6), length]
    ratio = _with_numbers("{0}/{1}", [m_pin, l_bc], numbers, _q(rt, "N", 1e-6))
    steps(what, _f("−{r}·{l} + {m} = 0 ⇒ {r} = {q}", r=rt_sym, l=l_bc, m=m_pin, q=ratio))
    ctx.doc.para(
        *ctx.doc.say(
            "f_tangent",
            rt=Math("R^τ", r"R^{\tau}"),
            rn=Math("R^n", "R^{n}"),
            perp=Math(f"⊥{b}{c}", rf"\perp {b}{c}"),
            par=Math(f"∥{b}{c}", rf"\parallel {b}{c}"),
            line=b + c,
            a=b,
            b=c,
        )
    )
    return rt * _j((pin.xy - base.xy) / length)


def _solve2(a: np.ndarray, b: np.ndarray, rhs: np.ndarray) -> tuple[float, float]:
    """``x·a + y·b = rhs``."""
    det = _cross(a, b)
    if abs(det) <= 1e-12:
        return math.nan, math.nan
    return _cross(rhs, b) / det, _cross(a, rhs) / det


def _balance(terms: Sequence[Math], loads: Math, found: Sequence[tuple[Math, float]]) -> Math:
    """``R^n_12 + R^τ_12 + … + ΣP = 0 ⇒ R^n_12 = …, …``."""
    values = [_f("{s} = {v}", s=s, v=_q(v, "N", 1e-6)) for s, v in found]
    lhs = math_join([*terms, loads], " + ")
    return _f("{lhs} = 0 ⇒ {values}", lhs=lhs, values=math_join(values, ", "))


def _offset(ctx: _Ctx, point: str, couple: float, nvec: np.ndarray, u: np.ndarray) -> None:
    """Where the guide's reaction acts: x = M/N along the guide from its point."""
    doc = ctx.doc
    if _norm(nvec) <= 1e-9 * max(1.0, abs(couple)):
        if abs(couple) > 1e-9:
            doc.para(*doc.say("f_couple", value=number(couple, 1e-6)))
        return
    doc.para(*doc.say("f_offset", x=number(couple / _cross(u, nvec), 1e-9), point=point))


def _slide_moment(
    ctx: _Ctx,
    steps: _Steps,
    link: str,
    known: str,
    s: _At,
    about: _At,
    loads: Sequence[_Load],
    nvec: np.ndarray,
    u: np.ndarray,
    extra: tuple[Math, float] | None = None,
) -> None:
    """ΣM_about(link) = 0 gives the moment of the guide's reaction about its point ``s``."""
    msym = _mag("M", _sub2(known, link))
    moment, what = _moment_step(ctx, link, about, loads, [msym])
    value = -(_cross(s.xy - about.xy, nvec) + moment + (extra[1] if extra else 0.0))
    terms = [msym]
    if s.name != about.name:
        arm = f"{about.name}{s.name}"
        terms.append(Math(f"{arm}×", rf"\vec{{{arm}}} \times ") + _rvec(known, link))
    if extra is not None:
        terms.append(extra[0])
    terms.append(_mag("M", about.name))
    lhs = math_join(terms, " + ")
    steps(what, _f("{lhs} = 0 ⇒ {m} = {v}", lhs=lhs, m=msym, v=_q(value, "N·m", 1e-6)))
    _offset(ctx, s.name, value, nvec, u)


def _link_balance(
    steps: _Steps, link: str, sources: tuple[str, str], rest: np.ndarray, gives: str
) -> None:
    """ΣF = 0 on ``link``: ``R_a,link + ΣP_link + R_b,link = 0`` gives ``R_gives,link``.

    ``sources`` are the links ``a``, ``b`` whose reactions on ``link`` enter; ``rest``
    is the known part of the sum, ``ΣP_link`` and the other reaction.
    """
    doc = steps.doc
    a, b = sources
    sym = _rvec(gives, link)
    lhs = math_join([_rvec(a, link), _sum(link), _rvec(b, link)], " + ")
    what = _what(doc, doc.say("f_force_link", link=link), [sym])
    steps(what, _f("{lhs} = 0 ⇒ {r} = {v}", lhs=lhs, r=sym, v=_xy(-rest, "N")))


def _moment_of(point: str, source: str, target: str) -> Math:
    """``M_B(R_32)``: the moment about ``point`` of the force ``source`` exerts on ``target``."""
    sub = _sub2(source, target)
    return Math(f"M_{point}(R_{sub})", rf"M_{{{point}}}(R_{{{sub}}})")


def _dyad_forces(ctx: _Ctx, g: AssurGroup, d: Dyad, loads: Mapping[str, list[_Load]]) -> None:
    """The textbook's equations of a dyad, each solved for its unknowns with numbers."""
    doc = ctx.doc
    steps = _Steps(doc)
    (mid,) = g.internal_pairs
    ext = {p.links[0]: p for p in g.external_pairs}
    forces = {x: _sum_force(loads[x]) for x in g.links}
    if mid.kind is PairKind.R:
        _pin_dyad_forces(ctx, steps, g, ext, ctx.pin(mid.point or "?"), loads, forces)
        return
    la, lb = d.la, d.lhs_link or ""
    u, name = ctx.guide(mid.pair)
    nn = _j(u)
    n_sym = _rsym(la, lb)
    doc.para(*doc.say("f_slide", sym=n_sym, guide=name))
    b, s = ctx.pin(ext[la].point or "?"), ctx.slide_at(mid.pair)
    src_a = ext[la].links[1]
    if ext[lb].kind is PairKind.R:  # RPR: moments about the block's pin, then the other pivot
        p_d = ctx.pin(ext[lb].point or "?")
        m_b, m_d = _mag("M", b.name), _mag("M", p_d.name)
        mb, what = _moment_step(ctx, la, b, loads[la], [])
        inner = _moment_of(b.name, lb, la)
        steps(what, _f("{i} + {m} = 0 ⇒ {i} = {v}", i=inner, m=m_b, v=_q(-mb, "N·m", 1e-6)))
        md, what = _moment_step(ctx, lb, p_d, loads[lb], [n_sym])
        lever = _cross(b.xy - p_d.xy, nn)
        doc.para(*doc.say("f_lever", sym=n_sym, point=b.name, about=p_d.name, h=number(lever)))
        value = -(mb + md) / lever if abs(lever) > 1e-12 else math.nan
        found = _q(value, "N", 1e-6)
        solved = _f("−({b} + {d})/{h} = {v}", b=_paren(mb), d=_paren(md), h=_paren(lever), v=found)
        steps(what, _f("{n}·h + {b} + {d} = 0 ⇒ {n} = {s}", n=n_sym, b=m_b, d=m_d, s=solved))
        nvec = value * nn
        _offset(ctx, s.name, mb - _cross(s.xy - b.xy, nvec), nvec, u)
        _link_balance(steps, la, (src_a, lb), forces[la] - nvec, gives=src_a)
        src_b = ext[lb].links[1]
        _link_balance(steps, lb, (src_b, la), forces[lb] + nvec, gives=src_b)
        return
    e = ext[lb]  # RPP: the inner slide and the outer guide carry the forces on lb
    ue, name_e = ctx.guide(e.pair)
    ne = _j(ue)
    e_sym = _rsym(e.links[1], lb)
    doc.para(*doc.say("f_slide", sym=e_sym, guide=name_e))
    x_mid, x_ext = _solve2(nn, ne, -forces[lb])
    terms = [_rvec(la, lb), _rvec(e.links[1], lb)]
    what = _what(doc, doc.say("f_force_link", link=lb), [n_sym, e_sym])
    steps(what, _balance(terms, _sum(lb), [(n_sym, x_mid), (e_sym, x_ext)]))
    nvec = x_mid * nn
    _link_balance(steps, la, (src_a, lb), forces[la] - nvec, gives=src_a)
    couple_sym = _mag("M", _sub2(la, lb))
    mb, what = _moment_step(ctx, la, b, loads[la], [couple_sym])
    couple = mb - _cross(s.xy - b.xy, nvec)
    steps(what, _f("{c} = {v}", c=couple_sym, v=_q(couple, "N·m", 1e-6)))
    _offset(ctx, s.name, couple, nvec, u)
    se = ctx.slide_at(e.pair)
    extra = (_moment_of(se.name, la, lb), couple + _cross(s.xy - se.xy, nvec))
    _slide_moment(ctx, steps, lb, e.links[1], se, se, loads[lb], x_ext * ne, ue, extra)


def _pin_dyad_forces(
    ctx: _Ctx,
    steps: _Steps,
    g: AssurGroup,
    ext: Mapping[str, GroupPair],
    pin: _At,
    loads: Mapping[str, list[_Load]],
    forces: Mapping[str, np.ndarray],
) -> None:
    """RRR, RRP, PRP: tangential components, the group's force balance, the inner pin."""
    doc = ctx.doc
    tangent = {
        link: _tangential(ctx, steps, link, e.links[1], ctx.pin(e.point or "?"), pin, loads[link])
        for link, e in ext.items()
        if e.kind is PairKind.R
    }
    rest = forces[g.links[0]] + forces[g.links[1]] + sum(tangent.values(), np.zeros(2))
    unknown: list[tuple[Math, np.ndarray]] = []
    terms: list[Math] = []
    for link in g.links:
        e, src = ext[link], ext[link].links[1]
        if e.kind is PairKind.R:
            n = pin.xy - ctx.pin(e.point or "").xy
            unknown.append((_rsym(src, link, "n"), n / _norm(n)))
            terms += [_rvec(src, link, "n"), _rvec(src, link, "τ")]
        else:
            u, name = ctx.guide(e.pair)
            unknown.append((_rsym(src, link), _j(u)))
            terms.append(_rvec(src, link))
            doc.para(*doc.say("f_slide", sym=_rsym(src, link), guide=name))
    (s1, d1), (s2, d2) = unknown
    x1, x2 = _solve2(d1, d2, -rest)
    what = _what(doc, [doc.word("f_force_group")], [s1, s2])
    steps(what, _balance(terms, _sum(), [(s1, x1), (s2, x2)]))
    outer = {g.links[0]: x1 * d1, g.links[1]: x2 * d2}
    for link, t in tangent.items():
        outer[link] = outer[link] + t
    first = next((x for x in g.links if ext[x].kind is PairKind.R), g.links[0])
    other = g.links[1] if first == g.links[0] else g.links[0]
    src = ext[first].links[1]
    _link_balance(steps, first, (src, other), outer[first] + forces[first], gives=other)
    for link, e in ext.items():
        if e.kind is PairKind.P:
            u, s = ctx.guide(e.pair)[0], ctx.slide_at(e.pair)
            _slide_moment(ctx, steps, link, e.links[1], s, pin, loads[link], outer[link], u)


def _group_forces(
    ctx: _Ctx,
    solution: ForceSolution,
    step: GroupStep,
    applied: Sequence[_Load],
    farther: set[str],
    whole: bool,
) -> None:
    doc = ctx.doc
    g = step.group
    loads = {
        link: [x for x in applied if x.link == link] + _carried(ctx, solution, link, farther)
        for link in step.links
    }
    for link in step.links:
        _known_loads(ctx, link, loads[link])
    pairs = list(g.pairs) if g is not None else []
    listing = _commas([_rsym(p.links[1], p.links[0]), f" ({p.point})"] for p in pairs)
    if listing:
        doc.para(*doc.say("f_unknowns", list=listing))
    d = None if whole else dyad_of(ctx.plan, ctx.state, g)
    if g is not None and d is not None:
        _dyad_forces(ctx, g, d, loads)
    elif g is not None:
        doc.para(*doc.say("f_generic", eqs=3 * len(g.links), n=len(g.links)))
    doc.para(doc.word("f_found"))
    for p in pairs:
        _show_reaction(ctx, solution, p.links[1], p.links[0], p.point or "", p.kind.value)
    if g is None:
        for r in solution.reactions:
            if step.redundant_link in r.links and r.kind in ("R", "P"):
                _show_reaction(ctx, solution, r.links[0], r.links[1], r.point or "", r.kind)


def _virtual(plan: SolvePlan, state: KinematicState) -> tuple[KinematicState, bool]:
    """The motion the power check uses: the real one, or one with unit driver speeds."""
    if any(abs(d.speed) > 0 for d in plan.drivers):
        return state, False
    drivers = tuple(dataclasses.replace(d, speed=1.0) for d in plan.drivers)
    return solve_pose(dataclasses.replace(plan, drivers=drivers), state.inputs), True


def _pose(plan: SolvePlan, inputs: Sequence[float]) -> Math:
    """The driver inputs from the sketch: ``φ1 = 0.5 rad`` (turned), ``s1 = 0.02 m`` (slid)."""
    parts = []
    for d, x in zip(plan.drivers, inputs, strict=True):
        if d.kind == "R":
            parts.append(_f("{s} = {v}", s=subscript("φ", d.link), v=_q(x, "rad")))
        else:
            parts.append(_f("{s} = {v}", s=Math(f"s{d.link}", f"s_{{{d.link}}}"), v=_q(x, "m")))
    return math_join(parts, ", ")


_Power = tuple[Math, float, Math, float]  # balancing symbol, its value, speed symbol, speed


def _driver_forces(
    ctx: _Ctx,
    vctx: _Ctx,
    solution: ForceSolution,
    drv: DriverStep,
    loads: Sequence[_Load],
) -> _Power:
    """The balancing moment (or force) from the driver's equilibrium, then the ground's reaction."""
    doc = ctx.doc
    link = drv.link
    if drv.kind == "P":
        u = drv.direction
        along = -float(_sum_force(loads) @ u)
        found = float(solution.balancing_moment.get(link, along))
        sym = _mag("F", "cb")
        doc.equation(_f("{s} + ΣP·u = 0 ⇒ {s} = {v}", s=sym, v=_q(along, "N", 1e-6)))
        doc.item(*doc.say("f_fcb_value", sym=sym, value=number(found, 1e-6), angle=_angle(u)))
        pid = ctx.slide.get(link)
        point = (ctx.m.pair(pid).point or "") if pid else ""
        _show_reaction(ctx, solution, ctx.ground, link, point, "P")
        speed = float(link_rates(vctx.plan, vctx.state, link)[1][:2] @ u)
        return sym, found, Math(f"v{link}", f"v_{{{link}}}"), speed
    pivot = drv.point or "?"
    a = ctx.pin(pivot).xy if pivot in ctx.state.points else np.asarray(drv.pivot)
    ma = _moment_about(loads, a)
    doc.para(*doc.say("f_mcb", sum=_moment_sum(pivot), link=link))
    sums = doc.say("f_sum_moments", link=link, point=pivot)
    doc.item(_mag("M", pivot), ": ", *sums, " = ", _q(ma, "N·m", 1e-6))
    balance = next((x for x in ctx.m.loads if x.kind == "balance" and x.link == link), None)
    if balance is not None and solution.balancing_force is not None:
        t = math.radians(balance.values[0])
        u = np.array([math.cos(t), math.sin(t)])
        point = balance.point or ""
        known = ctx.m.coordinates(point) is not None
        at = point_at(ctx.plan, ctx.state, link, point)[0] if known else a
        lever = _cross(at - a, u)
        sym = _mag("P", "cb")
        value = -ma / lever if abs(lever) > 1e-12 else math.nan
        doc.equation(
            _f(
                "{s}·h + {m} = 0, h = {h} ⇒ {s} = −{m}/h = {v}",
                s=sym,
                m=_mag("M", pivot),
                h=_q(lever, "m"),
                v=_q(value, "N", 1e-6),
            )
        )
        found = float(np.asarray(solution.balancing_force) @ u)
        doc.item(
            *doc.say(
                "f_pcb_value",
                sym=sym,
                value=number(found, 1e-6),
                angle=number(balance.values[0]),
                point=point,
            )
        )
        on_driver = found * u
        speed_sym = _f("{v}·u", v=_vec("v", point))
        speed = float(point_at(vctx.plan, vctx.state, link, point)[1] @ u)
        power: _Power = (sym, found, speed_sym, speed)
    else:
        sym = _mag("M", "cb")
        m_pivot = _mag("M", pivot)
        doc.equation(
            _f("{s} + {m} = 0 ⇒ {s} = −{m} = {v}", s=sym, m=m_pivot, v=_q(-ma, "N·m", 1e-6))
        )
        found = float(solution.balancing_moment.get(link, -ma))
        sense = doc.word("ccw" if found >= 0 else "cw")
        doc.item(*doc.say("f_mcb_value", sym=sym, value=number(found, 1e-6), sense=sense))
        on_driver = np.zeros(2)
        power = (sym, found, _w(link), _turning(vctx, link)[0])
    ground = -(_sum_force(loads) + on_driver)
    doc.para(*doc.say("f_ground", link=link))
    doc.equation(
        _f("{r} = −{p} = {v}", r=_rvec(ctx.ground, link), p=_sum(link), v=_xy(ground, "N"))
    )
    _show_reaction(ctx, solution, ctx.ground, link, pivot, "R")
    return power


def _power_check(
    ctx: _Ctx,
    k: int,
    applied: Sequence[_Load],
    drivers: Sequence[_Power],
    solution: ForceSolution,
    virtual: bool,
) -> None:
    """Σ P·v + Σ M·ω + M_cb·ω1 = 0 with every term's numbers."""
    doc = ctx.doc
    doc.heading(*doc.say("f_power", k=k))
    doc.para(doc.word("f_power_intro"))
    if virtual:
        doc.para(doc.word("f_power_virtual"))
    doc.equation(POWER_EQUATION)
    values: list[float] = []
    for load in applied:
        if load.power is not None:
            doc.item(load.power[0])
            values.append(load.power[1])
    loads_power = sum(values, 0.0)
    for sym, value, speed_sym, speed in drivers:
        doc.item(_power(sym, speed_sym, value, speed))
        values.append(value * speed)
    if solution.friction_loss is not None:
        doc.item(*doc.say("f_power_friction", value=number(solution.friction_loss, 1e-9)))
        values.append(-solution.friction_loss)
    total = sum(values, 0.0)
    scale = max([abs(x) for x in values] + [1e-300])
    key = "f_power_sum" if abs(total) <= 1e-6 * scale else "f_power_bad"
    doc.para(*doc.say(key, value=number(total, 1e-6 * scale)))
    if len(drivers) == 1 and abs(drivers[0][3]) > 1e-12 and solution.friction_loss is None:
        sym, _, speed_sym, speed = drivers[0]
        value = -loads_power / speed
        numbers = [_paren(loads_power), _paren(speed)]
        solved = _with_numbers("−{0}/{1}", [_f("ΣP·v"), speed_sym], numbers, _num(value, 1e-6))
        eq = _f("{s} = {v}", s=sym, v=solved)
        doc.para(*doc.say("f_power_gives", eq=eq))


def explain_forces(
    report: StructuralReport,
    plan: SolvePlan,
    solution: ForceSolution,
    lang: str = "en",
    fmt: str = "text",
) -> str:
    """The kinetostatics of ``solution`` (at its pose) as the textbook's worked solution.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis the plan was made from.
    plan : SolvePlan
        From :func:`kinematics.plan.make_plan`.
    solution : ForceSolution
        From :func:`kinematics.forces.solve_forces`, at any pose: the motion
        (inertia loads, the power check) is solved at its ``inputs``.
    lang : {"en", "vi"}
        English or Vietnamese.
    fmt : {"text", "markdown", "latex"}
        Plain text, Markdown with LaTeX mathematics, or a LaTeX fragment.

    Returns
    -------
    str
        The loads; for each group from the farthest, its equilibrium
        equations in the order solved with the unknowns each gives, and the
        reactions found; the driver's balancing moment from ``ΣM_A = 0``; the
        virtual-power check with numbers.

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.

    Examples
    --------
    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.plan import make_plan
    >>> from kinematics.forces import solve_forces
    >>> m = parse_edgelist(["driver 1 omega=1", "0 1 R A", "point A 0 0", "point B 0.1 0 on=1",
    ...                     "force 1 B 0 -100"])
    >>> r = analyze(m); plan = make_plan(r)
    >>> "M_cb = −M_A = 10 N·m" in explain_forces(r, plan, solve_forces(plan))
    True
    """
    check_options(lang, fmt)
    doc = Doc(PHRASES, lang)
    state = solve_pose(plan, solution.inputs or None)
    ctx = _Ctx(doc, plan, state)
    virtual_state, virtual = _virtual(plan, state)
    vctx = _Ctx(doc, plan, virtual_state) if virtual else ctx
    m = report.mechanism
    if any(solution.inputs):
        pose = _pose(plan, solution.inputs)
        doc.title(*doc.say("f_title_at", name=m.name or m.source, pose=pose))
    else:
        doc.title(*doc.say("f_title", name=m.name or m.source))
    doc.para(doc.word("f_conventions"))
    doc.para(*doc.say("f_order", order=" → ".join(solution.order)))
    doc.heading("1. " + doc.word("loads"))
    applied = _applied_loads(ctx, vctx)
    if not applied:
        doc.para(doc.word("no_loads"))
    whole = any(p.friction or p.circle for p in ctx.m.pairs)
    if whole:
        doc.para(doc.word("f_friction"))
    if any(s.group is None for s in plan.steps):
        doc.para(doc.word("f_indeterminate"))
    farther: set[str] = set()
    k = 2
    for step in reversed(plan.steps):
        kind = f" {step.kind}" if step.kind else ""
        doc.heading(*doc.say("f_group", k=k, label=step.label, kind=kind))
        _group_forces(ctx, solution, step, applied, farther, whole)
        farther |= set(step.links)
        k += 1
    powers = []
    for drv in plan.drivers:
        doc.heading(*doc.say("f_driver", k=k, link=drv.link))
        k += 1
        on_driver = [x for x in applied if x.link == drv.link]
        loads = on_driver + _carried(ctx, solution, drv.link, farther)
        _known_loads(ctx, drv.link, loads)
        powers.append(_driver_forces(ctx, vctx, solution, drv, loads))
    for _, a, b, point in plan.contacts:
        for r in solution.reactions:
            if r.kind == "H" and set(r.links) == {a, b}:
                doc.para(*doc.say("f_contact", point=point or "?"))
                magnitude = f", |F| = {number(r.magnitude, 1e-6)} N"
                doc.item(_rsym(r.links[0], r.links[1]), ": ", _xy(r.force, "N"), magnitude)
    _power_check(ctx, k, applied, powers, solution, virtual)
    return render(doc, fmt)
