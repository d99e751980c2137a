"""Sweeps against closed forms derived by hand: the four-bar by loop closure, the slider-crank
by its position formula differentiated twice. Both solution paths are checked: the closed
form over Assur groups and the general Newton continuation (forced by dropping the former)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from kinematika.sweep import run_sweep
from kinematika.sweep.run import Sweeper

from .models import four_bar_closed_form, four_bar_tree, slider_crank_closed_form, slider_crank_tree

GEOMETRY = dict(ground=4.0, crank=1.0, coupler=4.0, rocker=3.0)


def newton(tree, **kw):
    sweeper = Sweeper(tree)
    sweeper.closed = None          # force the general path
    return sweeper.run(**kw)


@pytest.mark.parametrize("solve", [run_sweep, newton], ids=["closed-form", "newton"])
def test_four_bar_over_a_turn_matches_loop_closure(solve):
    tree = four_bar_tree(**GEOMETRY, crank_deg=90, w=10.0, al=-3.0, side=-1.0)
    result = solve(tree, by=360, steps=24)
    theta = np.radians(90 + result.coordinate)
    expect = four_bar_closed_form(theta, **GEOMETRY, side=-1.0, w=10.0, al=-3.0, point=(2.0, 1.0))
    assert result.ok.all()
    assert result.points["B@rocker"]["position"] == pytest.approx(np.column_stack(expect["B"]), abs=1e-9)
    assert result.points["P@coupler"]["position"] == pytest.approx(np.column_stack(expect["P"]), abs=1e-9)
    assert result.bodies["coupler"]["omega"] == pytest.approx(expect["w3"], abs=1e-8)
    assert result.bodies["rocker"]["omega"] == pytest.approx(expect["w4"], abs=1e-8)
    assert result.bodies["coupler"]["alpha"] == pytest.approx(expect["a3"], abs=1e-7)
    assert result.bodies["rocker"]["alpha"] == pytest.approx(expect["a4"], abs=1e-7)
    assert result.points["P@coupler"]["velocity"] == pytest.approx(np.column_stack(expect["vP"]), abs=1e-8)
    assert result.points["P@coupler"]["acceleration"] == pytest.approx(np.column_stack(expect["aP"]),
                                                                         abs=1e-7)
    assert result.bodies["crank"]["alpha"] == pytest.approx(-3.0)


@pytest.mark.parametrize("solve", [run_sweep, newton], ids=["closed-form", "newton"])
def test_offset_slider_crank_matches_its_formula(solve):
    r, l, e, w = 1.0, 3.0, 0.5, 10.0
    result = solve(slider_crank_tree(r, l, e, crank_deg=60, w=w), by=360, steps=18)
    theta = np.radians(60 + result.coordinate)
    expect = slider_crank_closed_form(theta, r, l, e, w)
    assert result.points["B@slider"]["position"][:, 0] == pytest.approx(expect["x"], abs=1e-9)
    assert result.points["B@slider"]["position"][:, 1] == pytest.approx(np.full(19, e), abs=1e-9)
    assert result.points["B@slider"]["velocity"][:, 0] == pytest.approx(expect["v"], abs=1e-8)
    assert result.points["B@slider"]["acceleration"][:, 0] == pytest.approx(expect["a"], abs=1e-7)
    phi0 = expect["phi"][0]
    assert result.bodies["rod"]["angle"] == pytest.approx(np.degrees(expect["phi"] - phi0), abs=1e-8)
    assert result.bodies["rod"]["omega"] == pytest.approx(expect["w"], abs=1e-8)
    assert result.bodies["rod"]["alpha"] == pytest.approx(expect["al"], abs=1e-7)
    assert result.bodies["slider"]["omega"] == pytest.approx(np.zeros(19), abs=1e-12)


def test_slider_driven_slider_crank_moves_the_crank_back():
    # drive the slider: its joint is the sweep's; the crank follows (RRR read from the slider side)
    tree = slider_crank_tree(1.0, 3.0, 0.0, crank_deg=90, w=0.0)
    tree["drivers"] = [{"velocity": "B@slider", "along": [1, 0], "value": -2.0}]
    result = run_sweep(tree, by=-0.3, steps=3)
    x = result.points["B@slider"]["position"][:, 0]
    x0 = math.sqrt(9 - 1)
    assert x == pytest.approx(x0 - np.array([0, 0.1, 0.2, 0.3]), abs=1e-12)
    # the crank angle θ solves x = cos θ + √(9 − sin² θ) on the drawn branch (θ from 90°)
    for k, xk in enumerate(x):
        th = math.radians(90 + result.bodies["crank"]["angle"][k])
        assert math.cos(th) + math.sqrt(9 - math.sin(th) ** 2) == pytest.approx(xk, abs=1e-10)
    assert result.points["B@slider"]["velocity"][:, 0] == pytest.approx(np.full(4, -2.0))


@settings(max_examples=15, deadline=None)
@given(crank=st.floats(0.5, 1.5), coupler=st.floats(3.0, 5.0), rocker=st.floats(2.5, 4.0),
       start=st.floats(0, 360), side=st.sampled_from([1.0, -1.0]))
def test_paths_agree_on_random_crank_rockers(crank, coupler, rocker, start, side):
    ground = 4.0
    lengths = sorted([ground, crank, coupler, rocker])
    assume(lengths[0] == crank and lengths[0] + lengths[3] < lengths[1] + lengths[2] - 0.3)
    tree = four_bar_tree(ground, crank, coupler, rocker, crank_deg=start, side=side)
    fast = run_sweep(tree, by=360, steps=12)
    slow = newton(tree, by=360, steps=12)
    assert fast.method == "closed form" and slow.method == "newton"
    for name in fast.points:
        for q in ("position", "velocity", "acceleration"):
            assert slow.points[name][q] == pytest.approx(fast.points[name][q], rel=1e-7, abs=1e-7)
    for name in fast.bodies:
        assert slow.bodies[name]["angle"] == pytest.approx(fast.bodies[name]["angle"], abs=1e-7)


@pytest.mark.parametrize("name", ["watt_six_bar", "jansen_leg"])
def test_paths_agree_on_multi_loop_examples(name):
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "examples" / f"{name}.yaml"
    fast = run_sweep(path, steps=24)
    slow = newton(path, steps=24)
    assert fast.method == "closed form"
    for point in fast.points:
        for q in ("position", "velocity", "acceleration"):
            assert slow.points[point][q] == pytest.approx(fast.points[point][q], abs=1e-7)
