"""Model trees for the sweep tests, and their answers derived by hand (closed forms).

Every closed form here is written from the loop equations, independently of the code
under test: positions by circle intersection (four-bar) or by the slider-crank formula
x = r cos θ + √(l² − (r sin θ − e)²), rates by differentiating them by hand.
"""
from __future__ import annotations

import copy
import math

import numpy as np


def circle_meet(p, r1, q, r2, side):
    """The meeting point of the circle (p, r1) and (q, r2) on the left (+1) of p→q or right."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d2 = dx * dx + dy * dy
    f = (r1 * r1 - r2 * r2 + d2) / (2 * d2)
    h = side * math.sqrt(r1 * r1 / d2 - f * f)
    return (p[0] + f * dx - h * dy, p[1] + f * dy + h * dx)


def four_bar_tree(ground=4.0, crank=1.0, coupler=4.0, rocker=3.0, crank_deg=90.0, w=10.0, al=0.0,
                  point=(2.0, 1.0), side=1.0):
    """A four-bar O2-A-B-O4 with a coupler point P (`point[0]` along AB, `point[1]` to its left).

    B is drawn on the left (`side` +1) or the right (−1) of the line from A to O4.
    """
    a = (crank * math.cos(math.radians(crank_deg)), crank * math.sin(math.radians(crank_deg)))
    o4 = (ground, 0.0)
    b = circle_meet(a, coupler, o4, rocker, side)
    u = ((b[0] - a[0]) / coupler, (b[1] - a[1]) / coupler)
    p = (a[0] + point[0] * u[0] - point[1] * u[1], a[1] + point[0] * u[1] + point[1] * u[0])
    return {
        "name": "Four-bar",
        "points": {"O2": [0, 0], "A": list(a), "B": list(b), "O4": list(o4), "P": list(p)},
        "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B", "P"],
                   "rocker": ["B", "O4"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                   {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                   {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                   {"type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"}],
        "drivers": [{"omega": "crank", "value": w, "alpha": al}],
    }


def four_bar_closed_form(theta, ground, crank, coupler, rocker, side, w, al, point):
    """Loop closure at crank angles θ (radians, absolute): B, P, ω3, ω4, α3, α4 and v_P, a_P.

    Velocity: ω2 k×OA + ω3 k×AB = ω4 k×O4B (Cramer); acceleration likewise with the
    centripetal terms −ω² r moved to the right side.
    """
    theta = np.asarray(theta, dtype=float)
    ax, ay = crank * np.cos(theta), crank * np.sin(theta)
    dx, dy = ground - ax, -ay
    d2 = dx * dx + dy * dy
    f = (coupler ** 2 - rocker ** 2 + d2) / (2 * d2)
    h = side * np.sqrt(coupler ** 2 / d2 - f * f)
    bx, by = ax + f * dx - h * dy, ay + f * dy + h * dx
    r3 = (bx - ax, by - ay)
    r4 = (bx - ground, by)
    va = (-w * ay, w * ax)
    aa = (-al * ay - w * w * ax, al * ax - w * w * ay)
    # ω3 k×r3 − ω4 k×r4 = −v_A: columns (−r3y, r3x) and (r4y, −r4x)
    rx, ry = -va[0], -va[1]
    m11, m12, m21, m22 = -r3[1], r4[1], r3[0], -r4[0]
    det = m11 * m22 - m12 * m21
    w3 = (rx * m22 - m12 * ry) / det
    w4 = (m11 * ry - rx * m21) / det
    kx = -aa[0] + w3 ** 2 * r3[0] - w4 ** 2 * r4[0]
    ky = -aa[1] + w3 ** 2 * r3[1] - w4 ** 2 * r4[1]
    a3 = (kx * m22 - m12 * ky) / det
    a4 = (m11 * ky - kx * m21) / det
    ux, uy = r3[0] / coupler, r3[1] / coupler
    px, py = ax + point[0] * ux - point[1] * uy, ay + point[0] * uy + point[1] * ux
    qx, qy = px - ax, py - ay
    vp = (va[0] - w3 * qy, va[1] + w3 * qx)
    ap = (aa[0] - a3 * qy - w3 ** 2 * qx, aa[1] + a3 * qx - w3 ** 2 * qy)
    return {"B": (bx, by), "P": (px, py), "w3": w3, "w4": w4, "a3": a3, "a4": a4, "vP": vp, "aP": ap}


def slider_crank_tree(r=1.0, l=3.0, e=0.5, crank_deg=60.0, w=10.0, al=0.0):
    """Crank O-A (radius r), rod A-B (length l), slider B on the line y = e along x."""
    t = math.radians(crank_deg)
    a = (r * math.cos(t), r * math.sin(t))
    b = (a[0] + math.sqrt(l * l - (a[1] - e) ** 2), e)
    return {
        "name": "Slider-crank",
        "points": {"O": [0, 0], "A": list(a), "B": list(b)},
        "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                   {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
                   {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
                   {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
        "drivers": [{"omega": "crank", "value": w, "alpha": al}],
    }


def slider_crank_closed_form(theta, r, l, e, w):
    """x, ẋ, ẍ of the slider and φ, ω, α of the rod at crank angles θ (constant ω)."""
    theta = np.asarray(theta, dtype=float)
    s, s1, s2 = r * np.sin(theta) - e, r * np.cos(theta), -r * np.sin(theta)
    g = np.sqrt(l * l - s * s)
    x = r * np.cos(theta) + g
    x1 = -r * np.sin(theta) - s * s1 / g
    x2 = -r * np.cos(theta) - (s1 * s1 + s * s2) / g - (s * s1) ** 2 / g ** 3
    phi = np.arctan2(-s, g)
    phi1 = -s1 / g
    phi2 = -s2 / g - s * s1 * s1 / g ** 3
    return {"x": x, "v": x1 * w, "a": x2 * w * w, "phi": phi, "w": phi1 * w, "al": phi2 * w * w}


def copy_tree(tree: dict, **changes) -> dict:
    out = copy.deepcopy(tree)
    out.update(copy.deepcopy(changes))
    return out


def rocker_driven_tree(ground=4.0, crank=1.0, coupler=4.0, rocker=3.0, rocker_deg=120.0, w=1.0,
                       side=1.0):
    """A four-bar O2-A-B-O4 driven from its rocker O4B (drawn at `rocker_deg`, absolute), A on
    the left (`side` +1) or the right of the line from O2 to B."""
    b = (ground + rocker * math.cos(math.radians(rocker_deg)), rocker * math.sin(math.radians(rocker_deg)))
    a = circle_meet((0.0, 0.0), crank, b, coupler, side)
    return {"name": "Rocker-driven four-bar",
            "points": {"O2": [0, 0], "A": list(a), "B": list(b), "O4": [ground, 0]},
            "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B"],
                       "rocker": ["B", "O4"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                       {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                       {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                       {"type": "revolute", "bodies": ["ground", "rocker"], "at": "O4"}],
            "drivers": [{"omega": "rocker", "value": w}]}
