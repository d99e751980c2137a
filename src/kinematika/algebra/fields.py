"""Exact arithmetic with rational functions and square roots, for fast symbolic solving.

sympy's general expressions are slow to simplify. Here a value is a polynomial over QQ in
a fixed set of generators — the model's symbols and stand-ins for the other atoms
(``cos(theta)``, ``pi``), with sin²u + cos²u = 1 keeping each sine at most linear — over a
denominator kept as a product of polynomial factors, so that sums and products need no
polynomial gcd (the costly step of rational-function arithmetic): denominators are the
pivots of the elimination and the radicands' denominators, and they are written factored.

Square roots are not atoms but a tower of quadratic extensions: ``sqrt(X)`` is the root
r of r² = X, with X itself a value over the roots below it, so that ``sqrt(X)``,
``1/sqrt(X)`` and ``X**(3/2)`` are powers of one r however X is written, r² is replaced by
X, and a division by a sum with roots goes through its conjugates. A value is then a sum
over products of distinct roots; for independent roots that form is canonical, so that
the velocity of a point reads the same from every body that carries it.
"""
from __future__ import annotations

import functools
from typing import Any, Iterable

from ..budget import spend, within
from ..memo import Memo, Pure

PRIME_LIMIT = 10 ** 12      # rational radicands up to this size are split into prime roots
MAX_ROOTS = 40


PRODUCT_TERMS = 16      # a product of more than this × the budget's terms is not formed


def _terms(x: "Value") -> int:
    return sum(len(p) for p in x.num.values())


class TooLarge(ArithmeticError):
    """The exact arithmetic went past its budget (terms or time): the caller keeps a form it has."""


class DependentRoots(ArithmeticError):
    """Two square roots of the field are not independent (a product of roots is rational,
    or a radicand is a square): the form is not canonical and a division may fail."""


class Value:
    """Σ num[m]·(roots of mask m) / Π f**k for (f, k) in den: polynomials over QQ."""

    __slots__ = ("den", "num")

    def __init__(self, num: dict, den: dict | None = None) -> None:
        self.num = num
        self.den = den or {}

    def __bool__(self) -> bool:
        return bool(self.num)


def _may_divide(p: Any, f: Any) -> bool:
    """False when f surely does not divide p: with every variable but one of f's set to a
    small integer, f's image does not divide p's (p = q·f holds in every image). Dividing
    the images takes a univariate division instead of a multivariate one (a long numerator
    over a factor that does not divide it was most of `cancel`)."""
    ring = f.ring
    if ring.ngens < 2:
        return True
    keep = max(range(ring.ngens), key=lambda i: f.degree(ring.gens[i]))
    points = [(ring.gens[i], PROBE_POINTS[i % len(PROBE_POINTS)]) for i in range(ring.ngens) if i != keep]
    image = f.evaluate(points)
    if image.is_ground:                 # a constant image (0 or not) proves nothing
        return True
    return not p.evaluate(points).rem(image)


PROBE_POINTS = (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37)


