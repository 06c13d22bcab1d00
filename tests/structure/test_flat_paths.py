"""The flat-array paths of the structural analysis give the answers of the plain ones.

A large mechanism's constraint system, matching, irreducible blocks and block
patterns are handled as numpy arrays; a small one's were handled row by row.
Here the constraint system is checked against a row-by-row build of the
table in :mod:`structure.rigidity.constraints`, the bulk matching against
rows added one at a time, and the numpy block path of the generic rank
(forced on small systems) against the plain one, on random mechanisms of
every group kind, with compound pins, redundant pairs and singular loops.
"""

from __future__ import annotations

import dataclasses
import random
from pathlib import Path

import numpy as np
import pytest

import structure.assur as assur_module
import structure.model as model_module
import structure.rigidity.constraints as constraints_module
import structure.rigidity.rank as rank_module
from structure.assur import plan_groups
from structure.errors import MechanismError
from structure.generators import random_mechanism, random_mechanism_with_groups
from structure.kinds import PairKind
from structure.model import Mechanism, Pair
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze
from structure.rigidity.constraints import RowKind, constraint_system
from structure.rigidity.matching import Matcher, _set_keeps_order
from structure.rigidity.rank import generic_rank


def _mechanisms() -> list[Mechanism]:
    out = [random_mechanism_with_groups(8 + s, s, compound=0.4)[0] for s in range(25)]
    out += [random_mechanism(3 + s % 12, seed=s) for s in range(25)]
    for seed in range(15):  # extra R pairs: redundant rows, free units
        m = random_mechanism(4 + seed % 9, seed=seed)
        pairs = [
            (p.a, p.b, p.kind.value, p.point)
            + (({"angle": p.angle_deg},) if p.kind is PairKind.P else ())
            for p in m.pairs
        ]
        rng = random.Random(seed)
        for k in range(1 + seed % 3):
            a, b = rng.sample(list(m.links), 2)
            pairs.append((a, b, "R", f"X{k}"))
        out.append(Mechanism.from_pairs(pairs))
    # a loop of three P pairs (generically singular) hung on a crank
    loop = [("0", "1", "R", "A"), ("1", "2", "P", "B", {"angle": 10}),
            ("2", "3", "P", "C", {"angle": 80}), ("3", "1", "P", "D", {"angle": 140}),
            ("3", "0", "R", "E")]  # fmt: skip
    out.append(Mechanism.from_pairs(loop))
    return out


MECHANISMS = _mechanisms()


def _rows_one_by_one(m: Mechanism) -> list[tuple[RowKind, int, tuple[int, ...], int, str]]:
    """The pair rows as the table of the constraints module lists them, pair after pair."""
    links = m.moving_links
    pos = {x: 2 * i for i, x in enumerate(links)}
    pins: dict[str, int] = {}

    def body(x: str) -> tuple[int, ...]:
        return () if x == m.ground else (pos[x], pos[x] + 1)

    rows = []
    done: set[str] = set()
    for p in m.pairs:
        h = m.compound_hinges.get(p.point) if p.kind is PairKind.R and p.point else None
        if p.kind is PairKind.R and h is None:
            rows.append((RowKind.HINGE, 2, body(p.b) + body(p.a), p.id, ""))
        elif h is not None and h.point not in done:
            done.add(h.point)
            first: dict[str, int] = {}
            for pid in h.pairs:
                for x in m.pair(pid).links:
                    first.setdefault(x, pid)
            extra: tuple[int, ...] = ()
            if m.ground not in h.links:
                pins[h.point] = extra_pin = 2 * len(links) + len(pins)
                extra = (extra_pin,)
            for x in h.links:
                if x != m.ground:
                    rows.append((RowKind.PIN, 2, extra + body(x), first[x], x))
        elif p.kind is PairKind.P:
            angles = tuple(pos[x] + 1 for x in (p.b, p.a) if x != m.ground)
            rows.append((RowKind.SLIDE_ANGLE, 1, angles, p.id, ""))
            rows.append((RowKind.SLIDE, 1, body(p.b) + body(p.a), p.id, ""))
        elif p.kind is PairKind.H:
            rows.append((RowKind.CONTACT, 1, body(p.b) + body(p.a), p.id, ""))
    # newest unknowns first in every row
    return [(k, s, tuple(sorted(adj, reverse=True)), pid, x) for k, s, adj, pid, x in rows]


