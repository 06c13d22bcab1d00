"""The atlas: every mechanism of every chain, classified by its Assur groups.

A mechanism of a chain (:mod:`structure.chains`) is a choice of ground link and of
``F`` drivers jointed to it. :func:`mechanism_choices` lists them as labelled
choices, or one per orbit of the chain's automorphisms with its *multiplicity*
(the labelled choices it stands for, so the multiplicities of a chain add up to
its labelled count). Each is classified by the single-mechanism path,
:func:`structure.report.analyze` on the mechanism the chain and the choice make
(:func:`chain_mechanism`), into an :class:`AtlasRow`: groups, class, formula.
:func:`atlas` does it for every chain of a link count, in order, in this process,
in local processes or on Dask (:mod:`structure.parallel`), and can start after
the chains a previous run finished (:func:`completed_chains`).

>>> rows = list(atlas(6))
>>> [(r.chain, r.ground, r.drivers, r.multiplicity, r.mechanism_class) for r in rows][:3]
[('ELr?', 0, (3,), 2, 3), ('ELr?', 0, (4,), 4, 2), ('ELr?', 2, (1,), 2, 3)]
>>> sum(r.multiplicity for r in rows) == sum(2 * len(c.joints) for c in enumerate_chains(6))
True
"""

from __future__ import annotations

import itertools
import json
import os
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from math import comb
from typing import Any

from .assur import roman
from .chains import KinematicChain, enumerate_chains
from .errors import MechanismError
from .model import Mechanism
from .parallel import ordered_map
from .readwrite.table import Column, read_table_lines
from .report import analyze

__all__ = [
    "ATLAS_COLUMNS",
    "AtlasGroup",
    "AtlasRow",
    "MechanismChoice",
    "SummaryLine",
    "atlas",
    "atlas_row_dict",
    "atlas_summary",
    "chain_mechanism",
    "classify_chain",
    "completed_chains",
    "format_summary",
    "labelled_count",
    "mechanism_choices",
    "row_mechanism",
]


@dataclass(frozen=True, slots=True)
class MechanismChoice:
    """A ground link and drivers jointed to it.

    ``multiplicity`` is how many labelled choices this one stands for (1 for a
    labelled choice); ``orbit`` numbers the distinct mechanisms of the chain.
    """

    ground: int
    drivers: tuple[int, ...]
    multiplicity: int
    orbit: int


def labelled_count(chain: KinematicChain) -> int:
    """Labelled choices of a chain: a ground and ``F`` of the links jointed to it."""
    return sum(comb(d, chain.dof) for d in chain.degrees)


def _labelled_choices(chain: KinematicChain) -> list[tuple[int, tuple[int, ...]]]:
    return [
        (ground, drivers)
        for ground in range(chain.links)
        for drivers in itertools.combinations(chain.neighbours(ground), chain.dof)
    ]


def mechanism_choices(
    chain: KinematicChain, *, labelled: bool = False
) -> tuple[MechanismChoice, ...]:
    """The mechanisms of a chain: distinct up to its symmetry, or every labelled one.

    Distinct choices are the first of each orbit of the automorphisms (grounds
    and drivers in increasing order), each with the size of its orbit.

    >>> from structure.chains import chain_from_code
    >>> [(c.ground, c.drivers, c.multiplicity) for c in mechanism_choices(chain_from_code("C]"))]
    [(0, (2,), 8)]
    """
    choices = _labelled_choices(chain)
    index = {choice: k for k, choice in enumerate(choices)}
    parent = list(range(len(choices)))

    def find(k: int) -> int:
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    for g in chain.generators:
        for k, (ground, drivers) in enumerate(choices):
            image = index[(g[ground], tuple(sorted(g[d] for d in drivers)))]
            a, b = find(k), find(image)
            if a != b:
                parent[max(a, b)] = min(a, b)
    roots = [find(k) for k in range(len(choices))]
    number = {root: n for n, root in enumerate(sorted(set(roots)))}
    size = {root: roots.count(root) for root in number}
    if labelled:
        return tuple(
            MechanismChoice(ground, drivers, 1, number[roots[k]])
            for k, (ground, drivers) in enumerate(choices)
        )
    return tuple(
        MechanismChoice(*choices[root], size[root], number[root]) for root in sorted(number)
    )


