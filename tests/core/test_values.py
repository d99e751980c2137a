"""Formulas as a textbook writes them: each form checked for equality and for its text."""
from __future__ import annotations

import pytest
import sympy as sp

from kinematika.report.values import formula

L, s, v0, a, b, w, th, R, h = sp.symbols("L s v0 a b w theta R h", positive=True)


@pytest.mark.parametrize("value,text", [
    (-sp.sqrt(2) * v0 * (-L + s) / (2 * L), "sqrt(2)*v0*(L - s)/(2*L)"),        # sign absorbed
    (-3 * v0 / (2 * (s - L)), "3*v0/(2*(L - s))"),                               # in a denominator
    (-3 * (s - L), "3*(L - s)"),
    (-a * w * sp.cos(th) / sp.sqrt((b - a * sp.sin(th)) * (b + a * sp.sin(th))),
     "-a*w*cos(theta)/sqrt(-a**2*sin(theta)**2 + b**2)"),                        # radicand expanded
    (sp.sqrt(R * (2 * h - R)), "sqrt(R)*sqrt(-R + 2*h)"),
    (4 * w / 3, "4*w/3"),
])
def test_formulas_read_as_in_the_notes(value, text):
    assert formula(value) == text
    names = {str(x): x for x in (L, s, v0, a, b, w, th, R, h)}
    assert sp.simplify(sp.sympify(text, locals=names) - value) == 0
