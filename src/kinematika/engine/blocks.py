"""Large sparse systems solved block by block, without scipy.

A mechanism's velocity matrix in block lower-triangular order (rows matched to unknowns,
then the strongly connected components of what each unknown depends on: the
Dulmage–Mendelsohn fine blocks) falls apart into small square blocks, a chain's loops or
a machine's Assur groups, solved one after the other. Consecutive blocks are merged up to
`MERGED` unknowns and every merged block is inverted densely in one stacked numpy call, so
a solve is a short Python loop of small products, one per block (its inverse and its
couplings to earlier blocks multiplied out once per factorisation, `_steps`). When a block is large, the matching
takes too long or a block is singular, `BlockLU.factor` returns None and the caller falls
back on scipy's sparse LU, whose import alone costs more CPU than a 1 000-body instant.
"""
from __future__ import annotations

from typing import Any, Optional, Sequence

import numpy as np

BLOCK_MAX = 64      # largest fine block solved as a dense matrix
MERGED = 24         # consecutive blocks merged up to this many unknowns (the inverses' n·MERGED²
                    # against one product per block and solve: 24 is the least for a long chain)
MATCH_WORK = 50     # matching steps allowed per nonzero before giving up (scipy decides)


class SparseRows:
    """A sparse matrix by rows (CSR arrays) with what the solves need: products, scaling,
    column sums, a dense or scipy copy for the diagnosis of a failure."""

    def __init__(self, indptr: np.ndarray, cols: np.ndarray, vals: np.ndarray, shape: tuple[int, int]):
        self.indptr, self.cols, self.vals, self.shape = indptr, cols, vals, shape
        self.row_index = np.repeat(np.arange(shape[0]), np.diff(indptr))

    def __matmul__(self, x: np.ndarray) -> np.ndarray:
        return np.bincount(self.row_index, weights=self.vals * x[self.cols], minlength=self.shape[0])

    def scaled(self, row: np.ndarray, col: np.ndarray) -> "SparseRows":
        """diag(row) · A · diag(col)."""
        return SparseRows(self.indptr, self.cols, self.vals * row[self.row_index] * col[self.cols],
                          self.shape)

    def row_max(self) -> np.ndarray:
        """The largest |a_ij| of every row (0 for an empty row)."""
        out = np.zeros(self.shape[0])
        np.maximum.at(out, self.row_index, np.abs(self.vals))
        return out

    def column_sums(self) -> np.ndarray:
        """Σ_i |a_ij| of every column (‖A‖₁ is their maximum)."""
        return np.bincount(self.cols, weights=np.abs(self.vals), minlength=self.shape[1])

    def toarray(self) -> np.ndarray:
        """The matrix as a dense numpy array (repeated entries of a row and column summed), to
        diagnose a failure by SVD."""
        out = np.zeros(self.shape)
        np.add.at(out, (self.row_index, self.cols), self.vals)
        return out

    def to_scipy(self) -> Any:
        """The matrix as a scipy CSR matrix, for scipy's sparse LU when the blocks cannot be
        used (scipy imported only then)."""
        from scipy.sparse import csr_matrix

        return csr_matrix((self.vals, self.cols, self.indptr), shape=self.shape)


