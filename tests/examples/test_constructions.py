"""Instant centres found by the notes' graphical constructions: C5-1.2 (bar on wheels on
inclined planes) and C5-1.3 (bar sliding in a sleeve on a rolling support). The expected
centres are intersections of lines drawn as the notes draw them; speeds follow as ω·distance."""
from __future__ import annotations

import sympy
from sympy import Rational, sqrt

from .helpers import answer, is_close, cross, line_meet, solved


def test_seed_c5_1_2_bar_on_inclined_wheels():
    name = "seed_c5_1_2_bar_on_inclined_wheels"
    # The model's geometry (its Data text): planes at 30° and 45° meeting at K0 = (0, 0), the
    # wheels (r = 1) touching them s = 3 from K0, each centre r along its plane's normal, J at
    # (−5, 2). By hand: O = s(−√3/2, 1/2) + r(1/2, √3/2), Q = s(√2/2, √2/2) + r(−√2/2, √2/2)
    # = (√2, 2√2); |OQ| = 3.543 > 2r (at s = 2 the wheels overlapped: 1.956). The normals
    # through O and Q meet at I_OQ = (−0.6432, 4.886); the line I_OQ–O meets x = −5 at
    # I_OJ = (−5, −2.660); ω_OJ = v_O,x / (−(y_O − y_IOJ)) = −0.5013, v_J = (2.336, 0).
    s, r = 3, 1
    n1 = [Rational(1, 2), sqrt(3) / 2]             # normal of the 30° plane, into the valley
    n2 = [-sqrt(2) / 2, sqrt(2) / 2]               # normal of the 45° plane
    k1 = [-s * sqrt(3) / 2, Rational(s, 2)]        # wheel 1's contact, s up its plane
    k2 = [s * sqrt(2) / 2, s * sqrt(2) / 2]
    o = [k1[0] + r * n1[0], k1[1] + r * n1[1]]     # wheel 1's centre, r along the normal
    qq = [k2[0] + r * n2[0], k2[1] + r * n2[1]]
    j = [-5, 2]
    assert sympy.sqrt((qq[0] - o[0]) ** 2 + (qq[1] - o[1]) ** 2) > 2 * r     # the wheels are apart
    # wheel centres move parallel to their planes: OQ's centre is where the normals meet
    icr_oq = line_meet(o, n1, qq, n2)
    # J moves horizontally: OJ's centre is on the vertical through J and on the line from
    # OQ's centre through O (v_O is perpendicular to it)
    icr_oj = line_meet(j, [0, 1], icr_oq, [o[0] - icr_oq[0], o[1] - icr_oq[1]])
    w_oq = 1
    v_o = cross(w_oq, [o[0] - icr_oq[0], o[1] - icr_oq[1]])
    w_oj = sympy.simplify(v_o[0] / cross(1, [o[0] - icr_oj[0], o[1] - icr_oj[1]])[0])
    v_j = cross(w_oj, [j[0] - icr_oj[0], j[1] - icr_oj[1]])
    assert is_close(icr_oq, [-0.6432381521, 4.8858788392]) and is_close(w_oj, -0.5013357225)
    assert is_close(answer(name, icr="OQ")["point"], icr_oq, scale=5)
    assert is_close(answer(name, icr="OJ")["point"], icr_oj, scale=5)
    assert is_close(answer(name, omega="OJ"), w_oj)
    assert is_close(answer(name, velocity="J@OJ"), v_j, scale=5)
    assert abs(float(v_j[1])) < 1e-12                       # horizontal, as the floor demands
    assert is_close(answer(name, icr="wheel1")["point"], k1, scale=5)   # its contact


def test_seed_c5_1_3_bar_in_a_sleeve():
    name = "seed_c5_1_3_bar_in_sleeve"
    o, qq, _s, e, j = [0, 0], [1, 2], [4, 1], [Rational(11, 2), Rational(1, 2)], [4, 0]
    along = [3, -1]
    # the bar's centre is on OQ (v_Q ⟂ OQ) and on the perpendicular to the bar through the
    # point where drag (rotation about J) and relative (along the bar) velocities are
    # parallel: the foot of the perpendicular from J, so on the perpendicular through J
    icr = line_meet(o, qq, j, [1, 3])
    assert icr == [12, 24]
    v_q = cross(2, qq)                                   # OQ turns at 2 rad/s about O
    w_bar = sympy.simplify(v_q[0] / cross(1, [qq[0] - icr[0], qq[1] - icr[1]])[0])
    v_e = cross(w_bar, [e[0] - icr[0], e[1] - icr[1]])
    assert is_close(answer(name, icr="bar")["point"], icr, scale=10)
    assert is_close(answer(name, icr="support")["point"], j, scale=10)
    assert is_close(answer(name, omega="bar"), w_bar) and is_close(w_bar, -2 / 11)
    assert is_close(answer(name, omega="support"), w_bar)      # a prismatic pair turns together
    assert is_close(answer(name, velocity="E"), v_e, scale=5)
    # the composition with the support as the moving frame: drag is rotation about J, and
    # the relative velocity runs along the bar
    parts = answer(name, decompose="E", moving="support")
    assert is_close(parts["velocity"]["drag"], cross(w_bar, [e[0] - j[0], e[1] - j[1]]), scale=5)
    rel = parts["velocity"]["relative"]
    assert abs(rel[0] * along[1] - rel[1] * along[0]) < 1e-9
    assert solved(name)[1]["dof"] == 1
