"""Independent derivations of the textbook cases in this folder (NAME.yaml).

Each function solves one problem as a student would, by hand: the position of what is
asked is written as a function of the input (loop closure, triangles, Freudenstein,
rolling conditions, the cones of a spherical linkage) and differentiated in time, by
mpmath at 40 digits: with q(t) = q0 + w t + al t²/2, d/dt = w d/dq and
d²/dt² = w² d²/dq² + al d/dq (`motion` of tests/cases/derive.py). Rates of bodies are the
derivatives of their angles; the symbolic cases give formulas derived by hand (see
their docstrings). Nothing here calls kinematika.

`python tests/textbook/derive.py` rewrites each case's NAME.expect.json from these
derivations; tests/textbook/test_textbook.py checks that the files hold exactly these
values and runs every case through the command line under check-cases' rules.
"""
from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import mpmath

HERE = Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location("cases_derive", HERE.parent / "cases" / "derive.py")
base = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(base)
meet, polar, motion, curvature, line_meet, turn, cross = (base.meet, base.polar, base.motion, base.curvature,
                                                         base.line_meet, base.turn, base.cross)
D = mpmath.radians


def angle(p, q):
    """Direction of p→q (radians)."""
    return mpmath.atan2(q[1] - p[1], q[0] - p[0])


