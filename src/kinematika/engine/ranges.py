"""The range of sizes the engine computes with floats: a model's length scale and its rates.

Kinematics has no preferred unit, but floats do: a length of 1e-200 has no square, and a
velocity of 1e200 no cube. A model whose size, or whose largest rate (an ω; a speed or a
sliding joint's rate over the size; the square roots of the accelerations'), lies outside
`limits.SCALE` is refused with a clear error instead of answering 0 for a velocity or a
straight path for a curved one; inside, every square and cube the engine forms is a float.
"""
from __future__ import annotations

import math
from typing import Any

from .. import limits
from ..errors import KinematikaError, Num, Said


def check_size(size: float) -> None:
    """The model's length scale within the range (`limits.SCALE`)."""
    if not 1 / limits.SCALE <= size <= limits.SCALE:
        shown = Num(size, ".3g") if math.isfinite(size) else Said("beyond-floats")
        raise KinematikaError("schema", "model-size-range", "points", size=shown, low=1 / limits.SCALE,
                              high=float(limits.SCALE))


def check_rates(inst: Any) -> float:
    """The mechanism's rate scale within the range: the largest rate among the drivers'
    values and the square roots of their accelerations (an acceleration far below ω² is
    only a small one; all of them tiny, or one huge, is out of range). Returns it."""
    # the joints that slide, for a driver of a joint's rate (none asked of a chain of pins)
    sliding = ({j.id for j in inst.model.joints if j.kind.slides}
               if any(d.kind == "joint" for d in inst.model.drivers) else set())
    largest, where = 0.0, "drivers"
    for d in inst.model.drivers:
        for level in ("value", "accel"):
            given = getattr(d, level)
            if given is None:
                continue
            values = inst.vector(given, d.where) if isinstance(given, tuple) else (inst.value(given, d.where),)
            size = math.hypot(*inst.numvec(values))
            linear = d.kind == "velocity" or (d.kind == "joint" and d.joint in sliding)
            rate = size / inst.scale if linear else size
            rate = math.sqrt(rate) if level == "accel" else rate
            if not rate <= largest:
                largest, where = rate, d.where
    if largest and not 1 / limits.SCALE <= largest <= limits.SCALE:
        raise KinematikaError("schema", "rates-range", where, rate=Num(largest, ".3g"), low=1 / limits.SCALE,
                              high=float(limits.SCALE))
    return largest
