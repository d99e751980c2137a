"""Instant centres, acceleration poles and contacts as marked points; Aronhold–Kennedy
lines; curvature circles with their centres; 3D screw axes.

A marked point far outside the mechanism (beyond the view) is drawn at the edge of the
view as a triangle pointing towards it, its label giving its coordinates, so that one
distant centre does not shrink the mechanism to a dot; a centre at infinity (a translation)
is a double arrow at the edge, along its direction.
"""
from __future__ import annotations

import re

from typing import Optional, TypedDict

import numpy as np

from .geometry import clip_line, clip_polyline, clip_segment, edge_point, unit
from .bodies import labelled_at
from .context import Context
from .scene import CurvatureView, KennedyLine, MarkView
from .names import coordinates
from .words import word
from .style import ACCELERATION, CENTRE, CURVATURE, INK

MARKERS = {"icr": dict(shape="o", size=9, fill="white", colour=CENTRE, width=2.2),
           "pole": dict(shape="D", size=7, fill="white", colour=ACCELERATION, width=2.0),
           "contact": dict(shape="X", size=7, fill=INK, colour="white", width=0.8)}
COLOURS = {"icr": CENTRE, "pole": ACCELERATION, "contact": INK}


class LineStyle(TypedDict):
    """A line's look in matplotlib's words (`Line2D`'s keywords, the legend's handle): width,
    (offset, dashes), colour, opacity, layer."""

    lw: float
    ls: tuple[float, tuple[float, ...]]
    color: str
    alpha: float
    zorder: float


KENNEDY = LineStyle(lw=0.9, ls=(0, (6, 4)), color=CENTRE, alpha=0.65, zorder=1)
NORMAL = LineStyle(lw=1.1, ls=(0, (8, 3, 1.5, 3)), color=CENTRE, alpha=0.85, zorder=1)
DOTTED = (1.0, 1.65)            # matplotlib's ":" in line widths


def draw_marks(ctx: Context) -> None:
    """Instant centres, acceleration poles and contacts (a far one at the view's edge pointing
    towards it, one at infinity as a double arrow along its direction), then the
    Aronhold–Kennedy lines and the wheels' and slots' normals."""
    for group in mark_groups(ctx.scene.marks, ctx.size):
        mark = group[0]
        if mark.point is None:
            _infinite_mark(ctx, group)
        elif ctx.view.contains(mark.point):
            _mark(ctx, group)
        else:
            _far_mark(ctx, group, mark.point)
    for line in ctx.scene.kennedy:
        # a centre's line to a pin, perpendicular to its velocity, is drawn as the normals
        # are (dash-dot), the line of one velocity's perpendicular; a line through two
        # centres (Aronhold–Kennedy) dashed — the centres' caption names them so
        _kennedy(ctx, line, NORMAL if line.key.startswith("radius:") else None)
    for line in ctx.scene.normals:
        _kennedy(ctx, line, NORMAL)


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


LINE_CHARS = 26         # characters a group label's line holds at most, as read (I₁₂ four, I_portador ten)


def group_label(group: list[MarkView], per_line: int = 4) -> str:
    """The names of a group of marks, a few to a line: I₁₂, I₁₃, I₁₄ — at most `per_line`
    names, and no more than a line of `LINE_CHARS` characters as read holds: centres named
    after their bodies are long, and three on one line ("I_portador, I_central, I_corona",
    C5-1.4's three centres at the pin O, twenty-eighth round (c)) made a label so wide that
    its middle lay nearer the next point than its own ring."""
    names = [m.label for m in group]
    lines: list[list[str]] = [[]]
    for name in names:
        line = lines[-1]
        if line and (len(line) >= per_line or sum(_read(n) + 2 for n in line) + _read(name) > LINE_CHARS):
            lines.append([])
        lines[-1].append(name)
    return ",\n".join(", ".join(line) for line in lines)


def _read(label: str) -> int:
    """How many characters a label reads as: its mathtext's markup left out ($I_{\\mathrm{sun}}$: 4)."""
    return len(re.sub(r"\\mathrm|[${}_^\\]", "", label))


def _key(group: list[MarkView]) -> str:
    return "+".join(m.key for m in group)


