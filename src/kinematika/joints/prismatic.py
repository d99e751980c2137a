"""The prismatic joint (sliding pair, P): the second body slides along a direction fixed in
the first, without turning relative to it.

Condition: ω_b = ω_a, and (Q_b − Q_a)·n = 0 for the guide's normals n (fixed in a).
Velocity rows: ω_b − ω_a = 0, v_rel·n = 0; acceleration rows add the Coriolis term
2 v_rel·(ω_a × n) (`derivatives.sliding`). Its coordinate is b's displacement along
`along`; the relative instant centre is at infinity, perpendicular to `along`.

Example: a slider on a guide along (3, 4), its joint driven at 2 (length per second). By
hand, every point of the slider moves at 2 × (3, 4)/5 = (1.2, 1.6):

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("slider").point("O", 0, 0).point("B", 1, 1)
    >>> m = m.body("ground", "O").body("slider", "B")
    >>> guide = m.prismatic("ground", "slider", along=(3, 4))
    >>> sol = m.drive_joint(guide, 2).solve()
    >>> np.allclose(sol.velocity("B"), (1.2, 1.6)), np.allclose(sol.omega("slider"), 0)
    (True, True)
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from .positions import Residual
from .capabilities import Centre, Chain, Coordinate
from .base import AXES, JointGeometry, JointKind, ModelJoint, Rows
from .derivatives import same_rotation, sliding
from .positions import across
from ..errors import Said

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism, Scalar


class Prismatic(JointKind):
    """A slider on a straight guide."""

    name = "prismatic"
    summary = "the second body slides along a direction fixed in the first; no relative rotation"
    condition = "ω_b − ω_a = 0; v_rel·n = 0 across the guide"
    sweepable = True
    coordinate = Coordinate.LENGTH
    slides = True
    chain = Chain.P
    centre = Centre.INFINITY
    fields = {"along": "required", "axis": "optional in 3D"}

    def conditions(self, dim: int) -> int:
        """Two in the plane (no relative rotation, no motion across the guide), five in space
        (only the slide along the guide is free)."""
        return 2 if dim == 2 else 5

    def prepare(self, inst: Instant, joint: ModelJoint) -> JointGeometry:
        """In 3D a prismatic pair given by its `axis` alone slides along that axis: `along` is
        the axis and the guide's normals its two perpendiculars."""
        geo = super().prepare(inst, joint)
        if inst.space.dim == 3 and geo.along is None:
            geo.along = geo.axis
            geo.perps = inst.space.perpendiculars(geo.unit_along(), inst.backend.sqrt)
        return geo

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """ω_b − ω_a = 0 (one row in the plane, three in space) and v_rel·n = 0 for each normal
        n of the guide, at `at` or the reference point; the acceleration rows add the Coriolis
        term 2 v_rel·(ω_a × n)."""
        j = geo.joint
        q = geo.at if geo.at is not None else lv.ref
        rows = [(c, Said("row-no-rotation-axis", axis=AXES[i]) if lv.space.dim == 3 else Said("row-no-rotation"))
                for i, c in enumerate(same_rotation(lv, j.a, j.b))]
        rows += [(sliding(lv, j.a, j.b, q, n), Said("row-across-guide", n=k + 1))
                 for k, n in enumerate(geo.perps)]
        return rows

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """No relative rotation; the offset across the guide kept."""
        a, b = geo.joint.a, geo.joint.b
        p0 = geo.at if geo.at is not None else ref
        return lambda q, _: q.rotation_error(a, b) + across(q, a, b, p0, geo.perps)

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """A block on its guide (a fixed guide hatched)."""
        from . import symbols     # drawing only (start-up)

        return symbols.block_on_guide(view, ctx)

    def rate(self, geo: JointGeometry, lv: Level) -> Scalar:
        """(v_Qb − v_Qa)·u along the guide u (its derivative with the Coriolis term)."""
        j = geo.joint
        q = geo.at if geo.at is not None else lv.ref
        return sliding(lv, j.a, j.b, q, geo.unit_along())

    def add(self, m: Mechanism, a: str, b: str, along: Any, id: Optional[str] = None) -> str:
        """`b` slides on `a` along `along` (a vector or two points): `m.prismatic("ground", "slider", along=(1, 0))`."""
        return m.joint(self.name, a, b, id, along=along)


KIND = Prismatic()
