"""Velocity and acceleration polygons as textbooks draw them: each side of a vector
equation head to tail from the pole o, to scale, all sides closing on the target's tip
(seed 001). Vertices are lettered as the images of the points (o, a, b, …); terms that
lie on one line are drawn side by side, offset across the line, so none hides another,
and the result is drawn (offset) even where it coincides with a term."""
from __future__ import annotations

import math

from .context import Ctx
from .document import Arrow, Equation, Figure, msg

OFFSET = 0.035          # of the polygon's size: the gap between collinear arrows


def polygon(ctx: Ctx, eq: Equation) -> Figure | None:
    """The polygon of a planar equation, or None when there is nothing to draw."""
    if not ctx.planar or eq.level not in ("v", "a") or not eq.figure:
        return None
    unit = "speed" if eq.level == "v" else "accel"
    origin = (0.0, 0.0)
    arrows: list[Arrow] = []
    images: dict[str, tuple] = {}
    for side in eq.sides:
        tip = origin
        for term in side:
            step = ctx.num(term.value)
            if sum(c * c for c in step) == 0:
                continue
            end = (tip[0] + step[0], tip[1] + step[1])
            arrows.append(Arrow(tip, end, term.sym, "unknown" if term.unknown else "known"))
            if term.kind == "point" and tip == origin:
                images.setdefault(_letter(term.sym.sub), end)
            tip = end
    end = ctx.num(eq.target.value)
    if len(arrows) < 2:
        return None
    if sum(c * c for c in end) > 0:
        arrows.append(Arrow(origin, end, eq.target.sym, "result"))
        images.setdefault(_letter(eq.target.sym.sub), end)
    styles = {a.style for a in arrows}
    fig = Figure(msg("fig.polygon_v" if eq.level == "v" else "fig.polygon_a",
                     unknown=int("unknown" in styles), result=int("result" in styles)),
                 arrows=_separated(arrows), unit=unit, sample=ctx.symbolic)
    fig.points.append(("o", origin, "pole"))
    fig.points += [(name, xy, "image") for name, xy in images.items() if name]
    return fig


def _letter(label: str) -> str:
    """The image of a point in the polygon: its name in lower case (A → a, O4 → o4)."""
    name = label.split("∈")[0].split("/")[0]
    return name.lower() if name and name[0].isalpha() else ""


def _separated(arrows: list[Arrow]) -> list[Arrow]:
    """Arrows moved across their line, in turn, while they overlap one already placed."""
    pts = [p for a in arrows for p in (a.start, a.end)]
    size = max(max(abs(p[0]) for p in pts), max(abs(p[1]) for p in pts), 1e-300)
    gap = OFFSET * size
    placed: list[Arrow] = []
    for a in arrows:
        k = 0
        moved = a
        while any(_overlap(moved, b, 0.2 * gap) for b in placed) and k < 8:
            k += 1
            shift = gap * ((k + 1) // 2) * (1 if k % 2 else -1)
            moved = _shifted(a, shift)
        placed.append(moved)
    return placed


def _shifted(a: Arrow, d: float) -> Arrow:
    dx, dy = a.end[0] - a.start[0], a.end[1] - a.start[1]
    n = math.hypot(dx, dy) or 1.0
    ox, oy = -dy / n * d, dx / n * d
    return Arrow((a.start[0] + ox, a.start[1] + oy), (a.end[0] + ox, a.end[1] + oy), a.label, a.style)


def _overlap(a: Arrow, b: Arrow, tol: float) -> bool:
    """Whether two arrows lie on one line (within tol) with overlapping extents."""
    ux, uy = a.end[0] - a.start[0], a.end[1] - a.start[1]
    vx, vy = b.end[0] - b.start[0], b.end[1] - b.start[1]
    la, lb = math.hypot(ux, uy), math.hypot(vx, vy)
    if la == 0 or lb == 0 or abs(ux * vy - uy * vx) > 1e-6 * la * lb:
        return False
    wx, wy = b.start[0] - a.start[0], b.start[1] - a.start[1]
    if abs(ux * wy - uy * wx) / la > tol:
        return False
    t0 = (wx * ux + wy * uy) / la
    t1 = ((b.end[0] - a.start[0]) * ux + (b.end[1] - a.start[1]) * uy) / la
    lo, hi = min(t0, t1), max(t0, t1)
    return hi > 0.02 * la and lo < 0.98 * la
