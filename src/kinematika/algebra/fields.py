"""Exact arithmetic in a field of rational functions, for fast symbolic solving.

sympy's general expressions are slow to simplify; rational functions over QQ in a fixed
set of generators are fast and canonical (numerator and denominator kept coprime). The
generators are the model's symbols and stand-ins for every irrational atom (``sqrt(3)``,
``cos(theta)``, ``pi``); substituting the atoms back gives an ordinary sympy expression.
"""
from __future__ import annotations

import functools

from typing import Any, Iterable


class RationalField:
    """QQ(symbols, atoms) with conversions from and back to sympy expressions."""

    def __init__(self, exprs: Iterable[Any]) -> None:
        import sympy

        self.sp = sympy
        self.atoms: dict[Any, Any] = {}
        symbols: set = set()
        for e in exprs:
            self._lift(sympy.sympify(e), symbols)
        # sines first, so that lex division by sin² + cos² − 1 removes the sines' squares
        atoms = sorted(self.atoms, key=lambda a: not isinstance(a, sympy.sin))
        self.gens = sorted(symbols, key=str) + [self.atoms[a] for a in atoms]
        self.back_map = {d: a for a, d in self.atoms.items()}
        self.domain = sympy.QQ.frac_field(*self.gens) if self.gens else sympy.QQ
        self.pythagoras = [(self.atoms[a], self.atoms[sympy.cos(a.args[0])]) for a in atoms
                           if isinstance(a, sympy.sin) and sympy.cos(a.args[0]) in self.atoms]

    def _lift(self, e: Any, symbols: set) -> Any:
        """`e` with each irrational atom replaced by its stand-in symbol."""
        sp = self.sp
        if e.is_Symbol:
            symbols.add(e)
            return e
        if e.is_Rational:
            return e
        if e.is_Add or e.is_Mul:
            return e.func(*[self._lift(a, symbols) for a in e.args])
        if e.is_Pow and e.exp.is_Integer:
            return self._lift(e.base, symbols) ** e.exp
        if e.is_Float:
            return sp.Rational(str(e))
        if e not in self.atoms:
            self.atoms[e] = sp.Dummy(f"atom{len(self.atoms)}")
        return self.atoms[e]

    def to(self, e: Any) -> Any:
        return self.domain.from_sympy(self._lift(self.sp.sympify(e), set()))

    def back(self, x: Any) -> Any:
        return self.domain.to_sympy(x).xreplace(self.back_map)

    def reduce_trig(self, x: Any) -> Any:
        """Numerator and denominator reduced by sin²u + cos²u = 1 (at most linear in sin u)."""
        if not self.pythagoras:
            return x
        ring = self.domain.field.ring
        index = {g: i for i, g in enumerate(self.gens)}
        identities = [ring.gens[index[s]] ** 2 + ring.gens[index[c]] ** 2 - 1
                      for s, c in self.pythagoras]
        return self.domain.field.new(x.numer.rem(identities), x.denom.rem(identities))


def canonical(e: Any) -> Any:
    """`e` as a quotient of coprime expanded polynomials, factored for reading."""
    import sympy

    e = sympy.sympify(e)
    return e if e.is_Atom else _canonical(e)


@functools.lru_cache(maxsize=4096)
def _canonical(e: Any) -> Any:
    """`canonical` of a compound expression, remembered: the same velocity is often asked of
    several material points, and the same value both in the answers and in the tables."""
    import sympy

    field = RationalField([e])
    value = field.back(field.reduce_trig(field.to(e)))
    return sympy.factor(value) if value.free_symbols else sympy.radsimp(value)
