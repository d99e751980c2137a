"""Vehicles: the notes' C5-E.4 (upper wheel, symbols and a designer's numbers), C5-E.5
(unequal wheels), C5-E.6 (bicycle), C5-2.1 (tricycle) and C5-2.2 (articulated vehicle).

The wheeled ones use sympy.physics.vector: a translating chassis frame, each wheel a frame
turning at the rate the no-slip conditions give (derived by hand in each test), and the
points' velocities and accelerations by v2pt_theory / a2pt_theory.
"""
from __future__ import annotations

import sympy
from sympy import sqrt
from sympy.physics.vector import Point, ReferenceFrame, dynamicsymbols

from .helpers import answer, check_curvature, cli_answers, cross, formula, is_close, line_meet, same, solved, symbols

x, q = dynamicsymbols("x q")
t = dynamicsymbols._t


def wheel_point(centre, ratio, offset, speed, accel):
    """A point at `offset` (x, y) from a wheel's `centre` (x, y at the instant); the centre
    translates along x with
    velocity u(t), the wheel turns at ratio·u(t) (ccw). Returns (p, v, a) in the plane at the
    instant where u = `speed`, du/dt = `accel`."""
    u = sympy.Function("u")(t)
    n = ReferenceFrame("N")
    wheel = n.orientnew("W", "Axis", [q, n.z])
    o = Point("O")
    o.set_vel(n, 0)
    hub = o.locatenew("C", (centre[0] + x) * n.x + centre[1] * n.y)
    p = hub.locatenew("P", offset[0] * wheel.x + offset[1] * wheel.y)
    hub.set_vel(n, u * n.x)
    hub.set_acc(n, u.diff(t) * n.x)
    p.set_vel(wheel, 0)
    p.v2pt_theory(hub, n, wheel)
    p.a2pt_theory(hub, n, wheel)
    subs = {q.diff(t, 2): ratio * accel, q.diff(t): ratio * speed, q: 0, x: 0,
            u.diff(t): accel, u: speed}

    def plane(vec):
        return [sympy.simplify(vec.dot(n.x).xreplace(subs)), sympy.simplify(vec.dot(n.y).xreplace(subs))]

    return plane(p.pos_from(o)), plane(p.vel(n)), plane(p.acc(n))


def test_seed_c5_e4_upper_wheel():
    name = "seed_c5_e4_upper_wheel"
    s = symbols(name)
    R, v, vd = s["R"], s["v"], s["vd"]
    # chassis to the left at v: the lower wheels roll about their contacts, w1 = v/R ccw. Seen
    # from the chassis (a translation), wheel 1 turns at v/R and the upper wheel, touching it
    # without slip, at −v/R (equal radii, external contact): the same relative to the ground.
    # The lower centres are 2√2·R apart (issue 30, round 29 (d): 2R made the lower wheels touch
    # and rub at (0, R)); U is 2R from each, so √((2R)² − (√2·R)²) = √2·R above them.
    assert sympy.simplify(2 * sqrt(2) * R - 2 * R) != 0       # the lower wheels do not touch
    w1, w_up = v / R, -v / R
    _, vp, ap = wheel_point([0, R + sqrt(2) * R], 1 / R, [0, R], -v, -vd)     # rate −v/R
    assert vp == [0, 0] and ap == [0, -v ** 2 / R]            # the notes: P is the centre, a = v²/R ↓
    assert same(name, answer(name, omega="wheel1"), w1)
    assert same(name, answer(name, icr="wheel1")["point"], [-sqrt(2) * R, 0])
    assert same(name, answer(name, omega="upper"), w_up)
    assert same(name, answer(name, icr="upper")["point"], [0, 2 * R + sqrt(2) * R])
    assert same(name, answer(name, velocity="P"), vp)
    assert same(name, answer(name, acceleration="P"), ap)


