"""Reading the files a user names (structure.readwrite.textfile), issue 22, item 6.

Only regular files are read, under a size limit that the message names with the
option that raises it; a FIFO is refused without being opened (it would wait for
a writer for ever), a link to a device by what it points to.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path

import pytest

from structure.errors import EdgeListError
from structure.readwrite.edgelist import read_edgelist
from structure.readwrite.formats import read_mechanism
from structure.readwrite.textfile import (
    MAX_FILE_BYTES,
    MAX_FILE_OPTION,
    file_problem,
    open_user_file,
    read_text,
)

from ..conftest import FIXTURES

FOURBAR = FIXTURES / "fourbar.edges"


@pytest.fixture
def fifo(tmp_path) -> Path:
    path = tmp_path / "pipe.edges"
    os.mkfifo(path)
    return path


def _refused(reader, path, reason: str) -> None:
    with pytest.raises(EdgeListError) as info:
        reader(path)
    assert info.value.source == str(path)
    assert reason in info.value.reason, info.value.reason


@pytest.mark.parametrize("reader", [read_text, read_edgelist, read_mechanism])
def test_a_fifo_is_refused_without_waiting(fifo, reader):
    done = threading.Event()
    outcome: list[BaseException] = []

    def read() -> None:
        try:
            reader(fifo)
        except BaseException as exc:
            outcome.append(exc)
        done.set()

    threading.Thread(target=read, daemon=True).start()
    if not done.wait(10):
        with open(fifo, "w"):  # let the reader go before failing
            pass
        pytest.fail("reading a FIFO waited for a writer")
    assert isinstance(outcome[0], EdgeListError)
    assert "not a regular file (a FIFO)" in outcome[0].reason


@pytest.mark.parametrize("reader", [read_text, read_edgelist, read_mechanism])
def test_a_link_to_a_device_is_refused(tmp_path, reader):
    link = tmp_path / "zero.edges"
    link.symlink_to("/dev/zero")
    _refused(reader, link, "not a regular file (a character device)")


def test_a_file_over_the_limit_is_refused_by_its_size_with_the_option(tmp_path):
    path = tmp_path / "big.edges"
    path.write_text(FOURBAR.read_text(encoding="utf-8"), encoding="utf-8")
    size = path.stat().st_size
    with pytest.raises(EdgeListError) as info:
        read_edgelist(path, max_bytes=size - 1)
    assert f"the file is {size} bytes" in info.value.reason
    assert f"more than the {size - 1} bytes assur reads" in info.value.reason
    assert MAX_FILE_OPTION in info.value.reason
    assert read_edgelist(path, max_bytes=size).name == read_edgelist(FOURBAR).name


def test_the_default_limit_holds_a_million_line_edge_list():
    # a 10^6-line edge list is about 26 MB (benchmarks/classify_memory.py)
    assert MAX_FILE_BYTES >= 26_300_000


def test_missing_directories_and_not_utf8_keep_their_messages(tmp_path):
    _refused(read_text, tmp_path / "none.edges", "cannot read: No such file or directory")
    _refused(read_text, tmp_path, "cannot read: Is a directory")
    binary = tmp_path / "b.edges"
    binary.write_bytes(b"\xff\xfe\x00")
    _refused(read_edgelist, binary, "not a UTF-8 text file")


def test_file_problem_judges_without_opening(fifo, tmp_path):
    assert file_problem(FOURBAR) is None
    assert "FIFO" in file_problem(fifo)
    assert "No such file" in file_problem(tmp_path / "none")
    assert file_problem(FOURBAR, max_bytes=10).startswith("the file is")


def test_a_regular_file_streams_its_lines(tmp_path):
    with open_user_file(FOURBAR) as handle:
        assert next(iter(handle)).startswith("#")