def frame(p, q, x, y):
    """p + x u + y n, u the unit vector p→q and n = u turned +90°."""
    dist = mpmath.sqrt((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2)
    u = [(q[0] - p[0]) / dist, (q[1] - p[1]) / dist]
    return [p[0] + x * u[0] - y * u[1], p[1] + x * u[1] + y * u[0]]


def on_line(centre, r, through, direction, ahead=True):
    """Where the circle (centre, r) meets the line through `through` along `direction`:
    the intersection farther along the direction when `ahead`."""
    n = mpmath.sqrt(direction[0] ** 2 + direction[1] ** 2)
    d = [direction[0] / n, direction[1] / n]
    w = [through[0] - centre[0], through[1] - centre[1]]
    b = w[0] * d[0] + w[1] * d[1]
    s = -b + (1 if ahead else -1) * mpmath.sqrt(b * b - (w[0] ** 2 + w[1] ** 2 - r * r))
    return [through[0] + s * d[0], through[1] + s * d[1]]


# four-bars ---------------------------------------------------------------------------------
def four_bar(d, a, b, c, side=1):
    """B of the four-bar O2 = (0, 0), O4 = (d, 0) at crank angle t."""
    return lambda t: meet(polar([0, 0], a, t), b, [d, 0], c, side)


def fb_crank_rocker_coupler():
    """B from the circles about A (7) and O4 (6), left of A→O4 (the open circuit);
    P = A + 3 u − 1.5 n; θ3 = angle of AB, θ4 = angle of O4B, differentiated at θ2 = 50°,
    ω2 = −12, α2 = −30; curvature of P's path |v|³/|v × a|."""
    b_of = four_bar(8, 2, 7, 6)

    def pos(t):
        a, b = polar([0, 0], 2, t), b_of(t)
        p = frame(a, b, 3, mpmath.mpf("-1.5"))
        return [angle(a, b), angle([8, 0], b), p[0], p[1]]

    (_, _, px, py), (w3, w4, vx, vy), (al3, al4, ax, ay) = motion(pos, math.radians(50), -12, -30)
    return [w3, w4, al3, al4, [vx, vy], [ax, ay], curvature([px, py], [vx, vy], [ax, ay])]


def fb_crossed_icr():
    """B right of A→O4 (crossed); ω3, ω4 and α3 differentiated at 50°, ω2 = 5; the
    coupler's centre where the lines O2A and O4B meet (Kennedy), the rocker's its pivot."""
    b_of = four_bar(8, 2, 7, 6, side=-1)

    def pos(t):
        a, b = polar([0, 0], 2, t), b_of(t)
        return [angle(a, b), angle([8, 0], b), b[0], b[1]]

    (_, _, bx, by), (w3, w4, vx, vy), (al3, _, _, _) = motion(pos, math.radians(50), 5)
    a = [2 * math.cos(math.radians(50)), 2 * math.sin(math.radians(50))]
    icr = line_meet([0, 0], a, [8, 0], [bx - 8, by])
    return [w3, w4, al3, {"point": icr}, {"point": [8.0, 0.0]}, [vx, vy]]


def _triple_rocker(theta_deg):
    b_of = four_bar(6, 5, 4, mpmath.mpf("3.5"))

    def pos(t):
        a, b = polar([0, 0], 5, t), b_of(t)
        return [angle(a, b), angle([6, 0], b), b[0], b[1]]

    _, (w3, w4, vx, vy), (al3, al4, ax, ay) = motion(pos, math.radians(theta_deg), 3, -2)
    return [w3, w4, al3, al4, [vx, vy], [ax, ay]]


def fb_non_grashof():
    """Open circuit (B left of A→O4) at 60°, ω2 = 3, α2 = −2; angles of AB and O4B
    differentiated."""
    return _triple_rocker(60)


def fb_non_grashof_moved():
    """At 60° − 40° = 20°: |AO4| stays between |b − c| = 0.5 and b + c = 7.5 from 60° down
    to 20° (|AO4|² = 61 − 60 cos θ ≥ 1), so no dead point is met and B stays left of A→O4:
    the open circuit at 20°."""
    return _triple_rocker(20)


def fb_drag_link_moved():
    """A drag link never toggles (|AO4| between 3 and 7, inside [0.5, 11.5]), so after
    290° the linkage is on its drawn (left) circuit at 200° + 290° = 130°; ω2 = 4."""
    b_of = four_bar(2, 5, 6, mpmath.mpf("5.5"))

    def pos(t):
        a, b = polar([0, 0], 5, t), b_of(t)
        return [angle([2, 0], b), angle(a, b), b[0], b[1]]

    _, (w4, w3, vx, vy), (al4, al3, _, _) = motion(pos, math.radians(130), 4)
    return [w4, al4, w3, al3, [vx, vy]]


def fb_parallelogram():
    """A parallelogram: B = A + (8, 0), so the coupler translates (ω3 = α3 = 0), the rocker
    turns with the crank (ω4 = 6, α4 = 2), v_B = v_A = ω2 k × O2A; the coupler's centre is
    at infinity along O2A (perpendicular to v_A)."""
    t = math.radians(70)
    return [0.0, 0.0, 6.0, 2.0, {"point": None, "direction": [math.cos(t), math.sin(t)]},
            [-6 * 3 * math.sin(t), 6 * 3 * math.cos(t)]]


# slider-cranks and their inversions ----------------------------------------------------------
def sc_offset_above(theta_deg: float = 300):
    """x_B = a cos θ + √(b² − (e − a sin θ)²) on y = e = 15; the rod's angle
    φ = atan2(e − a sin θ, x_B − a cos θ); M the midpoint of AB; θ = 300°, ω2 = −40,
    α2 = 100. The rod's centre where the line O2A meets the vertical through B; the slider's
    path is straight (no centre of curvature); the rod's acceleration pole from a_A."""
    a, b, e = 30, 90, 15

    def pos(t):
        pa = polar([0, 0], a, t)
        pb = [pa[0] + mpmath.sqrt(b ** 2 - (e - pa[1]) ** 2), e]
        return [pb[0], angle(pa, pb), (pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2]

    t = math.radians(theta_deg)
    (xb, _, _, _), (vb, w3, vmx, vmy), (ab, al3, _, _) = motion(pos, t, -40, 100)
    icr = line_meet([0, 0], [math.cos(t), math.sin(t)], [xb, e], [0, 1])
    # the rod's acceleration pole P: a_A + α k × AP − ω² AP = 0, so
    # AP = (ω² a_A + α J a_A)/(ω⁴ + α²) (J a quarter turn); a_A = α2 k × OA − ω2² OA
    pa = [a * math.cos(t), a * math.sin(t)]
    a_a = [x - 1600 * y for x, y in zip(turn(100, pa), pa)]
    ja = [-a_a[1], a_a[0]]
    den = w3 ** 4 + al3 ** 2
    pole = [p + (w3 * w3 * x + al3 * y) / den for p, x, y in zip(pa, a_a, ja)]
    return [[vb, 0.0], [ab, 0.0], w3, al3, {"point": icr}, [vmx, vmy], {"radius": None, "center": None},
            {"point": pole}]


def _vertical_engine(theta_deg):
    def pos(t):
        pa = polar([0, 0], 50, t)
        pb = [-10, pa[1] + mpmath.sqrt(160 ** 2 - (pa[0] + 10) ** 2)]
        return [pb[1], angle(pa, pb)]

    _, (vb, w3), (ab, al3) = motion(pos, math.radians(theta_deg), 100)
    return [[0.0, vb], [0.0, ab], w3, al3]


def sc_vertical_engine():
    """y_B = r sin θ + √(l² − (r cos θ + 10)²) on x = −10; the rod's angle atan2(B − A);
    θ = 30°, ω = 100."""
    return _vertical_engine(30)


def sc_vertical_engine_moved():
    """l = 160 > r + 10, so the piston stays above the crank for every angle: the moved
    configuration is the same formula at 30° + 120° = 150°."""
    return _vertical_engine(150)


def isc_oscillating_cylinder():
    """φ = atan2(A − O4), ρ = |A − O4| with A = 0.1 (cos θ, sin θ), θ = 220°, ω2 = 25,
    α2 = 40; seen from the cylinder the piston moves ρ' u and ρ'' u (u along O4A); drag
    v = ω k × r, a = α k × r − ω² r (r = O4A), Coriolis 2 ω k × ρ' u; totals v_A, a_A."""
    o4 = [mpmath.mpf("-0.3"), mpmath.mpf("0.1")]

    def pos(t):
        pa = polar([0, 0], mpmath.mpf("0.1"), t)
        return [angle(o4, pa), mpmath.sqrt((pa[0] - o4[0]) ** 2 + (pa[1] - o4[1]) ** 2)]

    t = math.radians(220)
    (phi, rho), (w, rho_d), (al, rho_dd) = motion(pos, t, 25, 40)
    u = [math.cos(phi), math.sin(phi)]
    r = [rho * u[0], rho * u[1]]
    v_rel, a_rel = [rho_d * u[0], rho_d * u[1]], [rho_dd * u[0], rho_dd * u[1]]
    v_drag = turn(w, r)
    a_drag = [x - w * w * y for x, y in zip(turn(al, r), r)]
    cor = turn(2 * w, v_rel)
    pa = [0.1 * math.cos(t), 0.1 * math.sin(t)]
    v_a, a_a = turn(25, pa), [x - 625 * y for x, y in zip(turn(40, pa), pa)]
    return [w, al, v_rel, a_rel,
            {"velocity": {"drag": v_drag, "relative": v_rel, "total": v_a},
             "acceleration": {"drag": a_drag, "relative": a_rel, "coriolis": cor, "total": a_a}}]


def isc_slotted_crank():
    """B = s e on the slot (e = (cos θ, sin θ)), |B − O4| = 3: s = 4 cos θ + √(9 − 16 sin² θ)
    (the far root); the rocker's angle atan2(B − O4); seen from the crank the pin moves s' e
    and s'' e. θ = 30°, ω = 2, α = 1."""
    def pos(t):
        s = 4 * mpmath.cos(t) + mpmath.sqrt(9 - 16 * mpmath.sin(t) ** 2)
        return [angle([4, 0], [s * mpmath.cos(t), s * mpmath.sin(t)]), s]

    t = math.radians(30)
    _, (w4, sd), (al4, sdd) = motion(pos, t, 2, 1)
    e = [math.cos(t), math.sin(t)]
    return [w4, al4, [sd * e[0], sd * e[1]], [sdd * e[0], sdd * e[1]]]


def sc_offset_symbolic_theta():
    """x_B = 3 cos θ + R, R = √(100 − (1 − 3 sin θ)²): v = w (−3 sin θ + 3 cos θ (1 − 3 sin θ)/R);
    the rod's sin φ = (1 − 3 sin θ)/10, so φ' cos φ = −3 cos θ/10 and ω = −3 w cos θ/R."""
    root = "sqrt(100 - (1 - 3*sin(theta))**2)"
    return [[f"w*(-3*sin(theta) + 3*cos(theta)*(1 - 3*sin(theta))/{root})", "0"], f"-3*w*cos(theta)/{root}"]


def isc_oscillating_cylinder_symbolic():
    """tan φ = sin θ/(cos θ − 3): φ' = w (1 − 3 cos θ)/ρ² with ρ² = 10 − 6 cos θ; ρ' = 3 w sin θ/ρ
    (from ρ² = 10 − 6 cos θ), along u = (cos θ − 3, sin θ)/ρ."""
    return ["w*(1 - 3*cos(theta))/(10 - 6*cos(theta))",
            ["3*w*sin(theta)*(cos(theta) - 3)/(10 - 6*cos(theta))", "3*w*sin(theta)**2/(10 - 6*cos(theta))"]]


# quick-returns, Geneva, pin in slot ----------------------------------------------------------
def qr_whitworth_opposite():
    """φ = atan2(A − O4), B = O4 − 100 (cos φ, sin φ), x_C = x_B + √(300² − (20 − y_B)²);
    the block seen from the slotted link moves ρ' u (ρ = |O4A|, u along O4A); θ = 250°, ω = 3."""
    o4 = [50, 0]

    def pos(t):
        pa = polar([0, 0], 150, t)
        phi = angle(o4, pa)
        pb = polar(o4, -100, phi)
        rho = mpmath.sqrt((pa[0] - 50) ** 2 + pa[1] ** 2)
        return [pb[0] + mpmath.sqrt(300 ** 2 - (20 - pb[1]) ** 2), phi, rho]

    (_, phi, _), (vc, w4, rho_d), (ac, al4, _) = motion(pos, math.radians(250), 3)
    return [[vc, 0.0], [ac, 0.0], w4, al4, [rho_d * math.cos(phi), rho_d * math.sin(phi)]]


def qr_drag_link():
    """B from the circles about A (5) and O4 (4.5), left of A→O4; ψ = angle of O4B,
    C = O4 − 3 (cos ψ, sin ψ), x_D = x_C + √(64 − y_C²) on y = 0; θ = 75°, ω = 5."""
    def pos(t):
        pb = meet(polar([0, 0], 4, t), 5, [mpmath.mpf("1.5"), 0], mpmath.mpf("4.5"), 1)
        psi = angle([mpmath.mpf("1.5"), 0], pb)
        pc = polar([mpmath.mpf("1.5"), 0], -3, psi)
        return [psi, pc[0] + mpmath.sqrt(64 - pc[1] ** 2)]

    _, (w4, vd), (al4, ad) = motion(pos, math.radians(75), 5)
    return [w4, al4, [vd, 0.0], [ad, 0.0]]


def geneva_four_slot():
    """The slot's line passes through O3 and P: φ = atan2(r sin θ, r cos θ − c),
    ρ = |O3P|; seen from the wheel the pin moves straight along the slot: ρ' u and ρ'' u.
    θ = 20°, ω = 10, r = 50, c = 50√2."""
    c = 50 * mpmath.sqrt(2)

    def pos(t):
        pp = polar([0, 0], 50, t)
        return [angle([c, 0], pp), mpmath.sqrt((pp[0] - c) ** 2 + pp[1] ** 2)]

    (phi, _), (w, rd), (al, rdd) = motion(pos, math.radians(20), 10)
    u = [math.cos(phi), math.sin(phi)]
    return [w, al, [rd * u[0], rd * u[1]], [rdd * u[0], rdd * u[1]]]


def fb_parallelogram_letters():
    """B = A + (L, 0) is left of A→O4 at 70° (the cross product of O4 − A and B − A is
    r L sin 70° > 0), so the coupler translates: ω3 = 0, ω4 = w, its centre at infinity
    along O2A, v_B = v_A = r w (−sin 70°, cos 70°). (It used to be a long formula in
    sin(7π/18) and cos(π/9), equal to 0 but not seen to be, and the centre 'zoo'.)"""
    return ["0", "w", {"point": None, "direction": ["cos(7*pi/18)", "sin(7*pi/18)"]},
            ["-r*w*sin(7*pi/18)", "r*w*cos(7*pi/18)"]]


def geneva_symbolic_theta():
    """tan φ = sin θ/(cos θ − √2): φ' = w (1 − √2 cos θ)/(3 − 2√2 cos θ)."""
    return ["w*(1 - sqrt(2)*cos(theta))/(3 - 2*sqrt(2)*cos(theta))"]


def scotch_yoke():
    """x_Y = 80 cos θ: v = −80 ω sin θ, a = −80 (ω² cos θ + α sin θ); seen from the
    yoke the pin moves along the slot at 80 ω cos θ. θ = 35°, ω = 30, α = −10."""
    t, w, al = math.radians(35), 30, -10
    return [[-80 * w * math.sin(t), 0.0], [-80 * (w * w * math.cos(t) + al * math.sin(t)), 0.0],
            [0.0, 80 * w * math.cos(t)]]


def scotch_yoke_symbolic():
    """x_Y = r cos θ: v = −r w sin θ, a = −r w² cos θ − r al sin θ."""
    return [["-r*w*sin(theta)", "0"], ["-r*w**2*cos(theta) - r*al*sin(theta)", "0"]]


def pin_slotted_rocker():
    """tan φ = 0.3/x, the block at x = 0.4 moving at 0.6 (constant): φ and ρ = √(x² + 0.09)
    differentiated; drag v = ω k × OP, a = α k × OP − ω² OP; relative ρ' u, ρ'' u;
    Coriolis 2 ω k × ρ' u; the pin's own v = (0.6, 0), a = 0."""
    def pos(x):
        return [mpmath.atan2(mpmath.mpf("0.3"), x), mpmath.sqrt(x * x + mpmath.mpf("0.09"))]

    (phi, rho), (w, rd), (al, rdd) = motion(pos, 0.4, 0.6)
    u = [math.cos(phi), math.sin(phi)]
    r = [rho * u[0], rho * u[1]]
    v_rel, a_rel = [rd * u[0], rd * u[1]], [rdd * u[0], rdd * u[1]]
    return [w, al, {"velocity": {"drag": turn(w, r), "relative": v_rel, "total": [0.6, 0.0]},
                    "acceleration": {"drag": [x - w * w * y for x, y in zip(turn(al, r), r)], "relative": a_rel,
                                     "coriolis": turn(2 * w, v_rel), "total": [0.0, 0.0]}}]


# six-bars ----------------------------------------------------------------------------------
def watt_one():
    """Loop 1: B from the circles about A (5.5) and O4 (4), left of A→O4; C = A + 3 at 40°
    from AB, D = O4 + 2.5 at 50° from O4B; loop 2: E from the circles about C (4) and
    D (3.5), left of C→D; angles of CE and ED and E differentiated at 80°, ω2 = 10, α2 = 5."""
    o4 = [6, 0]

    def pos(t):
        a = polar([0, 0], mpmath.mpf("1.5"), t)
        b = meet(a, mpmath.mpf("5.5"), o4, 4, 1)
        c = polar(a, 3, angle(a, b) + D(40))
        d = polar(o4, mpmath.mpf("2.5"), angle(o4, b) + D(50))
        e = meet(c, 4, d, mpmath.mpf("3.5"), 1)
        return [angle(c, e), angle(e, d), e[0], e[1]]

    _, (w5, w6, vx, vy), (al5, al6, ax, ay) = motion(pos, math.radians(80), 10, 5)
    return [w5, w6, al5, al6, [vx, vy], [ax, ay]]


def stephenson_slider():
    """B from the circles about A (4.5) and O4 (3.5), left; P = A + 2.5 at −35° from AB;
    x_Q = x_P + √(25 − (y_P + 1.5)²) on y = −1.5; the rod's angle; θ = 140°, ω = −8."""
    def pos(t):
        a = polar([0, 0], mpmath.mpf("1.5"), t)
        b = meet(a, mpmath.mpf("4.5"), [5, 0], mpmath.mpf("3.5"), 1)
        p = polar(a, mpmath.mpf("2.5"), angle(a, b) - D(35))
        q = [p[0] + mpmath.sqrt(25 - (p[1] + mpmath.mpf("1.5")) ** 2), mpmath.mpf("-1.5")]
        return [q[0], angle(p, q)]

    _, (vq, w5), (aq, al5) = motion(pos, math.radians(140), -8)
    return [[vq, 0.0], [aq, 0.0], w5, al5]


def _triad_drawn():
    """The drawn points of the triad case, from its stated angles."""
    a = polar([0, 0], 1, D(30))
    b = polar(a, 3, D(20))
    c, d = polar(b, mpmath.mpf("2.5"), D(-30)), polar(b, 2, D(60))
    return a, b, c, d, polar(c, mpmath.mpf("2.8"), D(-80)), polar(d, mpmath.mpf("2.2"), D(120))


def triad_pose(t, start):
    """The triad closed at crank angle t by Newton from `start` = (φ1, ψ, φ2, φ3): the angles
    of AB, of the ternary (its BC direction), of O4C and of O6D. The loops
    A + 3 e(φ1) + 2.5 e(ψ) = O4 + 2.8 e(φ2) and A + 3 e(φ1) + 2 e(ψ + 90°) = O6 + 2.2 e(φ3)
    (the ternary's BD is 90° from BC)."""
    _, _, _, _, o4, o6 = _triad_drawn()
    a = polar([0, 0], 1, t)

    def loops(f1, psi, f2, f3):
        b = polar(a, 3, f1)
        c, d = polar(b, mpmath.mpf("2.5"), psi), polar(b, 2, psi + D(90))
        cc, dd = polar(o4, mpmath.mpf("2.8"), f2), polar(o6, mpmath.mpf("2.2"), f3)
        return [c[0] - cc[0], c[1] - cc[1], d[0] - dd[0], d[1] - dd[1]]

    return mpmath.findroot(loops, start, tol=mpmath.mpf(10) ** (-2 * mpmath.mp.dps + 10))


def stephenson_triad():
    """No dyad closes first: the four angles solve the two loop equations together (Newton
    from the drawn pose, at 40 digits); C = O4 + 2.8 e(φ2); everything differentiated in θ
    at 30° with ω = 4."""
    _, _, _, _, o4, _ = _triad_drawn()
    start = [D(20), D(-30), D(100), D(-60)]

    def pos(t):
        f1, psi, f2, f3 = triad_pose(t, start)
        c = polar(o4, mpmath.mpf("2.8"), f2)
        return [f1, psi, f2, f3, c[0], c[1]]

    _, (w1, wt, w2, w3, vx, vy), (_, alt, _, _, ax, ay) = motion(pos, math.radians(30), 4)
    return [w1, wt, w2, w3, alt, [vx, vy], [ax, ay]]


def triad_assemblies(steps: int = 720) -> list[tuple[float, float]]:
    """Every closure of the triad at the drawn crank angle, as (φ1, ψ) in degrees: for each
    direction φ1 of AB, C = B + 2.5 e(ψ) on the circle of radius 2.8 about O4 gives two ψ
    (cos(ψ − β) = (|O4B|² + 2.5² − 2.8²)/(5 |O4B|)); a closure is where |D − O6| − 2.2
    changes sign along φ1 on either branch (refined by the secant method at 30 digits)."""
    a, _, _, _, o4, o6 = _triad_drawn()

    def branch(f1, s):
        b = polar(a, 3, f1)
        dist = mpmath.sqrt((o4[0] - b[0]) ** 2 + (o4[1] - b[1]) ** 2)
        k = (dist ** 2 + mpmath.mpf("6.25") - mpmath.mpf("7.84")) / (5 * dist)
        if abs(k) > 1:
            return None
        psi = angle(b, o4) + s * mpmath.acos(k)
        d = polar(b, 2, psi + D(90))
        return psi, mpmath.sqrt((d[0] - o6[0]) ** 2 + (d[1] - o6[1]) ** 2) - mpmath.mpf("2.2")

    out = []
    with mpmath.workdps(30):
        for s in (1, -1):
            prev = None
            for i in range(steps + 1):
                f1 = 2 * mpmath.pi * i / steps
                here = branch(f1, s)
                if here is not None and prev is not None and prev[1] * here[1] < 0:
                    root = mpmath.findroot(lambda x, s=s: branch(x, s)[1], (prev[0], f1), solver="secant")
                    out.append((float(mpmath.degrees(root)) % 360, float(mpmath.degrees(branch(root, s)[0])) % 360))
                prev = None if here is None else (f1, here[1])
    return sorted(out)


# gears and rolling --------------------------------------------------------------------------
def gear_compound_train():
    """External meshes reverse: ω2 = ω3 = −ω1 r1/r2 = −50, ω4 = −ω3 r3/r4 = 50/3,
    α4 = α1 (r1/r2)(r3/r4) = 10/9. The pitch point K = (20, 0) stays put (geometric
    contact at rest); gear 1's point there: v = ω1 k × O1K, a = α1 k × O1K − ω1² O1K;
    gear 2's: the same with ω2 = −50, α2 = −10/3 about O2 = (80, 0)."""
    w1, al1 = 150, 10
    w2, al2 = -w1 * 20 / 60, -al1 * 20 / 60
    r1, r2 = [20, 0], [-60, 0]

    def point(w, al, r):
        return {"velocity": turn(w, r), "acceleration": [x - w * w * y for x, y in zip(turn(al, r), r)]}

    return [w2, -w2 * 25 / 75, al1 * (20 / 60) * (25 / 75),
            {"body_a": point(w1, al1, r1), "body_b": point(w2, al2, r2),
             "geometric": {"velocity": [0.0, 0.0], "acceleration": [0.0, 0.0]}}]


def epicyclic_arm():
    """Rolling on the fixed sun: the planet turns (1 + 40/20) = 3 times the arm, so with the
    arm at β: Q = 60 e(β) + 20 e(90° + 3 (β − 30°)); ω_p = 18, α_p = 6; differentiated at
    β = 30° with ω = 6, α = 2; the planet's centre is its contact with the sun, 40 e(30°)."""
    b0 = D(30)

    def pos(b):
        a = polar([0, 0], 60, b)
        return polar(a, 20, D(90) + 3 * (b - b0))

    (qx, qy), v, acc = motion(pos, math.radians(30), 6, 2)
    return [18.0, 6.0, v, acc, curvature([qx, qy], v, acc),
            {"point": [40 * math.cos(math.radians(30)), 40 * math.sin(math.radians(30))]}]


def planetary_two_inputs():
    """Willis: (ω_r − ω_c)/(ω_s − ω_c) = −r_s/r_r = −1/2, so ω_r = 20 − 40 = −20; relative to
    the carrier the planet turns −(ω_s − ω_c) r_s/r_p = −160, absolutely −140; the planet's
    centre moves with the carrier: 20 × 45 upwards; relative to the carrier the planet turns
    about its pin A."""
    return [-20.0, -140.0, -160.0, [0.0, 900.0], {"point": [45.0, 0.0]}]


def rolling_hypocycloid():
    """Rolling inside the ring: the contact point of the wheel is at rest, so
    3 ω_arm + 1 ω_w = 0: the wheel turns at −3 times the arm. P = 3 e(β) + e(110° − 3 (β − 20°))
    differentiated at β = 20° (ω = 2, α = 0.5); ω_w = −6, α_w = −1.5; the centre is the
    contact, 4 e(20°)."""
    b0 = D(20)

    def pos(b):
        return polar(polar([0, 0], 3, b), 1, D(110) - 3 * (b - b0))

    p, v, acc = motion(pos, math.radians(20), 2, 0.5)
    return [-6.0, -1.5, v, acc, curvature(p, v, acc),
            {"point": [4 * math.cos(math.radians(20)), 4 * math.sin(math.radians(20))]}]


def rolling_on_plank():
    """No slip at the contact J: v_C + ω r = v_plank, so ω = (1.5 + 0.5)/0.3, α = (0.5 − 0)/0.3;
    v_T = v_C − ω r, a_T = (a_C − α r, −ω² r); the centre is on the vertical through C where
    v_C − ω y = 0 (y up from C): r + v_C/ω above J; the plank's point at J moves with the plank,
    the disc's point at J has the plank's velocity and (a_C + α r, ω² r); the geometric
    contact stays under C: (v_C, 0) and (a_C, 0)."""
    r, vp, ap, vc, ac = 0.3, 1.5, 0.5, -0.5, 0.0
    w, al = (vp - vc) / r, (ap - ac) / r
    return [w, al, [vc - w * r, 0.0], [ac - al * r, -w * w * r], {"point": [0.0, r + vc / w]},
            {"body_a": {"velocity": [vp, 0.0], "acceleration": [ap, 0.0]},
             "body_b": {"velocity": [vc + w * r, 0.0], "acceleration": [ac + al * r, w * w * r]},
             "geometric": {"velocity": [vc, 0.0], "acceleration": [ac, 0.0]}}]


def rolling_wheel_rod():
    """With the centre at x (moving at 2, 1 m/s²) the wheel has turned −x/r: A = (x, r) +
    r e(135° − x/r); x_B = x_A + √(0.8² − y_A²) on the floor; ω_w = −2/0.25; the rod's angle
    and x_B differentiated in x at 0."""
    r, l = mpmath.mpf("0.25"), mpmath.mpf("0.8")

    def pos(x):
        a = polar([x, r], r, D(135) - x / r)
        b = [a[0] + mpmath.sqrt(l * l - a[1] ** 2), 0]
        return [angle(a, b), b[0]]

    _, (w, vb), (al, ab) = motion(pos, 0.0, 2, 1)
    return [-8.0, w, al, [vb, 0.0], [ab, 0.0]]


def rolling_on_drum():
    """The roller's contact point is at rest: v_C = ω k × (C − J), so ω = v/r = 20 and
    α = a_t/r = −30; C moves on the circle of radius R + r: a_C = a_t e⊥ − v²/(R + r) e
    (e along OC at 60°); the roller's contact point: a_C + α k × (J − C) − ω² (J − C) =
    ω² r R/(R + r) e."""
    t, v, at, big_r, r = math.radians(60), 2.0, -3.0, 0.4, 0.1
    e, n = [math.cos(t), math.sin(t)], [-math.sin(t), math.cos(t)]
    a_c = [at * y - v * v / (big_r + r) * x for x, y in zip(e, n)]
    w, al = v / r, at / r
    jc = [-r * x for x in e]
    return [w, al, a_c, [x + y - w * w * z for x, y, z in zip(a_c, turn(al, jc), jc)]]


def rack_and_pinion():
    """The pinion's point at the pitch point K = (0, −25) moves with the rack:
    ω k × OK = (25 ω, 0) = (−500, 0), so ω = −20, α = −200/25 = −8; T = 28 e(30°):
    v = ω k × OT, a = α k × OT − ω² OT."""
    w, al = -500 / 25, -200 / 25
    t = [28 * math.cos(math.radians(30)), 28 * math.sin(math.radians(30))]
    return [w, al, turn(w, t), [x - w * w * y for x, y in zip(turn(al, t), t)]]


def fb_coupler_driven():
    """With θ3 = g(θ2) and θ4 = h(θ2) (the open four-bar), the motor holds
    ω3 − ω2 = (g' − 1) ω2 = 4: ω2 = 4/(g' − 1), and differentiating
    α2 = −4 ω2 g''/(g' − 1)² (= α3: the relative rate is constant); ω3 = g' ω2,
    α3 = g' α2 + g'' ω2², ω4 = h' ω2, α4 = h' α2 + h'' ω2²."""
    b_of = four_bar(5, 2, mpmath.mpf("4.5"), mpmath.mpf("3.5"))

    def pos(t):
        a, b = polar([0, 0], 2, t), b_of(t)
        return [angle(a, b), angle([5, 0], b)]

    _, (g1, h1), (g2, h2) = motion(pos, math.radians(75), 1.0)    # at unit rate: g', h' and g'', h''
    w2 = 4 / (g1 - 1)
    al2 = -4 * w2 * g2 / (g1 - 1) ** 2
    return [w2, g1 * w2, h1 * w2, al2, g1 * al2 + g2 * w2 * w2, h1 * al2 + h2 * w2 * w2]


# spatial linkages ---------------------------------------------------------------------------
def v_cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def v_dot(u, v):
    return sum(x * y for x, y in zip(u, v))


def spherical_b(t):
    """B on the unit sphere 75° from A(t) and 45° from D: B = p A + q D + s A × D with p, q
    from B·A = cos 75°, B·D = cos 45° and s from |B| = 1 (the root with s > 0, which is
    the drawn one)."""
    a = [mpmath.sin(D(25)) * mpmath.cos(t), mpmath.sin(D(25)) * mpmath.sin(t), mpmath.cos(D(25))]
    d = [mpmath.sin(D(70)), 0, mpmath.cos(D(70))]
    ad = v_dot(a, d)
    cb, cc = mpmath.cos(D(75)), mpmath.cos(D(45))
    p, q = (cb - ad * cc) / (1 - ad * ad), (cc - ad * cb) / (1 - ad * ad)
    n = v_cross(a, d)
    base_ = [p * x + q * y for x, y in zip(a, d)]
    s = mpmath.sqrt((1 - v_dot(base_, base_)) / v_dot(n, n))
    return a, d, [x + s * y for x, y in zip(base_, n)]


def spherical_crank_rocker():
    """B(θ) from the two cones (spherical_b); the rocker's angle ψ about D measured from
    y toward D × y, so ω4 = ψ' D, α4 = ψ'' D (a fixed axis); the coupler turns about O, so
    from v_A = ω × A and v_B = ω × B: ω3 = (v_A × v_B)/(v_A · B). θ = 60°, ω = 2."""
    def pos(t):
        _, d, b = spherical_b(t)
        e2 = v_cross(d, [0, 1, 0])
        return [mpmath.atan2(v_dot(b, e2), b[1]), *b]

    t = math.radians(60)
    (_, *b), (w4, *vb), (al4, *ab) = motion(pos, t, 2)
    a, d, _ = spherical_b(mpmath.mpf(t))
    va = [float(x) for x in v_cross([0, 0, 2], a)]
    w3 = [x / v_dot(va, b) for x in v_cross(va, vb)]
    d = [float(x) for x in d]
    return [[w4 * x for x in d], [al4 * x for x in d], w3, vb, ab]


def _rssr_b(t):
    """B = D + 1.1 (0, cos ψ, sin ψ) at the drawn coupler length from A(t) = (cos t, sin t, 0):
    with w = D − A, |w|² + 1.1² + 2.2 (w_y cos ψ + w_z sin ψ) = b², so
    ψ = atan2(w_z, w_y) + acos(K/√(w_y² + w_z²)), K = (b² − |w|² − 1.21)/2.2 (the drawn root)."""
    dd = [mpmath.mpf("2.5"), mpmath.mpf("0.5"), mpmath.mpf("1.2")]
    c = mpmath.mpf("1.1")
    b0 = [dd[0], dd[1] + c * mpmath.cos(D(120)), dd[2] + c * mpmath.sin(D(120))]
    a0 = [mpmath.cos(D(45)), mpmath.sin(D(45)), 0]
    length2 = sum((x - y) ** 2 for x, y in zip(b0, a0))
    a = [mpmath.cos(t), mpmath.sin(t), 0]
    w = [x - y for x, y in zip(dd, a)]
    k = (length2 - v_dot(w, w) - c * c) / (2 * c)
    psi = mpmath.atan2(w[2], w[1]) + mpmath.acos(k / mpmath.sqrt(w[1] ** 2 + w[2] ** 2))
    return a, psi, [dd[0], dd[1] + c * mpmath.cos(psi), dd[2] + c * mpmath.sin(psi)]


def rssr_offset():
    """ψ(θ) closed form (_rssr_b, which reproduces ψ = 120° at 45°); ω4 = (ψ', 0, 0),
    α4 = (ψ'', 0, 0) with ω = 3 constant; the coupler without spin about AB:
    ω3 = AB × (v_B − v_A)/|AB|², so ω3 = 3 g(θ) with g = AB × (B' − A')/|AB|² (' = d/dθ) and
    α3 = 9 g'(θ); its screw axis through A + ω3 × v_A/|ω3|², sliding at v_A·ω̂3."""
    def g(t):
        a, _, b = _rssr_b(t)
        da = [mpmath.diff(lambda s, i=i: _rssr_b(s)[0][i], t) for i in range(3)]
        db = [mpmath.diff(lambda s, i=i: _rssr_b(s)[2][i], t) for i in range(3)]
        ab = [x - y for x, y in zip(b, a)]
        return [x / v_dot(ab, ab) for x in v_cross(ab, [x - y for x, y in zip(db, da)])]

    def pos(t):
        _, psi, b = _rssr_b(t)
        return [psi, *b]

    t = math.radians(45)
    _, (w4, *vb), (al4, *ab) = motion(pos, t, 3)
    with mpmath.workdps(40):
        g0 = g(mpmath.mpf(t))
        g1 = [mpmath.diff(lambda s, i=i: g(s)[i], mpmath.mpf(t)) for i in range(3)]
    w3 = [float(3 * x) for x in g0]
    # the screw axis: Q = A + ω × v_A/|ω|² has v_Q ∥ ω; the point nearest O is
    # Q − (Q·û)û; the slide v_A·û (u = ω/|ω|)
    a = [float(x) for x in _rssr_b(mpmath.mpf(t))[0]]
    va = [-3 * a[1], 3 * a[0], 0.0]
    size = math.sqrt(v_dot(w3, w3))
    u = [x / size for x in w3]
    q = [x + y / size ** 2 for x, y in zip(a, v_cross(w3, va))]
    p = [x - v_dot(q, u) * y for x, y in zip(q, u)]
    axis = {"point": p, "direction": u, "omega": size, "slide": v_dot(va, u)}
    return [[w4, 0.0, 0.0], [al4, 0.0, 0.0], vb, ab, w3, [float(9 * x) for x in g1], axis]


def _hooke(t):
    """The input's fork arm F = (0, cos t, sin t); the cross's other arm G = F × u/|F × u|
    (u the output axis); the output's angle φ = atan2(G·q, G·p) about u, p = (−sin β, cos β, 0),
    q = (0, 0, 1) (p × q = u)."""
    beta = D(25)
    u = [mpmath.cos(beta), mpmath.sin(beta), 0]
    f = [0, mpmath.cos(t), mpmath.sin(t)]
    g = v_cross(f, u)
    n = mpmath.sqrt(v_dot(g, g))
    g = [x / n for x in g]
    return u, g, mpmath.atan2(g[2], -mpmath.sin(beta) * g[0] + mpmath.cos(beta) * g[1])


def hooke_joint_60():
    """φ(θ) from _hooke: ω_out = φ' u, α_out = φ'' u (ω_in = 10 constant). The cross turns
    with the input about F and with the output about G: ω_c = ω_in x + λ F = φ' u + μ G;
    dotting with G (F·G = u·G = 0) gives μ = ω_in G_x, so ω_c = φ' u + ω_in G_x G and
    α_c = φ'' u + ω_in d/dt(G_x G)."""
    def pos(t):
        _, g, phi = _hooke(t)
        return [phi, *(g[0] * x for x in g)]

    t = math.radians(60)
    (_, *gg), (w, *dgg), (al, *_) = motion(pos, t, 10)
    u, g, _ = _hooke(mpmath.mpf(t))
    u, g = [float(x) for x in u], [float(x) for x in g]
    return [[w * x for x in u], [al * x for x in u], [w * x + 10 * y for x, y in zip(u, gg)],
            [al * x + 10 * y for x, y in zip(u, dgg)]]


# vehicles -----------------------------------------------------------------------------------
def tricycle_steering():
    """The rear wheels keep v_M along the chassis (u); F = M + L e: v_F = u e + ω L e⊥ must be
    v e(δ): u = v cos δ, ω = v sin δ/L for all t, so α = v cos δ δ'/L (v constant: the
    driver's acceleration along the wheel is 0); a_M = u' e + u ω e⊥ = (−v sin δ δ', u ω);
    the centre on the rear axle line at L/tan δ; v_RL = (u − ω s, 0); the front wheel turns
    at ω + δ'; RL moves along x (speed u − ω s > 0): its acceleration
    a_M + α k × (0, s) − ω² (0, s) split along x (tangential) and y (normal)."""
    v, big_l, s, d, dd = 3, 1.1, 0.45, math.radians(30), 0.4
    u, w = v * math.cos(d), v * math.sin(d) / big_l
    al = v * math.cos(d) * dd / big_l
    a_m = [-v * math.sin(d) * dd, u * w]
    a_rl = [a_m[0] - al * s, a_m[1] - w * w * s]          # a_M + α k × (0, s) − ω² (0, s)
    speed = u - w * s
    return [w, al, {"point": [0.0, big_l / math.tan(d)]}, [speed, 0.0], a_m, w + dd,
            {"speed": abs(speed), "tangent": [1.0, 0.0], "tangential": a_rl[0], "normal": abs(a_rl[1]),
             "tangential_vector": [a_rl[0], 0.0], "normal_vector": [0.0, a_rl[1]]}]


def forklift_rear_steer():
    """The front wheels keep v_M = u e; R = M − L e: v_R = u e − ω L e⊥ must lie along e(δ):
    ω = −u tan δ/L, α = −u δ'/(L cos² δ) (u constant); the centre on the front axle line at
    u/ω; v_R = (u, −ω L); a_R = a_M + α k × MR − ω² MR with a_M = (0, u ω), MR = (−L, 0)."""
    u, big_l, d, dd = 2, 1.4, math.radians(-25), -0.3
    w, al = -u * math.tan(d) / big_l, -u * dd / (big_l * math.cos(d) ** 2)
    return [w, al, {"point": [0.0, u / w]}, [u, -w * big_l], [w * w * big_l, u * w - al * big_l]]


NUMERIC = {f.__name__: f for f in (
    fb_crank_rocker_coupler, fb_crossed_icr, fb_non_grashof, fb_non_grashof_moved, fb_drag_link_moved,
    fb_parallelogram, sc_offset_above, sc_vertical_engine, sc_vertical_engine_moved, isc_oscillating_cylinder,
    isc_slotted_crank, qr_whitworth_opposite, qr_drag_link, geneva_four_slot, scotch_yoke, pin_slotted_rocker,
    watt_one, stephenson_slider, stephenson_triad, gear_compound_train, epicyclic_arm, planetary_two_inputs,
    rolling_hypocycloid, rolling_on_plank, rolling_wheel_rod, spherical_crank_rocker, rssr_offset, hooke_joint_60,
    tricycle_steering, forklift_rear_steer, rolling_on_drum, rack_and_pinion, fb_coupler_driven)}
SYMBOLIC = {f.__name__: f for f in (sc_offset_symbolic_theta, isc_oscillating_cylinder_symbolic, fb_parallelogram_letters,
                                     geneva_symbolic_theta, scotch_yoke_symbolic)}
ERRORS = {"fb_err_move_past_limit": "assembly", "fb_err_two_drivers": "mobility"}


def expected(name: str) -> dict:
    """The NAME.expect.json content of a case, from its derivation."""
    return base.expected_in(HERE, name, ERRORS, SYMBOLIC, NUMERIC, _floats)


def _floats(value):
    if isinstance(value, (list, tuple)):
        return [_floats(v) for v in value]
    if isinstance(value, dict):
        return {k: _floats(v) for k, v in value.items()}
    if isinstance(value, (mpmath.mpf, int)) and not isinstance(value, bool):
        return float(value)
    return value


CASES = sorted([*NUMERIC, *SYMBOLIC, *ERRORS])

if __name__ == "__main__":
    base.write_expectations(HERE, CASES, expected)
