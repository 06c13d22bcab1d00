"""The report page's words in English and Vietnamese: titles, table headings, one-line notes.

:data:`PHRASES` maps a language to its phrases by key; :func:`say` fills a
phrase's ``{fields}``. The Vietnamese follows the course's vocabulary (khâu,
khớp, khâu dẫn, nhóm tĩnh định, họa đồ vận tốc, áp lực khớp động, mômen cân
bằng, phương pháp công suất, tỉ số truyền).

>>> sorted(PHRASES) == ["en", "vi"] and PHRASES["en"].keys() == PHRASES["vi"].keys()
True
>>> say("vi", "s_forces")
'4. Phân tích lực tại vị trí đang xét'
"""

from __future__ import annotations

__all__ = ["PHRASES", "say"]

_ENGLISH: dict[str, str] = {
    "page_title": "Analysis of {name}",
    "made_by": "Made by assur report from {source}. SI units; angles counter-clockwise.",
    "contents": "Contents",
    # sections
    "s_mechanism": "1. The mechanism",
    "s_structure": "2. Structural analysis",
    "s_kinematics": "3. Kinematics at the pose",
    "s_forces": "4. Forces at the pose",
    "s_cycle": "5. The whole cycle",
    "s_gears": "6. Gear train",
    "s_worked": "10. Worked solution, step by step",
    "s_cams": "7. Cam design",
    "s_dynamics": "8. Machine dynamics: steady running, flywheel, shaking",
    "s_synthesis": "9. Dimensional synthesis: the design's targets",
    "no_targets": "Not applicable: the file gives no design targets (target lines).",
    "h_targets": "The targets over the path of P",
    "target_distance": "distance from P",
    # the one-line notes of a section that does not apply
    "no_geometry": "Not applicable: the file gives no point coordinates.",
    "no_loads": "Not applicable: the file gives no loads (force, moment or mass lines).",
    "no_gears": "Not applicable: the mechanism has no gear train.",
    "no_cams": "Not applicable: the mechanism has no cam with a program (a cam statement).",
    "unsolved": "Not computed: {reason}",
    # mechanism and structure
    "h_drawing": "The mechanism at the sketch pose, its Assur groups in colour",
    "h_graph": "Kinematic graph: links as nodes, pairs as edges",
    "h_counts": "Counts and degree of freedom",
    "h_redundant": "Redundant constraints",
    "h_passive": "Passive freedoms",
    "h_replaced": "Higher pairs replaced by lower pairs",
    "h_groups": "Assur groups, in solve order",
    "h_formula": "Structural formula",
    "none": "None.",
    "quantity": "quantity",
    "meaning": "meaning",
    "given": "as given",
    "after_replacement": "after replacement",
    "q_n": "moving links",
    "q_p5": "lower pairs (class 5)",
    "q_p4": "higher pairs (class 4)",
    "q_r": "redundant constraints",
    "q_w_th": "passive freedoms",
    "q_w": "degree of freedom",
    "pair": "pair",
    "line": "line",
    "constraints": "constraints",
    "origin": "origin",
    "structural": "structural count (a sub-chain with more constraints than freedoms)",
    "geometric": "the sketch's dimensions (rank of the constraint Jacobian)",
    "roller": "the spin of a roller about its own axis",
    "link": "link",
    "links": "links",
    "freedoms": "freedoms",
    "higher_pair": "higher pair",
    "virtual_link": "virtual link",
    "scheme": "scheme",
    "new_pairs": "new pairs",
    "roller_removed": "roller removed",
    "group": "group",
    "class": "class",
    "order": "order",
    "kind": "kind",
    "attached_to": "attached to",
    "formula_groups": "In solve order, from the driver(s): {formula}",
    "formula_textbook": "W = one per driver + 0 per group: {formula}",
    "mechanism_class": "The mechanism is of class {cls}, the highest class of its groups.",
    "set_aside": "Set aside as redundant before the groups are detached: links {links}.",
    "drivers_chosen": "No driver was named in the file: chosen among the links on the ground.",
    # kinematics and forces
    "h_drivers": "Drivers",
    "h_links": "Links",
    "h_points": "Points",
    "h_velocity_polygon": "Velocity polygon, to scale",
    "h_acceleration_polygon": "Acceleration polygon, to scale",
    "driver_r": "driver {link} turns about {pivot}: ω = {speed} rad/s, ε = {acc} rad/s²",
    "driver_p": "driver {link} slides: v = {speed} m/s, a = {acc} m/s²",
    "assumed": " (not given in the file: taken as 0)",
    "point": "point",
    "on_link": "on link",
    "angle_turned": "angle turned (rad)",
    "h_reactions": "Joint reactions, farthest group first (order {order})",
    "h_balancing": "Balancing moment",
    "h_power": "Virtual-power check",
    "h_force_polygons": "Force polygons, to scale",
    "acting": "link on link",
    "couple": "couple (N·m)",
    "balancing_moment": (
        "balancing moment on driver {link}: M_cb = {value} N·m (counter-clockwise +)"
    ),
    "balancing_slide": "balancing force on driver {link}: {value} N along its slide",
    "balancing_force": "balancing force: ({fx}, {fy}) N",
    "friction_loss": "power lost to friction: {value} W",
    "compound_pin": "compound pin {point}: the pin pushes {forces} N",
    "power_check": (
        "The powers of every load and of the balancing moment add up to zero; what is left is "
        "{value} of the largest term."
    ),
    # the cycle
    "h_animation": "Animation over the cycle",
    "h_plots": "Positions, velocities, accelerations, transmission angle and balancing",
    "animation_help": (
        "Drag the slider or press play: {count} poses of the driver(s), computed beforehand."
    ),
    "play": "Play",
    "pause": "Pause",
    "pose_slider": "pose",
    "partial": (
        "Not a whole turn: the mechanism reaches from {low}, to {high}. The poses shown go "
        "from {start} to {end}."
    ),
    "stroke": (
        "The stroke of the sliding driver: from {low}, to {high}. The poses shown go from "
        "{start} to {end}."
    ),
    "limit_dead_point": "{at}, a dead point of group {group}",
    "limit_change_point": "{at}, a change point of group {group} (two assembly modes meet)",
    "limit_singular": "{at}, a singular pose of group {group}",
    "limit_free": "{at} (the mechanism does not stop the slide)",
    # gears
    "h_meshes": "Meshes",
    "h_willis": "Willis relations, one per mesh in its carrier's frame",
    "h_ratios": "Speed ratios to the input (ω_link / ω_input), exact",
    "h_torques": "Torques",
    "teeth": "teeth z",
    "carrier": "carrier",
    "internal": "internal",
    "external": "external",
    "exact": "exact",
    "value": "value",
    "train_dof": "DOF of the train: {dof}; input(s): {inputs}.",
    "teeth_found": "From coaxiality: z of {link} in {pair} = {z}.",
    "train_moment": "balancing moment on the input (by power): {exact} ≈ {value} N·m",
    "train_moment_of": "balancing moment on input {link} (by power): {exact} ≈ {value} N·m",
    "train_inertia": "moment of inertia reduced to the input: {exact} ≈ {value} kg·m²",
    "train_inertia_matrix": "inertia matrix reduced to the inputs ({inputs}): {rows} kg·m²",
    "h_relations": "Speeds in the inputs' speeds (ω_link = Σ k·ω_input), exact",
    "relation": "relation",
    "speed": "speed (rad/s)",
    "train_force_moment": "balancing moment from the planets' force balance: {value} N·m",
    "planet_pin": "pin of planet {planet}: radial {radial} N, tangential {tangential} N",
    "tooth_force": "tooth force in {pair}: {value} N",
    "no_torques": "No moment load on the train: no torques to find.",
    # worked solution
    "h_worked_structure": "Structure",
    "h_worked_kinematics": "Velocities and accelerations",
    "h_worked_forces": "Forces",
}

