"""The cylindrical joint (3D): the second body turns about and slides along an axis fixed
in the first.

Condition: (ω_b − ω_a) × e = 0 and (Q_b − Q_a) × e = 0 for the axis e through `at`.
Velocity rows: (ω_b − ω_a)·nₖ = 0 and v_rel·nₖ = 0 for the axis's two normals.
It has two coordinates (a turn and a slide): drive them by a body's omega and a point's
velocity, not by a joint rate.

Example: a sleeve on the z axis through O, turning at ω = (0, 0, 2) rad/s while its point
A = (1, 0, 0) rises at 5. By hand, v_A = 5 e_z + ω × OA = (0, 0, 5) + (0, 2, 0) = (0, 2, 5):

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("sleeve", dimension=3).point("O", 0, 0, 0).point("A", 1, 0, 0)
    >>> m = m.body("ground", "O").body("sleeve", "O", "A")
    >>> pair = m.cylindrical("ground", "sleeve", at="O", axis=(0, 0, 1))
    >>> m = m.drive_omega("sleeve", (0, 0, 2)).drive_velocity("A", 5, along=(0, 0, 1))
    >>> np.allclose(m.solve().velocity("A"), (0, 2, 5))
    True
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from .positions import Residual
from ..errors import KinematikaError, Said
from .base import JointGeometry, JointKind, ModelJoint, Rows
from .derivatives import sliding, turning
from .positions import across, axis_kept

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism


class Cylindrical(JointKind):
    """A pin that may also slide along its axis."""

    name = "cylindrical"
    summary = "3D: turning about and sliding along `axis` through `at`"
    condition = "(ω_b − ω_a)·nₖ = 0, v_rel·nₖ = 0 (3D)"
    dimensions = (3,)
    slides = True
    fields = {"at": "required", "axis": "required in 3D"}

    def conditions(self, dim: int) -> int:
        """Four: two relative rotations and two relative translations across the axis are
        forbidden (turning about it and sliding along it are free)."""
        return 4

    def prepare(self, inst: Instant, joint: ModelJoint) -> JointGeometry:
        """The axis's two unit normals n₁, n₂, across which neither rotation nor sliding is
        allowed."""
        geo = super().prepare(inst, joint)
        geo.perps = inst.space.perpendiculars(geo.unit_axis(), inst.backend.sqrt)
        return geo

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """(ω_b − ω_a)·nₖ = 0 and v_rel·nₖ = 0 at `at`, for the axis's two normals nₖ (four
        rows)."""
        j = geo.joint
        rows = [(turning(lv, j.a, j.b, p), Said("row-turning-axis", n=k + 1))
                for k, p in enumerate(geo.perps)]
        rows += [(sliding(lv, j.a, j.b, geo.point_at(), p), Said("row-sliding-axis", n=k + 1))
                 for k, p in enumerate(geo.perps)]
        return rows

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """The axis kept, the offset across it kept."""
        a, b = geo.joint.a, geo.joint.b
        return lambda q, _: axis_kept(q, a, b, geo.unit_axis(), geo.perps) + across(q, a, b, geo.point_at(), geo.perps)

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """A block on its guide, as a prismatic pair."""
        from . import symbols     # drawing only (start-up)

        return symbols.block_on_guide(view, ctx)

    def no_rate(self, where: str) -> KinematikaError:
        """The error for a joint-rate driver: a cylindrical joint has two rates, so the user is
        told to drive a body's omega relative to the other body and a point's velocity along the
        axis."""
        return KinematikaError("schema", "cylindrical-two-rates", where)

    def add(self, m: Mechanism, a: str, b: str, at: str, axis: Any, id: Optional[str] = None) -> str:
        """`b` turns about and slides along `axis` through point `at`, fixed in `a`."""
        return m.joint(self.name, a, b, id, at=at, axis=axis)


KIND = Cylindrical()
