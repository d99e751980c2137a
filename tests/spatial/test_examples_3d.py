"""The spatial examples against derivations with sympy.physics.vector: the robot arm, the
gyroscope in its gimbal (and the same top on a ball joint) and the steering car wheel."""
from __future__ import annotations

import functools
import math

import pytest
import sympy as sp
import yaml
from sympy.physics.mechanics import msubs
from sympy.physics.vector import Point, ReferenceFrame

from kinematika import solve
from kinematika.api import answers

from .derive import (EXAMPLES, carried, assert_close, components, coordinates, cross, fixed_point, instant,
                     minus, t, times)


def by_question(sol) -> dict:
    """Answers keyed by the question as written (kind, target, relative_to)."""
    out = {}
    for q, value in answers(sol):
        out[(q.kind, str(q.target), q.relative_to)] = value
    return out


# --- robot arm -----------------------------------------------------------------------------
def test_robot_arm():
    """Base yawed ψ about z; arm pitched γ about −(base y), so Arm.x = cos γ Base.x + sin γ z."""
    psi, gam = coordinates("psi gam")
    N = ReferenceFrame("N")
    base = N.orientnew("Base", "Axis", (psi, N.z))
    arm = base.orientnew("Arm", "Axis", (gam, -base.y))
    h, L = sp.Rational(1, 2), sp.Rational(4, 5)
    O = fixed_point("O", N)
    S = carried(O, "S", h * N.z, N, base)
    E = carried(S, "E", L * arm.x, N, arm)
    s = instant({psi: (sp.pi / 6, sp.Rational(1, 2), sp.Rational(1, 5)),
                 gam: (sp.pi / 4, 1, -sp.Rational(1, 2))})
    sol = solve(EXAMPLES / "robot_arm_3d.yaml")
    assert_close(sol.omega("arm"), components(arm.ang_vel_in(N), N, s))
    assert_close(sol.alpha("arm"), components(arm.ang_acc_in(N), N, s))
    assert_close(sol.velocity("E"), components(E.vel(N), N, s))
    assert_close(sol.acceleration("E"), components(E.acc(N), N, s))
    # composition with the base as moving frame: E seen from the base, the base's point at E
    v_rel = components(E.pos_from(S).dt(base), N, s)
    a_rel = components(E.pos_from(S).dt(base).dt(base), N, s)
    drag = carried(O, "D", E.pos_from(O), N, base)
    dec = by_question(sol)[("decompose", "E@arm", None)]
    assert_close(dec["velocity"]["relative"], v_rel)
    assert_close(dec["acceleration"]["relative"], a_rel)
    assert_close(dec["velocity"]["drag"], components(drag.vel(N), N, s))
    assert_close(dec["acceleration"]["drag"], components(drag.acc(N), N, s))
    assert_close(dec["acceleration"]["coriolis"], times(2, cross(components(base.ang_vel_in(N), N, s), v_rel)))
    # the arm turns about the fixed point S: its screw axis is the line through S along ω
    ax = by_question(sol)[("axis", "arm", None)]
    w = components(arm.ang_vel_in(N), N, s)
    size = sp.sqrt(sum(c ** 2 for c in w))
    assert_close(ax["direction"], times(1 / size, w))
    assert abs(float(ax["slide"])) < 1e-12
    s_point = (0, 0, h)
    foot = minus(s_point, times(sum(a * b for a, b in zip(s_point, w)) / size ** 2, w))
    assert_close(ax["point"], foot)