def test_vehicle_upper_wheel_with_numbers():
    # the same with R = 0.25, v = 2 (to the left), braking: acceleration +1 along x
    R, v, acc = 0.25, 2.0, 1.0
    w_up, al_up = -v / R, acc / R            # w = −v/R with v(t) the leftward speed; dv/dt = −1
    name = "vehicle_upper_wheel"
    assert is_close(answer(name, omega="wheel1"), v / R) and is_close(answer(name, omega="upper"), w_up)
    assert is_close(answer(name, alpha="upper"), al_up)
    assert is_close(answer(name, velocity="P"), [0, 0], scale=10)
    assert is_close(answer(name, acceleration="P"), [0, -v ** 2 / R], scale=10)
    # the pole: a_U + α k × r − w² r = 0, a_U = (1, 0); solve the 2×2 system by hand
    det = w_up ** 4 + al_up ** 2
    rx = (w_up ** 2 * acc) / det
    ry = (al_up * acc) / det
    u = (0.0, R + 2 ** 0.5 * R)           # 2R from A1 = (−√2·R, R): √(4R² − 2R²) above
    assert is_close(answer(name, pole="upper")["point"], [u[0] + rx, u[1] + ry], scale=1)
    # contact wheel 1 / upper wheel: at the midpoint of A1 U, both wheels' points move alike
    a1 = (-(2 ** 0.5) * R, R)
    c = ((a1[0] + u[0]) / 2, (a1[1] + u[1]) / 2)
    contact = answer(name, contact="w1_upper")
    assert is_close(contact["point"], c, scale=1)
    turn = cross(v / R, (c[0] - a1[0], c[1] - a1[1]))
    v_wheel1 = [-v + turn[0], turn[1]]
    assert is_close(contact["body_a"]["velocity"], v_wheel1, scale=10)
    assert is_close(contact["body_b"]["velocity"], v_wheel1, scale=10)
    # the geometric contact point stays at the midpoint of the translating centres
    assert is_close(contact["geometric"]["velocity"], [-v, 0], scale=10)
    assert is_close(contact["geometric"]["acceleration"], [acc, 0], scale=10)


def test_seed_c5_e5_unequal_wheels():
    name = "seed_c5_e5_unequal_wheels"
    s = symbols(name)
    R, r1, r2, v, vd = s["R"], s["r1"], s["r2"], s["v"], s["vd"]
    # wheel R rolls on the ground: its top moves at 2v. Wheel 1 (centre at v) touches it there
    # without slip: v + w1 r1 = 2v, w1 = v/r1 ccw; its centre of rotation is r1 above D.
    w1 = v / r1
    assert same(name, answer(name, omega="wheel1"), w1)
    assert same(name, answer(name, icr="wheel1")["point"], [0, 2 * R + 2 * r1])
    assert same(name, answer(name, omega="wheel2"), -v / r2)
    path = wheel_point([s["L"], r2], -1 / r2, [0, -r1], v, vd)
    assert same(name, answer(name, velocity="P"), path[1])
    assert same(name, answer(name, acceleration="P"), path[2])
    # the notes print r2/(r2 − r1)² (not a length): their normal acceleration uses CP = r2
    # instead of r1. It is v² r1/r2² upwards, and the radius (r2 − r1)²/r1.
    assert sympy.simplify(path[2][1] - v ** 2 * r1 / r2 ** 2) == 0
    check_curvature(name, "P", path, (r2 - r1) ** 2 / r1)


def test_seed_c5_e5_through_the_cli():
    name = "seed_c5_e5_unequal_wheels"
    s = symbols(name)
    got = next(a["value"] for a in cli_answers(name) if a["ask"] == {"curvature": "P"})
    assert same(name, got["radius"], (s["r2"] - s["r1"]) ** 2 / s["r1"])


def test_seed_c5_e6_bicycle():
    name = "seed_c5_e6_bicycle"
    s = symbols(name)
    R_roda, R, r, L, b, v, vd = (s[k] for k in ("R_roda", "R", "r", "L", "b", "v", "vd"))
    # rear wheel about its contact: v/R_roda clockwise; the chain (speed r·v/R_roda relative
    # to the frame, which translates) turns the chainring at (r/R) v/R_roda clockwise.
    w_ring = -(r / R) * v / R_roda
    assert same(name, answer(name, omega="rear"), -v / R_roda)
    assert same(name, answer(name, omega="chainring"), w_ring)
    k_height = R_roda + r - R
    d = R_roda * R / r                          # the notes: the pedals' centre is d below K
    assert same(name, answer(name, icr="chainring")["point"], [b, k_height - d])
    path = wheel_point([b, k_height], -(r / R) / R_roda, [0, -L], v, vd)
    assert same(name, answer(name, velocity="P"), path[1])
    # The notes print (R/r)² R_roda, independent of L: they keep only L·w of v(P) and do not
    # square it. Derived: (d − L)²/L.
    check_curvature(name, "P", path, (d - L) ** 2 / L)


