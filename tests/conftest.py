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


#: the fixtures that the default run checks one by one where a test runs over every fixture
#: and each costs a drawing or a page: one of each kind (a four-bar, a slider, a slotted link, a
#: triad, a class IV group, two drivers, loads, a cam, gears, a long linkage); the others run
#: in the slow run (python -m pytest -m slow), as CI does
SAMPLE = (
    "ch1_1_10a_peaucellier",
    "cam_flat_follower",
    "cam_roller_follower",
    "ch3_3_4_fourbar",
    "ch3_3_7_sieve",
    "class4_group",
    "crank_slider",
    "eightbar_triad",
    "exam_1_slotted_link",
    "exam_2_planetary",
    "fivebar_two_drivers",
    "gear_pair",
    "jansen",
    "klann",
)


def sampled(stems: list, sample: tuple[str, ...] = SAMPLE, stem=lambda s: s) -> list:
    """``stems`` as parameters: those of ``sample`` in the default run, the rest slow.

    ``stem`` gives an item's fixture name (a path's ``.stem``).
    """
    return [
        pytest.param(item, id=stem(item), marks=() if stem(item) in sample else pytest.mark.slow)
        for item in stems
    ]


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
