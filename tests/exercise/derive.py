"""Hand derivations of the two exercise models, with the usual mistakes made by hand: the
independent values the exercise tests compare with (numpy solves 2×2 systems written here
from the notes' vector equations; nothing of kinematika is used).

P pair (examples/exercises/p_pair_coriolis.yaml): the guide M turns about A (ω, α), the block
N at B = s·u (u at β) slides on it, the rocker EB turns about E. With k× the quarter turn,

    ω_EB k×(B − E) = ω k×B + ṡ u                                    (velocities)
    α_EB k×(B − E) − n ω_EB² (B − E) = α k×B − n ω² B + s̈ u + c 2ω ṡ k×u   (accelerations)

with c = 1, n = 1 in mechanics (c = 0 or 2: the Coriolis term left out or doubled; n = 0:
the normal terms left out). Asked: ω_EB, α_EB, v_rel = ṡ u, a_rel = s̈ u, v_B, a_B.

Four-bar (examples/exercises/four_bar.yaml): A = a(cos θ, sin θ), O4 = (d, 0), B where the
circles (A, b) and (O4, c) meet, left of A→O4;

    ω2 k×A + ω3 k×(B − A) = ω4 k×(B − O4)
    −n ω2² A + α3 k×(B − A) − n ω3² (B − A) = α4 k×(B − O4) − n ω4² (B − O4)

Asked: ω3, ω4, α3, α4, v_B, a_B.
"""
from __future__ import annotations

import math

import numpy as np


def k(v):
    return np.array([-v[1], v[0]])


def p_pair(s, beta, ex, ey, w, al, c=1, n=1):
    """The six answers (q1 … q6) of the P pair, in SI units and radians."""
    u = np.array([math.cos(beta), math.sin(beta)])
    B, E = s * u, np.array([ex, ey])
    r = B - E
    m = np.column_stack([k(r), -u])
    w_eb, sd = np.linalg.solve(m, w * k(B))
    rhs = al * k(B) - n * w ** 2 * B + c * 2 * w * sd * k(u) + n * w_eb ** 2 * r
    a_eb, sdd = np.linalg.solve(m, rhs)
    return {"q1": w_eb, "q2": a_eb, "q3": sd * u, "q4": sdd * u, "q5": w_eb * k(r),
            "q6": a_eb * k(r) - n * w_eb ** 2 * r}


def p_pair_drag(s, beta, w, al):
    """The drag velocity and acceleration of B (the guide's point at B): q5 and q6 mistaken."""
    B = s * np.array([math.cos(beta), math.sin(beta)])
    return {"q5": w * k(B), "q6": al * k(B) - w ** 2 * B}


def four_bar(d, a, b, c, theta, w2, n=1):
    """The six answers of the four-bar, or None when it does not assemble."""
    A, O4 = a * np.array([math.cos(theta), math.sin(theta)]), np.array([d, 0.0])
    gap = O4 - A
    L = float(np.linalg.norm(gap))
    if not abs(b - c) < L < b + c:
        return None
    along = (b ** 2 - c ** 2 + L ** 2) / (2 * L)
    height = math.sqrt(b ** 2 - along ** 2)
    e = gap / L
    B = A + along * e + height * k(e)             # left of A→O4
    m = np.column_stack([k(B - A), -k(B - O4)])
    w3, w4 = np.linalg.solve(m, -w2 * k(A))
    rhs = n * w2 ** 2 * A + n * w3 ** 2 * (B - A) - n * w4 ** 2 * (B - O4)
    a3, a4 = np.linalg.solve(m, rhs)
    return {"q1": w3, "q2": w4, "q3": a3, "q4": a4, "q5": w4 * k(B - O4),
            "q6": a4 * k(B - O4) - n * w4 ** 2 * (B - O4)}


def rows(answers):
    """{'q1': x, 'q3': [x, y]} as key rows {'q1': x, 'q3.x': x, 'q3.y': y}, with each row's
    size (the vector's magnitude)."""
    out = {}
    for q, v in answers.items():
        v = np.atleast_1d(np.asarray(v, dtype=float))
        if v.size == 1:
            out[q] = (float(v[0]), abs(float(v[0])))
        else:
            size = float(np.linalg.norm(v))
            for axis, x in zip("xy", v):
                out[f"{q}.{axis}"] = (float(x), size)
    return out


def three_figures(x):
    """`x` (a number or an array) rounded to three significant figures, as a student writes
    an intermediate result."""
    def one(v):
        v = float(v)
        if v == 0 or not math.isfinite(v):
            return v
        return round(v, 2 - math.floor(math.log10(abs(v))))
    x = np.asarray(x, dtype=float)
    return np.vectorize(one)(x) if x.ndim else one(x)


def p_pair_by_hand(s, beta, ex, ey, w, al):
    """The P pair solved as a student does on paper: every intermediate (the guide's direction,
    B, B − E, each term of the equations, ω_EB, ṡ, α_EB, s̈) and each answer rounded to three
    significant figures before it is used."""
    R = three_figures
    u = R([math.cos(beta), math.sin(beta)])
    B, E = R(s * u), np.array([ex, ey])
    r = R(B - E)
    m = np.column_stack([k(r), -u])
    w_eb, sd = R(np.linalg.solve(m, R(w * k(B))))
    rhs = R(al * k(B)) - R(w ** 2 * B) + R(2 * w * sd * k(u)) + R(w_eb ** 2 * r)
    a_eb, sdd = R(np.linalg.solve(m, R(rhs)))
    return {"q1": w_eb, "q2": a_eb, "q3": R(sd * u), "q4": R(sdd * u), "q5": R(w_eb * k(r)),
            "q6": R(R(a_eb * k(r)) - R(w_eb ** 2 * r))}
