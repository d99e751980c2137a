"""The exact field and the symbolic solve in stand-ins: every form equals its input, roots
are one generator however they are written, and the quick-return's formulas equal the
derivatives of its positions (differentiated here with sympy, not by the solver)."""
from __future__ import annotations

import random
from pathlib import Path

import mpmath
import pytest
import sympy as sp

import kinematika
from kinematika.algebra.fields import ExactField, canonical
from kinematika.report.values import formula
from tests.conftest import DEEP, sampled

ROOT = Path(__file__).resolve().parents[2]
R, rho, w, b = sp.symbols("R rho w beta", positive=True)
x = sp.Symbol("x", real=True)


def random_expressions(seed: int, count: int) -> list:
    atoms = [R, rho, w, x, sp.sin(b), sp.cos(b), sp.sqrt(R ** 2 + rho ** 2), sp.sqrt(2), R ** 3, 1 / R,
             sp.sqrt(R), sp.sqrt(R ** 3 * rho), sp.sqrt(rho / R ** 3)]
    rng = random.Random(seed)

    def build(depth: int):
        if depth == 0:
            return rng.choice(atoms) * rng.choice([1, 2, -3, sp.Rational(1, 2)])
        a, c, k = build(depth - 1), build(depth - 1), rng.random()
        if k < 0.3:
            return a + c
        if k < 0.6:
            return a * c
        if k < 0.7:
            return a / (c + 5)
        if k < 0.85:
            return sp.sqrt(a ** 2 + c ** 2 + 1)
        return a - c

    return [build(3) for _ in range(count)]


@pytest.mark.parametrize("seed", sampled([1, 2], lambda seed: seed == 1))      # both in a deep run
def test_canonical_forms_equal_their_input(seed):
    """Random sums, products, quotients and roots of roots: their canonical forms have the
    same value (20 expressions, the first of the deep run's 60: the same random stream)."""
    at = {R: 0.7, rho: 1.3, b: 0.4, w: 2.1, x: -0.8}
    for e in random_expressions(seed, 60 if DEEP else 20):
        got, want = complex(canonical(e).evalf(subs=at)), complex(e.evalf(subs=at))
        assert abs(got - want) <= 1e-9 * (1 + abs(want)), e


def test_a_root_is_one_generator_however_it_is_written():
    c, r, th = sp.symbols("c r th", positive=True)
    q2 = c ** 2 + 2 * c * r * sp.sin(th) + r ** 2
    other = r ** 2 * sp.cos(th) ** 2 + (c + r * sp.sin(th)) ** 2        # the same, written otherwise
    assert canonical(sp.sqrt(other) / sp.sqrt(q2)) == 1
    assert canonical(q2 ** sp.Rational(3, 2) / (q2 * sp.sqrt(other))) == 1
    assert canonical(sp.sqrt(6) - sp.sqrt(2) * sp.sqrt(3)) == 0
    assert canonical(1 / (1 + sp.sqrt(2))) == sp.sqrt(2) - 1


def test_division_goes_through_conjugates():
    field = ExactField([x, sp.sqrt(x ** 2 + 1)])
    value = field.div(field.one, field.to(x + sp.sqrt(x ** 2 + 1)))
    assert sp.simplify(field.back(value) - (sp.sqrt(x ** 2 + 1) - x)) == 0


def value(e, at: dict) -> float:
    """A formula's number at `at` {symbol: number}, at 30 digits (lambdify to mpmath: what
    `evalf(subs=...)` gives, in a tenth of the time on these long derivatives)."""
    with mpmath.workdps(30):
        return float(sp.lambdify(list(at), e, "mpmath")(*[mpmath.mpf(str(v)) for v in at.values()]))


@pytest.fixture(scope="module")
def quick_return():
    """examples/quick_return.yaml, every parameter a symbol, solved once for this file."""
    return kinematika.solve(ROOT / "examples" / "quick_return.yaml", symbolic=True)


