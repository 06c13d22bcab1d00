"""``--json`` of a large mechanism: compact, streamed, and the same data as the dict (issue 11)."""

from __future__ import annotations

import io
import json

from structure import analyze
from structure.generators import random_mechanism_with_groups
from structure.readwrite.reports import LARGE_REPORT, report_to_dict, write_report_json


def test_large_report_is_compact_and_complete() -> None:
    m, _ = random_mechanism_with_groups(LARGE_REPORT + 1, seed=3, compound=0.2)
    report = analyze(m)
    out = io.StringIO()
    write_report_json(report, out)
    text = out.getvalue()
    assert text.endswith("}\n") and text.count("\n") == 1  # compact: one line
    assert json.loads(text) == json.loads(json.dumps(report_to_dict(report)))


def test_small_report_is_indented_as_before() -> None:
    m, _ = random_mechanism_with_groups(9, seed=3)
    report = analyze(m)
    out = io.StringIO()
    write_report_json(report, out)
    assert out.getvalue() == json.dumps(report_to_dict(report), indent=2, ensure_ascii=False) + "\n"
