"""Models for the figure tests and their motion derived by hand, in closed form.

Positions are complex numbers z = x + iy. For a body turning at ω, α, a point P relative
to a point Q of the same body moves as v_P = v_Q + iω (P − Q) and
a_P = a_Q + (iα − ω²)(P − Q). The four-bar's ω3, ω4 (α3, α4) follow from the loop
A + (B − A) = O4 + (B − O4) differentiated, solved by cross products
(x × y = Im(conj(x) y)); the slider-crank's slider speed is the time derivative of
x_B = r cos θ + sqrt(L² − r² sin² θ).
"""
from __future__ import annotations

import copy
import math

# four-bar: crank O2A (1), coupler ABP (ternary), rocker O4B; ICR of the coupler nearby
O2, A, B, O4 = 0j, 1 + 1j, 3 + 1.5j, 3.5 + 0j
P = A + 0.5 * (B - A) + 0.6j * (B - A)          # coupler point off the line AB
W2, AL2 = 10.0, 4.0


def xy(z: complex) -> list[float]:
    return [z.real, z.imag]


def cross(x: complex, y: complex) -> float:
    return (x.conjugate() * y).imag


def four_bar_tree(ask: list | None = None, **points: complex) -> dict:
    """The four-bar as a model tree; `points` adds points to the crank (name=position)."""
    extra = {name: xy(z) for name, z in points.items()}
    return {
        "name": "Test four-bar",
        "parameters": {"w2": W2, "al2": AL2},
        "points": {"O2": xy(O2), "A": xy(A), "B": xy(B), "O4": xy(O4), "P": xy(P), **extra},
        "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A", *extra],
                   "coupler": ["A", "B", "P"], "rocker": ["B", "O4"]},
        "joints": [
            {"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
            {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
            {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
            {"type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"},
        ],
        "drivers": [{"omega": "crank", "value": "w2", "alpha": "al2"}],
        "ask": copy.deepcopy(ask) if ask is not None else [{"velocity": "B"}],
    }


def four_bar_rates() -> tuple[float, float, float, float]:
    """ω3, ω4, α3, α4 of coupler and rocker."""
    a, c, b = A - O2, B - A, B - O4
    w3 = -W2 * cross(a, b) / cross(c, b)
    w4 = W2 * cross(a, c) / cross(b, c)
    rhs = -((1j * AL2 - W2 ** 2) * a - w3 ** 2 * c + w4 ** 2 * b)   # α3 (ic) − α4 (ib) = rhs
    ic, ib = 1j * c, 1j * b
    a3 = cross(rhs, ib) / cross(ic, ib)
    a4 = -cross(rhs, ic) / cross(ib, ic)
    return w3, w4, a3, a4


def four_bar_motion(point: str) -> tuple[complex, complex]:
    """(velocity, acceleration) of A, B, P (coupler) or a crank point, as complex numbers."""
    w3, w4, a3, a4 = four_bar_rates()
    v_a, a_a = 1j * W2 * (A - O2), (1j * AL2 - W2 ** 2) * (A - O2)
    if point == "A":
        return v_a, a_a
    if point == "B":
        return 1j * w4 * (B - O4), (1j * a4 - w4 ** 2) * (B - O4)
    if point == "P":
        return v_a + 1j * w3 * (P - A), a_a + (1j * a3 - w3 ** 2) * (P - A)
    raise KeyError(point)


def coupler_icr() -> complex:
    """Where the lines O2A and O4B meet (the velocities of A and B are normal to them)."""
    d1, d2 = A - O2, B - O4
    t = cross(O4 - O2, d2) / cross(d1, d2)
    return O2 + t * d1


def line_meet(p1: complex, q1: complex, p2: complex, q2: complex) -> complex:
    d1, d2 = q1 - p1, q2 - p2
    return p1 + cross(p2 - p1, d2) / cross(d1, d2) * d1


# slider-crank: crank r at θ, rod L, slider on the x axis
R, L, THETA, W = 0.1, 0.3, math.radians(50), 12.0


def slider_position() -> float:
    """x_B, also the mechanism's extent (O to B is its larger side)."""
    return R * math.cos(THETA) + math.sqrt(L ** 2 - (R * math.sin(THETA)) ** 2)


def slider_crank_tree() -> dict:
    a = (R * math.cos(THETA), R * math.sin(THETA))
    xb = slider_position()
    return {
        "name": "Test slider-crank",
        "parameters": {"w": W},
        "points": {"O": [0, 0], "A": list(a), "B": [xb, 0]},
        "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
        "joints": [
            {"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
            {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
            {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
            {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]},
        ],
        "drivers": [{"omega": "crank", "value": "w", "alpha": 0}],
        "ask": [{"velocity": "A"}, {"velocity": "B"}],
    }


def slider_speed() -> float:
    """dx_B/dt = −r ω sin θ − r² ω sin θ cos θ / sqrt(L² − r² sin² θ)."""
    s, c = math.sin(THETA), math.cos(THETA)
    return -R * W * s - R ** 2 * W * s * c / math.sqrt(L ** 2 - (R * s) ** 2)
