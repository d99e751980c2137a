"""Exact formulas evaluated as numbers, fast: once per shared subexpression, in mpmath.

sympy's `float(e)` evaluates a formula as a tree with adaptive precision: a long exact
number (a triad's velocity in sines of 20° and 80°, a spherical four-bar's in 16-digit
decimals) is a tree of hundreds of thousands of nodes over a few thousand distinct ones,
and its evaluation took seconds. Here each distinct node is evaluated once at two
precisions; when they agree the value is kept, else sympy's evaluation decides.
"""
from __future__ import annotations

from typing import Any

LOW, HIGH = 40, 70        # decimal digits of the two evaluations
AGREE = 1e-15             # relative agreement that makes the value trusted
ZERO = 1e-30              # below this times its largest part, both evaluations say 0


class Unsupported(Exception):
    """A node this evaluator does not know (sympy's evaluation is used instead)."""


def complex_value(e: Any, at: dict | None = None) -> complex:
    """The value of formula `e` with its symbols at the numbers `at`, as a complex number."""
    import mpmath
    import sympy

    if isinstance(e, (int, float, complex)):
        return complex(e)
    at = at or {}
    try:
        with mpmath.workdps(LOW):
            low = mpmath.mpc(_value(e, at, {}))
        with mpmath.workdps(HIGH):
            memo: dict = {}
            high = mpmath.mpc(_value(e, at, memo))
            top = max((abs(v) for v in memo.values()), default=abs(high))
    except (Unsupported, ZeroDivisionError, ValueError, TypeError, OverflowError):
        return complex(sympy.sympify(e).xreplace(at) if at else e)
    size = abs(high)
    if not (mpmath.isfinite(size) and mpmath.isfinite(top)):
        return complex(sympy.sympify(e).xreplace(at) if at else e)
    if abs(low - high) <= AGREE * size:
        return complex(high)
    if max(abs(low), size) <= ZERO * top:       # zero (a cancellation of every digit): 0 as
        return complex(high)                    # far as any float comparison can tell
    return complex(sympy.sympify(e).xreplace(at) if at else e)


def _value(e: Any, at: dict, memo: dict) -> Any:
    import mpmath

    if e in memo:
        return memo[e]
    if e in at:
        out = mpmath.mpmathify(at[e])
    elif e.is_Integer:
        out = mpmath.mpf(int(e))
    elif e.is_Rational:
        out = mpmath.mpf(int(e.p)) / int(e.q)
    elif e.is_Float:
        out = mpmath.mpf(e._mpf_)
    elif e.is_Add:
        out = mpmath.fsum(_value(a, at, memo) for a in e.args)
    elif e.is_Mul:
        out = mpmath.fprod(_value(a, at, memo) for a in e.args)
    elif e.is_Pow:
        base, exp = _value(e.base, at, memo), e.exp
        if exp.is_Integer:
            out = base ** int(exp)
        elif exp.is_Rational and exp.q == 2:
            out = mpmath.sqrt(mpmath.mpc(base)) ** int(exp.p) if base < 0 else mpmath.sqrt(base) ** int(exp.p)
        else:
            out = mpmath.power(base, _value(exp, at, memo))
    elif e.is_Function and len(e.args) == 1 and type(e).__name__ in _FUNCTIONS:
        out = getattr(mpmath, _FUNCTIONS[type(e).__name__])(_value(e.args[0], at, memo))
    elif e.is_NumberSymbol and str(e) == "pi":
        out = +mpmath.pi
    else:
        raise Unsupported(type(e).__name__)
    memo[e] = out
    return out


_FUNCTIONS = {"sin": "sin", "cos": "cos", "tan": "tan", "exp": "exp", "log": "log",
              "asin": "asin", "acos": "acos", "atan": "atan", "sinh": "sinh", "cosh": "cosh",
              "tanh": "tanh"}
