"""Two outlines touching at a point and free to slide: the higher pair's geometry, its row
and its position form, for every joint whose bodies touch (curves in contact, a pin in a
curved slot, a cam and its follower).

An outline is what a body touches with: a point (a pin, a knife edge: `Point`), a circle, a
line, or any curve (`shapes.Curve`: a spline, a cam's profile or pitch curve). At the
contact J the outlines share the unit normal n (from body a's outline towards b's) and
have signed radii of curvature ρa, ρb, positive when the outline is convex towards the
other one; their centres of curvature

    Ca = J − ρa n  (fixed in a),   Cb = J + ρb n  (fixed in b)

are, to second order, the ends of a link of length L = ρa + ρb along n (the *equivalent
linkage* of a higher pair: Norton, *Design of Machinery*, §2.14; Shigley and Uicker §4.13).
Keeping the contact is keeping that length:

    velocity:      (v_Cb − v_Ca)·n = 0                     (= (v_Jb − v_Ja)·n: no approach)
    acceleration:  (a_Cb − a_Ca)·n + (|v_rel|² − (v_rel·n)²)/L = 0,   v_rel = v_Cb − v_Ca

(the second derivative of |Cb − Ca|). When an outline is straight (ρ infinite), its centre
is at infinity: the pair is a slider on that line, d/dt [(Cb − Q_a)·n] with n fixed in the
line's body, Coriolis term included (`derivatives.sliding`). A point has ρ = 0: Cb = J.
Which way n points does not matter: turning it turns ρa, ρb and L, and the rows change
sign only. Circles, lines and points are exact (symbols allowed); other curves numeric.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from ..algebra.vectors import add, dot, scale, sub
from ..errors import KinematikaError
from ..shapes import Cam, Circle, Curve, Line
from .base import rounding_hint
from .derivatives import sliding
from .positions import differences


@dataclass(frozen=True)
class Point:
    """A body's point as an outline (a pin, a knife edge): the drawn point `at`."""

    at: tuple
    name: str = ""


@dataclass
class Touch:
    """Where two outlines touch at this instant: the contact J, the unit normal n from a's
    outline towards b's, the signed radii of curvature (None: straight), the gap left (0 when
    they touch) and what the sweep's position form needs to follow the contact."""

    point: tuple
    normal: tuple
    radius_a: Any
    radius_b: Any
    gap: float
    outline_a: Any
    outline_b: Any
    side: float = 1.0                   # n = side × (a curve's own normal), at the drawing
    param: Optional[float] = None       # a curve's parameter at J
    kind: str = "sliding"
    bodies: tuple = ("", "")            # the joint's bodies a, b (set by `find_touch`)

    @property
    def centre_a(self) -> Optional[tuple]:
        """Ca = J − ρa n, the centre of curvature of a's outline (None when straight)."""
        return None if self.radius_a is None else sub(self.point, scale(self.radius_a, self.normal))

    @property
    def centre_b(self) -> Optional[tuple]:
        """Cb = J + ρb n (J itself for a point; None when straight)."""
        return None if self.radius_b is None else add(self.point, scale(self.radius_b, self.normal))

    # the geometric contact point (the `contact` question), bodies a and b given by the caller
    def jdot(self, motion: Any) -> tuple:
        """J̇, the velocity of the geometric contact point: on the line of the centres,
        J = Ca + μ(Cb − Ca) with μ = ρa/(ρa + ρb), so J̇ = v_Ca + μ(v_Cb − v_Ca); a point of b
        is the contact itself (J̇ = v_P); a straight outline carries the other's centre's foot."""
        return self._moving(motion, "velocity")

    def jddot(self, motion: Any) -> tuple:
        """J̈ likewise (exact while the radii stay constant: points, circles, lines)."""
        for outline in (self.outline_a, self.outline_b):
            if isinstance(outline, Curve):
                raise KinematikaError("schema", "the geometric contact point's acceleration on a general "
                                      "curve needs its curvature's rate: ask for the bodies' points", "")
        return self._moving(motion, "acceleration")

    def _moving(self, motion: Any, level: str) -> tuple:
        a, b = self.bodies
        of = motion.point_velocity if level == "velocity" else motion.point_acceleration
        if self.radius_b == 0:
            return of(b, self.point)
        if self.radius_a is None or self.radius_b is None:
            straight, body, centre, radius = ((a, b, self.centre_b, self.radius_b) if self.radius_a is None
                                              else (b, a, self.centre_a, self.radius_a))
            n = self.normal if self.radius_a is None else scale(-1, self.normal)
            state = motion.states.get(straight)
            w = state.omega if state else 0
            turn = motion.space.cross(w, n)
            if level == "acceleration":
                al = state.alpha if state else 0
                turn = add(motion.space.cross(al, n), motion.space.cross(w, turn))
            return sub(of(body, centre), scale(radius, turn))
        mu = self.radius_a / (self.radius_a + self.radius_b)
        va, vb = of(a, self.centre_a), of(b, self.centre_b)
        return add(va, scale(mu, sub(vb, va)))


