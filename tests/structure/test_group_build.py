"""The fast paths of the group build and of the groups' JSON give what the plain forms give.

``classify_group`` skips the contour search for one joint, forests and rings:
it must agree with the definition (most joints on a link, longest contour) on
every shape. The compact ``--json`` writes the groups without building their
dicts: it must give the very text ``json.dumps`` gives of
:func:`~structure.readwrite.reports.report_to_dict`, names needing escapes
included.
"""

from __future__ import annotations

import dataclasses
import io
import itertools
import json
import random

import pytest

from structure import analyze
from structure.assur import GroupPair, _group_pair, classify_group
from structure.generators import random_mechanism_with_groups
from structure.kinds import PairKind
from structure.model import Mechanism
from structure.readwrite.reports import LARGE_REPORT, report_to_dict, write_report_json


def _longest_cycle(links: list[str], joints: list[tuple[str, ...]]) -> int:
    """Most joints on a simple cycle links ↔ joints, by trying every sequence of joints."""
    best = 0
    for size in range(2, len(joints) + 1):
        for chosen in itertools.permutations(range(len(joints)), size):
            if chosen[0] != min(chosen):
                continue
            # joint chosen[k] and chosen[k+1] share a link, each link used once
            for shared in itertools.product(links, repeat=size):
                ok = len(set(shared)) == size and all(
                    shared[k] in joints[chosen[k]] and shared[k] in joints[chosen[(k + 1) % size]]
                    for k in range(size)
                )
                if ok:
                    best = max(best, size)
                    break
    return best


def _class_by_definition(links: list[str], joints: list[tuple[str, ...]]) -> int:
    most = max((sum(x in j for j in joints) for x in links), default=0)
    return max(2, most, _longest_cycle(links, joints))


def _random_joints(rng: random.Random, links: list[str]) -> list[tuple[str, ...]]:
    joints = []
    for _ in range(rng.randint(0, 5)):
        size = 2 if rng.random() < 0.8 else 3
        joints.append(tuple(rng.sample(links, min(size, len(links)))))
    return joints


@pytest.mark.parametrize("seed", range(300))
def test_classify_group_agrees_with_the_definition(seed: int) -> None:
    rng = random.Random(seed)
    links = [f"L{i}" for i in range(rng.randint(2, 5))]
    joints = _random_joints(rng, links)
    assert classify_group(links, joints) == _class_by_definition(links, joints)


@pytest.mark.parametrize(
    ("links", "joints", "expected"),
    [
        (list("ab"), [], 2),
        (list("abc"), [("a", "b"), ("b", "c"), ("c", "a")], 3),  # a ring of three
        (list("abcd"), [("a", "b"), ("c", "d")], 2),  # two pieces, no contour
        (list("abcd"), [("a", "b"), ("b", "a"), ("c", "d"), ("d", "c")], 2),  # two rings of two
        (list("abcde"), [("a", "b"), ("b", "c"), ("c", "a"), ("c", "d"), ("d", "e")], 3),
    ],
)
def test_classify_group_shapes(links, joints, expected) -> None:
    assert classify_group(links, joints) == expected == _class_by_definition(links, joints)


def test_fast_group_pair_is_the_record() -> None:
    assert GroupPair.__slots__ == tuple(f.name for f in dataclasses.fields(GroupPair))
    for external, point in ((True, "B"), (False, None)):
        fast = _group_pair(PairKind.P, ("a", "b"), point, external, 7)
        plain = GroupPair(PairKind.P, ("a", "b"), point, external, 7)
        assert fast == plain and hash(fast) == hash(plain) and repr(fast) == repr(plain)
    assert _group_pair(PairKind.R, ("a", "b"), "C", True) == GroupPair(
        PairKind.R, ("a", "b"), "C", True
    )
    with pytest.raises(dataclasses.FrozenInstanceError):
        fast.point = "D"  # type: ignore[misc]


def _renamed(mechanism: Mechanism, rename) -> Mechanism:
    pairs = [
        dataclasses.replace(
            p, a=rename(p.a), b=rename(p.b), point=None if p.point is None else rename(p.point)
        )
        for p in mechanism.pairs
    ]
    drivers = [rename(d.link) for d in mechanism.drivers]
    return Mechanism.from_pairs(pairs, ground=rename(mechanism.ground), drivers=drivers)


def _compact(report) -> str:
    return json.dumps(report_to_dict(report), ensure_ascii=False, separators=(",", ":")) + "\n"


@pytest.mark.parametrize("compound", [0.0, 0.3])
def test_large_report_json_is_the_dumps_text(compound: float) -> None:
    m, _ = random_mechanism_with_groups(LARGE_REPORT + 1, seed=5, compound=compound)
    report = analyze(m)
    out = io.StringIO()
    write_report_json(report, out)
    assert out.getvalue() == _compact(report)


def test_large_report_json_escapes_names() -> None:
    m, _ = random_mechanism_with_groups(LARGE_REPORT + 1, seed=6, compound=0.2)
    odd = ['"', "\\", "é", "\t", "\u2028", "/", "\x01", "ö\u00a0"]
    m = _renamed(m, lambda name: f"{odd[sum(map(ord, name)) % len(odd)]}{name}")
    report = analyze(m)
    out = io.StringIO()
    write_report_json(report, out)
    text = out.getvalue()
    assert text == _compact(report)
    assert '\\"' in text and "\\\\" in text and "\\t" in text and "é" in text  # escaped
