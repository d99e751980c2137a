"""Plane geometry for drawing: boxes, clipping, hulls and the outlines of symbols."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, Optional

import numpy as np

from ..joints.symbols import perpendicular, rectangle, stadium, unit  # noqa: F401  (drawn shapes: one definition)

Vec = np.ndarray


@dataclass(frozen=True)
class Box:
    """An axis-aligned rectangle on the page."""

    xmin: float
    ymin: float
    xmax: float
    ymax: float

    @classmethod
    def around(cls, points: Iterable[Vec]) -> "Box":
        """The smallest box holding `points`."""
        arr = np.array([np.asarray(p, dtype=float) for p in points])
        lo, hi = arr.min(axis=0), arr.max(axis=0)
        return cls(float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))

    @property
    def width(self) -> float:
        """xmax − xmin."""
        return self.xmax - self.xmin

    @property
    def height(self) -> float:
        """ymax − ymin."""
        return self.ymax - self.ymin

    @property
    def centre(self) -> Vec:
        """The box's centre point."""
        return np.array([(self.xmin + self.xmax) / 2, (self.ymin + self.ymax) / 2])

    def grow(self, margin: float) -> "Box":
        """The box with `margin` added on every side (a negative margin shrinks it)."""
        return Box(self.xmin - margin, self.ymin - margin, self.xmax + margin, self.ymax + margin)

    def union(self, points: Iterable[Vec]) -> "Box":
        """The smallest box holding this one and `points`."""
        pts = [np.asarray(p, dtype=float) for p in points]
        if not pts:
            return self
        return Box.around(pts + [np.array([self.xmin, self.ymin]), np.array([self.xmax, self.ymax])])

    def contains(self, p: Vec, tol: float = 0.0) -> bool:
        """Whether `p` lies in the box, widened by `tol`."""
        return (self.xmin - tol <= p[0] <= self.xmax + tol) and (self.ymin - tol <= p[1] <= self.ymax + tol)

    def with_aspect(self, aspect: float) -> "Box":
        """The smallest box around this one whose height/width is `aspect` (same centre)."""
        w, h = max(self.width, 1e-300), max(self.height, 1e-300)
        if h / w < aspect:
            h = w * aspect
        else:
            w = h / aspect
        c = self.centre
        return Box(c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)


def clip_line(point: Vec, direction: Vec, box: Box) -> Optional[tuple[Vec, Vec]]:
    """The part of the infinite line through `point` along `direction` inside `box`."""
    return clip_segment(point - 1e6 * box.width * direction, point + 1e6 * box.width * direction,
                        box)


def clip_segment(p: Vec, q: Vec, box: Box) -> Optional[tuple[Vec, Vec]]:
    """The part of segment pq inside `box` (Liang–Barsky), or None."""
    d = q - p
    t0, t1 = 0.0, 1.0
    for dp, lo, hi, x in ((d[0], box.xmin, box.xmax, p[0]), (d[1], box.ymin, box.ymax, p[1])):
        if abs(dp) < 1e-300:
            if x < lo or x > hi:
                return None
            continue
        ta, tb = (lo - x) / dp, (hi - x) / dp
        t0, t1 = max(t0, min(ta, tb)), min(t1, max(ta, tb))
        if t0 > t1:
            return None
    return p + t0 * d, p + t1 * d


def clip_polyline(points: Vec, box: Box) -> Vec:
    """`points` with every vertex outside `box` replaced by NaN (breaks the line there)."""
    out = np.array(points, dtype=float)
    inside = (out[:, 0] >= box.xmin) & (out[:, 0] <= box.xmax) & \
        (out[:, 1] >= box.ymin) & (out[:, 1] <= box.ymax)
    out[~inside] = np.nan
    return out


def edge_point(box: Box, towards: Vec, inset: float) -> Vec:
    """Where the ray from the box's centre towards `towards` leaves the box (moved `inset` in)."""
    inner = box.grow(-inset)
    c = inner.centre
    d = towards - c
    ts = []
    for i, (lo, hi) in enumerate(((inner.xmin, inner.xmax), (inner.ymin, inner.ymax))):
        if abs(d[i]) > 1e-300:
            ts.append(((hi if d[i] > 0 else lo) - c[i]) / d[i])
    return c + min(ts) * d if ts else c


def convex_hull(points: list[Vec]) -> Vec:
    """The convex hull (counter-clockwise, Andrew's monotone chain) of 2D points."""
    pts = sorted({(float(p[0]), float(p[1])) for p in points})
    if len(pts) <= 2:
        return np.array(pts)

    def half(seq: Iterable[tuple[float, float]]) -> list[tuple[float, float]]:
        chain: list[tuple[float, float]] = []
        for p in seq:
            while len(chain) >= 2 and _turn(chain[-2], chain[-1], p) <= 0:
                chain.pop()
            chain.append(p)
        return chain[:-1]

    return np.array(half(pts) + half(reversed(pts)))


def _turn(o, a, b) -> float:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


AXES_POINTS = 72 * 0.96 * 8.0     # points across a figure's axes at the default width (`DrawOptions.width`, `figure.new_figure`)
ALONG_ANGLE = 8.0                 # degrees: a line this near an arrow's direction runs along it


def points_to_data(points: float, view: Box, per_point: Optional[float] = None) -> float:
    """A length of `points` on the page in the drawing's units: at `per_point` (units a
    point, the figure's own scale when it is known), else as a figure of the default width
    shows `view` (an estimate, for telling whether two strokes touch)."""
    if per_point:
        return points * per_point
    return points * max(view.width, view.height, 1e-300) / AXES_POINTS


def overlap_along(p: Vec, q: Vec, a: Vec, b: Vec, near: float, angle: float = ALONG_ANGLE) -> float:
    """How long the segment ab runs along the segment pq: the length of pq's stretch that ab
    covers when ab is parallel to pq (within `angle` degrees) and both its ends' stretch lies
    within `near` of pq's line; 0 otherwise (a line crossing an arrow, or beside it, is not
    under it)."""
    p, q, a, b = (np.asarray(x, dtype=float) for x in (p, q, a, b))
    length = float(np.linalg.norm(q - p))
    lab = float(np.linalg.norm(b - a))
    if length <= 1e-300 or lab <= 1e-300:
        return 0.0
    d = (q - p) / length
    if abs(float(d @ (b - a))) / lab < np.cos(np.radians(angle)):
        return 0.0
    n = np.array([-d[1], d[0]])
    ta, tb = float((a - p) @ d), float((b - p) @ d)
    lo, hi = max(min(ta, tb), 0.0), min(max(ta, tb), length)
    if hi <= lo:
        return 0.0
    # the line ab's distance from pq's line over the shared stretch (its ends there)
    sa, sb = float((a - p) @ n), float((b - p) @ n)
    def across(t: float) -> float:
        return sa + (sb - sa) * (t - ta) / (tb - ta) if tb != ta else sa
    if max(abs(across(lo)), abs(across(hi))) > near:
        return 0.0
    return hi - lo
