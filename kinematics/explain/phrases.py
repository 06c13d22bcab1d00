"""The sentences of the kinematics and force worked solutions, in English and Vietnamese.

:data:`PHRASES` maps a language (``en``, ``vi``) to its phrases by key; a
phrase's ``{name}`` fields take prose or mathematics (see
:meth:`structure.explain.document.Doc.say`). The keys of the force solution
start with ``f_``.

>>> sorted(PHRASES) == ["en", "vi"] and PHRASES["en"].keys() == PHRASES["vi"].keys()
True
"""

from __future__ import annotations

__all__ = ["PHRASES"]

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
