"""Solving the linear systems, on numbers or on symbols, with one analysis of their matrix.

The velocity and acceleration systems share the matrix A, so it is analysed once: made
dimensionless, its rank and condition checked (`mobility`), a square set of independent
rows chosen, and, for exact solving, ordered into blocks (block-triangular form via a
matching of rows to unknowns and the strongly connected components of the dependencies).
Each block is then a small system solved exactly, in order; numerically the whole system
is solved with the SVD computed for the analysis.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Callable, Sequence

import numpy as np

from ..errors import KinematikaError
from .blocks import BlockLU, SparseRows
from .mobility import SINGULAR_CONDITION, Diagnosis, Scaled, conflict_error

if TYPE_CHECKING:
    from .dense import Analysis


CONSISTENT = 1e-6   # relative residual of redundant conditions that still agree (geometry given to ~1e-6)


def solve_numeric(an: Analysis | SparseAnalysis, b: np.ndarray, labels: Sequence[Any], wheres: Sequence[str],
                  is_driver: np.ndarray, check: bool = True, natural: float = 0.0) -> np.ndarray:
    """Least squares with the analysis' SVD (or sparse LU); a residual means conflicting
    conditions. It is measured against the size of the right side and of the solution, and
    at least against `natural`, the size they have in the mechanism's own units (its rate, or
    the rate squared for accelerations): a right side that is all round-off (a train turning
    rigidly at a constant rate: every acceleration term cancels) is no conflict."""
    bs = b * an.scaled.row_scale
    if isinstance(an, SparseAnalysis):
        xs = an.lu.refined(bs) if isinstance(an.lu, BlockLU) else an.lu.solve(bs)
    else:
        y = (an.u.T @ bs) / an.s
        xs = an.vt.T @ y
    if check:
        residual = an.scaled.matrix @ xs - bs
        top = 1.0 if isinstance(an, SparseAnalysis) else _largest(an.scaled.matrix)
        size = max(_largest(bs), top * _largest(xs), natural, 1e-300)
        if _largest(residual) > CONSISTENT * size:
            raise conflict_error(residual, labels, wheres, is_driver, an.diagnosis)
    return xs * an.scaled.col_scale


def _largest(x: np.ndarray) -> float:
    """max |xᵢ| (0 for no entries): `np.abs(x).max(initial=0.0)`, the same reduction without
    the method's Python wrapper (a motion in time asks for it four times an instant)."""
    return _MAXIMUM(np.abs(x), axis=None, initial=0.0)


_MAXIMUM = np.maximum.reduce


# large systems: sparse LU ------------------------------------------------------------------
LARGE = 150      # unknowns above which a numeric system is kept sparse
DENSE_DIAGNOSIS = 3000   # largest system whose failure is explained with the dense SVD


@dataclass
class SparseAnalysis:
    """A square, nonsingular, dimensionless sparse system factorised by LU."""

    scaled: Scaled[SparseRows]
    lu: Any
    diagnosis: Diagnosis
    rows: list[int]
    blocks: list = field(default_factory=list)


def sparse_matrix(rows: list[Any], n: int) -> SparseRows:
    """The rows' coefficients as a sparse matrix by rows (numeric rows only)."""
    indptr, cols, vals = [0], [], []
    for row in rows:
        terms = row.lin.terms
        cols += terms.keys()
        vals += terms.values()
        indptr.append(len(cols))
    return SparseRows(np.array(indptr), np.array(cols, dtype=np.int64), np.array(vals, dtype=float),
                      (len(rows), n))


def analyse_sparse(a: SparseRows, is_driver: np.ndarray, translation_columns: np.ndarray, length: float,
                   labels: Sequence[Any], wheres: Sequence[str], body_of: list[str],
                   restating: Any = None) -> Analysis | SparseAnalysis:
    """`analyse` for a large sparse system: scaling, a block LU (`blocks`, or scipy's sparse
    LU when the blocks are large) and a 1-norm condition estimate.

    A square system whose LU succeeds with condition number below the limit is solved by the
    LU. Any other (redundant rows, rank deficiency, a dead point) goes to the dense analysis,
    which gives the same answers and messages as for a small system.
    """
    m, n = a.shape
    col = np.where(translation_columns, length, 1.0)
    norms = a.scaled(np.ones(m), col).row_max()
    row = np.where(norms > 0, 1.0 / np.where(norms > 0, norms, 1.0), 1.0)
    scaled = a.scaled(row, col)
    if m == n:
        lu = BlockLU.factor(scaled) or _scipy_lu(scaled)
        if lu is not None:
            cond = float(scaled.column_sums().max()) * inverse_norm(lu, n)
            if np.isfinite(cond) and cond <= SINGULAR_CONDITION:
                given = int(is_driver.sum())
                return SparseAnalysis(Scaled(scaled, row, col), lu, Diagnosis(n, given, given, cond),
                                      list(range(m)))
    if n > DENSE_DIAGNOSIS:
        raise KinematikaError("singular", "jacobian-singular-large", "drivers", rows=m, columns=n)
    from .dense import analyse       # (defined only where a dense analysis is made: see its module)

    return analyse(a.toarray(), is_driver, translation_columns, length, labels, wheres, body_of,
                   restating=restating)


