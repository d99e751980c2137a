"""Exact formulas evaluated as numbers over their shared subformulas (`algebra.evaluate`):
the values sympy's own evaluation gives, at far less cost on long exact numbers."""
from __future__ import annotations

import math

import sympy as sp

from kinematika.algebra.evaluate import complex_value


def test_values_are_sympys():
    x, y = sp.symbols("x y", positive=True)
    at = {x: 0.7, y: 1.9}
    for e in (sp.sqrt(x ** 2 + y) / (3 * sp.cos(sp.pi / 9) - x), sp.sin(4 * sp.pi / 9) ** 3 * y - sp.Rational(22, 7),
              (x - y) ** 5 + sp.sqrt(3) * sp.tan(x), sp.exp(-x) * sp.log(y) + sp.asin(x / 2)):
        want = complex(e.xreplace(at))
        got = complex_value(e, at)
        assert abs(got - want) <= 1e-14 * abs(want), (e, got, want)


def test_cancellation_is_exact_enough():
    """Terms of 10²⁰ that cancel (sin(π/9 + π/18) = 1/2 written as a sum of products,
    where floats lose the 1/7), and a trigonometric identity that is zero, as the
    exact values say."""
    a, b = sp.pi / 9, sp.pi / 18
    e = 10 ** 20 * (sp.sin(a) * sp.cos(b) + sp.cos(a) * sp.sin(b)) - 10 ** 20 / sp.Integer(2) + sp.Rational(1, 7)
    assert abs(complex_value(e) - 1 / 7) <= 1e-15
    zero = sp.sin(sp.pi / 9) ** 2 + sp.cos(sp.pi / 9) ** 2 - 1
    assert abs(complex_value(zero)) <= 1e-25


def test_complex_and_unknown_nodes():
    """A root of a negative number is complex; a function it does not know (atan2, Abs)
    goes to sympy; a symbol without a value is sympy's TypeError, as `float` gives."""
    x = sp.Symbol("x", real=True)
    assert abs(complex_value(sp.sqrt(x - 2), {x: 1.0}) - 1j) <= 1e-15
    assert math.isclose(complex_value(sp.atan2(x, 1) + sp.Abs(x), {x: -1.0}).real, -math.pi / 4 + 1)
    try:
        complex_value(x + 1)
    except TypeError:
        pass
    else:
        raise AssertionError("a free symbol must not evaluate")
