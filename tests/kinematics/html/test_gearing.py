"""The report's gear-train section (kinematics.html.gearing) for a train with two inputs."""

from __future__ import annotations

import html
import re

from kinematics.html.gearing import gears_html, train_summary
from structure.readwrite.edgelist import parse_edgelist

from ..cli.test_gears import DIFFERENTIAL


def _text(section: str) -> str:
    return re.sub(r"\s+", " ", html.unescape(re.sub(r"<[^>]+>", " ", section)))


def test_the_report_of_a_differential_uses_its_moment_load():
    # issue 22, item 1: `moment 3 20` on the input 3 itself is balanced there alone, M_3 = −20,
    # and M_c = 0 (ωc does not move 3); the section used to say "No moment load"
    mechanism = parse_edgelist([*DIFFERENTIAL.splitlines(), "moment 3 20"])
    text = _text(gears_html(train_summary(mechanism), mechanism, "en"))
    assert "No moment load" not in text
    assert "balancing moment on input 3 (by power): -20" in text
    assert "balancing moment on input c (by power): 0" in text
    assert "ω4 = 2·ωc − ω3" in text and "ω2 = 3·ωc − 2·ω3" in text


def test_the_speeds_of_a_differential_are_tied_to_the_command_line():
    # ωc = 10, ω3 = 4 on the driver lines: ω4 = 16, ω2 = 22, each cell tied to `gears --json`
    text = DIFFERENTIAL.replace("driver c", "driver c omega=10").replace(
        "driver 3", "driver 3 omega=4"
    )
    mechanism = parse_edgelist(text.splitlines())
    section = gears_html(train_summary(mechanism), mechanism, "vi")
    tied = dict(re.findall(r'data-path="speeds/(\w+)/float" data-value="([^"]+)"', section))
    assert tied == {"c": "10.0", "3": "4.0", "4": "16.0", "2": "22.0"}
