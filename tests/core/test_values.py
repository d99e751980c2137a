"""Formulas as a textbook writes them: each form checked for equality and for its text."""
from __future__ import annotations

import pytest
import sympy as sp

from kinematika.report.values import formula

L, s, v0, a, b, w, th, R, h = sp.symbols("L s v0 a b w theta R h", positive=True)
c, r, ph, ps, de = sp.symbols("c r ph ps de", positive=True)


@pytest.mark.parametrize("value,text", [
    (-sp.sqrt(2) * v0 * (-L + s) / (2 * L), "sqrt(2)*v0*(L - s)/(2*L)"),        # sign absorbed
    (-3 * v0 / (2 * (s - L)), "3*v0/(2*(L - s))"),                               # in a denominator
    (-3 * (s - L), "3*(L - s)"),
    (-a * w * sp.cos(th) / sp.sqrt((b - a * sp.sin(th)) * (b + a * sp.sin(th))),
     "-a*w*cos(theta)/sqrt(-a**2*sin(theta)**2 + b**2)"),                        # radicand expanded
    (sp.sqrt(R * (2 * h - R)), "sqrt(R)*sqrt(-R + 2*h)"),
    (4 * w / 3, "4*w/3"),
    (-v0 * (sp.cos(th) - 1), "v0*(1 - cos(theta))"),
    # a four-bar's ω₃ = a ω sin(θ − ψ)/(b sin(ψ − φ)), from its expanded form
    (a * w * (sp.sin(th) * sp.cos(ps) - sp.sin(ps) * sp.cos(th))
     / (b * (sp.sin(ps) * sp.cos(ph) - sp.sin(ph) * sp.cos(ps))), "a*w*sin(ps - theta)/(b*sin(ph - ps))"),
    # the quick-return rocker's α: the denominator is (c² + 2cr sin θ + r²)² with cos² = 1 − sin²
    (c * r * w ** 2 * (c ** 2 - r ** 2) * sp.cos(th)
     / (c ** 4 + 4 * c ** 3 * r * sp.sin(th) - 4 * c ** 2 * r ** 2 * sp.cos(th) ** 2 + 6 * c ** 2 * r ** 2
        + 4 * c * r ** 3 * sp.sin(th) + r ** 4),
     "c*r*w**2*(c - r)*(c + r)*cos(theta)/(c**2 + 2*c*r*sin(theta) + r**2)**2"),
    # the tricycle's ρ: L² cos² δ + 2Ls sin δ cos δ + s² sin² δ = (L cos δ + s sin δ)²
    (sp.sqrt(L ** 2 * sp.cos(de) ** 2 + 2 * L * s * sp.sin(de) * sp.cos(de) - s ** 2 * sp.cos(de) ** 2
             + s ** 2), "Abs(L*cos(de) + s*sin(de))"),
])
def test_formulas_read_as_in_the_notes(value, text):
    assert formula(value) == text
    names = {str(x): x for x in (L, s, v0, a, b, w, th, R, h, c, r, ph, ps, de)}
    difference = sp.sympify(text, locals=names) - value
    at = {x: 0.3 + 0.17 * i for i, x in enumerate(names.values())}     # simplify cannot always tell
    assert sp.simplify(difference) == 0 or abs(complex(difference.subs(at))) < 1e-12


# numbers rounded by arrays ----------------------------------------------------------------
from hypothesis import given, settings, strategies as st  # noqa: E402


def _same(array, scale):
    import math

    import numpy as np

    from kinematika.report.values import number, numbers

    got = numbers(np.array(array, dtype=float), scale).tolist()
    want = [number(x, scale) for x in array]
    for g, w in zip(got, want):
        assert (math.isnan(g) and math.isnan(w)) or (g == w and math.copysign(1, g) == math.copysign(1, w))


@given(st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=50),
       st.floats(min_value=1e-30, max_value=1e30))
def test_numbers_round_arrays_exactly_as_number_rounds_each(values, scale):
    _same(values, scale)


@settings(max_examples=50)
@given(st.integers(-40, 40), st.integers(1, 10 ** 12), st.sampled_from([0.5, 0.49999999999, 1.0, 0.0, 0.5000001]))
def test_numbers_round_near_ties_and_powers_of_ten_as_number(exponent, mantissa, tail):
    """Values whose 13th digit is (nearly) a half, or that are (nearly) powers of ten."""
    values = [(mantissa + tail) * 10.0 ** (exponent - 12), -(mantissa + tail) * 10.0 ** (exponent - 12),
              10.0 ** exponent, 10.0 ** exponent * (1 - 1e-16), 10.0 ** exponent * (1 + 2e-16)]
    _same(values, 1e-30)
