"""Random planar linkages for the property tests, assembled here by circle intersection.

Each strategy draws link lengths, an input angle and the input's rate and acceleration,
closes the loop in the test (never with kinematika) and returns a model tree; draws that
cannot be assembled, or sit near a dead point, are rejected with `assume`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from hypothesis import assume
from hypothesis import strategies as st

lengths = st.floats(0.3, 5.0)
angles = st.floats(0.0, 2 * math.pi)
rates = st.floats(-20.0, 20.0).filter(lambda w: abs(w) > 0.05)
accels = st.floats(-50.0, 50.0)


@dataclass
class Drawn:
    """A model tree and what the test knows of it by construction."""

    tree: dict
    points: dict[str, tuple[float, float]]
    rate: float
    accel: float
    extra: dict = field(default_factory=dict)


def circle_meet(p, rp, q, rq, side):
    """Intersection of circles (p, rp) and (q, rq), left (side=+1) or right of p→q; None if
    they miss or cross at a grazing angle (a dead point of the linkage)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = math.hypot(dx, dy)
    if d < 1e-3 or d > rp + rq or d < abs(rp - rq):
        return None
    a = (rp ** 2 - rq ** 2 + d ** 2) / (2 * d)
    h = math.sqrt(max(rp ** 2 - a ** 2, 0.0))
    if h < 0.05 * min(rp, rq):
        return None
    return (p[0] + (a * dx - side * h * dy) / d, p[1] + (a * dy + side * h * dx) / d)


def revolute(a: str, b: str, at: str) -> dict:
    return {"type": "revolute", "bodies": [a, b], "at": at}


@st.composite
def four_bars(draw) -> Drawn:
    ground, crank, coupler, rocker = draw(lengths), draw(lengths), draw(lengths), draw(lengths)
    theta, side = draw(angles), draw(st.sampled_from([1, -1]))
    w, al = draw(rates), draw(accels)
    a = (crank * math.cos(theta), crank * math.sin(theta))
    b = circle_meet(a, coupler, (ground, 0.0), rocker, side)
    assume(b is not None)
    points = {"O2": (0.0, 0.0), "A": a, "B": b, "O4": (ground, 0.0),
              "M": ((a[0] + b[0]) / 2 + 0.3, (a[1] + b[1]) / 2 - 0.2)}   # a coupler point off AB
    tree = {
        "points": {k: list(v) for k, v in points.items()},
        "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B", "M"],
                   "rocker": ["B", "O4"]},
        "joints": [revolute("ground", "crank", "O2"), revolute("crank", "coupler", "A"),
                   revolute("coupler", "rocker", "B"), revolute("rocker", "ground", "O4")],
        "drivers": [{"omega": "crank", "value": w, "alpha": al}],
    }
    return Drawn(tree, points, w, al)


