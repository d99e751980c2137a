"""Rolling without slipping: the shapes of the two bodies (circle on line, circle on circle
outside or inside; in 3D a disc on a plane) touch at J and their material points there
have equal velocity.

Condition: contact is kept and v_J(b) = v_J(a). Differentiating along the motion:
a_J(b) − a_J(a) = ω_rel × (v_J(a) − J̇), J̇ the velocity of the geometric contact point
(`contact.Contact.jdot`). The relative instant centre of the pair is J.
"""
from __future__ import annotations

from typing import Any, Optional

from ..algebra.vectors import sub
from .base import AXES, JointGeometry, JointKind, Rows
from .contact import find_contact
from .derivatives import coincident


class Rolling(JointKind):
    """Two shapes rolling on each other."""

    name = "rolling"
    summary = "the bodies' shapes roll on each other without slipping"
    touches = True
    rolls = True
    route = "contact"
    fields = {"at": "optional", "internal": "optional"}

    def conditions(self, dim: int) -> int:
        return 2 if dim == 2 else 3

    def prepare(self, inst: Any, joint: Any) -> JointGeometry:
        geo = super().prepare(inst, joint)
        geo.contact = find_contact(inst, joint)
        return geo

    def rows(self, geo: JointGeometry, lv: Any) -> Rows:
        """v_J(b) − v_J(a) = 0; a_J(b) − a_J(a) − ω_rel × (v_J(a) − J̇) = 0."""
        j, sp = geo.joint, lv.space
        c = geo.contact
        diff = coincident(lv, j.a, j.b, c.point)
        if lv.accel:
            w_rel = sp.rot_sub(lv.w(j.b), lv.w(j.a))
            rolling_velocity = sub(lv.v(j.a, c.point), c.jdot(lv.motion))
            diff = sub(diff, sp.cross(w_rel, rolling_velocity))
        return [(x, f"no slip at the contact of {j.a} and {j.b} ({AXES[i]})") for i, x in enumerate(diff)]

    def add(self, m: Any, a: str, b: str, at: Optional[str] = None, id: Optional[str] = None) -> str:
        """The shapes of `a` and `b` roll on each other (touching at point `at`, if named)."""
        return m.joint(self.name, a, b, id, at=at)


KIND = Rolling()