# --- gyroscope -----------------------------------------------------------------------------
@functools.cache
def gyroscope_derivation():
    """Euler angles z-x-z: precession ψ, nutation θ, spin φ; G on the spin axis, Q, Q2 on the rim.
    Derived once in the process that runs the tests, not while the suite is collected."""
    psi, th, phi = coordinates("psi th phi")
    N = ReferenceFrame("N")
    outer = N.orientnew("Out", "Axis", (psi, N.z))
    inner = outer.orientnew("In", "Axis", (th, outer.x))
    rotor = inner.orientnew("Rot", "Axis", (phi, inner.z))
    d, r = sp.Rational(1, 10), sp.Rational(1, 20)
    O = fixed_point("O", N)
    G = carried(O, "G", d * inner.z, N, rotor)
    pts = {"G": G, "Q": carried(G, "Q", r * rotor.x, N, rotor),
           "Q2": carried(G, "Q2", r * rotor.y, N, rotor)}
    s = instant({psi: (0, 2, 0), th: (sp.pi / 6, sp.Rational(1, 2), sp.Rational(3, 10)),
                 phi: (0, 100, 0)})
    out = {name: (components(p.vel(N), N, s), components(p.acc(N), N, s)) for name, p in pts.items()}
    out["omega"] = components(rotor.ang_vel_in(N), N, s)
    out["alpha"] = components(rotor.ang_acc_in(N), N, s)
    out["spin"] = components(rotor.ang_vel_in(inner), N, s)
    out["alpha_outer"] = components(rotor.ang_acc_in(outer), N, s)
    return out


def test_gyroscope_in_a_gimbal():
    GYRO = gyroscope_derivation()
    sol = solve(EXAMPLES / "gyroscope.yaml")
    ans = by_question(sol)
    assert_close(ans[("omega", "rotor", None)], GYRO["omega"])
    assert_close(ans[("alpha", "rotor", None)], GYRO["alpha"])
    assert_close(ans[("omega", "rotor", "inner")], GYRO["spin"])
    assert_close(ans[("alpha", "rotor", "outer")], GYRO["alpha_outer"])
    for name in ("G", "Q", "Q2"):
        assert_close(sol.velocity(name), GYRO[name][0])
        assert_close(sol.acceleration(name), GYRO[name][1])
    ax = ans[("axis", "rotor", None)]
    assert_close(ax["point"], (0, 0, 0))
    assert abs(float(ax["slide"])) < 1e-12


def test_the_same_top_on_a_ball_joint():
    """A spherical joint at the pivot and the rotor's ω, α given as vectors: same motion."""
    GYRO = gyroscope_derivation()
    sol = solve(EXAMPLES / "gyroscope.yaml")
    th = math.radians(30)
    points = {"O": [0, 0, 0], **{n: list(sol.inst.points[n]) for n in ("G", "Q", "Q2")}}
    tree = {"dimension": 3, "points": points,
            "bodies": {"ground": ["O"], "top": ["O", "G", "Q", "Q2"]},
            "joints": [{"type": "spherical", "bodies": ["ground", "top"], "at": "O"}],
            "drivers": [{"omega": "top", "value": [float(c) for c in GYRO["omega"]],
                         "alpha": [float(c) for c in GYRO["alpha"]]}]}
    top = solve(tree)
    for name in ("G", "Q", "Q2"):
        assert_close(top.velocity(name), GYRO[name][0])
        assert_close(top.acceleration(name), GYRO[name][1])
    # and the centre by hand: G = d e3 turns with ω, v_G = ω × G
    g = (0, -0.1 * math.sin(th), 0.1 * math.cos(th))
    assert_close(top.velocity("G"), cross(GYRO["omega"], g))


