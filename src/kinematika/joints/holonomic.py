"""A joint's condition on positions alone (`JointKind.holonomic`), in a module of its own:
only a motion followed in time (`simulate`) makes one, so a solve does not define the class."""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Optional

from .positions import Residual

if TYPE_CHECKING:
    from .seam import Pose


@dataclass
class Holonomic:
    """The part of a joint's condition that is on positions alone, which a motion followed in
    time (`simulate`) keeps its poses on by projection.

    `values(q, 0.0)` is the residual at the poses `q` (zero on the condition), with the
    signature of `JointKind.residual`'s functions (whose `aux` and `key`, when they carry them,
    are kept); `weights(q)` says how the rate of each value is made of the joint's engine rows
    (one list of weights per value), so that the Jacobian of the values is those weights times
    the engine's velocity matrix; None: the values are the rows themselves, one for one."""

    values: Residual
    weights: Optional[Callable[[Pose], list]] = None
