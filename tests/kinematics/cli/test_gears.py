"""``assur gears``: a train with two inputs (issue 22, item 1), its JSON and its report page.

The reproducer is an open differential in its planar equivalent: the case c carries the planet
2 (z = 10), which meshes externally with the side gear 3 and internally with the side gear 4
(z = 20 both). Willis in the case's frame:

    10(ω2 − ωc) = −20(ω3 − ωc)  →  ω2 = 3ωc − 2ω3
    10(ω2 − ωc) = +20(ω4 − ωc)  →  ω4 = 2ωc − ω3   (the side gears' mean speed is the case's)

It used to end in exit 3 (``float()`` of a ratio that is an expression in two speeds).
"""

from __future__ import annotations

import json

from .conftest import run

DIFFERENTIAL = """name open differential (planar equivalent)
ground 0
0 c R O
0 3 R O
0 4 R O
c 2 R P
2 3 H gear z=10,20
2 4 H gear z=10,20 internal=4
driver c
driver 3
"""


def _file(tmp_path, text: str) -> str:
    path = tmp_path / "differential.edges"
    path.write_text(text, encoding="utf-8")
    return str(path)


def test_two_inputs_print_the_willis_relations(capsys, tmp_path):
    code, out, err = run(capsys, "gears", _file(tmp_path, DIFFERENTIAL))
    assert (code, err) == (0, "")
    assert "ω4 = 2·ωc − ω3" in out
    assert "ω2 = 3·ωc − 2·ω3" in out
    assert "give omega= on every driver line" in out


def test_two_inputs_json_carries_the_relations(capsys, tmp_path):
    code, out, _ = run(capsys, "gears", _file(tmp_path, DIFFERENTIAL), "--json")
    assert code == 0
    data = json.loads(out)
    assert "speed_ratio" not in data  # no single input to divide by
    relation = data["relations"]["4"]
    assert relation["text"] == "ω4 = 2·ωc − ω3"
    assert {x: k["exact"] for x, k in relation["coefficients"].items()} == {"c": "2", "3": "-1"}
    assert {x: k["exact"] for x, k in data["relations"]["2"]["coefficients"].items()} == {
        "c": "3",
        "3": "-2",
    }


def test_two_given_speeds_give_the_numbers(capsys, tmp_path):
    # ωc = 10, ω3 = 4: ω4 = 20 − 4 = 16, ω2 = 30 − 8 = 22. A load M4 = −20 on 4 is balanced
    # by virtual power, M_c·ωc + M_3·ω3 − 20·(2ωc − ω3) = 0 for every ωc, ω3: M_c = 40,
    # M_3 = −20
    text = DIFFERENTIAL.replace("driver c", "driver c omega=10").replace(
        "driver 3", "driver 3 omega=4"
    )
    path = _file(tmp_path, text + "moment 4 -20\n")
    code, out, _ = run(capsys, "gears", path, "--json")
    assert code == 0
    data = json.loads(out)
    speeds = {link: value["exact"] for link, value in data["speeds"].items()}
    assert speeds == {"c": "10", "3": "4", "4": "16", "2": "22"}
    moments = {x: value["exact"] for x, value in data["balancing_moments"].items()}
    assert moments == {"c": "40", "3": "-20"}
    code, out, _ = run(capsys, "gears", path)
    assert "4: 16 ≈ 16 rad/s" in out and "2: 22 ≈ 22 rad/s" in out
    assert "c: 40 ≈ 40 N·m" in out and "3: -20 ≈ -20 N·m" in out
    # with losses (η = 0.98): M_c = 20 + 20/η², M_3 = −20/η² (tests/kinematics/test_gears.py)
    code, out, _ = run(capsys, "gears", path, "--json", "--efficiency", "0.98")
    lossy = json.loads(out)["with_losses"]["balancing_moments"]
    assert abs(lossy["c"] - (20 + 20 / 0.98**2)) < 1e-9
    assert abs(lossy["3"] + 20 / 0.98**2) < 1e-9


def test_losses_of_two_inputs_ask_for_their_speeds(capsys, tmp_path):
    path = _file(tmp_path, DIFFERENTIAL + "moment 4 -20\n")
    code, out, err = run(capsys, "gears", path, "--efficiency", "0.98")
    assert (code, out) == (1, "")
    assert "give omega= on every driver line" in err
