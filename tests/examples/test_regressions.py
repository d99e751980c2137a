"""Engine bugs found while writing the examples, each pinned by a small model."""
from __future__ import annotations

import math

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

