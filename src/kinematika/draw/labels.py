"""Label placement: every label near its anchor, clear of the others and of the drawing.

Labels are collected while the figure is painted and placed at the end, once the axes
limits are final: each in turn (most important first) tries offsets around its anchor —
12 directions at growing distances — and takes the one with the lowest cost: overlap with
labels already placed (heaviest), leaving the axes, covering drawn lines and arrows, then
distance from the anchor and, for a vector, not lying along its direction. A label pushed
far from its anchor gets a thin leader line.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from matplotlib.text import Text

from .style import LABEL_SIZE

DISTANCES = (6.0, 12.0, 20.0, 32.0, 48.0, 68.0)      # points
DIRECTIONS = 12
OBSTACLE_PAD = 4.0                                   # px: half a bar's width
LEADER = 24.0                                        # points: farther labels get a leader


@dataclass
class Label:
    anchor: np.ndarray                 # data coordinates
    text: str
    colour: str
    priority: int                      # lower is placed first
    gid: str
    prefer: Optional[np.ndarray] = None   # a preferred direction on the page
    size: float = LABEL_SIZE
    weight: str = "normal"
    style: str = "normal"


@dataclass
class LabelBoard:
    """Labels to place and the drawn geometry they should keep clear of."""

    labels: list[Label] = field(default_factory=list)
    obstacles: list[np.ndarray] = field(default_factory=list)   # polylines, data coordinates

    def add(self, anchor: Any, text: str, colour: str, priority: int, gid: str,
            prefer: Any = None, **kw: Any) -> None:
        pref = None if prefer is None else np.asarray(prefer, dtype=float)
        self.labels.append(Label(np.asarray(anchor, dtype=float), text, colour, priority, gid,
                                 pref, **kw))

    def avoid(self, *polyline: Any) -> None:
        """Keep labels off the drawn polyline through these points (a single point too)."""
        self.obstacles.append(np.array([np.asarray(p, dtype=float) for p in polyline]))

    def place(self, ax: Any, renderer: Any) -> list[Any]:
        """Create the labels' annotations in `ax` at their best offsets."""
        axes_box = ax.get_window_extent(renderer)
        obstacles = self._sample(ax)
        px_per_pt = ax.figure.dpi / 72.0
        placed: list[Any] = []
        boxes: list[tuple] = []
        for label in sorted(self.labels, key=lambda lb: lb.priority):
            ann = _annotation(ax, label, (0.0, 0.0), "left", "bottom", leader=False)
            bb = Text.get_window_extent(ann, renderer)
            size = (bb.width, bb.height)
            anchor = ax.transData.transform(label.anchor)
            best = min(_candidates(), key=lambda c: _cost(
                _box(anchor, size, c, px_per_pt), c, label, axes_box, boxes, obstacles))
            ann.remove()
            ann = _annotation(ax, label, best[:2], best[3], best[4], leader=best[2] >= LEADER)
            boxes.append(_box(anchor, size, best, px_per_pt))
            placed.append(ann)
        return placed

    def _sample(self, ax: Any) -> np.ndarray:
        """The obstacles as display points about 5 px apart."""
        pts = []
        for line in self.obstacles:
            disp = ax.transData.transform(line)
            pts.append(disp[:1])
            for p, q in zip(disp[:-1], disp[1:]):
                n = max(1, int(np.linalg.norm(q - p) / 5))
                t = np.linspace(0, 1, n + 1)[1:, None]
                pts.append(p + t * (q - p))
        return np.vstack(pts) if pts else np.zeros((0, 2))


def _annotation(ax: Any, label: Label, offset: tuple, ha: str, va: str, leader: bool) -> Any:
    arrow = dict(arrowstyle="-", color=label.colour, lw=0.6, alpha=0.7, shrinkA=0,
                 shrinkB=2) if leader else None
    return ax.annotate(label.text, xy=label.anchor, xytext=offset, textcoords="offset points",
                       ha=ha, va=va, fontsize=label.size, color=label.colour, weight=label.weight,
                       style=label.style, zorder=20, gid=f"label:{label.gid}",
                       annotation_clip=False, arrowprops=arrow,
                       bbox=dict(boxstyle="round,pad=0.12", fc="white", ec="none", alpha=0.75))


def _candidates() -> list[tuple]:
    """(dx, dy, distance, ha, va) offsets in points around the anchor."""
    out = []
    for r in DISTANCES:
        for k in range(DIRECTIONS):
            t = 2 * math.pi * k / DIRECTIONS
            c, s = math.cos(t), math.sin(t)
            ha = "left" if c > 0.3 else "right" if c < -0.3 else "center"
            va = "bottom" if s > 0.3 else "top" if s < -0.3 else "center"
            out.append((r * c, r * s, r, ha, va))
    return out


def _box(anchor: np.ndarray, size: tuple, cand: tuple, px_per_pt: float) -> tuple:
    """The display box of a label of `size` (px) placed at candidate `cand`, padded 2 px."""
    w, h = size
    x = anchor[0] + cand[0] * px_per_pt
    y = anchor[1] + cand[1] * px_per_pt
    x0 = x - {"left": 0.0, "center": w / 2, "right": w}[cand[3]]
    y0 = y - {"bottom": 0.0, "center": h / 2, "top": h}[cand[4]]
    return (x0 - 2, y0 - 2, x0 + w + 2, y0 + h + 2)


def _cost(box: tuple, cand: tuple, label: Label, axes_box: Any, boxes: list,
          obstacles: np.ndarray) -> float:
    x0, y0, x1, y1 = box
    area = max((x1 - x0) * (y1 - y0), 1.0)
    cost = 0.0
    for bx0, by0, bx1, by1 in boxes:
        w, h = min(x1, bx1) - max(x0, bx0), min(y1, by1) - max(y0, by0)
        if w > 0 and h > 0:
            cost += 400.0 * (1 + w * h / area)
    inside_w = max(0.0, min(x1, axes_box.x1) - max(x0, axes_box.x0))
    inside_h = max(0.0, min(y1, axes_box.y1) - max(y0, axes_box.y0))
    cost += 1000.0 * (1 - inside_w * inside_h / area)
    if len(obstacles):
        pad = OBSTACLE_PAD
        hits = (obstacles[:, 0] > x0 - pad) & (obstacles[:, 0] < x1 + pad) & \
            (obstacles[:, 1] > y0 - pad) & (obstacles[:, 1] < y1 + pad)
        cost += 6.0 * float(hits.sum())
    cost += 0.12 * cand[2]
    if label.prefer is not None and np.linalg.norm(label.prefer) > 0:
        d = np.array(cand[:2]) / cand[2]
        p = label.prefer / np.linalg.norm(label.prefer)
        cost += 4.0 * (1 - float(d @ p))
    return cost
