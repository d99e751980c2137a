"""Curves in contact (planar `contact`): the outlines of two bodies — circles, lines, curves
through points, a cam's profile, or a body's point `at` — touch at one point and may slide
on each other. Rolling without slipping is the `rolling` kind; this one lets them slip.

Condition: the contact is kept, one scalar condition (`touching`): at the velocity level
(v_Jb − v_Ja)·n = 0, no approach along the common normal n; at the acceleration level the
second derivative of the distance between the centres of curvature Ca and Cb (the pair's
equivalent link), with the curvature terms. The sliding speed is (v_Jb − v_Ja)·t. The
relative instant centre of the two bodies lies on the common normal at J.

Example: an eccentric cam — a circle of radius 2 about C = (1, 0), turning at ω = 3 rad/s
about O — under a flat-faced follower that slides vertically, touching it at (1, 2). By
hand, the face stays at y = e sin θ + R, so it rises at e ω cos θ = 1 × 3 × 1 = 3:

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("eccentric").point("O", 0, 0).point("C", 1, 0).point("F", 1, 2)
    >>> m = m.body("ground", "O").body("cam", "O", "C", circle=("C", 2))
    >>> m = m.body("follower", "F", line=("F", (1, 0)))
    >>> pin = m.revolute("ground", "cam", at="O")
    >>> guide = m.prismatic("ground", "follower", along=(0, 1))
    >>> touch = m.contact("cam", "follower")
    >>> np.allclose(m.drive_omega("cam", 3).solve().velocity("F"), (0, 3))
    True
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Optional

from .positions import Residual
from .capabilities import Centre, PointOn
from ..errors import Said
from .base import JointGeometry, JointKind, ModelJoint, Rows
from .touching import Follow, find_touch, outlines, touch_of, touch_row

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism


class Contact(JointKind):
    """Two outlines that touch and slide."""

    name = "contact"
    summary = "the bodies' outlines (circles, lines, curves, a cam's profile, or point `at`) touch and may slide"
    condition = "(v_Jb − v_Ja)·n = 0 along the common normal"
    dimensions = (2,)
    touches = True
    centre = Centre.NORMAL
    centre_line = "normal"                 # the common normal at the contact
    fields = {"at": "optional"}
    point_on = PointOn.B
    keeps = "row-touching"          # the message of its condition (errors' catalogue)
    """The condition's words (a row's label), with the bodies' names."""

    def conditions(self, dim: int) -> int:
        """One: the outlines keep touching; sliding along the tangent is free."""
        return 1

    def prepare(self, inst: Instant, joint: ModelJoint, near: object = None, touching: bool = True) -> JointGeometry:
        """Where the two outlines touch at this instant: the contact J, common normal n and
        radii of curvature (`geo.contact`), the branch nearest `near` when given."""
        geo = super().prepare(inst, joint)
        first, second = self.outlines(inst, joint, geo)
        geo.contact = find_touch(inst, joint, first, second, near, touching)
        return geo

    def outlines(self, inst: Instant, joint: ModelJoint, geo: JointGeometry) -> tuple[list, list]:
        """The outlines that touch: the first body's (circles, lines, curves, a cam's
        profile) and the second's, or its point `at`."""
        return outlines(inst, joint, joint.a), outlines(inst, joint, joint.b, joint.at)

    def moved(self, geo: JointGeometry, inst: Instant, hint: object = None) -> Optional[JointGeometry]:
        """Found anew at the pose, near the sweep's last contact on the curve (whether the
        outlines touch there is for the caller to judge: a sweep's residual, a simulation's
        projection)."""
        return self.prepare(inst, geo.joint, hint, touching=False)

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """(v_Jb − v_Ja)·n = 0: no approach along the common normal (at the acceleration level
        with the curvature terms, `touching.touch_row`)."""
        j = geo.joint
        return [(touch_row(lv, j.a, j.b, touch_of(geo)), Said(self.keeps, a=j.a, b=j.b))]

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """The contact point (a still figure only)."""
        from . import symbols     # drawing only (start-up)

        return symbols.contact_dot(view, ctx)

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """The gap between the outlines along the normal (0 while they touch)."""
        return Follow(geo.joint.a, geo.joint.b, touch_of(geo), geo.joint.id)

    def add(self, m: Mechanism, a: str, b: str, at: Optional[str] = None, id: Optional[str] = None) -> str:
        """The outlines of `a` and `b` touch and may slide (`at`: b's point that touches)."""
        return m.joint(self.name, a, b, id, at=at)


KIND = Contact()
