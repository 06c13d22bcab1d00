"""Every option that sets a size has a bound that names the memory: issue 22, item 20.

Each size beyond the bound is refused before any work, in one message that names
the memory it would take, the memory a run may take and the largest size that fits
(structure.limits.check_size), as ``sweep --steps`` always had.
"""

from __future__ import annotations

import re
import time

import pytest

import structure.limits
from kinematics.solvers import sweep as sweep_module
from structure.limits import memory_limit

from .conftest import fixture, run

_MEMORY = re.compile(
    r"would take about [\d.e+]+ [kMGT]?B of memory, more than the [\d.]+ [kMGT]?B a run may "
    r"take \(half of this machine's\): "
)


@pytest.mark.parametrize(
    ("argv", "asks"),
    [
        (["sweep", fixture("fourbar"), "--steps", "1000000000000"], "poses (steps=, --steps"),
        (["convert", fixture("fourbar"), "x.csv", "--steps", "1000000000000"], "--steps"),
        (["animate", fixture("fourbar"), "x.gif", "--steps", "10000000"], "frames (--steps"),
        (["report", fixture("fourbar"), "-o", "x.html", "--steps", "1000000000000"], "(--steps)"),
        (["atlas", "--links", "16"], "ask for at most 14 links"),
        (["atlas", "--links", "14", "--summary"], "leave out --summary"),
        (["atlas", "--links", "6", "--jobs", "1000000"], "--jobs"),
        (["atlas", "--links", "6", "--dask-local", "1000000"], "--dask-local"),
        (["classify", fixture("fourbar"), fixture("fourbar"), "--jobs", "1000000"], "--jobs"),
    ],
    ids=lambda value: " ".join(value) if isinstance(value, list) else None,
)
def test_a_size_beyond_memory_is_refused_at_once_naming_the_memory(
    capsys, tmp_path, monkeypatch, argv, asks
):
    monkeypatch.chdir(tmp_path)
    started = time.monotonic()
    code, out, err = run(capsys, *argv)
    assert time.monotonic() - started < 20
    assert code == 1 and out == ""
    assert _MEMORY.search(err), err
    assert asks in err
    assert list(tmp_path.iterdir()) == []  # refused before any file was written


def test_absurd_link_counts_end_at_once(capsys):
    started = time.monotonic()
    code, _, err = run(capsys, "atlas", "--links", "1000000000000000")
    assert code == 1 and "more than 10^15 chains" in err
    code, _, err = run(capsys, "atlas", "--links", "1000000000000000", "--count")
    assert code == 1 and "CPU-days" in err
    code, _, err = run(capsys, "atlas", "--links", "18", "--count")
    assert code == 1 and "ask for at most 16 links" in err
    code, _, err = run(capsys, "atlas", "--links", "9" * 20, "--dof", "1" + "0" * 11, "--count")
    assert code == 1 and "no chain of F = 100000000000 is that quick" in err
    code, _, err = run(capsys, "atlas", "--links", "4-100000")
    assert code == 2 and "a range spans at most 100 link counts" in err
    assert time.monotonic() - started < 20


def test_the_poses_of_an_inputs_file_are_bounded_as_they_are_read(capsys, tmp_path, monkeypatch):
    """The poses are counted while the file is read, not kept once they are too many."""
    limit = 100_000
    monkeypatch.setattr(structure.limits, "memory_limit", lambda: limit)
    monkeypatch.setattr(sweep_module, "memory_limit", lambda: limit)
    poses = tmp_path / "poses.txt"
    poses.write_text("".join(f"{k}\n" for k in range(2000)), encoding="utf-8")
    code, _, err = run(capsys, "sweep", fixture("fourbar"), "--inputs", str(poses))
    assert code == 1
    assert f"the 2000 poses of {poses} would take about" in err
    assert "more than the 100 kB a run may take" in err


@pytest.mark.parametrize(
    ("out", "fps", "says"),
    [
        ("x.gif", "1000", "a GIF plays 0.00153 to 50 frames per second"),
        ("x.gif", "0", "a GIF plays"),
        ("x.mp4", "1e6", "a MP4 plays 0.01 to 240 frames per second"),
    ],
)
def test_frame_rates_a_format_cannot_play_are_usage_errors(capsys, tmp_path, out, fps, says):
    code, _, err = run(capsys, "animate", fixture("fourbar"), str(tmp_path / out), "--fps", fps)
    assert code == 2 and says in err
    assert list(tmp_path.iterdir()) == []


def test_the_bound_is_half_of_this_machine():
    assert memory_limit() > 10**8