class ExactField:
    """QQ[symbols, atoms]/(sin² + cos² − 1) with factored denominators and square roots."""

    def __init__(self, exprs: Iterable[Any], roots: bool = True, max_terms: int | None = None,
                 max_work: int | None = None) -> None:
        import sympy
        from sympy.polys.orderings import lex
        from sympy.polys.rings import PolyRing

        self.sp = sympy
        self.use_roots = roots
        self.max_terms = max_terms          # budget: terms of a value's numerators
        self.max_work = max_work            # budget: terms of all values formed and products
        self._work = 0                      # of terms taken, summed (a count: the same forms
                                            # in every run)
        symbols: set = set()
        atoms: dict[Any, None] = {}
        self._scanned: set = set()
        for e in exprs:
            self._scan(sympy.sympify(e), symbols, atoms)
        # sines before cosines, so that lex division by sin² + cos² − 1 removes the sines' squares
        ordered = sorted(atoms, key=lambda a: (not isinstance(a, sympy.sin), sympy.default_sort_key(a)))
        stand = [sympy.Dummy(f"atom{i}") for i in range(len(ordered))]
        syms = sorted(symbols, key=str)
        self.back_symbols = syms + ordered or [sympy.Dummy("unused")]
        self.ring = PolyRing(syms + stand or [sympy.Dummy("unused")], sympy.QQ, lex)
        self.gen_of = dict(zip(syms + ordered, self.ring.gens))
        pairs = [(a, sympy.cos(a.args[0])) for a in ordered
                 if isinstance(a, sympy.sin) and sympy.cos(a.args[0]) in atoms]
        self.identities = [self.gen_of[s] ** 2 + self.gen_of[c] ** 2 - self.ring.one for s, c in pairs]
        self.trig_pairs = [(self.ring.gens.index(self.gen_of[s]), self.ring.gens.index(self.gen_of[c]))
                           for s, c in pairs]
        # the tower: root i is sqrt(radicands[i]), a value over roots 0..i-1
        self.radicands: list[Value] = []
        self.root_exprs: list[Any] = []
        self._root_of: dict[Any, int] = {}
        self._monomials: dict[tuple[int, int], Value] = {}
        self._memo: dict[Any, Value] = {}
        self._den_exprs: dict[Any, Any] = {}

    # building --------------------------------------------------------------------------------
    def _scan(self, e: Any, symbols: set, atoms: dict) -> None:
        """Collect the symbols and the atoms of the base ring (a root's radicand is scanned)."""
        if e in self._scanned:
            return
        self._scanned.add(e)
        if e.is_Symbol:
            symbols.add(e)
        elif e.is_Rational or e.is_Float:
            return
        elif e.is_Add or e.is_Mul:
            for a in e.args:
                self._scan(a, symbols, atoms)
        elif e.is_Pow and (e.exp.is_Integer or (self.use_roots and e.exp.is_Rational and e.exp.q == 2)):
            self._scan(e.base, symbols, atoms)
        else:
            atoms[e] = None

    def constant(self, p: int, q: int = 1) -> Value:
        """The rational p/q as a value of the field (zero has no terms)."""
        value = self.sp.QQ(p, q)
        return Value({0: self.ring.ground_new(value)}) if value else Value({})

    @property
    def zero(self) -> Value:
        """0: the value with no terms."""
        return Value({})

    @property
    def one(self) -> Value:
        """1: the constant polynomial over an empty denominator."""
        return Value({0: self.ring.one})

    def to(self, e: Any) -> Value:
        """`e` as a value of the field."""
        return self._value(self.sp.sympify(e))

    def _value(self, e: Any) -> Value:
        memo = self._memo
        if e in memo:
            return memo[e]
        if e.is_Rational:
            out = self.constant(int(e.p), int(e.q))
        elif e.is_Float:
            r = self.sp.Rational(str(e))
            out = self.constant(int(r.p), int(r.q))
        elif e.is_Add:
            out = self.zero
            for a in e.args:
                out = self.add(out, self._value(a))
        elif e.is_Mul:
            out = self.one
            for a in e.args:
                out = self.mul(out, self._value(a))
        elif e.is_Pow and e.exp.is_Integer:
            out = self.power(self._value(e.base), int(e.exp))
        elif e.is_Pow and self.use_roots and e.exp.is_Rational and e.exp.q == 2:
            out = self.power(self.sqrt(self._value(e.base), e.base), int(e.exp.p))
        else:
            out = Value({0: self.gen_of[e]})
        memo[e] = out
        return out

    # arithmetic ------------------------------------------------------------------------------
    def _den_product(self, den: dict) -> Any:
        out = self.ring.one
        for f, k in den.items():
            out = out * f ** k
        return out

    def add(self, x: Value, y: Value) -> Value:
        """x + y over the least common multiple of the factored denominators (no polynomial gcd:
        each factor is raised to the larger of its two powers); checked against the budget."""
        if not x.num:
            return y
        if not y.num:
            return x
        if x.den == y.den:
            den, sx, sy = x.den, None, None
        else:
            den = dict(x.den)
            for f, k in y.den.items():
                if den.get(f, 0) < k:
                    den[f] = k
            sx = self._den_product({f: k - x.den.get(f, 0) for f, k in den.items() if k > x.den.get(f, 0)})
            sy = self._den_product({f: k - y.den.get(f, 0) for f, k in den.items() if k > y.den.get(f, 0)})
        num = {m: (p * sx if sx is not None else p) for m, p in x.num.items()}
        for m, p in y.num.items():
            q = p * sy if sy is not None else p
            total = num[m] + q if m in num else q
            if total:
                num[m] = total
            else:
                num.pop(m, None)
        out = Value(num, den if num else {})
        self._check(out)
        return out

    def neg(self, x: Value) -> Value:
        """−x: each numerator negated over the same denominator."""
        return Value({m: -p for m, p in x.num.items()}, x.den)

    def sub(self, x: Value, y: Value) -> Value:
        """x − y, as x + (−y)."""
        return self.add(x, self.neg(y))

    def mul(self, x: Value, y: Value) -> Value:
        """x·y: numerators multiplied term by term (a product of the same root replaced by its
        radicand), denominators' factor powers added; refused (`TooLarge`) before it is formed
        when it would pass the budget."""
        if not x.num or not y.num:
            return self.zero
        products = _terms(x) * _terms(y)
        if self.max_terms is not None and products > PRODUCT_TERMS * self.max_terms:
            raise TooLarge("too many terms")      # before the product is formed, not after
        self._work += products
        spend(products)
        den = dict(x.den)
        for f, k in y.den.items():
            den[f] = den.get(f, 0) + k
        plain: dict = {}
        reduced = self.zero
        for m1, p1 in x.num.items():
            for m2, p2 in y.num.items():
                p = p1 * p2
                if not m1 & m2:
                    m = m1 | m2
                    total = plain[m] + p if m in plain else p
                    if total:
                        plain[m] = total
                    else:
                        plain.pop(m, None)
                else:
                    mono = self._monomial(m1, m2)
                    reduced = self.add(reduced, Value({m: q * p for m, q in mono.num.items()}, mono.den))
        out = self.add(Value(plain), reduced) if reduced.num else Value(plain)
        if not out.num:
            return self.zero
        for f, k in out.den.items():
            den[f] = den.get(f, 0) + k
        out = Value(self._reduce(out.num), den)
        self._check(out)
        return out

    def _check(self, x: Value) -> None:
        terms = sum(len(p) for p in x.num.values())
        self._work += terms
        spend(terms)
        if self.max_work is not None and self._work > self.max_work:
            raise TooLarge("too much work")
        if self.max_terms is not None and terms > self.max_terms:
            raise TooLarge("too many terms")

    def _monomial(self, m1: int, m2: int) -> Value:
        """The product of the root monomials m1 and m2, each square replaced by its radicand."""
        key = (m1, m2) if m1 <= m2 else (m2, m1)
        if key in self._monomials:
            return self._monomials[key]
        common, rest = m1 & m2, m1 ^ m2
        out = Value({rest: self.ring.one})
        i = 0
        while common:
            if common & 1:
                out = self.mul(out, self.radicands[i])
            common >>= 1
            i += 1
        self._monomials[key] = out
        return out

    def power(self, x: Value, n: int) -> Value:
        """xⁿ by repeated squaring; a negative n is a power of 1/x."""
        if n < 0:
            return self.power(self.inverse(x), -n)
        out, base = self.one, x
        while n:
            if n & 1:
                out = self.mul(out, base)
            n >>= 1
            if n:
                base = self.mul(base, base)
        return out

    def inverse(self, x: Value) -> Value:
        """1/x: the top root removed by the conjugate, down the tower; a root-free numerator
        becomes a factor of the denominator."""
        num = self._reduce(x.num)
        if not num:
            raise ZeroDivisionError("division by zero in the exact field")
        top = max(num).bit_length() - 1
        if top < 0:
            c, f = self._factor(num[0])
            out = Value({0: self._den_product(x.den).mul_ground(1 / c)}, {f: 1} if f is not None else {})
            return out
        bit = 1 << top
        a = Value({m: p for m, p in num.items() if not m & bit})
        b = Value({m ^ bit: p for m, p in num.items() if m & bit})
        conj = self.add(a, Value({m | bit: -p for m, p in b.num.items()}))
        norm = self.sub(self.mul(a, a), self.mul(self.mul(b, b), self.radicands[top]))
        if not self._reduce(norm.num):
            raise DependentRoots(f"{self.root_exprs[top]} is not independent of the other roots")
        return self.mul(self.mul(conj, Value({0: self._den_product(x.den)})), self.inverse(norm))

    def div(self, x: Value, y: Value) -> Value:
        """x / y, as x · (1/y) (`inverse`: the roots removed by conjugates)."""
        return self.mul(x, self.inverse(y))

    def _factor(self, p: Any) -> tuple[Any, Any]:
        """p = c·f with c rational and f primitive with a positive leading coefficient (None
        when p is a constant)."""
        if p.is_ground:
            return p.LC, None
        c, f = p.primitive()
        if f.LC < 0:
            c, f = -c, -f
        return c, f

    def _reduce(self, num: dict) -> dict:
        """Numerators reduced by sin²u + cos²u = 1 (each sine at most linear)."""
        if not self.identities:
            return num
        out = {}
        for m, p in num.items():
            r = p.rem(self.identities)
            if r:
                out[m] = r
        return out

    def is_zero(self, x: Value) -> bool:
        """Whether x is 0 once sin²u + cos²u = 1 is used (its denominator cannot make it zero)."""
        return not self._reduce(x.num)

    def cancel(self, x: Value) -> Value:
        """x with each denominator factor that divides every numerator divided out (also when
        it divides them only with the cosines' squares written as 1 − sin², as sin u divides
        1 − cos² u)."""
        num, den = dict(x.num), dict(x.den)
        for f in list(den):
            while den.get(f):
                quotients = self._divide_all(num, f)
                if quotients is None and self.trig_pairs:
                    quotients = self._divide_all({m: self._cosines_reduced(p) for m, p in num.items()}, f)
                    if quotients is not None:
                        quotients = self._reduce(quotients)
                if quotients is None:
                    break
                num = quotients
                den[f] -= 1
                if not den[f]:
                    del den[f]
        return Value(num, den)

    @staticmethod
    def _divide_all(num: dict, f: Any) -> dict | None:
        """Each numerator divided by f, or None when f does not divide one of them."""
        if not all(_may_divide(p, f) for p in num.values()):
            return None
        out = {}
        for m, p in num.items():
            q, r = p.div(f)
            if r:
                return None
            out[m] = q
        return out

    def _cosines_reduced(self, p: Any) -> Any:
        """p with each cos²u written 1 − sin²u (cosines at most linear)."""
        ring = self.ring
        out = ring.zero
        for monom, coeff in p.terms():
            mon, factor = list(monom), ring.one
            for si, ci in self.trig_pairs:
                k = mon[ci] // 2
                if k:
                    mon[ci] -= 2 * k
                    factor = factor * (ring.one - ring.gens[si] ** 2) ** k
            out += ring.term_new(tuple(mon), coeff) * factor
        return out

    # roots -----------------------------------------------------------------------------------
    def sqrt(self, x: Value, written: Any = None) -> Value:
        """√x: a rational factor times roots of the tower (added when new). `written` is x as
        the input wrote it, kept for display when it is shorter than x's canonical form."""
        x = Value(self._reduce(x.num), x.den)
        if not x.num:
            return self.zero
        factor, parts = self._split_radicand(self.cancel(x))
        whole = (len(parts) == 1 and not factor.den and list(factor.num) == [0]
                 and factor.num[0] == self.ring.one)
        out = factor
        for part in parts:
            out = self.mul(out, Value({1 << self._root(part, written if whole else None): self.ring.one}))
        return out

    def _split_radicand(self, x: Value) -> tuple[Value, list[Value]]:
        """x = f² · p₁ · p₂ ⋯ with f a value and each pᵢ the radicand of a root: the square of
        the rational content taken out, prime numbers and positive symbols to odd powers
        given their own roots (√6 = √2 √3, √(r³X) = r √r √X for r > 0)."""
        QQ = self.sp.QQ
        content = functools.reduce(QQ.gcd, [abs(p.content()) for p in x.num.values()])
        factor, parts = self._split_number(int(QQ.numer(content)), int(QQ.denom(content)))
        num = {m: p.quo_ground(content) for m, p in x.num.items()}
        # powers of positive symbols: common to every term, or factors of the denominator
        positive = [getattr(b, "is_positive", False) is True for b in self.back_symbols]
        tops = [e if positive[i] else 0 for i, e in enumerate(_monomial_gcd(list(num.values())))]
        bottoms = [0] * len(tops)
        den = dict(x.den)
        for f, k in list(den.items()):
            if len(f) == 1 and f.LC == 1 and all(positive[i] for i, e in enumerate(f.LM) if e):
                for i, e in enumerate(f.LM):
                    bottoms[i] += e * k
                del den[f]
        if any(tops):
            num = {m: p.quo_term((tuple(tops), QQ.one)) for m, p in num.items()}
        for i, (top, bottom) in enumerate(zip(tops, bottoms)):
            e = top - bottom                      # x = g**e · rest
            if not e:
                continue
            g = self.ring.gens[i]
            half = e // 2
            factor = self.mul(factor, Value({0: g ** half}) if half >= 0
                              else Value({0: self.ring.one}, {g: -half}))
            if e % 2:
                parts.append(Value({0: g}))
        rest = Value(num, den)
        if not (not den and list(num) == [0] and num[0] == self.ring.one):
            parts.append(rest)
        return factor, parts

    def _split_number(self, num: int, den: int) -> tuple[Value, list[Value]]:
        """√(num/den) = f·√p₁·√p₂⋯ for a positive rational (primes when it is small enough)."""
        from math import isqrt

        import sympy

        value = num * den            # √(num/den) = √(num·den)/den
        outside = sympy.Rational(1, den)
        parts: list[Value] = []
        if value < PRIME_LIMIT:
            for prime, k in sympy.factorint(value).items():
                outside *= sympy.Integer(prime) ** (k // 2)
                if k % 2:
                    parts.append(self.constant(prime))
        else:
            root = isqrt(value)
            if root * root == value:
                outside *= root
            else:
                parts.append(self.constant(value))
        return self.constant(int(outside.p), int(outside.q)), parts

    def _root(self, radicand: Value, written: Any = None) -> int:
        """The index of the root of `radicand`, added to the tower when new; it is written
        with the shorter of the radicand's canonical form and its input form (inner roots
        written as the tower writes them)."""
        key = (frozenset(radicand.num.items()), frozenset(radicand.den.items()))
        if key in self._root_of:
            return self._root_of[key]
        index = len(self.radicands)
        if index >= MAX_ROOTS:
            raise TooLarge("too many square roots")
        self.radicands.append(radicand)
        plain = self.back(radicand)
        shown = _ROOTS_SHOWN.get(plain)
        if shown is None:               # the first way met of writing it, if shorter, for good
            shown = plain
            if self.trig_pairs:         # √(9 − sin²θ) as a textbook writes it, not √(cos²θ + 8)
                syms = self.back_symbols
                sines = self.sp.Mul(self.sp.Add(*[self._cosines_reduced(p).as_expr(*syms) * self._roots(m)
                                                  for m, p in sorted(radicand.num.items())]),
                                    *[self.sp.Pow(self._den_expr(f), -k) for f, k in radicand.den.items()])
                if ops(sines) <= ops(shown):
                    shown = sines
            if written is not None:
                other = self._written(written)
                if ops(other) <= ops(shown):
                    shown = other
            _ROOTS_SHOWN.put(plain, shown)
        self.root_exprs.append(self.sp.Pow(shown, self.sp.S.Half))
        self._root_of[key] = index
        return index

    def _written(self, e: Any) -> Any:
        """e as written, with each root in it as the tower writes it."""
        if e.is_Pow and e.exp.is_Rational and e.exp.q == 2:
            return self.back(self._value(e))
        if e.is_Add or e.is_Mul or e.is_Pow:
            return e.func(*[self._written(a) for a in e.args])
        return e

    # back to sympy ---------------------------------------------------------------------------
    def _roots(self, mask: int) -> Any:
        out = self.sp.S.One
        i = 0
        while mask:
            if mask & 1:
                out *= self.root_exprs[i]
            mask >>= 1
            i += 1
        return out

    def back(self, x: Value) -> Any:
        """The sympy expression of `x`: its numerator over its denominator's factors."""
        sp = self.sp
        x = self.cancel(Value(self._reduce(x.num), x.den))
        if not x.num:
            return sp.S.Zero
        syms = self.back_symbols
        top = sp.Add(*[p.as_expr(*syms) * self._roots(m) for m, p in sorted(x.num.items())])
        bottom = [self._den_expr(f) ** k for f, k in x.den.items()]
        return sp.Mul(top, *[sp.Pow(b, -1) for b in bottom])

    def _den_expr(self, f: Any) -> Any:
        if f not in self._den_exprs:
            self._den_exprs[f] = f.as_expr(*self.back_symbols)
        return self._den_exprs[f]


_ROOTS_SHOWN = Memo(4096)   # a radicand's canonical form -> how its root is written, the
                            # same in every field of a command, so that equal roots combine


def _monomial_gcd(polys: list) -> tuple:
    """The exponents of the monomial dividing every term of every polynomial."""
    out: list | None = None
    for p in polys:
        for mon in p.itermonoms():
            out = list(mon) if out is None else [min(a, b) for a, b in zip(out, mon)]
    return tuple(out or ())


class RationalField:
    """QQ(symbols, atoms) with every root a free atom, as sympy's rational functions (a gcd
    after each operation keeps an elimination's entries small): the linear solves."""

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
            out = self._gen_of[e]    # type: ignore[index]  # set by `to`, which calls this
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


MAX_TERMS = 400          # a canonical form is computed within this many numerator terms ...
MAX_WORK = 500_000       # ... and this much work (terms formed, and products of terms); past either,
                         # the factors' forms are kept (a count: the same forms in every run)
FACTOR_OPS = 60          # forms factored for reading up to this size (multivariate factoring
                         # is randomised and grows fast: a rare draw takes minutes on a long form)
COMMON_OPS = 600         # larger forms, past reading anyway, are not searched for common factors
FACTOR_SEED = 1


EXACT_OPS = 80           # sizes up to this are sympy's count_ops; above, a quick count


def ops(e: Any) -> Any:
    """The size of formula `e` in operations, as sympy's count_ops for small formulas (so
    that the choice among short forms is sympy's); for a large one a count of the same
    kind in one pass over its shared subtrees (count_ops takes a tenth of a second there)."""
    import sympy

    known = _OPS.get(e)
    if known is not None:
        return known
    quick = _quick_ops(e, {})
    return _OPS.put(e, sympy.count_ops(e) if quick <= EXACT_OPS else quick)


_OPS = Memo(8192)   # a form's size is asked by each step that weighs it


def _quick_ops(e: Any, memo: dict) -> int:
    """Operations of `e`: one per sum or product of two terms, power and function."""
    if e.is_Atom:
        return 0
    if e in memo:
        return memo[e]
    args = e.args
    out = (len(args) - 1 if e.is_Add or e.is_Mul else 1) + sum(_quick_ops(a, memo) for a in args)
    memo[e] = out
    return out


def canonical(e: Any) -> Any:
    """A short exact form of `e`: the canonical form over one denominator (roots in the
    numerator, factored), or, when that is longer or past its budget, the product of the
    canonical forms of e's factors (a nested root stays in its place)."""
    import sympy

    from ..budget import check

    check("stage-simplifying")
    e = sympy.sympify(e)
    if e.is_Atom:
        return e
    known = _KNOWN.get(e)
    if known is None:
        known = _KNOWN.put(e, _canonical(e))
        _KNOWN.put(known, known)             # a canonical form is its own canonical form
    return known


_KNOWN = Memo(8192)     # the same velocity is often asked of several material points, and
                        # the same value is shown in the answers and the tables


def _canonical(e: Any) -> Any:
    """`canonical` of a compound expression."""

    forms = list(_whole(e, written=True))
    if e.is_Mul or e.is_Pow:
        forms.append(_by_factors(e))
    forms.append(e)
    sizes = [ops(f) for f in forms]
    best = min(range(len(forms)), key=sizes.__getitem__)
    # the canonical form, factored, unless another is clearly shorter
    return forms[0] if len(forms) > 2 and sizes[0] <= 1.25 * sizes[best] + 2 else forms[best]


def _whole(e: Any, max_terms: int = MAX_TERMS, written: bool = False) -> Any:
    """The canonical form of e over one denominator, factored (None past the budget); with
    `written`, a list of it and of e as written with its roots written canonically."""
    import sympy

    value, field = None, None
    for roots in (True, False):
        try:
            field = ExactField([e], roots=roots, max_terms=max_terms, max_work=MAX_WORK)
            value = field.back(field.to(e))
            break
        except DependentRoots:
            continue
        except TooLarge:
            return [] if written else None
    if value is None:
        return [] if written else None
    if not value.free_symbols:
        value = sympy.radsimp(value)
    elif ops(value) <= FACTOR_OPS:
        value = factored(value)
    elif ops(value) <= COMMON_OPS:          # too large to factor: common factors taken out
        value = within(ops(value), common_factors, value, default=value)
    if not written or field is None:
        return value
    try:
        return [value, field._written(e)]
    except (TooLarge, DependentRoots):
        return [value]


def factored(e: Any) -> Any:
    """e factored with its roots as they are (a radicand keeps the way it is written), or e
    itself past the command's allowance for optional steps (`budget.within`)."""
    import sympy

    powers = sorted(e.atoms(sympy.Pow), key=sympy.default_sort_key)   # Dummies made in one order
    roots = {p: sympy.Dummy() for p in powers if p.exp.is_Rational and not p.exp.is_Integer}
    if not roots:
        return within(ops(e), factor, e, default=e)
    out = within(ops(e), factor, e.xreplace(roots))
    return e if out is None else out.xreplace({d: p for p, d in roots.items()})


def factor(e: Any) -> Any:
    """sympy's factor with its random choices drawn the same way every time: multivariate
    factoring picks random evaluation points, and a rare draw takes far longer; seeded,
    the same formula is factored alike (and as fast) in every run. Remembered for the
    process (`_FACTORED`) with the state of sympy's random numbers after it, which a
    formula met again restores: the process goes on as if it had been factored again."""
    import sympy
    from sympy.core import random

    known = _FACTORED.get(e)
    if known is not None:
        random.rng.setstate(known[1])
        return known[0]
    random.rng.seed(FACTOR_SEED)
    out = sympy.factor(e)
    _FACTORED.put(e, (out, random.rng.getstate()))
    return out


_FACTORED = Pure(4096)


def common_factors(e: Any) -> Any:
    """sympy's factor_terms(e) (common factors taken out, nothing expanded), remembered for
    the process (`_COMMON`): a function of e alone, and the canonical forms of several
    answers often end in the same long form."""
    import sympy

    known = _COMMON.get(e)
    return _COMMON.put(e, sympy.factor_terms(e)) if known is None else known


_COMMON = Pure(4096)


def _by_factors(e: Any) -> Any:
    """e as the product of its factors' canonical forms (each kept as it is past its budget)."""
    import sympy

    out = []
    for f in sympy.Mul.make_args(e):
        base, power = f.as_base_exp()
        if base.is_Atom:
            out.append(f)
            continue
        inner = _whole(base)
        out.append((inner if inner is not None else base) ** power)
    return sympy.Mul(*out)