def _scipy_lu(a: SparseRows) -> Any:
    """scipy's sparse LU of a square matrix, or None when it is singular."""
    from scipy.sparse.linalg import splu

    try:
        return splu(a.to_scipy().tocsc())
    except RuntimeError:
        return None


def inverse_norm(lu: Any, n: int, steps: int = 5) -> float:
    """An estimate of ‖A⁻¹‖₁ from A's LU (a lower bound, almost always the exact value):
    Hager's method as LAPACK's xLACN2 does it, with Higham's extra test vector; a few solves
    with A and Aᵀ, in linear time (scipy's `onenormest` checks its sign vectors for
    parallel pairs in quadratic time) and always the same answer (no random vectors)."""
    with np.errstate(all="ignore"):
        x = np.full(n, 1.0 / n)
        estimate, signs = 0.0, np.zeros(0)        # no signs yet: the first step never compares them
        for step in range(steps):
            y = lu.solve(x)
            size = float(np.abs(y).sum())
            new_signs = np.where(y >= 0, 1.0, -1.0)
            if step and (size <= estimate or np.array_equal(new_signs, signs)):
                estimate = max(estimate, size)
                break
            estimate, signs = size, new_signs
            z = lu.solve(signs, trans="T")
            j = int(np.argmax(np.abs(z)))
            if step and abs(z[j]) <= z @ x:
                break
            x = np.zeros(n)
            x[j] = 1.0
        alternating = np.where(np.arange(n) % 2, -1.0, 1.0) * (1.0 + np.arange(n) / max(n - 1, 1))
        extra = 2.0 * float(np.abs(lu.solve(alternating)).sum()) / (3.0 * n)
    value = max(estimate, extra)
    return value if np.isfinite(value) else float("inf")


def solve_symbolic(an: Analysis, a_sym: Sequence[Sequence[Any]], b_sym: Sequence[Any],
                   a_num: np.ndarray, name: Callable[[int, Any], Any] | None = None) -> list[Any]:
    """Exact solution, block by block in dependency order, in a field of rational functions.

    With `name`, each solved unknown is passed on to later blocks as `name(column, value)`
    (a stand-in symbol for a compound value): a later loop of a multi-loop linkage is then
    solved in its own small terms, not with the earlier loops' formulas written in, and
    each block in its own field of rational functions."""
    from ..algebra.fields import RationalField

    n = a_num.shape[1]
    if name is None:
        used = [r for rows, _ in an.blocks for r in rows]
        entries = [a_sym[r][c] for r in used for c in range(n) if _nonzero(a_num[r, c], a_num)]
        field = RationalField(entries + [b_sym[r] for r in used])
        x: dict[int, Any] = {}
        for rows, cols in an.blocks:
            x.update(zip(cols, _solve_block(field, rows, cols, a_sym, b_sym, a_num, x)))
        return [field.back(x[c]) for c in range(n)]
    out: dict[int, Any] = {}
    passed: dict[int, Any] = {}           # what later blocks read of each solved unknown
    for rows, cols in an.blocks:
        known = {r: b_sym[r] - sum((a_sym[r][c] * v for c, v in passed.items()
                                    if _nonzero(a_num[r, c], a_num)), 0) for r in rows}
        entries = [a_sym[r][c] for r in rows for c in cols if _nonzero(a_num[r, c], a_num)]
        field = RationalField(entries + list(known.values()))
        solved = _solve_block(field, rows, cols, a_sym, known, a_num, {})
        for c, value in zip(cols, solved):
            out[c] = field.back(value)
            passed[c] = name(c, out[c])
    return [out[c] for c in range(n)]


def _solve_block(field: Any, rows: list[int], cols: list[int], a_sym: Sequence[Sequence[Any]],
                 b_sym: Any, a_num: np.ndarray, x: dict[int, Any]) -> list[Any]:
    """One block's unknowns in `field`, the unknowns `x` of earlier blocks known."""
    to = field.to
    rhs = []
    for r in rows:
        value = to(b_sym[r])
        for c, xc in x.items():
            if _nonzero(a_num[r, c], a_num):
                value -= to(a_sym[r][c]) * xc
        rhs.append(value)
    block = [[to(a_sym[r][c]) if _nonzero(a_num[r, c], a_num) else field.domain.zero
              for c in cols] for r in rows]
    return _eliminate(block, rhs, a_num[np.ix_(rows, cols)])


