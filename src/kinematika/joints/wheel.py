"""The knife edge (planar `wheel`): the point `at` of the second body moves, relative to
the first, only along the direction `along` fixed in the second body (a vehicle's wheel
seen from above, a skate).

Condition (non-holonomic): v_rel(Q_b)·n_b = 0, n_b the normal to `along`, fixed in b.
Acceleration: (a_Qb − a_Qa − ω_a × v_rel)·n + v_rel·(ω_b × n) = 0.
The relative instant centre lies on the wheel's axle line (through `at`, along n_b).

Example: a cart on a knife edge at P = (0, 0) along x, turning at ω = 2 rad/s with P
moving forward at 3. By hand, v_P = (3, 0) (no slip sideways) and the point Q = (0, 1)
of the cart moves at v_P + ω k × PQ = (3, 0) + 2 k × (0, 1) = (1, 0):

    >>> import numpy as np, kinematika
    >>> m = kinematika.Mechanism("cart").point("O", 0, 0).point("P", 0, 0).point("Q", 0, 1)
    >>> m = m.body("ground", "O").body("cart", "P", "Q")
    >>> edge = m.wheel("ground", "cart", at="P", along=(1, 0))
    >>> sol = m.drive_omega("cart", 2).drive_velocity("P", 3, along=(1, 0)).solve()
    >>> np.allclose(sol.velocity("P"), (3, 0)), np.allclose(sol.velocity("Q"), (1, 0))
    (True, True)
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .capabilities import Centre, PointOn, Side
from ..algebra.vectors import dot, sub
from .base import JointGeometry, JointKind, Rows
from .holonomic import Holonomic
from .derivatives import coincident
from ..errors import Said

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView, Level, Mechanism


class Wheel(JointKind):
    """A wheel that does not slip sideways."""

    name = "wheel"
    summary = "knife edge: point `at` of the second body moves only along `along`, fixed in it"
    condition = "v_rel·n_b = 0 (n_b fixed in the wheel)"
    dimensions = (2,)
    guides_point = True
    along_in = Side.B
    centre = Centre.NORMAL                 # on the normal to `along` at `at`
    centre_line = "wheel"                  # its axle
    knife_edge = True
    velocity_only = (2,)
    fields = {"at": "required", "along": "required"}
    point_on = PointOn.B

    def conditions(self, dim: int) -> int:
        """One, non-holonomic: no sideways velocity of the wheel's point relative to the ground
        it runs on."""
        return 1

    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """v_rel(Q_b)·n_b = 0, n_b the normal to `along` fixed in the wheel; at the acceleration
        level (a_Qb − a_Qa − ω_a × v_rel)·n + v_rel·(ω_b × n) = 0, the normal turning with the
        wheel."""
        j, sp = geo.joint, lv.space
        n = geo.perps[0]
        row = dot(coincident(lv, j.a, j.b, geo.point_at()), n)
        if lv.accel:
            v_rel = sub(lv.v(j.b, geo.point_at()), lv.v(j.a, geo.point_at()))
            row = row - dot(sp.cross(lv.w(j.a), v_rel), n) + dot(v_rel, sp.cross(lv.w(j.b), n))
        return [(row, Said("row-no-sideways", point=f"{j.at}@{j.b}", body=j.a))]

    def holonomic(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Holonomic:
        """None of it: the condition is on velocities only (no sideways slip), so the wheel
        may be anywhere; its place is where the motion in time has taken it."""
        return Holonomic(lambda q, dq: [], lambda q: [])

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """A knife edge seen from above: a narrow wheel along its rolling direction, outlined
        in ink and filled grey (`TYRE`). Filled black, it hid the first half of the velocity
        that starts at its centre and runs along it, white casing or not: C5-2.1's v_C1,
        C5-2.2's v_C1, v_C2 and v_C4 read as starting at the wheel's edge, half hidden (issue
        30, twenty-ninth round (e))."""
        from . import symbols     # drawing only (start-up)

        if view.at is None or view.along is None:
            return []
        wheel = symbols.rectangle(np.asarray(view.at, dtype=float), np.asarray(view.along, dtype=float),
                                  0.10 * ctx.size, 0.03 * ctx.size)
        return [symbols.Mark("polygon", wheel, "ink", TYRE, 1.2, zorder=5, gid=f"joint:{view.id}",
                             moves_with=symbols.mover(view, ctx))]

    def add(self, m: Mechanism, a: str, b: str, at: str, along: Any, id: Optional[str] = None) -> str:
        """A knife edge: point `at` of `b` moves relative to `a` only along `along`, fixed in `b`."""
        return m.joint(self.name, a, b, id, at=at, along=along)


TYRE = "#90a4ae"     # a knife edge's fill: a tyre's grey, dark enough to read as a wheel, light enough under an arrow

KIND = Wheel()
