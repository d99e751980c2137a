"""Linear algebra on stacks of small matrices (one per sweep position), as numpy arrays:
products, norms, matrices certified regular, and solves refined from a neighbour's inverse."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

REFINEMENTS = 40            # iterations of a solve from a neighbour's inverse (each ≤ ½ the last)


def times(a: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Stacked matrix-vector products: (…, i, j) · (…, j) → (…, i)."""
    return (a @ x[..., None])[..., 0]


def dot(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Stacked dot products: (…, i) · (…, i) → (…)."""
    return np.einsum("...i,...i->...", u, v)


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Stacked cross products (…, 3): as np.cross, with less overhead on small arrays."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


@dataclass
class Regular:
    """Matrices A = R⁻¹ S C⁻¹ certified regular: S, S⁻¹, C's and R's diagonals, ‖S‖₁, ‖S⁻¹‖₁."""

    scaled: np.ndarray
    s_inv: np.ndarray
    column: np.ndarray
    rows: np.ndarray
    size: np.ndarray
    size_inv: np.ndarray

    def inverse(self) -> np.ndarray:
        """A⁻¹ = C S⁻¹ R, formed (the chord iterations apply it many times)."""
        return self.column[None, :, None] * self.s_inv * self.rows[:, None, :]

    def solve(self, b: np.ndarray) -> np.ndarray:
        """A x = b for every stacked matrix: x = C S⁻¹ R b."""
        return self.column * times(self.s_inv, self.rows * b)


class Twists:
    """Every row's twists and their rates, filled as they are found."""

    def __init__(self, n_rows: int, n: int) -> None:
        self.x_v, self.x_a = np.zeros((n_rows, n)), np.zeros((n_rows, n))
        self.known = np.zeros(n_rows, dtype=bool)

    def put(self, rows, x_v, x_a) -> None:
        """The twists x_v = (ω, v₀) and their rates x_a = (α, a₀) of rows `rows`, found."""
        self.x_v[rows], self.x_a[rows], self.known[rows] = x_v, x_a, True


def norm1(a: np.ndarray, in_place: bool = False) -> np.ndarray:
    """Stacked matrices' 1-norms (largest column sum); `in_place` overwrites a with |a|."""
    return np.abs(a, out=a if in_place else None).sum(axis=-2).max(axis=-1)


def refined(s: np.ndarray, p: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """S y = b by y ← y + P(b − S y) from y = P b, P ≈ S⁻¹, until the error left (the last
    correction times its ratio to the one before) is within a few round-offs of y or the
    corrections stop shrinking; with the rows where that error is below 1e-14 of y (what an
    explicit inverse leaves at condition numbers of a hundred)."""
    y = times(p, b)
    scale = np.abs(y).sum(axis=-1)          # y's size: changed by far less than itself below
    last = left = np.full(len(b), np.inf)
    for _ in range(REFINEMENTS):
        dy = times(p, b - times(s, y))
        y += dy
        size = np.abs(dy).sum(axis=-1)
        left = size * (np.minimum(size / np.maximum(last, 1e-300), 0.5) if np.isfinite(last).all() else 0.5)
        if ((left <= 1e-15 * scale) | (size > 0.5 * last)).all():
            break
        last = size
    return y, left <= 1e-14 * scale
