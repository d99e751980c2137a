"""Where the points are for many designs at once: `positions` over arrays of parameters.

The constructions are the ones `engine.positions` evaluates for one design, with the same
formulas (inherited); only the checks differ. A design whose construction cannot be
drawn (circles apart, parallel lines, two points fit and no side given) gets NaN instead
of an error, and the per-design path later says why in the contract's words.
"""
from __future__ import annotations

import functools
from typing import Any, Optional

import numpy as np

from ..model.constructions import CircleLine, LineDef, TwoCircles, TwoLines
from .positions import TOLERANCE, _Builder, line_meet, positions


def array_positions(inst: Any) -> dict[str, tuple]:
    """Every point's coordinates (arrays over the designs, NaN where it cannot be drawn)."""
    with np.errstate(all="ignore"):
        return positions(inst, _ArrayBuilder)


def _largest(values: list) -> Any:
    """The elementwise largest of numbers and arrays."""
    return functools.reduce(np.maximum, values)


def _nan_unless(ok: Any, value: Any) -> Any:
    return np.where(ok, value, np.nan)


class _ArrayBuilder(_Builder):
    """`engine.positions`' constructions with their checks made per design (NaN, no error)."""

    def num(self, x: Any) -> Any:
        return x

    def length(self, expr: Any, field: str, what: str) -> Any:
        r = self.value(expr, field)
        return _nan_unless(np.asarray(r) > 0, r)

    def unit_from(self, p: tuple, q: tuple, field: str) -> tuple:
        d = (q[0] - p[0], q[1] - p[1])
        norm2 = d[0] * d[0] + d[1] * d[1]
        big = _largest([1.0] + [c * c for c in p + q])
        norm = _nan_unless(norm2 > 1e-24 * big, np.sqrt(norm2))
        return (d[0] / norm, d[1] / norm)

    def _circles_meet(self, c: TwoCircles, p: tuple, q: tuple, r1: Any, r2: Any, d2: Any,
                      disc: Any) -> tuple[Any, Any]:
        d = np.sqrt(d2)
        tol = TOLERANCE * np.maximum(np.maximum(d, r1), r2)
        ok = (d > 1e-12 * np.maximum(r1, r2)) & (d - (r1 + r2) <= tol) & (np.abs(r1 - r2) - d <= tol)
        tangent = (np.abs(d - (r1 + r2)) <= tol) | (np.abs(np.abs(r1 - r2) - d) <= tol)
        return _nan_unless(ok, np.maximum(disc, 0.0)), tangent

    def _line_meets(self, c: CircleLine, p: tuple, r: Any, q: tuple, d: tuple, dd: Any,
                    disc: Any) -> tuple[Any, Any]:
        dist = np.abs((p[0] - q[0]) * d[1] - (p[1] - q[1]) * d[0]) / np.sqrt(dd)
        ok = (dd > 0) & (dist - r <= TOLERANCE * np.maximum(r, dist))
        return _nan_unless(ok, np.maximum(disc, 0.0)), np.abs(dist - r) <= TOLERANCE * np.maximum(r, dist)

    def lines(self, c: TwoLines) -> tuple:
        (q1, d1), (q2, d2) = (self.line(line, f"lines[{i}]") for i, line in enumerate(c.lines))
        cross = d1[0] * d2[1] - d1[1] * d2[0]
        scale = np.sqrt((d1[0] ** 2 + d1[1] ** 2) * (d2[0] ** 2 + d2[1] ** 2))
        cross = _nan_unless(np.abs(cross) > 1e-12 * scale, cross)
        return line_meet(q1, d1, q2, d2, cross)

    def line(self, line: LineDef, field: str) -> tuple[tuple, tuple]:
        q = self.at(line.through, f"{field}.through" if line.direction is not None else f"{field}[0]")
        if line.direction is not None:
            d = self.inst.vector(line.direction, f"{self.where}.{field}.direction")
            zero = (np.asarray(d[0]) == 0) & (np.asarray(d[1]) == 0)
        else:
            assert line.toward is not None              # a line has a direction or a second point
            r = self.at(line.toward, f"{field}[1]")
            d = (r[0] - q[0], r[1] - q[1])
            big = _largest([1.0] + [c * c for c in q + r])
            zero = d[0] * d[0] + d[1] * d[1] <= 1e-24 * big
        return q, (_nan_unless(~zero, d[0]), _nan_unless(~zero, d[1]))

    def choose(self, side: Optional[str], near: Optional[tuple], options: dict[str, tuple],
               disc: Any, relation: str, tangent: Any = False) -> tuple:
        first, second = options.values()
        if side is not None:
            return options[side]
        if near is not None:
            sketch = (self.value(near[0], "near[0]"), self.value(near[1], "near[1]"))
            d1 = sum((a - b) ** 2 for a, b in zip(first, sketch))
            d2 = sum((a - b) ** 2 for a, b in zip(second, sketch))
            pick = d1 <= d2
        else:
            one = np.where(tangent | (disc == 0), 1.0, np.nan)   # one point (touching), else none
            return (one * (first[0] + second[0]) / 2, one * (first[1] + second[1]) / 2)
        return (np.where(pick, first[0], second[0]), np.where(pick, first[1], second[1]))
