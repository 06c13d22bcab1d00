"""Tests of structure.parallel: the same rows in the same order locally and on Dask.

The Dask tests start a LocalCluster with two worker processes and compare its rows
with the local run's; they are skipped only when dask[distributed] is not installed
(it is in the ``test`` extra, so CI runs them).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from kinematics.cli.commands import main
from structure.atlas import atlas
from structure.batch import batch_items, classify_batch
from structure.parallel import (
    Counted,
    MissingExtraError,
    check_scheduler,
    local_cluster,
    ordered_map,
)

ROOT = Path(__file__).resolve().parents[2]
FIXTURE_FILES = sorted(str(p) for p in (ROOT / "fixtures").glob("*.edges"))


def _square(x: int) -> int:
    return x * x


def test_ordered_map_keeps_the_order_in_every_local_mode():
    expected = [x * x for x in range(50)]
    assert list(ordered_map(_square, range(50))) == expected
    assert list(ordered_map(_square, range(50), jobs=2, chunk=7)) == expected
    assert list(ordered_map(_square, [], jobs=2)) == []


def test_dask_missing_is_a_clear_message(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    with pytest.raises(MissingExtraError, match=r"pip install 'assur\[dask\]'"):
        list(ordered_map(_square, range(3), dask_local=2))
    assert main(["atlas", "--links", "4", "--dask-local", "2"]) == 2
    assert "assur[dask]" in capsys.readouterr().err


@pytest.fixture(scope="module")
def scheduler():
    distributed = pytest.importorskip("dask.distributed")
    cluster = distributed.LocalCluster(
        n_workers=2,
        threads_per_worker=1,
        processes=True,
        host="127.0.0.1",
        dashboard_address="127.0.0.1:0",
    )
    try:
        yield cluster.scheduler_address
    finally:
        cluster.close()


def test_dask_atlas_rows_equal_the_local_rows(scheduler):
    local = list(atlas(8))
    assert list(atlas(8, scheduler=scheduler)) == local
    assert list(atlas(7, 2, labelled=True, scheduler=scheduler)) == list(atlas(7, 2, labelled=True))


def test_dask_batch_rows_equal_the_local_rows(scheduler):
    items = list(batch_items(FIXTURE_FILES))
    assert list(classify_batch(items, scheduler=scheduler)) == list(classify_batch(items))


def test_dask_local_cluster_from_the_command_line(capsys):
    pytest.importorskip("dask.distributed")
    assert main(["atlas", "--links", "6"]) == 0
    local = capsys.readouterr().out
    assert main(["atlas", "--links", "6", "--dask-local", "2"]) == 0
    assert capsys.readouterr().out == local


def test_local_cluster_has_every_worker_up_and_large_tasks_keep_the_order():
    distributed = pytest.importorskip("dask.distributed")
    items = list(batch_items(FIXTURE_FILES)) * 3  # several items per task
    with local_cluster(2) as address:
        with distributed.Client(address) as client:
            assert len(client.scheduler_info()["workers"]) == 2
        assert list(classify_batch(items, scheduler=address)) == list(classify_batch(items))
        assert list(ordered_map(_square, range(101), scheduler=address)) == [
            x * x for x in range(101)
        ]


# ------------------------------------------------------------------ issue 22, item 7
@pytest.mark.parametrize(
    "address",
    ["garbage", "tcp://host", "tcp://host:99999", "host:8786x", "http://host:8786", "tcp://:8786"],
)
@pytest.mark.parametrize(
    "command", [["classify", "fixtures/fourbar.edges"], ["atlas", "--links", "6"]]
)
def test_a_bad_scheduler_address_is_a_usage_error_naming_the_form(capsys, command, address):
    """``--scheduler garbage`` ended with exit 3 (ValueError from Dask)."""
    assert main([*command, "--scheduler", address]) == 2
    err = capsys.readouterr().err
    assert f"--scheduler {address!r} is not a Dask scheduler's address" in err
    assert "tcp://HOST:PORT" in err


@pytest.mark.parametrize(
    "address", ["tcp://10.0.0.5:8786", "tls://scheduler.example.org:8786", "[::1]:8786", "h:1"]
)
def test_good_scheduler_addresses_pass(address):
    assert check_scheduler(address) == address


def test_items_made_lazily_keep_their_order_in_processes():
    made: list[int] = []

    def items():
        for k in range(40):
            made.append(k)
            yield k

    assert list(ordered_map(abs, Counted(items(), 40), jobs=2, chunk=3)) == list(range(40))
    assert made == list(range(40))
