"""What a model says about its figures, and nothing else reads: `draw_at` (the numbers a
symbolic model is drawn at) and `up` (the vertical of a 3D model), checked here."""
from __future__ import annotations

import math
from typing import Any, Optional

from .. import limits
from ..errors import KinematikaError
from .model import Parameter


def draw_values(raw: Optional[dict[str, Any]], params: dict[str, Parameter]) -> dict[str, float]:
    """`draw_at`: a number for some symbolic parameters (positive ones positive)."""
    out: dict[str, float] = {}
    for name, value in (raw or {}).items():
        where = f"draw_at.{name}"
        param = params.get(name)
        if param is None:
            known = ", ".join(params) or "none"
            raise KinematikaError("schema", f"unknown parameter {name!r} (parameters: {known})",
                                  where)
        if param.value is not None:
            raise KinematikaError("schema", f"{name!r} has a value already: draw_at gives "
                                  "numbers to symbolic parameters (null)", where)
        value = float(value)
        if not math.isfinite(value) or (param.positive and value <= 0):
            raise KinematikaError("schema", f"{name!r} is drawn at {value:g}: give a finite"
                                  f"{' positive' if param.positive else ''} number", where)
        if value != 0 and not 1 / limits.SCALE <= abs(value) <= limits.SCALE:
            raise KinematikaError("schema", f"{name!r} is drawn at {value:g}: figures are drawn with "
                                  f"numbers between {1 / limits.SCALE:g} and {limits.SCALE:g} in size",
                                  where)
        out[name] = value
    return out


def up_vector(raw: Optional[list], dimension: int) -> Optional[tuple[float, float, float]]:
    """`up`: the direction drawn vertical on the page (3D models only)."""
    if raw is None:
        return None
    if dimension != 3:
        raise KinematikaError("schema", "up names the vertical of a 3D model; a planar model is "
                              "drawn in its own plane", "up")
    vec = tuple(float(c) for c in raw)
    if len(vec) != 3 or not all(math.isfinite(c) for c in vec) or math.hypot(*vec) == 0:
        raise KinematikaError("schema", "up is a non-zero direction of 3 numbers, such as "
                              "[0, 1, 0]", "up")
    return vec