def chain_mechanism(
    chain: KinematicChain, ground: int, drivers: Sequence[int], name: str = ""
) -> Mechanism:
    """The mechanism of a chain with this ground and these drivers (links named ``'0'``...).

    >>> from structure.chains import chain_from_code
    >>> m = chain_mechanism(chain_from_code("C]"), 0, [2])
    >>> m.ground, m.driver_links, len(m.pairs)
    ('0', ('2',), 4)
    """
    return Mechanism.from_pairs(
        [(str(i), str(j), "R") for i, j in chain.joints],
        ground=str(ground),
        drivers=[str(d) for d in drivers],
        name=name,
        source=f"<atlas {chain.code}>",
    )


@dataclass(frozen=True, slots=True)
class AtlasGroup:
    """An Assur group of an atlas mechanism: its links (chain labels), class, order, kind."""

    links: tuple[int, ...]
    assur_class: int
    order: int
    kind: str | None


@dataclass(frozen=True, slots=True)
class AtlasRow:
    """One mechanism of the atlas and its classification (``error`` when it has none)."""

    links: int
    dof: int
    chain: str
    chain_index: int
    joints: tuple[tuple[int, int], ...]
    ground: int
    drivers: tuple[int, ...]
    multiplicity: int
    orbit: int
    degenerate: bool
    mechanism_class: int | None
    groups: tuple[AtlasGroup, ...]
    formula: str
    error: str | None = None


def _classify(chain: KinematicChain, choice: MechanismChoice, index: int, bad: bool) -> AtlasRow:
    drivers = ", ".join(map(str, choice.drivers))
    name = f"chain {chain.code} ground {choice.ground} driver {drivers}"
    common = (
        chain.links,
        chain.dof,
        chain.code,
        index,
        chain.joints,
        choice.ground,
        choice.drivers,
        choice.multiplicity,
        choice.orbit,
        bad,
    )
    try:
        report = analyze(chain_mechanism(chain, choice.ground, choice.drivers, name))
    except MechanismError as exc:
        return AtlasRow(*common, None, (), "", str(exc))
    groups = tuple(
        AtlasGroup(tuple(int(x) for x in g.links), g.assur_class, g.order, g.kind)
        for g in report.groups
    )
    return AtlasRow(*common, report.mechanism_class, groups, report.formula)


def classify_chain(
    chain: KinematicChain, chain_index: int = 0, *, labelled: bool = False
) -> tuple[AtlasRow, ...]:
    """Every mechanism of one chain, classified (distinct ones, or every labelled one)."""
    bad = chain.degenerate
    return tuple(
        _classify(chain, choice, chain_index, bad)
        for choice in mechanism_choices(chain, labelled=labelled)
    )


def _chain_task(task: tuple[KinematicChain, int, bool]) -> tuple[AtlasRow, ...]:
    chain, index, labelled = task
    return classify_chain(chain, index, labelled=labelled)


def atlas(
    links: int,
    dof: int = 1,
    *,
    degenerate: bool = False,
    fractionated: bool = True,
    labelled: bool = False,
    start: int = 0,
    jobs: int = 1,
    scheduler: str | None = None,
    dask_local: int = 0,
    progress: Callable[[int], None] | None = None,
    chains: Sequence[KinematicChain] | None = None,
) -> Iterator[AtlasRow]:
    """The classified mechanisms of every chain, chain by chain in code order.

    Parameters
    ----------
    links, dof, degenerate, fractionated
        Which chains (:func:`~structure.chains.enumerate_chains`); or ``chains``.
    labelled : bool
        One row per labelled choice instead of one per orbit.
    start : int
        Skip the first ``start`` chains (a resumed run).
    jobs, scheduler, dask_local
        Where to run (:func:`~structure.parallel.ordered_map`); the rows and their
        order are the same everywhere.
    progress : callable, optional
        Called with the number of chains done so far, after each chain.

    Raises
    ------
    ValueError
        No chain has that many links and degrees of freedom.
    MissingExtraError
        Dask asked for but not installed.
    """
    if chains is None:
        chains = enumerate_chains(links, dof, degenerate=degenerate, fractionated=fractionated)
    tasks = ((chain, k, labelled) for k, chain in enumerate(chains) if k >= start)
    done = start
    for rows in ordered_map(
        _chain_task, tasks, jobs=jobs, scheduler=scheduler, dask_local=dask_local, chunk=4
    ):
        yield from rows
        done += 1
        if progress is not None:
            progress(done)


