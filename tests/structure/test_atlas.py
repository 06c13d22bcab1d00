"""Tests of structure.atlas: choices and multiplicities, agreement with analyze, summary, resume."""

from __future__ import annotations

import io
import json
import random

import pytest

from structure.atlas import (
    atlas,
    atlas_row_dict,
    atlas_summary,
    chain_mechanism,
    classify_chain,
    completed_chains,
    format_summary,
    labelled_count,
    mechanism_choices,
    row_mechanism,
)
from structure.chains import enumerate_chains
from structure.errors import MechanismError
from structure.readwrite.edgelist import parse_edgelist, write_edgelist
from structure.readwrite.table import open_table
from structure.report import analyze

from structure.atlas import ATLAS_COLUMNS  # isort: skip


def _shape(row) -> tuple:
    """What a relabelling keeps: the class and the sorted (class, order, size) of the groups."""
    return row.mechanism_class, sorted((g.assur_class, g.order, len(g.links)) for g in row.groups)


@pytest.mark.parametrize(("links", "dof"), [(4, 1), (6, 1), (8, 1), (10, 1), (7, 2), (9, 2)])
def test_multiplicities_add_up_to_the_labelled_choices(links, dof):
    for chain in enumerate_chains(links, dof):
        distinct = mechanism_choices(chain)
        labelled = mechanism_choices(chain, labelled=True)
        assert sum(c.multiplicity for c in distinct) == len(labelled) == labelled_count(chain)
        assert [c.orbit for c in distinct] == list(range(len(distinct)))
        for choice in labelled:
            assert set(choice.drivers) <= set(chain.neighbours(choice.ground))
            assert len(choice.drivers) == dof
        # each distinct choice is the first labelled one of its orbit
        first = {}
        for c in labelled:
            first.setdefault(c.orbit, (c.ground, c.drivers))
        assert [(c.ground, c.drivers) for c in distinct] == [first[c.orbit] for c in distinct]
        sizes = [sum(1 for c in labelled if c.orbit == d.orbit) for d in distinct]
        assert sizes == [c.multiplicity for c in distinct]


def test_four_bar_is_one_mechanism_of_eight_labelled_choices():
    (row,) = atlas(4)
    assert (row.ground, row.drivers, row.multiplicity, row.mechanism_class) == (0, (2,), 8, 2)
    assert [(g.links, g.assur_class, g.order, g.kind) for g in row.groups] == [
        ((3, 1), 2, 2, "RRR")
    ]


def test_symmetric_choices_classify_alike():
    for chain in enumerate_chains(8):
        rows = classify_chain(chain, labelled=True)
        by_orbit: dict[int, set] = {}
        for row in rows:
            by_orbit.setdefault(row.orbit, set()).add(repr(_shape(row)))
        assert all(len(shapes) == 1 for shapes in by_orbit.values())


def _single_path(row) -> tuple:
    """Classify the row's mechanism the way ``assur classify FILE`` does: text, parse, analyze."""
    text = write_edgelist(row_mechanism(atlas_row_dict(row)))
    try:
        report = analyze(parse_edgelist(text.splitlines(), source="rebuilt.edges"))
    except MechanismError as exc:
        return str(exc)
    groups = [
        (tuple(int(x) for x in g.links), g.assur_class, g.order, g.kind) for g in report.groups
    ]
    return report.mechanism_class, groups, report.formula, tuple(int(d) for d in report.drivers)


def test_atlas_agrees_with_the_single_mechanism_path():
    rows = list(atlas(8))
    rng = random.Random(13)
    for k, chain in rng.sample(list(enumerate(enumerate_chains(10))), 8):
        rows += classify_chain(chain, k)
    rows += list(atlas(7, 2))
    errors = 0
    for row in rows:
        if row.error is not None:  # two drivers whose motions depend on each other
            assert row.dof == 2 and _single_path(row) == row.error
            errors += 1
            continue
        groups = [(g.links, g.assur_class, g.order, g.kind) for g in row.groups]
        expected = (row.mechanism_class, groups, row.formula, row.drivers)
        assert _single_path(row) == expected, row
    assert errors < len(rows) // 10


def test_chain_mechanism_names_links_by_chain_label():
    chain = enumerate_chains(6)[0]
    m = chain_mechanism(chain, 2, [3])
    assert m.ground == "2" and m.driver_links == ("3",)
    assert sorted((int(p.a), int(p.b)) for p in m.pairs) == list(chain.joints)


def test_degenerate_chains_are_rows_too():
    rows = list(atlas(6, degenerate=True))
    assert {r.chain for r in rows} == {c.code for c in enumerate_chains(6, degenerate=True)}
    assert any(r.degenerate for r in rows)
    assert all(r.error is None or r.mechanism_class is None for r in rows)


def test_local_processes_give_the_same_rows_in_the_same_order():
    assert list(atlas(8, jobs=2)) == list(atlas(8))


def test_row_dict_holds_the_output_contract_and_rebuilds():
    for row in atlas(6):
        data = atlas_row_dict(row)
        for key in ("chain", "ground", "driver", "groups", "mechanism_class", "multiplicity"):
            assert key in data
        assert isinstance(data["mechanism_class"], int)
        assert data["driver"] == row.drivers[0]
        assert set(data) == {name for name, _ in ATLAS_COLUMNS}
        json.dumps(data)
        m = row_mechanism(json.loads(json.dumps(data)))
        assert (m.ground, m.driver_links) == (str(row.ground), tuple(map(str, row.drivers)))


def test_summary_counts_chains_mechanisms_and_labelled_choices():
    rows = [atlas_row_dict(r) for r in atlas(8)]
    labelled_rows = [atlas_row_dict(r) for r in atlas(8, labelled=True)]
    lines = atlas_summary(rows)
    assert atlas_summary(labelled_rows) == lines
    total = lines[0]
    assert (total.links, total.assur_class) == (8, None)
    assert (total.chains, total.mechanisms, total.labelled) == (16, len(rows), 320)
    by_class = [line for line in lines if line.assur_class is not None]
    assert sum(line.mechanisms for line in by_class) == total.mechanisms
    assert sum(line.labelled for line in by_class) == total.labelled
    text = format_summary(lines, {8: 55})
    assert text.splitlines()[2] == f"| 8 | all | 16 | {len(rows)} | 320 | 55 |"


@pytest.mark.parametrize("fmt", ["jsonl", "csv"])
def test_completed_chains_finds_where_an_interrupted_run_stopped(tmp_path, fmt):
    chains = enumerate_chains(8)
    tasks = list(enumerate(chains))
    rows = [atlas_row_dict(r) for r in atlas(8, chains=chains)]
    path = tmp_path / f"atlas.{fmt}"
    with open(path, "w", encoding="utf-8", newline="") as handle:
        writer = open_table(handle, fmt, ATLAS_COLUMNS)
        writer.write(rows)
        writer.close()
    assert completed_chains(path, fmt, tasks) == (16, path.stat().st_size)
    # cut in the middle of chain 5's rows, and in the middle of a line
    first_five = sum(len(mechanism_choices(c)) for c in chains[:5])
    buffer = io.StringIO()
    writer = open_table(buffer, fmt, ATLAS_COLUMNS)
    writer.write(rows[:first_five])
    whole = buffer.getvalue().encode()
    writer.write(rows[first_five : first_five + 1])
    cut = buffer.getvalue().encode()
    path.write_bytes(cut[:-7])
    assert completed_chains(path, fmt, tasks) == (5, len(whole))
    assert completed_chains(tmp_path / "none.jsonl", fmt, tasks) == (0, 0)
