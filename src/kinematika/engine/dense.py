"""The dense analysis of a system's matrix (`Analysis`, `analyse`): made dimensionless, its
SVD, rank and condition checked (`mobility`), a square set of independent rows chosen and,
for exact solving, ordered into blocks (block-triangular form via a matching of rows to
unknowns and the strongly connected components of the dependencies).

In a module of its own, imported where a dense analysis is made (`engine.system` for a
small or symbolic system, `linsolve.analyse_sparse` when a large one fails its sparse LU),
so that a large numeric system solved sparse (the 1000-body chain) does not define it
(docs/performance.md). `linsolve` solves with either analysis.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np

from ..errors import KinematikaError
from .blocks import tarjan
from .mobility import SINGULAR_CONDITION, Diagnosis, Scaled, diagnose, scale_system, underdetermined_error


@dataclass
class Analysis:
    """The dimensionless matrix, its SVD, the independent rows and the block order."""

    scaled: Scaled[np.ndarray]
    u: np.ndarray
    s: np.ndarray
    vt: np.ndarray
    diagnosis: Diagnosis
    rows: list[int]                      # n independent rows
    blocks: list[tuple[list[int], list[int]]]   # (rows, columns) in solving order


def analyse(a: np.ndarray, is_driver: np.ndarray, translation_columns: np.ndarray, length: float,
            labels: Sequence[Any], wheres: Sequence[str], body_of: list[str],
            want_blocks: bool = False, restating: Any = None) -> Analysis:
    """Check that A fixes every unknown and prepare the solves; raise `mobility`/`singular`.
    `restating()`, when given, marks the driver rows that only restate a joint."""
    m, n = a.shape
    scaled = scale_system(a, translation_columns, length)
    # one SVD for the solve and the diagnosis (an underdetermined system is only diagnosed)
    svd = np.linalg.svd(scaled.matrix, full_matrices=False) if m >= n else None
    diag = diagnose(scaled.matrix, is_driver, svd[1] if svd is not None and scaled.matrix.size else None)
    if svd is None or diag.condition_number > SINGULAR_CONDITION:
        raise underdetermined_error(scaled.matrix, is_driver, labels, wheres, body_of, diag,
                                    restating() if restating else None)
    u, s, vt = svd
    rows, blocks = list(range(m)), []
    if want_blocks:
        rows = independent_rows(scaled.matrix, n)
        blocks = _blocks(a[rows], rows)
    return Analysis(scaled, u, s, vt, diag, rows, blocks)


def independent_rows(a: np.ndarray, n: int) -> list[int]:
    """n linearly independent rows, chosen greedily (Gram–Schmidt, joints before drivers)."""
    basis: list[np.ndarray] = []
    chosen: list[int] = []
    for i, row in enumerate(a):
        residual = row.astype(float).copy()
        for q in basis:
            residual -= (q @ residual) * q
        size = float(np.linalg.norm(residual))
        if size > 1e-9 * max(float(np.linalg.norm(row)), 1e-300):
            basis.append(residual / size)
            chosen.append(i)
            if len(chosen) == n:
                break
    return chosen


def _blocks(a_rows: np.ndarray, rows: list[int]) -> list[tuple[list[int], list[int]]]:
    """Block-triangular order of a square nonsingular system (Dulmage–Mendelsohn fine blocks)."""
    n = a_rows.shape[1]
    top = np.abs(a_rows).max(initial=0.0)
    pattern = np.abs(a_rows) > 1e-12 * max(top, 1e-300)
    match = _matching(pattern)
    # row i is matched to column match[i]; unknown match[i] depends on the others of row i
    row_of_col = {c: i for i, c in enumerate(match)}
    deps = [[int(k) for k in np.flatnonzero(pattern[row_of_col[c]]) if k != c] for c in range(n)]
    order = tarjan(n, deps)
    return [([rows[row_of_col[c]] for c in comp], comp) for comp in order]


def _matching(pattern: np.ndarray) -> list[int]:
    """A perfect matching of rows to columns over the nonzeros (augmenting paths)."""
    n = pattern.shape[0]
    col_owner: dict[int, int] = {}
    options = [[int(c) for c in np.flatnonzero(pattern[i])] for i in range(n)]

    def augment(i: int, seen: set[int]) -> bool:
        for c in options[i]:
            if c in seen:
                continue
            seen.add(c)
            if c not in col_owner or augment(col_owner[c], seen):
                col_owner[c] = i
                return True
        return False

    for i in range(n):
        if not augment(i, set()):
            raise KinematikaError("singular", "structurally-singular", "drivers")
    match = [0] * n
    for c, i in col_owner.items():
        match[i] = int(c)
    return match
