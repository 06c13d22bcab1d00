"""Start-up: ``assur classify`` of a fixture imports only what classifying needs (issue 12).

The whole process is timed by ``benchmarks/startup.py``; here the cheap, exact
part: which heavy libraries a run loads. networkx is imported when a graph is
asked for, sympy when an exact value is, matplotlib when a figure is, PyYAML
when a Pyslvs project is read.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("networkx", "sympy", "matplotlib", "yaml", "scipy", "pandas")

RUN = """
import contextlib, io, sys
from kinematics.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    try:
        main({argv!r})
    except SystemExit:
        pass
print(" ".join(m for m in {heavy!r} if m in sys.modules))
"""


def _loaded(argv: list[str]) -> set[str]:
    code = RUN.format(argv=argv, heavy=HEAVY)
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT
    )
    return set(done.stdout.split())


@pytest.mark.parametrize("options", [[], ["--json"]])
def test_classify_of_a_fixture_loads_no_heavy_library(options: list[str]) -> None:
    assert _loaded(["classify", *options, "fixtures/fourbar.edges"]) == set()


def test_the_kinematic_graph_is_still_a_networkx_multigraph_when_asked_for() -> None:
    from structure import read_edgelist

    mechanism = read_edgelist(ROOT / "fixtures" / "fourbar.edges")
    graph = mechanism.graph
    assert graph.is_multigraph() and set(graph.nodes) == set(mechanism.links)
    assert graph.number_of_edges() == len(mechanism.pairs)
