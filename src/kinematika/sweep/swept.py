"""What the ways of following a motion read of the model analysed for sweeps (`run.Sweeper`):
the model and its drawn instant with the engine's solver there, the points and motion
classes, the closed form (if any) and its variants, and how rows become a `SweepResult`.
Newton's path (`newton`, `assembler`), the compiled spatial sweeps (`compiled`), the limit
positions (`limit_positions`) and the search of assemblies (`search`) are handed a
`Sweeper` by `run`, which they do not import.
"""
from __future__ import annotations

from typing import Any, Optional, Protocol

import numpy as np

from ..engine.instant import Instant
from ..engine.system import InstantSolver
from ..model.model import Joint, Model
from .plan import Plan
from .result import SweepResult


class Swept(Protocol):
    """A model analysed once for sweeps of one driven joint (`run.Sweeper`)."""

    model: Model
    inst: Instant
    solver: InstantSolver
    joint: Joint
    drawn: Any                                  # the engine's solution at the drawn instant
    points: dict[str, tuple]                    # every point's drawn place, as floats
    motions: list[tuple[str, str, list[str]]]   # material points that move alike (`run.motion_classes`)
    closed: Any                                 # the closed form (`closed_form.ClosedForm`), or None

    def form(self, flips: dict[int, float]) -> Any:
        """The closed form with the dyads in `flips` closed the other way."""

    def result(self, plan: Plan, ok: np.ndarray, bodies: dict, motions: dict,
               dead: list[float], coordinate: Optional[np.ndarray] = None,
               travel: Optional[np.ndarray] = None, limits: Any = None,
               closed: bool = False) -> SweepResult:
        """A `SweepResult` from per-body arrays and per-motion-class point arrays."""
