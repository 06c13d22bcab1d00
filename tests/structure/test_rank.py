"""The rank engine's shortcuts give the answers of their plain definitions.

The dense pass keeps a row when its component orthogonal to the rows kept
before exceeds 1e-8 of its norm: here that definition is run row by row (plain
Gram-Schmidt) and compared with :func:`structure.rigidity.rank.dense_rank`; the
null space is checked against its definition (orthonormal, annihilated by the
Jacobian, of dimension unknowns minus rank); the remembered regular block
patterns must not change a generic analysis.
"""

from __future__ import annotations

import random

import numpy as np
import pytest

import structure.rigidity.rank as rank_module
from structure.generators import random_mechanism
from structure.model import Mechanism
from structure.rigidity.constraints import constraint_system, random_realization
from structure.rigidity.rank import (
    dense_rank,
    dimensionless_jacobian,
    generic_rank,
    null_space,
)


def _over_constrained(seed: int) -> Mechanism:
    """A random mechanism with one to three extra R pairs between random links."""
    m = random_mechanism(4 + seed % 9, seed=seed)
    pairs = [
        (p.a, p.b, p.kind.value, p.point)
        + (({"angle": p.angle_deg},) if p.kind.value == "P" else ())
        for p in m.pairs
    ]
    rng = random.Random(seed)
    for k in range(1 + seed % 3):
        a, b = rng.sample(list(m.links), 2)
        pairs.append((a, b, "R", f"X{k}"))
    return Mechanism.from_pairs(pairs)


def _row_by_row(J: np.ndarray) -> list[int]:
    """The rows kept by the definition: each against the span of those kept before."""
    basis: list[np.ndarray] = []
    kept = []
    for i, v in enumerate(J):
        norm = np.linalg.norm(v)
        w = v.copy()
        for _ in range(2):
            for b in basis:
                w = w - (b @ w) * b
        if norm > 0 and np.linalg.norm(w) > 1e-8 * norm:
            basis.append(w / np.linalg.norm(w))
            kept.append(i)
    return kept


@pytest.mark.parametrize("seed", range(40))
@pytest.mark.parametrize("drivers", [(), ("1",)])
def test_dense_rank_keeps_the_rows_of_the_row_by_row_definition(seed, drivers):
    system = constraint_system(_over_constrained(seed), drivers)
    realization = random_realization(system, seed)
    J, _ = dimensionless_jacobian(system, realization)
    kept = _row_by_row(J)
    _, ro = system.scalar_offsets()
    expected: dict[int, int] = {}
    for r in range(len(system.row_kind)):
        dropped = sum(1 for i in range(ro[r], ro[r + 1]) if i not in kept)
        if dropped:
            expected[r] = dropped
    got = dense_rank(system, realization, "dense")
    assert got.dependent == expected
    assert got.dof == system.n_scalar_unknowns - sum(
        1 for i in kept if i < ro[system.n_pair_rows]
    )


@pytest.mark.parametrize("seed", range(20))
def test_null_space_is_the_definition(seed):
    system = constraint_system(_over_constrained(seed), ("1",) if seed % 2 else ())
    realization = random_realization(system, seed)
    J, _ = dimensionless_jacobian(system, realization)
    N = null_space(system, realization)
    assert N.shape == (system.n_scalar_unknowns, J.shape[1] - np.linalg.matrix_rank(J))
    assert np.allclose(N.T @ N, np.eye(N.shape[1]), atol=1e-12)
    assert np.allclose(J @ N, 0.0, atol=1e-9)


def test_remembered_regular_patterns_change_no_generic_analysis(monkeypatch):
    mechanisms = [random_mechanism(3 + s % 12, seed=s) for s in range(30)]
    mechanisms += [_over_constrained(s) for s in range(30)]
    systems = [constraint_system(m, ("1",)) for m in mechanisms]

    def fields(a):
        return (a.dependent, a.rank, a.dof, a.free, a.blocks, a.assigned, a.method)

    warm = [fields(generic_rank(s)) for s in systems]  # the memory fills as it goes
    monkeypatch.setattr(rank_module, "_REGULAR_PATTERNS", {})
    cold = []
    for s in systems:
        rank_module._REGULAR_PATTERNS.clear()  # every system evaluated from scratch
        cold.append(fields(generic_rank(s)))
    assert warm == cold
