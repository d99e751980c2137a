"""The spherical joint (ball joint, S; 3D only): the two bodies share the point `at` and
turn freely about it.

Condition: P_b = P_a at `at`. Velocity rows: v_P(b) − v_P(a) = 0 (three components).

Example: a link OA = (1, 0, 0) on a ball joint at O, turning at ω = (0, 0, 3) rad/s. By
hand, v_A = ω × OA = (0, 3, 0):

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("ball", dimension=3).point("O", 0, 0, 0).point("A", 1, 0, 0)
    >>> m = m.body("ground", "O").body("link", "O", "A")
    >>> ball = m.spherical("ground", "link", at="O")
    >>> np.allclose(m.drive_omega("link", (0, 0, 3)).solve().velocity("A"), (0, 3, 0))
    True
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Optional

from .positions import Residual
from .capabilities import PointOn
from .base import AXES, JointGeometry, JointKind, Rows
from .derivatives import coincident
from .positions import coincide
from ..errors import Said

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism


class Spherical(JointKind):
    """A ball joint."""

    name = "spherical"
    summary = "3D ball joint: the bodies share point `at`"
    condition = "v_P(b) − v_P(a) = 0 (3D)"
    dimensions = (3,)
    pins = True
    ball = True
    fields = {"at": "required"}
    point_on = PointOn.AB

    def conditions(self, dim: int) -> int:
        """Three: the centre `at` is shared; every relative rotation is free."""
        return 3

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """v_P(b) − v_P(a) = 0 at the ball's centre, one row per component."""
        j = geo.joint
        return [(c, Said("row-moves-with", point=f"{j.at}@{j.b}", other=f"{j.at}@{j.a}", axis=AXES[i]))
                for i, c in enumerate(coincident(lv, j.a, j.b, geo.point_at()))]

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """A pin with a dot (a ball), on a fixed pivot when the frame is one of its bodies."""
        from . import symbols     # drawing only (start-up)

        if view.at is None:
            return []
        out = symbols.support(view.at, ctx) if ctx.frame in (view.a, view.b) else []
        return out + symbols.pin(view, ctx, centre_dot=True)

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """P_b − P_a at the ball."""
        a, b, p0 = geo.joint.a, geo.joint.b, geo.point_at()
        return lambda q, _: coincide(q, a, b, p0)

    def add(self, m: Mechanism, a: str, b: str, at: str, id: Optional[str] = None) -> str:
        """A ball joint between `a` and `b` at point `at`."""
        return m.joint(self.name, a, b, id, at=at)


KIND = Spherical()
