"""Tests of ``assur atlas`` (kinematics.cli.atlas): the output contract, formats, resume."""

from __future__ import annotations

import csv
import io
import json
import sys

import networkx as nx
import pytest

from kinematics.cli.commands import main
from kinematics.cli.tables import progress_bar
from structure.atlas import ATLAS_COLUMNS
from structure.chains import chain_from_code, count_chains
from structure.readwrite.edgelist import read_edgelist
from structure.report import analyze


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_jsonl_rows_hold_the_output_contract(capsys):
    code, out, err = run(capsys, "atlas", "--links", "6", "--dof", "1", "--format", "jsonl")
    assert code == 0 and err == ""
    rows = [json.loads(line) for line in out.splitlines()]
    assert len(rows) == 9
    for row in rows:
        assert {"chain", "ground", "driver", "groups", "mechanism_class", "multiplicity"} <= set(
            row
        )
        assert isinstance(row["mechanism_class"], int)
        assert isinstance(row["driver"], int)
    assert sum(row["multiplicity"] for row in rows) == 28  # 2 × 7 pins, twice each
    assert {row["chain"] for row in rows} == {"ELr?", "Eie_"}


def test_labelled_rows(capsys):
    code, out, _ = run(capsys, "atlas", "--links", "6", "--labelled")
    rows = [json.loads(line) for line in out.splitlines()]
    assert code == 0 and len(rows) == 28
    assert {row["multiplicity"] for row in rows} == {1}


