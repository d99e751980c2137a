"""Rolling without slip: the wheel on the ground, seed 001's rolling pair, and the notes'
C5-1.7, C5-1.8, C5-E.1 and C5-E.3.

Each material point is written as a function of one coordinate, with the wheel's rotation
angle tied to it by the rolling condition integrated by hand, and differentiated by sympy.
"""
from __future__ import annotations

import sympy
from sympy import asin, cos, sin
from sympy.physics.vector import dynamicsymbols

from .helpers import (answer, at_instant, carried, check_curvature, cli_answers, is_close, cross,
                      curvature, line_meet, same, symbols)

x, phi = dynamicsymbols("x phi")


def test_wheel_rolling_on_the_ground():
    name = "wheel_rolling"
    s = symbols(name)
    R, v, vd = s["R"], s["v"], s["vd"]
    coords = {x: (0, v, vd)}
    centre = [x, R]
    turn = -x / R                        # no slip: the arc R·(−turn) equals the distance x

    def point(offset):
        return at_instant(carried(centre, turn, offset), coords)

    _, w, al = at_instant(turn, coords)
    assert same(name, answer(name, omega="wheel"), w) and same(name, answer(name, alpha="wheel"), al)
    assert w == -v / R
    # instant centre C + k × v_C / ω: the contact point
    assert same(name, answer(name, icr="wheel")["point"], [0, 0])
    pt, vt, at = point([0, R])
    assert same(name, answer(name, velocity="T"), vt) and vt == [2 * v, 0]
    assert same(name, answer(name, velocity="F"), point([R, 0])[1])
    _, vj, aj = point([0, -R])
    assert same(name, answer(name, acceleration="J@wheel"), aj) and aj == [0, v ** 2 / R]
    radius, centre_t = curvature(pt, vt, at)
    got = answer(name, curvature="T")
    assert same(name, got["radius"], 4 * R) and same(name, got["radius"], radius)
    assert same(name, got["center"], centre_t)
    contact = answer(name, contact="roll")
    assert same(name, contact["body_a"]["velocity"], [0, 0])
    assert same(name, contact["body_a"]["acceleration"], [0, 0])
    assert same(name, contact["body_b"]["velocity"], vj)
    assert same(name, contact["body_b"]["acceleration"], aj)
    _, vg, ag = at_instant([x, 0], coords)               # the geometric contact point
    assert same(name, contact["geometric"]["velocity"], vg)
    assert same(name, contact["geometric"]["acceleration"], ag)
    # the acceleration pole: a_C + α k × r − ω² r = 0
    r = sympy.symbols("r0:2")
    eqs = [ac + c - w ** 2 * ri for ac, c, ri in zip([vd, 0], cross(al, r), r)]
    pole = sympy.solve(eqs, r, dict=True)[0]
    assert same(name, answer(name, pole="wheel")["point"], [pole[r[0]], R + pole[r[1]]])


def test_seed_001_rolling_pair():
    # the slider carries the roller's centre A = (x, 0); the lever's edge through B at angle
    # beta stays tangent to the roller: x sin(beta) = rho. Seen from the lever, A slides along
    # the edge (s = x cos beta) and the roller rolls on it: w_R − w_N = ds/dt / rho.
    rho, v = sympy.Rational(1, 10), sympy.Rational(1, 2)
    beta = asin(rho / x)
    s_along = x * cos(beta)
    coords = {x: (rho / sin(sympy.pi / 6), v, 0)}
    _, w_n, al_n = at_instant(beta, coords)
    _, w_r, al_r = at_instant(beta + s_along / rho, coords)
    assert is_close(w_n, -0.5 * 3 ** -0.5 / 0.2)           # −v tan(beta)/x
    assert is_close(w_r, 0.5 * 3 ** 0.5 / 2 / 0.1)          # v cos(beta)/rho
    name = "seed_001_rolling_pair"
    for key, value in (("omega", w_n), ("alpha", al_n)):
        assert is_close(answer(name, **{key: "N"}), value)
    for key, value in (("omega", w_r), ("alpha", al_r)):
        assert is_close(answer(name, **{key: "R"}), value)
    # the three contact points: the lever's, the roller's, the geometric one (s along the edge)
    edge = [cos(beta), sin(beta)]
    pf, vf, af = at_instant([s_along * edge[0], s_along * edge[1]], coords)
    a0 = [0.2, 0]
    af_lever = [c - w_n ** 2 * p for c, p in zip(cross(al_n, pf), pf)]
    fa = [p - q for p, q in zip(pf, a0)]
    af_roller = [c - w_r ** 2 * p for c, p in zip(cross(al_r, fa), fa)]
    contact = answer(name, contact="j4")
    assert is_close(contact["point"], pf)
    assert is_close(contact["body_a"]["velocity"], cross(w_n, pf), scale=1)
    assert is_close(contact["body_b"]["velocity"], [v + c for c, v in zip(cross(w_r, fa), [0.5, 0])], scale=1)
    assert is_close(contact["body_a"]["velocity"], contact["body_b"]["velocity"], scale=1)   # no slip
    assert is_close(contact["body_a"]["acceleration"], af_lever, scale=10)
    assert is_close(contact["body_b"]["acceleration"], af_roller, scale=10)
    assert is_close(contact["geometric"]["velocity"], vf, scale=1)
    assert is_close(contact["geometric"]["acceleration"], af, scale=10)
    # composition from the lever: drag (lever's point at A) + relative (along the edge) + Coriolis
    _, s_d, s_dd = at_instant(s_along, coords)
    e0 = [3 ** 0.5 / 2, 0.5]
    parts = answer(name, decompose="A@R", moving="N")
    assert is_close(parts["velocity"]["relative"], [s_d * k for k in e0], scale=1)
    assert is_close(parts["acceleration"]["relative"], [s_dd * k for k in e0], scale=10)
    assert is_close(parts["acceleration"]["coriolis"], cross(2 * w_n, [s_d * k for k in e0]), scale=10)
    assert is_close(parts["acceleration"]["total"], [0, 0], scale=10)


