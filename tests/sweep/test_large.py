"""One instant of a large mechanism: the sparse path (a chain of parallelogram loops).

Every loop is a parallelogram, so by hand every rocker turns exactly as the crank does
(ω, α) and every coupler translates. Small chains (dense SVD) and large ones (sparse LU)
must give the same answers, and a dead point must still be reported.
"""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

from kinematika import KinematikaError, solve
from kinematika.engine import linsolve

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
from chain import four_bar_chain


def test_large_chain_moves_as_its_crank():
    sol = solve(four_bar_chain(301, w=10.0, alpha=3.0))
    assert type(sol.solver.analysis).__name__ == "SparseAnalysis"
    assert sol.dof == 1
    for i in (1, 75, 150):
        assert sol.omega(f"rocker{i}") == pytest.approx(10.0, rel=1e-9)
        assert sol.alpha(f"rocker{i}") == pytest.approx(3.0, rel=1e-7)
        assert sol.omega(f"coupler{i}") == pytest.approx(0.0, abs=1e-9)
    # the pin of the last loop moves as the crank pin: v = ω k × (0, 1)
    assert sol.velocity("A150@rocker150") == pytest.approx((-10.0, 0.0), abs=1e-8)


def test_sparse_and_dense_paths_agree(monkeypatch):
    tree = four_bar_chain(61, w=4.0, alpha=-2.0)
    tree["points"]["A5"] = [20.0, 1.0]
    sparse = solve(tree)
    monkeypatch.setattr(linsolve, "LARGE", 10 ** 6)
    monkeypatch.setattr("kinematika.engine.system.LARGE", 10 ** 6)
    dense = solve(tree)
    assert type(dense.solver.analysis).__name__ == "Analysis"
    for body in sparse.model.moving_bodies:
        assert sparse.omega(body) == pytest.approx(dense.omega(body), abs=1e-10)
        assert sparse.alpha(body) == pytest.approx(dense.alpha(body), abs=1e-9)


def test_a_flat_chain_is_reported_as_by_the_dense_path(monkeypatch):
    # crank horizontal: every parallelogram lies flat on the ground line, where each loop
    # gains an instantaneous degree of freedom; the sparse LU fails and the dense analysis
    # names the free bodies, as for a small system
    tree = four_bar_chain(61)
    for name, xy in tree["points"].items():
        if name.startswith("A"):
            xy[0], xy[1] = xy[0] + 1.0, 0.0
    with pytest.raises(KinematikaError) as sparse:
        solve(tree)
    monkeypatch.setattr("kinematika.engine.system.LARGE", 10 ** 6)
    with pytest.raises(KinematikaError) as dense:
        solve(tree)
    assert (sparse.value.kind, str(sparse.value)) == (dense.value.kind, str(dense.value))
    assert sparse.value.kind == "mobility" and "left free: coupler1, rocker1" in str(sparse.value)


@pytest.mark.parametrize("seed", range(6))
def test_the_inverse_norm_estimate_is_a_close_lower_bound(seed):
    """Hager's estimate of ‖A⁻¹‖₁ from the LU against the exact norm of the dense inverse:
    never above it, and within a factor 3 of it (it is exact for almost every matrix)."""
    import numpy as np
    from scipy.sparse import identity, random as sparse_random
    from scipy.sparse.linalg import splu

    n = 60 + 40 * seed
    a = (sparse_random(n, n, density=4 / n, random_state=seed) + 0.3 * identity(n)).tocsc()
    exact = np.abs(np.linalg.inv(a.toarray())).sum(axis=0).max()
    estimate = linsolve.inverse_norm(splu(a), n)
    assert exact / 3 <= estimate <= exact * (1 + 1e-12)
