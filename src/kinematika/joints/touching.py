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
from typing import TYPE_CHECKING, Any, Callable, Optional

import numpy as np

from ..algebra.vectors import add, dot, scale, sub
from ..errors import KinematikaError, Num, Said
from ..shapes import Cam, Circle, Curve, Line
from .base import JointGeometry, ModelJoint, rounding_hint
from .curve_search import circle_contact, curves_contact, support
from .derivatives import sliding
from .positions import differences
from .tangency import tangency

if TYPE_CHECKING:
    from .seam import Instant, Level, Motion, Pose


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
    param: Any = None                   # a curve's parameter at J (two curves: the pair (u, v))
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
    def jdot(self, motion: Motion) -> tuple:
        """J̇, the velocity of the geometric contact point: on the line of the centres,
        J = Ca + μ(Cb − Ca) with μ = ρa/(ρa + ρb), so J̇ = v_Ca + μ(v_Cb − v_Ca); a point of b
        is the contact itself (J̇ = v_P); a straight outline carries the other's centre's foot."""
        return self._moving(motion, "velocity")

    def jddot(self, motion: Motion) -> tuple:
        """J̈ likewise (exact while the radii stay constant: points, circles, lines)."""
        for outline in (self.outline_a, self.outline_b):
            if isinstance(outline, Curve):
                raise KinematikaError("schema", "contact-acceleration-curve", "")
        return self._moving(motion, "acceleration")

    def _moving(self, motion: Motion, level: str) -> tuple:
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
            assert centre is not None, "two straight outlines touch along a line, not at a point"
            return sub(of(body, centre), scale(radius, turn))
        mu = self.radius_a / (self.radius_a + self.radius_b)
        ca, cb = self.centre_a, self.centre_b
        assert ca is not None and cb is not None            # both radii given
        va, vb = of(a, ca), of(b, cb)
        return add(va, scale(mu, sub(vb, va)))


def touch_row(lv: Level, a: str, b: str, t: Touch) -> Any:
    """The condition of keeping the contact at level `lv` (see the module's formulas)."""
    n = t.normal
    ca, cb = t.centre_a, t.centre_b
    if ca is None or cb is None:
        if cb is not None:                  # a straight: b's centre slides along a's line
            return sliding(lv, a, b, cb, n)
        if ca is not None:                  # b straight: a's centre slides along b's line
            return sliding(lv, b, a, ca, scale(-1, n))
        raise KinematikaError("geometry", "straight-outlines", "")
    row = dot(sub(lv.point(b, cb), lv.point(a, ca)), n)
    if lv.accel:
        v = sub(lv.v(b, cb), lv.v(a, ca))
        row = row + (dot(v, v) - dot(v, n) ** 2) / (t.radius_a + t.radius_b)
    return row


# finding the contact -------------------------------------------------------------------------
def outlines(inst: Instant, joint: ModelJoint, body: str, point: Optional[str] = None) -> list:
    """What `body` may touch with: its point `point` (a pin, a knife edge), or its shapes
    (a cam's profile)."""
    if point is not None:
        return [Point(inst.points[point], point)]
    out = []
    for s in inst.shapes[body]:
        out.append(s.profile if isinstance(s, Cam) else s)
    return out


def closest(first: list, second: list, pair: Callable[[Any, Any], Any], gap: Callable[[Any], float],
            joint: ModelJoint, cannot: Any) -> Any:
    """Of every pair (one outline of each body) that can touch, `pair(oa, ob)` not None, the
    one with the smallest |gap|; none at all is a `geometry` error naming the joint (`cannot`:
    why, in words)."""
    candidates = [made for oa in first for ob in second if (made := pair(oa, ob)) is not None]
    if not candidates:
        raise KinematikaError("geometry", "pair-cannot", joint.where, kind=joint.type, body=joint.a,
                              other=joint.b, why=cannot)
    return min(candidates, key=lambda c: abs(gap(c)))


def find_touch(inst: Instant, joint: ModelJoint, first: list, second: list, near: Any = None,
               touching: bool = True) -> Touch:
    """The touching pair of outlines of the joint's two bodies (the one with the smallest
    gap), checked to touch: else a `geometry` error with the gap (unless not `touching`: a
    moved pose, whose caller judges the gap). `near`: a curve's parameter close to the
    contact (a sweep's previous one), which spares the search along the curve."""
    if not first or not second:
        missing = joint.a if not first else joint.b
        raise KinematikaError("schema", "touching-needs-outlines", joint.where, kind=joint.type, body=missing)
    touch = closest(first, second, lambda oa, ob: _pair(inst, oa, ob, near), lambda t: t.gap, joint,
                    Said("outlines-cannot-touch"))
    touch.bodies = (joint.a, joint.b)
    if touching and abs(touch.gap) > 1e-6 * inst.scale:
        raise KinematikaError("geometry", "no-touch", joint.where, body=joint.b, other=joint.a, gap=Num(touch.gap, ".6g"),
                              hint=rounding_hint(touch.gap, inst.scale, Said("the-contact")))
    return touch


def _pair(inst: Instant, oa: Any, ob: Any, near: Any = None) -> Optional[Touch]:
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


