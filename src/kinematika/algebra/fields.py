"""Exact arithmetic in a field of rational functions, for fast symbolic solving.

sympy's general expressions are slow to simplify; rational functions over QQ in a fixed
set of generators are fast and canonical (numerator and denominator kept coprime). The
generators are the model's symbols and stand-ins for every irrational atom (``sqrt(3)``,
``cos(theta)``, ``pi``); substituting the atoms back gives an ordinary sympy expression.
"""
from __future__ import annotations

from typing import Any, Iterable


class RationalField:
    """QQ(symbols, atoms) with conversions from and back to sympy expressions."""

    def __init__(self, exprs: Iterable[Any]) -> None:
        import sympy

        self.sp = sympy
        self.atoms: dict[Any, Any] = {}
        symbols: set = set()
        lifted = [self._lift(sympy.sympify(e), symbols) for e in exprs]
        del lifted
        self.gens = sorted(symbols, key=str) + list(self.atoms.values())
        self.back_map = {d: a for a, d in self.atoms.items()}
        self.domain = sympy.QQ.frac_field(*self.gens) if self.gens else sympy.QQ

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

    def covers(self, exprs: Iterable[Any]) -> bool:
        """Whether every symbol and atom of `exprs` is a generator already."""
        symbols: set = set()
        known = dict(self.atoms)
        for e in exprs:
            self._lift(self.sp.sympify(e), symbols)
        fresh = set(self.atoms) - set(known)
        if fresh:
            for a in fresh:
                del self.atoms[a]
            return False
        return symbols <= set(self.gens)

    def to(self, e: Any) -> Any:
        return self.domain.from_sympy(self._lift(self.sp.sympify(e), set()))

    def back(self, x: Any) -> Any:
        return self.domain.to_sympy(x).xreplace(self.back_map)


def canonical(e: Any) -> Any:
    """`e` as a quotient of coprime expanded polynomials, factored for reading."""
    import sympy

    e = sympy.sympify(e)
    if e.is_Atom:
        return e
    field = RationalField([e])
    value = field.back(field.to(e))
    return sympy.factor(value) if value.free_symbols else sympy.radsimp(value)
