"""The scale bar's unit skips factoring what cannot be a product of symbols (`polygon._may_be_a_product`):
the skip must never change `bar_unit`'s answer, so what it lets through and what it stops are
checked on forms worked out by hand."""
from __future__ import annotations

import sympy

from kinematika.explain.polygon import _may_be_a_product

v, R, r, w, a, b, th = sympy.symbols("v R r w a b theta")


def test_products_of_symbols_and_their_hidden_forms_are_factored():
    """v²/R, (2 + √3)/2 · v (a root of a number is a number), and r·w·(a + b) − r·w·b
    (r·w·a once expanded) may be products: they go on to the factoring."""
    for expr in (v**2 / R, (2 + sympy.sqrt(3)) / 2 * v, r * w * (a + b) - r * w * b, (a**2 - b**2) / (a - b)):
        assert _may_be_a_product(sympy.expand(expr)), expr
    assert sympy.factor(sympy.expand((a**2 - b**2) / (a - b))) == a + b      # a sum: bar_unit then refuses it


def test_a_function_or_a_root_of_a_sum_left_after_expanding_is_no_product():
    """r·w·sin θ, √(a² + b²)·v and v/cos θ keep a generator that is not a symbol in every
    factored form: skipped. sin θ · a − sin θ · a is 0 once expanded (no function left)."""
    for expr in (r * w * sympy.sin(th), sympy.sqrt(a**2 + b**2) * v, v / sympy.cos(th), (a + b)**sympy.Rational(3, 2)):
        assert not _may_be_a_product(sympy.expand(expr)), expr
    assert _may_be_a_product(sympy.expand(sympy.sin(th) * (a + b) - sympy.sin(th) * b - sympy.sin(th) * a + v))
