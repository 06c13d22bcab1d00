"""Tests of the report's text and JSON forms (structure.readwrite.reports)."""

from __future__ import annotations

import importlib
import json

import pytest

import structure
from structure.readwrite import reports

MOVED = ["format_mobility_error", "format_report", "mobility_error_dict", "report_to_dict"]


@pytest.mark.parametrize("name", MOVED)
def test_old_path_still_works_with_a_deprecation_warning(name):
    old = importlib.import_module("structure.report")
    with pytest.warns(DeprecationWarning, match=f"structure.report.{name} is deprecated"):
        moved = getattr(old, name)
    assert moved is getattr(reports, name) is getattr(structure, name)


def test_report_module_keeps_the_analysis_only():
    old = importlib.import_module("structure.report")
    assert sorted(old.__all__) == ["DriverChoice", "StructuralReport", "all_driver_choices",
                                   "analyze"]  # fmt: skip
    with pytest.raises(AttributeError):
        old.no_such_name  # noqa: B018


def test_report_dict_holds_plain_strings():
    m = structure.parse_edgelist(["driver 1", "0 1 R A", "1 2 R B", "2 3 P C", "3 0 R D"])
    data = reports.report_to_dict(structure.analyze(m))
    kind = data["groups"][0]["kind"]
    assert type(kind) is str and kind == "RPR"
    assert json.loads(json.dumps(data)) == data