@pytest.mark.parametrize("numpy_from", [0, 1 << 30], ids=["numpy", "rows"])
@pytest.mark.parametrize("index", range(len(MECHANISMS)))
def test_constraint_system_is_the_table_row_by_row(index, numpy_from, monkeypatch):
    monkeypatch.setattr(constraints_module, "_NUMPY_PAIRS", numpy_from)
    m = MECHANISMS[index]
    s = constraint_system(m)
    got = list(zip(s.row_kind, s.row_size, s.row_adj, s.row_pair, s.row_link, strict=True))
    assert got == _rows_one_by_one(m)
    assert [u.size for u in s.unknowns] == s.unknown_sizes()
    assert s.n_scalar_unknowns == sum(u.size for u in s.unknowns)


@pytest.mark.parametrize("index", range(len(MECHANISMS)))
def test_bulk_matching_is_rows_added_one_by_one(index):
    m = MECHANISMS[index]
    s = constraint_system(m, m.driver_links or ("1",))
    one = Matcher(s.unknown_sizes())
    left: dict[int, int] = {}
    for r, (adj, size) in enumerate(zip(s.row_adj, s.row_size, strict=True)):
        got = one.add_row(adj, size)
        if got < size:
            left[r] = size - got
    bulk = Matcher(s.unknown_sizes())
    assert bulk.add_rows(s.adj_start, s.adj, s.row_size) == left
    assert list(bulk.assigned) == list(one.assigned)
    assert bulk.owners == one.owners
    # a matching: every unknown holds at most its capacity, every row at most its size
    assert all(len(rows) <= c for rows, c in zip(bulk.owners, bulk.cap, strict=True))
    assert all(len(a) <= k for a, k in zip(bulk.assigned, s.row_size, strict=True))


def _fields(a):
    return (a.dependent, a.rank, a.dof, a.free, a.blocks, list(a.assigned), a.method)


@pytest.mark.parametrize("index", range(len(MECHANISMS)))
def test_numpy_block_path_gives_the_plain_answers(index, monkeypatch):
    m = MECHANISMS[index]
    system = constraint_system(m, m.driver_links or ("1",))
    monkeypatch.setattr(rank_module, "_REGULAR_PATTERNS", {})
    monkeypatch.setattr(rank_module, "NUMPY_ROWS", 1 << 30)
    plain = _fields(generic_rank(system))
    remembered = dict(rank_module._REGULAR_PATTERNS)
    rank_module._REGULAR_PATTERNS.clear()
    monkeypatch.setattr(rank_module, "NUMPY_ROWS", 0)
    assert _fields(generic_rank(system)) == plain
    assert rank_module._REGULAR_PATTERNS == remembered


def test_the_p_loop_is_found_singular_by_both_paths(monkeypatch):
    system = constraint_system(MECHANISMS[-1], ("1",))
    found = []
    for threshold in (1 << 30, 0):
        monkeypatch.setattr(rank_module, "NUMPY_ROWS", threshold)
        analysis = generic_rank(system)
        # the slide angles of a closed loop sum to zero: the third (row 5, pair D) is implied
        # by the other two, which the matching cannot see and the block's determinant does.
        # Then 2 pivoted angles + 3 for link 2 - 5 independent P constraints = 0: the
        # chain is rigid, and the driver (row 8) is fixed already
        assert analysis.method == "dense"
        assert analysis.dependent == {5: 1, 8: 1}
        found.append(_fields(analysis))
    assert found[0] == found[1]


@pytest.mark.parametrize("index", range(len(MECHANISMS)))
def test_numpy_group_plan_gives_the_plain_plan(index, monkeypatch):
    m = MECHANISMS[index]
    drivers = m.driver_links or ("1",)
    plans = []
    for threshold in (1 << 30, 0):
        monkeypatch.setattr(assur_module, "NUMPY_ROWS", threshold)
        try:
            plan = plan_groups(m, drivers)
        except MechanismError as exc:
            plans.append(str(exc))
            continue
        plans.append((plan.members, plan.order, list(plan.edges), plan.removed_links))
    assert plans[0] == plans[1]


