"""Motion laws against the textbooks' formulas, differentiated independently by sympy, and
their peak factors against the published values."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from kinematika.cams import laws

x = sp.Symbol("x")
pi = sp.pi

# The textbook statements of S(x), typed in as the books print them (piecewise where they are)
TEXTBOOK = {
    "uniform": [(0, 1, x)],
    "harmonic": [(0, 1, (1 - sp.cos(pi * x)) / 2)],                        # Norton eq. 8.3
    "cycloidal": [(0, 1, x - sp.sin(2 * pi * x) / (2 * pi))],                # Norton eq. 8.6
    "3-4-5": [(0, 1, 10 * x**3 - 15 * x**4 + 6 * x**5)],                    # Norton eq. 8.24
    "4-5-6-7": [(0, 1, 35 * x**4 - 84 * x**5 + 70 * x**6 - 20 * x**7)],     # Norton eq. 8.25
    # modified sine, closed form in (4 + π): Norton eq. 8.17
    "modified-sine": [
        (0, sp.Rational(1, 8), (pi * x - sp.sin(4 * pi * x) / 4) / (4 + pi)),
        (sp.Rational(1, 8), sp.Rational(7, 8), (2 + pi * x - sp.Rational(9, 4) * sp.sin(4 * pi * x / 3 + pi / 3)) / (4 + pi)),
        (sp.Rational(7, 8), 1, (4 + pi * x - sp.sin(4 * pi * x) / 4) / (4 + pi)),
    ],
}

# Norton's modified trapezoid (eq. 8.16) as he tabulates it, with 8-digit coefficients
NORTON_TRAPEZOID = [
    (0, sp.Rational(1, 8), 0.38898448 * x - 0.0309544 * sp.sin(4 * pi * x)),
    (sp.Rational(1, 8), sp.Rational(3, 8), 2.44406184 * x**2 - 0.22203097 * x + 0.00723407),
    (sp.Rational(3, 8), sp.Rational(5, 8), 1.6110154 * x - 0.0309544 * sp.sin(4 * pi * x - pi) - 0.3055077),
    (sp.Rational(5, 8), sp.Rational(7, 8), -2.44406184 * x**2 + 4.6660917 * x - 1.2292648),
    (sp.Rational(7, 8), 1, 0.6110154 + 0.38898448 * x + 0.0309544 * sp.sin(4 * pi * x - 3 * pi)),
]


def textbook_values(pieces, xs):
    """S, S', S'', S''' of the textbook's pieces at xs (sympy differentiates)."""
    out = np.zeros((4, len(xs)))
    for lo, hi, expr in pieces:
        fs = [sp.lambdify(x, sp.diff(expr, x, k), "numpy") for k in range(4)]
        mask = (xs >= float(lo)) & (xs <= float(hi))
        for k, f in enumerate(fs):
            out[k, mask] = np.broadcast_to(f(xs[mask]), mask.sum())
    return out


XS = np.array([0.0, 0.03, 0.1, 0.2, 0.3, 0.45, 0.5, 0.55, 0.7, 0.8, 0.9, 0.97, 1.0])


@pytest.mark.parametrize("name", list(TEXTBOOK))
def test_each_law_is_its_textbook_formula_and_its_derivatives(name):
    expected = textbook_values(TEXTBOOK[name], XS)
    got = np.array(laws.LAWS[name](XS))
    assert np.allclose(got, expected, atol=1e-11, rtol=1e-11)


def test_the_modified_trapezoid_is_nortons_to_his_eight_digits():
    expected = textbook_values(NORTON_TRAPEZOID, XS)
    got = np.array(laws.MODIFIED_TRAPEZOID(XS))
    for k, tol in enumerate((2e-7, 2e-6, 2e-5, 2e-4)):     # his coefficients are rounded
        assert np.allclose(got[k], expected[k], atol=tol), k


# Peak acceleration factors C_a (peak d²s/dθ² = C_a·h/β²) as the books give them
PEAK_ACCELERATION = {"harmonic": math.pi**2 / 2, "cycloidal": 2 * math.pi, "3-4-5": 10 / math.sqrt(3),
                     "modified-trapezoid": 4.8881, "modified-sine": 5.5280, "4-5-6-7": 7.5132}


@pytest.mark.parametrize("name", list(PEAK_ACCELERATION))
def test_peak_acceleration_factors_are_the_books(name):
    _, ca, _ = laws.LAWS[name].factors()
    assert ca == pytest.approx(PEAK_ACCELERATION[name], abs=2e-4)


def test_peak_velocity_and_jerk_of_the_cycloid_and_the_modified_sine():
    """Cycloidal: S' peaks at 2, S''' at 4π²; modified sine: C_v = 1.76, C_j = 69.47."""
    cv, _, cj = laws.CYCLOIDAL.factors()
    assert (cv, cj) == (pytest.approx(2.0), pytest.approx(4 * math.pi**2))
    cv, _, cj = laws.MODIFIED_SINE.factors()
    assert (cv, cj) == (pytest.approx(1.76, abs=5e-3), pytest.approx(69.47, abs=5e-2))


def test_a_polynomial_from_boundary_conditions_is_the_textbooks():
    """s, v, a zero at both ends and s(1) = 1 give 3-4-5; adding zero jerk gives 4-5-6-7."""
    p = laws.Polynomial.through({0: 0, 1: 0, 2: 0}, {0: 1, 1: 0, 2: 0})
    assert np.allclose(p.coefficients, [0, 0, 0, 10, -15, 6])
    p = laws.Polynomial.through({0: 0, 1: 0, 2: 0, 3: 0}, {0: 1, 1: 0, 2: 0, 3: 0})
    assert np.allclose(p.coefficients, [0, 0, 0, 0, 35, -84, 70, -20])


def test_every_law_rises_from_zero_to_one_at_rest_except_uniform():
    for name, law in laws.LAWS.items():
        s, v, a, _ = law(np.array([0.0, 1.0]))
        if name == "dwell":
            assert np.all(s == 0)
            continue
        assert s[0] == pytest.approx(0, abs=1e-14) and s[1] == pytest.approx(1, abs=1e-14)
        if name != "uniform":
            assert np.allclose(v, 0, atol=1e-12)
