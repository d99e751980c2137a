"""Instant centres, acceleration poles and contacts as marked points; Aronhold–Kennedy
lines; curvature circles with their centres; 3D screw axes.

A marked point far outside the mechanism (beyond the view) is drawn at the edge of the
view as a triangle pointing towards it, its label giving its coordinates, so that one
distant centre does not shrink the mechanism to a dot; a centre at infinity (a translation)
is a double arrow at the edge, along its direction.
"""
from __future__ import annotations

from typing import Optional

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import FancyArrowPatch

from .canvas import Canvas
from .geometry import clip_line, clip_polyline, clip_segment, edge_point, unit
from .scene import CurvatureView, MarkView
from .names import coordinates
from .style import ACCELERATION, CENTRE, CURVATURE, INK

MARKERS = {"icr": dict(marker="o", ms=9, mfc="white", mec=CENTRE, mew=2.2),
           "pole": dict(marker="D", ms=7, mfc="white", mec=ACCELERATION, mew=2.0),
           "contact": dict(marker="X", ms=7, mfc=INK, mec="white", mew=0.8)}
COLOURS = {"icr": CENTRE, "pole": ACCELERATION, "contact": INK}
KENNEDY = dict(lw=0.9, ls=(0, (6, 4)), color=CENTRE, alpha=0.65, zorder=1)
NORMAL = dict(lw=1.1, ls=(0, (8, 3, 1.5, 3)), color=CENTRE, alpha=0.85, zorder=1)


def paint_marks(cv: Canvas) -> None:
    """Instant centres, acceleration poles and contacts (a far one at the view's edge pointing
    towards it, one at infinity as a double arrow along its direction), then the
    Aronhold–Kennedy lines and the wheels' and slots' normals."""
    for group in mark_groups(cv.scene.marks, cv.size):
        mark = group[0]
        if mark.point is None:
            _infinite_mark(cv, group)
        elif cv.view.contains(mark.point):
            _mark(cv, group)
        else:
            _far_mark(cv, group)
    for line in cv.scene.kennedy:
        _kennedy(cv, line)
    for line in cv.scene.normals:
        _kennedy(cv, line, NORMAL)


def mark_groups(marks: list[MarkView], size: float) -> list[list[MarkView]]:
    """The marks drawn, those of one kind at one place together (the centres of a gear
    train's pairs at its axis; centres at infinity along one direction)."""
    groups: list[list[MarkView]] = []
    for m in marks:
        if m.rest or (m.point is None and m.direction is None):
            continue
        for g in groups:
            if g[0].kind == m.kind and _same_place(g[0], m, size):
                g.append(m)
                break
        else:
            groups.append([m])
    return groups


def _same_place(a: MarkView, b: MarkView, size: float) -> bool:
    if a.point is not None and b.point is not None:
        return bool(np.linalg.norm(a.point - b.point) <= 1e-6 * size)
    if a.direction is not None and b.direction is not None:
        return abs(float(a.direction[0] * b.direction[1] - a.direction[1] * b.direction[0])) < 1e-9
    return False


def group_label(group: list[MarkView], per_line: int = 4) -> str:
    """The names of a group of marks, a few to a line: I₁₂, I₁₃, I₁₄."""
    names = [m.label for m in group]
    return ",\n".join(", ".join(names[i:i + per_line]) for i in range(0, len(names), per_line))


def _key(group: list[MarkView]) -> str:
    return "+".join(m.key for m in group)


def _mark(cv: Canvas, group: list[MarkView]) -> None:
    mark = group[0]
    p = mark.point
    for m in group:
        cv.add(Line2D([p[0]], [p[1]], zorder=11, gid=f"{m.key}", **MARKERS[m.kind]))
    if mark.kind == "icr":
        cv.add(Line2D([p[0]], [p[1]], marker="o", ms=2.5, color=CENTRE, zorder=12))
    cv.board.avoid(p, weight=3.0, radius=5.0)
    cv.label(p, group_label(group), COLOURS[mark.kind], 2, _key(group))


def _far_mark(cv: Canvas, group: list[MarkView]) -> None:
    """A mark beyond the view: an arrow at the edge pointing at it, labelled with its
    coordinates."""
    mark = group[0]
    q = edge_point(cv.view, mark.point, 0.02 * cv.size)
    d = unit(mark.point - q)
    tail = q - 0.07 * cv.size * d
    cv.add(FancyArrowPatch(tuple(tail), tuple(q), arrowstyle="-|>", mutation_scale=14, lw=1.8,
                           color=COLOURS[mark.kind], zorder=11, gid=f"{mark.key}:far"))
    cv.board.avoid(tail, q, weight=3.0)
    at = coordinates(mark.point, cv.size, cv.lang)
    where = f"at {at}" if cv.words else f"= {at}"
    cv.label(tail, f"{group_label(group)} {where}", COLOURS[mark.kind], 2, _key(group), -d)


def _infinite_mark(cv: Canvas, group: list[MarkView]) -> None:
    """A centre at infinity: a double arrow at the edge of the view along its direction (it
    lies at infinity both ways), labelled with the centre's name and ∞."""
    mark = group[0]
    d = unit(np.asarray(mark.direction, dtype=float))
    inset = 0.06 * cv.size
    q = edge_point(cv.view, cv.view.centre + 1e6 * cv.size * d, inset)
    half = 0.06 * cv.size * d
    cv.add(FancyArrowPatch(q - half, q + half, arrowstyle="<|-|>", mutation_scale=14, lw=1.8,
                           color=COLOURS[mark.kind], zorder=11, gid=f"{_key(group)}:infinity"))
    cv.board.avoid(q - half, q + half, weight=3.0)
    cv.label(q, f"{group_label(group)} {'at ∞' if cv.words else '→ ∞'}", COLOURS[mark.kind], 2, _key(group),
             np.array([-d[1], d[0]]))


def _kennedy(cv: Canvas, line, style: Optional[dict] = None) -> None:
    """The part of the line covering its centres (and a little beyond; up to the edge
    towards one that lies off the view), inside the view."""
    d = unit(np.asarray(line.direction, dtype=float))
    ts = [float((a - line.through) @ d) for a in line.anchors]
    margin = 0.12 * cv.size
    if ts:
        seg = clip_segment(line.through + (min(ts) - margin) * d,
                           line.through + (max(ts) + margin) * d, cv.view)
    else:
        seg = clip_line(line.through, d, cv.view)
    if seg is not None:
        cv.add(Line2D(*np.array(seg).T, **(style or KENNEDY), gid=line.key))


def paint_curvatures(cv: Canvas) -> None:
    """Each asked curvature: the osculating circle of the point's path, its centre and the
    radius."""
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
        cv.board.avoid(c.centre, weight=3.0, radius=4.5)
        cv.label(c.centre, c.label, CURVATURE, 2, f"curvature:{c.ref}")
    else:
        cv.label(c.point + 0.5 * (seg[1] - seg[0]) if seg is not None else c.point,
                 f"{c.label}, centre {coordinates(c.centre, cv.size, cv.lang)}", CURVATURE, 2, f"curvature:{c.ref}")


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
