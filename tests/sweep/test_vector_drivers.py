"""A 3D ω driver along a revolute's axis is that joint's rate in a motion (`sweep.joint_rates`):
the notes' fan (seed 000), whose blades' ω relative to the motor block is written as the
vector (ω₂, 0, 0) along the hub's axis BC, swept over the shaft's turn and followed in time.

By hand: the block turns about +y by θ, so the hub's axis is e(θ) = R_y(θ) x̂ = (cos θ, 0,
−sin θ); the blades turn about it relative to the block by φ. Their angular velocity is
ω = ω₁ ŷ + ω₂ e, and (the relative rate's derivative seen from the block being α₂ e) their
angular acceleration α = α₁ ŷ + α₂ e + ω₁ ŷ × ω₂ e, with ŷ × e = (−sin θ, 0, −cos θ). B, the
origin, is on the hub's axis and on the shaft, so it stays at rest and v_P = ω × P; the
blade point P = R_y(θ) (0.6, 0.3 cos φ, 0.3 sin φ) (C = (0.6, 0, 0), CP = (0, 0.3, 0) drawn).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from kinematika.simulate import run_simulation
from kinematika.sweep import run_sweep

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
W1, A1, W2, A2 = 0.1, 0.2, 0.5, 0.01


def axis(theta):
    return np.column_stack([np.cos(theta), np.zeros_like(theta), -np.sin(theta)])


def blade_point(theta, phi):
    x, y, z = 0.6 + 0 * phi, 0.3 * np.cos(phi), 0.3 * np.sin(phi)
    return np.column_stack([x * np.cos(theta) + z * np.sin(theta), y, -x * np.sin(theta) + z * np.cos(theta)])


@pytest.mark.parametrize("name", ["fan_absolute", "fan_composition", "fan_symbolic"])
def test_the_fan_is_swept_over_the_shafts_turn(name):
    """The sweep turns the shaft by θ and holds the blades' turn relative to it (φ = 0)."""
    result = run_sweep(EXAMPLES / f"{name}.yaml", by=360, steps=8)
    theta = np.radians(result.coordinate)
    e = axis(theta)
    up = np.array([0.0, 1.0, 0.0])
    omega = W1 * up + W2 * e
    alpha = A1 * up + A2 * e + W1 * W2 * np.column_stack([-np.sin(theta), 0 * theta, -np.cos(theta)])
    blades = next(b for b in result.bodies if b == "blades")
    assert result.ok.all()
    assert result.bodies[blades]["omega"] == pytest.approx(omega, abs=1e-12)
    assert result.bodies[blades]["alpha"] == pytest.approx(alpha, abs=1e-12)
    p = blade_point(theta, 0 * theta)
    point = result.points["P@blades"]
    assert point["position"] == pytest.approx(p, abs=1e-12)
    assert point["velocity"] == pytest.approx(np.cross(omega, p), abs=1e-12)
    assert point["velocity"][0] == pytest.approx([0, 0, 0.09])          # the notes' v_P
    assert point["acceleration"][0] == pytest.approx([0.024, -0.075, -0.117])   # the notes' a_P


def test_the_fan_turns_about_both_axes_in_time():
    """In time both rates are kept (their accelerations left out, as the summary says):
    θ = ω₁ t, φ = ω₂ t, α = ω₁ ŷ × ω₂ e."""
    result = run_simulation(EXAMPLES / "fan_absolute.yaml", time=12.0, steps=6)
    t = result.time
    theta, phi = W1 * t, W2 * t
    e = axis(theta)
    omega = W1 * np.array([0.0, 1.0, 0.0]) + W2 * e
    assert result.ok.all()
    assert result.bodies["blades"]["omega"] == pytest.approx(omega, abs=1e-9)
    assert result.bodies["blades"]["alpha"] == pytest.approx(
        W1 * W2 * np.column_stack([-np.sin(theta), 0 * t, -np.cos(theta)]), abs=1e-9)
    p = blade_point(theta, phi)
    assert result.points["P@blades"]["position"] == pytest.approx(p, abs=1e-8)
    assert result.points["P@blades"]["velocity"] == pytest.approx(np.cross(omega, p), abs=1e-8)
    assert math.isclose(result.bodies["block"]["angle"][-1][1], math.degrees(W1 * 12.0), rel_tol=1e-9)


def test_a_vector_driver_off_the_axis_is_left_as_written():
    """A vector ω not along the joint's axis is no joint's rate: the sweep still says the
    drivers contradict the joints once the shaft has turned."""
    import yaml

    from kinematika.errors import KinematikaError

    tree = yaml.safe_load((EXAMPLES / "fan_composition.yaml").read_text(encoding="utf-8"))
    tree["drivers"][1] = {"omega": "blades", "value": [0.5, 0.1, 0]}      # absolute: off the hub's axis
    with pytest.raises(KinematikaError) as err:
        run_sweep(tree, by=90, steps=2)
    assert err.value.kind == "mobility"


def test_the_fan_posed_at_a_row_of_its_sweep_keeps_its_driver_along_the_turned_axis():
    """The page's slider poses the model at a row of its sweep (`prepare(row=...)`): at
    θ = 45° the blades' rate relative to the block is ω₂ e(45°), and their absolute ω and
    α are the formulas above."""
    from kinematika.sweep.posing import solved

    sol = solved(EXAMPLES / "fan_composition.yaml", row=45)
    theta = np.radians([45.0])
    e = axis(theta)[0]
    assert [float(c) for c in sol.omega("blades", "block")] == pytest.approx(W2 * e, abs=1e-12)
    assert [float(c) for c in sol.omega("blades")] == pytest.approx(W1 * np.array([0, 1, 0]) + W2 * e, abs=1e-12)
    assert [float(c) for c in sol.alpha("blades")] == pytest.approx(
        A1 * np.array([0, 1, 0]) + A2 * e + W1 * W2 * np.array([-np.sin(theta[0]), 0, -np.cos(theta[0])]), abs=1e-12)
    assert [float(c) for c in sol.position("P@blades")] == pytest.approx(blade_point(theta, 0 * theta)[0], abs=1e-12)
