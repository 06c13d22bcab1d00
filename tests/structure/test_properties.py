"""Property tests: random mechanisms built from known Assur groups (structure.generators).

The generator attaches minimal groups one after another to known links, so a
correct analysis must give back exactly those groups, in an order compatible
with how they hang on each other, whatever the listing or the naming.

Every test runs twice: with the dyad kinds RRR, RRP, RPR, PRP plus triads and
class IV groups, and with all kinds (RPP dyads included), so that a failure
specific to RPP dyads shows up in the test id.
"""

from __future__ import annotations

import itertools
import random
from functools import lru_cache

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from networkx.utils import UnionFind as NetworkxUnionFind

from structure.assur import AssurGroup
from structure.generators import GROUP_KINDS, random_mechanism_with_groups
from structure.model import Mechanism, PairKind
from structure.report import StructuralReport, analyze
from structure.utils import UnionFind

KIND_SETS = {
    "no-RPP": tuple(k for k in GROUP_KINDS if k != "RPP"),
    "all-kinds": tuple(GROUP_KINDS),
}

kind_sets = pytest.mark.parametrize("kinds", list(KIND_SETS.values()), ids=list(KIND_SETS))

sizes = st.integers(min_value=5, max_value=40)
seeds = st.integers(min_value=0, max_value=2**32 - 1)
compounds = st.sampled_from([0.0, 0.25, 0.6, 1.0])

common = settings(
    max_examples=120,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)


@lru_cache(maxsize=4096)
def built(
    n: int, seed: int, kinds: tuple[str, ...], compound: float
) -> tuple[Mechanism, list[tuple[str, ...]]]:
    return random_mechanism_with_groups(n, seed, kinds=kinds, compound=compound)


@lru_cache(maxsize=4096)
def analyzed(n: int, seed: int, kinds: tuple[str, ...], compound: float) -> StructuralReport:
    return analyze(built(n, seed, kinds, compound)[0])


def signature(report: StructuralReport, rename=lambda x: x) -> set:
    """The groups as a set: links (renamed), class, order, kind."""
    return {
        (frozenset(rename(x) for x in g.links), g.assur_class, g.order, g.kind)
        for g in report.groups
    }


def pair_tuples(m: Mechanism, pairs=None) -> list[tuple]:
    out = []
    for p in m.pairs if pairs is None else pairs:
        item: tuple = (p.a, p.b, p.kind.value, p.point)
        if p.angle_deg is not None:
            item += ({"angle": p.angle_deg},)
        out.append(item)
    return out


def expected_shape(m: Mechanism, links: tuple[str, ...]) -> tuple[int, int, str | None]:
    """(class, order, dyad kind) of an attached group, read off the mechanism itself."""
    inside = set(links)
    first = min(int(x) for x in links)  # links are numbered in order of attachment
    internal = {x: 0 for x in links}
    letters: dict[str, str] = {}
    middle = ""
    for p in m.pairs:
        a_in, b_in = p.a in inside, p.b in inside
        if a_in and b_in:
            internal[p.a] += 1
            internal[p.b] += 1
            middle = p.kind.value
        elif (a_in or b_in) and int(p.b if a_in else p.a) < first:  # external, not a later group
            letters[p.a if a_in else p.b] = p.kind.value
    if len(links) == 2:
        word = letters[links[0]] + middle + letters[links[1]]
        kind = {"PRR": "RRP", "PPR": "RPP"}.get(word, word)
        return 2, 2, kind
    if max(internal.values()) == 3:  # ternary base link: a triad
        return 3, 3, None
    return 4, 2, None  # ring of four: class IV


# ----------------------------------------------------------------------------- properties
@kind_sets
@common
@given(n=sizes, seed=seeds, compound=compounds)
def test_groups_partition_the_driven_links(kinds, n, seed, compound):
    m, _ = built(n, seed, kinds, compound)
    report = analyzed(n, seed, kinds, compound)
    assert report.mobility.W == 1
    assert report.drivers == ("1",)
    links = [x for g in report.groups for x in g.links]
    assert len(links) == len(set(links)), "a link lies in two groups"
    assert set(links) == set(m.moving_links) - set(report.drivers)


