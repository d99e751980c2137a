"""Questions a user asks of a solved instant, one module per concept; `answer` dispatches."""
from __future__ import annotations

from typing import Any, Callable

from ..model.model import Question
from ..solution import Solution
from .axis import axis
from .contact import contact
from .curvature import curvature, intrinsic
from .decompose import decompose
from .icr import icr
from .inflection import inflection
from .motion import acceleration, alpha, omega, velocity
from .pole import pole

ANSWERS: dict[str, Callable[[Solution, Question], Any]] = {
    "velocity": velocity, "acceleration": acceleration, "omega": omega, "alpha": alpha,
    "icr": icr, "curvature": curvature, "decompose": decompose, "contact": contact,
    "axis": axis, "pole": pole, "intrinsic": intrinsic, "inflection": inflection,
}


def answer(sol: Solution, q: Question) -> Any:
    """The raw answer (backend scalars) to one question."""
    return ANSWERS[q.kind](sol, q)