def touch_row(lv: Any, a: str, b: str, t: Touch) -> Any:
    """The condition of keeping the contact at level `lv` (see the module's formulas)."""
    n = t.normal
    ca, cb = t.centre_a, t.centre_b
    if ca is None and cb is None:
        raise KinematikaError("geometry", "two straight outlines touch along a line, not at a point: "
                              "join them by a prismatic joint", "")
    if ca is None and cb is not None:       # a straight: b's centre slides along a's line
        return sliding(lv, a, b, cb, n)
    if cb is None and ca is not None:       # b straight: a's centre slides along b's line
        return sliding(lv, b, a, ca, scale(-1, n))
    row = dot(sub(lv.point(b, cb), lv.point(a, ca)), n)
    if lv.accel:
        v = sub(lv.v(b, cb), lv.v(a, ca))
        row = row + (dot(v, v) - dot(v, n) ** 2) / (t.radius_a + t.radius_b)
    return row


# finding the contact -------------------------------------------------------------------------
def outlines(inst: Any, joint: Any, body: str, point: Optional[str] = None) -> list:
    """What `body` may touch with: its point `point` (a pin, a knife edge), or its shapes
    (a cam's profile)."""
    if point is not None:
        return [Point(inst.points[point], point)]
    out = []
    for s in inst.shapes[body]:
        out.append(s.profile if isinstance(s, Cam) else s)
    return out


def closest(first: list, second: list, pair: Callable[[Any, Any], Any], gap: Callable[[Any], float],
            joint: Any, cannot: str) -> Any:
    """Of every pair (one outline of each body) that can touch, `pair(oa, ob)` not None, the
    one with the smallest |gap|; none at all is a `geometry` error naming the joint (`cannot`:
    why, in words)."""
    candidates = [made for oa in first for ob in second if (made := pair(oa, ob)) is not None]
    if not candidates:
        raise KinematikaError("geometry", f"{joint.kind.name} between {joint.a!r} and {joint.b!r}: {cannot}",
                              joint.where)
    return min(candidates, key=lambda c: abs(gap(c)))


def find_touch(inst: Any, joint: Any, first: list, second: list, near: Optional[float] = None,
               touching: bool = True) -> Touch:
    """The touching pair of outlines of the joint's two bodies (the one with the smallest
    gap), checked to touch: else a `geometry` error with the gap (unless not `touching`: a
    moved pose, whose caller judges the gap). `near`: a curve's parameter close to the
    contact (a sweep's previous one), which spares the search along the curve."""
    if not first or not second:
        missing = joint.a if not first else joint.b
        raise KinematikaError("schema", f"a {joint.kind.name} joint needs an outline on both bodies: give "
                              f"{missing!r} a circle, line or curve (or name its point with `at`)", joint.where)
    touch = closest(first, second, lambda oa, ob: _pair(inst, oa, ob, near), lambda t: t.gap, joint,
                    "these outlines cannot touch at a point")
    touch.bodies = (joint.a, joint.b)
    if touching and abs(touch.gap) > 1e-6 * inst.scale:
        raise KinematikaError("geometry", f"{joint.b!r} does not touch {joint.a!r}: gap {touch.gap:.6g}"
                              + rounding_hint(touch.gap, inst.scale, "the contact"), joint.where)
    return touch