def _mark(ctx: Context, group: list[MarkView]) -> None:
    mark = group[0]
    p = mark.point
    for m in group:
        ctx.add("dot", [p], zorder=11, gid=f"{m.key}", layer="centres", group=f"mark:{m.key}",
                **MARKERS[m.kind])
    if mark.kind == "icr":
        ctx.add("dot", [p], size=2.5, colour=CENTRE, fill=CENTRE, width=1.0, zorder=12,
                layer="centres", group=f"mark:{mark.key}")
    ctx.avoid(p, weight=3.0, radius=5.0)
    if mark.kind == "contact" and p is not None and labelled_at(ctx, p, contacts=True):
        return          # the point or the page's contact letter is there already: one place, one letter
    if mark.kind == "icr" and p is not None and _named_once(ctx, p, group_label(group)):
        return
    ctx.label(p, group_label(group), COLOURS[mark.kind], 2, _key(group), layer="centres",
              group=f"mark:{mark.key}", radius=5.5)


def _named_once(ctx: Context, p: np.ndarray, names: str) -> bool:
    """Whether the instant centres `names` at `p` are written into the letter of the named
    point (or the page's contact) already labelled there: one label "I_wheels = J", in the
    centres' colour, set to the side by the placer as a point's letter is, instead of "J" and
    "I_wheels" jammed on one dot (C5-E.1's contact J at the top of the track, C5-E.4's P on the
    upper wheel; issue 30, twenty-ninth round (g)). The point's label keeps its gid (it still
    stands for the point) and is placed as early as the centre's was (its priority); the
    centres' ring is drawn as before."""
    tol = 1e-6 * ctx.size
    for m in ctx.marks:
        if m.kind == "text" and str(m.gid).startswith(("point:", "contact:")) and \
                float(np.linalg.norm(np.asarray(m.points[0], dtype=float) - p)) <= tol:
            m.text = f"{names} = {m.text}"
            m.colour = COLOURS["icr"]
            m.priority = min(m.priority, 2)         # placed when the centre's label was
            return True
    return False


def _far_mark(ctx: Context, group: list[MarkView], point: np.ndarray) -> None:
    """A mark beyond the view, at `point`: an arrow at the edge pointing at it, labelled with
    its coordinates."""
    mark = group[0]
    q = edge_point(ctx.view, point, 0.02 * ctx.size)
    d = unit(point - q)
    tail = q - 0.07 * ctx.size * d
    ctx.add("arrow", [tail, q], head="-|>", size=14, width=1.8, colour=COLOURS[mark.kind],
            zorder=11, gid=f"{mark.key}:far", layer="centres", group=f"mark:{mark.key}")
    ctx.avoid(tail, q, weight=3.0)
    at = coordinates(point, ctx.size, ctx.lang)
    text = word("label-far-off", ctx.lang, label=group_label(group), place=at) if ctx.words \
        else f"{group_label(group)} = {at}"
    ctx.label(tail, text, COLOURS[mark.kind], 2, _key(group), -d,
              layer="centres", group=f"mark:{mark.key}",
              about={"name": group_label(group), "say": "far-off", "args": {"place": at}})


def _infinite_mark(ctx: Context, group: list[MarkView]) -> None:
    """A centre at infinity: a double arrow at the edge of the view along its direction (it
    lies at infinity both ways), labelled with the centre's name and ∞."""
    mark = group[0]
    d = unit(np.asarray(mark.direction, dtype=float))
    inset = 0.06 * ctx.size
    q = edge_point(ctx.view, ctx.view.centre + 1e6 * ctx.size * d, inset)
    half = 0.06 * ctx.size * d
    ctx.add("arrow", [q - half, q + half], head="<|-|>", size=14, width=1.8,
            colour=COLOURS[mark.kind], zorder=11, gid=f"{_key(group)}:infinity", layer="centres",
            group=f"mark:{mark.key}")
    ctx.avoid(q - half, q + half, weight=3.0)
    text = word("label-at-infinity", ctx.lang, label=group_label(group)) if ctx.words \
        else f"{group_label(group)} → ∞"
    ctx.label(q, text, COLOURS[mark.kind], 2,
              _key(group), np.array([-d[1], d[0]]), layer="centres", group=f"mark:{mark.key}",
              about={"name": group_label(group), "say": "at-infinity",
                     "args": {"direction": coordinates(d, 1.0, ctx.lang)}})


