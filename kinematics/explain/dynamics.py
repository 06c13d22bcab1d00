"""The worked solution of a machine's dynamics: the reduced inertia, the flywheel, in two languages.

:func:`explain_dynamics` writes, with the numbers of the actual solution
(:func:`~kinematics.dynamics.analysis.machine_dynamics`): the reduced moment of
inertia at the sketch pose, link by link from the velocity ratios, and over the
turn; the reduced moment; the equation of motion; the steady running and its
coefficient of speed fluctuation; the flywheel, approximately from the largest
swing of energy and exactly by Wittenbauer's tangents, and why they differ;
the driver's inertia torque at the file's ω and ε (problem 3.2 of the course).

>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.dynamics.analysis import machine_dynamics
>>> m = parse_edgelist(["driver 1 omega=0 epsilon=7", "0 1 R O", "point O 0 0",
...                     "mass 1 0 2 O"])
>>> text = explain_dynamics(machine_dynamics(analyze(m)))
>>> "M_J = −(J_r·ε1 + ½·J_r'·ω1²) = −(2·7 + ½·0·0²) = -14 N·m" in text
True
"""

from __future__ import annotations

import math

import numpy as np

from structure.explain.document import Doc, Math, check_options, formula, number, render, subscript

from ..dynamics.analysis import MachineDynamics

__all__ = ["PHRASES", "explain_dynamics"]

