"""Shared test helpers: the fixture directory and the expected-answer tables."""

from __future__ import annotations

from pathlib import Path

import pytest

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10: the same parser as a package
    import tomli as tomllib

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


STRUCTURE_TABLES = ("chapter1.toml", "classics.toml")
KINEMATICS_TABLE = "kinematics.toml"
FORCES_TABLE = "forces.toml"
GEARS_TABLE = "gears.toml"


def expected_table(names: tuple[str, ...] = STRUCTURE_TABLES) -> dict[str, dict]:
    """Expected answers from the named fixture tables, keyed by file stem."""
    table: dict[str, dict] = {}
    for name in names:
        path = FIXTURES / name
        if path.exists():
            with path.open("rb") as handle:
                table.update(tomllib.load(handle))
    return table


@pytest.fixture
def fixtures_dir() -> Path:
    return FIXTURES
