"""The memory bound of every option that sets a size (structure.limits), issue 22, item 20."""

from __future__ import annotations

import os

import pytest

from structure.errors import SizeError
from structure.limits import check_size, memory_limit, memory_text


def test_the_message_names_the_memory_the_limit_and_what_fits():
    with pytest.raises(SizeError) as info:
        check_size(
            5000, 1e6, "a sweep of 5000 poses", "ask for at most {fit} poses", limit=2 * 10**9
        )
    # 5000 poses of 1 MB: 5 GB; 2 GB fit 2000 of them
    assert str(info.value) == (
        "a sweep of 5000 poses would take about 5 GB of memory, more than the 2 GB a run may "
        "take (half of this machine's): ask for at most 2000 poses"
    )


def test_a_size_within_the_limit_passes_and_the_fixed_part_counts():
    check_size(2000, 1e6, "x", "y", limit=2 * 10**9)
    with pytest.raises(SizeError, match="at most 1000"):
        check_size(2000, 1e6, "x", "at most {fit}", fixed=1e9, limit=2 * 10**9)


def test_a_subclass_can_be_raised():
    class Mine(SizeError):
        pass

    with pytest.raises(Mine):
        check_size(3, 2, "x", "y", limit=5, error=Mine)


def test_the_limit_is_half_of_this_machine():
    total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    assert memory_limit() == total // 2
    assert memory_text(1.5e9) == "1.5 GB"