def _point_exact(inst: Instant, oa: Any, p: Point) -> Touch:
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


def _circles(inst: Instant, ca: Circle, cb: Circle) -> Optional[Touch]:
    """Circles touching outside each other or one inside the other (`tangency`): J on the
    line of centres, n = σ u from a's material into b's, the radii signed by the way they
    touch, so that Cₐ and C_b are the circles' centres."""
    bk = inst.backend
    d = sub(cb.center, ca.center)
    dist = bk.sqrt(dot(d, d))
    apart = float(inst.num(dist))
    if apart <= 1e-12 * inst.scale:
        return None
    u = tuple(bk.simplify(c / dist) for c in d)
    way = tangency(apart, float(inst.num(ca.radius)), float(inst.num(cb.radius)))
    ra, rb = ca.radius, cb.radius
    place_a, _ = way.places(ra, rb)
    radius_a, radius_b = way.radii(ra, rb)
    return Touch(add(ca.center, scale(place_a, u)), scale(way.sense, u), radius_a, radius_b, way.gap, ca, cb,
                 kind="circles")


def _circle_line(inst: Instant, ln: Line, c: Circle) -> Touch:
    """A circle of b touching a's line: J the foot of its centre, n the line's normal towards it."""
    m = (-ln.direction[1], ln.direction[0])
    h = dot(sub(c.center, ln.through), m)
    side = 1 if inst.num(h) >= 0 else -1
    n = scale(side, m)
    gap = abs(inst.num(h)) - inst.num(c.radius)
    return Touch(sub(c.center, scale(c.radius, n)), n, None, c.radius, gap, ln, c, kind="circle-line")


def _on_curve(inst: Instant, curve: Curve, ob: Any, hint: Any = None) -> Optional[Touch]:
    """b's point, circle, line or curve touching a's curve (numeric; `curve_search` finds
    where, from a sweep's last contact `hint` when given: a parameter, or two for two
    curves)."""
    if isinstance(ob, Curve):
        return _curves(curve, ob, hint if isinstance(hint, tuple) else None)
    near = None if isinstance(hint, tuple) else hint
    if isinstance(ob, (Point, Circle)):
        c = _floats(inst, ob.at if isinstance(ob, Point) else ob.center)
        r = 0.0 if isinstance(ob, Point) else float(inst.num(ob.radius))
        u = circle_contact(curve, c, r, near)
        d = float(np.dot(c - curve.point(u), curve.normal(u)))
        if isinstance(ob, Point):
            return _curve_touch(curve, u, 1.0, tuple(c), 0.0, d, ob, "point-curve")
        side = 1.0 if d >= 0 else -1.0
        return _curve_touch(curve, u, side, tuple(curve.point(u)), r, abs(d) - r, ob, "circle-curve")
    if isinstance(ob, Line):
        q, e = _floats(inst, ob.through), _floats(inst, ob.direction)
        m = np.array([-e[1], e[0]])
        toward = float(np.dot(curve.normal(near), m) * curve.curvature(near)) if near is not None else 0.0
        if toward != 0.0:                         # followed: the curve's centre of curvature side
            s = 1.0 if toward > 0 else -1.0
            (u, h) = support(curve, q, s * m, near)
        else:
            heights = [(support(curve, q, s * m), s) for s in (1.0, -1.0)]
            (u, h), s = min(heights, key=lambda x: abs(x[0][1]))
        side = float(np.sign(np.dot(curve.normal(u), -s * m)) or 1.0)
        return _curve_touch(curve, u, side, tuple(curve.point(u)), None, h, ob, "line-curve")
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


def _curves(ca: Curve, cb: Curve, near: Optional[tuple[float, float]] = None) -> Optional[Touch]:
    """Two curves: where they touch (`curve_search.curves_contact`); n = ± a's normal towards
    the side b's curve lies on near J (its centre of curvature's, or the side away from a's
    when b is straight there: never the sign of a gap that is round-off while they touch),
    b's radius of curvature ρb = (n_b·n)/κ_b along it."""
    u, v = curves_contact(ca, cb, near)
    j = ca.point(u)
    n = ca.normal(u)
    kb, nb = float(cb.curvature(v)), cb.normal(v)
    towards = kb * float(np.dot(nb, n)) if abs(kb) >= 1e-12 else -float(ca.curvature(u))
    side = -1.0 if towards < 0 else 1.0
    d = float(np.dot(cb.point(v) - j, n))
    radius_b = None if abs(kb) < 1e-12 else float(np.dot(nb, side * n)) / kb
    touch = _curve_touch(ca, u, side, tuple(j), radius_b, abs(d), cb, "curves")
    touch.param = (u, v)
    return touch


def _floats(inst: Instant, v: Any) -> np.ndarray:
    return np.array([float(inst.num(x)) for x in v])


def touch_of(geo: JointGeometry) -> Touch:
    """The touch a contact or curved slot's `prepare` found (`geo.contact`)."""
    assert isinstance(geo.contact, Touch), f"{geo.joint.where}: no touch found"
    return geo.contact


