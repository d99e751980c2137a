"""Engine bugs found while writing the examples, each pinned by a small model."""
from __future__ import annotations

import math

import sympy

import kinematika

from .helpers import EXAMPLES


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



def test_forced_symbols_keep_derived_parameters_as_formulas():
    # With --symbolic every parameter became an independent symbol, also those defined from
    # others (y2 = r2 − r3 in the pulley train), so the geometry no longer held ("'belt2'
    # does not touch 'pulley3'"). Given values become symbols; derived ones stay formulas.
    sol = kinematika.solve(EXAMPLES / "pulley_train.yaml", symbolic=True)
    r1, r2, r3, r4, w1 = (sympy.Symbol(n, positive=True) for n in ("r1", "r2", "r3", "r4", "w1"))
    # belt speeds equal at each pulley's lowest point: w1 r1 = w2 r2, w2 r3 = w4 r4
    assert sympy.simplify(sol.omega("pulley4") - w1 * r1 / r2 * r3 / r4) == 0