# --- car wheel -----------------------------------------------------------------------------
def car_derivation(v=5, L=2, r=sp.Rational(3, 10), delta0=sp.pi / 9, steer=sp.Rational(2, 5)):
    """Tricycle: rear axle midpoint M moves at v along the chassis x (no side slip), the front
    wheel has no side slip (ψ' = v tan δ / L) and rolls (its spin φ' = v_K·F.x / r)."""
    psi, delta, phi = coordinates("psi delta phi")
    N = ReferenceFrame("N")
    chassis = N.orientnew("Ch", "Axis", (psi, N.z))
    fork = chassis.orientnew("F", "Axis", (delta, chassis.z))
    wheel = fork.orientnew("W", "Axis", (phi, fork.y))
    rates = {psi.diff(t): v * sp.tan(delta) / L, delta.diff(t): steer}
    M = Point("M")
    M.set_vel(N, v * chassis.x)
    K = M.locatenew("K", L * chassis.x)
    v_k = msubs(K.v2pt_theory(M, N, chassis), rates)
    rates[phi.diff(t)] = sp.simplify(v_k.dot(fork.x) / r)

    def rate_of(vec):
        return msubs(vec.dt(N), rates)

    w_wheel = msubs(wheel.ang_vel_in(N), rates)
    w_chassis = msubs(chassis.ang_vel_in(N), rates)
    s = {psi: 0, delta: delta0, phi: 0}
    a_k = rate_of(v_k)
    down = -r * N.z
    al = rate_of(w_wheel)
    out = {"omega": w_wheel, "alpha": al, "omega_chassis": w_chassis, "alpha_chassis": rate_of(w_chassis),
           "v_K": v_k, "a_K": a_k, "spin": msubs(wheel.ang_vel_in(fork), rates),
           "a_contact": a_k + al.cross(down) + w_wheel.cross(w_wheel.cross(down))}
    return {k: components(vec, N, s) for k, vec in out.items()}


def test_car_front_wheel_steering_while_rolling():
    e = car_derivation()
    sol = solve(EXAMPLES / "car_wheel_steering.yaml")
    ans = by_question(sol)
    assert_close(ans[("omega", "chassis", None)], e["omega_chassis"])
    assert_close(ans[("alpha", "chassis", None)], e["alpha_chassis"])
    assert_close(ans[("velocity", "K@chassis", None)], e["v_K"])
    assert_close(sol.acceleration("K"), e["a_K"])
    assert_close(ans[("omega", "front", None)], e["omega"])
    assert_close(ans[("alpha", "front", None)], e["alpha"])
    assert_close(ans[("omega", "front", "fork")], e["spin"])
    contact = ans[("contact", "tyre_front", None)]
    assert_close(contact["body_b"]["velocity"], (0, 0, 0))
    assert_close(contact["body_b"]["acceleration"], e["a_contact"])
    # the geometric contact point stays under K: it moves as K does
    assert_close(contact["geometric"]["velocity"], e["v_K"])
    assert_close(contact["geometric"]["acceleration"], e["a_K"])
    # the planar closed forms of the notes: yaw rate v tan δ / L, spin v / (r cos δ)
    d = math.radians(20)
    assert_close(e["omega_chassis"], (0, 0, 5 * math.tan(d) / 2))
    spin = [float(c) for c in e["spin"]]
    assert math.hypot(*spin) == pytest.approx(5 / (0.3 * math.cos(d)))


def test_chassis_screw_axis_is_the_vertical_through_its_instant_centre():
    """The chassis turns about the vertical through the point of the rear axle line at
    L / tan δ from M: the screw axis' point nearest the origin is (0, L/tan δ, 0)."""
    tree = yaml.safe_load((EXAMPLES / "car_wheel_steering.yaml").read_text())
    tree["ask"] = [{"axis": "chassis"}, {"axis": "chassis", "relative_to": "fork"}]
    sol = solve(tree)
    ax, seen_from_fork = (value for _, value in answers(sol))
    assert_close(ax["point"], (0, 2 / math.tan(math.radians(20)), 0))
    assert_close(ax["direction"], (0, 0, 1))
    assert abs(float(ax["slide"])) < 1e-12
    # relative to the fork the chassis turns about the kingpin (through K, along -z)
    assert_close(seen_from_fork["point"], (2, 0, 0))
    assert_close(seen_from_fork["direction"], (0, 0, -1))
    assert float(seen_from_fork["omega"]) == pytest.approx(0.4)
