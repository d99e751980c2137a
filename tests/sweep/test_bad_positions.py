"""Positions that cannot be assembled, or are singular: the error names the increment, and
--skip-bad leaves those rows empty (NaN in Python, null in JSON)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinematika import KinematikaError
from kinematika.sweep import run_sweep
from kinematika.sweep.run import Sweeper

from .models import four_bar_tree, rocker_driven_tree

# non-Grashof (2.5 + 4 > 3 + 3): the "crank" cannot turn fully
TRIPLE_ROCKER = dict(ground=4.0, crank=2.5, coupler=3.0, rocker=3.0)


def _reach_limits():
    """Crank angles (absolute, degrees) where |O4A| = coupler + rocker = 6: the loop's limit."""
    # |A - O4|² = 2.5² + 16 - 20 cos θ = 36  ->  cos θ = (6.25 + 16 - 36) / 20
    return math.degrees(math.acos((6.25 + 16 - 36) / 20))


@pytest.mark.parametrize("general", [False, True], ids=["closed-form", "newton"])
def test_sweep_stops_with_an_assembly_error_naming_the_increment(general):
    sweeper = Sweeper(four_bar_tree(**TRIPLE_ROCKER, crank_deg=90, side=1.0))
    if general:
        sweeper.closed = None
    limit = _reach_limits()                      # 133.4°: rows beyond 43.4° of travel fail
    first_bad = math.ceil((limit - 90) / 10)
    with pytest.raises(KinematikaError) as err:
        sweeper.run(by=360, steps=36, through=False)
    assert err.value.kind == "assembly"
    assert f"increment {first_bad} (j1 = {10 * first_bad} deg" in str(err.value)
    assert "--skip-bad" in str(err.value)


@pytest.mark.parametrize("general", [False, True], ids=["closed-form", "newton"])
def test_skip_bad_leaves_the_rows_empty(general):
    sweeper = Sweeper(four_bar_tree(**TRIPLE_ROCKER, crank_deg=90, side=1.0))
    if general:
        sweeper.closed = None
    result = sweeper.run(by=360, steps=36, skip_bad=True, through=False)
    travel = result.coordinate
    # assemblable while |θ| <= limit (θ = 90° + travel, taken in (−180°, 180°])
    theta = (90 + travel + 180) % 360 - 180
    expected = np.abs(theta) <= _reach_limits()
    assert (result.ok == expected).all()
    assert np.isnan(result.bodies["rocker"]["omega"][~expected]).all()
    assert np.isnan(result.points["B@coupler"]["position"][~expected]).all()
    if general:
        assert result.dead_points[0] == pytest.approx(40.0)    # the last row before the gap
    else:                                                       # the closed form finds the edge
        assert result.dead_points[0] == pytest.approx(_reach_limits() - 90, abs=10 / 4096)
        assert result.dead_points[1] == pytest.approx(270 - _reach_limits(), abs=10 / 4096)
    data = result.to_json()
    bad = int(np.flatnonzero(~expected)[0])
    assert data["bodies"]["rocker"]["angle"][bad] is None
    assert data["points"]["B@coupler"]["velocity"][bad] is None
    assert data["points"]["B@coupler"]["velocity"][0] is not None


def test_a_sweep_onto_a_dead_point_is_singular():
    # Driven from the rocker, the crank-rocker 4, 1, 4, 3 stops where crank and coupler are in
    # line: |O2B| = 5 makes O2-O4-B a 3-4-5 triangle, the rocker straight up (90°).
    tree = rocker_driven_tree()          # ground 4, crank 1, coupler 4, rocker 3 at 120°, A on the left
    with pytest.raises(KinematikaError) as err:
        run_sweep(tree, by=-30, steps=3)
    assert err.value.kind == "singular"
    assert "increment 3 (j4 = -30 deg" in str(err.value)
    result = run_sweep(tree, by=-30, steps=3, skip_bad=True)
    assert result.ok.tolist() == [True, True, True, False]
    assert result.dead_points == [-30.0]
