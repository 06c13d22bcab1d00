"""The worked solution of the dynamics: its numbers are the solution's, in both languages."""

from __future__ import annotations

import re

import pytest

from kinematics.dynamics.analysis import machine_dynamics
from kinematics.explain.dynamics import PHRASES, explain_dynamics
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze

from ...conftest import FIXTURES


@pytest.fixture(scope="module")
def engine():
    report = analyze(read_edgelist(FIXTURES / "engine_three_crank.edges"))
    return machine_dynamics(report, delta=0.01)


def test_both_languages_have_every_phrase():
    assert PHRASES["en"].keys() == PHRASES["vi"].keys()


def test_the_flywheel_s_numbers_are_khurmi_s(engine):
    """ΔE = 12.2 kN·m; J = 12200/(0.01·(15π)²) = 549.386 in all, 189.386 more than 360."""
    text = explain_dynamics(engine)
    assert "ΔE_max = W_max − W_min = 12200 J" in text
    assert "= 549.386 kg·m²" in text
    found = re.search(r"J_F = \(A − B\)/\(k_max − k_min\) = .* = ([0-9.]+) kg·m²", text)
    assert found and float(found.group(1)) == pytest.approx(189.386, rel=1e-5)
    assert "δ = (ω_max − ω_min)/ω_m = 0.0152607" in text


def test_the_reduced_inertia_link_by_link():
    report = analyze(read_edgelist(FIXTURES / "press_flywheel.edges"))
    text = explain_dynamics(machine_dynamics(report, runs=False))
    # at the sketch the rod turns at −r/l = −0.25 of the crank, its centre moves at r/2 = 0.05
    assert "link 2: m·(v_S/ω1)² + J_S·(ω/ω1)² = 3·0.05² + 0.04·(-0.25)² = 0.01 kg·m²" in text
    assert "J_r(0) = 20.01 kg·m²" in text


@pytest.mark.parametrize("fmt", ["text", "markdown", "latex", "html"])
@pytest.mark.parametrize("lang", ["en", "vi"])
def test_every_format_and_language(engine, fmt: str, lang: str):
    text = explain_dynamics(engine, lang, fmt)
    assert text.endswith("\n") and ("bánh đà" in text) == (lang == "vi")
