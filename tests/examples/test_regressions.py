"""Engine bugs found while writing the examples, each pinned by a small model."""
from __future__ import annotations

import math

import pytest
import sympy

import kinematika


def test_parameter_value_may_use_pi():
    # `pi` was accepted in points but rejected in a parameter's value ("unknown name 'pi'").
    sol = kinematika.solve({
        "parameters": {"w": "1500*2*pi/60"},
        "points": {"O": [0, 0], "A": [0.1, 0]},
        "bodies": {"ground": ["O"], "crank": ["O", "A"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"}],
        "drivers": [{"omega": "crank", "value": "w"}],
    })
    assert math.isclose(float(sol.omega("crank")), 50 * math.pi)


SYMBOLIC_SLIDER_CRANK = {
    "parameters": {"r": None, "l": None, "w": None},
    "points": {"O": [0, 0], "A": ["r/2", "sqrt(3)*r/2"], "B": ["r/2 + sqrt(l**2 - 3*r**2/4)", 0]},
    "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
               {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
               {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
               {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
    "drivers": [{"omega": "crank", "value": "w"}],
}


def test_symbolic_geometry_real_only_for_some_values_of_the_symbols():
    # sqrt(l² − 3r²/4) is real only for l > (√3/2) r; the engine's default probe values of
    # the symbols fell outside and the solve crashed ("Cannot convert complex to float").
    sol = kinematika.solve(SYMBOLIC_SLIDER_CRANK)
    r, l, w = (sympy.Symbol(n, positive=True) for n in "rlw")
    root = sympy.sqrt(l ** 2 - 3 * r ** 2 / 4)
    # v_B = ω k × OA + ω_rod k × AB, AB = (root, −√3 r/2), with v_B horizontal:
    # y: ω r/2 + ω_rod root = 0; x: −(√3/2) r ω + (√3/2) r ω_rod = −(√3/2) r ω (1 + r/(2 root))
    expected = -sympy.sqrt(3) / 2 * r * w * (1 + r / 2 / root)
    assert sympy.simplify(sol.velocity("B")[0] - expected) == 0


def test_symbolic_points_never_real_are_a_geometry_error():
    tree = dict(SYMBOLIC_SLIDER_CRANK, points={"O": [0, 0], "A": ["r/2", "sqrt(-r)"], "B": [1, 0]})
    with pytest.raises(kinematika.KinematikaError) as err:
        kinematika.solve(tree)
    assert err.value.kind == "geometry" and "not real" in str(err.value)
