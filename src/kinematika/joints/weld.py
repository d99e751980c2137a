"""The weld: the two bodies move as one.

Condition: ω_b = ω_a and the bodies' points at the reference coincide in motion.
Velocity rows: ω_b − ω_a = 0, v_R(b) − v_R(a) = 0 at the reference point R.

Example: an arm AB welded to a crank OA = (1, 0) that turns at ω = 3 rad/s about O. By
hand, the arm turns with the crank (ω = 3) and B = (1, 2) moves at ω k × OB = (−6, 3):

    >>> import math, numpy as np, kinematika
    >>> m = kinematika.Mechanism("welded").point("O", 0, 0).point("A", 1, 0).point("B", 1, 2)
    >>> m = m.body("ground", "O").body("crank", "O", "A").body("arm", "A", "B")
    >>> pin, weld = m.revolute("ground", "crank", at="O"), m.weld("crank", "arm")
    >>> sol = m.drive_omega("crank", 3).solve()
    >>> math.isclose(sol.omega("arm"), 3), np.allclose(sol.velocity("B"), (-6, 3))
    (True, True)
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Optional

from .positions import Residual
from .capabilities import Centre
from .base import AXES, JointGeometry, JointKind, Rows
from .derivatives import coincident, same_rotation
from .positions import coincide
from ..errors import Said

if TYPE_CHECKING:
    from .seam import Instant, Level, Mechanism


class Weld(JointKind):
    """Two bodies fixed together."""

    name = "weld"
    summary = "the two bodies move as one"
    condition = "ω_b − ω_a = 0; v(b) − v(a) = 0"
    rigid = True
    centre = Centre.REST

    def conditions(self, dim: int) -> int:
        """Three in the plane, six in space: no relative motion at all."""
        return 3 if dim == 2 else 6

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """ω_b − ω_a = 0 and v_R(b) − v_R(a) = 0 at the reference point R: the two bodies share
        one twist."""
        j = geo.joint
        rows = [(c, Said("row-turns-with", body=j.b, other=j.a)) for c in same_rotation(lv, j.a, j.b)]
        rows += [(c, Said("row-body-moves-with", body=j.b, other=j.a, axis=AXES[i]))
                 for i, c in enumerate(coincident(lv, j.a, j.b, lv.ref))]
        return rows

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """No relative rotation; the points at the reference coincide."""
        a, b = geo.joint.a, geo.joint.b
        return lambda q, _: q.rotation_error(a, b) + coincide(q, a, b, ref)

    def add(self, m: Mechanism, a: str, b: str, id: Optional[str] = None) -> str:
        """`a` and `b` move as one body."""
        return m.joint(self.name, a, b, id)


KIND = Weld()
