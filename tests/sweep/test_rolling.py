"""The general path through rolling contacts: the rolled arcs are equal (no slip)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinematika.sweep import run_sweep


def test_planet_rolling_inside_a_ring():
    # arm O-C turns by θ; a planet of radius 1 pinned at C rolls inside a fixed ring of radius 3.
    # No slip at the contact: 3 θ = 1 (θ − φ) so the planet turns by φ = −2 θ (absolute).
    tree = {"points": {"O": [0, 0], "C": [2, 0], "Q": [3, 0]},
            "bodies": {"ground": {"points": ["O"], "circle": {"center": "O", "radius": 3}},
                       "arm": ["O", "C"],
                       "planet": {"points": ["C", "Q"], "circle": {"center": "C", "radius": 1}}},
            "joints": [{"type": "revolute", "bodies": ["ground", "arm"], "at": "O"},
                       {"type": "revolute", "bodies": ["arm", "planet"], "at": "C"},
                       {"type": "rolling", "bodies": ["ground", "planet"]}],
            "drivers": [{"omega": "arm", "value": 1.5, "alpha": 0.5}]}
    result = run_sweep(tree, by=360, steps=24)
    assert result.method == "newton"
    assert result.bodies["planet"]["angle"] == pytest.approx(-2 * result.coordinate, abs=1e-8)
    assert result.bodies["planet"]["omega"] == pytest.approx(np.full(25, -3.0), abs=1e-9)
    assert result.bodies["planet"]["alpha"] == pytest.approx(np.full(25, -1.0), abs=1e-9)
    # Q, drawn at the contact, is a cusp of the hypocycloid: back on the ring when θ = 120°
    theta = np.radians(result.coordinate)
    q = np.column_stack([2 * np.cos(theta) + np.cos(-2 * theta), 2 * np.sin(theta) + np.sin(-2 * theta)])
    assert result.points["Q@planet"]["position"] == pytest.approx(q, abs=1e-9)


def test_pinion_drives_a_rack():
    # pinion of radius 0.5 pinned at the origin meshes with a rack whose pitch line is y = -0.5:
    # the pinion's contact point (0, -0.5) moves at ω k × (0, -0.5) = (0.5 ω, 0), so turning the
    # pinion by θ ccw moves the rack by 0.5 θ to the right.
    tree = {"points": {"O": [0, 0], "R": [0, -0.5]},
            "bodies": {"ground": ["O"],
                       "pinion": {"points": ["O"], "circle": {"center": "O", "radius": 0.5}},
                       "rack": {"points": ["R"], "line": {"through": "R", "direction": [1, 0]}}},
            "joints": [{"type": "revolute", "bodies": ["ground", "pinion"], "at": "O"},
                       {"type": "prismatic", "bodies": ["ground", "rack"], "along": [1, 0]},
                       {"type": "gear", "bodies": ["pinion", "rack"]}],
            "drivers": [{"omega": "pinion", "value": 2.0}]}
    result = run_sweep(tree, by=180, steps=6)
    theta = np.radians(result.coordinate)
    assert result.points["R@rack"]["position"][:, 0] == pytest.approx(0.5 * theta, abs=1e-9)
    assert result.points["R@rack"]["velocity"][:, 0] == pytest.approx(np.full(7, 1.0), abs=1e-9)
    assert math.isclose(result.points["R@rack"]["position"][-1, 1], -0.5, abs_tol=1e-12)


def test_the_roller_under_a_lever_sweeps_along_its_slider():
    """examples/seed_001_rolling_pair.yaml (its sweep: the slider 0.3 m on): the lever's line
    through B touches the roller (radius ρ, centre A at x from B), so sin β = ρ/x; then
    ω_N = dβ/dt = −v tan β / x, and no slip at the contact gives ω_R = v cos β / ρ (the slides)."""
    from pathlib import Path

    result = run_sweep(Path(__file__).resolve().parents[2] / "examples" / "seed_001_rolling_pair.yaml")
    assert len(result) == 61 and result.ok.all()
    rho, v = 0.1, 0.5
    x = 0.2 + np.asarray(result.coordinate)
    beta = np.arcsin(rho / x)
    assert result.bodies["N"]["angle"] == pytest.approx(np.degrees(beta - math.radians(30)), abs=1e-8)
    assert result.bodies["N"]["omega"] == pytest.approx(-v * np.tan(beta) / x, abs=1e-9)
    assert result.bodies["R"]["omega"] == pytest.approx(v * np.cos(beta) / rho, abs=1e-9)