def _pair(inst: Any, oa: Any, ob: Any, near: Optional[float] = None) -> Optional[Touch]:
    """The contact of outline oa (body a) and ob (body b), or None if they cannot touch."""
    if isinstance(oa, (Circle, Line)) and isinstance(ob, Point):
        return _point_exact(inst, oa, ob)
    if isinstance(oa, Circle) and isinstance(ob, Circle):
        return _circles(inst, oa, ob)
    if isinstance(oa, Circle) and isinstance(ob, Line):
        return _flip(_circle_line(inst, ob, oa))
    if isinstance(oa, Line) and isinstance(ob, Circle):
        return _circle_line(inst, oa, ob)
    if isinstance(oa, Curve):
        return _on_curve(inst, oa, ob, near)
    if isinstance(ob, Curve) and not isinstance(oa, Point):
        return _flip(_on_curve(inst, ob, oa, near))
    return None


def _flip(t: Optional[Touch]) -> Optional[Touch]:
    """The same contact seen from the other body: n and the radii exchanged."""
    if t is None:
        return None
    return Touch(t.point, scale(-1, t.normal), t.radius_b, t.radius_a, t.gap, t.outline_b, t.outline_a,
                 t.side, t.param, t.kind + "*")


def _point_exact(inst: Any, oa: Any, p: Point) -> Touch:
    """A point of b on a's circle (a pin in a circular slot) or line (a pin in a straight one)."""
    bk = inst.backend
    if isinstance(oa, Circle):
        d = sub(p.at, oa.center)
        dist = bk.sqrt(dot(d, d))
        n = tuple(bk.simplify(c / dist) for c in d)
        gap = inst.num(dist) - inst.num(oa.radius)
        return Touch(p.at, n, oa.radius, 0, gap, oa, p, kind="point-circle")
    n = (-oa.direction[1], oa.direction[0])
    gap = inst.num(dot(sub(p.at, oa.through), n))
    return Touch(p.at, n, None, 0, gap, oa, p, kind="point-line")


def _circles(inst: Any, ca: Circle, cb: Circle) -> Optional[Touch]:
    """Circles touching outside (|Cb − Ca| = Ra + Rb) or one inside the other."""
    bk = inst.backend
    d = sub(cb.center, ca.center)
    dist = bk.sqrt(dot(d, d))
    if inst.num(dist) <= 1e-12 * inst.scale:
        return None
    u = tuple(bk.simplify(c / dist) for c in d)
    ra, rb = ca.radius, cb.radius
    gaps = {"external": inst.num(dist) - inst.num(ra + rb), "internal": inst.num(dist) - abs(inst.num(ra - rb))}
    kind = min(gaps, key=lambda k: abs(gaps[k]))
    if kind == "external":                    # J on the segment, n from a to b
        return Touch(add(ca.center, scale(ra, u)), u, ra, rb, gaps[kind], ca, cb, kind="circles")
    if inst.num(ra) >= inst.num(rb):          # b inside a: a concave towards b
        return Touch(add(ca.center, scale(ra, u)), u, -ra, rb, gaps[kind], ca, cb, kind="circles")
    n = scale(-1, u)                          # a inside b
    return Touch(sub(ca.center, scale(ra, u)), n, ra, -rb, gaps[kind], ca, cb, kind="circles")


def _circle_line(inst: Any, ln: Line, c: Circle) -> Touch:
    """A circle of b touching a's line: J the foot of its centre, n the line's normal towards it."""
    m = (-ln.direction[1], ln.direction[0])
    h = dot(sub(c.center, ln.through), m)
    side = 1 if inst.num(h) >= 0 else -1
    n = scale(side, m)
    gap = abs(inst.num(h)) - inst.num(c.radius)
    return Touch(sub(c.center, scale(c.radius, n)), n, None, c.radius, gap, ln, c, kind="circle-line")