def test_seed_c5_1_7_wheel_on_a_semicylinder():
    # OC turns at phi (from the vertical, clockwise): C = 3r (sin phi, cos phi). No slip at J
    # (2r from O): v_C = 3r phi_dot = r w, so phi_dot = w/3 and the wheel's clockwise turn is
    # 3 phi. P, the top of the wheel, is C + r (sin 3phi, cos 3phi): an epicycloid.
    name = "seed_c5_1_7_semicylinder"
    s = symbols(name)
    r, w, wd = s["r"], s["w"], s["wd"]
    coords = {phi: (0, w / 3, wd / 3)}
    c = [3 * r * sin(phi), 3 * r * cos(phi)]
    p = [c[0] + r * sin(3 * phi), c[1] + r * cos(3 * phi)]
    pp, vp, ap = at_instant(p, coords)
    pc, vc, ac = at_instant(c, coords)
    check_curvature(name, "P", (pp, vp, ap), 3 * r)         # the notes' answer: 3r
    assert same(name, answer(name, curvature="P")["center"], [0, r])   # 3r below P
    assert same(name, answer(name, velocity="P"), vp) and vp == [2 * r * w, 0]
    assert same(name, answer(name, acceleration="P"), ap)
    assert sympy.simplify(ap[1] + sympy.Rational(4, 3) * r * w ** 2) == 0   # a_n = (4/3) r w², down
    intrinsic = answer(name, intrinsic="P")
    assert same(name, intrinsic["speed"], 2 * r * w)
    assert same(name, intrinsic["tangential"], ap[0])
    assert same(name, intrinsic["normal"], sympy.Rational(4, 3) * r * w ** 2)
    assert same(name, answer(name, velocity="C"), vc) and same(name, answer(name, acceleration="C"), ac)
    got = answer(name, curvature="C")
    assert same(name, got["radius"], 3 * r) and same(name, got["center"], [0, 0])


def test_seed_c5_1_8_three_contact_points():
    # as in C5-1.7 with w0 constant: phi_dot = w0/3. The wheel's point at the contact is
    # C + r (−sin 3phi, −cos 3phi); the geometric contact point is 2r (sin phi, cos phi).
    # The notes' printed list is garbled; these are the derived values (see the example).
    name = "seed_c5_1_8_contact_points"
    s = symbols(name)
    r, w0 = s["r"], s["w0"]
    coords = {phi: (0, w0 / 3, 0)}
    c = [3 * r * sin(phi), 3 * r * cos(phi)]
    wheel_point = [c[0] - r * sin(3 * phi), c[1] - r * cos(3 * phi)]
    _, v_wheel, a_wheel = at_instant(wheel_point, coords)
    _, v_geom, a_geom = at_instant([2 * r * sin(phi), 2 * r * cos(phi)], coords)
    _, v_c, a_c = at_instant(c, coords)
    assert v_wheel == [0, 0] and a_wheel == [0, 2 * r * w0 ** 2 / 3]       # towards C
    assert v_geom == [2 * r * w0 / 3, 0] and a_geom == [0, -2 * r * w0 ** 2 / 9]   # towards O
    assert v_c == [r * w0, 0] and a_c == [0, -r * w0 ** 2 / 3]
    got = answer(name, contact="j1")
    assert same(name, got["body_a"]["velocity"], [0, 0]) and same(name, got["body_a"]["acceleration"], [0, 0])
    assert same(name, got["body_b"]["velocity"], v_wheel)
    assert same(name, got["body_b"]["acceleration"], a_wheel)
    assert same(name, got["geometric"]["velocity"], v_geom)
    assert same(name, got["geometric"]["acceleration"], a_geom)
    assert same(name, answer(name, velocity="C"), v_c) and same(name, answer(name, acceleration="C"), a_c)


