"""A gear pair: the pitch circles of the two bodies roll on each other (`internal: true`
for a ring gear); the same kinematics as `rolling`, counted as one condition when the
gears' centres are held by other joints, as a mesh is.

Condition: v_J(b) = v_J(a) at the pitch point J (see `rolling`).

Example: a pinion of pitch radius 1 at O1 drives a wheel of pitch radius 2 at O2, 3 away,
at ω1 = 4 rad/s. By hand, the pitch point has one velocity on both: ω1 r1 = −ω2 r2, so
ω2 = −4 × 1/2 = −2 rad/s:

    >>> import math, kinematika
    >>> m = kinematika.Mechanism("gears").point("O1", 0, 0).point("O2", 3, 0)
    >>> m = m.body("ground", "O1", "O2")
    >>> m = m.body("pinion", "O1", circle=("O1", 1)).body("wheel", "O2", circle=("O2", 2))
    >>> pins = m.revolute("ground", "pinion", at="O1"), m.revolute("ground", "wheel", at="O2")
    >>> mesh = m.gear("pinion", "wheel")
    >>> math.isclose(m.drive_omega("pinion", 4).solve().omega("wheel"), -2)
    True
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Optional

from .rolling import Rolling

if TYPE_CHECKING:
    from .seam import Mechanism


class Gear(Rolling):
    """Two gears in mesh (their pitch circles)."""

    name = "gear"
    summary = "the pitch circles of the two bodies roll on each other (`internal` for a ring)"
    condition = "as rolling, on the pitch circles (one condition in a structure)"
    pitch = True

    def conditions(self, dim: int) -> int:
        """One, in the structural count: the mesh fixes only the gears' turns when their centres
        are held by other joints (its rows are rolling's, v_J(b) = v_J(a))."""
        return 1

    def add(self, m: Mechanism, a: str, b: str, internal: bool = False,  # type: ignore[override]  # each kind names its own fields (`JointKind.add`)
            id: Optional[str] = None) -> str:
        """The pitch circles of `a` and `b` mesh (`internal=True` for a ring gear)."""
        return m.joint(self.name, a, b, id, internal=internal)


KIND = Gear()
