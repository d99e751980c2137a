"""Two rockers whose outlines touch and slide, and the motion derived by hand, independently
of kinematika: the pair's geometric condition φ(θ₂, θ₄) = 0 written in closed form for each
kind of pair (circles a constant distance apart, a circle's centre a constant distance from
a line), differentiated by sympy:

    φ₂ θ̇₂ + φ₄ θ̇₄ = 0,
    φ₂₂ θ̇₂² + 2 φ₂₄ θ̇₂ θ̇₄ + φ₄₄ θ̇₄² + φ₂ θ̈₂ + φ₄ θ̈₄ = 0,

and the contact point J(θ₂, θ₄) (on the line of the centres at Ra from a's centre; a line's
foot of the circle's centre) differentiated likewise. Rocker 2 (pivot O2, the driven one)
carries outline a, rocker 4 (pivot O4) outline b (Norton §2.14: the pair's equivalent
four-bar or slider)."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Optional

import numpy as np
import sympy

O2, O4 = (0.0, 0.0), (40.0, 20.0)
T2, W2, A2 = math.radians(150), -3.0, 6.0        # the drive: θ₂ at the drawing, ω₂, α₂
x2, x4 = sympy.symbols("x2 x4", real=True)


def _polar(o: tuple, r: float, x) -> sympy.Matrix:
    return sympy.Matrix([o[0] + r * sympy.cos(x), o[1] + r * sympy.sin(x)])


@dataclass
class Pair:
    """One case: outline a on rocker 2 and outline b on rocker 4, with the model's points and
    shapes, the condition φ and the contact J as formulas in x2, x4."""

    name: str
    phi: sympy.Expr
    contact: sympy.Matrix
    t4: float                        # θ₄ at the drawing
    points: dict
    shape_a: Optional[dict]
    shape_b: Optional[dict]
    at: Optional[str] = None         # b's point that touches (a pin)
    placed: Any = None               # θ₄ as a function of θ₂ (arrays): the position in closed form

    def tree(self, kind: str = "contact") -> dict:
        """The model: ground, rocker l2 driven at ω₂, α₂, rocker l4, the pair as `kind`."""
        pts = {k: [float(v[0]), float(v[1])] for k, v in self.points.items()}
        l2 = {"points": ["O2", *(p for p in pts if p.endswith("2") and p != "O2")], **(self.shape_a or {})}
        l4 = {"points": ["O4", *(p for p in pts if p.endswith("4") and p != "O4")], **(self.shape_b or {})}
        joint = {"type": kind, "bodies": ["l2", "l4"], **({"at": self.at} if self.at else {})}
        return {"name": self.name, "points": pts, "bodies": {"ground": ["O2", "O4"], "l2": l2, "l4": l4},
                "joints": [{"type": "revolute", "bodies": ["ground", "l2"], "at": "O2"},
                           {"type": "revolute", "bodies": ["ground", "l4"], "at": "O4"}, joint],
                "drivers": [{"omega": "l2", "value": W2, "alpha": A2}],
                "ask": [{"omega": "l4"}, {"alpha": "l4"}, {"contact": "j3"}]}

    def motion(self, t2: float = T2, t4: Optional[float] = None, w2: float = W2,
               a2: float = A2) -> dict:
        """ω₄, α₄, and J with its velocity and acceleration, by implicit differentiation."""
        at = {x2: t2, x4: self.t4 if t4 is None else t4}
        d = {k: float(sympy.diff(self.phi, *k).subs(at)) for k in [(x2,), (x4,), (x2, x2), (x2, x4), (x4, x4)]}
        w4 = -d[(x2,)] * w2 / d[(x4,)]
        a4 = -(d[(x2, x2)] * w2**2 + 2 * d[(x2, x4)] * w2 * w4 + d[(x4, x4)] * w4**2 + d[(x2,)] * a2) / d[(x4,)]
        j = self.contact

        def part(*k):
            return np.array([float(c) for c in sympy.diff(j, *k).subs(at)])

        jv = part(x2) * w2 + part(x4) * w4
        ja = (part(x2, x2) * w2**2 + 2 * part(x2, x4) * w2 * w4 + part(x4, x4) * w4**2
              + part(x2) * a2 + part(x4) * a4)
        point = np.array([float(c) for c in j.subs(at)])
        return {"omega": w4, "alpha": a4, "J": point, "J_v": jv, "J_a": ja}

    def over(self, t2: np.ndarray, w2: float = W2, a2: float = A2) -> dict:
        """θ₄ (continuous), ω₄ and α₄ at every θ₂ of an array, the drive's ω₂ and α₂ the same at
        each (as a sweep keeps its driver's rates): φ's partial derivatives as numpy functions."""
        t4 = np.unwrap(self.placed(t2))
        d = {k: sympy.lambdify((x2, x4), sympy.diff(self.phi, *k), "numpy")
             for k in [(x2,), (x4,), (x2, x2), (x2, x4), (x4, x4)]}
        p = {k: np.broadcast_to(f(t2, t4), t2.shape) for k, f in d.items()}
        w4 = -p[(x2,)] * w2 / p[(x4,)]
        a4 = -(p[(x2, x2)] * w2**2 + 2 * p[(x2, x4)] * w2 * w4 + p[(x4, x4)] * w4**2 + p[(x2,)] * a2) / p[(x4,)]
        return {"angle": t4, "omega": w4, "alpha": a4}


def _four_bar(t2: np.ndarray, crank: float, length: float, rocker: float) -> np.ndarray:
    """θ₄ of the four-bar O2–C2–C4–O4 (|O2C2| = crank, |C2C4| = length, |O4C4| = rocker),
    C4 left of the direction C2 → O4 (the drawn branch): where two circles meet."""
    c2 = crank * np.stack([np.cos(t2), np.sin(t2)], axis=-1)
    d = np.subtract(O4, c2)
    dist = np.hypot(d[..., 0], d[..., 1])
    along = (length**2 - rocker**2 + dist**2) / (2 * dist)
    up = np.sqrt(length**2 - along**2)
    u = d / dist[..., None]
    c4 = c2 + along[..., None] * u + up[..., None] * np.stack([-u[..., 1], u[..., 0]], axis=-1)
    return np.arctan2(c4[..., 1] - O4[1], c4[..., 0] - O4[0])


def circles(name: str, ra: float, rb: float, how: str, crank: float = 30.0, rocker: float = 45.0,
            outline_a: str = "circle", outline_b: str = "circle") -> Pair:
    """Circles of radii ra (centre C2, `crank` from O2) and rb (centre C4, `rocker` from O4):
    `how` "outside" (|C2C4| = ra + rb, J at ra from C2 towards C4), "b inside a" (ra − rb,
    J at ra from C2 beyond C4), "a inside b" (rb − ra, J at ra from C2 away from C4)."""
    length = {"outside": ra + rb, "b inside a": ra - rb, "a inside b": rb - ra}[how]
    c2, c4 = _polar(O2, crank, x2), _polar(O4, rocker, x4)
    u = (c4 - c2) / length                             # unit while they touch
    contact = c2 + (-ra if how == "a inside b" else ra) * u
    t4 = float(_four_bar(np.array(T2), crank, length, rocker))
    points = {"O2": O2, "O4": O4, "C2": tuple(c2.subs(x2, T2)), "C4": tuple(_polar(O4, rocker, t4))}
    return Pair(name, (c4 - c2).dot(c4 - c2) - length**2, contact, t4, points,
                outline(outline_a, "C2", ra, points["C2"]), outline(outline_b, "C4", rb, points["C4"]),
                placed=lambda t: _four_bar(t, crank, length, rocker))


def pin_on_circle(name: str, radius: float = 50.0, kind_a: str = "circle") -> Pair:
    """Rocker 4's pin C4 on a's circle (a slot) of radius `radius` about C2."""
    pair = circles(name, radius, 0.0, "b inside a", outline_a=kind_a)
    pair.shape_b, pair.at = None, "C4"
    pair.contact = _polar(O4, 45.0, x4)
    return pair


def circle_on_line(name: str, side: int, radius: float = 10.0) -> Pair:
    """a's circle (centre C2, 30 from O2) on b's line, the line through O4 at angle θ₄ (the
    rocker is a flat-faced follower), the centre on the `side` of the line's left normal m:
    (C2 − O4)·m = side·r, J = C2 − side·r·m."""
    c2 = _polar(O2, 30.0, x2)
    m = sympy.Matrix([-sympy.sin(x4), sympy.cos(x4)])
    def placed(t2: np.ndarray) -> np.ndarray:           # (C2 − O4)·m = |C2 − O4| sin(β − θ₄) = side·r
        rel = 30.0 * np.stack([np.cos(t2), np.sin(t2)], axis=-1) - O4
        return np.arctan2(rel[..., 1], rel[..., 0]) - np.arcsin(side * radius / np.hypot(rel[..., 0], rel[..., 1]))

    t4 = float(placed(np.array(T2)))
    points = {"O2": O2, "O4": O4, "C2": tuple(c2.subs(x2, T2))}
    line = {"line": {"through": "O4", "direction": [math.cos(t4), math.sin(t4)]}}
    return Pair(name, (c2 - sympy.Matrix(O4)).dot(m) - side * radius, c2 - side * radius * m, t4, points,
                {"circle": {"center": "C2", "radius": radius}}, line, placed=placed)


def line_on_circle(name: str, side: int, radius: float = 10.0, rocker: float = 60.0) -> Pair:
    """b's circle (centre C4, `rocker` from O4) on a's line, the line through O2 at angle θ₂:
    (C4 − O2)·m = side·r, J = C4 − side·r·m."""
    c4 = _polar(O4, rocker, x4)
    m = sympy.Matrix([-sympy.sin(x2), sympy.cos(x2)])
    def placed(t2: np.ndarray) -> np.ndarray:           # O4·m + rocker·sin(θ₄ − θ₂) = side·r
        along = -O4[0] * np.sin(t2) + O4[1] * np.cos(t2)
        return t2 + np.arcsin((side * radius - along) / rocker)

    t4 = float(placed(np.array(T2)))
    points = {"O2": O2, "O4": O4, "C4": tuple(c4.subs(x4, t4))}
    line = {"line": {"through": "O2", "direction": [math.cos(T2), math.sin(T2)]}}
    return Pair(name, c4.dot(m) - side * radius, c4 - side * radius * m, t4, points, line,
                {"circle": {"center": "C4", "radius": radius}}, placed=placed)


def outline(kind: str, centre: str, radius: float, at: tuple, n: int = 360) -> Optional[dict]:
    """A body's outline: a `circle`, or the closed `curve` through n points of that circle, or
    a `cam` whose measured profile is that circle (the cam centred at the body's pivot O2)."""
    if radius == 0:
        return None
    c = np.array([float(at[0]), float(at[1])])
    ring = [[float(c[0] + radius * math.cos(t)), float(c[1] + radius * math.sin(t))]
            for t in np.linspace(0, 2 * math.pi, n, endpoint=False)]
    if kind == "circle":
        return {"circle": {"center": centre, "radius": radius}}
    if kind == "curve":
        return {"curve": {"through": ring, "closed": True}}
    assert kind == "cam"
    return {"cam": {"center": "O2", "angle": 0, "profile": ring,
                    "follower": {"motion": "translating", "contact": "flat"}}}
