"""Symbolic answers, evaluated at random numbers, equal the numeric answers of the same model
with those numbers. Each model is solved symbolically once (the costly part); every draw
is one fast numeric solve."""
from __future__ import annotations

import copy
import functools
import math

import pytest
import sympy
from hypothesis import given
from hypothesis import strategies as st

import kinematika

# an offset-free slider-crank, crank at 60°, its lengths and crank motion all symbols
SLIDER_CRANK = {
    "parameters": {"r": None, "l": None, "w": None, "al": {"value": None, "positive": False}},
    "points": {"O": [0, 0], "A": ["r/2", "sqrt(3)*r/2"], "B": ["r/2 + sqrt(l**2 - 3*r**2/4)", 0]},
    "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
               {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
               {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
               {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
    "drivers": [{"omega": "crank", "value": "w", "alpha": "al"}],
    "ask": [{"velocity": "B"}, {"acceleration": "B"}, {"omega": "rod"}, {"alpha": "rod"},
            {"icr": "rod"}, {"curvature": "A@rod", "relative_to": "slider"},
            {"decompose": "B@rod", "moving": "crank"}],
}

# a wheel (radius r) rolling on a fixed cylinder (radius R), its centre driven around it
WHEEL_ON_CYLINDER = {
    "parameters": {"R": None, "r": None, "w": None, "wd": {"value": None, "positive": False}},
    "points": {"O": [0, 0], "C": [0, "R + r"], "P": ["r", "R + r"]},
    "bodies": {"ground": {"points": ["O"], "circle": {"center": "O", "radius": "R"}},
               "arm": ["O", "C"],
               "wheel": {"points": ["C", "P"], "circle": {"center": "C", "radius": "r"}}},
    "joints": [{"type": "revolute", "bodies": ["ground", "arm"], "at": "O"},
               {"type": "revolute", "bodies": ["arm", "wheel"], "at": "C"},
               {"id": "roll", "type": "rolling", "bodies": ["ground", "wheel"]}],
    "drivers": [{"omega": "arm", "value": "w", "alpha": "wd"}],
    "ask": [{"omega": "wheel"}, {"alpha": "wheel"}, {"curvature": "P"}, {"contact": "roll"},
            {"pole": "wheel"}, {"intrinsic": "P"}],
}

MODELS = {"slider_crank": SLIDER_CRANK, "wheel_on_cylinder": WHEEL_ON_CYLINDER}
positive = st.floats(0.2, 3.0)
signed = st.floats(-5.0, 5.0)


@functools.lru_cache(maxsize=None)
def symbolic_answers(name: str) -> list:
    sol = kinematika.solve(MODELS[name])
    assert sol.symbolic
    return [value for _, value in kinematika.answers(sol)]


def numeric_answers(name: str, values: dict[str, float]) -> list:
    tree = copy.deepcopy(MODELS[name])
    tree["parameters"] = dict(values)
    return [value for _, value in kinematika.answers(kinematika.solve(tree))]


@functools.lru_cache(maxsize=None)
def compiled(formula: sympy.Expr):
    """The formula as a fast numeric function of its symbols, by name."""
    names = sorted(s.name for s in formula.free_symbols)
    fn = sympy.lambdify([sympy.Symbol(n) for n in names], formula.xreplace(
        {s: sympy.Symbol(s.name) for s in formula.free_symbols}), "math")
    return lambda values: fn(*(values[n] for n in names))


def agree(formula, number, values: dict, scale: float) -> bool:
    """A symbolic answer at `values` equals the numeric one (recursively through dicts/tuples)."""
    if isinstance(formula, dict):
        return formula.keys() == number.keys() and all(
            agree(formula[k], number[k], values, scale) for k in formula)
    if isinstance(formula, (tuple, list)):
        return len(formula) == len(number) and all(agree(f, n, values, scale) for f, n in zip(formula, number))
    if formula is None or isinstance(formula, bool):
        return formula == number
    value = float(compiled(sympy.sympify(formula))(values))
    return math.isclose(value, float(number), rel_tol=1e-7, abs_tol=1e-8 * scale)


def check(name: str, values: dict[str, float]) -> None:
    symbolic = symbolic_answers(name)
    scale = max(abs(v) for v in values.values()) ** 3 + 1
    numbers = numeric_answers(name, values)
    for q, f, n in zip(MODELS[name]["ask"], symbolic, numbers):
        assert agree(f, n, values, scale), (q, f, n)


@pytest.mark.slow
@given(r=positive, ratio=st.floats(1.0, 4.0), w=signed.filter(lambda w: abs(w) > 0.1), al=signed)
def test_slider_crank_formulas_match_numbers(r, ratio, w, al):
    check("slider_crank", {"r": r, "l": r * ratio, "w": w, "al": al})


@pytest.mark.slow
@given(big=positive, r=positive, w=positive, wd=signed)
def test_wheel_on_cylinder_formulas_match_numbers(big, r, w, wd):
    check("wheel_on_cylinder", {"R": big, "r": r, "w": w, "wd": wd})


def test_symbolic_geometry_real_only_for_some_values_of_the_symbols():
    # Regression: sqrt(l² − 3r²/4) is real only for l > (√3/2) r; the engine's default probe
    # values of the symbols fell outside and the solve crashed ("Cannot convert complex to
    # float"). Now other probe values are tried.
    sol = kinematika.solve(SLIDER_CRANK)
    r, l, w = (sympy.Symbol(n, positive=True) for n in "rlw")
    root = sympy.sqrt(l ** 2 - 3 * r ** 2 / 4)
    # v_B = ω k × OA + ω_rod k × AB, AB = (root, −√3 r/2), with v_B horizontal:
    # y: ω r/2 + ω_rod root = 0; x: −(√3/2) r ω + (√3/2) r ω_rod = −(√3/2) r ω (1 + r/(2 root))
    expected = -sympy.sqrt(3) / 2 * r * w * (1 + r / 2 / root)
    assert sympy.simplify(sol.velocity("B")[0] - expected) == 0


def test_symbolic_points_never_real_are_a_geometry_error():
    tree = dict(SLIDER_CRANK, points={"O": [0, 0], "A": ["r/2", "sqrt(-r)"], "B": [1, 0]})
    with pytest.raises(kinematika.KinematikaError) as err:
        kinematika.solve(tree)
    assert err.value.kind == "geometry" and "not real" in str(err.value)