# the position form -----------------------------------------------------------------------------
@dataclass
class Follow:
    """The gap of a touching pair at a pose, for sweeps, signed so that its rate is the
    engine's row (v_Jb − v_Ja)·n (Newton's method takes the engine's matrix for its
    Jacobian):

    - circles, points: the centres Ca, Cb carried by their bodies keep their distance,
      sign(L)·|Cb − Ca| − L with L = ρa + ρb (Cb − Ca = L n at the drawing);
    - a line: the other's centre keeps its height above it, (Cb − Q)·n − ρb with n and Q
      carried by the line's body (or (Ca − Q)·(−n) − ρa);
    - a curve: the other outline brought into the drawn place of the curve's body (the
      pose's inverse for it), the gap measured from the curve along the normal on the side
      it had at the drawing, where they touch now (`curve_search`), its parameter followed
      from the previous pose (`aux`)."""

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

    def __call__(self, q: Pose, _: float) -> list:
        if isinstance(self.curve, Curve):
            return [self._on_curve(q, q.aux.get(self.key, self.touch.param), gap=True)[0]]
        return [self._exact(q)]

    def aux(self, q: Pose) -> Any:
        """The curve parameter at this pose (two curves: both), remembered for the next one."""
        if not isinstance(self.curve, Curve):
            return None
        return self._on_curve(q, q.aux.get(self.key, self.touch.param), gap=False)[1]

    def _on_curve(self, q: Pose, u0: Any, gap: bool) -> tuple[float, Any]:
        """(gap, parameter) of the element on the curve at pose q, from the parameter u0 (the
        gap left 0 unless asked for: the parameter alone is what a sweep remembers)."""
        curve, ob, side = self.curve, self.element, self.touch.side
        back = _inverse(q, self.holder)
        if isinstance(ob, (Point, Circle)):
            p = back(q.point(self.other, ob.at if isinstance(ob, Point) else ob.center))
            radius = float(ob.radius) if isinstance(ob, Circle) else 0.0
            u = circle_contact(curve, p, radius, near=u0)
            return (float(np.dot(p - curve.point(u), side * curve.normal(u))) - radius if gap else 0.0), u
        if isinstance(ob, Line):
            through = back(q.point(self.other, ob.through))
            e = _turn_back(q, self.holder, q.turn(self.other, ob.direction))
            m = np.array([-e[1], e[0]])
            m = m if np.dot(m, side * curve.normal(u0)) < 0 else -m      # from the line towards the curve
            u, height = support(curve, through, m, near=u0)
            return height, u
        assert isinstance(ob, Curve)
        other = Curve(ob.curve, tuple(back(q.point(self.other, ob.origin))),
                      ob.angle + _turned(q, self.other) - _turned(q, self.holder), ob.role)
        u, v = curves_contact(curve, other, near=u0)
        return (float(np.dot(other.point(v) - curve.point(u), side * curve.normal(u))) if gap else 0.0), (u, v)

    def _exact(self, q: Pose) -> float:
        t, a, b = self.touch, self.a, self.b
        ca, cb = t.centre_a, t.centre_b
        if ca is not None and cb is not None:
            length = float(t.radius_a + t.radius_b)
            d = np.subtract(q.point(b, _numbers(cb)), q.point(a, _numbers(ca)))
            return math.copysign(1.0, length) * float(np.hypot(*d)) - length
        if ca is None and cb is not None:          # a straight: b's centre above a's line
            straight, other, centre, n, height = a, b, cb, _numbers(t.normal), float(t.radius_b)
        elif ca is not None:                       # b straight: a's centre above b's line
            straight, other, centre, n, height = b, a, ca, tuple(-x for x in _numbers(t.normal)), float(t.radius_a)
        else:
            raise KinematikaError("geometry", "two-straights-touch", "")
        gap = np.subtract(q.point(other, _numbers(centre)), q.point(straight, _numbers(t.point)))
        return float(np.dot(gap, q.turn(straight, n))) - height


def _numbers(v: Any) -> tuple:
    return tuple(float(x) for x in v)


def _turned(q: Pose, body: str) -> float:
    """How far a body has turned at pose q from the drawing (radians)."""
    ex = q.turn(body, (1.0, 0.0))
    return math.atan2(float(ex[1]), float(ex[0]))


def _inverse(q: Pose, body: str) -> Any:
    """The map from where points are at pose q back to where body's drawn points were."""
    origin = np.asarray(q.point(body, (0.0, 0.0)), dtype=float)
    ex = np.asarray(q.turn(body, (1.0, 0.0)), dtype=float)
    r = np.array([[ex[0], -ex[1]], [ex[1], ex[0]]])
    return lambda p: (np.asarray(p, dtype=float) - origin) @ r


def _turn_back(q: Pose, body: str, e: Any) -> np.ndarray:
    ex = np.asarray(q.turn(body, (1.0, 0.0)), dtype=float)
    r = np.array([[ex[0], -ex[1]], [ex[1], ex[0]]])
    return np.asarray(e, dtype=float) @ r


__all__ = ["Follow", "Point", "Touch", "differences", "find_touch", "outlines", "touch_row"]