def test_seed_c5_e1_wheels_in_a_cavity():
    # OC at angle theta (ccw from the vertical): C = 2R u, u = (−sin theta, cos theta); the R
    # wheel touches the track (3R) at J = 3R u. No slip, v_J = 0: 2R thd (k×u) + w R (k×u) = 0,
    # so w = −2 thd at every instant and the wheels' turn is −2 theta.
    name = "seed_c5_e1_cavity"
    s = symbols(name)
    R, thd, thdd = s["R"], s["thd"], s["thdd"]
    theta = phi
    coords = {theta: (0, thd, thdd)}
    c = [-2 * R * sin(theta), 2 * R * cos(theta)]
    path_p = at_instant(carried(c, -2 * theta, [0, -R]), coords)
    path_o = at_instant(carried(c, -2 * theta, [0, -2 * R]), coords)
    vp, vo = path_p[1], path_o[1]
    assert same(name, answer(name, omega="wheels"), -2 * thd)
    assert same(name, answer(name, icr="wheels")["point"], [0, 3 * R])
    assert same(name, answer(name, velocity="P"), vp) and vp == [-4 * R * thd, 0]
    assert same(name, answer(name, velocity="O@wheels"), vo) and vo == [-6 * R * thd, 0]
    # The notes print 2R/3 and 9R/10: they use speeds 2R thd and 3R thd (not 4R thd and
    # 6R thd) and add the centripetal terms with the wrong sense. The derivation gives 8R, 6R.
    check_curvature(name, "P", path_p, 8 * R)
    check_curvature(name, "O@wheels", path_o, 6 * R)


def test_seed_c5_e1_through_the_cli():
    answers = {str(a["ask"]): a["value"] for a in cli_answers("seed_c5_e1_cavity")}
    assert same("seed_c5_e1_cavity", answers["{'curvature': 'P'}"]["radius"], 8 * symbols("seed_c5_e1_cavity")["R"])
    assert same("seed_c5_e1_cavity", answers["{'omega': 'wheels'}"], -2 * symbols("seed_c5_e1_cavity")["thd"])


def test_seed_c5_e3_wheels_with_a_rod():
    # the notes' construction: each wheel's centre is its contact; v(A) ⟂ JA, v(B) ⟂ KB, so
    # the rod's centre is where the lines JA and KB meet; speeds are w·distance.
    name = "seed_c5_e3_wheels_with_rod"
    s = symbols(name)
    R, w = s["R"], s["w"]
    j1, j2, a, b = [0, 0], [4 * R, 0], [0, 2 * R], [5 * R, R]
    icr = line_meet(j1, [a[0] - j1[0], a[1] - j1[1]], j2, [b[0] - j2[0], b[1] - j2[1]])
    assert icr == [0, -4 * R]
    v_a = cross(-w, [a[0] - j1[0], a[1] - j1[1]])            # wheel 1 turns at w clockwise
    w_rod = sympy.simplify(v_a[0] / cross(1, [a[0] - icr[0], a[1] - icr[1]])[0])
    v_b = cross(w_rod, [b[0] - icr[0], b[1] - icr[1]])
    w2 = sympy.simplify(v_b[0] / cross(1, [b[0] - j2[0], b[1] - j2[1]])[0])
    assert same(name, answer(name, icr="rod")["point"], icr)
    assert same(name, answer(name, icr="wheel1")["point"], j1)
    assert same(name, answer(name, icr="wheel2")["point"], j2)
    assert same(name, answer(name, omega="rod"), w_rod) and w_rod == -w / 3
    assert same(name, answer(name, omega="wheel2"), w2) and w2 == -5 * w / 3