#: the sentences of the dynamics' worked solution, by language
PHRASES: dict[str, dict[str, str]] = {
    "en": {
        "title": "Machine dynamics of {name}",
        "conventions": (
            "Units m, s, rad, kg; φ is the driver's rotation from the sketch, counter-clockwise. "
            "The machine is reduced to its driver {link}: its kinetic energy is that of the "
            "driver alone with the reduced moment of inertia J_r, and the power of every load is "
            "that of the reduced moment M_r on the driver."
        ),
        "h_inertia": "1. The reduced moment of inertia",
        "inertia_def": (
            "Each link's kinetic energy ½·(m·v_S² + J_S·ω²), divided by ½·ω1², gives its part of "
            "J_r; the ratios v_S/ω1 and ω/ω1 depend on the pose only (the kinematics at "
            "ω1 = 1 rad/s):"
        ),
        "inertia_at": "At the sketch pose (φ = 0):",
        "link_share": "link {link}: {terms}",
        "massless": "Links {links} have no mass line: they are massless and add nothing.",
        "inertia_sum": "Sum:",
        "inertia_turn": (
            "Over the turn J_r goes from {low} kg·m² (φ = {at_low}°) to {high} kg·m² "
            "(φ = {at_high}°), mean {mean} kg·m²; its slope dJ_r/dφ comes from the "
            "accelerations at ω1 = 1, ε1 = 0:"
        ),
        "h_moment": "2. The reduced moment",
        "moment_def": "The power of each load, divided by ω1:",
        "moment_term": "{label}: {law}",
        "t_loads": "the file's forces and moments, constant over the turn",
        "t_gravity": "gravity on the masses",
        "t_moment": "a moment on link {link}",
        "t_force": "a force on link {link} at {point}",
        "t_drive": "the drive on link {link}",
        "l_value": "{value}",
        "l_motor": "motor curve M0·(1 − ω/W0) = {m0}·(1 − ω/{w0})",
        "l_table": "a table of {count} points over the turn",
        "l_formula": "the formula {text}",
        "no_terms": "No drive and no load acts.",
        "assumed": (
            "The file gives no drive: a constant torque equal to the loads' mean, {value} N·m, "
            "is taken."
        ),
        "h_motion": "3. The equation of motion",
        "motion_def": (
            "From the kinetic energy ½·J_r·ω² (Lagrange's equation with the one coordinate φ), "
            "or in energy form:"
        ),
        "inertia_torque": (
            "At the driver's motion in the file the links' inertia reduced to the driver is "
            "the inertia torque:"
        ),
        "inertia_torque_after": (
            "The motor supplies its opposite, {value} N·m, on top of the loads (over the turn "
            "the inertia torque goes from {low} to {high} N·m)."
        ),
        "h_steady": "4. Steady running",
        "steady_energy": (
            "M_r does not depend on ω: ½·J_r·ω² = E0 + W(φ), W the work of M_r since φ = 0; "
            "the work of a turn is 0, and E0 is the root that gives the mean speed {mean} rad/s."
        ),
        "steady_shooting": (
            "M_r depends on ω: the speed at φ = 0 that comes back after one turn of the "
            "energy form is found by shooting: ω(0) = {omega0} rad/s."
        ),
        "steady_values": (
            "ω_max = {high} rad/s (φ = {at_high}°), ω_min = {low} rad/s (φ = {at_low}°):"
        ),
        "delta_time": (
            "(over the time mean 2π/T = {mean} rad/s, with T = {period} s a turn: δ = {delta})"
        ),
        "h_flywheel": "5. The flywheel for δ = {delta}",
        "swing": (
            "The energy W(φ) the drive and the loads put in since φ = 0 is largest at "
            "φ = {at_high}° ({high} J) and smallest at φ = {at_low}° ({low} J):"
        ),
        "approximate": "Approximately, the machine taken as one constant inertia:",
        "less_mean": "less the mechanism's own mean J_r ({mean} kg·m²): {value} kg·m².",
        "wittenbauer": (
            "Exactly, by Wittenbauer's energy–inertia diagram: W(φ) against J_r(φ). With a "
            "flywheel J_F, ω²/2 is the slope from the true origin (−J_F, −E0) to the curve. "
            "The tangents with the slopes of ω_max,min = ω_m·(1 ± δ/2):"
        ),
        "tangent_max": "the upper one touches at φ = {at}°: A = max(W − k_max·J_r) = {value} J",
        "tangent_min": "the lower one touches at φ = {at}°: B = min(W − k_min·J_r) = {value} J",
        "exact": "They meet at the true origin when",
        "not_needed": (
            "J_F ≤ 0: no flywheel is needed, the machine's own inertia keeps δ within the goal."
        ),
        "motor_goal": (
            "M_r depends on ω (a motor curve): the flywheel whose steady running has δ at the "
            "goal is {value} kg·m² (Wittenbauer's diagram at the speed without it gives the first "
            "answer; a few steady runs with the flywheel correct it)."
        ),
        "check": "Check: the steady running with the flywheel has δ = {delta}.",
        "difference": (
            "Why they differ: the approximate formula lets only the loads' energy swing the "
            "speed, through one constant inertia; the exact one also counts the links' own "
            "kinetic energy, which J_r(φ) stores and gives back over the turn (with J_r "
            "constant, J_F = ΔE_max/(δ·ω_m²) − J_r exactly)."
        ),
    },
    "vi": {
        "title": "Động lực học máy: {name}",
        "conventions": (
            "Đơn vị m, s, rad, kg; φ là góc quay của khâu dẫn so với hình vẽ, ngược chiều kim "
            "đồng hồ. Thu gọn máy về khâu dẫn {link}: động năng của máy bằng động năng của khâu "
            "dẫn với mômen quán tính thu gọn J_td, công suất của mọi lực bằng công suất của "
            "mômen thu gọn M_td trên khâu dẫn."
        ),
        "h_inertia": "1. Mômen quán tính thu gọn",
        "inertia_def": (
            "Động năng ½·(m·v_S² + J_S·ω²) của mỗi khâu chia cho ½·ω1² cho phần của nó trong "
            "J_td; các tỉ số v_S/ω1 và ω/ω1 chỉ phụ thuộc vị trí (động học với ω1 = 1 rad/s):"
        ),
        "inertia_at": "Tại vị trí trên hình vẽ (φ = 0):",
        "link_share": "khâu {link}: {terms}",
        "massless": "Các khâu {links} không có dòng khối lượng: coi như không có khối lượng.",
        "inertia_sum": "Tổng:",
        "inertia_turn": (
            "Trong một vòng J_td biến thiên từ {low} kg·m² (φ = {at_low}°) đến {high} kg·m² "
            "(φ = {at_high}°), trung bình {mean} kg·m²; đạo hàm dJ_td/dφ tính từ gia tốc với "
            "ω1 = 1, ε1 = 0:"
        ),
        "h_moment": "2. Mômen thu gọn",
        "moment_def": "Công suất của mỗi lực chia cho ω1:",
        "moment_term": "{label}: {law}",
        "t_loads": "các lực và mômen cho trong tệp, không đổi trong một vòng",
        "t_gravity": "trọng lực của các khâu",
        "t_moment": "mômen trên khâu {link}",
        "t_force": "lực trên khâu {link} tại {point}",
        "t_drive": "mômen động trên khâu {link}",
        "l_value": "{value}",
        "l_motor": "đặc tính động cơ M0·(1 − ω/W0) = {m0}·(1 − ω/{w0})",
        "l_table": "bảng {count} điểm theo góc quay",
        "l_formula": "công thức {text}",
        "no_terms": "Không có mômen động và không có lực cản.",
        "assumed": (
            "Tệp không cho mômen động: lấy mômen động không đổi bằng trung bình của mômen cản, "
            "{value} N·m."
        ),
        "h_motion": "3. Phương trình chuyển động của máy",
        "motion_def": (
            "Từ động năng ½·J_td·ω² (phương trình Lagrange với một toạ độ φ), hoặc dạng năng lượng:"
        ),
        "inertia_torque": (
            "Với chuyển động của khâu dẫn cho trong tệp, lực quán tính của các khâu thu gọn về "
            "khâu dẫn là mômen lực quán tính:"
        ),
        "inertia_torque_after": (
            "Động cơ phải cấp mômen ngược lại, {value} N·m, ngoài phần thắng lực cản (trong một "
            "vòng mômen lực quán tính biến thiên từ {low} đến {high} N·m)."
        ),
        "h_steady": "4. Chuyển động bình ổn",
        "steady_energy": (
            "M_td không phụ thuộc ω: ½·J_td·ω² = E0 + W(φ), W là công của M_td từ φ = 0; công "
            "trong một vòng bằng 0, E0 là nghiệm cho vận tốc góc trung bình {mean} rad/s."
        ),
        "steady_shooting": (
            "M_td phụ thuộc ω: vận tốc tại φ = 0 sao cho sau một vòng (dạng năng lượng) trở lại "
            "đúng giá trị đó, tìm bằng phương pháp bắn: ω(0) = {omega0} rad/s."
        ),
        "steady_values": (
            "ω_max = {high} rad/s (φ = {at_high}°), ω_min = {low} rad/s (φ = {at_low}°):"
        ),
        "delta_time": (
            "(theo trung bình thời gian 2π/T = {mean} rad/s, T = {period} s một vòng: δ = {delta})"
        ),
        "h_flywheel": "5. Bánh đà cho hệ số chuyển động không đều δ = {delta}",
        "swing": (
            "Công W(φ) của mômen động và mômen cản từ φ = 0 lớn nhất tại φ = {at_high}° "
            "({high} J) và nhỏ nhất tại φ = {at_low}° ({low} J):"
        ),
        "approximate": "Gần đúng, coi máy như một mômen quán tính không đổi:",
        "less_mean": (
            "trừ mômen quán tính thu gọn trung bình của cơ cấu ({mean} kg·m²): {value} kg·m²."
        ),
        "wittenbauer": (
            "Chính xác, bằng đồ thị năng lượng – mômen quán tính (đồ thị Wittenbauer): W(φ) theo "
            "J_td(φ). Với bánh đà J_đ, ω²/2 là hệ số góc từ gốc thật (−J_đ, −E0) đến đường cong. "
            "Các tiếp tuyến có hệ số góc ứng với ω_max,min = ω_tb·(1 ± δ/2):"
        ),
        "tangent_max": "tiếp tuyến trên chạm tại φ = {at}°: A = max(W − k_max·J_td) = {value} J",
        "tangent_min": "tiếp tuyến dưới chạm tại φ = {at}°: B = min(W − k_min·J_td) = {value} J",
        "exact": "Chúng cắt nhau tại gốc thật khi",
        "not_needed": (
            "J_đ ≤ 0: không cần bánh đà, quán tính của bản thân máy đã giữ δ trong giới hạn."
        ),
        "motor_goal": (
            "M_td phụ thuộc ω (đặc tính động cơ): bánh đà cho chuyển động bình ổn với đúng δ là "
            "{value} kg·m² (đồ thị Wittenbauer ở vận tốc khi chưa có bánh đà cho giá trị đầu; vài "
            "lần tính chuyển động bình ổn với bánh đà hiệu chỉnh nó)."
        ),
        "check": "Kiểm tra: chuyển động bình ổn với bánh đà có δ = {delta}.",
        "difference": (
            "Vì sao hai kết quả khác nhau: công thức gần đúng chỉ để biến thiên năng lượng của "
            "các lực làm dao động vận tốc qua một mômen quán tính không đổi; công thức chính xác "
            "còn tính động năng của chính các khâu, mà J_td(φ) tích và trả lại trong một vòng "
            "(khi J_td không đổi, J_đ = ΔE_max/(δ·ω_tb²) − J_td đúng)."
        ),
    },
}