def test_csv_rows(capsys):
    code, out, _ = run(capsys, "atlas", "--links", "8", "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 0
    assert list(rows[0]) == [name for name, _ in ATLAS_COLUMNS]
    assert sum(int(row["multiplicity"]) for row in rows) == 320
    assert json.loads(rows[0]["groups"])[0]["class"] >= 2


def test_write_edgelists_rebuilds_every_mechanism(tmp_path, capsys):
    directory = tmp_path / "mechanisms"
    code, out, _ = run(capsys, "atlas", "--links", "6", "--write-edgelists", str(directory))
    assert code == 0
    rows = [json.loads(line) for line in out.splitlines()]
    assert len(list(directory.glob("*.edges"))) == len(rows)
    for row in rows:
        report = analyze(read_edgelist(directory / row["edgelist"]))
        assert report.formula == row["formula"]
        assert report.mechanism_class == row["mechanism_class"]


def test_summary_table(capsys):
    code, out, _ = run(capsys, "atlas", "--links", "4-8", "--summary")
    assert code == 0
    lines = out.splitlines()
    assert lines[0] == (
        "| links | class | chains | mechanisms | labelled choices | degenerate chains left out |"
    )
    assert "| 4 | all | 1 | 1 | 8 | 0 |" in lines
    assert "| 6 | all | 2 | 9 | 28 | 3 |" in lines
    assert any(
        line.startswith("| 8 | all | 16 | ") and line.endswith(" 320 | 55 |") for line in lines
    )


def test_count(capsys):
    code, out, _ = run(capsys, "atlas", "--links", "4-10", "--count")
    assert code == 0
    assert [line.split(":")[1].split()[0] for line in out.splitlines()] == [
        "1",
        "2",
        "16",
        "230",
    ]
    assert "71 inversions" in out.splitlines()[2]


@pytest.mark.parametrize("fmt", ["jsonl", "csv"])
def test_resume_gives_the_table_of_an_uninterrupted_run(tmp_path, capsys, fmt):
    whole = tmp_path / f"whole.{fmt}"
    assert run(capsys, "atlas", "--links", "8", "--format", fmt, "-o", str(whole))[0] == 0
    data = whole.read_bytes()
    resumed = tmp_path / f"resumed.{fmt}"
    resumed.write_bytes(data[: len(data) // 3])  # the run was stopped in the middle of a row
    code, out, _err = run(
        capsys, "atlas", "--links", "8", "--format", fmt, "-o", str(resumed), "--resume"
    )
    assert code == 0 and out == ""
    assert resumed.read_bytes() == data
    # resuming a finished table changes nothing
    assert (
        run(capsys, "atlas", "--links", "8", "--format", fmt, "-o", str(resumed), "--resume")[0]
        == 0
    )
    assert resumed.read_bytes() == data


def test_usage_errors(capsys):
    assert run(capsys, "atlas", "--links", "5")[0] == 2
    code, _, err = run(capsys, "atlas", "--links", "6", "--resume")
    assert code == 2 and "--resume needs --output" in err
    code, _, err = run(capsys, "atlas", "--links", "6", "--format", "parquet")
    assert code == 2 and "--output" in err
    assert run(capsys, "atlas", "--links", "six")[0] == 2


def test_parquet(tmp_path, capsys):
    pq = pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "atlas.parquet"
    assert run(capsys, "atlas", "--links", "8", "--format", "parquet", "-o", str(out))[0] == 0
    table = pq.read_table(out)
    assert table.column_names == [name for name, _ in ATLAS_COLUMNS]
    assert sum(table.column("multiplicity").to_pylist()) == 320


def test_progress_bar_only_on_a_terminal(monkeypatch):
    update, close = progress_bar(10, "chain")
    assert update is None  # stderr is captured, not a terminal
    close()

    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    monkeypatch.setitem(sys.modules, "tqdm", None)
    update, close = progress_bar(10, "chain")
    assert update is None and "assur[progress]" in terminal.getvalue()
    monkeypatch.delitem(sys.modules, "tqdm")
    pytest.importorskip("tqdm")
    update, close = progress_bar(10, "chain")
    update(4)
    update(10)
    close()
    assert "10/10" in terminal.getvalue()


# ------------------------------------------------------------------ counts (issue 22, item 12)
def _counted(capsys, *argv: str) -> list[tuple[int, int]]:
    """(chains, inversions) of each line of ``atlas --count``."""
    code, out, _ = run(capsys, "atlas", "--count", *argv)
    assert code == 0
    found = []
    for line in out.splitlines():
        _, rest = line.split(": ", 1)
        chains = int(rest.split()[0])
        inversions = int(rest.split(" inversions")[0].rsplit(" ", 1)[1])
        found.append((chains, inversions))
    return found


def test_the_published_one_dof_counts():
    """1, 2, 16, 230 non-degenerate 1-DOF chains of 4 to 10 links, as published (the
    references of structure/chains.py: Mruthyunjaya 2003, Yan and Chiu 2015, OEIS A180923),
    and pyslvs's atlas of 40 eight-link chains, which keeps the degenerate ones but no chain
    a link cuts in two."""
    assert [count_chains(n).kept for n in (4, 6, 8, 10)] == [1, 2, 16, 230]
    assert count_chains(8, degenerate=True, fractionated=False).kept == 40
    # the 2-DOF chains of 5, 7, 9 links: 1, 4, 40 (the same references)
    assert [count_chains(n, 2).kept for n in (5, 7, 9)] == [1, 4, 40]


@pytest.mark.slow
def test_the_published_counts_of_twelve_links_and_eleven_at_two_dof():
    assert count_chains(12).kept == 6856
    assert count_chains(11, 2).kept == 839


def test_count_follows_degenerate_as_the_rows_do(capsys):
    """The issue's reproducer: ``--count --degenerate --no-fractionated`` said 16 at 8 links
    where the rows of the same options hold 40 chains."""
    assert _counted(capsys, "--links", "8", "--degenerate", "--no-fractionated")[0][0] == 40
    assert _counted(capsys, "--links", "8", "--degenerate")[0][0] == 71
    assert _counted(capsys, "--links", "8")[0][0] == 16


def _ground_orbits(code: str) -> int:
    """The links of a chain up to its symmetry, by networkx's own isomorphism matcher."""
    chain = chain_from_code(code)
    graph = nx.MultiGraph()
    graph.add_nodes_from(range(chain.links))
    graph.add_edges_from(chain.joints)
    matcher = nx.algorithms.isomorphism.MultiGraphMatcher(graph, graph)
    orbit = {link: {link} for link in graph}
    for mapping in matcher.isomorphisms_iter():
        for link, image in mapping.items():
            orbit[link].add(image)
    return len({frozenset(o) for o in orbit.values()})


_OPTIONS = {
    "plain": [],
    "degenerate": ["--degenerate"],
    "no-fractionated": ["--no-fractionated"],
    "pyslvs": ["--degenerate", "--no-fractionated"],
}


@pytest.mark.parametrize(
    ("links", "dof", "options"),
    [
        *[pytest.param("4,6", "1", o, id=f"4,6-{name}") for name, o in _OPTIONS.items()],
        *[pytest.param("5,7", "2", o, id=f"5,7-{name}") for name, o in _OPTIONS.items()],
        pytest.param("8", "1", _OPTIONS["pyslvs"], id="8-pyslvs"),
        *[
            pytest.param("8", "1", o, id=f"8-{name}", marks=pytest.mark.slow)
            for name, o in _OPTIONS.items()
            if name != "pyslvs"
        ],
    ],
)
def test_count_equals_the_rows_for_every_option(capsys, links, dof, options):
    """``--count`` gives, per link count, the chains the rows of the same options hold, and
    their inversions: the ground links up to each chain's symmetry (counted here from the
    rows' chains with networkx, not with the atlas's own canonical labelling)."""
    counts = _counted(capsys, "--links", links, "--dof", dof, *options)
    code, out, _ = run(capsys, "atlas", "--links", links, "--dof", dof, *options)
    assert code == 0
    chains: dict[int, set[str]] = {}
    for line in out.splitlines():
        row = json.loads(line)
        chains.setdefault(row["links"], set()).add(row["chain"])
    found = [
        (len(codes), sum(_ground_orbits(code) for code in codes))
        for _, codes in sorted(chains.items())
    ]
    assert counts == found
