"""Tests of structure.canonical and structure.chains: canonical codes, degeneracy, counts.

The counts are the published ones (THEORY.md §5; OEIS A180923 for 1-DOF chains):
1-DOF chains without a rigid subchain 4->1, 6->2, 8->16, 10->230 (12->6856 in
benchmarks/atlas_speed.py); 2-DOF chains 5->1, 7->4, 9->40 (3, 35 without a cut
link); pyslvs's atlas of eight-link chains, degenerate ones kept, has no chain with
a cut link: 40.
"""

from __future__ import annotations

import itertools
import random

import networkx as nx
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from networkx.algorithms.isomorphism import GraphMatcher

from structure.canonical import canonical_form, group_order, orbits
from structure.chains import (
    chain_from_code,
    chain_from_joints,
    count_chains,
    enumerate_chains,
    graph6,
    is_degenerate,
    joint_count,
)


def _adjacency(n: int, edges) -> list[dict[int, int]]:
    adjacency: list[dict[int, int]] = [{} for _ in range(n)]
    for i, j in edges:
        adjacency[i][j] = adjacency[j][i] = 1
    return adjacency


def _rigid_subset(n: int, edges) -> bool:
    """Brute force: some S, |S| >= 2, with 3(|S| - 1) - 2 e(S) <= 0."""
    for size in range(2, n + 1):
        for subset in itertools.combinations(range(n), size):
            inside = set(subset)
            e = sum(1 for i, j in edges if i in inside and j in inside)
            if 3 * (size - 1) - 2 * e <= 0:
                return True
    return False


# --------------------------------------------------------------------------- counts
@pytest.mark.parametrize(("links", "count"), [(4, 1), (6, 2), (8, 16), (10, 230)])
def test_one_dof_chain_counts(links, count):
    chains = enumerate_chains(links)
    assert len(chains) == count
    assert all(c.dof == 1 and not c.degenerate for c in chains)
    assert len({c.code for c in chains}) == count


@pytest.mark.parametrize(("links", "count", "without_cut"), [(5, 1, 1), (7, 4, 3), (9, 40, 35)])
def test_two_dof_chain_counts(links, count, without_cut):
    chains = enumerate_chains(links, 2)
    assert len(chains) == count
    assert sum(1 for c in chains if not c.fractionated) == without_cut
    assert len(enumerate_chains(links, 2, fractionated=False)) == without_cut


def test_pyslvs_eight_link_atlas_keeps_degenerate_chains_without_cut_link():
    chains = enumerate_chains(8, degenerate=True, fractionated=False)
    assert len(chains) == 40
    assert sum(c.degenerate for c in chains) == 24
    counts = count_chains(8)
    assert (counts.chains, counts.degenerate, counts.degenerate_fractionated) == (16, 55, 31)
    assert len(enumerate_chains(8, degenerate=True)) == 16 + 55


@pytest.mark.parametrize(("links", "inversions"), [(4, 1), (6, 5), (8, 71), (10, 1834)])
def test_inversions_are_ground_links_up_to_symmetry(links, inversions):
    # Tuttle's counts of inversions: 1, 5 (Watt I-II, Stephenson I-III), 71, 1834
    assert sum(len(c.link_orbits) for c in enumerate_chains(links)) == inversions
    assert count_chains(links).inversions == inversions


def test_enumerated_chains_are_pairwise_non_isomorphic_and_complete_for_eight_links():
    chains = enumerate_chains(8, degenerate=True)
    graphs = [nx.Graph(list(c.joints)) for c in chains]
    for a, b in itertools.combinations(graphs, 2):
        if sorted(d for _, d in a.degree) == sorted(d for _, d in b.degree):
            assert not nx.is_isomorphic(a, b)
    # every connected 8-vertex, 10-edge graph with minimum degree 2 is one of them
    codes = {c.code for c in chains}
    rng = random.Random(3)
    for _ in range(300):
        g = nx.gnm_random_graph(8, 10, seed=rng.randrange(10**9))
        if nx.is_connected(g) and min(d for _, d in g.degree) >= 2:
            assert chain_from_joints(g.edges, 8).code in codes


def test_joint_count_and_impossible_counts():
    assert joint_count(10, 1) == 13
    assert joint_count(7, 2) == 8
    with pytest.raises(ValueError, match="no chain of 5 links"):
        joint_count(5, 1)