#: the symbols that differ by language: J_r or J_td, J_F or J_đ, ω_m or ω_tb
_SYMBOLS = {
    "en": {
        "J": ("J_r", "J_{r}"),
        "M": ("M_r", "M_{r}"),
        "F": ("J_F", "J_{F}"),
        "m": ("ω_m", r"\omega_{m}"),
    },
    "vi": {
        "J": ("J_td", "J_{td}"),
        "M": ("M_td", "M_{td}"),
        "F": ("J_đ", r"J_{\text{đ}}"),
        "m": ("ω_tb", r"\omega_{tb}"),
    },
}


def _symbol(lang: str, key: str) -> Math:
    text, latex = _SYMBOLS[lang][key]
    return Math(text, latex)


def _law_words(doc: Doc, law) -> list:
    """A law in the document's language."""
    kind = law.kind.value
    if kind == "value":
        return doc.say("l_value", value=number(law.numbers[0]))
    if kind == "motor":
        return doc.say("l_motor", m0=number(law.numbers[0]), w0=number(law.numbers[1]))
    if kind == "table":
        return doc.say("l_table", count=len(law.points))
    return doc.say("l_formula", text=law.formula.text)


def _signed(x: float) -> str:
    """A number to be squared: in brackets when negative."""
    text = number(x)
    return f"({text})" if text.startswith("-") else text