def _kennedy(ctx: Context, line: KennedyLine, style: Optional[LineStyle] = None) -> None:
    """The part of the line covering its centres (and a little beyond; up to the edge
    towards one that lies off the view), inside the reach."""
    d = unit(np.asarray(line.direction, dtype=float))
    ts = [float((a - line.through) @ d) for a in line.anchors]
    margin = 0.12 * ctx.size
    if ts:
        seg = clip_segment(line.through + (min(ts) - margin) * d,
                           line.through + (max(ts) + margin) * d, ctx.reach)
    else:
        seg = clip_line(line.through, d, ctx.reach)
    if seg is not None:
        st = style or KENNEDY
        ctx.add("line", seg, width=st["lw"], dash=st["ls"][1], colour=st["color"], alpha=st["alpha"],
                zorder=st["zorder"], gid=line.key, layer="centres",
                group=f"{'normal' if style is NORMAL else 'kennedy'}:{line.key}")
        # labels keep off it (`draw.labels.Layout._lines_under`): a name across a dash-dot line
        # reads as struck through (C5-1.1's ezkerreko kable-zatia, twenty-fourth round (f))
        ctx.avoid(*seg, weight=0.5)


def draw_curvatures(ctx: Context) -> None:
    """Each asked curvature: the osculating circle of the point's path, its centre and the
    radius."""
    for c in ctx.scene.curvatures:
        _curvature(ctx, c)


def _curvature(ctx: Context, c: CurvatureView) -> None:
    group = f"curvature:{c.ref}"
    circle = clip_polyline(c.circle, ctx.reach)
    ctx.add("line", circle, width=1.3, colour=CURVATURE, alpha=0.9, zorder=3,
            gid=f"curvature:{c.ref}", layer="curvature", group=group)
    seg = clip_segment(c.point, c.centre, ctx.reach)
    if seg is not None:
        ctx.add("line", seg, width=0.9, dash=DOTTED, colour=CURVATURE, zorder=3, layer="curvature",
                group=group)
    if ctx.view.contains(c.centre):
        ctx.add("dot", [c.centre], shape="P", size=8, colour="white", fill=CURVATURE, width=0.6,
                zorder=10, gid=f"curvature-centre:{c.ref}", layer="curvature", group=group)
        ctx.avoid(c.centre, weight=3.0, radius=4.5)
        ctx.label(c.centre, c.label, CURVATURE, 2, f"curvature:{c.ref}", layer="curvature",
                  group=group, radius=4.5)
    else:
        seg = clip_segment(c.point, c.centre, ctx.view)
        ctx.label(c.point + 0.5 * (seg[1] - seg[0]) if seg is not None else c.point,
                  word("label-curvature-centre", ctx.lang, label=c.label,
                       place=coordinates(c.centre, ctx.size, ctx.lang)), CURVATURE, 2,
                  f"curvature:{c.ref}", layer="curvature", group=group)


def draw_axes(ctx: Context) -> None:
    """3D screw axes, dash-dot across the view."""
    for a in ctx.scene.axes:
        d = a.direction
        group = f"axis:{a.key}"
        if np.linalg.norm(d) < 1e-9:      # seen end-on: a point
            ctx.add("dot", [a.point], size=8, fill="none", colour=CENTRE, width=1.0, zorder=10,
                    gid=a.key, layer="centres", group=group)
            ctx.label(a.point, a.label, CENTRE, 2, a.key, layer="centres", group=group)
            continue
        seg = clip_line(a.point, unit(d), ctx.reach)
        if seg is not None:
            ctx.add("line", seg, width=1.4, dash=True, colour=CENTRE, zorder=3, gid=a.key,
                    layer="centres", group=group)
            shown = clip_line(a.point, unit(d), ctx.view) or seg
            ctx.label((shown[0] + shown[1]) / 2, a.label, CENTRE, 2, a.key, layer="centres",
                      group=group)
