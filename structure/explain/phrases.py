"""The sentences of the structural worked solution, in English and Vietnamese.

:data:`PHRASES` maps a language (``en``, ``vi``) to its phrases by key; a
phrase's ``{name}`` fields take prose or mathematics (see
:meth:`structure.explain.document.Doc.say`). The Vietnamese follows the
source's vocabulary (khâu, giá, khâu dẫn, khớp quay, khớp tịnh tiến, bậc tự
do, ràng buộc trùng, bậc tự do thừa, nhóm tĩnh định, loại, bậc, công thức cấu
tạo).

>>> sorted(PHRASES) == ["en", "vi"] and PHRASES["en"].keys() == PHRASES["vi"].keys()
True
"""

from __future__ import annotations

__all__ = ["PHRASES"]

#: every sentence of the structural explanation, by language; ``{name}`` fields take
#: prose or mathematics
PHRASES: dict[str, dict[str, str]] = {
    "en": {
        "title": "Structure of {name}",
        "mobility": "1. Degree of freedom",
        "formula_intro": "The degree of freedom is given by",
        "n": "n = {n} moving links ({links}); the ground {ground} is not counted",
        "p5": "P5 = {p5} lower pairs: {r} revolute (R), {p} prismatic (P)",
        "compound": (
            "compound hinge {point} joins {k} links ({links}): it counts {k} − 1 = {pairs} "
            "revolute pairs"
        ),
        "p4": "P4 = {p4} higher pair(s): {pairs}",
        "p4_none": "P4 = 0: no higher pairs",
        "cam": "cam contact",
        "gear": "gear teeth",
        "r_none": "r = 0: no redundant constraints",
        "r": "r = {r} redundant constraint(s):",
        "r_structural": (
            "{k} in pair {pair}{line}: a sub-chain with more constraints than its links can take "
            "(structural count)"
        ),
        "r_geometric": (
            "{k} in pair {pair}{line}: the dimensions repeat a constraint (rank of the constraint "
            "Jacobian at the sketch pose)"
        ),
        "line": " (line {line})",
        "w_none": "W_th = 0: no passive freedoms",
        "w": "W_th = {w} passive freedom(s):",
        "w_roller": "the spin of roller {link} about its own axis",
        "w_geometric": "link {link} can move alone ({k} freedom(s), found at the sketch pose)",
        "substituted": "With the numbers:",
        "note": "Note: {note}",
        "replacement": "2. Replacement of the higher pairs",
        "replacement_intro": (
            "The higher pairs are replaced by lower pairs (valid at this pose, for positions, "
            "velocities and accelerations): each becomes a virtual link with two lower pairs."
        ),
        "roller": (
            "roller {roller} is removed with its pair {pair}: its spin was the passive freedom; "
            "the contact now acts at its axis {axis}, a point of link {follower}"
        ),
        "replace_rr": (
            "{pair} ({what}) → virtual link {v} with {new}: revolute pairs at the centres of "
            "curvature of the two profiles"
        ),
        "replace_rp": (
            "{pair} ({what}) → virtual link {v} with {new}: the profile of link {flat} is straight "
            "at the contact, so that side becomes a prismatic pair along it"
        ),
        "replaced_counts": (
            "The replaced mechanism: n = {n}, P5 = {p5}, P4 = 0; the roller spins are gone "
            "(W_th = 0):"
        ),
        "unchanged": "W is unchanged, as it must be.",
        "drivers": "{k}. Driver(s)",
        "driver": "link {link} is the driver, joined to the ground by {pair}",
        "driver_chosen": ("(no driver was named: chosen among the links joined to the ground)"),
        "w_drivers": "W = {w}: {w} driver(s) with one freedom each.",
        "set_aside": (
            "the redundant link(s) {links} (pairs {pairs}) are set aside before the groups are "
            "detached"
        ),
        "groups": "{k}. Assur groups, detached from the farthest",
        "groups_intro": (
            "Each group is the smallest set of links with 3·n = 2·p (statically determinate) that "
            "is attached to what is left; the textbook detaches them starting from the farthest "
            "from the driver, the solvers run them in the reverse order."
        ),
        "no_groups": "There are no groups: the driver(s) and the ground are the whole mechanism.",
        "group": "Group {i}: {label}",
        "group_links": "links {links}: n = {n}",
        "group_pairs": "pairs: {pairs}: p = {p}",
        "outer": "outer",
        "inner": "inner",
        "check": "3·n = 2·p:",
        "class_dyad": "class II: a dyad (2 links, 3 pairs); order {order}; kind {kind}",
        "class_base": (
            "class {cls}: link {link} is a base link with {k} inner pairs and there is no "
            "longer closed contour; order {order}"
        ),
        "class_contour": "class {cls}: a closed contour of {k} inner pairs; order {order}",
        "attached": "attached to link(s) {links}",
        "remains": (
            "What remains is the driver(s) {drivers} with the ground {ground}: a class-I mechanism."
        ),
        "formula": "{k}. Structural formula and class",
        "formula_groups": "In solve order (from the driver):",
        "formula_textbook": "W = one per driver + 0 per group:",
        "class": "The mechanism is of class {cls}: the highest class of its groups.",
    },
    "vi": {
        "title": "Cấu trúc và xếp loại cơ cấu: {name}",
        "mobility": "1. Bậc tự do",
        "formula_intro": "Bậc tự do cơ cấu được tính theo công thức",
        "n": "n = {n} khâu động ({links}); giá {ground} không tính",
        "p5": "P5 = {p5} khớp thấp loại 5: {r} khớp quay (R), {p} khớp tịnh tiến (P)",
        "compound": (
            "khớp quay kép {point} nối {k} khâu ({links}): tính là {k} − 1 = {pairs} khớp quay"
        ),
        "p4": "P4 = {p4} khớp cao loại 4: {pairs}",
        "p4_none": "P4 = 0: không có khớp cao",
        "cam": "khớp cam",
        "gear": "khớp bánh răng",
        "r_none": "r_th = 0: không có ràng buộc trùng",
        "r": "r_th = {r} ràng buộc trùng:",
        "r_structural": (
            "{k} tại khớp {pair}{line}: một chuỗi con có nhiều ràng buộc hơn số khâu của nó cho "
            "phép (đếm theo cấu trúc)"
        ),
        "r_geometric": (
            "{k} tại khớp {pair}{line}: kích thước làm một ràng buộc lặp lại (hạng ma trận Jacobi "
            "tại vị trí đang xét)"
        ),
        "line": " (dòng {line})",
        "w_none": "W_th = 0: không có bậc tự do thừa",
        "w": "W_th = {w} bậc tự do thừa:",
        "w_roller": "chuyển động quay của con lăn {link} quanh trục của nó",
        "w_geometric": "khâu {link} chuyển động riêng được ({k} bậc tự do, tại vị trí đang xét)",
        "substituted": "Thay số:",
        "note": "Ghi chú: {note}",
        "replacement": "2. Thay thế khớp cao",
        "replacement_intro": (
            "Vì có khớp cao nên ta phải thay thế khớp cao thành khớp thấp (đúng tại vị trí đang "
            "xét, cho vị trí, vận tốc và gia tốc): mỗi khớp cao thành một khâu thay thế với hai "
            "khớp thấp."
        ),
        "roller": (
            "bỏ con lăn {roller} cùng khớp {pair}: chuyển động quay của nó là bậc tự do thừa; "
            "điểm tiếp xúc chuyển về tâm con lăn {axis}, một điểm của khâu {follower}"
        ),
        "replace_rr": (
            "{pair} ({what}) → khâu thay thế {v} với {new}: khớp quay tại tâm cong của hai biên "
            "dạng"
        ),
        "replace_rp": (
            "{pair} ({what}) → khâu thay thế {v} với {new}: biên dạng của khâu {flat} tại chỗ tiếp "
            "xúc là phẳng nên phía đó thay bằng khớp tịnh tiến"
        ),
        "replaced_counts": (
            "Bậc tự do cơ cấu thay thế: n = {n}, P5 = {p5}, P4 = 0; không còn bậc tự do thừa "
            "(W_th = 0):"
        ),
        "unchanged": "W không đổi.",
        "drivers": "{k}. Khâu dẫn",
        "driver": "chọn khâu {link} là khâu dẫn, nối với giá bằng khớp {pair}",
        "driver_chosen": "(không ghi khâu dẫn: chọn trong các khâu nối với giá)",
        "w_drivers": "W = {w}: cơ cấu có {w} khâu dẫn.",
        "set_aside": (
            "khâu thừa {links} (khớp {pairs}) được bỏ ra trước khi tách nhóm (ràng buộc trùng)"
        ),
        "groups": "{k}. Tách nhóm tĩnh định (nhóm Assur), bắt đầu từ nhóm xa khâu dẫn nhất",
        "groups_intro": (
            "Mỗi nhóm là tập khâu nhỏ nhất có 3·n = 2·p (nhóm tĩnh định) nối vào phần còn lại; "
            "tách nhóm từ nhóm xa khâu dẫn nhất, còn khi giải thì đi theo thứ tự ngược lại."
        ),
        "no_groups": "Không có nhóm nào: cơ cấu chỉ gồm khâu dẫn và giá.",
        "group": "Nhóm {i}: {label}",
        "group_links": "khâu {links}: n = {n}",
        "group_pairs": "khớp: {pairs}: p = {p}",
        "outer": "khớp chờ",
        "inner": "khớp trong",
        "check": "3·n = 2·p:",
        "class_dyad": "nhóm loại 2: nhóm hai khâu ba khớp; bậc {order}; dạng {kind}",
        "class_base": (
            "nhóm loại {cls}: khâu {link} là khâu cơ sở có {k} khớp trong, không có chuỗi kín dài "
            "hơn; bậc {order}"
        ),
        "class_contour": "nhóm loại {cls}: có chuỗi động kín {k} khớp trong; bậc {order}",
        "attached": "nối vào khâu {links}",
        "remains": "Còn lại khâu dẫn {drivers} và giá {ground}: cơ cấu loại 1.",
        "formula": "{k}. Công thức cấu tạo và loại cơ cấu",
        "formula_groups": "Theo thứ tự giải (từ khâu dẫn):",
        "formula_textbook": "Công thức cấu tạo cơ cấu:",
        "class": "Đây là cơ cấu loại {cls} (loại cao nhất của các nhóm).",
    },
}
