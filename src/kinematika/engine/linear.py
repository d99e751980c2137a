"""Linear forms in the unknown twists: the rows of the velocity and acceleration systems.

A `Lin` is ``sum(coef[i] * x[i]) + const``; coefficients are floats or sympy expressions.
Every constraint is written as a `Lin` that must vanish, so one joint formula gives both
the velocity row and (with the known velocities in its constant) the acceleration row.
"""
from __future__ import annotations

from typing import Any


class Lin:
    """A linear form Σ coefᵢ·xᵢ + const in the unknown twists: what a joint's or a driver's
    condition is written as, and must vanish. It adds, subtracts and scales like a number (a
    product of two unknowns is refused), so the joint formulas are written once with ``+ − *``."""

    __slots__ = ("const", "terms")
    __array_ufunc__ = None   # numpy scalars defer to us instead of building object arrays

    def __init__(self, terms: dict[int, Any] | None = None, const: Any = 0) -> None:
        self.terms = terms or {}
        self.const = const

    @staticmethod
    def unknown(index: int) -> "Lin":
        """The unknown xᵢ itself: coefficient 1 at column `index`, no constant."""
        return Lin({index: 1})

    def __add__(self, other: Any) -> "Lin":
        if isinstance(other, Lin):
            terms = dict(self.terms)
            for k, v in other.terms.items():
                terms[k] = terms[k] + v if k in terms else v
            return Lin(terms, self.const + other.const)
        return Lin(self.terms, self.const + other)

    __radd__ = __add__

    def __neg__(self) -> "Lin":
        return Lin({k: -v for k, v in self.terms.items()}, -self.const)

    def __sub__(self, other: Any) -> "Lin":
        # self + (-other), without the negated form: the same operations, term by term
        if isinstance(other, Lin):
            terms = dict(self.terms)
            for k, v in other.terms.items():
                terms[k] = terms[k] + (-v) if k in terms else -v
            return Lin(terms, self.const + (-other.const))
        return Lin(self.terms, self.const + (-other))

    def __rsub__(self, other: Any) -> "Lin":
        return (-self) + other

    def __mul__(self, k: Any) -> "Lin":
        if isinstance(k, Lin):
            raise TypeError("a product of two unknowns is not linear")
        if isinstance(k, (int, float)) and k == 0:
            return Lin()
        return Lin({i: v * k for i, v in self.terms.items()}, self.const * k)

    __rmul__ = __mul__

    def __truediv__(self, k: Any) -> "Lin":
        return Lin({i: v / k for i, v in self.terms.items()}, self.const / k)

    def __repr__(self) -> str:
        parts = [f"{v}*x{k}" for k, v in sorted(self.terms.items())]
        return " + ".join(parts + [str(self.const)])


def as_lin(x: Any) -> Lin:
    """A constant (from a fixed body's zero motion) as a linear form without unknowns."""
    return x if isinstance(x, Lin) else Lin(const=x)
