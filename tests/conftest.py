"""Shared test helpers: the fixture directory, the expected-answer tables, pyslvs's sdist."""

from __future__ import annotations

from pathlib import Path

import pytest

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10: the same parser as a package
    import tomli as tomllib

from tests.pyslvs_sdist import (
    PYSLVS_VERSION,
    SDIST_DIR_VARIABLE,
    PyslvsSdist,
    download_sdist,
    read_sdist,
    sdist_dir,
)

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


@pytest.fixture(scope="session")
def pyslvs_sdist() -> PyslvsSdist:
    """pyslvs's own examples and published positions, read from its sdist.

    The sdist is looked for in ``$ASSUR_PYSLVS_SDIST_DIR`` (else ``.cache/pyslvs``)
    and downloaded there once when missing; without it the tests that need it skip
    (CI downloads it first, see .ci/run).
    """
    directory = sdist_dir()
    path, why = download_sdist(directory)
    if path is None:
        pytest.skip(
            f"needs the pyslvs {PYSLVS_VERSION} sdist in {directory} "
            f"(set {SDIST_DIR_VARIABLE} or run .ci/run online): {why}"
        )
    return read_sdist(path)