def _renumbered(m: Mechanism, seed: int) -> Mechanism:
    """``m`` with its pair ids shuffled (ids that are not positions)."""
    ids = [10 * k + 3 for k in range(len(m.pairs))]
    random.Random(seed).shuffle(ids)
    return Mechanism.from_pairs(
        [dataclasses.replace(p, id=i) for p, i in zip(m.pairs, ids, strict=True)],
        ground=m.ground,
        drivers=m.drivers,
    )


RENUMBERED = [_renumbered(m, s) for s, m in enumerate(MECHANISMS[:25])]


FIXTURES = sorted((Path(__file__).resolve().parents[2] / "fixtures").glob("*.edges"))


def _planned(m: Mechanism):
    """The plan of ``m`` (its higher pairs replaced) and each link's level, or None."""
    try:
        report = analyze(m)
    except MechanismError:
        return None
    d = report.decomposition
    plan = plan_groups(d.mechanism, d.drivers)
    level = {plan.mechanism.ground: -1, **dict.fromkeys(plan.drivers, -1)}
    for i, b in enumerate(plan.order):
        level.update(dict.fromkeys(plan.members[b], i))
    return plan, level


@pytest.mark.parametrize(
    "m", [*MECHANISMS, *RENUMBERED, *map(read_edgelist, FIXTURES)], ids=lambda m: m.source + m.name
)
def test_all_group_pairs_at_once_are_the_ones_group_by_group(m, monkeypatch):
    planned = _planned(m)
    if planned is None:
        return
    plan, level = planned
    groups = [plan.members[b] for b in plan.order]
    compound = dict(plan.mechanism.compound_hinges)
    one_by_one = [
        assur_module._group_pairs(plan.mechanism, links, level, i, compound)
        for i, links in enumerate(groups)
    ]
    for chunk in (4096, 3, 1):  # groups sorted out at a time, chunk boundaries included
        monkeypatch.setattr(assur_module, "_GROUP_CHUNK", chunk)
        found = assur_module._all_group_pairs(plan.mechanism, plan.drivers, groups, compound)
        assert list(found) == one_by_one


def test_group_pairs_at_once_need_every_link_placed_and_read_its_level():
    plan, level = _planned(random_mechanism_with_groups(300, 5, compound=0.3)[0])
    groups = [plan.members[b] for b in plan.order]
    compound = dict(plan.mechanism.compound_hinges)
    # a group left out: its links have no level, and the per-group path is taken
    assert (
        assur_module._all_group_pairs(plan.mechanism, plan.drivers, groups[:-1], compound) is None
    )
    levels = assur_module._LinkLevels(plan.mechanism, [level[x] for x in plan.mechanism.links])
    assert dict(levels) == level and len(levels) == len(level)


def _pin_rows_from_records(m: Mechanism, pins_start: int) -> tuple:
    """The compound-pin rows read from the pair records, file order first (by hand)."""
    number = {link: i for i, link in enumerate(m.moving_links)}
    keys, pair_ids, adjs, links, pins, done = [], [], [], [], [], set()
    for position, p in enumerate(m.pairs):
        if p.kind is not PairKind.R or p.point not in m.compound_hinges or p.point in done:
            continue
        done.add(p.point)
        h = m.compound_hinges[p.point]
        pin = () if m.ground in h.links else (pins_start + len(pins),)
        if pin:
            pins.append(h.point)
        for k, link in enumerate(x for x in h.links if x != m.ground):
            keys.append(position * constraints_module._ROW_STRIDE + k)
            pair_ids.append(next(q for q in h.pairs if link in m.pair(q).links))
            adjs.append((*pin, 2 * number[link] + 1, 2 * number[link]))
            links.append(link)
    return keys, pair_ids, adjs, links, tuple(pins)


@pytest.mark.parametrize("m", [*MECHANISMS, *RENUMBERED], ids=lambda m: m.name)
def test_compound_pin_rows_from_link_numbers_are_the_ones_from_records(m):
    rows = constraints_module._compound_rows(m, 2 * len(m.moving_links))
    assert (rows.key, rows.pair, rows.adj, rows.links, rows.pins) == _pin_rows_from_records(
        m, 2 * len(m.moving_links)
    )