_VIETNAMESE: dict[str, str] = {
    "page_title": "Phân tích cơ cấu: {name}",
    "made_by": (
        "Tạo bằng assur report từ tệp {source}. Đơn vị SI; góc dương ngược chiều kim đồng hồ."
    ),
    "contents": "Mục lục",
    "s_mechanism": "1. Cơ cấu",
    "s_structure": "2. Phân tích cấu trúc",
    "s_kinematics": "3. Động học tại vị trí đang xét",
    "s_forces": "4. Phân tích lực tại vị trí đang xét",
    "s_cycle": "5. Cả chu kỳ chuyển động",
    "s_gears": "6. Hệ bánh răng",
    "s_worked": "10. Lời giải chi tiết từng bước",
    "s_cams": "7. Thiết kế cơ cấu cam",
    "s_dynamics": "8. Động lực học máy: chuyển động bình ổn, bánh đà, lực rung",
    "s_synthesis": "9. Tổng hợp kích thước: các điểm mục tiêu của thiết kế",
    "no_targets": "Không áp dụng: tệp không có điểm mục tiêu thiết kế (dòng target).",
    "h_targets": "Các điểm mục tiêu trên quỹ đạo của điểm P",
    "target_distance": "khoảng cách tới P",
    "no_geometry": "Không áp dụng: tệp không cho tọa độ các điểm.",
    "no_loads": "Không áp dụng: tệp không cho ngoại lực (lực, mômen hay khối lượng).",
    "no_gears": "Không áp dụng: cơ cấu không có hệ bánh răng.",
    "no_cams": "Không áp dụng: cơ cấu không có cam cho theo quy luật chuyển động (lệnh cam).",
    "unsolved": "Không tính được: {reason}",
    "h_drawing": "Lược đồ cơ cấu tại vị trí đang xét, các nhóm Assur tô màu",
    "h_graph": "Đồ thị khâu – khớp: khâu là đỉnh, khớp là cạnh",
    "h_counts": "Số khâu, số khớp và bậc tự do",
    "h_redundant": "Ràng buộc trùng",
    "h_passive": "Bậc tự do thừa",
    "h_replaced": "Thay thế khớp cao bằng khớp thấp",
    "h_groups": "Các nhóm tĩnh định (nhóm Assur), theo thứ tự giải",
    "h_formula": "Công thức cấu tạo",
    "none": "Không có.",
    "quantity": "đại lượng",
    "meaning": "ý nghĩa",
    "given": "theo đề",
    "after_replacement": "sau khi thay thế",
    "q_n": "số khâu động",
    "q_p5": "số khớp thấp loại 5",
    "q_p4": "số khớp cao loại 4",
    "q_r": "số ràng buộc trùng",
    "q_w_th": "số bậc tự do thừa",
    "q_w": "bậc tự do",
    "pair": "khớp",
    "line": "dòng",
    "constraints": "số ràng buộc",
    "origin": "nguồn gốc",
    "structural": "đếm theo cấu trúc (chuỗi con có nhiều ràng buộc hơn số bậc tự do)",
    "geometric": "do kích thước trên hình vẽ (hạng ma trận Jacobi của các ràng buộc)",
    "roller": "chuyển động quay của con lăn quanh trục của nó",
    "link": "khâu",
    "links": "khâu",
    "freedoms": "số bậc tự do",
    "higher_pair": "khớp cao",
    "virtual_link": "khâu thay thế",
    "scheme": "cách thay",
    "new_pairs": "khớp mới",
    "roller_removed": "con lăn bỏ đi",
    "group": "nhóm",
    "class": "loại",
    "order": "bậc",
    "kind": "dạng",
    "attached_to": "nối vào khâu",
    "formula_groups": "Theo thứ tự giải, từ khâu dẫn: {formula}",
    "formula_textbook": "Công thức cấu tạo (mỗi khâu dẫn 1, mỗi nhóm 0): {formula}",
    "mechanism_class": "Đây là cơ cấu loại {cls}, loại cao nhất của các nhóm.",
    "set_aside": "Khâu thừa bỏ ra trước khi tách nhóm: {links}.",
    "drivers_chosen": "Tệp không ghi khâu dẫn: chọn trong các khâu nối với giá.",
    "h_drivers": "Khâu dẫn",
    "h_links": "Các khâu",
    "h_points": "Các điểm",
    "h_velocity_polygon": "Họa đồ vận tốc, đúng tỉ lệ",
    "h_acceleration_polygon": "Họa đồ gia tốc, đúng tỉ lệ",
    "driver_r": "khâu dẫn {link} quay quanh {pivot}: ω = {speed} rad/s, ε = {acc} rad/s²",
    "driver_p": "khâu dẫn {link} tịnh tiến: v = {speed} m/s, a = {acc} m/s²",
    "assumed": " (không cho trong đề: lấy bằng 0)",
    "point": "điểm",
    "on_link": "thuộc khâu",
    "angle_turned": "góc quay (rad)",
    "h_reactions": "Áp lực khớp động, từ nhóm xa khâu dẫn nhất (thứ tự {order})",
    "h_balancing": "Mômen cân bằng",
    "h_power": "Kiểm tra bằng phương pháp công suất",
    "h_force_polygons": "Họa đồ lực, đúng tỉ lệ",
    "acting": "khâu tác dụng lên khâu",
    "couple": "mômen (N·m)",
    "balancing_moment": (
        "mômen cân bằng trên khâu dẫn {link}: M_cb = {value} N·m "
        "(dương khi ngược chiều kim đồng hồ)"
    ),
    "balancing_slide": "lực cân bằng trên khâu dẫn {link}: {value} N dọc giá trượt",
    "balancing_force": "lực cân bằng: ({fx}, {fy}) N",
    "friction_loss": "công suất mất do ma sát: {value} W",
    "compound_pin": "khớp quay kép {point}: chốt đẩy {forces} N",
    "power_check": (
        "Tổng công suất của mọi ngoại lực và của mômen cân bằng bằng không; phần còn lại bằng "
        "{value} số hạng lớn nhất."
    ),
    "h_animation": "Mô phỏng chuyển động trong một chu kỳ",
    "h_plots": "Vị trí, vận tốc, gia tốc, góc truyền động và mômen cân bằng",
    "animation_help": (
        "Kéo thanh trượt hoặc bấm nút chạy: {count} vị trí của khâu dẫn, đã tính sẵn."
    ),
    "play": "Chạy",
    "pause": "Dừng",
    "pose_slider": "vị trí",
    "partial": (
        "Không quay được trọn vòng: cơ cấu chỉ đi được từ {low}, đến {high}. Các vị trí vẽ từ "
        "{start} đến {end}."
    ),
    "stroke": (
        "Hành trình của khâu dẫn trượt: từ {low}, đến {high}. Các vị trí vẽ từ {start} đến {end}."
    ),
    "limit_dead_point": "{at}, một điểm chết của nhóm {group}",
    "limit_change_point": "{at}, một điểm rẽ nhánh của nhóm {group} (hai dạng lắp ráp gặp nhau)",
    "limit_singular": "{at}, một vị trí suy biến của nhóm {group}",
    "limit_free": "{at} (cơ cấu không chặn con trượt)",
    "h_meshes": "Các cặp bánh răng ăn khớp",
    "h_willis": (
        "Công thức Willis, mỗi cặp ăn khớp một phương trình, trong hệ quy chiếu gắn với cần"
    ),
    "h_ratios": "Tỉ số truyền so với khâu vào (ω_khâu / ω_vào), giá trị đúng",
    "h_torques": "Mômen",
    "teeth": "số răng z",
    "carrier": "cần",
    "internal": "ăn khớp trong",
    "external": "ăn khớp ngoài",
    "exact": "giá trị đúng",
    "value": "giá trị",
    "train_dof": "Bậc tự do của hệ: {dof}; khâu vào: {inputs}.",
    "teeth_found": "Từ điều kiện đồng trục: số răng của {link} trong {pair} là {z}.",
    "train_moment": "mômen cân bằng trên khâu vào (phương pháp công suất): {exact} ≈ {value} N·m",
    "train_moment_of": (
        "mômen cân bằng trên khâu vào {link} (phương pháp công suất): {exact} ≈ {value} N·m"
    ),
    "train_inertia": "mômen quán tính thu gọn về khâu vào: {exact} ≈ {value} kg·m²",
    "train_inertia_matrix": "ma trận quán tính thu gọn về các khâu vào ({inputs}): {rows} kg·m²",
    "h_relations": "Vận tốc góc theo vận tốc các khâu vào (ω_khâu = Σ k·ω_vào), giá trị đúng",
    "relation": "quan hệ",
    "speed": "vận tốc góc (rad/s)",
    "train_force_moment": "mômen cân bằng từ cân bằng lực các bánh vệ tinh: {value} N·m",
    "planet_pin": "chốt bánh vệ tinh {planet}: hướng kính {radial} N, tiếp tuyến {tangential} N",
    "tooth_force": "lực ăn khớp tại {pair}: {value} N",
    "no_torques": "Hệ không chịu mômen: không có mômen cần tính.",
    "h_worked_structure": "Cấu trúc",
    "h_worked_kinematics": "Vận tốc và gia tốc",
    "h_worked_forces": "Lực",
}

#: every phrase of the page, by language then key
PHRASES: dict[str, dict[str, str]] = {"en": _ENGLISH, "vi": _VIETNAMESE}


def say(lang: str, key: str, **fields: object) -> str:
    """The phrase ``key`` in ``lang`` with its ``{fields}`` filled (plain text, not escaped)."""
    text = PHRASES[lang][key]
    return text.format(**fields) if fields else text
