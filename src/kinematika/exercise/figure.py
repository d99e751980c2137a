"""The figure of a statement: the mechanism drawn to the variant's values (`draw`), with its
data marked as dimensions and no answer drawn (no vectors, centres or circles).

The dimensions are the data the model is built from, as a statement's figure shows them:
each construction's lengths and angles (a polar point's distance and angle, the radii of
circles that meet), and the coordinates of fixed points written with parameters, measured
from the point at the origin; `exercise.dimensions` adds others. A dimension given by a
parameter reads `s = 400 mm`, as the statement states it; any other its value.
"""
from __future__ import annotations

import io
import math
from decimal import Decimal
from typing import Any, Optional

from ..draw.dimensions import Dimension
from ..model.constructions import CircleLine, Polar, TwoCircles
from ..expressions import Expr
from .stated import number_text, stated_text

WIDTH = 4.6         # inches: printed about at its size, so that its text reads as 9 pt
DPI = 150


def figure_png(sol: Any, dimensions: list[Dimension], lang: str) -> bytes:
    """The statement's figure as PNG bytes."""
    from ..draw import DrawOptions, draw
    from ..draw.lock import MATPLOTLIB

    options = DrawOptions(velocities=False, accelerations=False, centres=False, curvature=False,
                          bare=True, lang=lang, width=WIDTH, dimensions=dimensions)
    out = io.BytesIO()
    with MATPLOTLIB:
        draw(sol, None, options).savefig(out, format="png", dpi=DPI, facecolor="white", bbox_inches="tight",
                                         pad_inches=0.08, metadata={"Software": None})
    return out.getvalue()


class Labels:
    """The text of a dimension: `s = 400 mm` for a parameter, else the value."""

    def __init__(self, exercise: Any, stated: dict[str, Decimal], lang: str) -> None:
        self.exercise = exercise
        self.stated = stated
        self.lang = lang

    def of(self, name: Optional[str], value: float, angle: bool) -> str:
        """`name = value unit` for a parameter `name`, else `value` in degrees or lengths."""
        from ..explain.render.names import unicode_name

        if name in self.stated:
            unit = self.exercise.unit_of(name)
            return f"{unicode_name(name)} = {stated_text(self.stated[name], unit, self.lang)}"
        if angle:
            return f"{number_text(math.degrees(value), self.lang, 4)}°"
        return f"{number_text(value, self.lang, 4)}\u00a0{self.exercise.section.length.name}"


def dimensions_of(exercise: Any, sol: Any, stated: dict[str, Decimal], lang: str) -> list[Dimension]:
    """The dimension marks of a variant's figure (planar models; none in 3D)."""
    model, inst = sol.model, sol.inst
    if model.dimension != 2:
        return []
    labels = Labels(exercise, stated, lang)
    at = {name: tuple(float(c) for c in inst.points[name]) for name in model.points}
    out: list[Dimension] = []
    seen: set = set()

    def length(p: str, q: str, name: Optional[str], along: str = "aligned", text: Optional[str] = None,
               side: Optional[str] = None) -> None:
        key = (frozenset((p, q)), along)
        if key in seen or at[p] == at[q]:
            return
        seen.add(key)
        if along == "aligned":
            gap = math.dist(at[p], at[q])
        else:
            gap = abs(at[q]["xy".index(along)] - at[p]["xy".index(along)])
        out.append(Dimension("length", at[p], at[q], text or labels.of(name, gap, False), along, side=side))

    origin = next((name for name, c in model.points.items() if isinstance(c, tuple)
                   and all(e.text.strip() in ("0", "0.0") for e in c)), None)
    for name, c in model.points.items():
        if isinstance(c, Polar) and isinstance(c.origin, str):
            reference = 0.0
            if c.reference is not None and all(isinstance(r, str) for r in c.reference):
                a, b = at[c.reference[0]], at[c.reference[1]]
                reference = math.atan2(b[1] - a[1], b[0] - a[0])
            sweep = math.remainder(float(inst.value(c.angle, f"points.{name}.angle")), 2 * math.pi)
            # the length on the side of the arm away from the angle's arc
            length(c.origin, name, _name(c.distance), side="left" if sweep >= 0 else "right")
            out.append(Dimension("angle", at[c.origin], at[name], labels.of(_name(c.angle), sweep, True),
                                 reference=reference, sweep=sweep))
        elif isinstance(c, TwoCircles):
            for centre, radius in zip(c.centers, c.radii):
                if isinstance(centre, str):
                    length(centre, name, _name(radius))
        elif isinstance(c, CircleLine) and isinstance(c.center, str):
            length(c.center, name, _name(c.radius))
        elif isinstance(c, tuple) and origin is not None and name != origin:
            for axis, expr in zip("xy", c):
                if expr.names():
                    length(origin, name, _name(expr), axis)
    for mark in exercise.section.dimensions:
        named = mark.label if mark.label in stated else None
        length(*mark.between, named, mark.along, None if named else mark.label)
    return out


def _name(expr: Expr) -> Optional[str]:
    """The parameter an expression is, when it is one name alone."""
    text = expr.text.strip()
    return text if text.isidentifier() else None