@kind_sets
@common
@given(n=sizes, seed=seeds, compound=compounds)
def test_each_group_counts_3n_equals_2p(kinds, n, seed, compound):
    report = analyzed(n, seed, kinds, compound)
    for g in report.groups:
        assert 3 * len(g.links) == 2 * len(g.pairs), g
        assert len(g.internal_pairs) + len(g.external_pairs) == len(g.pairs), g
        assert g.order == len(g.external_pairs), g


@kind_sets
@common
@given(n=sizes, seed=seeds, compound=compounds)
def test_groups_are_the_attached_ones(kinds, n, seed, compound):
    # the generator attaches minimal groups: any coarser or finer split is wrong
    _, attached = built(n, seed, kinds, compound)
    report = analyzed(n, seed, kinds, compound)
    assert {frozenset(g.links) for g in report.groups} == {frozenset(g) for g in attached}


@kind_sets
@common
@given(n=sizes, seed=seeds, compound=compounds)
def test_class_order_and_kind_of_each_group(kinds, n, seed, compound):
    m, attached = built(n, seed, kinds, compound)
    report = analyzed(n, seed, kinds, compound)
    found: dict[frozenset, AssurGroup] = {frozenset(g.links): g for g in report.groups}
    for links in attached:
        g = found.get(frozenset(links))
        assert g is not None, f"attached group {links} not found: {report.formula}"
        assert (g.assur_class, g.order, g.kind) == expected_shape(m, links), g
    assert report.mechanism_class == max(
        (expected_shape(m, links)[0] for links in attached), default=1
    )


@kind_sets
@common
@given(n=sizes, seed=seeds, compound=compounds)
def test_solve_order_follows_the_dag(kinds, n, seed, compound):
    m, _ = built(n, seed, kinds, compound)
    report = analyzed(n, seed, kinds, compound)
    dag = report.dag
    assert set(dag.nodes) == set(range(len(report.groups)))
    assert all(i < j for i, j in dag.edges), "solve order is not a topological order"
    group_of = {x: i for i, g in enumerate(report.groups) for x in g.links}
    known = {m.ground, *report.drivers}
    for j, g in enumerate(report.groups):
        assert g.known_links, g
        for x in g.known_links:
            assert x in known, f"{g} hangs on {x}, not known before it"
            if x in group_of:
                assert dag.has_edge(group_of[x], j), (x, g)
        known.update(g.links)


def _relisted(m: Mechanism, rng: random.Random) -> Mechanism:
    """The same mechanism with every compound hinge's pairs listed as another tree."""
    pairs = list(m.pairs)
    slots: dict[int, tuple] = {}
    fixed = {m.ground, *m.driver_links}
    for h in m.hinges:
        if len(h.links) < 3:
            continue
        links = list(h.links)
        # the driver must keep its own pair to the ground (the model requires it)
        keep = [x for x in links if x in fixed] if fixed <= set(links) else []
        if rng.random() < 0.5:  # a star from a random centre
            centre = rng.choice(keep or links)
            edges = [(centre, x) for x in links if x != centre]
        else:  # a path in random order
            rest = [x for x in links if x not in keep]
            rng.shuffle(rest)
            cut = rng.randrange(len(rest) + 1)
            order = rest[:cut] + keep + rest[cut:]
            edges = list(itertools.pairwise(order))
        ids = sorted(h.pairs)
        for pid, (a, b) in zip(ids, edges, strict=True):
            if rng.random() < 0.5:
                a, b = b, a
            slots[pid] = (a, b, "R", h.point)
    items = [slots.get(p.id, t) for p, t in zip(pairs, pair_tuples(m), strict=True)]
    return Mechanism.from_pairs(items, ground=m.ground, drivers=m.driver_links)


