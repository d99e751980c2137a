"""Branch continuity: a crank-rocker whose assembly comes close to its mirror image.

Ground 4, crank 2.1, coupler 3.9, rocker 2.3: Grashof (2.1 + 4 < 3.9 + 2.3) by a margin of
0.1 only, so twice a turn the transmission angle falls to about 20° and the mirror position
of B is near. Over a full turn the mechanism must stay on the drawn branch: the side of
the line A→O4 on which B lies never changes, angles change smoothly, and the last
position is the first.
"""
from __future__ import annotations

import numpy as np
import pytest

from kinematika.sweep import run_sweep
from kinematika.sweep.run import Sweeper

from .models import four_bar_closed_form, four_bar_tree

NEAR = dict(ground=4.0, crank=2.1, coupler=3.9, rocker=2.3)


def _side(result) -> np.ndarray:
    a = result.points["A@coupler"]["position"]
    b = result.points["B@coupler"]["position"]
    o4 = result.points["O4@rocker"]["position"]
    return np.sign((o4[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1]) - (o4[:, 1] - a[:, 1]) * (b[:, 0] - a[:, 0]))


@pytest.mark.parametrize("side", [1.0, -1.0])
@pytest.mark.parametrize("steps", [360, 20])
@pytest.mark.parametrize("general", [False, True], ids=["closed-form", "newton"])
def test_full_turn_stays_on_the_drawn_branch(side, steps, general):
    tree = four_bar_tree(**NEAR, crank_deg=30, point=(1.5, 1.2), side=side)
    sweeper = Sweeper(tree)
    if general:
        sweeper.closed = None
    result = sweeper.run(by=360, steps=steps)
    assert result.ok.all()
    assert (_side(result) == _side(result)[0]).all()
    expect = four_bar_closed_form(np.radians(30 + result.coordinate), **NEAR, side=side, w=10.0,
                                  al=0.0, point=(1.5, 1.2))
    assert result.points["P@coupler"]["position"] == pytest.approx(np.column_stack(expect["P"]), abs=1e-8)
    for body in ("coupler", "rocker"):
        angle = result.bodies[body]["angle"]
        assert angle[-1] == pytest.approx(angle[0], abs=1e-8)        # the cycle closes
    if steps == 360:
        assert np.abs(np.diff(result.bodies["rocker"]["angle"])).max() < 3.0   # no jump


def test_crank_angle_is_continuous_and_ends_at_a_full_turn():
    result = run_sweep(four_bar_tree(**NEAR, side=1.0), by=360, steps=8)
    assert result.bodies["crank"]["angle"] == pytest.approx(np.linspace(0, 360, 9))
    back = run_sweep(four_bar_tree(**NEAR, side=1.0), by=-720, steps=8)
    assert back.bodies["crank"]["angle"][-1] == pytest.approx(-720)
