"""The slot (pin in a straight slot, planar): the point `at` of the second body slides
along a line fixed in the first; relative rotation is free.

Condition: (P_b − S)·n = 0, S on the slot's line, n its normal (fixed in a).
Velocity row: v_rel·n = 0; acceleration row: (a_Pb − a_Pa)·n + 2 v_rel·(ω_a × n) = 0,
the Coriolis term (`derivatives.sliding`). Its coordinate is the pin's displacement along
`along`; the relative instant centre lies on the normal to the slot through the pin.

Example: a Scotch yoke. A crank OA = (0, 2) turns at ω = 3 rad/s; its pin A runs in a
vertical slot of a yoke that slides along x. By hand, v_A = ω k × OA = (−6, 0), and the
yoke takes the component of v_A across its slot: v_yoke = (−6, 0):

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("yoke").point("O", 0, 0).point("A", 0, 2).point("B", 3, 0)
    >>> m = m.body("ground", "O").body("crank", "O", "A").body("yoke", "B")
    >>> pin = m.revolute("ground", "crank", at="O")
    >>> guide = m.prismatic("ground", "yoke", along=(1, 0))
    >>> slot = m.slot("yoke", "crank", at="A", along=(0, 1))
    >>> sol = m.drive_omega("crank", 3).solve()
    >>> np.allclose(sol.velocity("B"), (-6, 0))
    True
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .positions import Residual
from .capabilities import Centre, Chain, Coordinate, PointOn
from .base import JointGeometry, JointKind, ModelJoint, Rows, off_line
from .derivatives import sliding
from .positions import across
from ..errors import Said

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism, Scalar


class Slot(JointKind):
    """A pin in a slot."""

    name = "slot"
    summary = "point `at` of the second body slides along a line fixed in the first; rotation free"
    condition = "v_rel·n = 0 at the pin"
    dimensions = (2,)
    coordinate = Coordinate.LENGTH
    slides = True
    guides_point = True
    chain = Chain.PR                   # the slot's line in a, a slider block, the pin of b
    centre = Centre.NORMAL                 # on the normal to `along` at `at`
    centre_line = "slot"                   # the normal to the slot at the pin
    fields = {"at": "required", "along": "required"}
    point_on = PointOn.B

    def conditions(self, dim: int) -> int:
        """One: the pin stays on the slot's line; sliding along it and turning are free."""
        return 1

    def prepare(self, inst: Instant, joint: ModelJoint) -> JointGeometry:
        """The slot's direction and normal at this instant; a slot given by two points must
        have the pin on their line (`off_line`: else a geometry error with the gap)."""
        geo = super().prepare(inst, joint)
        off_line(inst, joint, geo)
        return geo

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """v_rel·n = 0 at the pin, n the slot's normal; the acceleration row adds the Coriolis
        term 2 v_rel·(ω_a × n)."""
        j = geo.joint
        return [(sliding(lv, j.a, j.b, geo.point_at(), geo.perps[0]), Said("row-slot", point=f"{j.at}@{j.b}", body=j.a))]

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """The pin's offset across the slot's line."""
        a, b = geo.joint.a, geo.joint.b
        return lambda q, _: across(q, a, b, geo.point_at(), geo.perps)

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """The slot of the first body (a rounded outline along its line) and the pin in it."""
        from . import symbols     # drawing only (start-up)

        if view.at is None or view.along is None:
            return []
        at, along = np.asarray(view.at, dtype=float), np.asarray(view.along, dtype=float)
        half = symbols.SLOT_WIDTH * ctx.size / 2
        if view.span is not None:
            p, q = (np.asarray(x, dtype=float) for x in view.span)
            d = symbols.unit(q - p)
            p, q = p - 2 * half * d, q + 2 * half * d
            if float((at - p) @ d) < 0 or float((at - q) @ d) > 0:   # pin beyond the given span
                ts = [float((x - p) @ d) for x in (p, q, at)]
                p, q = p + (min(ts) - 2 * half) * d, p + (max(ts) + 2 * half) * d
        else:
            p, q = at - 0.15 * ctx.size * along, at + 0.15 * ctx.size * along
        colour = "ground" if view.a == ctx.frame else f"body:{view.a}"
        outline = symbols.Mark("polygon", symbols.stadium(p, q, half), colour, "white", 2.0, zorder=3,
                               gid=f"slot:{view.id}", moves_with=None if view.a == ctx.frame else view.a)
        return [outline, *symbols.pin(view, ctx, body=None if view.b == ctx.frame else view.b)]

    def rate(self, geo: JointGeometry, lv: Level) -> Scalar:
        """(v_Pb − v_Pa)·u along the slot u (its derivative with the Coriolis term)."""
        j = geo.joint
        return sliding(lv, j.a, j.b, geo.point_at(), geo.unit_along())

    def add(self, m: Mechanism, a: str, b: str, at: str, along: Any, id: Optional[str] = None) -> str:
        """Point `at` of `b` slides in a slot of `a` along `along`: `m.slot("rocker", "crank", at="A", along=("O4", "B"))`."""
        return m.joint(self.name, a, b, id, at=at, along=along)


KIND = Slot()