def _on_curve(inst: Any, curve: Curve, ob: Any, near: Optional[float] = None) -> Optional[Touch]:
    """b's point, circle, line or curve touching a's curve (numeric)."""
    if isinstance(ob, Point):
        p = _floats(inst, ob.at)
        u = curve.nearest(p, near)
        n = curve.normal(u)
        gap = float(np.dot(p - curve.point(u), n))
        return _curve_touch(curve, u, 1.0, tuple(p), 0.0, gap, ob, "point-curve")
    if isinstance(ob, Circle):
        c = _floats(inst, ob.center)
        u = curve.nearest(c, near)
        d = float(np.dot(c - curve.point(u), curve.normal(u)))
        side = 1.0 if d >= 0 else -1.0
        r = float(inst.num(ob.radius))
        return _curve_touch(curve, u, side, tuple(curve.point(u)), r, abs(d) - r, ob, "circle-curve")
    if isinstance(ob, Line):
        q, e = _floats(inst, ob.through), _floats(inst, ob.direction)
        m = np.array([-e[1], e[0]])
        heights = [(_support(curve, q, s * m), s) for s in (1.0, -1.0)]
        (u, h), s = min(heights, key=lambda x: abs(x[0][1]))
        side = float(np.sign(np.dot(curve.normal(u), -s * m)) or 1.0)
        return _curve_touch(curve, u, side, tuple(curve.point(u)), None, h, ob, "line-curve")
    if isinstance(ob, Curve):
        return _curves(curve, ob)
    return None


def _curve_touch(curve: Curve, u: float, side: float, point: tuple, radius_b: Any, gap: float,
                 ob: Any, kind: str) -> Touch:
    """A contact on a's curve at parameter u, n = side × the curve's normal: a's radius
    ρa = −side/κ (its centre of curvature is at J + n_c/κ), None where it is straight."""
    n = side * curve.normal(u)
    kappa = float(curve.curvature(u))
    radius_a = None if abs(kappa) < 1e-12 else -side / kappa
    return Touch(tuple(float(x) for x in point), tuple(float(x) for x in n), radius_a, radius_b, gap,
                 curve, ob, side, float(u), kind)


def _support(curve: Curve, q: np.ndarray, m: np.ndarray) -> tuple[float, float]:
    """The curve's point lowest along m from the line through q (a flat face touching a cam):
    (u, height); sampled, then Newton on (r'·m) = 0."""
    a, b = curve.curve.domain
    grid = np.linspace(a, b, 2048, endpoint=not curve.curve.closed)
    h = (curve.point(grid) - q) @ m
    u = float(grid[int(np.argmin(h))])
    for _ in range(50):
        d1 = curve.curve.d1(u) @ _rot(curve.angle).T
        d2 = curve.curve.d2(u) @ _rot(curve.angle).T
        g, dg = float(d1 @ m), float(d2 @ m)
        if dg <= 0:
            break
        step = g / dg
        u = float(curve.curve.wrap(u - step))
        if abs(step) < 1e-14 * max(1.0, abs(u)):
            break
    return u, float((curve.point(u) - q) @ m)


def _curves(ca: Curve, cb: Curve) -> Optional[Touch]:
    """Two curves: the closest pair of points (sampled, then Newton on both parameters)."""
    pb = cb.points(512)
    ua = np.array([ca.nearest(p) for p in pb[::8]])
    gaps = np.linalg.norm(ca.point(ua) - pb[::8], axis=-1)
    k = int(np.argmin(gaps))
    u, v = float(ua[k]), float(cb.nearest(ca.point(ua[k])))
    for _ in range(40):
        u = ca.nearest(cb.point(v), near=u)
        v2 = cb.nearest(ca.point(u), near=v)
        if abs(v2 - v) < 1e-14 * max(1.0, abs(v)):
            break
        v = v2
    j = ca.point(u)
    n = ca.normal(u)
    d = float(np.dot(cb.point(v) - j, n))
    side = 1.0 if d >= 0 else -1.0
    kb = float(cb.curvature(v))
    nb = cb.normal(v)
    radius_b = None if abs(kb) < 1e-12 else float(np.dot(nb, side * n)) / kb
    return _curve_touch(ca, u, side, tuple(j), radius_b, abs(d), cb, "curves")


def _floats(inst: Any, v: Any) -> np.ndarray:
    return np.array([float(inst.num(x)) for x in v])