class BlockLU:
    """A square matrix as merged diagonal blocks (inverted) and the entries below them.

    Rows and columns are renumbered in block order (`row_order`, `col_order`); block k holds
    positions start[k]:start[k+1] of both. `solve(b)` solves A x = b, `solve(c, trans="T")`
    Aᵀ y = c, as scipy's SuperLU does (so `linsolve.inverse_norm` takes either)."""

    def __init__(self, matrix, row_order, col_order, start, forward, backward) -> None:
        self.matrix = matrix
        self.row_order, self.col_order, self.start = row_order, col_order, start
        self.forward = forward            # per block, in order: (start, end, H, where), see `_steps`
        self.backward = backward          # the same for Aᵀ, last block first
        self.n = len(col_order)

    @classmethod
    def factor(cls, a: SparseRows) -> Optional["BlockLU"]:
        """The block form of a square matrix, or None (scipy's LU must decide)."""
        m, n = a.shape
        if m != n or n == 0:
            return None
        nonzero = a.vals != 0
        cols_all = a.cols.tolist()
        ptr = a.indptr.tolist()
        if nonzero.all():
            rows = [cols_all[ptr[i]:ptr[i + 1]] for i in range(m)]
        else:
            keep = nonzero.tolist()
            rows = [[c for c, k in zip(cols_all[ptr[i]:ptr[i + 1]], keep[ptr[i]:ptr[i + 1]]) if k]
                    for i in range(m)]
        col_row = _match(rows, n, MATCH_WORK * max(len(cols_all), 1))
        if col_row is None:
            return None
        blocks = _merged(_in_own_order(a.row_index[nonzero], a.cols[nonzero], col_row)
                         or tarjan(n, [rows[r] for r in col_row]))  # column c depends on its row's others
        if blocks is None:
            return None
        col_order = np.array([c for block in blocks for c in block], dtype=np.int64)
        row_order = np.array(col_row, dtype=np.int64)[col_order]
        sizes = np.array([len(b) for b in blocks], dtype=np.int64)
        start = np.r_[0, np.cumsum(sizes)]
        block_of = np.repeat(np.arange(len(blocks)), sizes)
        row_pos, col_pos = np.empty(n, np.int64), np.empty(n, np.int64)
        row_pos[row_order], col_pos[col_order] = np.arange(n), np.arange(n)
        r = row_pos[a.row_index[nonzero]]
        c = col_pos[a.cols[nonzero]]
        v = a.vals[nonzero]
        rb, cb = block_of[r], block_of[c]
        width = int(sizes.max())
        dense = np.zeros((len(blocks), width, width))
        pad = np.arange(width)[None, :] >= sizes[:, None]
        dense[:, np.arange(width), np.arange(width)] = pad
        diagonal = rb == cb
        dense[rb[diagonal], r[diagonal] - start[rb[diagonal]], c[diagonal] - start[cb[diagonal]]] = v[diagonal]
        try:
            inverses = np.linalg.inv(dense)
        except np.linalg.LinAlgError:
            return None
        if not np.isfinite(inverses).all():
            return None
        low = cb < rb                    # entries left of the diagonal blocks (none are right of them)
        forward = _steps(inverses, start, n, rb[low], r[low] - start[rb[low]], c[low], v[low])
        backward = _steps(inverses.transpose(0, 2, 1), start, n, cb[low], c[low] - start[cb[low]],
                          r[low], v[low])[::-1]
        return cls(a, row_order, col_order, start, forward, backward)

    def refined(self, b: np.ndarray) -> np.ndarray:
        """A x = b with one step of iterative refinement: solving with the blocks' explicit
        inverses loses digits as a block's condition grows; the residual's solve wins them back."""
        x = self.solve(b)
        return x + self.solve(b - self.matrix @ x)

    def solve(self, b: np.ndarray, trans: str = "N") -> np.ndarray:
        """x with A x = b (``trans="N"``) or Aᵀ x = b (``trans="T"``): forward through the
        blocks in order, backwards for the transpose, as scipy's SuperLU solves. One vector
        holds the unknowns found so far and the right side (`_steps`); each block's unknowns
        are one product of its matrix with the entries it reads of that vector."""
        n = self.n
        first, then = (self.row_order, self.col_order) if trans == "N" else (self.col_order, self.row_order)
        known = np.empty(2 * n)
        known[n:2 * n] = b[first]
        dot = np.dot                      # (a tenth cheaper than `@` on a block's small product)
        for s0, s1, h, where in (self.forward if trans == "N" else self.backward):
            known[s0:s1] = dot(h, known[where])
        out = np.empty(n)
        out[then] = known[:n]
        return out


def _steps(inverses: np.ndarray, start: np.ndarray, n: int, block: np.ndarray, local: np.ndarray,
           at: np.ndarray, value: np.ndarray) -> list[tuple[int, int, np.ndarray, np.ndarray]]:
    """Each block's solve as one product: block k's unknowns x_k (positions s0:s1) are
    A_kk⁻¹ (b_k − C_k x_at) = [A_kk⁻¹ | −A_kk⁻¹ C_k] · [b_k; x_at], C_k being the entries
    (`local` row, position `at`, `value`) coupling it to unknowns found before it. With the
    unknowns at 0:n of one vector and the right side at n:2n, that is H_k · v[where_k]:
    H_k = [A_kk⁻¹ | −A_kk⁻¹ C_k] and where_k the block's right side and the positions it reads
    (a block's inverse is applied once per solve, not once per coupling: the products are
    made here, once per factorisation)."""
    count = len(inverses)
    bounds = start.tolist()
    key = np.sort(block * n + at)                     # each block's distinct coupled positions, sorted
    distinct = np.ones(len(key), dtype=bool)          # (not np.unique: it imports numpy.ma)
    distinct[1:] = key[1:] != key[:-1]
    key = key[distinct]
    owner = key // n
    first = np.searchsorted(owner, np.arange(count + 1)).tolist()
    column = np.searchsorted(key, block * n + at) - np.asarray(first)[block]
    width = max((first[k + 1] - first[k] for k in range(count)), default=0)
    coupling = np.zeros((count, inverses.shape[1], width))
    np.add.at(coupling, (block, local, column), value)
    product = -(inverses @ coupling)
    reads = key % n
    out = []
    for k in range(count):
        s0, s1 = bounds[k], bounds[k + 1]
        size, used = s1 - s0, first[k + 1] - first[k]
        h = np.concatenate((inverses[k, :size, :size], product[k, :size, :used]), axis=1)
        out.append((s0, s1, h, np.concatenate((np.arange(n + s0, n + s1), reads[first[k]:first[k + 1]]))))
    return out