@pytest.mark.parametrize("m", [*MECHANISMS, *RENUMBERED], ids=lambda m: m.name)
def test_pair_positions_and_compound_flags(m):
    ids = [p.id for p in m.pairs]
    picked = ids[::-2]
    assert m.pair_positions(picked).tolist() == [ids.index(i) for i in picked]
    for unknown in (max(ids) + 1, 0, -5):
        with pytest.raises(KeyError):
            m.pair_positions([ids[0], unknown])
    expected = [p.kind is PairKind.R and p.point in m.compound_hinges for p in m.pairs]
    assert m.at_compound_hinge().tolist() == expected


def test_pairs_at_each_link_as_flat_arrays_are_pairs_of():
    for m in [*MECHANISMS, *map(read_edgelist, FIXTURES)]:
        offsets, pairs, others = m.incidence()
        for k, link in enumerate(m.links):
            at = slice(offsets[k], offsets[k + 1])
            assert [m.pairs[i] for i in pairs[at]] == list(m.pairs_of(link))
            assert [m.links[j] for j in others[at]] == [p.other(link) for p in m.pairs_of(link)]
        assert m.link_numbers(reversed(m.links)).tolist() == list(range(len(m.links)))[::-1]


@pytest.mark.parametrize("index", range(len(MECHANISMS)))
def test_numpy_dag_edges_are_the_plain_ones(index, monkeypatch):
    m = MECHANISMS[index]
    monkeypatch.setattr(assur_module, "NUMPY_ROWS", 0)
    try:
        plan = plan_groups(m, m.driver_links or ("1",))
    except MechanismError:
        return
    assert isinstance(plan.edges, assur_module.Dependencies)
    numpy_edges = assur_module._dag_edges(plan.order, plan.edges)
    place = {b: i for i, b in enumerate(plan.order)}
    by_hand = sorted((place[u], place[v]) for u, v in plan.edges)
    assert numpy_edges == tuple(by_hand) == assur_module._dag_edges(plan.order, list(plan.edges))


def test_distinct_edges_are_the_set_of_edges_sorted():
    rng = np.random.default_rng(3)
    for size in (0, 1, 10, 1000, 20000):
        sources = rng.integers(0, 50, size).astype(np.int32)
        targets = rng.integers(0, 5000, size).astype(np.int32)
        whole = set(zip(sources.tolist(), targets.tolist(), strict=True))
        kept_sources, kept_targets = assur_module._distinct_edges(sources, targets)
        kept = list(zip(kept_sources.tolist(), kept_targets.tolist(), strict=True))
        assert kept == sorted(whole)


def test_the_order_of_a_set_of_two_ints_is_predicted():
    rng = random.Random(7)
    pairs = [
        (rng.randrange(1 << k), rng.randrange(1 << k)) for k in (3, 6, 12, 24) for _ in range(4000)
    ]
    pairs += [(a, a + 8 * d) for a in range(8) for d in range(1, 200)]  # same first slot
    pairs = [(a, b) for a, b in pairs if a != b]
    first = np.array([a for a, _ in pairs], dtype=np.int64)
    second = np.array([b for _, b in pairs], dtype=np.int64)
    predicted = _set_keeps_order(first, second).tolist()
    assert predicted == [tuple({a, b}) == (a, b) for a, b in pairs]


@pytest.mark.parametrize("index", range(len(MECHANISMS)))
def test_link_tables_grouped_by_numpy_and_by_rows_agree(index, monkeypatch):
    original = MECHANISMS[index]
    tables = []
    for threshold in (0, 1 << 30):
        monkeypatch.setattr(model_module, "_NUMPY_PAIRS", threshold)
        m = original.evolve(pairs=original.pairs)
        reached = m.connected_to_ground()
        tables.append([(x, [p.id for p in m.pairs_of(x)], x in reached) for x in m.links])
    assert tables[0] == tables[1]
    # each link's pairs are those that name it, in file order
    named = [[p.id for p in original.pairs if x in (p.a, p.b)] for x in original.links]
    assert [pairs for _, pairs, _ in tables[0]] == named


def test_links_off_ground_are_the_links_connected_to_ground_leaves_out():
    pairs = [("0", "1"), ("2", "3"), ("1", "4"), ("3", "5"), ("6", "0")]
    loose = Mechanism(tuple(Pair(k, PairKind.R, a, b) for k, (a, b) in enumerate(pairs, start=1)))
    for m in [loose, *MECHANISMS]:
        reach = m.connected_to_ground()
        assert m.links_off_ground() == [link for link in m.links if link not in reach]
    assert loose.links_off_ground() == ["2", "3", "5"]
