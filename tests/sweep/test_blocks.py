"""Large systems solved block by block (engine.blocks) without scipy: the same solutions as a
dense solve, a condition estimate that bounds the dense one, and the same mechanism answers
as scipy's sparse LU (which remains the fallback)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from kinematika import solve
from kinematika.engine import blocks, linsolve
from kinematika.engine.blocks import BlockLU, SparseRows

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
from chain import four_bar_chain


def sparse(dense: np.ndarray) -> SparseRows:
    rows, cols = np.nonzero(dense)
    indptr = np.r_[0, np.cumsum(np.bincount(rows, minlength=dense.shape[0]))]
    return SparseRows(indptr, cols.astype(np.int64), dense[rows, cols], dense.shape)


def block_triangular(seed: int, blocks_: int = 30) -> np.ndarray:
    """A random block lower-triangular matrix of blocks of 1 to 9 unknowns, rows and
    columns shuffled (the matching must find the order back)."""
    rng = np.random.default_rng(seed)
    sizes = rng.integers(1, 10, blocks_)
    n = int(sizes.sum())
    a = np.zeros((n, n))
    start = np.r_[0, np.cumsum(sizes)]
    for k, s in enumerate(sizes):
        a[start[k]:start[k + 1], start[k]:start[k + 1]] = rng.normal(size=(s, s)) + 3 * np.eye(s)
        if k:
            lo = start[max(0, k - 3)]
            fill = rng.random((s, start[k] - lo)) < 0.2
            a[start[k]:start[k + 1], lo:start[k]] = fill * rng.normal(size=fill.shape)
    return a[rng.permutation(n)][:, rng.permutation(n)]


@pytest.mark.parametrize("seed", range(5))
def test_block_solves_equal_the_dense_ones(seed):
    a = block_triangular(seed)
    n = len(a)
    lu = BlockLU.factor(sparse(a))
    assert lu is not None
    b = np.random.default_rng(100 + seed).normal(size=n)
    x, y = np.linalg.solve(a, b), np.linalg.solve(a.T, b)
    assert np.abs(lu.solve(b) - x).max() <= 1e-9 * np.abs(x).max()
    assert np.abs(lu.refined(b) - x).max() <= 1e-11 * np.abs(x).max()
    assert np.abs(lu.solve(b, trans="T") - y).max() <= 1e-9 * np.abs(y).max()
    exact = np.abs(np.linalg.inv(a)).sum(axis=0).max()
    estimate = linsolve.inverse_norm(lu, n)
    assert exact / 3 <= estimate <= exact * (1 + 1e-9)


def test_a_full_block_needs_augmenting_paths():
    # every greedy first choice is taken by the row before: only augmenting paths match it
    n = 12
    a = np.eye(n) + np.diag(np.ones(n - 1), 1)
    a[:, 0] += 1.0
    shuffled = a[::-1]
    lu = BlockLU.factor(sparse(shuffled))
    b = np.arange(1.0, n + 1)
    assert lu.solve(b) == pytest.approx(np.linalg.solve(shuffled, b))


def test_singular_and_large_blocks_are_left_to_scipy(monkeypatch):
    singular = block_triangular(1)
    singular[:, 3] = 0.0
    assert BlockLU.factor(sparse(singular)) is None              # structurally singular
    numerically = block_triangular(2)
    numerically[:, 5] = numerically[:, 7]
    assert BlockLU.factor(sparse(numerically)) is None or \
        linsolve.inverse_norm(BlockLU.factor(sparse(numerically)), len(numerically)) > 1e12
    monkeypatch.setattr(blocks, "BLOCK_MAX", 4)
    assert BlockLU.factor(sparse(block_triangular(3))) is None   # a block of more than 4


def test_chain_by_blocks_and_by_scipy_agree(monkeypatch):
    tree = four_bar_chain(401, w=4.0, alpha=-2.0)
    tree["points"]["A7"] = [28.5, 1.2]              # not parallelograms everywhere
    by_blocks = solve(tree)
    assert isinstance(by_blocks.solver.analysis.lu, BlockLU)
    monkeypatch.setattr(BlockLU, "factor", classmethod(lambda cls, a: None))
    by_scipy = solve(tree)
    assert not isinstance(by_scipy.solver.analysis.lu, BlockLU)
    for body in by_blocks.model.moving_bodies:
        assert by_blocks.omega(body) == pytest.approx(by_scipy.omega(body), abs=1e-9)
        assert by_blocks.alpha(body) == pytest.approx(by_scipy.alpha(body), abs=1e-8)
    # past the changed loop every rocker turns with its crank again, a parallelogram's rule
    assert by_blocks.omega("rocker200") == pytest.approx(by_blocks.omega("rocker8"), rel=1e-12)


@pytest.mark.parametrize("seed", range(8))
def test_tarjan_gives_the_mutually_reachable_sets_each_after_what_it_depends_on(seed):
    # independently: v and w share a component iff each reaches the other (the transitive
    # closure of the edges, by repeated squaring of the boolean adjacency matrix); an edge
    # v → w between components puts w's before v's; an edge to itself changes nothing
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 60))
    deps = [rng.integers(0, n, int(rng.integers(0, 4))).tolist() for _ in range(n)]
    reach = np.eye(n, dtype=bool)
    for v, ws in enumerate(deps):
        reach[v, ws] = True
    for _ in range(int(np.ceil(np.log2(n))) + 1):
        reach = reach | ((reach.astype(int) @ reach.astype(int)) > 0)
    mutual = reach & reach.T
    comps = blocks.tarjan(n, deps)
    assert sorted(v for comp in comps for v in comp) == list(range(n))
    where = {v: k for k, comp in enumerate(comps) for v in comp}
    for comp in comps:
        assert comp == sorted(comp)
        assert {int(w) for w in np.flatnonzero(mutual[comp[0]])} == set(comp)
    assert all(where[w] <= where[v] for v, ws in enumerate(deps) for w in ws)
    assert blocks.tarjan(n, [[w for w in ws if w != v] for v, ws in enumerate(deps)]) == comps


def test_factoring_imports_nothing_more():
    # np.unique imports numpy.ma (about 30 M instructions, a 1000-body instant's start):
    # the blocks find each block's distinct couplings by sorting instead
    code = ("import sys, numpy as np\n"
            "from kinematika.engine.blocks import BlockLU, SparseRows\n"
            "a = np.eye(4) + np.diag([1.0, 2.0, 3.0], -1)\n"
            "r, c = np.nonzero(a)\n"
            "ptr = np.r_[0, np.cumsum(np.bincount(r, minlength=4))]\n"
            "before = set(sys.modules)\n"
            "lu = BlockLU.factor(SparseRows(ptr, c.astype(np.int64), a[r, c], (4, 4)))\n"
            "print(lu.solve(np.ones(4)).tolist(), sorted(set(sys.modules) - before))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split("] ")[1].strip() == "[]"
    # x0 = 1, x1 = 1 − x0 = 0, x2 = 1 − 2·x1 = 1, x3 = 1 − 3·x2 = −2
    assert out.split("] ")[0] + "]" == "[1.0, 0.0, 1.0, -2.0]"


def test_a_system_in_block_order_keeps_its_own_order(monkeypatch):
    # rows and columns already block lower-triangular (blocks of 3, 2, 4, 1 unknowns, each
    # reading the one before): the blocks are read off the order, the components' walk is
    # not needed, and the solves are the dense ones
    sizes = [3, 2, 4, 1]
    n = sum(sizes)
    rng = np.random.default_rng(7)
    a = np.zeros((n, n))
    start = np.r_[0, np.cumsum(sizes)]
    for k, s in enumerate(sizes):
        a[start[k]:start[k + 1], start[k]:start[k + 1]] = rng.normal(size=(s, s)) + 3 * np.eye(s)
        if k:
            a[start[k]:start[k + 1], start[k - 1]:start[k]] = rng.normal(size=(s, sizes[k - 1]))

    def no_walk(*args):
        raise AssertionError("the components were walked")

    monkeypatch.setattr(blocks, "tarjan", no_walk)
    monkeypatch.setattr(blocks, "MERGED", 4)          # each block its own (2 + 4 > 4, 3 + 2 > 4)
    lu = BlockLU.factor(sparse(a))
    assert lu.start.tolist() == [0, 3, 5, 9, 10]
    b = rng.normal(size=n)
    assert lu.solve(b) == pytest.approx(np.linalg.solve(a, b), rel=1e-12, abs=1e-12)
    assert lu.solve(b, trans="T") == pytest.approx(np.linalg.solve(a.T, b), rel=1e-12, abs=1e-12)


def test_an_order_with_a_block_larger_than_merged_is_walked(monkeypatch):
    # the last row reads the first unknown: in its own order the system is one block of 10,
    # larger than a merged block, so the components are found (a 1-cycle chain: one block
    # after all) and the solve is still the dense one
    n = 10
    a = 3 * np.eye(n) + np.diag(np.ones(n - 1), -1)
    a[0, n - 1] = 1.0
    walked = []
    real = blocks.tarjan
    monkeypatch.setattr(blocks, "tarjan", lambda *args: walked.append(1) or real(*args))
    monkeypatch.setattr(blocks, "MERGED", 4)
    monkeypatch.setattr(blocks, "BLOCK_MAX", 12)
    lu = BlockLU.factor(sparse(a))
    assert walked == [1]
    b = np.arange(1.0, n + 1)
    assert lu.solve(b) == pytest.approx(np.linalg.solve(a, b), rel=1e-12, abs=1e-12)
