"""Solving the linear systems, on numbers or on symbols, with one analysis of their matrix.

The velocity and acceleration systems share the matrix A, so it is analysed once: made
dimensionless, its rank and condition checked (`mobility`), a square set of independent
rows chosen, and, for exact solving, ordered into blocks (block-triangular form via a
matching of rows to unknowns and the strongly connected components of the dependencies).
Each block is then a small system solved exactly, in order; numerically the whole system
is solved with the SVD computed for the analysis.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np
import scipy.linalg
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import maximum_bipartite_matching

from ..errors import KinematikaError
from .mobility import SINGULAR_CONDITION, Diagnosis, conflict_error, diagnose, scale_system, underdetermined_error


@dataclass
class Analysis:
    """The dimensionless matrix, its SVD, the independent rows and the block order."""

    scaled: Any
    u: np.ndarray
    s: np.ndarray
    vt: np.ndarray
    diagnosis: Diagnosis
    rows: list[int]                      # n independent rows
    blocks: list[tuple[list[int], list[int]]]   # (rows, columns) in solving order

    @property
    def condition_number(self) -> float:
        return self.diagnosis.condition_number


def analyse(a: np.ndarray, is_driver: np.ndarray, translation_columns: np.ndarray, length: float,
            labels: list[str], wheres: list[str], body_of: list[str],
            want_blocks: bool = False) -> Analysis:
    """Check that A fixes every unknown and prepare the solves; raise `mobility`/`singular`."""
    m, n = a.shape
    scaled = scale_system(a, translation_columns, length)
    diag = diagnose(scaled.matrix, is_driver)
    if m < n or diag.condition_number > SINGULAR_CONDITION:
        raise underdetermined_error(scaled.matrix, is_driver, labels, wheres, body_of, diag)
    u, s, vt = np.linalg.svd(scaled.matrix, full_matrices=False)
    _, _, piv = scipy.linalg.qr(scaled.matrix.T, pivoting=True, mode="economic")
    rows = sorted(int(i) for i in piv[:n])
    blocks = _blocks(a[rows], rows) if want_blocks else []
    return Analysis(scaled, u, s, vt, diag, rows, blocks)


def solve_numeric(an: Analysis, b: np.ndarray, labels: list[str], wheres: list[str],
                  is_driver: np.ndarray, check: bool = True) -> np.ndarray:
    """Least squares with the analysis' SVD; a residual means conflicting conditions."""
    bs = b * an.scaled.row_scale
    y = (an.u.T @ bs) / an.s
    xs = an.vt.T @ y
    if check:
        residual = an.scaled.matrix @ xs - bs
        size = max(np.abs(bs).max(initial=0.0), np.abs(an.scaled.matrix).max(initial=0.0) *
                   np.abs(xs).max(initial=0.0), 1e-300)
        if np.abs(residual).max(initial=0.0) > 1e-7 * size:
            raise conflict_error(residual, labels, wheres, is_driver, an.diagnosis)
    return xs * an.scaled.col_scale


def solve_symbolic(an: Analysis, a_sym: Sequence[Sequence[Any]], b_sym: Sequence[Any],
                   simplify: Any) -> list[Any]:
    """Exact solution, block by block in dependency order, simplifying as it goes."""
    import sympy

    n = len(a_sym[0]) if a_sym else 0
    x: list[Any] = [None] * n
    for rows, cols in an.blocks:
        known = [c for c in range(n) if x[c] is not None]
        rhs = []
        for r in rows:
            value = b_sym[r]
            for c in known:
                coef = a_sym[r][c]
                if coef != 0:
                    value = value - coef * x[c]
            rhs.append(value)
        if len(cols) == 1:
            solution = [rhs[0] / a_sym[rows[0]][cols[0]]]
        else:
            block = sympy.Matrix([[a_sym[r][c] for c in cols] for r in rows])
            solution = list(block.LUsolve(sympy.Matrix(rhs)))
        for c, value in zip(cols, solution):
            x[c] = simplify(value)
    return x


def _blocks(a_rows: np.ndarray, rows: list[int]) -> list[tuple[list[int], list[int]]]:
    """Block-triangular order of a square nonsingular system (Dulmage–Mendelsohn fine blocks)."""
    n = a_rows.shape[1]
    top = np.abs(a_rows).max(initial=0.0)
    pattern = np.abs(a_rows) > 1e-12 * max(top, 1e-300)
    match = maximum_bipartite_matching(csr_matrix(pattern.astype(np.int8)), perm_type="column")
    if np.any(match < 0):
        raise KinematikaError("singular", "the system has no structurally independent set of "
                              "conditions for every unknown", "drivers")
    # row i is matched to column match[i]; unknown match[i] depends on the others of row i
    row_of_col = {int(c): i for i, c in enumerate(match)}
    deps = {c: [int(k) for k in np.flatnonzero(pattern[row_of_col[c]]) if k != c] for c in range(n)}
    order = _tarjan(n, deps)
    return [([rows[row_of_col[c]] for c in comp], comp) for comp in order]


def _tarjan(n: int, deps: dict[int, list[int]]) -> list[list[int]]:
    """Strongly connected components, each after the components it depends on."""
    index: dict[int, int] = {}
    low: dict[int, int] = {}
    stack: list[int] = []
    on_stack: set[int] = set()
    out: list[list[int]] = []
    counter = 0
    for root in range(n):
        if root in index:
            continue
        work = [(root, 0)]
        while work:
            v, i = work.pop()
            if i == 0:
                index[v] = low[v] = counter
                counter += 1
                stack.append(v)
                on_stack.add(v)
            recurse = False
            for k in range(i, len(deps[v])):
                w = deps[v][k]
                if w not in index:
                    work.append((v, k + 1))
                    work.append((w, 0))
                    recurse = True
                    break
                if w in on_stack:
                    low[v] = min(low[v], index[w])
            if recurse:
                continue
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                out.append(sorted(comp))
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[v])
    return out
