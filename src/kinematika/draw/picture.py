"""What a figure draws, as primitives: the scene turned into `Mark`s (outlines, hatches,
symbols, dots, arrows, texts) in page coordinates, with their colours, widths, layers and
the bodies they move with.

Every rule of how a thing is drawn lives on this side: how a body is drawn (`bodies`), a
joint (its kind's `symbol`), an instant centre, a Kennedy line, a curvature circle, a
screw axis (`marks`), a vector (`vectors`). The painters only paint the marks as they are:
matplotlib (`draw.paint`, for `draw`, `animate`, the explanations' figures) and the page
(`web/static/js/figure.js`, which receives them from `/api/draw`). A picture is made for a
`view` (the box the figure shows: far centres are marked at its edge, labels kept inside)
and a `reach` (where infinite lines stop; the view, unless the figure can be zoomed out).
"""
from __future__ import annotations

import dataclasses
from typing import Optional


from ..joints import kind as joint_kind
from ..joints.symbols import Mark
from .bodies import draw_bodies
from .context import Context
from .geometry import Box
from .marks import draw_axes, draw_curvatures, draw_marks
from .scene import Scene
from .style import GROUND, INK
from .vectors import draw_vectors


def picture(scene: Scene, view: Box, drawn: Optional[list] = None, still: bool = True,
            labels: bool = True, words: bool = True, lang: Optional[str] = None,
            reach: Optional[Box] = None, results: bool = True,
            per_point: Optional[float] = None) -> list[Mark]:
    """Every mark of the figure of `scene` showing `view`: the bodies, the joints, and with
    `results` the curvature circles, screw axes, instant centres and Kennedy lines and the
    `drawn` arrows (`vectors.arrows`); colours are colours (a symbol's roles resolved).
    `per_point`: the drawing's units a point on the page, when the figure is made for a size
    (what tells whether an arrow's stroke touches a line: `vectors.off_lines`)."""
    ctx = Context(scene, view, still, labels, words, lang, reach, per_point)
    if results:
        ctx.arrows = [(a.start, a.end) for a in drawn or [] if a.drawn]
    draw_bodies(ctx)
    draw_joints(ctx)
    if results:
        draw_curvatures(ctx)
        draw_axes(ctx)
        draw_marks(ctx)
        draw_vectors(ctx, drawn or [])
    return [dataclasses.replace(m, cap=cap_of(m)) for m in ctx.marks]


def cap_of(m: Mark) -> str:
    """The ends of a mark's strokes (its dashes' too), named for both painters: the mark's
    own, else butt for a dashed mark or an outline (a dash-dot's dot is one line width
    long, its gaps as drawn) and projecting for a solid line — how matplotlib has always
    painted them."""
    if m.cap:
        return m.cap
    return "projecting" if m.kind == "line" and not m.dash else "butt"


def draw_joints(ctx: Context) -> None:
    """Every joint's symbol, as its kind describes it (`joints.symbols`), with its colour
    roles as colours; a still figure gets the marks a moving one leaves out."""
    for j in ctx.scene.joints:
        for mark in joint_kind(j.type).symbol(j, ctx):
            ctx.marks.append(dataclasses.replace(
                mark, colour=colour_of(ctx.scene, mark.colour), fill=colour_of(ctx.scene, mark.fill),
                cap=mark.cap or "butt", group=mark.group or f"joint:{j.id}"))


def colour_of(scene: Scene, role: str) -> str:
    """A mark's colour role as a colour: ink, ground, white, none, body:NAME, or a colour."""
    if role.startswith("body:"):
        return scene.bodies[role[5:]].colour
    return {"ink": INK, "ground": GROUND, "white": "white", "none": "none"}.get(role, role)
