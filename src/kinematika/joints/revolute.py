"""The revolute joint (turning pair, R): the two bodies share the point `at` and turn
relative to each other only about it (about `axis` in 3D).

Condition: P_b = P_a at `at`; in 3D also (ω_b − ω_a) × e = 0 for the axis e.
Velocity rows: v_P(b) − v_P(a) = 0 (and (ω_b − ω_a)·nₖ = 0 for the axis's two normals).
Its coordinate is the angle of b relative to a, counter-clockwise (about `axis`).
The relative instant centre of the pair is `at`.

Example: a crank OA = (2, 0) pinned to the ground at O, turning at ω = 3 rad/s. By hand,
v_A = ω k × OA = 3 k × (2, 0) = (0, 6) and a_A = −ω² OA = (−18, 0):

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("crank").point("O", 0, 0).point("A", 2, 0)
    >>> m = m.body("ground", "O").body("crank", "O", "A")
    >>> pin = m.revolute("ground", "crank", at="O")
    >>> sol = m.drive_omega("crank", 3).solve()
    >>> np.allclose(sol.velocity("A"), (0, 6)), np.allclose(sol.acceleration("A"), (-18, 0))
    (True, True)
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .positions import Residual
from .capabilities import Centre, Chain, Coordinate, PointOn
from .base import AXES, JointGeometry, JointKind, ModelJoint, Rows
from .derivatives import coincident, turning
from .positions import axis_kept, coincide
from ..errors import Said

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism, Scalar


class Revolute(JointKind):
    """A pin (turning pair)."""

    name = "revolute"
    summary = "the two bodies share point `at` and turn relative to each other about it"
    condition = "v_P(b) − v_P(a) = 0 at `at` (and the axis kept, 3D)"
    sweepable = True
    coordinate = Coordinate.ANGLE
    pins = True
    chain = Chain.R
    centre = Centre.PIN
    fields = {"at": "required", "axis": "required in 3D"}
    point_on = PointOn.AB

    def conditions(self, dim: int) -> int:
        """Two in the plane (the point `at` shared), five in space (shared, and turning only
        about the axis)."""
        return 2 if dim == 2 else 5

    def prepare(self, inst: Instant, joint: ModelJoint) -> JointGeometry:
        """In 3D, the axis's two unit normals, about which the bodies may not turn relative to
        each other."""
        geo = super().prepare(inst, joint)
        if geo.axis is not None:
            geo.perps = inst.space.perpendiculars(geo.axis, inst.backend.sqrt)
        return geo

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """v_P(b) − v_P(a) = 0 at `at`, one row per component, and in 3D (ω_b − ω_a)·nₖ = 0 for
        the axis's two normals."""
        j = geo.joint
        rows = [(c, Said("row-moves-with", point=f"{j.at}@{j.b}", other=f"{j.at}@{j.a}", axis=AXES[i]))
                for i, c in enumerate(coincident(lv, j.a, j.b, geo.point_at()))]
        rows += [(turning(lv, j.a, j.b, p), Said("row-turning-axis", n=k + 1))
                 for k, p in enumerate(geo.perps)]
        return rows

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """P_b − P_a at the pin (and the axis kept, in 3D)."""
        a, b, p0 = geo.joint.a, geo.joint.b, geo.point_at()
        if inst.space.dim == 2:
            return lambda q, _: coincide(q, a, b, p0)
        return lambda q, _: coincide(q, a, b, p0) + axis_kept(q, a, b, geo.unit_axis(), geo.perps)

    def displacement(self, geo: JointGeometry, ref: tuple, swept: bool) -> Residual:
        """The angle turned about the axis since the drawing, less the increment."""
        a, b = geo.joint.a, geo.joint.b
        return lambda q, dq: [q.axis_angle_error(a, b, geo.axis, dq if swept else 0.0)]

    def rate(self, geo: JointGeometry, lv: Level) -> Scalar:
        """ω_b − ω_a (planar), (ω_b − ω_a)·e about the axis e (3D)."""
        j, sp = geo.joint, lv.space
        if sp.dim == 2:
            return sp.rot_sub(lv.omega(j.b), lv.omega(j.a))
        return turning(lv, j.a, j.b, geo.unit_axis())

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """A pin; on a fixed pivot's triangle when the frame is one of its bodies; its axis (3D)."""
        from . import symbols     # drawing only (start-up)

        if view.at is None:
            return []
        out = symbols.support(view.at, ctx) if ctx.frame in (view.a, view.b) else []
        if view.axis is not None and np.linalg.norm(view.axis) > 1e-6:
            half = 0.14 * ctx.size * np.asarray(view.axis, dtype=float)
            out.append(symbols.Mark("line", np.array([view.at - half, view.at + half]), width=1.0, dash=True,
                                    moves_with=symbols.mover(view, ctx)))
        return out + symbols.pin(view, ctx)

    def add(self, m: Mechanism, a: str, b: str, at: str, axis: Any = None, id: Optional[str] = None) -> str:
        """A pin between `a` and `b` at point `at` (about `axis` in 3D): `m.revolute("ground", "crank", at="O")`."""
        return m.joint(self.name, a, b, id, at=at, axis=axis)


KIND = Revolute()
