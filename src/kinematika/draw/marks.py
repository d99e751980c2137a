"""Instant centres, acceleration poles and contacts as marked points; Aronhold–Kennedy
lines; curvature circles with their centres; 3D screw axes.

A marked point far outside the mechanism (beyond the view) is drawn at the edge of the
view as a triangle pointing towards it, its label giving its coordinates, so that one
distant centre does not shrink the mechanism to a dot; a centre at infinity (a translation)
is a double arrow at the edge, along its direction.
"""
from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import FancyArrowPatch

from .canvas import Canvas
from .geometry import clip_line, clip_polyline, clip_segment, edge_point, unit
from .scene import CurvatureView, MarkView
from .style import ACCELERATION, CENTRE, CURVATURE, INK, number

MARKERS = {"icr": dict(marker="o", ms=9, mfc="white", mec=CENTRE, mew=2.2),
           "pole": dict(marker="D", ms=7, mfc="white", mec=ACCELERATION, mew=2.0),
           "contact": dict(marker="X", ms=7, mfc=INK, mec="white", mew=0.8)}
COLOURS = {"icr": CENTRE, "pole": ACCELERATION, "contact": INK}


def paint_marks(cv: Canvas) -> None:
    for mark in cv.scene.marks:
        if mark.point is None:
            if mark.direction is not None:
                _infinite_mark(cv, mark)
            continue
        if cv.view.contains(mark.point):
            _mark(cv, mark)
        else:
            _far_mark(cv, mark)
    for line in cv.scene.kennedy:
        _kennedy(cv, line)


def _mark(cv: Canvas, mark: MarkView) -> None:
    p = mark.point
    cv.add(Line2D([p[0]], [p[1]], zorder=11, gid=f"{mark.key}", **MARKERS[mark.kind]))
    if mark.kind == "icr":
        cv.add(Line2D([p[0]], [p[1]], marker="o", ms=2.5, color=CENTRE, zorder=12))
    cv.board.avoid(p)
    cv.label(p, mark.label, COLOURS[mark.kind], 2, mark.key)


def _far_mark(cv: Canvas, mark: MarkView) -> None:
    inset = 0.03 * cv.size
    q = edge_point(cv.view, mark.point, inset)
    d = unit(mark.point - cv.view.centre)
    angle = np.degrees(np.arctan2(d[1], d[0])) - 90
    cv.add(Line2D([q[0]], [q[1]], marker=(3, 0, angle), ms=9, color=COLOURS[mark.kind], zorder=11,
                  gid=f"{mark.key}:far"))
    x, y = (number(c, cv.size) for c in mark.point)
    cv.label(q, f"{mark.label} far off at ({x}, {y})", COLOURS[mark.kind], 2,
             mark.key, -d)


def _infinite_mark(cv: Canvas, mark: MarkView) -> None:
    """A centre at infinity: a double arrow at the edge of the view along its direction (it
    lies at infinity both ways), labelled with the centre's name and ∞."""
    d = unit(np.asarray(mark.direction, dtype=float))
    inset = 0.06 * cv.size
    q = edge_point(cv.view, cv.view.centre + 1e6 * cv.size * d, inset)
    half = 0.06 * cv.size * d
    cv.add(FancyArrowPatch(q - half, q + half, arrowstyle="<|-|>", mutation_scale=14, lw=1.8,
                           color=COLOURS[mark.kind], zorder=11, gid=f"{mark.key}:infinity"))
    cv.board.avoid(q - half, q + half)
    cv.label(q, f"{mark.label} at ∞", COLOURS[mark.kind], 2, mark.key, np.array([-d[1], d[0]]))


def _kennedy(cv: Canvas, line) -> None:
    """The part of the line covering its centres (and a little beyond), inside the view."""
    d = unit(np.asarray(line.direction, dtype=float))
    ts = [float((a - line.through) @ d) for a in line.anchors if cv.view.contains(a)]
    margin = 0.12 * cv.size
    if ts:
        seg = clip_segment(line.through + (min(ts) - margin) * d,
                           line.through + (max(ts) + margin) * d, cv.view)
    else:
        seg = clip_line(line.through, d, cv.view)
    if seg is not None:
        cv.add(Line2D(*np.array(seg).T, lw=0.9, ls=(0, (6, 4)), color=CENTRE, alpha=0.65,
                      zorder=1, gid=line.key))


def paint_curvatures(cv: Canvas) -> None:
    for c in cv.scene.curvatures:
        _curvature(cv, c)


def _curvature(cv: Canvas, c: CurvatureView) -> None:
    circle = clip_polyline(c.circle, cv.view)
    cv.add(Line2D(*circle.T, lw=1.3, color=CURVATURE, alpha=0.9, zorder=3,
                  gid=f"curvature:{c.ref}"))
    seg = clip_segment(c.point, c.centre, cv.view)
    if seg is not None:
        cv.add(Line2D(*np.array(seg).T, lw=0.9, ls=":", color=CURVATURE, zorder=3))
    if cv.view.contains(c.centre):
        cv.add(Line2D([c.centre[0]], [c.centre[1]], marker="P", ms=8, color=CURVATURE, mec="white",
                      mew=0.6, zorder=10, gid=f"curvature-centre:{c.ref}"))
        cv.board.avoid(c.centre)
        cv.label(c.centre, c.label, CURVATURE, 2, f"curvature:{c.ref}")
    else:
        x, y = (number(v, cv.size) for v in c.centre)
        cv.label(c.point + 0.5 * (seg[1] - seg[0]) if seg is not None else c.point,
                 f"{c.label}, centre ({x}, {y})", CURVATURE, 2, f"curvature:{c.ref}")


def paint_axes(cv: Canvas) -> None:
    """3D screw axes, dash-dot across the view."""
    for a in cv.scene.axes:
        d = a.direction
        if np.linalg.norm(d) < 1e-9:      # seen end-on: a point
            cv.add(Line2D([a.point[0]], [a.point[1]], marker="o", ms=8, mfc="none", mec=CENTRE,
                          zorder=10, gid=a.key))
            cv.label(a.point, a.label, CENTRE, 2, a.key)
            continue
        seg = clip_line(a.point, unit(d), cv.view)
        if seg is not None:
            cv.add(Line2D(*np.array(seg).T, lw=1.4, ls="-.", color=CENTRE, zorder=3, gid=a.key))
            mid = (seg[0] + seg[1]) / 2
            cv.label(mid, a.label, CENTRE, 2, a.key)