def quick_return_by_differentiation():
    """ω of the rocker and of the link: the time derivatives of their angles, from the
    positions the example's parameters define (θ̇ = w)."""
    r, c, L, l, h, th, ww = sp.symbols("r c L l h th w", positive=True)
    ax, ay = r * sp.cos(th), c + r * sp.sin(th)
    q = sp.sqrt(ax ** 2 + ay ** 2)
    bx, by = L * ax / q, L * ay / q
    cx = bx + sp.sqrt(l ** 2 - (h - by) ** 2)
    rocker = sp.diff(sp.atan2(ay, ax), th) * ww
    link = sp.diff(sp.atan2(h - by, cx - bx), th) * ww
    return (r, c, L, l, h, th, ww), rocker, link


def test_quick_return_formulas_are_the_derivatives_of_its_positions(quick_return):
    sol = quick_return
    names, rocker, link = quick_return_by_differentiation()
    symbols = {str(s): s for s in names}
    shown = {body: formula(sol.omega(body)) for body in ("rocker", "link")}
    for values in ({"r": 0.1, "c": 0.3, "L": 0.5, "l": 0.2, "h": 0.5, "th": 0.52, "w": 10},
                   {"r": 0.12, "c": 0.35, "L": 0.6, "l": 0.3, "h": 0.55, "th": 1.9, "w": 3}):
        at = {symbols[k]: v for k, v in values.items()}
        for body, expected in (("rocker", rocker), ("link", link)):
            got = value(sp.sympify(shown[body], locals=symbols), at)
            assert got == pytest.approx(value(expected, at), rel=1e-9)
    # compact: the link's ω is one product of the link's and rocker's quantities
    assert len(shown["link"]) < 200, shown["link"]


def test_a_point_shared_by_two_bodies_reads_the_same_from_both(quick_return):
    sol = quick_return
    assert [formula(v) for v in sol.velocity("B@rocker")] == [formula(v) for v in sol.velocity("B@link")]


def test_four_bar_by_lengths_at_a_general_angle_is_the_derivative_of_its_position():
    """Link lengths a, b, c, d and the crank angle θ all symbols (a construction-built model):
    ω of coupler and rocker equal the time derivatives of the link angles, with B written here
    by the textbook's two-circle intersection and differentiated by sympy."""
    model = ROOT / "benchmarks" / "models" / "symbolic" / "four_bar_general.yaml"
    sol = kinematika.solve(model)
    a, b, c, d, th, ww = sp.symbols("a b c d theta w", positive=True)
    ax, ay = a * sp.cos(th), a * sp.sin(th)
    f2 = (d - ax) ** 2 + ay ** 2                    # |A O4|²
    along = (b ** 2 - c ** 2 + f2) / (2 * f2)       # B = A + along·(O4 − A) + height·n, n to the left
    height = sp.sqrt(b ** 2 / f2 - along ** 2)
    bx = ax + along * (d - ax) + height * ay
    by = ay + along * (0 - ay) + height * (d - ax)
    coupler = sp.diff(sp.atan2(by - ay, bx - ax), th) * ww
    rocker = sp.diff(sp.atan2(by, bx - d), th) * ww
    symbols = {str(s): s for s in (a, b, c, d, th, ww)}
    shown = {body: formula(sol.omega(body)) for body in ("coupler", "rocker")}
    for values in ({"a": 2, "b": 7, "c": 9, "d": 6, "theta": 0.3, "w": 1.5},
                   {"a": 2.25, "b": 6.1, "c": 4.35, "d": 5.2, "theta": 2.4, "w": -0.7}):
        at = {symbols[k]: v for k, v in values.items()}
        for body, expected in (("coupler", coupler), ("rocker", rocker)):
            got = value(sp.sympify(shown[body], locals=symbols), at)
            assert got == pytest.approx(value(expected, at), rel=1e-9)
    # one root, written once as a textbook writes it: 4b²f² − (f² + b² − c²)²
    assert len({str(r) for r in sp.sympify(shown["coupler"], locals=symbols).atoms(sp.Pow)
                if r.exp == sp.S.Half}) == 1