def _deg(phi: float) -> str:
    return number(math.degrees(phi) % 360)


def explain_dynamics(result: MachineDynamics, lang: str = "en", fmt: str = "text") -> str:
    """The worked solution of ``result``'s reduced inertia, moment, motion and flywheel.

    Parameters
    ----------
    result : MachineDynamics
        From :func:`~kinematics.dynamics.analysis.machine_dynamics`.
    lang : {"en", "vi"}
        English or Vietnamese.
    fmt : {"text", "markdown", "latex", "html"}
        See :func:`~structure.explain.document.render`.

    Raises
    ------
    ValueError
        An unknown ``lang`` or ``fmt``.
    """
    check_options(lang, fmt)
    doc = Doc(PHRASES, lang)
    machine = result.machine
    name = result.report.mechanism.name or result.report.mechanism.source
    doc.title(*doc.say("title", name=name))
    doc.para(*doc.say("conventions", link=machine.driver))
    _inertia(doc, result)
    _moment(doc, result)
    _motion(doc, result)
    _steady(doc, result)
    _flywheel(doc, result)
    return render(doc, fmt)


def _inertia(doc: Doc, result: MachineDynamics) -> None:
    lang = doc.lang
    j = _symbol(lang, "J")
    props = result.machine.properties
    w1 = subscript("ω", "1")
    doc.heading(doc.word("h_inertia"))
    doc.para(*doc.say("inertia_def"))
    doc.equation(formula("{J} = Σ (m·v_S² + J_S·ω²)/{w}²", J=j, w=w1))
    mechanism = result.report.mechanism
    motion = props.motion
    if props.massless:
        doc.para(*doc.say("massless", links=", ".join(props.massless)))
    if motion is not None and props.shares:
        doc.para(*doc.say("inertia_at"))
        for load in mechanism.loads:
            if load.kind != "mass" or load.link not in motion.q:
                continue
            mass, inertia = load.values
            xy = np.array(mechanism.coordinates(load.point), dtype=float)
            _, v, _ = motion.point(load.link, xy)
            speed = float(np.hypot(*v[0]))
            ratio = float(motion.qd[load.link][0, 2])
            share = mass * speed * speed + inertia * ratio * ratio
            terms = formula(
                "m·(v_S/{w})² + J_S·(ω/{w})² = {m}·{v}² + {J}·{r}² = {s} kg·m²",
                w=w1, m=float(mass), v=speed, J=float(inertia), r=_signed(ratio), s=share,
            )  # fmt: skip
            doc.item(*doc.say("link_share", link=load.link, terms=terms))
        total = float(props.inertia[0])
        doc.para(*doc.say("inertia_sum"))
        doc.equation(formula("{J}(0) = {value} kg·m²", J=j, value=total))
    elif motion is None:
        doc.equation(formula("{J} = {value} kg·m²", J=j, value=float(props.inertia[0])))
    low, high = int(np.argmin(props.inertia)), int(np.argmax(props.inertia))
    doc.para(
        *doc.say(
            "inertia_turn",
            low=number(float(props.inertia[low])),
            at_low=_deg(float(props.phi[low])),
            high=number(float(props.inertia[high])),
            at_high=_deg(float(props.phi[high])),
            mean=number(float(np.mean(props.inertia[:-1]))),
        )
    )
    doc.equation(formula("d{J}/dφ = 2·Σ (m·v_S·a_S + J_S·ω·ε)/{w}³", J=j, w=w1))


