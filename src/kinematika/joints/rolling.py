"""Rolling without slipping: the shapes of the two bodies (circle on line, circle on circle
outside or inside; in 3D a disc on a plane) touch at J and their material points there
have equal velocity.

Condition: contact is kept and v_J(b) = v_J(a). Differentiating along the motion:
a_J(b) − a_J(a) = ω_rel × (v_J(a) − J̇), J̇ the velocity of the geometric contact point
(`contact.Contact.jdot`). The relative instant centre of the pair is J.

Example: a wheel of radius 2 rolling on the ground's line y = 0, turning at ω = −3 rad/s
(clockwise). By hand, the contact J is the instant centre: v_C = ω k × JC = −3 k × (0, 2)
= (6, 0) at the centre, and twice that, (12, 0), at the top T:

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("wheel").point("J", 0, 0).point("C", 0, 2).point("T", 0, 4)
    >>> m = m.body("ground", "J", line=("J", (1, 0))).body("wheel", "J", "C", "T", circle=("C", 2))
    >>> roll = m.rolling("ground", "wheel")
    >>> sol = m.drive_omega("wheel", -3).solve()
    >>> np.allclose(sol.velocity("C"), (6, 0)), np.allclose(sol.velocity("T"), (12, 0))
    (True, True)
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any, Optional

from .positions import Residual
from .capabilities import Centre
from ..algebra.vectors import sub
from ..errors import Said
from ..shapes import Circle, Disc, Plane
from .base import AXES, JointGeometry, JointKind, ModelJoint, Rows
from .holonomic import Holonomic
from .derivatives import coincident
from .positions import continued, differences, dot, wrap
from .rolling_contact import contact_of, drawn_pair, find_contact
from .tangency import circles_tangency

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism, Pose


class Rolling(JointKind):
    """Two shapes rolling on each other."""

    name = "rolling"
    summary = "the bodies' shapes roll on each other without slipping"
    condition = "v_J(b) − v_J(a) = 0 at the contact"
    touches = True
    rolls = True
    centre_path = True                # a wheel's centre runs parallel to the profile it rolls on
    velocity_only = (3,)              # a disc on a plane: where it has rolled depends on the path
    centre = Centre.CONTACT
    fields = {"at": "optional", "internal": "optional"}

    def conditions(self, dim: int) -> int:
        """Two in the plane (the contact kept, no slip), three in space (a disc on a plane:
        v_J(b) = v_J(a))."""
        return 2 if dim == 2 else 3

    def prepare(self, inst: Instant, joint: ModelJoint) -> JointGeometry:
        """The contact of the two shapes at this instant (`geo.contact`: the point J, its
        normal, and its motion J̇ for the acceleration rows)."""
        geo = super().prepare(inst, joint)
        geo.contact = find_contact(inst, joint)
        return geo

    def moved(self, geo: JointGeometry, inst: Instant, hint: object = None) -> Optional[JointGeometry]:
        """The carried geometry with the contact found anew where the circles now touch (the
        drawn contact point `at` does not travel with either body); whether they touch is for
        the caller to judge (a sweep's residual, a simulation's projection)."""
        geo.contact = find_contact(inst, replace(geo.joint, at=None), touching=False)
        return geo

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """v_J(b) − v_J(a) = 0; a_J(b) − a_J(a) − ω_rel × (v_J(a) − J̇) = 0."""
        j, sp = geo.joint, lv.space
        c = contact_of(geo)
        diff = coincident(lv, j.a, j.b, c.point)
        if lv.accel:
            w_rel = sp.rot_sub(lv.w(j.b), lv.w(j.a))
            rolling_velocity = sub(lv.v(j.a, c.point), c.jdot(lv.motion))
            diff = sub(diff, sp.cross(w_rel, rolling_velocity))
        return [(x, Said("row-no-slip", body=j.a, other=j.b, axis=AXES[i])) for i, x in enumerate(diff)]

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """The contact point (a still figure only: it is no body's point)."""
        from . import symbols     # drawing only (start-up)

        return symbols.contact_dot(view, ctx)

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """Planar circles and lines: the contact kept (normal) and the arcs rolled equal
        (tangential), as one vector whose components are the engine's x and y rows.

        Circle on circle: Φ = (D − (ρa − ρb)) u + ((ρa − ρb)(ψ − ψ₀) + ρb φb − ρa φa) τ, u the
        unit vector from centre a to centre b (angle ψ), τ = k × u, J = Cₐ + ρₐ u = C_b + ρ_b u
        the contact (signed distances along u). Circle on line: the centre keeps its distance
        to the line and advances along it by the arc rolled.
        """
        if inst.space.dim == 3:
            return super().residual(inst, geo, ref)
        j = geo.joint
        ca, cb = drawn_pair(inst, j)
        a, b = j.a, j.b
        if isinstance(ca, Circle) and isinstance(cb, Circle):
            return _circles(j.id, a, b, ca, cb)
        if isinstance(ca, Circle):
            return _on_line(ca, a, cb, b, -1.0)
        return _on_line(cb, b, ca, a, 1.0)

    def holonomic(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Holonomic:
        """In the plane, the whole condition (`residual`). A disc on a plane rolls without
        slipping on velocities only (where it has rolled to depends on the path), and keeps
        touching on positions: the gap σ n·(C − P) − R |n − (n·a) a| (C the disc's centre, a its
        axis, P and n the plane's point and normal, σ the side of the plane the disc is on), whose
        rate is σ n·(v_J(disc) − v_J(plane)), the engine's rows along the normal."""
        if inst.space.dim == 2:
            return super().holonomic(inst, geo, ref)
        return _disc_on_plane(inst, geo.joint)

    def add(self, m: Mechanism, a: str, b: str, at: Optional[str] = None, id: Optional[str] = None) -> str:
        """The shapes of `a` and `b` roll on each other (touching at point `at`, if named)."""
        return m.joint(self.name, a, b, id, at=at)


KIND = Rolling()


def _circles(key: str, a: str, b: str, ca: Circle, cb: Circle) -> Any:
    """Circle on circle, outside or inside (as they touch at the drawing, `tangency`)."""
    rho_a, rho_b = circles_tangency(ca, cb).places(float(ca.radius), float(cb.radius))
    gap = rho_a - rho_b
    d0 = differences(cb.center, ca.center)
    psi0 = math.atan2(d0[1], d0[0])

    def circles(q: Pose, _: float) -> list:
        d = differences(q.point(b, cb.center), q.point(a, ca.center))
        dist = math.hypot(*d)
        u = (d[0] / dist, d[1] / dist)
        psi = q.aux.get(key, psi0)
        psi += wrap(math.atan2(d[1], d[0]) - psi)
        slip = arc_slip(rho_a, rho_b, psi - psi0, q.angle(a), q.angle(b))
        return [(dist - gap) * u[0] - slip * u[1], (dist - gap) * u[1] + slip * u[0]]

    circles.key = key  # type: ignore[attr-defined]  # the continued angle's key and updater ride on the function (`simulate.holonomic`)
    circles.aux = lambda q: continued(q, key, psi0, differences(q.point(b, cb.center),  # type: ignore[attr-defined]  # (as key)
                                                                q.point(a, ca.center)))
    return circles


def _disc_on_plane(inst: Instant, j: Any) -> Holonomic:
    """The gap between a disc and the plane it rolls on, and its rate's weights on the rows."""
    import numpy as np

    disc_body, plane_body = (j.a, j.b) if any(isinstance(s, Disc) for s in inst.shapes[j.a]) else (j.b, j.a)
    disc = next(s for s in inst.shapes[disc_body] if isinstance(s, Disc))
    plane = next(s for s in inst.shapes[plane_body] if isinstance(s, Plane))
    c0, a0, r = (np.asarray(v, dtype=float) for v in (disc.center, disc.axis, (float(disc.radius),)))
    p0, n0 = np.asarray(plane.through, dtype=float), np.asarray(plane.normal, dtype=float)
    side = 1.0 if float(n0 @ (c0 - p0)) >= 0 else -1.0
    sign = side if disc_body == j.b else -side          # the rows are v_J(b) − v_J(a)

    def gap(q: Pose, _: float) -> list:
        a = np.asarray(q.turn(disc_body, tuple(a0)))
        n = np.asarray(q.turn(plane_body, tuple(n0)))
        centre = np.asarray(q.point(disc_body, tuple(c0))) - np.asarray(q.point(plane_body, tuple(p0)))
        return [side * float(n @ centre) - float(r[0]) * float(np.linalg.norm(n - (n @ a) * a))]

    def weights(q: Pose) -> list:
        return [[sign * float(x) for x in q.turn(plane_body, tuple(n0))]]

    return Holonomic(gap, weights)


def arc_slip(rho_a: Any, rho_b: Any, psi: Any, phi_a: Any, phi_b: Any) -> Any:
    """The arcs rolled on a's circle less those on b's, since the drawing, when the line of
    centres has turned by ψ and the bodies by φa, φb: (ρa − ρb) ψ + ρb φb − ρa φa, ρa and ρb
    the contact's places along the line of centres (`tangency.Tangency.places`). Rolling
    without slipping keeps it 0 (on numbers, formulas or arrays): solved for φb, a planet
    (radius r) on a fixed sun (R) whose arm turns by ψ turns by (R + r) ψ / r, and together
    for every pair of a gear train, Willis's equations (`sweep.carried`)."""
    return (rho_a - rho_b) * psi + rho_b * phi_b - rho_a * phi_a


def _on_line(circle: Any, cbody: str, line: Any, lbody: str, sign: float) -> Any:
    """A circle rolling on a line: its centre keeps its distance to the line and advances
    along it by the arc rolled."""
    e0 = line.direction
    n0 = (-e0[1], e0[0])
    rel0 = differences(circle.center, line.through)
    side = 1.0 if dot(rel0, n0) >= 0 else -1.0
    r = float(circle.radius)
    x0 = dot(rel0, e0)

    def on_line(q: Pose, _: float) -> list:
        e, n = q.turn(lbody, e0), q.turn(lbody, n0)
        rel = differences(q.point(cbody, circle.center), q.point(lbody, line.through))
        along = dot(rel, e) - x0 + side * r * (q.angle(cbody) - q.angle(lbody))
        across = dot(rel, n) - side * r
        return [sign * (along * e[0] + across * n[0]), sign * (along * e[1] + across * n[1])]

    return on_line