def _nonzero(value: float, a_num: np.ndarray) -> bool:
    return abs(value) > 1e-12 * max(np.abs(a_num).max(initial=0.0), 1e-300)


SPARSE_BLOCK = 7     # blocks from this size up are eliminated in the order of least fill


def _eliminate(block: list[list[Any]], rhs: list[Any], numeric: np.ndarray) -> list[Any]:
    """Gaussian elimination on field elements, pivoting on the numeric twin of the block."""
    k = len(rhs)
    if k == 1:
        return [rhs[0] / block[0][0]]
    if k >= SPARSE_BLOCK:
        return _eliminate_sparse(block, rhs, numeric)
    a = [row[:] + [r] for row, r in zip(block, rhs)]
    num = numeric.astype(float).copy()
    for col in range(k):
        pivot = col + int(np.argmax(np.abs(num[col:, col])))
        a[col], a[pivot] = a[pivot], a[col]
        num[[col, pivot]] = num[[pivot, col]]
        for row in range(col + 1, k):
            if num[row, col] == 0 and not a[row][col]:
                continue
            factor = a[row][col] / a[col][col]
            ratio = num[row, col] / num[col, col]
            a[row] = [x - factor * y for x, y in zip(a[row], a[col])]
            num[row] -= ratio * num[col]
    out: list[Any] = [None] * k
    for row in reversed(range(k)):
        value = a[row][k]
        for c in range(row + 1, k):
            value -= a[row][c] * out[c]
        out[row] = value / a[row][row]
    return out


def _eliminate_sparse(block: list[list[Any]], rhs: list[Any], numeric: np.ndarray) -> list[Any]:
    """Gaussian elimination for a large block (a triad's 12 unknowns): exact arithmetic
    needs no pivoting for size, so each pivot is the entry that creates the least fill-in
    (Markowitz: (row's nonzeros − 1)·(column's nonzeros − 1)), a plain number before a
    formula (the ±1 of a joint's velocity terms eliminates v₀ without fractions), among
    entries not negligible numerically. Far cheaper than partial pivoting, which fills the
    block with long entries."""
    k = len(rhs)
    rows = [{c: v for c, v in enumerate(row) if v} for row in block]
    right = list(rhs)
    num = numeric.astype(float).copy()
    top = np.abs(num).max(initial=0.0)
    order: list[tuple[int, int]] = []           # (row, column) of each pivot
    live_rows, live_cols = set(range(k)), set(range(k))
    for _ in range(k):
        col_count = dict.fromkeys(live_cols, 0)
        for r in live_rows:
            for c in rows[r]:
                if c in col_count:
                    col_count[c] += 1
        best = None
        for r in live_rows:
            n_r = sum(1 for c in rows[r] if c in live_cols)
            for c, v in rows[r].items():
                if c not in live_cols or abs(num[r, c]) <= 1e-9 * top:
                    continue
                key = ((n_r - 1) * (col_count[c] - 1), not _plain(v), -abs(num[r, c]))
                if best is None or key < best[0]:
                    best = (key, r, c)
        if best is None:
            raise ZeroDivisionError("no pivot in an exact block")
        _, pr, pc = best
        order.append((pr, pc))
        live_rows.discard(pr)
        live_cols.discard(pc)
        pivot_row, pivot = rows[pr], rows[pr][pc]
        for r in live_rows:
            factor_v = rows[r].get(pc)
            if not factor_v:
                continue
            factor = factor_v / pivot
            ratio = num[r, pc] / num[pr, pc]
            target = rows[r]
            for c, v in pivot_row.items():
                if c == pc:
                    continue
                new = target.get(c, 0) - factor * v if c in target else -(factor * v)
                if new:
                    target[c] = new
                else:
                    target.pop(c, None)
            del target[pc]
            right[r] = right[r] - factor * right[pr]
            num[r] -= ratio * num[pr]
            num[r, pc] = 0.0
    out: list[Any] = [None] * k
    for pr, pc in reversed(order):
        value = right[pr]
        for c, v in rows[pr].items():
            if c != pc:
                value -= v * out[c]
        out[pc] = value / rows[pr][pc]
    return out


def _plain(v: Any) -> bool:
    """A field element that is a number (no symbols, no atoms)."""
    try:
        return v.numer.is_ground and v.denom.is_ground
    except AttributeError:
        return True