def _moment(doc: Doc, result: MachineDynamics) -> None:
    machine = result.machine
    m = _symbol(doc.lang, "M")
    w1 = subscript("ω", "1")
    doc.heading(doc.word("h_moment"))
    doc.para(*doc.say("moment_def"))
    doc.equation(formula("{M} = Σ F·v_P/{w} + Σ M·ω/{w} + M_d", M=m, w=w1))
    if not machine.terms:
        doc.para(*doc.say("no_terms"))
    for term in machine.terms:
        label = doc.say(f"t_{term.kind}", link=term.link, point=term.point or "")
        law = _law_words(doc, term.law) if term.law is not None else ["—"]
        doc.item(*doc.say("moment_term", label=label, law=law))
    if machine.assumed_drive is not None:
        doc.para(*doc.say("assumed", value=number(machine.assumed_drive)))


def _motion(doc: Doc, result: MachineDynamics) -> None:
    j, m = _symbol(doc.lang, "J"), _symbol(doc.lang, "M")
    doc.heading(doc.word("h_motion"))
    doc.para(*doc.say("motion_def"))
    doc.equation(formula("{J}·φ'' + ½·{J}'·φ'² = {M}", J=j, M=m))
    doc.equation(formula("d(½·{J}·ω²)/dφ = {M}", J=j, M=m))
    if result.inertia_torque is None:
        return
    w, e, torque = result.inertia_torque
    props = result.machine.properties
    doc.para(*doc.say("inertia_torque"))
    w1, e1 = subscript("ω", "1"), subscript("ε", "1")
    k = 0
    value = float(torque[k])
    doc.equation(
        formula(
            "M_J = −({J}·{e} + ½·{J}'·{w}²) = −({jv}·{ev} + ½·{dv}·{wv}²) = {value} N·m",
            J=j,
            e=e1,
            w=w1,
            jv=float(props.inertia[k]),
            ev=float(e),
            dv=float(props.slope[k]),
            wv=float(w),
            value=value,
        )
    )
    doc.para(
        *doc.say(
            "inertia_torque_after",
            value=number(-value),
            low=number(float(np.min(torque))),
            high=number(float(np.max(torque))),
        )
    )


