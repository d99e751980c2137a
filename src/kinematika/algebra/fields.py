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
        self._back_symbols: list | None = None
        self._gen_of: dict | None = None
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
        """`e` as an element of the field, built directly from its tree (shared subtrees once)."""
        e = self.sp.sympify(e)
        if not self.gens:
            return self.domain.from_sympy(self._lift(e, set()))
        if self._gen_of is None:
            field = self.domain.field
            self._gen_of = {self.back_map.get(g, g): fg for g, fg in zip(self.gens, field.gens)}
        try:
            return self._element(e, {})
        except KeyError:                  # an atom the field was not built with
            return self.domain.from_sympy(self._lift(e, set()))

    def _element(self, e: Any, seen: dict) -> Any:
        if e in seen:
            return seen[e]
        field = self.domain.field
        if e.is_Rational:
            out = field.ground_new(self.sp.QQ(int(e.p), int(e.q)))
        elif e.is_Float:
            r = self.sp.Rational(str(e))
            out = field.ground_new(self.sp.QQ(int(r.p), int(r.q)))
        elif e.is_Add:
            out = field.zero
            for a in e.args:
                out = out + self._element(a, seen)
        elif e.is_Mul:
            out = field.one
            for a in e.args:
                out = out * self._element(a, seen)
        elif e.is_Pow and e.exp.is_Integer:
            out = self._element(e.base, seen) ** int(e.exp)
        else:
            out = self._gen_of[e]
        seen[e] = out
        return out

    def back(self, x: Any) -> Any:
        """The sympy expression of field element `x`, each stand-in written as its atom while
        the expression is built (one pass, no substitution over the finished tree)."""
        if not self.gens:
            return self.domain.to_sympy(x)
        if self._back_symbols is None:
            self._back_symbols = [self.back_map.get(g, g) for g in self.gens]
        return x.numer.as_expr(*self._back_symbols) / x.denom.as_expr(*self._back_symbols)

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

    from ..budget import check

    check("simplifying the formulas")
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
