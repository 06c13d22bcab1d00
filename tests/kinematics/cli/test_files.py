"""The files the command line reads and writes: issue 22, items 6 and 18.

No command writes over a file it reads (by resolved path or inode), two outputs
of one run are never one file, every output is written whole or not at all,
and only regular files under ``--max-file-size`` are read.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from .conftest import FIXTURES, run


@pytest.fixture
def work(tmp_path, monkeypatch) -> Path:
    """A folder with the four-bar as ``m.edges`` and its poses as ``poses.txt``, as the cwd."""
    shutil.copy(FIXTURES / "fourbar.edges", tmp_path / "m.edges")
    (tmp_path / "poses.txt").write_text("0\n30\n60\n", encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def _untouched(work: Path) -> None:
    assert (work / "m.edges").read_bytes() == (FIXTURES / "fourbar.edges").read_bytes()
    assert (work / "poses.txt").read_text(encoding="utf-8") == "0\n30\n60\n"
    assert not [p.name for p in work.iterdir() if p.name.startswith(".")]  # no temporary left


@pytest.mark.parametrize(
    "argv",
    [
        ["report", "m.edges", "-o", "m.edges"],
        ["report", "m.edges", "-o", "./sub/../m.edges"],
        ["convert", "m.edges", "m.edges"],
        ["convert", "m.edges", "poses.csv", "--inputs", "poses.csv"],
        ["convert", "m.edges", "m.json", "--inputs", "m.json"],
        ["classify", "m.edges", "--plot", "m.edges"],
        ["classify", "m.edges", "poses.txt", "-o", "poses.txt"],
        ["classify", ".", "--format", "csv", "-o", "m.edges"],
        ["kinematics", "m.edges", "--plot", "m.edges"],
        ["forces", "m.edges", "--plot", "m.edges"],
        ["sweep", "m.edges", "--csv", "m.edges"],
        ["sweep", "m.edges", "--inputs", "poses.txt", "--csv", "poses.txt"],
        ["sweep", "m.edges", "--csv", "a.svg", "--plot", "a.svg"],
        ["animate", "m.edges", "m.edges"],
        ["animate", "m.edges", "out.gif", "--inputs", "out.gif"],
    ],
    ids=lambda argv: " ".join(argv),
)
def test_no_command_writes_over_a_file_it_reads(capsys, work, argv):
    (work / "sub").mkdir()
    code, out, err = run(capsys, *argv)
    assert code == 2, err
    assert out == ""
    assert "a file this command reads" in err or "are the same file" in err
    _untouched(work)


def test_a_report_named_after_its_own_input_is_refused(capsys, work):
    """The issue's reproducer: ``assur report m.html`` wrote the page over m.html."""
    shutil.copy(work / "m.edges", work / "m.html")
    code, _, err = run(capsys, "report", "m.html")
    assert code == 2 and "the page m.html is m.html, a file this command reads" in err
    assert (work / "m.html").read_bytes() == (FIXTURES / "fourbar.edges").read_bytes()


def test_a_hard_link_and_a_symbolic_link_are_the_same_file(capsys, work):
    os.link(work / "m.edges", work / "hard.edges")
    (work / "soft.json").symlink_to(work / "m.edges")
    for target in ("hard.edges", "soft.json"):
        code, _, err = run(capsys, "convert", "m.edges", target)
        assert code == 2 and "a file this command reads" in err
    _untouched(work)


def test_a_failed_write_leaves_the_old_file(capsys, work):
    (work / "out.pyslvs").write_text("old\n", encoding="utf-8")
    shutil.copy(FIXTURES / "gear_pair.edges", work / "gears.edges")
    code, _, err = run(capsys, "convert", "gears.edges", "out.pyslvs")
    assert code == 1 and "pyslvs has no higher pair" in err
    assert (work / "out.pyslvs").read_text(encoding="utf-8") == "old\n"
    code, _, err = run(capsys, "convert", "m.edges", str(work / "no" / "m.json"))
    assert code == 1 and "cannot write" in err and "No such file or directory" in err
    _untouched(work)


def test_outputs_replace_their_file_whole(capsys, work):
    (work / "old.json").write_text("x" * 100_000, encoding="utf-8")
    assert run(capsys, "convert", "m.edges", "old.json")[0] == 0
    assert (work / "old.json").read_text(encoding="utf-8").startswith("{")
    assert run(capsys, "sweep", "m.edges", "--steps", "4", "--csv", "s.csv")[0] == 0
    assert len((work / "s.csv").read_text(encoding="utf-8").splitlines()) == 5
    _untouched(work)


@pytest.mark.parametrize(
    "argv",
    [
        ["classify", "{fifo}"],
        ["kinematics", "{fifo}"],
        ["convert", "{fifo}", "x.json"],
        ["report", "{fifo}", "-o", "x.html"],
        ["sweep", "m.edges", "--inputs", "{fifo}"],
        ["classify", "{zero}"],
        ["convert", "{zero}", "x.json"],
        ["gears", "{zero}"],
    ],
    ids=lambda argv: " ".join(argv),
)
def test_only_regular_files_are_read(capsys, work, argv):
    os.mkfifo(work / "pipe.edges")
    (work / "zero.edges").symlink_to("/dev/zero")
    filled = [a.format(fifo="pipe.edges", zero="zero.edges") for a in argv]
    code, _, err = run(capsys, *filled)
    assert code == 1
    assert "not a regular file" in err and "assur reads regular files only" in err


def test_max_file_size_names_the_limit_and_raises_it(capsys, work):
    size = (work / "m.edges").stat().st_size
    code, _, err = run(capsys, "classify", "m.edges", "--max-file-size", "100")
    assert code == 1
    assert f"the file is {size} bytes, more than the 100 bytes assur reads" in err
    assert "--max-file-size" in err
    assert run(capsys, "classify", "m.edges", "--max-file-size", "1MB")[0] == 0
    code, _, err = run(capsys, "classify", "m.edges", "--max-file-size", "lots")
    assert code == 2 and "'lots' is not a size" in err
    # a limit beyond what one read can take is no limit (was an OverflowError, exit 3)
    huge = "9" * 30
    assert run(capsys, "convert", "m.edges", "m.json", "--max-file-size", huge)[0] == 0
    assert run(capsys, "classify", "m.json", "m.edges", "--max-file-size", huge)[0] == 0


def test_atlas_writes_through_a_partial_file_that_resume_continues(capsys, work):
    whole = work / "whole.jsonl"
    assert run(capsys, "atlas", "--links", "8", "-o", str(whole))[0] == 0
    assert sorted(p.name for p in work.iterdir() if "whole" in p.name) == ["whole.jsonl"]
    data = whole.read_bytes()
    # a stopped run leaves its rows in the partial file, and no table at the name asked for
    (work / ".resumed.jsonl.partial").write_bytes(data[: len(data) // 2])
    assert not (work / "resumed.jsonl").exists()
    assert run(capsys, "atlas", "--links", "8", "-o", "resumed.jsonl", "--resume")[0] == 0
    assert (work / "resumed.jsonl").read_bytes() == data
    assert not (work / ".resumed.jsonl.partial").exists()


def test_atlas_resume_from_a_device_is_refused(capsys):
    """``atlas --resume -o /dev/full`` read /dev/full for ever (MemoryError, exit 3)."""
    code, _, err = run(capsys, "atlas", "--links", "6", "--resume", "-o", "/dev/full")
    assert code == 1 and "/dev/full: not a regular file (a character device)" in err
    code, _, err = run(capsys, "atlas", "--links", "6", "-o", "/dev/full")
    assert code == 1 and "cannot write /dev/full: No space left on device" in err