# --------------------------------------------------------------------------- rows as data
#: columns of an atlas table, in order, with their types
ATLAS_COLUMNS: tuple[Column, ...] = (
    ("links", "int"),
    ("dof", "int"),
    ("chain", "str"),
    ("chain_index", "int"),
    ("ground", "int"),
    ("driver", "json"),
    ("drivers", "json"),
    ("multiplicity", "int"),
    ("orbit", "int"),
    ("mechanism_class", "int"),
    ("class", "str"),
    ("groups", "json"),
    ("formula", "str"),
    ("degenerate", "bool"),
    ("joints", "json"),
    ("error", "str"),
)


def atlas_row_dict(row: AtlasRow) -> dict[str, Any]:
    """The row as JSON-ready data; ``driver`` is the driver (a list when ``F > 1``)."""
    return {
        "links": row.links,
        "dof": row.dof,
        "chain": row.chain,
        "chain_index": row.chain_index,
        "ground": row.ground,
        "driver": row.drivers[0] if len(row.drivers) == 1 else list(row.drivers),
        "drivers": list(row.drivers),
        "multiplicity": row.multiplicity,
        "orbit": row.orbit,
        "mechanism_class": row.mechanism_class,
        "class": roman(row.mechanism_class) if row.mechanism_class else None,
        "groups": [
            {"links": list(g.links), "class": g.assur_class, "order": g.order, "kind": g.kind}
            for g in row.groups
        ],
        "formula": row.formula,
        "degenerate": row.degenerate,
        "joints": [list(j) for j in row.joints],
        "error": row.error,
    }


def _cell_json(value: Any) -> Any:
    """A cell read back from CSV holds JSON text; from JSON lines, the value."""
    return json.loads(value) if isinstance(value, str) else value


def row_mechanism(row: Mapping[str, Any]) -> Mechanism:
    """Rebuild the mechanism of an atlas row (a dict read from JSON lines or CSV).

    >>> m = row_mechanism(atlas_row_dict(next(atlas(4))))
    >>> m.ground, m.driver_links, len(m.pairs)
    ('0', ('2',), 4)
    """
    pairs = [(str(i), str(j), "R") for i, j in _cell_json(row["joints"])]
    drivers = [str(d) for d in _cell_json(row["drivers"])]
    name = f"chain {row['chain']} ground {row['ground']} driver {', '.join(drivers)}"
    return Mechanism.from_pairs(
        pairs, ground=str(row["ground"]), drivers=drivers, name=name, source="<atlas row>"
    )


# ------------------------------------------------------------------------------ summary
@dataclass(frozen=True, slots=True)
class SummaryLine:
    """Chains and mechanisms of a link count, all (``assur_class`` None) or of one class.

    ``chains`` counts the chains with at least one such mechanism; ``mechanisms``
    the distinct mechanisms; ``labelled`` the labelled choices they stand for;
    ``errors`` the mechanisms that could not be classified.
    """

    links: int
    assur_class: int | None
    chains: int
    mechanisms: int
    labelled: int
    errors: int = 0


def _number(value: Any) -> int | None:
    """An integer cell (JSON lines: a number; CSV: its text; empty: None)."""
    return None if value is None or value == "" else int(value)


