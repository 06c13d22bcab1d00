"""Writing files whole or not at all (structure.readwrite.atomic), issue 22, item 18."""

from __future__ import annotations

import os
import stat

import pytest

from structure.errors import MechanismError
from structure.readwrite.atomic import atomic_file, atomic_path, partial_path, write_text


def _names(folder) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


def test_a_write_that_fails_leaves_the_old_file_and_no_temporary(tmp_path):
    target = tmp_path / "m.edges"
    target.write_text("old\n", encoding="utf-8")
    with pytest.raises(RuntimeError), atomic_file(target) as handle:
        handle.write("half of the new")
        raise RuntimeError("the writer crashed")
    assert target.read_text(encoding="utf-8") == "old\n"
    assert _names(tmp_path) == ["m.edges"]


def test_an_interrupt_leaves_no_half_file(tmp_path):
    target = tmp_path / "m.svg"
    with pytest.raises(KeyboardInterrupt), atomic_path(target) as temporary:
        temporary.write_text("<svg")
        raise KeyboardInterrupt
    assert _names(tmp_path) == []


def test_a_path_writer_sees_the_targets_extension(tmp_path):
    with atomic_path(tmp_path / "anim.gif") as temporary:
        assert temporary.suffix == ".gif" and temporary.parent == tmp_path
        assert temporary.name.startswith(".anim.")
        temporary.write_bytes(b"GIF89a")
    assert (tmp_path / "anim.gif").read_bytes() == b"GIF89a"


def test_the_targets_permissions_are_kept_and_a_new_file_gets_the_umasks(tmp_path):
    target = tmp_path / "kept.edges"
    target.write_text("old", encoding="utf-8")
    os.chmod(target, 0o640)
    write_text(target, "new")
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    umask = os.umask(0o022)
    os.umask(umask)
    fresh = write_text(tmp_path / "fresh.edges", "x")
    assert stat.S_IMODE(fresh.stat().st_mode) == 0o666 & ~umask


def test_a_link_is_written_through(tmp_path):
    real = tmp_path / "real.edges"
    real.write_text("old", encoding="utf-8")
    link = tmp_path / "link.edges"
    link.symlink_to(real)
    write_text(link, "new")
    assert link.is_symlink() and real.read_text(encoding="utf-8") == "new"


def test_a_device_is_written_in_place():
    write_text(os.devnull, "nothing")
    assert os.path.exists(os.devnull) and not os.path.isfile(os.devnull)


def test_a_full_disk_is_a_named_error():
    with pytest.raises(MechanismError, match="cannot write /dev/full: No space left on device"):
        write_text("/dev/full", "x" * 100_000)


def test_a_missing_directory_is_a_named_error(tmp_path):
    with pytest.raises(MechanismError, match=r"cannot write .*: No such file or directory"):
        write_text(tmp_path / "no" / "m.edges", "x")


def test_a_partial_file_is_kept_for_a_later_run_and_renamed_when_complete(tmp_path):
    target = tmp_path / "atlas.jsonl"
    with pytest.raises(RuntimeError), atomic_file(target, partial=True) as handle:
        handle.write("row 1\n")
        raise RuntimeError("stopped")
    partial = partial_path(target)
    assert not target.exists() and partial.read_text(encoding="utf-8") == "row 1\n"
    with atomic_file(target, "a", partial=True) as handle:
        handle.write("row 2\n")
    assert target.read_text(encoding="utf-8") == "row 1\nrow 2\n" and not partial.exists()
