"""The position constraints: the integrals of the engine's joint and driver rows.

The engine writes each joint as the time derivative of a geometric condition (its rows);
here are the conditions themselves, row for row in the engine's order, so that the
engine's velocity matrix is their Jacobian in the pose coordinates of `poses`:

- revolute: the two material points at `at` coincide (x, y);
- prismatic: no relative rotation; the offset across the guide is kept;
- slot: the pin stays on the line fixed in the slotted body;
- weld: no relative rotation; the material points at the reference point coincide;
- rolling and gear: the contact is kept (normal) and the arcs rolled are equal, no slip
  (tangential), as one vector whose components are the engine's x and y rows;
- drivers: each driver's coordinate keeps its drawn value, except the swept one, which
  advances by the increment;
- the idle spin of a link between two spherical joints has no position form (ω·AB = 0 is
  not integrable): its residual is 0, so that each Newton step carries no such spin.
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from ..engine.instant import Instant
from ..shapes import Circle, Line
from ..engine.idle import idle_links
from ..joints import JointGeometry
from ..errors import KinematikaError
from ..model.model import Driver, Joint
from .plan import Plan
from .poses import Poses, exp_rotation

Rows = Callable[[Poses, float], list]          # (poses, increment) -> residual rows


def residual_functions(inst: Instant, geos: dict[str, JointGeometry], plan: Plan) -> list[tuple[str, Rows]]:
    """(where, rows) for every joint then every driver, in the engine's row order."""
    out: list[tuple[str, Rows]] = []
    ref = inst.ref
    for j in inst.model.joints:
        out.append((j.where, _joint(inst, j, geos[j.id], ref)))
    for d in inst.model.drivers:
        out.append((d.where, _driver(inst, d, geos, plan)))
    for body, _, _ in idle_links(inst):
        out.append((f"bodies.{body}", lambda q, dq: [0.0]))
    return out


def _joint(inst: Instant, j: Joint, geo: JointGeometry, ref: tuple) -> Rows:
    a, b = j.a, j.b
    spatial = inst.space.dim == 3
    if j.type in ("revolute", "spherical"):
        p0 = geo.at
        if not spatial or j.type == "spherical":
            return lambda q, _: _sub(q.point(b, p0), q.point(a, p0))
        return lambda q, _: _sub(q.point(b, p0), q.point(a, p0)) + _turning(q, a, b, geo)
    if j.type == "prismatic":
        p0 = geo.at if geo.at is not None else ref
        return lambda q, _: q.rotation_error(a, b) + _across(q, a, b, p0, geo.perps)
    if j.type == "cylindrical":
        return lambda q, _: _turning(q, a, b, geo) + _across(q, a, b, geo.at, geo.perps)
    if j.type == "slot":
        return lambda q, _: _across(q, a, b, geo.at, geo.perps)
    if j.type == "weld":
        return lambda q, _: q.rotation_error(a, b) + _sub(q.point(b, ref), q.point(a, ref))
    if j.type in ("rolling", "gear") and not spatial:
        return _rolling(inst, j, geo)
    raise KinematikaError("schema", f"a sweep cannot follow a {j.type} joint{' in 3D' if spatial else ''}: "
                          "its condition is on velocities only, so the positions depend on the path "
                          "taken", j.where)


def _across(q: Poses, a: str, b: str, p0: tuple, perps: list) -> list:
    """The offset of b's point from a's across each direction fixed in a (sliding pairs)."""
    gap = _sub(q.point(b, p0), q.point(a, p0))
    return [_dot(gap, q.turn(a, n)) for n in perps]


def _turning(q: Poses, a: str, b: str, geo: JointGeometry) -> list:
    """3D: b's axis stays along a's: e_b·p₂ and e_b·p₁ (p₁, p₂ ⊥ e fixed in a), signed so that
    their rates are the engine's rows (ω_b − ω_a)·p₁ and (ω_b − ω_a)·p₂."""
    e = q.turn(b, geo.axis)
    return [-_dot(e, q.turn(a, geo.perps[1])), _dot(e, q.turn(a, geo.perps[0]))]