def _steady(doc: Doc, result: MachineDynamics) -> None:
    steady = result.steady
    if steady is None:
        return
    mean = _symbol(doc.lang, "m")
    doc.heading(doc.word("h_steady"))
    if steady.method == "energy":
        doc.para(*doc.say("steady_energy", mean=number(steady.omega_mean)))
    else:
        doc.para(*doc.say("steady_shooting", omega0=number(float(steady.omega[0]))))
    high, low = int(np.argmax(steady.omega)), int(np.argmin(steady.omega))
    doc.para(
        *doc.say(
            "steady_values",
            high=number(steady.omega_max),
            at_high=_deg(float(steady.phi[high])),
            low=number(steady.omega_min),
            at_low=_deg(float(steady.phi[low])),
        )
    )
    doc.equation(
        formula(
            "{m} = (ω_max + ω_min)/2 = {value} rad/s, δ = (ω_max − ω_min)/{m} = {delta}",
            m=mean,
            value=steady.omega_mean,
            delta=steady.delta,
        )
    )
    doc.para(
        *doc.say(
            "delta_time",
            mean=number(steady.omega_time_mean),
            period=number(steady.period),
            delta=number(steady.delta_time_mean),
        )
    )


def _flywheel(doc: Doc, result: MachineDynamics) -> None:
    wheel = result.flywheel
    if wheel is None:
        return
    lang = doc.lang
    jf, mean = _symbol(lang, "F"), _symbol(lang, "m")
    doc.heading(*doc.say("h_flywheel", delta=number(wheel.delta_goal)))
    high, low = int(np.argmax(wheel.work)), int(np.argmin(wheel.work))
    doc.para(
        *doc.say(
            "swing",
            at_high=_deg(float(wheel.phi[high])),
            high=number(float(wheel.work[high])),
            at_low=_deg(float(wheel.phi[low])),
            low=number(float(wheel.work[low])),
        )
    )
    doc.equation(formula("ΔE_max = W_max − W_min = {value} J", value=wheel.energy_swing))
    doc.para(*doc.say("approximate"))
    doc.equation(
        formula(
            "{F} ≈ ΔE_max/(δ·{m}²) = {e}/({d}·{w}²) = {value} kg·m²",
            F=jf,
            m=mean,
            e=wheel.energy_swing,
            d=wheel.delta_goal,
            w=wheel.omega_mean,
            value=wheel.approximate,
        )
    )
    own = wheel.approximate - wheel.approximate_less_mean
    doc.para(*doc.say("less_mean", mean=number(own), value=number(wheel.approximate_less_mean)))
    doc.para(*doc.say("wittenbauer"))
    (k_max, at_max, a_value), (k_min, at_min, b_value) = wheel.tangents
    doc.equation(
        formula("k_max = ω_max²/2 = {a}, k_min = ω_min²/2 = {b}", a=float(k_max), b=float(k_min))
    )
    doc.item(*doc.say("tangent_max", at=_deg(at_max), value=number(a_value)))
    doc.item(*doc.say("tangent_min", at=_deg(at_min), value=number(b_value)))
    doc.para(*doc.say("exact"))
    first = (a_value - b_value) / (k_max - k_min)
    doc.equation(
        formula(
            "{F} = (A − B)/(k_max − k_min) = ({a} − ({b}))/({d}) = {value} kg·m²",
            F=jf,
            a=a_value,
            b=b_value,
            d=float(k_max - k_min),
            value=first,
        )
    )
    if not wheel.needed:
        doc.para(*doc.say("not_needed"))
    elif result.machine.uses_omega:
        doc.para(*doc.say("motor_goal", value=number(wheel.exact)))
    if wheel.steady is not None:
        doc.para(*doc.say("check", delta=number(wheel.steady.delta)))
    doc.para(*doc.say("difference"))
