"""A gear pair: the pitch circles of the two bodies roll on each other (`internal: true`
for a ring gear); the same kinematics as `rolling`, counted as one condition when the
gears' centres are held by other joints, as a mesh is.

Condition: v_J(b) = v_J(a) at the pitch point J (see `rolling`).
"""
from __future__ import annotations

from typing import Optional

from .seam import Mechanism
from .rolling import Rolling


class Gear(Rolling):
    """Two gears in mesh (their pitch circles)."""

    name = "gear"
    summary = "the pitch circles of the two bodies roll on each other (`internal` for a ring)"
    pitch = True

    def conditions(self, dim: int) -> int:
        """One, in the structural count: the mesh fixes only the gears' turns when their centres
        are held by other joints (its rows are rolling's, v_J(b) = v_J(a))."""
        return 1

    def add(self, m: Mechanism, a: str, b: str, internal: bool = False,  # type: ignore[override]
            id: Optional[str] = None) -> str:
        """The pitch circles of `a` and `b` mesh (`internal=True` for a ring gear)."""
        return m.joint(self.name, a, b, id, internal=internal)


KIND = Gear()