@kind_sets
@common
@given(n=sizes, seed=seeds, compound=st.sampled_from([0.6, 1.0]), shuffle=seeds)
def test_relisting_compound_hinges_changes_nothing(kinds, n, seed, compound, shuffle):
    m, _ = built(n, seed, kinds, compound)
    report = analyzed(n, seed, kinds, compound)
    other = _relisted(m, random.Random(shuffle))
    again = analyze(other)
    assert again.mobility.W == report.mobility.W == 1
    assert signature(again) == signature(report)


@kind_sets
@common
@given(n=sizes, seed=seeds, compound=compounds, perm=seeds)
def test_renaming_links_changes_nothing(kinds, n, seed, compound, perm):
    m, _ = built(n, seed, kinds, compound)
    report = analyzed(n, seed, kinds, compound)
    fixed = {m.ground, *m.driver_links}
    movable = [x for x in m.links if x not in fixed]
    new_names = [f"L{x}" for x in movable]
    random.Random(perm).shuffle(new_names)
    rename = dict(zip(movable, new_names, strict=True))
    rename.update({x: x for x in fixed})
    items = [(rename[a], rename[b], *rest) for a, b, *rest in pair_tuples(m)]
    again = analyze(Mechanism.from_pairs(items, ground=m.ground, drivers=m.driver_links))
    assert again.mobility.W == report.mobility.W
    assert signature(again) == signature(report, rename.__getitem__)


@kind_sets
@common
@given(n=sizes, seed=seeds, compound=compounds, perm=seeds)
def test_listing_order_changes_nothing(kinds, n, seed, compound, perm):
    m, _ = built(n, seed, kinds, compound)
    report = analyzed(n, seed, kinds, compound)
    items = pair_tuples(m)
    random.Random(perm).shuffle(items)
    again = analyze(Mechanism.from_pairs(items, ground=m.ground, drivers=m.driver_links))
    assert again.mobility.W == report.mobility.W
    assert signature(again) == signature(report)


# ----------------------------------------------------------------------------- generator
@given(n=st.integers(min_value=1, max_value=60), seed=seeds, compound=compounds)
@settings(max_examples=100, deadline=None)
def test_generator_shape(n, seed, compound):
    m, groups = random_mechanism_with_groups(n, seed, compound=compound)
    assert m.ground == "0" and m.driver_links == ("1",)
    assert len(m.moving_links) == 1 + sum(len(g) for g in groups)
    assert n - 1 <= len(m.moving_links) <= n  # even sizes only: one short of an even n
    assert all(p.point for p in m.pairs)
    assert all(p.angle_deg is not None for p in m.pairs if p.kind is PairKind.P)
    assert 2 * len(m.pairs) == 3 * (len(m.moving_links) - 1) + 2
    assert random_mechanism_with_groups(n, seed, compound=compound)[1] == groups


def test_generator_rejects_bad_arguments():
    with pytest.raises(ValueError):
        random_mechanism_with_groups(0)
    with pytest.raises(ValueError):
        random_mechanism_with_groups(9, kinds=("RRRR",))
    with pytest.raises(ValueError):
        random_mechanism_with_groups(9, kinds=())
    with pytest.raises(ValueError):
        random_mechanism_with_groups(9, compound=1.5)


@settings(max_examples=200, deadline=None)
@given(
    st.lists(st.lists(st.integers(0, 12), min_size=0, max_size=4), max_size=12),
    st.lists(st.integers(0, 14), max_size=6),
)
def test_union_find_answers_as_networkx_does(unions, lookups):
    """structure.utils.UnionFind stands in for networkx's (start-up): same sets, same order."""
    ours, reference = UnionFind(range(10)), NetworkxUnionFind(range(10))
    for elements in unions:
        ours.union(*elements)
        reference.union(*elements)
    assert [ours[x] for x in lookups] == [reference[x] for x in lookups]
    assert list(ours) == list(reference)
    assert list(ours.to_sets()) == list(reference.to_sets())
