"""A cam and its follower (planar `cam`): the first body carries a cam (its `cam:` shape: a
motion program or measured profile, base circle and follower, `kinematika.cams`); the
second is the follower, touching it with its point `at` (a knife edge on the profile, a
roller's centre on the pitch curve) or its `line` (a flat face on the profile).

Condition: the follower keeps touching the cam, one scalar condition — a higher pair
(`touching`: velocity (v_Jb − v_Ja)·n = 0 along the common normal, acceleration with the
curvature terms of the equivalent link). Over a cycle it reproduces the program: a
translating follower's s(θ), v = s'·θ̇, a = s''·θ̇² + s'·θ̈. The relative instant centre
of cam and follower lies on the common normal at the contact (for a roller, through its
centre); the pressure angle is that normal's angle from the follower's direction of motion.
"""
from __future__ import annotations

from typing import Any, Optional

import numpy as np

from ..errors import KinematikaError
from ..shapes import Cam as CamShape
from ..shapes import Line
from . import symbols
from .base import JointGeometry, JointKind, Rows
from .touching import Follow, Point, find_touch, touch_row


class Cam(JointKind):
    """A cam and its follower."""

    name = "cam"
    summary = "the first body's cam drives the second, its follower (knife edge or roller at `at`, or flat face)"
    dimensions = (2,)
    touches = True
    route = "contact"
    centre = "normal"
    fields = {"at": "optional"}
    point_on = "b"

    def conditions(self, dim: int) -> int:
        """One: the follower keeps touching the cam (a higher pair, planar only)."""
        return 1

    def prepare(self, inst: Any, joint: Any, near: Optional[float] = None) -> JointGeometry:
        """The contact at this instant: a flat face (the follower's `line`) on the cam's
        profile, or the point `at` on the profile (a knife edge) or on the pitch curve (a
        roller's centre, `roller` its radius), the branch nearest `near` when given. A cam joint
        whose first body has no `cam:` shape, a flat face without a line or an edge without `at`
        is a schema error naming the joint."""
        geo = super().prepare(inst, joint)
        cams = [s for s in inst.shapes[joint.a] if isinstance(s, CamShape)]
        if not cams:
            raise KinematikaError("schema", f"a cam joint's first body carries the cam: give {joint.a!r} a "
                                  "`cam:` shape", joint.where)
        cam = cams[0]
        contact = cam.design.follower.contact
        if contact.touches_with_face:
            faces = [s for s in inst.shapes[joint.b] if isinstance(s, Line)]
            if not faces:
                raise KinematikaError("schema", f"a flat-faced follower touches with its face: give {joint.b!r} "
                                      "a `line` (the face)", joint.where)
            geo.contact = find_touch(inst, joint, [cam.profile], faces, near)
        else:
            if joint.at is None:
                what = "roller's centre" if contact.radius > 0 else "knife edge"
                raise KinematikaError("schema", f"a cam joint needs `at`: the follower's {what}", joint.where)
            curve = cam.pitch if contact.radius > 0 else cam.profile
            geo.contact = find_touch(inst, joint, [curve], [Point(inst.points[joint.at], joint.at)], near)
            geo.roller = float(contact.radius)
        return geo

    def moved(self, geo: JointGeometry, inst: Any, hint: Any = None) -> Optional[JointGeometry]:
        """Found anew at the pose, near the sweep's last contact on the curve."""
        return self.prepare(inst, geo.joint, hint)

    def rows(self, geo: JointGeometry, lv: Any) -> Rows:
        """(v_Jb − v_Ja)·n = 0 along the common normal at the contact J (at the acceleration
        level with the curvature terms, `touching.touch_row`)."""
        j = geo.joint
        return [(touch_row(lv, j.a, j.b, geo.contact), f"the follower {j.b} keeps touching the cam {j.a}")]

    def symbol(self, view: Any, ctx: Any) -> list:
        """The follower's roller (a circle about its centre `at`, moving with it) or knife
        edge (a pin), and the contact point."""
        out = symbols.contact_dot(view, ctx)
        if view.at is None:
            return out
        if view.radius > 0:
            roller = symbols.ring(np.asarray(view.at, dtype=float), view.radius)
            return [symbols.Mark("polygon", roller, f"body:{view.b}", "white", 1.8, zorder=5,
                                 gid=f"joint:{view.id}", moves_with=view.b), *symbols.pin(view, ctx, body=view.b), *out]
        return [*symbols.pin(view, ctx, body=view.b), *out]

    def residual(self, inst: Any, geo: JointGeometry, ref: tuple) -> Any:
        """The follower's gap from the cam along the normal."""
        return Follow(geo.joint.a, geo.joint.b, geo.contact, geo.joint.id)

    def add(self, m: Any, a: str, b: str, at: Optional[str] = None, id: Optional[str] = None) -> str:
        """The cam of `a` drives the follower `b` (touching at its point `at`, or with its face)."""
        return m.joint(self.name, a, b, id, at=at)


KIND = Cam()
