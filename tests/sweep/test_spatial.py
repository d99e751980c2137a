"""Sweeps of 3D models (general path): rotation vectors, redundant planar constraints."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from kinematika.sweep import run_sweep

from .models import four_bar_closed_form, four_bar_tree

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_robot_arm_yaw_turns_the_tip_on_a_circle():
    # yaw swept a full turn, the pitch joint held: E goes round the column at its height;
    # ω_arm = ψ' k + θ' u with the shoulder axis u = (sin ψ, −cos ψ, 0) turning with the base
    result = run_sweep(EXAMPLES / "robot_arm_3d.yaml", joint="yaw", by=360, steps=12)
    h, length, th = 0.5, 0.8, math.radians(45)
    psi = math.radians(30) + np.radians(result.coordinate)
    tip = np.column_stack([length * math.cos(th) * np.cos(psi), length * math.cos(th) * np.sin(psi),
                           np.full_like(psi, h + length * math.sin(th))])
    assert result.points["E@arm"]["position"] == pytest.approx(tip, abs=1e-10)
    omega = np.column_stack([np.sin(psi), -np.cos(psi), 0 * psi]) + [0, 0, 0.5]
    assert result.bodies["arm"]["omega"] == pytest.approx(omega, abs=1e-10)
    angle = result.bodies["base"]["angle"]           # a rotation vector, continued past 180°
    assert angle[:, 2] == pytest.approx(result.coordinate, abs=1e-9)
    assert angle[:, :2] == pytest.approx(np.zeros((13, 2)), abs=1e-9)


def test_planar_four_bar_built_in_3d_matches_loop_closure():
    tree = four_bar_tree(side=1.0)
    tree["dimension"] = 3
    tree["points"] = {k: v + [0] for k, v in tree["points"].items()}
    for joint in tree["joints"]:
        joint["axis"] = [0, 0, 1]
    tree["drivers"] = [{"omega": "crank", "value": [0, 0, 10], "alpha": [0, 0, -3]}]
    result = run_sweep(tree, by=360, steps=12)
    expect = four_bar_closed_form(np.radians(90 + result.coordinate), 4.0, 1.0, 4.0, 3.0, 1.0, 10.0,
                                  -3.0, (2.0, 1.0))
    assert result.points["P@coupler"]["position"][:, :2] == pytest.approx(np.column_stack(expect["P"]),
                                                                          abs=1e-9)
    assert result.bodies["rocker"]["omega"][:, 2] == pytest.approx(expect["w4"], abs=1e-9)
    assert result.bodies["rocker"]["alpha"][:, 2] == pytest.approx(expect["a4"], abs=1e-8)
    assert result.bodies["crank"]["angle"][-1] == pytest.approx([0, 0, 360], abs=1e-9)


def test_fan_driven_by_a_vector_along_its_hub_is_swept_as_by_the_hubs_rate():
    # the blades' ω relative to the block written as (0.5, 0, 0) in ground axes lies along the
    # hub's axis at the drawing: it is the hub's rate (`sweep.joint_rates`), carried along as
    # the block turns about y, and the sweep is the one driven by that rate. A vector off the
    # hub's axis is no joint's rate: once the block has turned, it contradicts the joints.
    from kinematika import KinematikaError

    tree = {"dimension": 3, "points": {"B": [0, 0, 0], "C": [0.6, 0, 0], "P": [0.6, 0.3, 0]},
            "bodies": {"ground": ["B"], "block": ["B", "C"], "blades": ["C", "P"]},
            "joints": [{"id": "shaft", "type": "revolute", "bodies": ["ground", "block"], "at": "B",
                        "axis": [0, 1, 0]},
                       {"id": "hub", "type": "revolute", "bodies": ["block", "blades"], "at": "C",
                        "axis": [1, 0, 0]}],
            "drivers": [{"joint": "shaft", "rate": 0.1},
                        {"omega": "blades", "relative_to": "block", "value": [0.5, 0, 0]}]}
    by_vector = run_sweep(tree, by=90, steps=3)
    tree["drivers"][1] = {"omega": "blades", "value": [0.5, 0.1, 0], "alpha": [0, 0, -0.05]}   # absolute: off the hub's axis
    for skip_bad in (False, True):
        with pytest.raises(KinematikaError) as err:
            run_sweep(tree, by=90, steps=3, skip_bad=skip_bad)
        assert err.value.kind == "mobility"
        assert "increment 1 (shaft = 30 deg" in str(err.value) and "rate" in str(err.value)
    tree["drivers"][1] = {"joint": "hub", "rate": 0.5}
    result = run_sweep(tree, by=90, steps=3)
    # the hub keeps its coordinate: P turns with the block about +y, (0.6 cos ψ, 0.3, −0.6 sin ψ)
    psi = np.radians(result.coordinate)
    expect = np.column_stack([0.6 * np.cos(psi), np.full(4, 0.3), -0.6 * np.sin(psi)])
    assert result.points["P@blades"]["position"] == pytest.approx(expect, abs=1e-10)
    for got in (by_vector, result):     # ω = 0.1 ŷ + 0.5 (cos ψ, 0, −sin ψ), the hub's axis turned
        assert got.bodies["blades"]["omega"] == pytest.approx(
            np.column_stack([0.5 * np.cos(psi), np.full(4, 0.1), -0.5 * np.sin(psi)]), abs=1e-12)
    assert by_vector.points["P@blades"]["velocity"] == pytest.approx(result.points["P@blades"]["velocity"], abs=1e-12)


def test_rssr_sweep_keeps_the_coupler_rigid_and_its_spin_idle():
    """The RSSR of tests/spatial/test_idle_spin.py, its crank turned back 60°. With the crank
    at θ (A = (−sin θ, cos θ, 0)) and the rocker at φ about x through D = (2, 0, 1)
    (B = (2, cos φ, 1 + sin φ)), the coupler's length gives
    (2 + sin θ)² + (cos φ − cos θ)² + (1 + sin φ)² = 5, solved here for φ by bisection on
    the drawn branch (φ from 0 upwards as θ decreases)."""
    from tests.spatial.test_idle_spin import RSSR

    result = run_sweep(RSSR, by=-60, steps=6)
    theta = np.radians(result.coordinate)

    def phi_of(t: float) -> float:
        f = lambda p: (2 + math.sin(t)) ** 2 + (math.cos(p) - math.cos(t)) ** 2 + (1 + math.sin(p)) ** 2 - 5
        lo, hi = -0.1, math.pi / 2
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if f(lo) * f(mid) > 0 else (lo, mid)
        return 0.5 * (lo + hi)

    phi = np.array([phi_of(t) for t in theta])
    b = np.column_stack([np.full_like(phi, 2.0), np.cos(phi), 1 + np.sin(phi)])
    assert result.points["B@rocker"]["position"] == pytest.approx(b, abs=1e-9)
    assert result.points["B@coupler"]["position"] == pytest.approx(b, abs=1e-9)
    a = np.column_stack([-np.sin(theta), np.cos(theta), 0 * theta])
    ab = b - a
    omega = result.bodies["coupler"]["omega"]
    assert np.einsum("ij,ij->i", omega, ab) == pytest.approx(np.zeros(7), abs=1e-9)   # no spin


def test_a_long_spatial_sweep_is_solved_in_chunks_with_the_same_positions(monkeypatch):
    """Long sweeps on the compiled Newton path build their stacked matrices a chunk at a
    time (memory): with chunks of 7 positions, the RSSR's 60 steps are the hand closure's
    φ(θ) as with one chunk, and velocities and accelerations are the same to 1e-12."""
    from kinematika.sweep import compiled
    from tests.spatial.test_idle_spin import RSSR

    whole = run_sweep(RSSR, by=-60, steps=60)
    monkeypatch.setattr(compiled, "CHUNK", 7)
    chunked = run_sweep(RSSR, by=-60, steps=60)
    theta = np.radians(chunked.coordinate)
    b = chunked.points["B@rocker"]["position"]
    a = np.column_stack([-np.sin(theta), np.cos(theta), 0 * theta])
    assert np.linalg.norm(b - a, axis=1) == pytest.approx(np.full(61, math.sqrt(5)), abs=1e-9)
    assert b[:, 0] == pytest.approx(np.full(61, 2.0), abs=1e-9)      # the rocker turns about x at D
    for kind in ("position", "velocity", "acceleration"):
        assert chunked.points["B@coupler"][kind] == pytest.approx(whole.points["B@coupler"][kind], abs=1e-12)
    assert chunked.bodies["coupler"]["alpha"] == pytest.approx(whole.bodies["coupler"]["alpha"], abs=1e-12)
