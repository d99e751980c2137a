"""Velocity and acceleration arrows, scaled per kind.

Within each kind the arrows are to scale: the longest is `LONGEST` of the drawing size.
An arrow that would come out shorter than `SHORTEST` of the drawing size is drawn at that
length instead, so that a small vector next to a much larger one stays visible; its label
then says "enlarged". A zero vector gets no arrow, only its label (= 0) at the point.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.patches import FancyArrowPatch

from .canvas import Canvas
from .scene import VectorView
from .style import KIND_COLOURS, LONGEST, SHORTEST, equation

ZERO = 1e-9          # relative to the largest vector of the kind


@dataclass
class Arrow:
    view: VectorView
    start: np.ndarray
    end: np.ndarray
    enlarged: bool
    zero: bool = False

    @property
    def drawn(self) -> bool:
        return bool(np.linalg.norm(self.end - self.start) > 0)


def arrow_scales(vectors: list[VectorView]) -> dict[str, float]:
    """For each kind, the largest magnitude among its vectors (what LONGEST stands for)."""
    out: dict[str, float] = {}
    for v in vectors:
        out[v.kind] = max(out.get(v.kind, 0.0), v.magnitude)
    return out


def arrow_for(view: VectorView, largest: float, size: float, origin=None, value=None,
              magnitude=None) -> Arrow:
    """The arrow of `view`, or of `value` (page) of `magnitude` (model) at `origin`.

    Lengths follow the model magnitude (a 3D vector is then projected like the drawing)."""
    origin = view.origin if origin is None else np.asarray(origin, dtype=float)
    value = view.value if value is None else np.asarray(value, dtype=float)
    magnitude = view.magnitude if magnitude is None else float(magnitude)
    if largest <= 0 or magnitude <= ZERO * largest or not np.all(np.isfinite(value)):
        return Arrow(view, origin, origin.copy(), False, zero=True)
    factor = LONGEST * size / largest
    enlarged = magnitude * factor < SHORTEST * size
    if enlarged:
        factor = SHORTEST * size / magnitude
    return Arrow(view, origin, origin + value * factor, enlarged)


def arrows(vectors: list[VectorView], size: float) -> list[Arrow]:
    largest = arrow_scales(vectors)
    return [arrow_for(v, largest[v.kind], size) for v in vectors]


def arrow_patch(arrow: Arrow, gid: str) -> FancyArrowPatch:
    colour = KIND_COLOURS[arrow.view.kind]
    return FancyArrowPatch(tuple(arrow.start), tuple(arrow.end), arrowstyle="-|>",
                           mutation_scale=15, lw=2.2, color=colour, shrinkA=0, shrinkB=0,
                           zorder=10 if arrow.view.kind == "velocity" else 9, gid=gid)


def paint_vectors(cv: Canvas, drawn: list[Arrow]) -> None:
    for arrow in drawn:
        v = arrow.view
        colour = KIND_COLOURS[v.kind]
        text = equation(v.label, "0" if arrow.zero else v.text)
        if arrow.enlarged:
            text += " (enlarged)"
        if arrow.drawn:
            cv.ax.add_patch(arrow_patch(arrow, v.key))
            cv.board.avoid(arrow.start, arrow.end)
            cv.label(arrow.end, text, colour, 1, v.key, arrow.end - arrow.start)
        else:
            cv.label(arrow.start, text, colour, 1, v.key)
