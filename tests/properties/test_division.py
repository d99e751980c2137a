"""The exact field's quick test of divisibility (`fields._may_divide`) never turns away a
true divisor (p = q·f holds in every image), and turns away the ones that do not divide."""
from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import QQ
from sympy.polys.orderings import lex
from sympy.polys.rings import ring

from kinematika.algebra.fields import _may_divide

from tests.conftest import DEEP

R, x, y, s, c = ring("x, y, s, c", QQ, lex)
GENS = (R.one, x, y, s, c)

# small polynomials: a few terms, each a rational coefficient times a product of two atoms
terms = st.tuples(st.fractions(min_value=-9, max_value=9, max_denominator=5),
                  st.sampled_from(GENS), st.sampled_from(GENS))
polys = st.lists(terms, min_size=1, max_size=5).map(
    lambda ts: sum((R(coeff) * a * b for coeff, a, b in ts), R.zero))


# sympy's rings make each example costly: 40 pairs by default, 500 in a deep run
@settings(max_examples=500 if DEEP else 40, deadline=None)
@given(polys, polys)
def test_a_true_divisor_is_never_turned_away(q, f):
    if f.is_ground:
        return
    assert _may_divide(q * f, f)


def test_by_hand():
    """(x + y)(x − 2y + s) is divisible by x + y and not by x + 2y, nor by s² + c² − 1."""
    p = (x + y) * (x - 2 * y + s)
    assert _may_divide(p, x + y)
    assert not _may_divide(p, x + 2 * y)
    assert not _may_divide(p, s**2 + c**2 - 1)
    assert _may_divide(p * (s**2 + c**2 - 1), s**2 + c**2 - 1)