def _in_own_order(row_index: np.ndarray, cols: np.ndarray, col_row: list[int]) -> Optional[list[list[int]]]:
    """The unknowns in their own order as blocks, when that order is already block
    triangular in blocks of at most `MERGED` unknowns (else None: the components must be
    found). With row `col_row[p]` at place p, a block may end after place p when no row up to
    p has an entry right of p: the running maximum of the rows' last columns is p.

    A system written body after body usually is (a chain's unknowns, loop after loop), and
    then the components' walk (`tarjan`, Python over every edge: about 18 M instructions for
    3 000 unknowns) is spared; its blocks may be coarser than the components, never larger
    than a merged block."""
    n = len(col_row)
    row_pos = np.empty(n, np.int64)
    row_pos[col_row] = np.arange(n)
    reach = np.zeros(n, np.int64)
    np.maximum.at(reach, row_pos[row_index], cols)
    ends = (np.flatnonzero(np.maximum.accumulate(reach) <= np.arange(n)) + 1).tolist()
    starts = [0] + ends[:-1]
    if max(e - s for s, e in zip(starts, ends)) > MERGED:
        return None
    return [list(range(s, e)) for s, e in zip(starts, ends)]


def _merged(components: list[list[int]]) -> Optional[list[list[int]]]:
    """Consecutive components joined up to `MERGED` unknowns (None if one is too large)."""
    out: list[list[int]] = []
    for comp in components:
        if len(comp) > BLOCK_MAX:
            return None
        if out and len(out[-1]) + len(comp) <= MERGED:
            out[-1] += comp
        else:
            out.append(list(comp))
    return out


def _match(rows: list[list[int]], n: int, budget: int) -> Optional[list[int]]:
    """A perfect matching of rows to columns (the row of each column): a cheap pass, then
    augmenting paths by depth-first search with lookahead (Duff's MC21); None if there is
    none or it takes more than `budget` steps.

    The cheap pass takes the rows with fewest entries first (a short row has fewer columns
    to lose to the rows before it): a chain's two-entry rows then leave its longer rows the
    columns they need, and no augmenting path is searched (in row order, one per loop)."""
    col_row = [-1] * n
    row_col = [-1] * n
    look = [0] * n
    for i in sorted(range(len(rows)), key=list(map(len, rows)).__getitem__):
        cs = rows[i]
        for k, c in enumerate(cs):
            if col_row[c] < 0:
                col_row[c], row_col[i], look[i] = i, c, k + 1
                break
    work = 0
    for root in range(n):
        if row_col[root] >= 0:
            continue
        stack, pos, seen = [root], [0], set()
        via: list[int] = []
        found = -1
        while stack:
            r = stack[-1]
            cs = rows[r]
            k = look[r]
            while k < len(cs) and col_row[cs[k]] >= 0:
                k += 1
            look[r] = k
            if k < len(cs):
                found = cs[k]
                break
            k = pos[-1]
            while k < len(cs) and cs[k] in seen:
                k += 1
            work += 1
            if work > budget:
                return None
            if k == len(cs):
                stack.pop(), pos.pop()
                if via:
                    via.pop()
                continue
            c = cs[k]
            pos[-1] = k + 1
            seen.add(c)
            via.append(c)
            stack.append(col_row[c])
            pos.append(0)
        if found < 0:
            return None
        for r, c in zip(stack, via + [found]):
            col_row[c], row_col[r] = r, c
    return col_row


def tarjan(n: int, deps: Sequence[Sequence[int]]) -> list[list[int]]:
    """Strongly connected components, each after the components it depends on (iterative,
    the vertices' index and low-link in lists: one pass, linear in the edges). An edge from
    a vertex to itself changes nothing (its index is never below its own low-link).

    Each vertex on the depth-first path keeps an iterator over its edges, resumed after the
    vertex it led to is done; a component is the top of the stack from its root's place."""
    index = [-1] * n                # -1: not visited yet
    low = [0] * n
    place = [0] * n                 # a vertex's place in `stack`
    on_stack = [False] * n
    stack: list[int] = []
    out: list[list[int]] = []
    counter = 0
    for root in range(n):
        if index[root] >= 0:
            continue
        index[root] = low[root] = counter
        counter += 1
        place[root] = len(stack)
        stack.append(root)
        on_stack[root] = True
        work = [(root, iter(deps[root]))]
        while work:
            v, edges = work[-1]
            for w in edges:
                if index[w] < 0:
                    index[w] = low[w] = counter
                    counter += 1
                    place[w] = len(stack)
                    stack.append(w)
                    on_stack[w] = True
                    work.append((w, iter(deps[w])))
                    break
                if on_stack[w] and index[w] < low[v]:
                    low[v] = index[w]
            else:
                work.pop()
                if low[v] == index[v]:
                    at = place[v]
                    comp = stack[at:]
                    del stack[at:]
                    for w in comp:
                        on_stack[w] = False
                    comp.sort()
                    out.append(comp)
                if work:
                    parent = work[-1][0]
                    if low[v] < low[parent]:
                        low[parent] = low[v]
    return out
