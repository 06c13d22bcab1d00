"""Helpers of the report tests: every fixture's report made once a session, the CLI's JSON answers.

The reports are written by the command line (``assur report FILE -o OUT``) into a
session directory, at most once per fixture and language; :func:`all_reports`
makes all of them at once, on two processes where the machine has them.
"""

from __future__ import annotations

import contextlib
import io
import json
import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor
from functools import cache
from pathlib import Path
from typing import Any

import pytest

from kinematics.cli.commands import main
from structure.readwrite.edgelist import read_edgelist

from ...conftest import FIXTURES

#: poses per turn in the tests' reports (the command's default is 120)
STEPS = 24
STEMS = sorted(path.stem for path in FIXTURES.glob("*.edges"))
#: the fixtures with point coordinates: their reports draw, solve and animate
SKETCHED = [stem for stem in STEMS if read_edgelist(str(FIXTURES / f"{stem}.edges")).points]
SECTION_IDS = [
    "mechanism",
    "structure",
    "kinematics",
    "forces",
    "cycle",
    "gears",
    "cams",
    "dynamics",
    "synthesis",
    "worked",
]
def run_cli(*argv: str) -> tuple[int, str, str]:
    """One run of ``assur`` in this process: exit code, stdout, stderr."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


def write_report(job: tuple[str, str, str]) -> tuple[str, int, str]:
    """Write one report with the command line: (source, output, lang) -> (output, code, stderr)."""
    source, output, lang = job
    code, _, err = run_cli("report", source, "-o", output, "--steps", str(STEPS), "--lang", lang)
    return output, code, err


@cache
def cli_json(command: str, stem: str) -> Any:
    """``assur COMMAND FIXTURE --json``, parsed (an error answer is ``{"error": ...}``)."""
    _, out, _ = run_cli(command, str(FIXTURES / f"{stem}.edges"), "--json")
    return json.loads(out)


def json_at(data: Any, path: str) -> Any:
    """The value at ``a/b/0`` in a JSON answer (list indices as numbers)."""
    for key in path.split("/"):
        data = data[int(key)] if isinstance(data, list) else data[key]
    return data


class Reports:
    """The reports of the session, made on demand and kept in ``directory``."""

    def __init__(self, directory: Path) -> None:
        self.directory = directory
        self.made: dict[tuple[str, str], Path] = {}

    def _job(self, stem: str, lang: str) -> tuple[str, str, str]:
        return str(FIXTURES / f"{stem}.edges"), str(self.directory / f"{stem}.{lang}.html"), lang

    def _keep(self, stem: str, lang: str, result: tuple[str, int, str]) -> Path:
        output, code, err = result
        assert code == 0, f"assur report {stem} --lang {lang} failed: {err}"
        self.made[stem, lang] = Path(output)
        return Path(output)

    def path(self, stem: str, lang: str = "en") -> Path:
        """The report of fixture ``stem`` in ``lang``, made now if not yet."""
        if (stem, lang) not in self.made:
            self._keep(stem, lang, write_report(self._job(stem, lang)))
        return self.made[stem, lang]

    def page(self, stem: str, lang: str = "en") -> str:
        return self.path(stem, lang).read_text(encoding="utf-8")

    def make(self, stems: list[str], lang: str = "en") -> None:
        """Make the reports of ``stems`` not made yet, on two processes when there are two cores."""
        todo = [stem for stem in stems if (stem, lang) not in self.made]
        workers = min(2, os.cpu_count() or 1, len(todo))
        if workers < 2:
            for stem in todo:
                self.path(stem, lang)
            return
        context = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(workers, mp_context=context) as pool:
            jobs = [self._job(stem, lang) for stem in todo]
            for stem, result in zip(todo, pool.map(write_report, jobs), strict=True):
                self._keep(stem, lang, result)


@pytest.fixture(scope="session")
def reports(tmp_path_factory) -> Reports:
    """The session's reports, each made when first asked for."""
    return Reports(tmp_path_factory.mktemp("reports"))


@pytest.fixture(scope="session")
def all_reports(request, reports: Reports) -> Reports:
    """The session's reports, the English ones of the collected tests' fixtures made at once.

    The tests parametrized by ``stem`` that ask for this fixture name the reports to
    make (all of them on a whole run, a few under ``-k``), in parallel.
    """
    wanted = {
        item.callspec.params["stem"]
        for item in request.session.items
        if "all_reports" in getattr(item, "fixturenames", ())
        and "stem" in getattr(getattr(item, "callspec", None), "params", {})
    }
    reports.make(sorted(wanted))
    return reports