def test_seed_c5_2_1_tricycle_steered_45_degrees():
    name = "seed_c5_2_1_tricycle"
    s = symbols(name)
    L, half, v0 = s["L"], s["s"], s["v0"]
    # no side slip: v(F) along the front wheel (1, 1)/√2, v of the rear wheels along x. The
    # chassis' centre is where the perpendiculars meet: the rear axle line and F + u(−1, 1).
    icr = line_meet([0, 0], [0, 1], [L, 0], [-1, 1])
    assert icr == [0, L]
    w = v0 / sqrt(L ** 2 + L ** 2)                        # |v(F)| / |F − I|, turning left
    v_left = cross(w, [0, half - L])
    assert same(name, answer(name, icr="chassis")["point"], icr)
    assert same(name, answer(name, omega="chassis"), w)
    assert same(name, answer(name, velocity="C1@chassis"), v_left)
    # (the right rear wheel's velocity is not asked: the notes do not ask it)
    # the notes' spin of the left rear wheel, phi_dot = v0/(√2 L) (L − s)/r: its centre moves
    # at r phi_dot, i.e. v0 (L − s)/(√2 L) (for s < L: the speed is |L − s| in general)
    v_rl = [formula(name, c) for c in answer(name, velocity="C1@chassis")]
    speed = sympy.sqrt(v_rl[0] ** 2 + v_rl[1] ** 2)
    assert sympy.simplify(speed / s["r"] - v0 * sympy.Abs(L - half) / (sqrt(2) * L * s["r"])) == 0
    assert solved(name)[1]["dof"] == 2                    # motion + steering


def test_seed_c5_2_2_articulated_vehicle():
    name = "seed_c5_2_2_articulated"
    s = symbols(name)
    a, r, w = s["a"], s["r"], s["w"]
    # S1 translates at r w: so does O. S2's axle midpoint P2 moves along S2 (no side slip),
    # direction e = (1, 1)/√2; equiprojectivity with O: v(P2)·e = v(O)·e = r w/√2, the notes'
    # r w'/√2 being a slip for r w/√2.
    e = [1 / sqrt(2), 1 / sqrt(2)]
    v_p2 = [r * w / sqrt(2) * k for k in e]
    p2 = [-sqrt(2) * a / 2, -sqrt(2) * a / 2]
    # S2's centre: on the perpendicular to v(P2) through P2 (S2's axle) and on O's (the y axis)
    icr = line_meet(p2, [1, -1], [0, 0], [0, 1])
    w2 = sympy.simplify(v_p2[0] / cross(1, [p2[0] - icr[0], p2[1] - icr[1]])[0])
    w4 = [-sqrt(2) * a / 4, -3 * sqrt(2) * a / 4]
    v_w4 = cross(w2, [w4[0] - icr[0], w4[1] - icr[1]])
    assert same(name, answer(name, omega="S1"), 0)
    assert same(name, answer(name, velocity="O"), [r * w, 0])
    assert same(name, answer(name, velocity="P@S2"), v_p2)
    assert same(name, answer(name, icr="S2")["point"], icr)
    assert same(name, answer(name, omega="S2"), w2)
    assert same(name, answer(name, velocity="C4"), v_w4)
    # the inner wheel's spin w' = |v(C4)|/r = w/(2√2)
    v_w4 = [formula(name, c) for c in answer(name, velocity="C4")]
    assert sympy.simplify(sympy.sqrt(v_w4[0] ** 2 + v_w4[1] ** 2) / r - w / (2 * sqrt(2))) == 0
    # wheels roll without side slip (knife edges, not a slot round a fixed pin): with e, n
    # along and across S2 (45°), P2 = O − a e and v(P2)·n = 0 give θ' = v(O)·n / a, and
    # with a(O) = 0, θ'' = v(O)·(dn/dt) / a = −θ' (v(O)·e) / a = r²w²/(2a²)
    assert same(name, solved(name)[1]["bodies"]["S2"]["alpha"], r ** 2 * w ** 2 / (2 * a ** 2))