def atlas_summary(rows: Iterable[Mapping[str, Any]]) -> tuple[SummaryLine, ...]:
    """Chains and mechanisms per link count and Assur class.

    ``rows`` are atlas rows as data (:func:`atlas_row_dict`, or read back from
    JSON lines or CSV), of a distinct or a labelled run.
    """
    seen: dict[tuple[int, int, int], int] = {}
    labelled: dict[tuple[int, int, int], int] = {}
    for row in rows:
        key = (int(row["links"]), int(row["chain_index"]), int(row["orbit"]))
        seen.setdefault(key, _number(row["mechanism_class"]) or 0)
        labelled[key] = labelled.get(key, 0) + int(row["multiplicity"])
    tally: dict[tuple[int, int | None], list[Any]] = {}
    for key, assur_class in seen.items():
        for cls in (None, assur_class):
            entry = tally.setdefault((key[0], cls), [set(), 0, 0])
            entry[0].add(key[1])
            entry[1] += 1
            entry[2] += labelled[key]
    out = []
    for (links, cls), (chains, mechanisms, count) in sorted(
        tally.items(), key=lambda item: (item[0][0], -1 if item[0][1] is None else item[0][1])
    ):
        if cls == 0:
            continue
        errors = tally.get((links, 0), [set(), 0, 0])[1] if cls is None else 0
        out.append(SummaryLine(links, cls, len(chains), mechanisms, count, errors))
    return tuple(out)


def format_summary(lines: Sequence[SummaryLine], left_out: Mapping[int, int] | None = None) -> str:
    """The summary as a Markdown table; ``left_out`` gives the degenerate chains per link count.

    >>> print(format_summary(atlas_summary(map(atlas_row_dict, atlas(4)))), end="")
    | links | class | chains | mechanisms | labelled choices |
    |---:|:---|---:|---:|---:|
    | 4 | all | 1 | 1 | 8 |
    | 4 | II | 1 | 1 | 8 |
    """
    head = ["links", "class", "chains", "mechanisms", "labelled choices"]
    if left_out is not None:
        head.append("degenerate chains left out")
    if any(line.errors for line in lines):
        head.append("not classified")
    out = ["| " + " | ".join(head) + " |", "|---:|:---|" + "---:|" * (len(head) - 2)]
    for line in lines:
        cells = [
            str(line.links),
            "all" if line.assur_class is None else roman(line.assur_class),
            str(line.chains),
            str(line.mechanisms),
            str(line.labelled),
        ]
        if left_out is not None:
            cells.append(str(left_out.get(line.links, 0)) if line.assur_class is None else "")
        if "not classified" in head:
            cells.append(str(line.errors) if line.assur_class is None else "")
        out.append("| " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


# ------------------------------------------------------------------------------- resume
def completed_chains(
    path: str | os.PathLike[str],
    fmt: str,
    tasks: Sequence[tuple[int, KinematicChain]],
    *,
    labelled: bool = False,
) -> tuple[int, int]:
    """How many of ``tasks`` a table already holds in full, and the byte offset after them.

    ``tasks`` are the ``(chain_index, chain)`` of a run in order; the table (JSON
    lines or CSV, as :func:`atlas` writes it) must hold their rows in the same
    order. A run resumes by cutting the file at the offset and classifying the
    tasks from that count on; the result is the table an uninterrupted run writes.
    Returns ``(0, 0)`` for a missing file.

    Raises
    ------
    EdgeListError
        The table is no regular file (a device, a FIFO) or cannot be read.
    """
    if not os.path.exists(path):
        return 0, 0
    done, offset = 0, 0
    current: tuple[int, int] | None = None
    count = 0
    expected = [len(mechanism_choices(chain, labelled=labelled)) for _, chain in tasks]
    for row, end in read_table_lines(path, fmt):
        if done >= len(tasks):
            break
        index, chain = tasks[done]
        try:
            key = (int(row["links"]), int(row["chain_index"]))
        except (KeyError, TypeError, ValueError):
            break  # not a row of an atlas: the rows before it are kept
        if key != (chain.links, index) or row.get("chain") != chain.code:
            break
        count = count + 1 if key == current else 1
        current = key
        if count == expected[done]:
            done, offset, current, count = done + 1, end, None, 0
    return done, offset
