"""Motions in time against closed forms derived by hand (each test's docstring says how):
a coin rolling at a constant lean, a trailer settling behind a tractor on a circle, the
notes' tricycle (C5-2.1) turning about its instant centre up to its dead point, the notes'
articulated vehicle (C5-2.2) trailing as a tractrix, and a slider-crank whose crank speeds
up in time."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from kinematika.simulate import run_simulation
from kinematika.simulate.run import SimulationStopped
from tests.conftest import sampled

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def coin_tree(radius=0.02, lean_deg=20.0, turn=2.0, spin=-6.0) -> dict:
    """A coin (a disc) rolling on the table z = 0, leaning by `lean_deg` from the vertical.
    A yoke holds its axle at the centre C and turns about the vertical at `turn` (ω of the
    yoke, fixed in the ground's axes: the lean stays); the coin spins on the axle at `spin`."""
    b = math.radians(lean_deg)
    return {
        "name": "Coin", "dimension": 3,
        "points": {"O": [0, 0, 0], "J": [0.15, 0, 0],
                   "C": [0.15 - radius * math.sin(b), 0, radius * math.cos(b)]},
        "bodies": {"ground": {"points": ["O"], "plane": {"through": "O", "normal": [0, 0, 1]}},
                   "yoke": ["C"],
                   "coin": {"points": ["C", "J"],
                            "disc": {"center": "C", "radius": radius, "axis": [math.cos(b), 0, math.sin(b)]}}},
        "joints": [{"id": "axle", "type": "revolute", "bodies": ["yoke", "coin"], "at": "C",
                    "axis": [math.cos(b), 0, math.sin(b)]},
                   {"id": "roll", "type": "rolling", "bodies": ["ground", "coin"]}],
        "drivers": [{"omega": "yoke", "value": [0, 0, turn]}, {"joint": "axle", "rate": spin}],
    }


def test_a_coin_at_a_constant_lean_traces_its_circle():
    """By hand: the coin's ω = Ω k + s a(t), a(t) the axis turned by Ωt about the vertical.
    Rolling, v_J = 0, so v_C = ω × R u with u = (−sin β, 0, cos β) (from J to C, turned by
    Ωt): k × u = (0, −sin β, 0) and a × u = (0, −1, 0), so v_C = −R (Ω sin β + s) ŷ turned by
    Ωt: a constant speed whose direction turns at Ω. C runs on a circle of radius
    ρ = −R (Ω sin β + s)/Ω about C₀ − (ρ, 0, 0), at the height R cos β."""
    radius, beta, turn, spin = 0.02, math.radians(20.0), 2.0, -6.0
    result = run_simulation(coin_tree(radius, 20.0, turn, spin), time=math.pi, steps=12)
    rho = -radius * (turn * math.sin(beta) + spin) / turn
    c0 = np.array([0.15 - radius * math.sin(beta), 0.0])
    t = result.time
    expect = (c0 - [rho, 0.0]) + rho * np.column_stack([np.cos(turn * t), np.sin(turn * t)])
    c = result.points["C@coin"]["position"]
    assert c[:, :2] == pytest.approx(expect, abs=1e-8)
    assert c[:, 2] == pytest.approx(np.full(len(t), radius * math.cos(beta)), abs=1e-10)
    axis = np.column_stack([math.cos(beta) * np.cos(turn * t), math.cos(beta) * np.sin(turn * t),
                            np.full(len(t), math.sin(beta))])
    omega = turn * np.array([0.0, 0.0, 1.0]) + spin * axis
    assert result.bodies["coin"]["omega"] == pytest.approx(omega, abs=1e-8)
    speed = np.linalg.norm(result.points["C@coin"]["velocity"], axis=1)
    assert speed == pytest.approx(np.full(len(t), turn * rho), rel=1e-8)
    assert result.drift.max() < 1e-7


def test_a_trailer_settles_on_the_circle_of_radius_root_of_r2_minus_l2():
    """By hand (the example's comment): the tractor turns about (0, ρ), ρ = wb/tan δ, fixed in
    the ground (its steering held), at ω = v/ρ; the hitch H runs on the circle of radius
    R = √(h² + ρ²). In the steady state the trailer's axle line passes through the centre and
    H is L from T along the trailer, so T runs on the circle of radius √(R² − L²)."""
    wb, steer, h, length, v = 2.5, math.radians(20.0), 1.0, 4.0, 2.0
    result = run_simulation(EXAMPLES / "tractor_trailer_turning.yaml", steps=30)
    rho = wb / math.tan(steer)
    centre = np.array([0.0, rho])
    big = math.hypot(h, rho)
    hitch = np.linalg.norm(result.points["H@trailer"]["position"] - centre, axis=1)
    assert hitch == pytest.approx(np.full(len(hitch), big), abs=1e-9)
    assert result.bodies["tractor"]["omega"] == pytest.approx(np.full(len(hitch), v / rho), rel=1e-10)
    axle = np.linalg.norm(result.points["T@trailer"]["position"] - centre, axis=1)
    late = result.time >= 40.0
    assert axle[late] == pytest.approx(np.full(late.sum(), math.sqrt(big ** 2 - length ** 2)), abs=1e-6)
    assert axle[0] == pytest.approx(math.hypot(h + length, rho))        # straight behind at the start
    assert result.bodies["trailer"]["omega"][late] == pytest.approx(np.full(late.sum(), v / rho), rel=1e-6)


def test_the_tricycle_turns_about_its_centre_until_its_dead_point():
    """The notes' C5-2.1 (L = 1.2, s = 0.4, v₀ = 2, its draw_at): the chassis turns about
    (0, L), fixed in the ground while the steering is held, at ω = v₀/(√2 L) at the start
    and the left rear wheel's centre moves at v₀ (L − s)/(√2 L) (the notes' answers). The
    driver keeps F's velocity along the fixed (1, 1)/√2 at v₀, and F's velocity, √2 L ω, turns
    with the chassis: √2 L ω cos θ = v₀, θ̇ = ω, so sin θ = v₀ t/(√2 L). At t* = √2 L/v₀ the
    velocity would be across the driver's direction: a dead point."""
    big, half, v0 = 1.2, 0.4, 2.0
    result = run_simulation(EXAMPLES / "seed_c5_2_1_tricycle.yaml", time=0.8, steps=8)
    t = result.time
    theta = np.arcsin(v0 * t / (math.sqrt(2) * big))
    assert result.bodies["chassis"]["omega"][0] == pytest.approx(v0 / (math.sqrt(2) * big))
    assert np.linalg.norm(result.points["C1@chassis"]["velocity"][0]) == pytest.approx(
        v0 * (big - half) / (math.sqrt(2) * big))
    centre = np.array([0.0, big])
    for name, drawn in (("C1@chassis", (0.0, half)), ("C2@chassis", (0.0, -half)), ("F@chassis", (big, 0.0))):
        r = np.subtract(drawn, centre)
        expect = centre + np.column_stack([np.cos(theta) * r[0] - np.sin(theta) * r[1],
                                           np.sin(theta) * r[0] + np.cos(theta) * r[1]])
        assert result.points[name]["position"] == pytest.approx(expect, abs=1e-8), name
    assert result.bodies["chassis"]["omega"] == pytest.approx(v0 / (math.sqrt(2) * big * np.cos(theta)), rel=1e-7)
    assert result.bodies["chassis"]["angle"] == pytest.approx(np.degrees(theta), abs=1e-7)
    with pytest.raises(SimulationStopped) as stop:
        run_simulation(EXAMPLES / "seed_c5_2_1_tricycle.yaml", time=1.0, steps=10)
    assert stop.value.kind == "singular"
    assert f"t = {math.sqrt(2) * big / v0:.6g} s" in stop.value.message
    kept = stop.value.result
    assert len(kept) == 9 and kept.time[-1] == pytest.approx(0.8)     # the rows before it
    assert "symbols at their draw_at numbers" in " ".join(kept.notes)


def test_the_articulated_vehicle_trails_as_a_tractrix():
    """The notes' C5-2.2 (a = 1, r = 0.3, w = 5, its draw_at): S1 translates at V = r w along x
    (its wheels on one axle, both driven), so the hinge O does. S2's axle midpoint P2 is a
    behind O along S2's heading φ (from P2 to O), and its knife edges forbid P2 any velocity
    across it: v_P2 = V x̂ − a φ̇ (−sin φ, cos φ) has no component along (−sin φ, cos φ), so
    φ̇ = −(V/a) sin φ: tan(φ/2) = tan(φ₀/2) e^(−V t/a), φ₀ = 45°; at the start ω_S2 = −V/(√2 a),
    as the notes find by the instant centre."""
    a, r, w = 1.0, 0.3, 5.0
    speed = r * w
    result = run_simulation(EXAMPLES / "seed_c5_2_2_articulated.yaml", time=2.0, steps=10)
    t = result.time
    phi = 2 * np.arctan(math.tan(math.radians(22.5)) * np.exp(-speed * t / a))
    hinge = np.column_stack([speed * t, np.zeros(len(t))])
    assert result.points["O@S1"]["position"] == pytest.approx(hinge, abs=1e-10)
    assert result.bodies["S1"]["omega"] == pytest.approx(np.zeros(len(t)), abs=1e-12)
    axle = hinge - a * np.column_stack([np.cos(phi), np.sin(phi)])
    assert result.points["P@S2"]["position"] == pytest.approx(axle, abs=1e-8)
    assert result.bodies["S2"]["omega"] == pytest.approx(-(speed / a) * np.sin(phi), abs=1e-8)
    assert result.bodies["S2"]["omega"][0] == pytest.approx(-speed / (math.sqrt(2) * a))


def slider_crank(theta, r, l, e):
    """The slider's x(θ) and its first two derivatives in θ (crank O-A of radius r, rod A-B of
    length l, B on the line y = e): x = r cos θ + g, g = √(l² − (r sin θ − e)²)."""
    s, s1, s2 = r * np.sin(theta) - e, r * np.cos(theta), -r * np.sin(theta)
    g = np.sqrt(l * l - s * s)
    x1 = -r * np.sin(theta) - s * s1 / g
    x2 = -r * np.cos(theta) - (s1 * s1 + s * s2) / g - (s * s1) ** 2 / g ** 3
    return r * np.cos(theta) + g, x1, x2


def test_a_mechanism_a_sweep_follows_moves_in_time_with_a_rate_written_in_t():
    """A slider-crank whose crank speeds up, ω = w₀ + k t: θ = θ₀ + w₀ t + k t²/2, α = k, and
    the slider's v = x' ω, a = x'' ω² + x' α (x' and x'' its derivatives in θ)."""
    r, l, e, w0, k, start = 1.0, 3.0, 0.5, 4.0, 3.0, math.radians(60.0)
    a = (r * math.cos(start), r * math.sin(start))
    tree = {"name": "Slider-crank speeding up", "parameters": {"t": 0, "w0": w0, "k": k},
            "points": {"O": [0, 0], "A": list(a), "B": [a[0] + math.sqrt(l * l - (a[1] - e) ** 2), e]},
            "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                       {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
                       {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
                       {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
            "drivers": [{"omega": "crank", "value": "w0 + k*t"}]}
    result = run_simulation(tree, time=1.5, steps=15)
    t = result.time
    omega = w0 + k * t
    theta = start + w0 * t + k * t * t / 2
    x, x1, x2 = slider_crank(theta, r, l, e)
    assert result.bodies["crank"]["angle"] == pytest.approx(np.degrees(theta - start), abs=1e-7)
    assert result.bodies["crank"]["alpha"] == pytest.approx(np.full(len(t), k))
    assert result.points["B@slider"]["position"][:, 0] == pytest.approx(x, abs=1e-9)
    assert result.points["B@slider"]["velocity"][:, 0] == pytest.approx(x1 * omega, abs=1e-8)
    assert result.points["B@slider"]["acceleration"][:, 0] == pytest.approx(x2 * omega ** 2 + x1 * k, abs=1e-7)
    assert result.drift.max() < 1e-8


IN_TIME = ["car_wheel_steering", "coin_rolling", "seed_c5_2_1_tricycle", "seed_c5_2_2_articulated",
           "tractor_trailer", "tractor_trailer_turning"]


def test_every_example_a_sweep_cannot_follow_moves_in_time():
    """The bundled examples with a knife edge or a disc rolling on a plane (listed here, so
    that a new one is seen) are followed in time, row 0 as drawn and drift kept small: a
    knife edge and a disc on a plane by default (every one in a deep run)."""
    from kinematika import load_model
    from kinematika.simulate import needs_time

    found = sorted(p.stem for p in EXAMPLES.glob("*.yaml") if needs_time(load_model(p)))
    assert found == IN_TIME
    for name in sampled(IN_TIME, {"coin_rolling", "tractor_trailer"}):
        result = run_simulation(EXAMPLES / f"{name}.yaml", time=0.1, steps=2)
        assert len(result) == 3 and result.ok.all(), name
        assert result.drift.max() < 1e-8, name


def test_a_wheel_rolls_once_round_a_cylinder():
    """The notes' C5-1.8 (r = 0.1, w0 = 2, its draw_at) over its section, 6π/w0: a wheel of
    radius r rolling outside a fixed circle of radius 2r at ω = −w0. The contact J = 2r u(ψ),
    u(ψ) = (cos ψ, sin ψ), is the wheel's instant centre, so v_C = ω k × (C − J) = ω r u'(ψ);
    C = 3r u(ψ) gives v_C = 3r ψ̇ u'(ψ): ψ̇ = ω/3, ψ = 90° − w0 t/3 — once round while the
    wheel turns three times, its angle −w0 t continuous past every half turn (the line of
    centres is read on the right sheet at every row); a_C = −3r ψ̇² u(ψ)."""
    r, w0 = 0.1, 2.0
    result = run_simulation(EXAMPLES / "seed_c5_1_8_contact_points.yaml", steps=12)
    t = result.time
    assert t[-1] == pytest.approx(6 * math.pi / w0)
    psi = math.pi / 2 - w0 * t / 3
    u = np.column_stack([np.cos(psi), np.sin(psi)])
    c = result.points["C@wheel"]
    assert c["position"] == pytest.approx(3 * r * u, abs=1e-8)
    assert c["velocity"] == pytest.approx(r * w0 * np.column_stack([np.sin(psi), -np.cos(psi)]), abs=1e-8)
    assert c["acceleration"] == pytest.approx(-3 * r * (w0 / 3) ** 2 * u, abs=1e-8)
    assert result.bodies["wheel"]["angle"] == pytest.approx(np.degrees(-w0 * t), abs=1e-6)
    assert result.drift.max() < 1e-8


def test_the_wheels_with_a_rod_stop_where_the_pin_reaches_the_ground():
    """The notes' C5-E.3 (R = 0.3, w = 2): wheels of radius R on the ground, centres 4R apart,
    the rod (√26 R long) pinned at the top A of the left wheel and the rightmost point B of
    the right one. Rolling, the left wheel turned by φ₁ (counter-clockwise) has its centre at
    −R φ₁ and A at (−R φ₁ − R sin φ₁, R + R cos φ₁); the right one turned by φ₂ has B at
    (4R − R φ₂ + R cos φ₂, R + R sin φ₂), whose rate in φ₂, (−R − R sin φ₂, R cos φ₂), is
    zero at φ₂ = −90°: B on the ground, the right wheel's instant centre. There the rod's
    length condition |A − B|² = 26 R² cannot be kept by the right wheel's turn, so the left
    wheel's turn φ₁ is at its extreme (a limit position of the input): φ₁* solves
    |A(φ₁) − (4R + R π/2, 0)|² = 26 R², and at ω = −w, t* = −φ₁*/w."""
    from scipy.optimize import brentq

    big, w = 0.3, 2.0

    def gap(p1):
        a = (-big * p1 - big * math.sin(p1), big + big * math.cos(p1))
        return (a[0] - 4 * big - big * math.pi / 2) ** 2 + a[1] ** 2 - 26 * big * big

    p1 = brentq(gap, -math.pi / 2, -0.1)
    with pytest.raises(SimulationStopped) as stop:
        run_simulation(EXAMPLES / "seed_c5_e3_wheels_with_rod.yaml", time=0.3, steps=3)
    assert stop.value.kind == "singular"
    assert f"t = {-p1 / w:.5g}" in stop.value.message
    assert len(run_simulation(EXAMPLES / "seed_c5_e3_wheels_with_rod.yaml", steps=2)) == 3    # its 0.4/w s


def test_the_pulley_on_a_cable_stops_at_the_end_of_its_sideways_travel():
    """The notes' C5-1.1 (r = 0.1, v = 1): the cable, tied at G1 = (−2√3 r, 4r) and G2 =
    (2√3 r, 4r), keeps its length ℓ(C) = t₁ + t₂ + r β (tangent lengths tᵢ = √(|Gᵢ − C|² − r²)
    and the arc β wrapped under the pulley, from the left strand's tangent point at angle
    atan2(G₁ − C) + acos(r/|G₁ − C|) round to the right one's at atan2(G₂ − C) − acos(r/|G₂ − C|)).
    Pushed sideways, the centre runs on ℓ(C) = ℓ(0) until that curve stands vertical
    (∂ℓ/∂y = 0): x* there, reached at t* = x*/v."""
    from scipy.optimize import fsolve

    r, v = 0.1, 1.0
    g1, g2 = np.array([-2 * math.sqrt(3) * r, 4 * r]), np.array([2 * math.sqrt(3) * r, 4 * r])

    def length(c):
        out, angles = 0.0, []
        for g, side in ((g1, 1.0), (g2, -1.0)):
            d = g - c
            size = math.hypot(*d)
            out += math.sqrt(size * size - r * r)
            angles.append(math.atan2(d[1], d[0]) + side * math.acos(r / size))
        return out + r * ((angles[1] - angles[0]) % (2 * math.pi))

    whole = length(np.zeros(2))

    def fold(c):
        h = 1e-6
        return [length(c) - whole, (length(c + [0, h]) - length(c - [0, h])) / (2 * h)]

    x, y = fsolve(fold, [0.45, 0.3], xtol=1e-12)
    assert y > 0.2                               # it has climbed towards G2
    with pytest.raises(SimulationStopped) as stop:
        run_simulation(EXAMPLES / "seed_c5_1_1_pulley_on_cable.yaml", time=0.5, steps=5)
    assert stop.value.kind == "singular"
    found = float(re.search(r"t = ([0-9.]+) s", stop.value.message).group(1))
    assert found == pytest.approx(x / v, abs=2e-5)
    kept = stop.value.result
    assert kept.points["C@pulley"]["position"][-1][0] == pytest.approx(0.4)      # the rows before it
