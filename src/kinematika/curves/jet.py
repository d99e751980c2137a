"""Jets: a quantity with its first derivatives along one parameter, carried through formulas.

A curve defined by a formula of its parameter (a cam's pitch curve is the follower's trace
point turned back by the cam angle, its profile that curve offset along its normal) has exact
derivatives, but writing them out by hand for every follower is long and error-prone. A
`Jet` holds f, f', f'', f''' (numpy arrays, derivatives with respect to the curve's
parameter u) and its arithmetic applies the rules of calculus as it goes (forward-mode
automatic differentiation of order 3):

- product (Leibniz): (fg)' = f'g + fg',  (fg)'' = f''g + 2f'g' + fg'',
  (fg)''' = f'''g + 3f''g' + 3f'g'' + fg''';
- composition F∘g (Faà di Bruno): (F∘g)' = F'·g',  (F∘g)'' = F''·g'² + F'·g'',
  (F∘g)''' = F'''·g'³ + 3F''·g'·g'' + F'·g'''.

A formula is then written once, as for numbers, and its derivatives are exact to rounding.
`derivative()` drops one order (the jet of f' from the jet of f), so a normal computed from
a third-order point is known to second order: enough for a point, d1 and d2.
"""
from __future__ import annotations

from typing import Callable, Sequence, Union

import numpy as np

Number = Union[float, np.ndarray]
Operand = Union["Jet", float, int, np.ndarray]


class Jet:
    """f and its derivatives f', f'', … (up to third order) along one parameter."""

    __slots__ = ("terms",)
    __array_priority__ = 100        # numpy arrays defer to the jet's operators

    def __init__(self, terms: Sequence[Number]) -> None:
        self.terms = tuple(np.asarray(t, dtype=float) for t in terms)

    @classmethod
    def variable(cls, u: Number, order: int = 3) -> Jet:
        """The parameter itself: u, 1, 0, 0."""
        u = np.asarray(u, dtype=float)
        return cls([u, np.ones_like(u)] + [np.zeros_like(u)] * (order - 1))

    @classmethod
    def constant(cls, c: Number, order: int = 3) -> Jet:
        """A constant: c, 0, 0, 0."""
        c = np.asarray(c, dtype=float)
        return cls([c] + [np.zeros_like(c)] * order)

    @property
    def order(self) -> int:
        """How many derivatives the jet carries."""
        return len(self.terms) - 1

    @property
    def value(self) -> np.ndarray:
        """f itself."""
        return self.terms[0]

    def d(self, k: int = 1) -> np.ndarray:
        """The k-th derivative f⁽ᵏ⁾."""
        return self.terms[k]

    def derivative(self) -> Jet:
        """The jet of f' (one order fewer)."""
        return Jet(self.terms[1:])

    # arithmetic ----------------------------------------------------------------------
    def _lift(self, other: Operand) -> Jet:
        return other if isinstance(other, Jet) else Jet.constant(other, self.order)

    def __add__(self, other: Operand) -> Jet:
        o = self._lift(other)
        return Jet([a + b for a, b in zip(self.terms, o.terms)])

    __radd__ = __add__

    def __neg__(self) -> Jet:
        return Jet([-a for a in self.terms])

    def __sub__(self, other: Operand) -> Jet:
        return self + (-self._lift(other))

    def __rsub__(self, other: Operand) -> Jet:
        return self._lift(other) - self

    def __mul__(self, other: Operand) -> Jet:
        if not isinstance(other, Jet):
            c = np.asarray(other, dtype=float)
            return Jet([a * c for a in self.terms])
        n = min(self.order, other.order)
        f, g = self.terms, other.terms
        out = [f[0] * g[0]]
        if n >= 1:
            out.append(f[1] * g[0] + f[0] * g[1])
        if n >= 2:
            out.append(f[2] * g[0] + 2 * f[1] * g[1] + f[0] * g[2])
        if n >= 3:
            out.append(f[3] * g[0] + 3 * f[2] * g[1] + 3 * f[1] * g[2] + f[0] * g[3])
        return Jet(out)

    __rmul__ = __mul__

    def __truediv__(self, other: Operand) -> Jet:
        if not isinstance(other, Jet):
            return self * (1.0 / np.asarray(other, dtype=float))
        return self * other.reciprocal()

    def __rtruediv__(self, other: Operand) -> Jet:
        return self.reciprocal() * other

    def compose(self, f0: Number, f1: Number, f2: Number = 0.0, f3: Number = 0.0) -> Jet:
        """F∘self, given F and its derivatives F', F'', F''' at self's value (Faà di Bruno)."""
        g = self.terms
        out = [np.asarray(f0, dtype=float) + 0 * g[0]]
        if self.order >= 1:
            out.append(f1 * g[1])
        if self.order >= 2:
            out.append(f2 * g[1] ** 2 + f1 * g[2])
        if self.order >= 3:
            out.append(f3 * g[1] ** 3 + 3 * f2 * g[1] * g[2] + f1 * g[3])
        return Jet(out)

    def reciprocal(self) -> Jet:
        """1/f: F' = −1/x², F'' = 2/x³, F''' = −6/x⁴."""
        x = self.value
        return self.compose(1 / x, -1 / x**2, 2 / x**3, -6 / x**4)


def sin(g: Jet) -> Jet:
    """sin g."""
    s, c = np.sin(g.value), np.cos(g.value)
    return g.compose(s, c, -s, -c)


def cos(g: Jet) -> Jet:
    """cos g."""
    s, c = np.sin(g.value), np.cos(g.value)
    return g.compose(c, -s, -c, s)


def sqrt(g: Jet) -> Jet:
    """√g: F' = 1/(2√x), F'' = −1/(4x^{3/2}), F''' = 3/(8x^{5/2})."""
    r = np.sqrt(g.value)
    return g.compose(r, 0.5 / r, -0.25 / r**3, 0.375 / r**5)


def hypot(x: Jet, y: Jet) -> Jet:
    """√(x² + y²)."""
    return sqrt(x * x + y * y)


def arctan(g: Jet) -> Jet:
    """arctan g: F' = 1/(1+x²), F'' = −2x/(1+x²)², F''' = (6x² − 2)/(1+x²)³."""
    x = g.value
    q = 1 + x * x
    return g.compose(np.arctan(x), 1 / q, -2 * x / q**2, (6 * x * x - 2) / q**3)


def of(function: Callable[[np.ndarray], Sequence[Number]], g: Jet) -> Jet:
    """F∘g for a function returning (F, F', F'', F''') at an array of values."""
    return g.compose(*function(g.value))


def rotate(x: Jet, y: Jet, angle: Jet) -> tuple[Jet, Jet]:
    """The vector (x, y) turned counter-clockwise by `angle`."""
    c, s = cos(angle), sin(angle)
    return x * c - y * s, x * s + y * c
