"""Shared test helpers: the fixture directory and the expected-answer tables."""

from __future__ import annotations

from pathlib import Path

import pytest
import tomllib

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def expected_table() -> dict[str, dict]:
    """Every fixture's expected answers from fixtures/*.toml, keyed by file stem."""
    table: dict[str, dict] = {}
    for path in sorted(FIXTURES.glob("*.toml")):
        with path.open("rb") as handle:
            table.update(tomllib.load(handle))
    return table


@pytest.fixture
def fixtures_dir() -> Path:
    return FIXTURES