# ------------------------------------------------------------------- canonical codes
def test_graph6_is_what_networkx_writes():
    for chain in enumerate_chains(8):
        g = nx.Graph()
        g.add_nodes_from(range(chain.links))
        g.add_edges_from(chain.joints)
        assert nx.to_graph6_bytes(g, header=False).decode().strip() == chain.code
        assert graph6(chain.links, chain.joints) == chain.code
        assert chain_from_code(chain.code) == chain


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(enumerate_chains(10)), st.randoms(use_true_random=False))
def test_canonical_code_is_invariant_under_relabelling(chain, rnd):
    relabel = list(range(chain.links))
    rnd.shuffle(relabel)
    joints = [(relabel[i], relabel[j]) for i, j in chain.joints]
    rnd.shuffle(joints)
    again = chain_from_joints(joints, chain.links)
    assert again.code == chain.code
    assert again.joints == chain.joints


@settings(max_examples=80, deadline=None)
@given(st.integers(4, 11), st.data())
def test_canonical_form_agrees_with_networkx_isomorphism(n, data):
    m = data.draw(st.integers(n - 1, min(2 * n, n * (n - 1) // 2)))
    seed_a = data.draw(st.integers(0, 10**6))
    seed_b = data.draw(st.integers(0, 10**6))
    a = nx.gnm_random_graph(n, m, seed=seed_a)
    b = nx.gnm_random_graph(n, m, seed=seed_b)
    form_a = canonical_form(n, _adjacency(n, a.edges))
    form_b = canonical_form(n, _adjacency(n, b.edges))
    assert (form_a.code == form_b.code) == nx.is_isomorphic(a, b)
    automorphisms = sum(1 for _ in GraphMatcher(a, a).isomorphisms_iter())
    assert group_order(n, form_a.generators) == automorphisms


def test_automorphism_generators_of_symmetric_graphs():
    petersen = nx.petersen_graph()
    form = canonical_form(10, _adjacency(10, petersen.edges))
    assert group_order(10, form.generators) == 120
    assert orbits(10, form.generators) == (tuple(range(10)),)
    cube = nx.convert_node_labels_to_integers(nx.hypercube_graph(3))
    assert group_order(8, canonical_form(8, _adjacency(8, cube.edges)).generators) == 48


def test_coloured_and_weighted_graphs():
    # a path 0-1-2 with the ends coloured differently has no symmetry
    path = _adjacency(3, [(0, 1), (1, 2)])
    assert canonical_form(3, path, [0, 0, 0]).generators
    assert not canonical_form(3, path, [1, 0, 0]).generators
    double = [{1: 2}, {0: 2}]
    assert canonical_form(2, double).code != canonical_form(2, [{1: 1}, {0: 1}]).code


def test_chain_symmetry_of_the_four_bar_and_the_six_bars():
    (four_bar,) = enumerate_chains(4)
    assert group_order(4, four_bar.generators) == 8
    stephenson, watt = enumerate_chains(6)
    assert [len(o) for o in stephenson.link_orbits] == [2, 2, 2]
    assert sorted(len(o) for o in watt.link_orbits) == [2, 4]


def test_chain_from_joints_refuses_double_pins():
    with pytest.raises(ValueError, match="simple pins"):
        chain_from_joints([(0, 1), (1, 0), (1, 2), (2, 0)])


# ------------------------------------------------------------------------ degeneracy
@settings(max_examples=150, deadline=None)
@given(st.integers(3, 9), st.data())
def test_pebble_game_agrees_with_the_subset_count(n, data):
    pairs = list(itertools.combinations(range(n), 2))
    edges = data.draw(st.lists(st.sampled_from(pairs), unique=True, max_size=2 * n))
    assert is_degenerate(n, edges) == _rigid_subset(n, edges)


def test_degenerate_examples():
    triangle_and_tail = [(0, 1), (1, 2), (2, 0), (2, 3), (3, 4), (4, 5), (5, 3)]
    assert is_degenerate(6, triangle_and_tail)
    watt = enumerate_chains(6)[1]
    assert not is_degenerate(6, watt.joints)
    # a pentagon with two diagonals from one corner holds two triangles
    assert is_degenerate(5, [(0, 1), (1, 2), (2, 3), (3, 4), (4, 0), (0, 2), (0, 3)])
