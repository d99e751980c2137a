"""Linkages (four-bar, slider-crank, inverted slider-crank, quick-return, Watt six-bar,
Jansen's leg, seed 001's R and P pairs) against their loop-closure equations, solved for the
positions as functions of the input angle (from the link lengths the files state) and
differentiated in time by sympy, or by mpmath for the deep chains: an independent route to
every number."""
from __future__ import annotations

import mpmath
import sympy
from sympy import atan2, cos, pi, sin, sqrt
from sympy.physics.vector import dynamicsymbols

from tests.conftest import hand_derivations

from .helpers import answer, at_instant, is_close, cross, solved

th, th2 = dynamicsymbols("theta theta2")


def circle_meet(p, rp, q, rq, side):
    """The intersection of circles (p, rp) and (q, rq) left (side=+1) or right of p→q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = sqrt(dx ** 2 + dy ** 2)
    a = (rp ** 2 - rq ** 2 + d ** 2) / (2 * d)
    h = sqrt(rp ** 2 - a ** 2)
    return [p[0] + a * dx / d - side * h * dy / d, p[1] + a * dy / d + side * h * dx / d]


def angle(p, q):
    return atan2(q[1] - p[1], q[0] - p[0])


def test_four_bar():
    # crank 1 (vertical at the instant), coupler 4, rocker 3, ground 4; B on the upper branch
    a = [cos(th), sin(th)]
    b = circle_meet(a, 4, [4, 0], 3, side=1)
    coords = {th: (pi / 2, 10, 0)}
    pos, vel, acc = at_instant(b, coords)
    assert is_close(pos, [(48 + 8 * 2 ** 0.5) / 17, 4 * (48 + 8 * 2 ** 0.5) / 17 - 11])
    assert is_close(answer("four_bar", velocity="B"), vel, scale=10)
    assert is_close(answer("four_bar", acceleration="B"), acc, scale=100)
    _, w3, a3 = at_instant(angle(a, b), coords)
    _, w4, a4 = at_instant(angle([4, 0], b), coords)
    assert is_close(answer("four_bar", omega="coupler"), w3)
    assert is_close(answer("four_bar", omega="rocker"), w4)
    assert is_close(answer("four_bar", alpha="coupler"), a3)
    assert is_close(answer("four_bar", alpha="rocker"), a4)


def test_slider_crank():
    r, l = sympy.Rational(5, 100), sympy.Rational(2, 10)
    xb = r * cos(th) + sqrt(l ** 2 - r ** 2 * sin(th) ** 2)
    a = [r * cos(th), r * sin(th)]
    b = [xb, 0]
    g = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]
    coords = {th: (pi / 3, 150, 0)}
    _, vb, ab = at_instant(b, coords)
    _, w_rod, al_rod = at_instant(angle(a, b), coords)
    _, _, ag = at_instant(g, coords)
    # textbook closed form as a second check: v_B = -r w sin th (1 + r cos th / sqrt(l² - r² sin² th))
    s3 = 3 ** 0.5 / 2
    v_text = -0.05 * 150 * s3 * (1 + 0.05 * 0.5 / (0.04 - 0.0025 * 0.75) ** 0.5)
    assert is_close(vb[0], v_text)
    assert is_close(answer("slider_crank", velocity="B"), vb, scale=10)
    assert is_close(answer("slider_crank", acceleration="B"), ab, scale=1000)
    assert is_close(answer("slider_crank", omega="rod"), w_rod)
    assert is_close(answer("slider_crank", alpha="rod"), al_rod)
    assert is_close(answer("slider_crank", acceleration="G"), ag, scale=1000)
    # the rod's instant centre: on the crank line O-A (v_A ⟂ OA) and above B (v_B horizontal)
    xb0 = float(xb.subs(th, pi / 3))
    icr = answer("slider_crank", icr="rod")["point"]
    assert is_close(icr, [xb0, xb0 * 3 ** 0.5])


def test_inverted_slider_crank_coriolis():
    r, d = sympy.Rational(1, 10), sympy.Rational(3, 10)
    a = [r * cos(th), r * sin(th)]
    phi = angle([d, 0], a)                      # the rod's angle
    rho = sqrt((a[0] - d) ** 2 + a[1] ** 2)     # O4-A along the rod
    coords = {th: (pi / 3, 20, 5)}
    pa, va, aa = at_instant(a, coords)
    _, w, al = at_instant(phi, coords)
    rho0, rho_d, rho_dd = at_instant(rho, coords)
    e = [(pa[0] - d) / rho0, pa[1] / rho0]
    o4a = [pa[0] - d, pa[1]]
    drag_v = cross(w, o4a)
    drag_a = [c1 - w ** 2 * c2 for c1, c2 in zip(cross(al, o4a), o4a)]
    rel_v = [rho_d * c for c in e]
    rel_a = [rho_dd * c for c in e]
    coriolis = cross(2 * w, rel_v)
    name = "inverted_slider_crank"
    assert is_close(answer(name, omega="rod"), w)
    assert is_close(answer(name, alpha="rod"), al)
    assert is_close(answer(name, velocity="A@block", relative_to="rod"), rel_v, scale=1)
    parts = answer(name, decompose="A@block", moving="rod")
    assert is_close(parts["velocity"]["drag"], drag_v, scale=1)
    assert is_close(parts["velocity"]["relative"], rel_v, scale=1)
    assert is_close(parts["velocity"]["total"], va, scale=1)
    assert is_close(parts["acceleration"]["drag"], drag_a, scale=10)
    assert is_close(parts["acceleration"]["relative"], rel_a, scale=10)
    assert is_close(parts["acceleration"]["coriolis"], coriolis, scale=10)
    assert is_close(parts["acceleration"]["total"], aa, scale=10)
    assert is_close(answer(name, acceleration="A@rod"), drag_a, scale=10)


def test_quick_return():
    r, c, big_l, l, h = (sympy.Rational(n, 10) for n in (1, 3, 5, 2, 5))
    a = [r * cos(th), c + r * sin(th)]
    phi = atan2(a[1], a[0])                     # rocker angle (slot through O4 and A)
    b = [big_l * cos(phi), big_l * sin(phi)]
    xc = b[0] + sqrt(l ** 2 - (h - b[1]) ** 2)
    rho = sqrt(a[0] ** 2 + a[1] ** 2)           # O4-A along the slot
    coords = {th: (pi / 6, 10, 0)}
    _, vc, ac = at_instant(xc, coords)
    _, w, al = at_instant(phi, coords)
    pa, va, aa = at_instant(a, coords)
    rho0, rho_d, rho_dd = at_instant(rho, coords)
    e = [pa[0] / rho0, pa[1] / rho0]
    rel_v = [rho_d * k for k in e]
    name = "quick_return"
    assert is_close(answer(name, velocity="C"), [vc, 0], scale=1)
    assert is_close(answer(name, acceleration="C"), [ac, 0], scale=10)
    assert is_close(answer(name, omega="rocker"), w)
    assert is_close(answer(name, alpha="rocker"), al)
    assert is_close(answer(name, velocity="A@crank", relative_to="rocker"), rel_v, scale=1)
    parts = answer(name, decompose="A@crank", moving="rocker")
    assert is_close(parts["acceleration"]["relative"], [rho_dd * k for k in e], scale=10)
    assert is_close(parts["acceleration"]["coriolis"], cross(2 * w, rel_v), scale=10)
    assert is_close(parts["acceleration"]["total"], aa, scale=10)


def test_seed_001_r_pairs_dyad_driven_at_both_ends():
    # crank A: O1=(0,0), |O1A| = 1 at 90°; crank E: O2=(4,0), |O2E| = √2 at 45°
    a = [cos(th), sin(th)]
    e = [4 + sqrt(2) * cos(th2), sqrt(2) * sin(th2)]
    b = circle_meet(a, sqrt(8), e, sqrt(13), side=1)
    coords = {th: (pi / 2, 10, 0), th2: (pi / 4, -5, 2)}
    pb, vb, ab = at_instant(b, coords)
    assert is_close(pb, [2, 3])
    _, w_n, al_n = at_instant(angle(a, b), coords)
    _, w_p, al_p = at_instant(angle(e, b), coords)
    name = "seed_001_r_pairs"
    assert solved(name)[1]["dof"] == 2
    assert is_close(answer(name, velocity="B"), vb, scale=10)
    assert is_close(answer(name, acceleration="B"), ab, scale=100)
    assert is_close(answer(name, omega="N"), w_n)
    assert is_close(answer(name, omega="P"), w_p)
    assert is_close(answer(name, alpha="N"), al_n)
    assert is_close(answer(name, alpha="P"), al_p)


def test_seed_001_p_pair_coriolis():
    # the guide M turns about A at beta(t); B slides on it at s(beta) from A, where the
    # rocker keeps |EB| fixed: s² − 2 s (u·E) + |E|² − |EB|² = 0, u = (cos beta, sin beta)
    beta = th
    ex, ey = sympy.Rational(1, 10), sympy.Rational(4, 10)
    s0 = sympy.Rational(4, 10)
    b0 = [s0 * cos(pi / 6), s0 * sin(pi / 6)]
    eb2 = (b0[0] - ex) ** 2 + (b0[1] - ey) ** 2
    ue = ex * cos(beta) + ey * sin(beta)
    s = ue + sqrt(ue ** 2 - ex ** 2 - ey ** 2 + eb2)
    assert abs(float(s.subs(beta, pi / 6)) - 0.4) < 1e-12     # the branch drawn
    b = [s * cos(beta), s * sin(beta)]
    coords = {beta: (pi / 6, 4, -2)}
    pb, vb, ab = at_instant(b, coords)
    _, w_rocker, al_rocker = at_instant(angle([ex, ey], b), coords)
    s_0, s_d, s_dd = at_instant(s, coords)
    u = [cos(pi / 6), sin(pi / 6)]
    rel_v = [s_d * k for k in u]
    name = "seed_001_p_pair_coriolis"
    assert is_close(answer(name, omega="rocker"), w_rocker)
    assert is_close(answer(name, alpha="rocker"), al_rocker)
    assert is_close(answer(name, omega="N"), 4)          # the block turns with its guide
    assert is_close(answer(name, velocity="B@N", relative_to="M"), rel_v, scale=1)
    assert is_close(answer(name, acceleration="B@N", relative_to="M"), [s_dd * k for k in u], scale=10)
    parts = answer(name, decompose="B@N", moving="M")
    assert is_close(parts["acceleration"]["coriolis"], cross(8, rel_v), scale=10)   # 2 w_M x v_rel
    assert is_close(parts["acceleration"]["total"], ab, scale=10)
    assert is_close(parts["velocity"]["total"], vb, scale=1)




meet = hand_derivations().meet     # circle_meet in mpmath numbers, for chains too deep for algebra


def by_crank(position, theta, w):
    """Value, velocity and acceleration of `position`(crank angle), a list of numbers, when
    the crank is at `theta` degrees turning at `w` steady: d/dt = w d/dθ, the derivatives
    taken by mpmath at 40 digits."""
    with mpmath.workdps(40):
        t0 = mpmath.radians(theta)
        n = len(position(t0))
        value = [float(c) for c in position(t0)]
        first = [float(w * mpmath.diff(lambda t, i=i: position(t)[i], t0, 1)) for i in range(n)]
        second = [float(w * w * mpmath.diff(lambda t, i=i: position(t)[i], t0, 2)) for i in range(n)]
    return value, first, second


def test_watt_six_bar_two_loops_by_their_lengths():
    def output(t):
        # loop 1: ground 4, crank 1, coupler 4, rocker 3; B above the ground line
        b = meet([mpmath.cos(t), mpmath.sin(t)], 4, [4, 0], 3, side=1)
        phi4 = mpmath.atan2(b[1], b[0] - 4)
        # the rocker's second pin C is 1 from O4, on the ground line when drawn (crank up):
        # it keeps its angle to O4B, so it turns with the rocker from angle 0
        b0 = meet([0, 1], 4, [4, 0], 3, side=1)
        turn = phi4 - mpmath.atan2(b0[1], b0[0] - 4)
        c = [4 + mpmath.cos(turn), mpmath.sin(turn)]
        d = meet(c, 4, [8, 0], 3, side=1)                 # loop 2: coupler 4, output 3
        return [d[0], d[1], mpmath.atan2(d[1], d[0] - 8)]

    (dx, dy, _), (_, _, w6), (_, _, a6) = by_crank(output, 90, 10)
    assert is_close([dx, dy], [23 / 3, 80 ** 0.5 / 3], scale=10)      # 4 from C = (5, 0), 3 from O6
    assert is_close(answer("watt_six_bar", omega="output"), w6)
    assert is_close(answer("watt_six_bar", alpha="output"), a6, scale=100)


def test_jansen_leg_from_the_holy_numbers():
    n = mpmath.mpf

    def foot(t):
        # every joint where two circles meet, on the side of the working leg
        a = [38 + 15 * mpmath.cos(t), n("7.8") + 15 * mpmath.sin(t)]
        z = [0, 0]
        b = meet(z, n("41.5"), a, 50, side=1)
        e = meet(z, n("40.1"), b, n("55.8"), side=1)
        d = meet(z, n("39.3"), a, n("61.9"), side=-1)
        f = meet(e, n("39.4"), d, n("36.7"), side=-1)
        return meet(d, 49, f, n("65.7"), side=1)

    pp, vp, ap = by_crank(foot, 90, 1)
    # the drawn foot, as the file gave it before (coordinates to 12 decimals)
    assert is_close(pp, [30.310933769358, -82.589351367404], rel=1e-11, scale=100)
    assert is_close(answer("jansen_leg", velocity="P"), vp, scale=10)
    assert is_close(answer("jansen_leg", acceleration="P"), ap, scale=10)