def _rolling(inst: Instant, j: Joint, geo: JointGeometry) -> Rows:
    """Circle on circle: Φ = (D − (ρa − ρb)) u + ((ρa − ρb)(ψ − ψ₀) + ρb φb − ρa φa) τ.

    With u the unit vector from centre a to centre b (angle ψ), τ = k × u, and J = Cₐ + ρₐ u
    = C_b + ρ_b u the contact (signed distances along u). Circle on line: the centre keeps
    its distance to the line and advances along it by the arc rolled.
    """
    ca, cb = _shape_pair(inst, j)
    a, b = j.a, j.b
    kind = geo.contact.kind
    if isinstance(ca, Circle) and isinstance(cb, Circle):
        ra, rb = float(ca.radius), float(cb.radius)
        rho_a, rho_b = {"external": (ra, -rb)}.get(kind, (ra, rb) if ra >= rb else (-ra, -rb))
        gap = rho_a - rho_b
        d0 = _sub(cb.center, ca.center)
        psi0 = math.atan2(d0[1], d0[0])

        def circles(q: Poses, _: float) -> list:
            d = _sub(q.point(b, cb.center), q.point(a, ca.center))
            dist = math.hypot(*d)
            u = (d[0] / dist, d[1] / dist)
            psi = q.aux.get(j.id, psi0)
            psi += _wrap(math.atan2(d[1], d[0]) - psi)
            slip = gap * (psi - psi0) + rho_b * q.angle(b) - rho_a * q.angle(a)
            return [(dist - gap) * u[0] - slip * u[1], (dist - gap) * u[1] + slip * u[0]]

        circles.key = j.id
        circles.aux = lambda q: _psi(q, j.id, psi0, _sub(q.point(b, cb.center), q.point(a, ca.center)))
        return circles
    circle, cbody, line, lbody, sign = ((ca, a, cb, b, -1.0) if isinstance(ca, Circle)
                                        else (cb, b, ca, a, 1.0))
    e0 = line.direction
    n0 = (-e0[1], e0[0])
    rel0 = _sub(circle.center, line.through)
    side = 1.0 if _dot(rel0, n0) >= 0 else -1.0
    r = float(circle.radius)
    x0 = _dot(rel0, e0)

    def on_line(q: Poses, _: float) -> list:
        e, n = q.turn(lbody, e0), q.turn(lbody, n0)
        rel = _sub(q.point(cbody, circle.center), q.point(lbody, line.through))
        along = _dot(rel, e) - x0 + side * r * (q.angle(cbody) - q.angle(lbody))
        across = _dot(rel, n) - side * r
        return [sign * (along * e[0] + across * n[0]), sign * (along * e[1] + across * n[1])]

    return on_line


def _shape_pair(inst: Instant, j: Joint) -> tuple:
    """The two shapes that touch at the drawn configuration (as `find_contact` chose them)."""
    best = None
    for sa in inst.shapes[j.a]:
        for sb in inst.shapes[j.b]:
            if isinstance(sa, Line) and isinstance(sb, Line):
                continue
            gap = _gap(sa, sb)
            if gap is not None and (best is None or gap < best[0]):
                best = (gap, sa, sb)
    if best is None:
        raise KinematikaError("schema", "a sweep follows rolling of circles and lines only", j.where)
    return best[1], best[2]


def _gap(sa, sb) -> float | None:
    if isinstance(sa, Circle) and isinstance(sb, Circle):
        dist = math.dist(sa.center, sb.center)
        ra, rb = float(sa.radius), float(sb.radius)
        return min(abs(dist - ra - rb), abs(dist - abs(ra - rb)))
    if isinstance(sa, Line):
        sa, sb = sb, sa
    if isinstance(sa, Circle) and isinstance(sb, Line):
        n = (-sb.direction[1], sb.direction[0])
        return abs(abs(_dot(_sub(sa.center, sb.through), n)) - float(sa.radius))
    return None


def _psi(q: Poses, key: str, psi0: float, d: tuple) -> float:
    psi = q.aux.get(key, psi0)
    return psi + _wrap(math.atan2(d[1], d[0]) - psi)


def _driver(inst: Instant, d: Driver, geos: dict[str, JointGeometry], plan: Plan) -> Rows:
    """The driver's coordinate minus its drawn value, minus the increment when it is swept."""
    swept = d is plan.driver
    spatial = inst.space.dim == 3
    j = plan.joint
    sign = 1.0 if j.a == inst.model.frame else -1.0      # the coordinate is j.b relative to j.a
    if d.kind == "joint":
        geo = geos[d.joint]
        jd = geo.joint
        if jd.type == "revolute":
            return lambda q, dq: [q.axis_angle_error(jd.a, jd.b, geo.axis, dq if swept else 0.0)]
        p0 = geo.at if geo.at is not None else inst.ref
        return lambda q, dq: [_dot(_sub(q.point(jd.b, p0), q.point(jd.a, p0)), q.turn(jd.a, geo.along))
                              - (dq if swept else 0.0)]
    if d.kind == "omega":
        rel = d.relative_to
        if not spatial:
            return lambda q, dq: q.rotation_error(rel, d.body, sign * dq if swept else 0.0)
        axis = np.asarray(geos[j.id].axis if swept else (0, 0, 1), dtype=float)
        return lambda q, dq: q.rotation_error(rel, d.body, exp_rotation(sign * dq * axis) if swept else None)
    p0 = inst.points[d.point.point]
    body, rel = d.point.body, d.relative_to
    along = None
    if d.along is not None:
        along = tuple(float(c) for c in inst.unit(inst.vector(d.along, d.where), d.where))

    def target(dq: float) -> list:
        """The drawn point's displacement when the swept joint has turned or slid by dq."""
        if not swept or dq == 0.0:
            return [0.0] * len(p0)
        if j.type == "prismatic":
            return [sign * dq * c for c in geos[j.id].along]
        r = np.subtract(p0, geos[j.id].at)
        axis = np.asarray(geos[j.id].axis if spatial else (0.0, 0.0, 1.0))
        if not spatial:
            r = np.append(r, 0.0)
        moved = exp_rotation(sign * dq * axis) @ r - r
        return moved[:len(p0)].tolist()

    def velocity(q: Poses, dq: float) -> list:
        moved = _sub(_sub(q.point(body, p0), q.point(rel, p0) if rel else p0), target(dq))
        return [_dot(moved, along)] if along is not None else moved

    return velocity


def _sub(p, r) -> list:
    return [x - y for x, y in zip(p, r)]


def _dot(p, r) -> float:
    return sum(x * y for x, y in zip(p, r))


def _wrap(x: float) -> float:
    return (x + math.pi) % (2 * math.pi) - math.pi
