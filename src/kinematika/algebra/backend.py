"""Numbers or symbols: the two algebras the one engine runs on.

The engine writes its formulas once with ``+ - * /`` and the few functions below; a
`Numeric` backend gives floats, a `Symbolic` backend gives exact sympy expressions.
sympy is imported only by `Symbolic`, so numeric work never pays for it.
"""
from __future__ import annotations

import math
from typing import Any, Callable

from .. import limits
from ..expressions import ExpressionError
from ..memo import Memo, Pure
from ..text import brief


class Numeric:
    """Floats, evaluated with the math module."""

    symbolic = False
    pi = math.pi

    def number(self, value: int | float) -> float:
        """A number written in the model, as a float."""
        return float(value)

    def function(self, name: str) -> Callable[..., float]:
        """The model's function `name` (sin, sqrt, atan2, deg …) on floats; `deg`, `rad` and
        `radians` all take degrees to radians, and sqrt refuses a real negative."""
        table: dict[str, Callable[..., float]] = {
            "sqrt": _real_sqrt, "cbrt": lambda x: math.copysign(abs(x) ** (1 / 3), x),
            "sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": math.asin,
            "acos": math.acos, "atan": math.atan, "atan2": math.atan2, "exp": math.exp,
            "log": math.log, "abs": abs, "deg": math.radians, "rad": math.radians,
            "radians": math.radians, "degrees": math.degrees,
            "sinh": math.sinh, "cosh": math.cosh, "tanh": math.tanh,
        }
        return table[name]

    def check(self, value: Any, source: str) -> Any:
        """A computed value must be finite: an infinity or NaN is an error naming the expression
        `source`."""
        if isinstance(value, float) and not math.isfinite(value):
            raise ExpressionError("expr-not-finite-value", source=brief(source))
        return value

    def symbol(self, name: str, positive: bool = True) -> float:
        """A parameter without a value cannot be a float: the error says so (the `Symbolic`
        backend makes it a symbol)."""
        raise ExpressionError("parameter-no-value", name=name)

    def sqrt(self, x: float) -> float:
        """√x; round-off below zero (> −1e-12) is 0, a real negative an error."""
        return _real_sqrt(x)

    def simplify(self, x: Any) -> Any:
        """`x` unchanged: floats have nothing to simplify."""
        return x


def _real_sqrt(x: float) -> float:
    if x < 0:
        if x > -1e-12:
            return 0.0
        raise ValueError(f"square root of a negative number {x:g}")
    return math.sqrt(x)


MAX_BITS = int(limits.EXACT_DIGITS * math.log2(10)) + 1   # integers of an exact number
TRIGSIMP_OPS = 40   # radicands simplified by trigsimp up to this size (beyond, it takes seconds)
_ROOTS = Memo(4096)  # a radicand -> its root: a drawn vector's |v| is asked by every figure
                     # drawn of it (one a language) and by the captions that read the figure,
                     # seconds of trigsimp each (a command's own memory: kinematika.memo)


def _radians(x: Any) -> Any:
    """x degrees in radians, exactly."""
    import sympy

    return x * sympy.pi / 180


