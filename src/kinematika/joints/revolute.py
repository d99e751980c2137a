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
from .base import AXES, JointGeometry, JointKind, ModelJoint, NumericRows, Rows
from .derivatives import coincident, turning
from .positions import axis_kept, coincide
from ..errors import Said, SaidLater

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
        rows = [(c, _shared(j, i)) for i, c in enumerate(coincident(lv, j.a, j.b, geo.point_at()))]
        rows += [(turning(lv, j.a, j.b, p), Said("row-turning-axis", n=k + 1))
                 for k, p in enumerate(geo.perps)]
        return rows

    def numeric_rows(self, geos: list[JointGeometry], lv: Level) -> Optional[NumericRows]:
        """`rows` of many planar pins on floats, as arrays: with r = P − ref and body k's
        columns (ω, v₀x, v₀y) from c_k,

            x row: v₀x(b) − ω_b r_y − v₀x(a) + ω_a r_y        (b_x = 0)
            y row: v₀y(b) + ω_b r_x − v₀y(a) − ω_a r_x        (b_y = 0)

        (the frame's terms left out, as are ω's where r's component is zero, in the order
        `coincident`'s forms hold them); at the acceleration level only the right sides,
        −(a_P(b) − a_P(a)) with a_P = n · ω × (ω × r) of each moving body's known ω (the
        frame's from `lv.point`). None in space, or when a value is not a float."""
        if lv.space.dim != 2 or not geos:
            return None
        ref = lv.ref
        at = [geo.at for geo in geos]
        if not all(type(p[0]) is float and type(p[1]) is float for p in at if p is not None):
            return None
        joints = [geo.joint for geo in geos]
        r = np.array(at, dtype=float) - np.array(ref, dtype=float)
        rx, ry = r[:, 0], r[:, 1]
        if lv.accel:            # (the labels are the velocity level's)
            return self._known_terms(joints, rx, ry, lv)
        labels = SaidLater(2 * len(joints), lambda: [label for j in joints for label in (_shared(j, 0), _shared(j, 1))])
        none = -1
        ca = np.array([none if (c := lv.column(j.a)) is None else c for j in joints])
        cb = np.array([none if (c := lv.column(j.b)) is None else c for j in joints])
        a_moves, b_moves = ca != none, cb != none
        ones = np.ones(len(joints))
        # per joint and row (x, y): the entries of b (v₀, ω), then of a (v₀, ω)
        cols = np.stack([np.stack([cb + 1, cb, ca + 1, ca], axis=1),
                         np.stack([cb + 2, cb, ca + 2, ca], axis=1)], axis=1)
        vals = np.stack([np.stack([ones, -ry, -ones, ry], axis=1),
                         np.stack([ones, rx, -ones, -rx], axis=1)], axis=1)
        keep = np.stack([np.stack([b_moves, b_moves & (ry != 0), a_moves, a_moves & (ry != 0)], axis=1),
                         np.stack([b_moves, b_moves & (rx != 0), a_moves, a_moves & (rx != 0)], axis=1)], axis=1)
        keep = keep.reshape(-1, 4)
        indptr = np.zeros(len(keep) + 1, dtype=np.int64)
        np.cumsum(keep.sum(axis=1), out=indptr[1:])
        # the constant is a float zero (so b = −0.0) where a product with r made it, else 0
        frame = ~(a_moves & b_moves)
        b = np.where(np.stack([frame | (ry != 0), frame | (rx != 0)], axis=1).reshape(-1), -0.0, 0.0)
        return NumericRows(2, indptr, cols.reshape(-1, 4)[keep], vals.reshape(-1, 4)[keep], b, labels)

    @staticmethod
    def _known_terms(joints: list, rx: np.ndarray, ry: np.ndarray, lv: Level) -> Optional[NumericRows]:
        """The acceleration level's right sides of `numeric_rows`: each body's known part
        0 + n · ω × (ω × r) as `lv.point` sums it, the frame's with ω = 0.0 (so +0.0, as
        `lv.point` gives the frame: 0 + (±0.0) is +0.0)."""
        w: dict[str, float] = {}
        for body in {j.a for j in joints} | {j.b for j in joints}:
            if lv.column(body) is None:
                w[body] = 0.0
                continue
            value = lv.w(body)
            if type(value) is not float:
                return None
            w[body] = value
        wa = np.array([w[j.a] for j in joints])
        wb = np.array([w[j.b] for j in joints])

        def point(wk: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            c = lv.terms.normal_part((-wk * (wk * rx), wk * (-wk * ry)))
            return 0.0 + c[0], 0.0 + c[1]

        (bx, by), (ax, ay) = point(wb), point(wa)
        b = -np.stack([bx - ax, by - ay], axis=1).reshape(-1)
        return NumericRows(2, None, None, None, b, None)

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


def _shared(j: ModelJoint, i: int) -> Said:
    """The label of the pin's row for axis i: the point `at` of b moves with that of a."""
    return Said("row-moves-with", point=f"{j.at}@{j.b}", other=f"{j.at}@{j.a}", axis=AXES[i])


KIND = Revolute()
