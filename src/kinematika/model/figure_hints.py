"""What a model says about its figures, and nothing else reads: `draw_at` (the numbers a
symbolic model is drawn at) and `up` (the vertical of a 3D model), checked here."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Optional

from .. import limits
from ..errors import KinematikaError

if TYPE_CHECKING:
    from .parameter import Parameter


def draw_values(raw: Optional[dict[str, Any]], params: dict[str, Parameter]) -> dict[str, float]:
    """`draw_at`: a number for some symbolic parameters (positive ones positive)."""
    out: dict[str, float] = {}
    for name, value in (raw or {}).items():
        where = f"draw_at.{name}"
        param = params.get(name)
        if param is None:
            raise KinematikaError("schema", "unknown-parameter", where, name=name, parameters=list(params))
        if param.value is not None:
            raise KinematikaError("schema", "draw-at-has-value", where, name=name)
        value = float(value)
        if not math.isfinite(value) or (param.positive and value <= 0):
            raise KinematikaError("schema", "draw-at-not-finite", where, name=name, value=value,
                                  positive=str(param.positive).lower())
        if value != 0 and not 1 / limits.SCALE <= abs(value) <= limits.SCALE:
            raise KinematikaError("schema", "draw-at-range", where, name=name, value=value, low=1 / limits.SCALE,
                                  high=float(limits.SCALE))
        out[name] = value
    return out


def up_vector(raw: Optional[list], dimension: int) -> Optional[tuple[float, float, float]]:
    """`up`: the direction drawn vertical on the page (3D models only)."""
    if raw is None:
        return None
    if dimension != 3:
        raise KinematikaError("schema", "up-planar", "up")
    vec = tuple(float(c) for c in raw)
    if len(vec) != 3 or not all(math.isfinite(c) for c in vec) or math.hypot(*vec) == 0:
        raise KinematikaError("schema", "up-direction", "up")
    return vec
