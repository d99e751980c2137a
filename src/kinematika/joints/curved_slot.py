"""A pin in a curved slot (planar `curved_slot`): the point `at` of the second body slides
along a curve fixed in the first — a circular arc (the body's `circle`) or any curve (its
`curve`); relative rotation is free.

Condition: the pin stays on the curve (`touching`, a point on a curve): at the velocity level
v_rel·n = 0, the relative velocity of the pin along the slot's tangent t; at the acceleration
level the relative acceleration has the normal part v_rel²/ρ towards the slot's centre of
curvature (ρ its radius there) besides the drag and Coriolis terms:

    a_P = a_P∈a + a_rel + 2 ω_a × v_rel,   a_rel = (dv_rel/dt) t + (v_rel²/ρ) n_c.

Its coordinate is the pin's displacement along the slot (arc length); the relative instant
centre of the two bodies lies on the slot's normal at the pin.

Example: a block whose pin P = (3, 4) runs in the ground's circular slot of radius 5 about
O; the block does not turn and P's x-velocity is 4. By hand, v_P is along the slot, normal
to OP: 3 v_x + 4 v_y = 0, so v_P = (4, −3), as every point of the block:

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("arc").point("O", 0, 0).point("P", 3, 4).point("Q", 3, 0)
    >>> m = m.body("ground", "O", circle=("O", 5)).body("block", "P", "Q")
    >>> slot = m.curved_slot("ground", "block", at="P")
    >>> sol = m.drive_omega("block", 0).drive_velocity("P", 4, along=(1, 0)).solve()
    >>> np.allclose(sol.velocity("P"), (4, -3)), np.allclose(sol.velocity("Q"), (4, -3))
    (True, True)
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Optional

from .positions import Residual
from .capabilities import Centre, Coordinate, PointOn
from ..errors import KinematikaError, Said
from ..shapes import Circle, Curve
from .derivatives import sliding
from .base import JointGeometry, JointKind, ModelJoint, Rows
from .touching import Follow, find_touch, outlines, touch_of, touch_row

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism, Scalar


class CurvedSlot(JointKind):
    """A pin in a slot along a circle or a curve."""

    name = "curved_slot"
    summary = "point `at` of the second body slides along the first body's circle or curve; rotation free"
    condition = "the pin's v_rel·n = 0 on the slot's curve"
    dimensions = (2,)
    coordinate = Coordinate.LENGTH
    slides = True
    guides_point = True
    touches = True
    centre = Centre.NORMAL
    centre_line = "normal"                 # the common normal at the pin
    fields = {"at": "required"}
    point_on = PointOn.B

    def conditions(self, dim: int) -> int:
        """One: the pin stays on the slot's curve; its motion along the slot and the relative
        rotation are free."""
        return 1

    def prepare(self, inst: Instant, joint: ModelJoint, near: object = None, touching: bool = True) -> JointGeometry:
        """The pin `at` on the first body's circle or curve at this instant: the contact (normal
        n, radius of curvature ρ) and `along`, the slot's tangent t = n turned a quarter turn (a
        circle's normal points outward, a curve's is its own). A first body without a circle or
        curve is a schema error naming the joint."""
        geo = super().prepare(inst, joint)
        curves = [s for s in inst.shapes[joint.a] if isinstance(s, (Circle, Curve))]
        if not curves:
            raise KinematikaError("schema", "curved-slot-outline", joint.where, body=joint.a)
        touch = geo.contact = find_touch(inst, joint, curves, outlines(inst, joint, joint.b, joint.at), near, touching)
        n = touch.normal                     # a circle's: outward; a curve's: its own normal
        geo.along = (-n[1], n[0]) if isinstance(touch.outline_a, Circle) else (n[1], -n[0])
        return geo

    def moved(self, geo: JointGeometry, inst: Instant, hint: object = None) -> Optional[JointGeometry]:
        """Found anew at the pose, near the sweep's last contact on the curve (whether the
        outlines touch there is for the caller to judge: a sweep's residual, a simulation's
        projection)."""
        return self.prepare(inst, geo.joint, hint, touching=False)

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """v_rel·n = 0 at the pin: its relative velocity is along the slot; at the acceleration
        level with the normal part v_rel²/ρ and Coriolis (`touching.touch_row`)."""
        j = geo.joint
        return [(touch_row(lv, j.a, j.b, touch_of(geo)), Said("row-curved-slot", point=f"{j.at}@{j.b}", body=j.a))]

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """The pin of the second body (the slot's curve is drawn as the first body's shape)."""
        from . import symbols     # drawing only (start-up)

        if view.at is None:
            return []
        return symbols.pin(view, ctx, body=None if view.b == ctx.frame else view.b)

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """The pin's distance from the slot's curve along its normal."""
        return Follow(geo.joint.a, geo.joint.b, touch_of(geo), geo.joint.id)

    def rate(self, geo: JointGeometry, lv: Level) -> Scalar:
        """The pin's speed along the slot, (v_P − v_P∈a)·t (at the acceleration level the
        tangential relative acceleration plus the Coriolis term's part along t):
        `derivatives.sliding` along the slot's tangent at the pin."""
        j = geo.joint
        return sliding(lv, j.a, j.b, geo.point_at(), geo.unit_along())

    def add(self, m: Mechanism, a: str, b: str, at: str, id: Optional[str] = None) -> str:
        """Point `at` of `b` slides in a slot of `a` along a's circle or curve."""
        return m.joint(self.name, a, b, id, at=at)


KIND = CurvedSlot()
