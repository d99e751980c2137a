"""Dimension marks: the data of a problem drawn on its figure, as a statement's figure shows
them (a length between two points with its extension lines and arrows, an angle's arc from
its reference direction), each with its text (`s = 400 mm`, `β = 30°`).

A figure draws the dimensions its `DrawOptions.dimensions` lists (planar figures; a view
that states a problem, such as an exercise, says which). Coordinates are the model's, as the
scene's page is for a planar model. Each length is drawn on the side away from the
mechanism's centre, a fixed fraction of the drawing's size off, so that it does not cross
the bars it measures.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

from .geometry import perpendicular, unit
from .style import DIMENSION, LABEL_SIZE

OFFSET = 0.09        # a length's line: this far (drawing sizes) off the measured points
GAP = 0.015          # extension lines start this far from their points
OVERSHOOT = 0.02     # and end this far past the dimension line
RADIUS = 0.16        # an angle's arc (drawing sizes), at most 0.6 of its arm
TEXT_GAP = 0.028     # a length's text stands this far off its line, outwards (drawing sizes)


@dataclass(frozen=True)
class Dimension:
    """A length between `start` and `end` measured `along` x, y or their own line
    ("aligned"), or an angle at the vertex `start` from the direction `reference` (radians
    from the x axis) by `sweep` radians (counter-clockwise positive), its arm towards `end`."""

    kind: str                               # "length" or "angle"
    start: tuple[float, float]
    end: tuple[float, float]
    text: str
    along: str = "aligned"
    reference: float = 0.0
    sweep: Optional[float] = None           # default: from `reference` to the direction of `end`
    side: Optional[str] = None              # an aligned length: "left" or "right" of start→end
                                            # (default: away from the mechanism's centre)


@dataclass(frozen=True)
class Placed:
    """A dimension's strokes on the page: lines, the arrowed segment or arc, the text."""

    lines: list                             # (p, q) plain lines (extension, reference)
    arrow: np.ndarray                       # the dimension line or arc, a polyline (n, 2)
    text_at: np.ndarray
    rotation: float                         # degrees
    align: tuple[str, str] = ("center", "center")   # the text's (ha, va) at `text_at`


def placed(d: Dimension, size: float, centre: np.ndarray) -> Placed:
    """Where a dimension's strokes go in a drawing of `size` around `centre`."""
    if d.kind == "angle":
        return _angle(d, size)
    return _length(d, size, centre)


def _length(d: Dimension, size: float, centre: np.ndarray) -> Placed:
    p, q = np.asarray(d.start, float), np.asarray(d.end, float)
    mid = (p + q) / 2
    if d.along in ("x", "y"):
        axis = 0 if d.along == "x" else 1
        other = 1 - axis
        out = 1.0 if mid[other] >= centre[other] else -1.0
        level = (max(p[other], q[other]) if out > 0 else min(p[other], q[other])) + out * OFFSET * size
        a, b = p.copy(), q.copy()
        a[other] = b[other] = level
        n = np.zeros(2)
        n[other] = out
        rotation = 0.0 if axis == 0 else 90.0
    else:
        n = perpendicular(unit(q - p))               # the left of p→q
        if d.side == "right" or (d.side is None and float(np.dot(mid - centre, n)) < 0):
            n = -n
        a, b = p + n * OFFSET * size, q + n * OFFSET * size
        rotation = math.degrees(math.atan2(q[1] - p[1], q[0] - p[0]))
        if rotation > 90:
            rotation -= 180
        elif rotation <= -90:
            rotation += 180
    lines = [(p + _toward(p, a) * GAP * size, a + _toward(p, a) * OVERSHOOT * size),
             (q + _toward(q, b) * GAP * size, b + _toward(q, b) * OVERSHOOT * size)]
    return Placed(lines, np.array([a, b]), (a + b) / 2 + n * TEXT_GAP * size, rotation)


def _toward(p: np.ndarray, a: np.ndarray) -> np.ndarray:
    return unit(a - p)


