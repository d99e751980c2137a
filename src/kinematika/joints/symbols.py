"""How joints are drawn, and the `Mark`, the primitive every figure is made of: each kind's
`symbol` gives marks — polygons, lines and dots in the model's (page) coordinates, with
their colours by role — which `draw.picture` puts in the figure beside the bodies' and the
results' marks, and every painter paints as they are: matplotlib (`draw.paint`) and the page
(`web/static/js/figure.js`) alike, so that no view redraws a joint symbol of its own.

A symbol is fixed in the body it belongs to, so that an animation moves it with that body:
a slider's block with the slider, its guide with the guiding body; a pin with the moving
body of the pair (`moves_with`). Sizes are fractions of the drawing's size, so a figure
reads the same whatever the model's units.

The context a symbol is drawn in (duck-typed, given by the figure): `size` (the drawing's
size), `frame` (the fixed body), `still` (a still figure, not an animation's frame),
`centroid()` (of the moving bodies' points: "away from the mechanism"), `points(body)`
(its points on the page), `clip(p, d, inset)` (the part of the line through p along d inside
the figure's reach, less `inset`, or None), `keep_out()` (closed outlines that fixed guides
stop short of: the moving bodies' wheels and cams) — `draw.context.Context`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional

import numpy as np

if TYPE_CHECKING:
    from .seam import DrawContext, JointView


Vec = np.ndarray

PIN_SIZE = 7.5              # marker size of a revolute pin, points
SUPPORT = 0.045             # size of a fixed-pivot symbol (of the drawing's size)
STEM_GAP = 0.4              # a wheel's axle: its support's apex beyond the rim (of the symbol's size)
HIDDEN = (3.0, 2.0)         # the stem's hidden part, inside the wheel: dashes, in line widths
BLOCK = (0.11, 0.06)        # slider block: length and height
SLOT_WIDTH = 0.035
HATCH_BAND = 0.03


@dataclass
class Mark:
    """One drawn primitive, in page coordinates: every figure is a list of them (a joint's
    symbol, and the whole figure `draw.picture` builds), painted as they are by matplotlib
    (`draw.paint`) and by the page (`web/static/js/figure.js`).

    `kind`: "polygon" (closed, filled and/or outlined; `hatch`: the frame's hatching),
    "line" (a polyline), "dot" (a marker of `size` points at `points[0]`, its `shape` "o",
    "D", "X" or "P"), "circle" (centre `points[0]`, radius `r` in model units), "ring" (the
    band between radii `r - band` and `r`), "arrow" (from `points[0]` to `points[1]`, its
    `head` "-|>" or "<|-|>" of `size` points, set `shift` points sideways, cased in white
    `halo` points beyond its stroke so that it stays seen on a bar it runs along), "text" (`text` at
    `points[0]`, placed by the painter near it, towards `prefer` when given, clear of the
    others in order of `priority`; `side` is a good side for a painter that places labels
    without weighing what is drawn, such as the page's) and "clear" (nothing painted: a polyline that labels keep
    off).

    `colour` (the stroke) and `fill` are colours or, in a joint's symbol, roles: "ink",
    "ground", "white", "none", or "body:NAME" (that body's colour), which `draw.picture`
    turns into colours. Widths and sizes are in points; `dash` is True (dash-dot, an axis) or
    the lengths of dashes and gaps in line widths. `avoid` is how strongly labels keep off it
    (0: not at all), `radius` how far around its points (points of the page). `moves_with`
    is the body that carries it (an animation and the page move it with that body); `group`
    ("ROLE:KEY") gathers the marks of one thing drawn (an instant centre's marker and label)
    and `about` holds what the page needs to move it (a live arrow's swept point)."""

    kind: str                           # see above
    points: Vec                         # (n, 2)
    colour: str = "ink"
    fill: str = "none"
    width: float = 1.3                  # line width, points
    size: float = 0.0                   # a dot's diameter, an arrow head's, a text's font, points
    hatch: bool | str = False           # the frame's hatching (a matplotlib pattern: across an edge)
    dash: Any = False                   # True: dash-dot (an axis); or dash lengths in line widths
    zorder: float = 3
    moves_with: Optional[str] = None    # the body that carries it (None: fixed)
    gid: str = ""
    avoid: float = 1.0
    radius: float = 0.0
    still: bool = False                 # true of a still figure only (not moved with any body)
    alpha: float = 1.0                  # opacity of the stroke and the fill
    r: float = 0.0                      # a circle's or a ring's radius, model units
    band: float = 0.0                   # a ring's width, model units
    cap: str = ""                       # stroke ends: "round", "butt", "projecting"; "" (`draw.picture.cap_of`)
    join: str = ""                      # corners: "round" or "" (miter)
    shape: str = "o"                    # a dot's marker
    head: str = ""                      # an arrow's heads
    shift: float = 0.0                  # an arrow's sideways shift, points
    halo: float = 0.0                   # an arrow's white casing, points beyond its stroke on each side
    text: str = ""                      # a text's words (matplotlib mathtext)
    prefer: Optional[Vec] = None        # a text's preferred direction from its anchor
    side: Optional[Vec] = None          # where it goes for a painter that does not weigh the drawing
    priority: int = 0                   # a text's order of placing (lower first)
    weight: str = "normal"              # a text's font
    style: str = "normal"
    layer: str = ""                     # results the page switches: velocity, acceleration, centres, curvature
    group: str = ""                     # ROLE:KEY of the thing it belongs to
    about: Optional[dict] = None        # what the page needs to move it (a live arrow)
    shaft: Optional[Vec] = None         # a vector's value: its arrow (start, end), beside which it may sit
    spots: Optional[Vec] = None         # a body's name: other points of its body it may be led from


# shapes of symbols -------------------------------------------------------------------------
def unit(v: Vec) -> Vec:
    """`v` over its length (a zero vector is returned as it is)."""
    n = float(np.linalg.norm(v))
    return v / n if n > 0 else v


def perpendicular(v: Vec) -> Vec:
    """`v` turned a quarter turn counter-clockwise: (−v_y, v_x)."""
    return np.array([-v[1], v[0]])


def rectangle(centre: Vec, along: Vec, length: float, height: float) -> Vec:
    """The corners of a rectangle centred at `centre`, its length along the unit `along`."""
    n = np.array([-along[1], along[0]])
    hl, hh = along * length / 2, n * height / 2
    return np.array([centre - hl - hh, centre + hl - hh, centre + hl + hh, centre - hl + hh])


def stadium(p: Vec, q: Vec, half_width: float) -> Vec:
    """The outline of a slot from p to q with rounded ends of radius `half_width`."""
    d = q - p
    base = math.atan2(d[1], d[0])
    ends = []
    for centre, start in ((q, base - math.pi / 2), (p, base + math.pi / 2)):
        t = np.linspace(start, start + math.pi, 19)
        ends.append(centre + half_width * np.column_stack([np.cos(t), np.sin(t)]))
    return np.vstack(ends + [ends[0][:1]])


def ring(centre: Vec, radius: float, n: int = 61) -> Vec:
    """A circle as a closed polygon."""
    t = np.linspace(0, 2 * math.pi, n)
    return centre + radius * np.column_stack([np.cos(t), np.sin(t)])


# shared symbols ----------------------------------------------------------------------------
def mover(view: JointView, ctx: DrawContext) -> Optional[str]:
    """The body a symbol at the joint moves with: the second body unless it is the frame."""
    if view.b != ctx.frame:
        return view.b
    return view.a if view.a != ctx.frame else None


def pin(view: JointView, ctx: DrawContext, centre_dot: bool = False, body: Any = "") -> list[Mark]:
    """A pin at the joint, moving with `body` (by default the pair's moving body)."""
    p = np.asarray(view.at, dtype=float)[None, :]
    body = mover(view, ctx) if body == "" else body
    out = [Mark("dot", p, "ink", "white", 1.6, PIN_SIZE, zorder=6, moves_with=body, gid=f"joint:{view.id}",
                avoid=2.0, radius=4.0)]
    if centre_dot:
        out.append(Mark("dot", p, "ink", "ink", 0, 2.5, zorder=7, moves_with=body, avoid=0))
    return out


def support(p: Vec, ctx: DrawContext) -> list[Mark]:
    """A fixed pivot: a triangle from the pin to a hatched base, below the pin (in a planar
    model, above it when the pin is clearly above the rest of the mechanism: it hangs).

    A pivot that is a moving wheel's axle (`DrawContext.hub`: a disc turning about it) has its
    support outside the wheel, on a stem from the pin (dashed across the disc: hidden behind
    it), on the first side
    (below or above as said, the other, right, left) where it lies on no other moving body:
    a support inside the wheel read as the wheel welded to the ground (C5-1.4's sun, turning
    at 7ω, and the carrier over the one support at O), and C5-1.5's upper pulleys as held
    inside by a piece of ground, with no ceiling to hang from (issue 30, twenty-seventh round
    (f))."""
    p = np.asarray(p, dtype=float)
    h = SUPPORT * ctx.size
    d = p - ctx.centroid()
    hanging = ctx.dim == 2 and d[1] > 0.3 * np.linalg.norm(d) and d[1] > 1e-9
    down = np.array([0.0, 1.0]) if hanging else np.array([0.0, -1.0])     # 3D: the vertical
    hub = ctx.hub(p) if ctx.dim == 2 and hasattr(ctx, "hub") else 0.0
    if hub <= 0:
        return _support_at(p, down, h)
    reach = hub + STEM_GAP * h
    sides = [down, -down, np.array([1.0, 0.0]), np.array([-1.0, 0.0])]

    def lying(u: Vec) -> int:                # the support's points on other moving bodies
        across = perpendicular(u)
        pts = [p + u * (reach + t * h) + s * h * across for t in (0.0, 0.5, 1.0, 1.5) for s in (-1.0, 0.0, 1.0)]
        return ctx.crowded(pts, p)

    u = min(sides, key=lambda u: (lying(u), next(i for i, v in enumerate(sides) if v is u)))
    apex, rim = p + reach * u, p + hub * u
    # the stem: hidden inside the wheel (dashed, as a draughtsman draws a hidden edge), seen beyond it
    hidden = Mark("line", np.array([p, rim]), "ground", width=1.2, dash=HIDDEN, zorder=1, gid="ground:axle",
                  avoid=0.3)                # a faint hidden line: a label may lie over it
    stem = Mark("line", np.array([rim, apex]), "ground", width=2.5, zorder=1, gid="ground:axle")
    return [hidden, stem] + _support_at(apex, u, h)


def _support_at(p: Vec, down: Vec, h: float) -> list[Mark]:
    """A fixed pivot's triangle from `p` to a hatched base `h` further along `down`."""
    side = perpendicular(down)
    base = p + down * h
    tri = np.array([p, base - 0.75 * h * side, base + 0.75 * h * side])
    band = 0.55 * h
    return [Mark("polygon", tri, "ground", "#e0e0e0", 1.3, zorder=2, gid="ground:pivot"),
            Mark("line", np.array([base - h * side, base + h * side]), "ground", width=1.8, zorder=2),
            Mark("polygon", np.array([base - h * side, base + h * side, base + h * side + band * down,
                                      base - h * side + band * down]), "ground", width=0, hatch=True, zorder=1)]


def hatched_edge(p: Vec, q: Vec, side: Vec, ctx: DrawContext, gid: str) -> list[Mark]:
    """A fixed edge from p to q, hatched on `side` (where the frame's material is)."""
    band = HATCH_BAND * ctx.size
    return [Mark("line", np.array([p, q]), "ground", width=1.8, zorder=2, gid=gid),
            Mark("polygon", np.array([p, q, q + band * side, p + band * side]), "ground", width=0,
                 hatch=True, zorder=1, avoid=0.7)]


def block_on_guide(view: JointView, ctx: DrawContext) -> list[Mark]:
    """A block (second body) on its guide (first body); a fixed guide is hatched."""
    along = view.along if view.along is not None else (unit(view.axis) if view.axis is not None else None)
    sleeve = None if along is None or view.at is not None else sleeve_at(view, along, ctx)
    centre = sleeve if sleeve is not None else slider_centre(view, ctx)
    if along is None or centre is None:
        return []
    length, height = (f * ctx.size for f in BLOCK)
    out = [] if sleeve is not None else guide(view.a, centre, along, height, ctx)
    block = rectangle(centre, along, length, height)
    owner = view.a if sleeve is not None else view.b          # a sleeve is the guiding body's
    fill = f"body:{owner}" if owner != ctx.frame else "ground"
    out.append(Mark("polygon", block, "ink", fill, 1.3, zorder=4, gid=f"joint:{view.id}",
                    moves_with=(view.a if sleeve is not None else mover(view, ctx)) if owner != ctx.frame else None))
    return out


def sleeve_at(view: JointView, along: Vec, ctx: DrawContext) -> Optional[Vec]:
    """Where a rod slides through a sleeve of the guiding body: when the sliding body's
    points lie on one line along the guide (it is the rod) and the guiding body, not the
    frame, has a point of its own on that line, the sleeve is there — the point the model
    gives it (C5-1.3: "the sleeve at its centre S" of the support, the bar along QS; the
    block was drawn at the bar's far end E). None otherwise: a block carried by its own point
    on a guide (001's N on M) keeps `slider_centre`."""
    if view.a == ctx.frame:
        return None
    rod = [np.asarray(p, dtype=float) for p in ctx.points(view.b)]
    u = unit(np.asarray(along, dtype=float))
    tol = 1e-9 * ctx.size

    def on(p: Vec) -> bool:
        d = p - rod[0]
        return abs(float(d[0] * u[1] - d[1] * u[0])) <= tol

    if len(rod) < 2 or not all(on(p) for p in rod[1:]):
        return None
    own = [np.asarray(p, dtype=float) for p in ctx.points(view.a)]
    found = [p for p in own if on(p) and not any(np.linalg.norm(p - q) <= tol for q in rod)]
    return found[0] if found else None


def slider_centre(view: JointView, ctx: DrawContext) -> Optional[Vec]:
    """Where a slider's block is drawn: at the joint's point `at`, else at the moving body's
    own points — those no other joint holds (the slider's, else the guide's) — else at the
    centroid of all its points, else nowhere (None). A body is drawn at its points: C5-1.5's
    block K hangs from strand 5, whose other point T7 is its contact with pulley 4, and a
    block at the centroid of T7 and K sat halfway down the strand, where no point is (issue
    30, sixteenth round (f))."""
    if view.at is not None:
        return np.asarray(view.at, dtype=float)
    for name in (view.b, view.a):
        pts = ctx.points(name)
        if len(pts) and name != ctx.frame:
            held = ctx.joined(name, view.id)
            own = [p for p in pts if not any(np.linalg.norm(p - q) <= 1e-9 * ctx.size for q in held)]
            return np.mean(own or pts, axis=0)
    return None


def guide(body: str, centre: Vec, along: Vec, height: float, ctx: DrawContext) -> list[Mark]:
    """The guide a block slides on: the frame's hatched edge beside the block, or a bar of
    the guiding body over its points.

    A fixed guide is the line the block runs on (tangent to the block, on the side away from
    the mechanism), hatched on that side only where the guide shows as ground: outside the
    moving bodies' wheels and cams. A block inside such an outline (001's slider carrying
    a roller on its axle) runs in a fixed `slot` through the roller — a hatched edge tangent
    to the roller read as a ground the roller rolls on (issue 30, sixteenth round (d)), a
    hatched line through its centre as a floor it was sunk into (eighteenth round (d)); a
    block outside them has its guide cut short of them (a follower's guide stops before its
    cam)."""
    if body == ctx.frame:
        n = perpendicular(along)
        side = n if float(n @ (centre - ctx.centroid())) > 1e-12 * ctx.size else -n
        base = centre + side * height / 2
        seg = ctx.clip(base, along, HATCH_BAND * ctx.size)
        if seg is None:
            return []
        outlines = ctx.keep_out()
        if carried_reach(centre, side, outlines) > 0:                 # the block rides inside a wheel
            return slot(seg, centre, along, height, outlines, ctx)
        seg = kept_out(seg, base, along, outlines, 0.5 * height)
        return [] if seg is None else hatched_edge(seg[0], seg[1], side, ctx, "ground:guide")
    pts = list(ctx.points(body)) + [centre]
    ts = [float((p - centre) @ along) for p in pts]
    margin = 0.12 * ctx.size
    line = np.array([centre + (min(ts) - margin) * along, centre + (max(ts) + margin) * along])
    return [Mark("line", line, f"body:{body}", width=3.0, zorder=3, moves_with=body)]


def slot(seg: tuple, centre: Vec, along: Vec, height: float, outlines: list,
         ctx: DrawContext) -> list[Mark]:
    """A fixed guide that runs through a moving wheel (a slider carrying a roller on its axle,
    001's rolling pair) drawn as the notes draw a fixed slot: two thin parallel lines, one on
    each side of the block (the block slides between them), across the wheel and a little
    beyond (not over the frame's other pivots on its line, 001's B), closed at each end by a short wall fixed to the frame — hatched outwards, away from the
    block and the roller, and only where the end lies outside every wheel. No hatched band
    runs along the slot: a hatched line through the roller's centre read as a floor the
    roller was sunk into (issue 30, eighteenth round (d); before, its line was hatched outside the wheel)."""
    p, q = seg
    n = perpendicular(along)
    half = height / 2
    t0, t1 = (float((x - centre) @ along) for x in (p, q))
    reach = [np.asarray(poly, dtype=float) - centre for poly in outlines]
    spans = [v @ along for v in reach if _inside(v)]
    if spans:                                   # the wheel's width and a little: not over the frame's pivots
        margin = 1.5 * height
        t0 = max(t0, min(float(t.min()) for t in spans) - margin)
        t1 = min(t1, max(float(t.max()) for t in spans) + margin)
    a, b = centre + t0 * along, centre + t1 * along
    out = [Mark("line", np.array([a + s * half * n, b + s * half * n]), "ground", width=1.0, zorder=2,
                gid="ground:slot") for s in (1.0, -1.0)]
    band = 0.6 * HATCH_BAND * ctx.size
    for end, out_dir in ((a, -along), (b, along)):
        if any(_inside(np.asarray(poly, dtype=float) - end) for poly in outlines):
            continue
        wall = np.array([end - half * n, end + half * n])
        out.append(Mark("line", wall, "ground", width=1.6, zorder=2, gid="ground:slot-end"))
        out.append(Mark("polygon", np.array([wall[0], wall[1], wall[1] + band * out_dir,
                                             wall[0] + band * out_dir]), "ground", width=0,
                        hatch=True, zorder=1, avoid=0.7, gid="ground:slot-end-hatch"))
    return out


def carried_reach(centre: Vec, side: Vec, outlines: list) -> float:
    """How far the outlines around a block's centre reach towards the guide's `side` (0 when
    none holds it): whether the block rides inside a wheel (001's rolling pair: a slider
    carrying a roller on its axle), whose guide `slot` draws."""
    reach = 0.0
    for poly in outlines:
        v = np.asarray(poly, dtype=float) - centre
        if _inside(v):
            reach = max(reach, float((v @ side).max()))
    return reach


def _inside(v: np.ndarray) -> bool:
    """Whether the origin is inside the closed polygon `v` (crossings of the ray +x)."""
    x, y = v[:, 0], v[:, 1]
    x2, y2 = np.roll(x, -1), np.roll(y, -1)
    crossing = (y > 0) != (y2 > 0)
    xs = (x + (x2 - x) * y / np.where(crossing, y - y2, 1.0))[crossing]
    return bool(np.count_nonzero(xs > 0) % 2 == 1)


def kept_out(seg: tuple, base: Vec, along: Vec, outlines: list, margin: float) -> Optional[tuple]:
    """The segment `seg` of the line through `base` along the unit `along`, cut where it would
    cross one of the closed `outlines` ((n, 2) polygons: the moving bodies' wheels and cams),
    less `margin`: a fixed guide stops short of the cam its follower rides on. An outline
    that `base` is inside is not cut for (the guide is inside it)."""
    t0, t1 = (float((p - base) @ along) for p in seg)
    normal = perpendicular(along)
    for poly in outlines:
        v = np.asarray(poly, dtype=float) - base
        h, t = v @ normal, v @ along                     # across and along the line
        h2, t2 = np.roll(h, -1), np.roll(t, -1)
        crossing = (h > 0) != (h2 > 0)
        ts = (t + (t2 - t) * h / np.where(crossing, h - h2, 1.0))[crossing]
        if np.count_nonzero(ts > 0) % 2 == 1:            # base inside the outline
            continue
        ahead, behind = ts[ts > 0], ts[ts < 0]
        if len(ahead):
            t1 = min(t1, float(ahead.min()) - margin)
        if len(behind):
            t0 = max(t0, float(behind.max()) + margin)
    if t1 - t0 <= margin:
        return None
    return base + t0 * along, base + t1 * along


def contact_dot(view: JointView, ctx: DrawContext) -> list[Mark]:
    """The contact point of a touching pair (a still figure only: it is no body's point)."""
    if view.contact is None or not ctx.still:
        return []
    return [Mark("dot", np.asarray(view.contact, dtype=float)[None, :], "ink", "ink", 0, 3.5, zorder=6,
                 gid=f"joint:{view.id}", still=True)]
