"""Independent derivations of the textbook cases in this folder (tb_*.yaml).

Each function solves one case as the textbook would, by hand trigonometry, and returns
the answers in the order the case asks them, in the contract's JSON shapes. Nothing here
calls kinematika. The four-bars follow Norton (Design of Machinery, eqs. 4.10-4.13 for
Freudenstein's solution, 6.18 and 7.12 for the rates, 6.36 and 7.32 for a coupler point);
the others write the position of the output as a function of the crank angle (loop
closure) and differentiate it in time: d/dt = ω d/dθ and d²/dt² = ω² d²/dθ² + α d/dθ,
with the derivatives taken by mpmath at 40 digits. The symbolic cases give formulas
derived by hand (see their docstrings).

`python tests/cases/derive.py` rewrites each case's NAME.expect.json from these
derivations; tests/model/test_cases.py checks that the files hold exactly these values.
"""
from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Callable

import mpmath

HERE = Path(__file__).resolve().parent
Vec = list


# hand geometry ----------------------------------------------------------------------------
def meet(p, rp, q, rq, side):
    """Where the circles (p, rp) and (q, rq) meet, left (side = +1) or right of p→q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = mpmath.sqrt(dx ** 2 + dy ** 2)
    a = (rp ** 2 - rq ** 2 + d ** 2) / (2 * d)
    h = mpmath.sqrt(rp ** 2 - a ** 2)
    return [p[0] + a * dx / d - side * h * dy / d, p[1] + a * dy / d + side * h * dx / d]


def polar(p, r, angle):
    return [p[0] + r * mpmath.cos(angle), p[1] + r * mpmath.sin(angle)]


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def turn(w, r):
    """ω k × r."""
    return [-w * r[1], w * r[0]]


def motion(position: Callable, theta: float, w: float, al: float = 0.0):
    """Value, velocity, acceleration of `position`(crank angle) (a list of numbers) when
    the crank is at `theta` radians, turning at w and accelerating at al."""
    with mpmath.workdps(40):
        t0 = mpmath.mpf(theta)
        value = position(t0)
        n = len(value)
        d1 = [mpmath.diff(lambda t, i=i: position(t)[i], t0, 1) for i in range(n)]
        d2 = [mpmath.diff(lambda t, i=i: position(t)[i], t0, 2) for i in range(n)]
        vel = [w * x for x in d1]
        acc = [w * w * y + al * x for x, y in zip(d1, d2)]
        return [float(x) for x in value], [float(x) for x in vel], [float(x) for x in acc]


def curvature(p, v, a):
    """Radius |v|³/|v × a| and centre P + |v|²/(v × a) k × v of a path."""
    vxa = cross(v, a)
    vv = v[0] ** 2 + v[1] ** 2
    return {"radius": vv ** 1.5 / abs(vxa),
            "center": [p[0] - vv / vxa * v[1], p[1] + vv / vxa * v[0]]}


def line_meet(p, d1, q, d2):
    """Where p + s d1 and q + u d2 cross (Cramer's rule)."""
    det = d1[0] * (-d2[1]) - d1[1] * (-d2[0])
    s = ((q[0] - p[0]) * (-d2[1]) - (q[1] - p[1]) * (-d2[0])) / det
    return [p[0] + s * d1[0], p[1] + s * d1[1]]


# Norton's four-bar --------------------------------------------------------------------------
def freudenstein(a, b, c, d, t2, open_circuit=True):
    """θ3, θ4 measured from the ground link (Norton eqs. 4.10-4.13)."""
    k1, k2, k3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    k4, k5 = d / b, (c * c - d * d - a * a - b * b) / (2 * a * b)
    aa = math.cos(t2) - k1 - k2 * math.cos(t2) + k3
    bb = -2 * math.sin(t2)
    cc = k1 - (k2 + 1) * math.cos(t2) + k3
    dd = math.cos(t2) - k1 + k4 * math.cos(t2) + k5
    ee = -2 * math.sin(t2)
    ff = k1 + (k4 - 1) * math.cos(t2) + k5
    s = -1 if open_circuit else 1
    t4 = 2 * math.atan2(-bb + s * math.sqrt(bb * bb - 4 * aa * cc), 2 * aa)
    t3 = 2 * math.atan2(-ee + s * math.sqrt(ee * ee - 4 * dd * ff), 2 * dd)
    return t3, t4


def norton_rates(a, b, c, t2, t3, t4, w2, al2):
    """ω3, ω4, α3, α4 (Norton eqs. 6.18 and 7.12); angles from the ground link."""
    w3 = a * w2 / b * math.sin(t4 - t2) / math.sin(t3 - t4)
    w4 = a * w2 / c * math.sin(t2 - t3) / math.sin(t4 - t3)
    big_a, big_b = c * math.sin(t4), b * math.sin(t3)
    big_c = (a * al2 * math.sin(t2) + a * w2 ** 2 * math.cos(t2) + b * w3 ** 2 * math.cos(t3)
             - c * w4 ** 2 * math.cos(t4))
    big_d, big_e = c * math.cos(t4), b * math.cos(t3)
    big_f = (a * al2 * math.cos(t2) - a * w2 ** 2 * math.sin(t2) - b * w3 ** 2 * math.sin(t3)
             + c * w4 ** 2 * math.sin(t4))
    al3 = (big_c * big_d - big_a * big_f) / (big_a * big_e - big_b * big_d)
    al4 = (big_c * big_e - big_b * big_f) / (big_a * big_e - big_b * big_d)
    return w3, w4, al3, al4


def rotate(v, angle):
    c, s = math.cos(angle), math.sin(angle)
    return [c * v[0] - s * v[1], s * v[0] + c * v[1]]


def inclined_four_bar(open_circuit: bool):
    """a 2, b 6.5, c 5.5, d 7; ground at 10°; θ2 = 40° from the ground; ω2 = −15, α2 = 25.
    The open circuit (Norton's −√ root) has B left of A→O4, the crossed one right."""
    a, b, c, d, tilt, t2, w2, al2 = 2, 6.5, 5.5, 7, math.radians(10), math.radians(40), -15, 25
    t3, t4 = freudenstein(a, b, c, d, t2, open_circuit)
    w3, w4, al3, al4 = norton_rates(a, b, c, t2, t3, t4, w2, al2)
    # the rocker O4B in ground axes: the ground frame turned by the tilt
    r = rotate([c * math.cos(t4), c * math.sin(t4)], tilt)
    v_b = turn(w4, r)
    a_b = [x - w4 ** 2 * y for x, y in zip(turn(al4, r), r)]
    # which side of A→O4 is B (to check the circuit the file names)
    o4, pa = rotate([d, 0], tilt), rotate([a * math.cos(t2), a * math.sin(t2)], tilt)
    side = cross([o4[0] - pa[0], o4[1] - pa[1]], [o4[0] + r[0] - pa[0], o4[1] + r[1] - pa[1]])
    return [w3, w4, al3, al4, v_b, a_b], side, [o4[0] + r[0], o4[1] + r[1]]


def tb_fourbar_inclined_ground():
    """Freudenstein's equation in the ground link's frame (θ2 = 40° from it), the open
    root (−√, B left of A→O4); ω, α by Norton 6.18 and 7.12; v_B = ω4 k × O4B and
    a_B = α4 k × O4B − ω4² O4B with O4B turned by the ground's 10°."""
    answers, side, _ = inclined_four_bar(open_circuit=True)
    assert side > 0                                  # left of A→O4, as the file says
    return answers


def tb_fourbar_crossed_near():
    """As the inclined four-bar, on the crossed root (+√, B right of A→O4), which is the
    intersection nearer the sketch point (4, −4)."""
    answers, side, b = inclined_four_bar(open_circuit=False)
    assert side < 0
    _, _, open_b = inclined_four_bar(open_circuit=True)
    sketch = (4, -4)                                 # the file's `near`: nearer the crossed B
    assert math.dist(sketch, b) < math.dist(sketch, open_b)
    return answers[:4]


def tb_fourbar_coupler_point(theta2: float = 120):
    """Freudenstein (open), Norton 6.18/7.12; the coupler point by Norton 6.36/7.32:
    V_P = V_A + p ω3 (−sin(θ3 + δ3), cos(θ3 + δ3)), A_P = A_A + p α3 (...) − p ω3² (...);
    the coupler's instant centre where the lines O2A and O4B meet; the curvature of P's path
    from v and a (radius |v|³/|v × a|)."""
    a, b, c, d, p, delta, t2, w2 = 3, 7.5, 8, 9, 4, math.radians(30), math.radians(theta2), 10
    t3, t4 = freudenstein(a, b, c, d, t2)
    w3, w4, al3, al4 = norton_rates(a, b, c, t2, t3, t4, w2, 0)
    pa = [a * math.cos(t2), a * math.sin(t2)]
    e = [math.cos(t3 + delta), math.sin(t3 + delta)]
    pp = [pa[0] + p * e[0], pa[1] + p * e[1]]
    v_a, a_a = turn(w2, pa), [-w2 ** 2 * pa[0], -w2 ** 2 * pa[1]]
    v_p = [x + p * w3 * y for x, y in zip(v_a, [-e[1], e[0]])]                 # Norton 6.36
    a_p = [x + p * al3 * y - p * w3 ** 2 * z for x, y, z in zip(a_a, [-e[1], e[0]], e)]   # 7.32
    # the coupler's centre: on the crank line O2A and on the rocker line O4B
    icr = line_meet([0, 0], pa, [d, 0], [math.cos(t4), math.sin(t4)])
    return [v_p, a_p, {"point": icr}, curvature(pp, v_p, a_p)]


def tb_fourbar_moved():
    """The coupler-point four-bar at 120° + 45° = 165°: a Grashof crank-rocker stays on its
    (open) circuit over the whole turn, so the moved configuration is Freudenstein's open
    root at 165°, and everything as for the coupler point there."""
    return tb_fourbar_coupler_point(120 + 45)


def tb_slider_crank_offset():
    """Crank 40 at 135°, rod 120, slider line y = −20; ω2 = 200, α2 = −50.
    x_B = a cos θ + √(b² − (a sin θ + 20)²); the rod's angle atan2(−20 − a sin θ, x_B − a cos θ)."""
    a, b, e = 40, 120, -20

    def pos(t):
        s = a * mpmath.sin(t) - e
        root = mpmath.sqrt(b ** 2 - s ** 2)
        return [a * mpmath.cos(t) + root, mpmath.atan2(-s, root)]

    _, vel, acc = motion(pos, math.radians(135), 200, -50)
    return [[vel[0], 0.0], [acc[0], 0.0], vel[1], acc[1]]


def tb_inverted_slider_crank():
    """Crank 50 at 70°, pivot O4 at (120, 0): the rod's angle φ = atan2(A − O4) and the
    block's distance ρ = |A − O4|; seen from the rod the block moves ρ' and ρ'' along it."""
    def pos(t):
        ax, ay = 50 * mpmath.cos(t) - 120, 50 * mpmath.sin(t)
        return [mpmath.atan2(ay, ax), mpmath.sqrt(ax ** 2 + ay ** 2)]

    (phi, _), (w4, rho_d), (al4, rho_dd) = motion(pos, math.radians(70), 8)
    u = [math.cos(phi), math.sin(phi)]
    return [w4, al4, [rho_d * u[0], rho_d * u[1]], [rho_dd * u[0], rho_dd * u[1]]]


def tb_whitworth():
    """Crank 0.2 about O2 = (0, 0), slotted link about O4 = (0, −0.1) through A, B 0.15
    beyond O4, rod 0.45 to the ram on y = −0.1: φ = atan2(A − O4),
    B = O4 − 0.15 (cos φ, sin φ), x_C = x_B + √(0.45² − (y_B + 0.1)²)."""
    def pos(t):
        phi = mpmath.atan2(0.2 * mpmath.sin(t) + mpmath.mpf("0.1"), 0.2 * mpmath.cos(t))
        bx, by = -mpmath.mpf("0.15") * mpmath.cos(phi), -mpmath.mpf("0.15") * mpmath.sin(phi)
        return [bx + mpmath.sqrt(mpmath.mpf("0.45") ** 2 - by ** 2), phi]

    _, (vc, w4), (ac, al4) = motion(pos, math.radians(60), 5)
    return [[vc, 0.0], [ac, 0.0], w4, al4]


def tb_crank_shaper():
    """Crank 0.12 about O2 = (0, 0.35), lever 0.75 about O4 = (0, 0) through A: φ =
    atan2(A); the ram follows x_B = 0.75 cos φ; B slides in the ram's vertical slot at
    y_B' (its velocity relative to the translating ram)."""
    r, c, big_l = mpmath.mpf("0.12"), mpmath.mpf("0.35"), mpmath.mpf("0.75")

    def pos(t):
        phi = mpmath.atan2(c + r * mpmath.sin(t), r * mpmath.cos(t))
        return [big_l * mpmath.cos(phi), big_l * mpmath.sin(phi), phi]

    _, (vx, vy, w4), (ax, _, al4) = motion(pos, math.radians(225), 6)
    return [[vx, 0.0], [ax, 0.0], w4, al4, [0.0, vy]]


def tb_watt_six_bar():
    """Loop 1 (O2, O4 = (5, 0); 1.5, 5, 3.5) gives the rocker's angle; C is 2.5 from O4 at
    −110° from O4B; loop 2 closes C-D-O6 (4.5, 3) with O6 = (9, 1.5)."""
    o4, o6 = [5, 0], [9, mpmath.mpf("1.5")]

    def pos(t):
        b = meet(polar([0, 0], mpmath.mpf("1.5"), t), 5, o4, mpmath.mpf("3.5"), 1)
        phi4 = mpmath.atan2(b[1] - o4[1], b[0] - o4[0])
        cc = polar(o4, mpmath.mpf("2.5"), phi4 - mpmath.radians(110))
        dd = meet(cc, mpmath.mpf("4.5"), o6, 3, 1)
        return [mpmath.atan2(dd[1] - o6[1], dd[0] - o6[0]), dd[0], dd[1]]

    _, (w6, vx, vy), (al6, _, _) = motion(pos, math.radians(60), 12)
    return [w6, al6, [vx, vy]]


def tb_stephenson_six_bar():
    """Four-bar (O2, O4 = (4, 0); 1.2, 4, 3) with P = A + 2 u + 1.5 n (u along AB, n to its
    left); the dyad P-E-O6 (3.5, 2.5) with O6 = (5.5, 5); ω2 = 10, α2 = 4."""
    o6 = [mpmath.mpf("5.5"), 5]

    def pos(t):
        a = polar([0, 0], mpmath.mpf("1.2"), t)
        b = meet(a, 4, [4, 0], 3, 1)
        u = [(b[0] - a[0]) / 4, (b[1] - a[1]) / 4]
        p = [a[0] + 2 * u[0] - mpmath.mpf("1.5") * u[1], a[1] + 2 * u[1] + mpmath.mpf("1.5") * u[0]]
        e = meet(p, mpmath.mpf("3.5"), o6, mpmath.mpf("2.5"), 1)
        return [mpmath.atan2(e[1] - o6[1], e[0] - o6[0]), e[0], e[1]]

    _, (w6, vx, vy), (al6, ax, ay) = motion(pos, math.radians(30), 10, 4)
    return [w6, al6, [vx, vy], [ax, ay]]


NUMERIC = {f.__name__: f for f in (
    tb_fourbar_inclined_ground, tb_fourbar_crossed_near, tb_fourbar_coupler_point, tb_fourbar_moved,
    tb_slider_crank_offset, tb_inverted_slider_crank, tb_whitworth, tb_crank_shaper,
    tb_watt_six_bar, tb_stephenson_six_bar)}


# symbolic cases: formulas derived by hand -----------------------------------------------------
def four_bar_rates_formula(a, b, c, d):
    """ω3, ω4 of a four-bar at a general θ (crank ω = w), open circuit (B left of A→O4).

    With u = O4 − A, e = |u|² = a² + d² − 2ad cos θ, k = b² − c² + e, D = 4b²e − k²:
    B − A = (k u + √D J u)/(2e) (J: +90°). From v_B = v_A + ω3 J(B − A) = ω4 J(B − O4),
    dotting with B − A and B − O4 and using (B − A) × u = −√D/2, v_A·u = −w a d sin θ,
    v_A·Ju = w a (d cos θ − a):
      ω4 = w a (k d sin θ − √D (d cos θ − a)) / (e √D)
      ω3 = w a ((k − 2e) d sin θ − √D (d cos θ − a)) / (e √D)."""
    e = f"({a**2 + d**2} - {2*a*d}*cos(theta))"
    k = f"({b**2 - c**2} + {e})"
    root = f"sqrt({4*b**2}*{e} - {k}**2)"
    w4 = f"w*{a}*({k}*{d}*sin(theta) - {root}*({d}*cos(theta) - {a}))/({e}*{root})"
    w3 = f"w*{a}*(({k} - 2*{e})*{d}*sin(theta) - {root}*({d}*cos(theta) - {a}))/({e}*{root})"
    return w3, w4


def tb_fourbar_symbolic_theta():
    return list(four_bar_rates_formula(2, 7, 9, 6))


def tb_crank_shaper_symbolic_theta():
    """Crank r = 3 about O2 = (0, c = 7), lever about O4 through A = (r cos θ, c + r sin θ):
    tan φ = (c + r sin θ)/(r cos θ), ρ² = r² + c² + 2rc sin θ, so φ' = r (r + c sin θ)/ρ²
    (differentiate atan); the ram follows x_B = L cos φ = L r cos θ/ρ with L = 12, so
    v = −L sin φ φ' w = −L (c + r sin θ) r (r + c sin θ) w / ρ³."""
    rho2 = "(58 + 42*sin(theta))"
    return [f"3*w*(3 + 7*sin(theta))/{rho2}",
            [f"-12*(7 + 3*sin(theta))*3*(3 + 7*sin(theta))*w/{rho2}**(3/2)", "0"]]


def tb_slider_crank_symbolic_lengths():
    """x_B = r cos θ + R, R = √(l² − r² sin² θ), θ = 60° turning at w: differentiating,
    v = −r w sin θ − r² w sin θ cos θ / R,
    a = −r w² cos θ − r² w² cos 2θ / R − r⁴ w² sin² θ cos² θ / R³;
    the rod's angle φ has l sin φ = −r sin θ, so ω = −r w cos θ / R.
    At 60°: sin = √3/2, cos = 1/2, cos 2θ = −1/2, R = √(l² − 3r²/4)."""
    root = "sqrt(l**2 - 3*r**2/4)"
    v = f"-sqrt(3)/2*r*w - sqrt(3)/4*r**2*w/{root}"
    acc = f"-r*w**2/2 + r**2*w**2/(2*{root}) - 3*r**4*w**2/(16*{root}**3)"
    return [[v, "0"], [acc, "0"], f"-r*w/(2*{root})"]


SYMBOLIC = {f.__name__: f for f in (tb_fourbar_symbolic_theta, tb_crank_shaper_symbolic_theta,
                                    tb_slider_crank_symbolic_lengths)}

ERRORS = {"tb_err_no_side": "geometry", "tb_err_circles_apart": "geometry", "tb_err_circle_inside": "geometry", "tb_err_cycle": "schema",
          "tb_err_near_symbolic": "schema", "tb_err_unknown_point": "schema",
          "tb_err_toggle_singular": "singular", "tb_err_parallel_lines": "geometry",
          "tb_err_rod_too_short": "geometry"}


def expected(name: str) -> dict:
    """The NAME.expect.json content of a case, from its derivation."""
    return expected_in(HERE, name, ERRORS, SYMBOLIC, NUMERIC)


def expected_in(folder: Path, name: str, errors: dict, symbolic: dict, numeric: dict,
                numbers: Callable = lambda answers: answers) -> dict:
    """The NAME.expect.json content of a case in `folder`: its error kind, or the answers of
    its symbolic or numeric derivation (`numbers` turns those into JSON numbers)."""
    source = _first_comment(folder / f"{name}.yaml")
    if name in errors:
        return {"source": source, "error": errors[name]}
    if name in symbolic:
        fn = symbolic[name]
        return {"source": f"{source} Derived by hand: {_docstring(fn)}", "symbolic": True,
                "assume_positive": True, "answers": fn()}
    fn = numeric[name]
    return {"source": f"{source} Derived by hand: {_docstring(fn)}", "symbolic": False,
            "tolerance": 1e-9, "abs": 1e-9, "answers": numbers(fn())}


def _docstring(fn) -> str:
    return " ".join((fn.__doc__ or "").split())


def _first_comment(path: Path) -> str:
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith("#"):
            break
        lines.append(line.lstrip("# ").rstrip())
    return " ".join(lines)


CASES = sorted([*NUMERIC, *SYMBOLIC, *ERRORS])

def write_expectations(folder: Path, cases: list[str], expected: Callable[[str], dict]) -> None:
    """Write every case's NAME.expect.json in `folder` from its derivation."""
    for case in cases:
        (folder / f"{case}.expect.json").write_text(json.dumps(expected(case), indent=1, ensure_ascii=False)
                                                    + "\n", encoding="utf-8")
        print("wrote", case)


if __name__ == "__main__":
    write_expectations(HERE, CASES, expected)