def _angle(d: Dimension, size: float) -> Placed:
    v, e = np.asarray(d.start, float), np.asarray(d.end, float)
    arm = float(np.linalg.norm(e - v))
    radius = min(RADIUS * size, 0.6 * arm) if arm > 0 else RADIUS * size
    sweep = d.sweep
    if sweep is None:
        sweep = (math.atan2(e[1] - v[1], e[0] - v[0]) - d.reference) % (2 * math.pi)
    t = np.linspace(d.reference, d.reference + sweep, max(8, int(abs(sweep) / 0.05)))
    arc = v + radius * np.column_stack([np.cos(t), np.sin(t)])
    ref = v + 1.35 * radius * np.array([math.cos(d.reference), math.sin(d.reference)])
    middle = d.reference + sweep / 2
    out = np.array([math.cos(middle), math.sin(middle)])
    text_at = v + (radius + 0.02 * size) * out
    # the text starts just outside the arc and runs away from it (not across the arms)
    align = ("left" if out[0] >= 0 else "right", "bottom" if out[1] >= 0.5 else "top" if out[1] <= -0.5 else "center")
    return Placed([(v, ref)], arc, text_at, 0.0, align)


def reach(dimensions: list[Dimension], size: float, centre: np.ndarray) -> list[np.ndarray]:
    """The points a figure must frame to show `dimensions` (their strokes and texts)."""
    out: list[np.ndarray] = []
    for d in dimensions:
        pl = placed(d, size, centre)
        out += [pt for line in pl.lines for pt in line] + list(pl.arrow) + [pl.text_at]
    return out


def avoid_dimensions(board: Any, ax: Any, dimensions: list[Dimension], size: float, centre: np.ndarray) -> None:
    """Keep the figure's other labels off the dimensions' lines and texts."""
    from .labels import text_extent

    box = ax.get_window_extent()
    per_point = (ax.get_xlim()[1] - ax.get_xlim()[0]) / (box.width * 72.0 / ax.figure.dpi)
    for d in dimensions:
        pl = placed(d, size, centre)
        board.avoid(*pl.arrow, weight=3.0)
        width, height = text_extent(d.text, LABEL_SIZE)
        turn = math.radians(pl.rotation)
        along = width * per_point * np.array([math.cos(turn), math.sin(turn)])
        start = {"left": 0.0, "center": -0.5, "right": -1.0}[pl.align[0]]
        board.avoid(pl.text_at + start * along, pl.text_at + (start + 1) * along, weight=8.0,
                    radius=0.6 * height)


def paint_dimensions(ax: Any, dimensions: list[Dimension], size: float, centre: np.ndarray) -> None:
    """Draw `dimensions` on the axes: thin lines, arrowheads at both ends of a length and at
    the end of an angle's arc, the text on a white ground."""
    for d in dimensions:
        pl = placed(d, size, centre)
        for p, q in pl.lines:
            ax.plot([p[0], q[0]], [p[1], q[1]], color=DIMENSION, lw=0.7,
                    ls=(0, (4, 3)) if d.kind == "angle" else "-", zorder=6, solid_capstyle="butt")
        ax.plot(pl.arrow[:, 0], pl.arrow[:, 1], color=DIMENSION, lw=0.9, zorder=6)
        style = "<|-|>" if d.kind == "length" else "-|>"
        start = pl.arrow[0] if d.kind == "length" else pl.arrow[-2]
        ax.annotate("", xy=tuple(pl.arrow[-1]), xytext=tuple(start),
                    arrowprops=dict(arrowstyle=style, color=DIMENSION, lw=0.9, shrinkA=0, shrinkB=0,
                                    mutation_scale=9), zorder=6)
        ax.text(pl.text_at[0], pl.text_at[1], d.text, rotation=pl.rotation, rotation_mode="anchor",
                ha=pl.align[0], va=pl.align[1], fontsize=LABEL_SIZE, color=DIMENSION, zorder=7,
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.85))
