"""Velocity and acceleration polygons: each side of a vector equation drawn head to tail
from the pole o, to scale; all sides close on the target's tip (seed 001)."""
from __future__ import annotations

from .context import Ctx
from .document import Arrow, Equation, Figure, msg


def polygon(ctx: Ctx, eq: Equation) -> Figure | None:
    """The polygon of a planar equation, or None when there is nothing to draw."""
    if not ctx.planar or eq.level not in ("v", "a") or not eq.figure:
        return None
    unit = "speed" if eq.level == "v" else "accel"
    fig = Figure(msg("fig.polygon_v" if eq.level == "v" else "fig.polygon_a"), unit=unit,
                 sample=ctx.symbolic)
    origin = (0.0, 0.0)
    drawn = 0
    for side in eq.sides:
        tip = origin
        for term in side:
            step = ctx.num(term.value)
            if sum(c * c for c in step) == 0:
                continue
            end = (tip[0] + step[0], tip[1] + step[1])
            fig.arrows.append(Arrow(tip, end, term.sym, "unknown" if term.unknown else "known"))
            tip = end
            drawn += 1
    end = ctx.num(eq.target.value)
    size = sum(c * c for c in end) ** 0.5
    same = [a for a in fig.arrows if a.start == origin and
            sum((p - q) ** 2 for p, q in zip(a.end, end)) ** 0.5 <= 1e-9 * size]
    if size > 0 and not same:
        fig.arrows.append(Arrow(origin, end, eq.target.sym, "result"))
    if drawn < 2:
        return None
    fig.points.append(("o", origin, "pole"))
    return fig