@st.composite
def slider_cranks(draw) -> Drawn:
    crank, theta = draw(st.floats(0.05, 1.0)), draw(angles)
    rod = crank * draw(st.floats(1.2, 5.0))
    offset = draw(st.floats(-0.5, 0.5)) * rod
    w, al = draw(rates), draw(accels)
    a = (crank * math.cos(theta), crank * math.sin(theta))
    rise = offset - a[1]
    assume(abs(rise) < 0.95 * rod)
    b = (a[0] + math.sqrt(rod ** 2 - rise ** 2), offset)
    points = {"O": (0.0, 0.0), "A": a, "B": b}
    tree = {
        "points": {k: list(v) for k, v in points.items()},
        "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
        "joints": [revolute("ground", "crank", "O"), revolute("crank", "rod", "A"),
                   revolute("rod", "slider", "B"),
                   {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
        "drivers": [{"omega": "crank", "value": w, "alpha": al}],
    }
    return Drawn(tree, points, w, al, {"guide": (1.0, 0.0)})


@st.composite
def inverted_slider_cranks(draw) -> Drawn:
    """A block pinned to the crank at A slides on a rod turning about O4 (a rotating guide)."""
    crank, theta = draw(st.floats(0.05, 1.0)), draw(angles)
    d = draw(st.floats(0.1, 3.0)) * draw(st.sampled_from([1, -1]))
    w, al = draw(rates), draw(accels)
    a = (crank * math.cos(theta), crank * math.sin(theta))
    assume(math.hypot(a[0] - d, a[1]) > 0.05)
    points = {"O2": (0.0, 0.0), "O4": (d, 0.0), "A": a}
    tree = {
        "points": {k: list(v) for k, v in points.items()},
        "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "block": ["A"], "rod": ["O4", "A"]},
        "joints": [revolute("ground", "crank", "O2"), revolute("crank", "block", "A"),
                   revolute("ground", "rod", "O4"),
                   {"type": "prismatic", "bodies": ["rod", "block"], "along": ["O4", "A"]}],
        "drivers": [{"omega": "crank", "value": w, "alpha": al}],
    }
    return Drawn(tree, points, w, al)


linkages = st.one_of(four_bars(), slider_cranks(), inverted_slider_cranks())


# plain planar vector algebra, written here so that the checks do not use kinematika's own
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def add(*vs):
    return (sum(v[0] for v in vs), sum(v[1] for v in vs))


def times(k, a):
    return (k * a[0], k * a[1])


def kcross(w, r):
    """w k × r."""
    return (-w * r[1], w * r[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def unit(a):
    n = math.hypot(*a)
    return (a[0] / n, a[1] / n)


def near(got, expected, scale: float) -> bool:
    """Equal within 1e-8 of `scale` (the size of the quantities compared)."""
    got = got if isinstance(got, tuple) else (got,)
    expected = expected if isinstance(expected, tuple) else (expected,)
    return all(abs(float(g) - float(e)) <= 1e-8 * scale for g, e in zip(got, expected))


def solve2(c1, c2, rhs):
    """x, y with x c1 + y c2 = rhs (Cramer)."""
    det = c1[0] * c2[1] - c1[1] * c2[0]
    return ((rhs[0] * c2[1] - rhs[1] * c2[0]) / det, (c1[0] * rhs[1] - c1[1] * rhs[0]) / det)


def loop_closure(m: Drawn) -> dict[str, float]:
    """Angular velocities and accelerations from the loop equation differentiated by hand."""
    p, w2, al2 = m.points, m.rate, m.accel
    if "O4" in p and "B" in p:           # four-bar: O2A + AB = O2O4 + O4B
        oa, ab, o4b = p["A"], sub(p["B"], p["A"]), sub(p["B"], p["O4"])
        w3, w4 = solve2(kcross(1, ab), times(-1, kcross(1, o4b)), times(-1, kcross(w2, oa)))
        known = add(times(-1, kcross(al2, oa)), times(w2 ** 2, oa), times(w3 ** 2, ab),
                    times(-w4 ** 2, o4b))
        a3, a4 = solve2(kcross(1, ab), times(-1, kcross(1, o4b)), known)
        return {"coupler": (w3, a3), "rocker": (w4, a4)}
    if "B" in p:                         # slider-crank: OA + AB = (x_B, offset)
        oa, ab = p["A"], sub(p["B"], p["A"])
        w3, _ = solve2(kcross(1, ab), (-1.0, 0.0), times(-1, kcross(w2, oa)))
        known = add(times(-1, kcross(al2, oa)), times(w2 ** 2, oa), times(w3 ** 2, ab))
        a3, _ = solve2(kcross(1, ab), (-1.0, 0.0), known)
        return {"rod": (w3, a3), "slider": (0.0, 0.0)}
    # inverted slider-crank: O2A = O2O4 + rho e, e along the rod
    oa, r = p["A"], sub(p["A"], p["O4"])
    e = unit(r)
    w4, rho_d = solve2(kcross(1, r), e, kcross(w2, oa))
    known = add(kcross(al2, oa), times(-w2 ** 2, oa), times(w4 ** 2, r), times(-2 * w4 * rho_d, kcross(1, e)))
    a4, _ = solve2(kcross(1, r), e, known)
    return {"rod": (w4, a4), "block": (w4, a4)}