class Symbolic:
    """Exact sympy expressions; decimals in the model become exact rationals."""

    symbolic = True

    def __init__(self) -> None:
        import sympy

        self.sp = sympy
        self.pi = sympy.pi

    def number(self, value: int | float) -> Any:
        """A number written in the model, exactly (0.1 is 1/10); at most `limits.EXACT_DIGITS`
        digits above and below the fraction bar, so that exact work stays bounded."""
        exact = self.sp.Integer(value) if isinstance(value, int) else self.sp.Rational(repr(value))
        if max(abs(exact.p), exact.q).bit_length() > MAX_BITS:
            raise ExpressionError("number-too-many-digits", number=brief(value, 30), limit=limits.EXACT_DIGITS)
        return exact

    def function(self, name: str) -> Callable[..., Any]:
        """The model's function `name` as sympy's (sin, sqrt, atan2 …); `deg`, `rad` and
        `radians` give x·π/180 exactly."""
        sp = self.sp
        table: dict[str, Callable[..., Any]] = {
            "sqrt": sp.sqrt, "cbrt": sp.cbrt, "sin": sp.sin, "cos": sp.cos, "tan": sp.tan,
            "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "atan2": sp.atan2, "exp": sp.exp,
            "log": sp.log, "abs": sp.Abs, "deg": _radians, "rad": _radians, "radians": _radians,
            "degrees": lambda x: x * 180 / sp.pi, "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh,
        }
        return table[name]

    def check(self, value: Any, source: str) -> Any:
        """A value must be finite, its exact numbers of at most `limits.EXACT_DIGITS` digits
        and its degree in the symbols at most `limits.DEGREE`; a number must also be real
        and in the range of floats, so that exact work stays bounded."""
        sp = self.sp
        if not isinstance(value, sp.Basic):
            return value
        if value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            raise ExpressionError("expr-not-finite-value", source=brief(source))
        if any(max(abs(r.p), r.q).bit_length() > MAX_BITS for r in value.atoms(sp.Rational)):
            raise ExpressionError("expr-too-many-digits", source=brief(source), limit=limits.EXACT_DIGITS)
        if not value.is_number:
            if degree(value) > limits.DEGREE:
                raise ExpressionError("expr-degree", source=brief(source), limit=limits.DEGREE)
            return value
        if value.is_real is False:
            raise ExpressionError("expr-not-real", source=brief(source))
        if not math.isfinite(abs(complex(value))):
            raise ExpressionError("expr-too-large", source=brief(source))
        return value

    def symbol(self, name: str, positive: bool = True) -> Any:
        """A user's parameter as a symbol; any identifier is allowed (`E`, `I`, `lambda`)."""
        if positive:
            return self.sp.Symbol(name, positive=True)
        return self.sp.Symbol(name, real=True)

    def sqrt(self, x: Any) -> Any:
        """√x, with sin² + cos² = 1 and squares of the symbols recognised first (in the
        exact field, where trigsimp on a long radicand would take seconds)."""
        x = self.sp.sympify(x)
        found = _ROOTS.get(x)
        return _ROOTS.put(x, self._sqrt(x)) if found is None else found

    def _sqrt(self, x: Any) -> Any:
        sp = self.sp
        size = sp.count_ops(x) if x.has(sp.sin, sp.cos) else None
        if size is not None and size <= TRIGSIMP_OPS:
            from ..budget import within

            x = within(size, _trigsimp_keeping_angles, x, default=x)
        elif not x.is_number:
            from .fields import canonical

            x = canonical(x)
        return sp.sqrt(x)

    def simplify(self, x: Any) -> Any:
        """A canonical, factored form of a rational expression in the symbols and atoms."""
        from .fields import canonical

        return canonical(x)

    def check_against(self, exact: list[Any], numeric: Any, probe: dict, scale: float = 0.0) -> None:
        """The exact solution must equal the numeric one at the probe values, within the
        numeric one's round-off: relative to the largest value of the solution, or to
        `scale` (the size the known terms give the unknowns) when the solution is all 0."""
        from .evaluate import complex_value

        values = []
        for e in exact:
            try:
                values.append(complex_value(self.sp.sympify(e), probe))
            except (TypeError, OverflowError):
                values.append(complex(math.nan))
        top = max([abs(float(x)) for x in numeric] + [scale])
        for e, value, x in zip(exact, values, numeric):
            if not abs(value - x) <= 1e-6 * max(abs(x), 1e-3 * top) + 1e-300:
                raise ArithmeticError(f"exact solution {brief(str(e))} disagrees with the numeric "
                                      f"one {x:.6g}")


def _trigsimp_keeping_angles(x: Any) -> Any:
    """trigsimp(x) with each numeric angle held as a symbol: alone, trigsimp writes
    1 − cos²(7π/18) as cos²(π/9), a new atom the exact field cannot relate to sin(7π/18),
    so that a rate that is zero (a parallelogram's coupler at 70°) was not seen to be.
    Remembered for the process (`_TRIGSIMPED`): a function of x alone, and most of a
    radicand's square root (0.3–0.8 s for a circle intersection of Jansen's leg, even when
    it returns x as it was)."""
    known = _TRIGSIMPED.get(x)
    return _TRIGSIMPED.put(x, _trigsimp_angles_held(x)) if known is None else known


_TRIGSIMPED = Pure(1024)


def _trigsimp_angles_held(x: Any) -> Any:
    """`_trigsimp_keeping_angles`, worked out."""
    import sympy as sp

    angles = {f.args[0] for f in x.atoms(sp.sin, sp.cos) if f.args[0].is_number}
    if not angles:
        return sp.trigsimp(x)
    held = {a: sp.Dummy(real=True) for a in sorted(angles, key=sp.default_sort_key)}   # one order
    simple = sp.trigsimp(x.replace(lambda e: isinstance(e, (sp.sin, sp.cos)) and e.args[0] in held,
                                   lambda e: e.func(held[e.args[0]])))
    return simple.xreplace({d: a for a, d in held.items()})


def degree(e: Any, memo: dict | None = None) -> int:
    """An upper bound of the degree of formula `e` in its symbols (a power's degree times
    its exponent, a product's the sum of its factors'), without expanding anything."""
    memo = {} if memo is None else memo
    if e in memo:
        return memo[e]
    if e.is_Symbol:
        out = 1
    elif e.is_Atom or e.is_number:
        out = 0
    elif e.is_Pow and e.exp.is_Rational:
        out = degree(e.base, memo) * math.ceil(abs(e.exp))
    elif e.is_Mul:
        out = sum(degree(a, memo) for a in e.args)
    else:
        out = max((degree(a, memo) for a in e.args), default=0)
    memo[e] = out
    return out


def probe_values(symbols: list[Any], seed: int = 7) -> dict[Any, float]:
    """Generic numeric values for symbols (positive ones in (0.6, 1.9), real ones of either sign).

    Used to find the structure (rank, independent rows, geometry gaps) of a symbolic model
    at a point where no accidental cancellation is to be expected.
    """
    if not symbols:
        return {}
    import random           # symbolic models only: a numeric command never imports it

    rng = random.Random(seed)
    values = {}
    for s in symbols:
        magnitude = rng.uniform(0.6, 1.9)
        positive = getattr(s, "is_positive", True)
        values[s] = magnitude if positive else magnitude * rng.choice((-1, 1))
    return values
