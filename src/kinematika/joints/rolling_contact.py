"""Rolling contacts: where two shapes touch, and how the geometric contact point moves.

Rolling without slipping keeps the two material points at the contact J at equal velocity;
differentiating that along the motion gives a_J(b) − a_J(a) = ω_rel × (v_J − J̇), where J̇ is
the velocity of the geometric contact point. That point is computed here for each pair of
shapes (circle–line, circle–circle outside or inside, disc–plane in 3D).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from ..algebra.vectors import add, cross3, dot, scale, sub
from ..errors import KinematikaError, Num, Said
from ..shapes import Circle, Disc, Line, Plane
from .base import JointGeometry, rounding_hint
from .tangency import circles_tangency, tangency
from .touching import closest

Instant = Any       # the instant (`engine.instant.Instant`): its shapes, points and algebra
Joint = Any         # the parsed joint (`model.model.Joint`)
Motion = Any        # the bodies' motion (`engine.motion.Motion`): their velocities and accelerations


@dataclass
class Contact:
    """The contact of a rolling or gear joint at this instant."""

    joint: Joint
    point: tuple                                   # J
    kind: str                                      # "circle-line", "external", "internal", "disc-plane"
    jdot: Callable[[Motion], tuple]                # velocity of the geometric point J
    jddot: Callable[[Motion], tuple]               # its acceleration
    normal: tuple = ()                             # unit normal at J (planar: from a towards b)
    centres: tuple = ()                            # ((body, centre), …) of the circles that touch
    ratio: Any = None                              # circles: J = Cₐ + ratio (C_b − Cₐ)
    line_body: str = ""                            # circle–line: the body of the line


def find_contact(inst: Instant, joint: Joint, touching: bool = True) -> Contact:
    """The contact of `joint`; a `geometry` error names the gap when the shapes do not touch
    (unless not `touching`: a pose between a motion's steps, off the conditions by the
    integrator's error, whose contact is the nearest pair of points)."""
    shapes_a, shapes_b = inst.shapes[joint.a], inst.shapes[joint.b]
    if not shapes_a or not shapes_b:
        missing = joint.a if not shapes_a else joint.b
        raise KinematikaError("schema", "rolling-needs-shapes", joint.where, kind=joint.type, body=missing,
                              dim=inst.space.dim)
    gap, contact = closest(shapes_a, shapes_b, lambda sa, sb: _pair(inst, joint, sa, sb), lambda c: c[0], joint,
                           Said("shapes-cannot-roll"))
    tol = 1e-6 * inst.scale
    if touching and abs(gap) > tol:
        raise KinematikaError("geometry", "no-touch", joint.where, body=joint.b, other=joint.a, gap=Num(gap, ".6g"),
                              hint=rounding_hint(gap, inst.scale, Said("the-contact-or-centre")))
    if joint.at is not None:
        dist = max(abs(x) for x in inst.numvec(sub(inst.points[joint.at], contact.point)))
        if dist > tol:
            raise KinematikaError("geometry", "contact-not-at", joint.where, point=joint.at, distance=Num(dist, ".6g"),
                                  hint=rounding_hint(dist, inst.scale, joint.at))
    if joint.internal is not None:
        if contact.kind not in ("external", "internal"):
            raise KinematikaError("schema", "internal-circles-only", joint.where, contact=contact.kind)
        if joint.internal != (contact.kind == "internal"):
            raise KinematikaError("geometry", "rolling-internal-wrong", joint.where, kind=joint.type,
                                  said="internal" if joint.internal else "external")
    return contact


def _pair(inst: Instant, joint: Joint, sa: Any, sb: Any) -> tuple[float, Contact] | None:
    if inst.space.dim == 3 and not {type(sa), type(sb)} <= {Disc, Plane}:
        return None
    if isinstance(sa, Circle) and isinstance(sb, Circle):
        return _circles(inst, joint, sa, sb)
    if isinstance(sa, Circle) and isinstance(sb, Line):
        return _circle_line(inst, joint, sa, joint.a, sb, joint.b, sign=-1)
    if isinstance(sa, Line) and isinstance(sb, Circle):
        return _circle_line(inst, joint, sb, joint.b, sa, joint.a, sign=1)
    if isinstance(sa, Disc) and isinstance(sb, Plane):
        return _disc_plane(inst, joint, sa, joint.a, sb, joint.b)
    if isinstance(sa, Plane) and isinstance(sb, Disc):
        return _disc_plane(inst, joint, sb, joint.b, sa, joint.a)
    return None


def _circles(inst: Instant, joint: Joint, ca: Circle, cb: Circle) -> tuple[float, Contact] | None:
    """J = Cₐ + μ (C_b − Cₐ), μ constant while rolling (the distance D stays Ra ± Rb)."""
    d = sub(cb.center, ca.center)
    dist = inst.num(dot(d, d)) ** 0.5
    if dist <= 1e-12 * inst.scale:
        return None   # concentric circles never roll on each other
    way = tangency(dist, inst.num(ca.radius), inst.num(cb.radius))
    mu = inst.backend.simplify(way.ratio(ca.radius, cb.radius))
    point = add(ca.center, scale(mu, d))
    sa, sb = joint.a, joint.b

    def jdot(motion: Motion) -> tuple:
        va, vb = motion.point_velocity(sa, ca.center), motion.point_velocity(sb, cb.center)
        return add(va, scale(mu, sub(vb, va)))

    def jddot(motion: Motion) -> tuple:
        aa, ab = motion.point_acceleration(sa, ca.center), motion.point_acceleration(sb, cb.center)
        return add(aa, scale(mu, sub(ab, aa)))

    normal = scale(way.sense / inst.backend.sqrt(dot(d, d)), d)
    return way.gap, Contact(joint, point, way.kind, jdot, jddot, tuple(inst.backend.simplify(c) for c in normal),
                            ((sa, ca.center), (sb, cb.center)), mu)


def _circle_line(inst: Instant, joint: Joint, c: Circle, cbody: str, ln: Line, lbody: str,
                 sign: int) -> tuple[float, Contact]:
    """J = C − h n, with n the line's normal (fixed in the line's body) and h = (C − A)·n."""
    sp = inst.space
    n = (-ln.direction[1], ln.direction[0])
    h = dot(sub(c.center, ln.through), n)
    hn = inst.num(h)
    gap = abs(hn) - inst.num(c.radius)
    h = inst.backend.simplify(c.radius if hn >= 0 else -c.radius)   # exact offset: the radius
    point = sub(c.center, scale(h, n))

    def jdot(motion: Motion) -> tuple:
        wl = motion.states[lbody].omega
        return sub(motion.point_velocity(cbody, c.center), scale(h, sp.cross(wl, n)))

    def jddot(motion: Motion) -> tuple:
        s = motion.states[lbody]
        n2 = add(sp.cross(s.alpha, n), sp.cross(s.omega, sp.cross(s.omega, n)))
        return sub(motion.point_acceleration(cbody, c.center), scale(h, n2))

    # normal from body a towards body b
    towards_circle = scale(1 if hn >= 0 else -1, n)
    normal = towards_circle if sign == 1 else scale(-1, towards_circle)
    return gap, Contact(joint, point, "circle-line", jdot, jddot, normal, ((cbody, c.center),),
                        line_body=lbody)


def _root(square: Any, inst: Instant) -> Any:
    """The positive root of `square`, each |e| in it written ±e by the sign e has at this
    instant (as the side of the plane is chosen): √(1 − sin² l) is cos l for the disc drawn,
    not |cos l|, so that formulas simplify and stay right on the drawn branch."""
    import sympy

    from ..algebra.fields import canonical

    root = sympy.sqrt(sympy.trigsimp(canonical(square)))
    return root.replace(lambda x: isinstance(x, sympy.Abs),
                        lambda x: x.args[0] if inst.num(x.args[0]) >= 0 else -x.args[0])


def _disc_plane(inst: Instant, joint: Joint, dc: Disc, dbody: str, pl: Plane,
                pbody: str) -> tuple[float, Contact]:
    """J = C + R w, w = −σ m/|m|, m = n − (n·a)a: the rim point nearest the plane.

    σ = ±1 is the side of the plane the centre is on, so that a disc below a plane (a wheel
    against a ceiling) touches with its highest point whichever way the normal is written.
    """
    a, n = dc.axis, pl.normal
    m = sub(n, scale(dot(n, a), a))
    if inst.num(dot(m, m)) < 1e-18:
        raise KinematikaError("geometry", "disc-flat-on-plane", joint.where, disc=dbody, plane=pbody)
    bk = inst.backend
    side = 1 if inst.num(dot(sub(dc.center, pl.through), n)) >= 0 else -1
    # |m|² = 1 − (n·a)² for unit n, a: the short form keeps symbolic roots simple
    norm_m = _root(1 - dot(n, a) ** 2, inst) if inst.symbolic else bk.sqrt(dot(m, m))
    w = tuple(bk.simplify(-side * x / norm_m) for x in m)
    reach = side * dc.radius                   # J = C − reach m/|m|
    point = add(dc.center, scale(dc.radius, w))
    gap = inst.num(dot(sub(point, pl.through), n))

    def derivatives(motion: Motion) -> tuple[tuple, tuple]:
        """(ṁ, m̈) from the turning of the disc's axis and of the plane's normal."""
        sd, sp_ = motion.states.get(dbody), motion.states.get(pbody)
        wd, ad = (sd.omega, sd.alpha) if sd else ((0, 0, 0), (0, 0, 0))
        wp, ap = (sp_.omega, sp_.alpha) if sp_ else ((0, 0, 0), (0, 0, 0))
        a1, n1 = cross3(wd, a), cross3(wp, n)
        a2 = add(cross3(ad, a), cross3(wd, a1))
        n2 = add(cross3(ap, n), cross3(wp, n1))
        na, na1 = dot(n, a), dot(n1, a) + dot(n, a1)
        na2 = dot(n2, a) + 2 * dot(n1, a1) + dot(n, a2)
        m1 = sub(sub(n1, scale(na1, a)), scale(na, a1))
        m2 = sub(sub(sub(n2, scale(na2, a)), scale(2 * na1, a1)), scale(na, a2))
        return m1, m2

    def jdot(motion: Motion) -> tuple:
        m1, _ = derivatives(motion)
        w1 = sub(scale(1 / norm_m, m1), scale(dot(m, m1) / norm_m ** 3, m))
        return sub(motion.point_velocity(dbody, dc.center), scale(reach, w1))

    def jddot(motion: Motion) -> tuple:
        m1, m2 = derivatives(motion)
        mm1 = dot(m, m1)
        w2 = scale(1 / norm_m, m2)
        w2 = sub(w2, scale(2 * mm1 / norm_m ** 3, m1))
        w2 = sub(w2, scale((dot(m1, m1) + dot(m, m2)) / norm_m ** 3, m))
        w2 = add(w2, scale(3 * mm1 ** 2 / norm_m ** 5, m))
        return sub(motion.point_acceleration(dbody, dc.center), scale(reach, w2))

    towards_disc = scale(side, n)
    normal = towards_disc if pbody == joint.a else scale(-1, towards_disc)
    return gap, Contact(joint, point, "disc-plane", jdot, jddot, normal)


def drawn_pair(inst: Instant, joint: Joint) -> tuple:
    """The two planar shapes (circles, lines) that touch at the drawn configuration, as
    `find_contact` chose them: a sweep follows their rolling."""
    best = None
    for sa in inst.shapes[joint.a]:
        for sb in inst.shapes[joint.b]:
            if isinstance(sa, Line) and isinstance(sb, Line):
                continue
            gap = _drawn_gap(sa, sb)
            if gap is not None and (best is None or gap < best[0]):
                best = (gap, sa, sb)
    if best is None:
        raise KinematikaError("schema", "sweep-rolling-only", joint.where)
    return best[1], best[2]


def _drawn_gap(sa: Any, sb: Any) -> float | None:
    if isinstance(sa, Circle) and isinstance(sb, Circle):
        return abs(circles_tangency(sa, sb).gap)
    if isinstance(sa, Line):
        sa, sb = sb, sa
    if isinstance(sa, Circle) and isinstance(sb, Line):
        n = (-sb.direction[1], sb.direction[0])
        return abs(abs(float(dot(sub(sa.center, sb.through), n))) - float(sa.radius))
    return None


def contact_of(geo: JointGeometry) -> Contact:
    """The contact a rolling pair's `prepare` found (`geo.contact`)."""
    assert isinstance(geo.contact, Contact), f"{geo.joint.where}: no contact found"
    return geo.contact