def _rot(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


# the position form -----------------------------------------------------------------------------
@dataclass
class Follow:
    """The gap of a touching pair at a pose, for sweeps: the other outline brought into the
    drawn place of the body whose outline is a curve (the pose's inverse for that body),
    measured from the curve along the normal as at the drawing, its parameter followed from
    the previous pose (`aux`). The gap is the same seen from either body, and its rate is the
    row's (v_Jb − v_Ja)·n."""

    a: str
    b: str
    touch: Touch
    key: str

    def __post_init__(self) -> None:
        t = self.touch
        if isinstance(t.outline_b, Curve) and not isinstance(t.outline_a, Curve):
            self.holder, self.curve, self.other, self.element = self.b, t.outline_b, self.a, t.outline_a
        else:
            self.holder, self.curve, self.other, self.element = self.a, t.outline_a, self.b, t.outline_b

    def __call__(self, q: Any, _: float) -> list:
        back = _inverse(q, self.holder)
        if isinstance(self.curve, Curve):
            return [self._on_curve(q, back, q.aux.get(self.key, self.touch.param))]
        return [self._exact(q, back)]

    def aux(self, q: Any) -> Optional[float]:
        """The curve parameter at this pose (remembered for the next one)."""
        if not isinstance(self.curve, Curve):
            return None
        back = _inverse(q, self.holder)
        u0 = q.aux.get(self.key, self.touch.param)
        if isinstance(self.element, (Point, Circle)):
            at = self.element.at if isinstance(self.element, Point) else self.element.center
            return self.curve.nearest(back(q.point(self.other, at)), near=u0)
        return u0

    def _on_curve(self, q: Any, back: Any, u0: float) -> float:
        curve, ob, side = self.curve, self.element, self.touch.side
        if isinstance(ob, (Point, Circle)):
            at = ob.at if isinstance(ob, Point) else ob.center
            p = back(q.point(self.other, at))
            u = curve.nearest(p, near=u0)
            radius = float(ob.radius) if isinstance(ob, Circle) else 0.0
            return float(np.dot(p - curve.point(u), side * curve.normal(u))) - radius
        if isinstance(ob, Line):
            through = back(q.point(self.other, ob.through))
            e = _turn_back(q, self.holder, q.turn(self.other, ob.direction))
            m = np.array([-e[1], e[0]])
            m = m if np.dot(m, side * curve.normal(u0)) < 0 else -m      # from the line towards the curve
            return _support(curve, through, m)[1]
        raise KinematikaError("schema", "a sweep follows a curve touching a point, a circle or a line", "")

    def _exact(self, q: Any, back: Any) -> float:
        oa, ob = self.curve, self.element
        if isinstance(oa, Circle) and isinstance(ob, Point):
            p = back(q.point(self.other, ob.at))
            return float(np.linalg.norm(p - np.asarray(oa.center, dtype=float))) - float(oa.radius)
        if isinstance(oa, Line) and isinstance(ob, Point):
            p = back(q.point(self.other, ob.at))
            n = np.array([-float(oa.direction[1]), float(oa.direction[0])])
            return float(np.dot(p - np.asarray(oa.through, dtype=float), n))
        raise KinematikaError("schema", "a sweep follows sliding contact of a point on a circle or line, or "
                              "of an outline on a curve", "")


def _inverse(q: Any, body: str) -> Any:
    """The map from where points are at pose q back to where body's drawn points were."""
    origin = np.asarray(q.point(body, (0.0, 0.0)), dtype=float)
    ex = np.asarray(q.turn(body, (1.0, 0.0)), dtype=float)
    r = np.array([[ex[0], -ex[1]], [ex[1], ex[0]]])
    return lambda p: (np.asarray(p, dtype=float) - origin) @ r


def _turn_back(q: Any, body: str, e: Any) -> np.ndarray:
    ex = np.asarray(q.turn(body, (1.0, 0.0)), dtype=float)
    r = np.array([[ex[0], -ex[1]], [ex[1], ex[0]]])
    return np.asarray(e, dtype=float) @ r


__all__ = ["Follow", "Point", "Touch", "differences", "find_touch", "outlines", "touch_row"]
