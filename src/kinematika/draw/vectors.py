"""Velocity and acceleration arrows, scaled per kind.

Within each kind the arrows are to scale: the longest is `LONGEST` of the drawing size.
An arrow that would come out shorter than `SHORTEST` of the drawing size is drawn at that
length instead, so that a small vector next to a much larger one stays visible; its label
then says "enlarged". A zero vector gets no arrow, only its label (= 0) at the point.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Optional

import numpy as np
from matplotlib.path import Path

from .geometry import overlap_along, perpendicular, points_to_data, unit
from .context import Context
from .scene import VectorView
from .names import equation
from .style import KIND_COLOURS, LONGEST, SHORTEST

ZERO = 1e-9          # relative to the largest vector of the kind
SIDE = 4.0           # points between arrows along one line from one point
SIDE_ANGLE = 6.0     # degrees: arrows closer than this in direction are side by side
HALO = 1.6           # points of white casing each side of an arrow's stroke (`arrow_mark`)
WIDTH = 2.2          # points: an arrow's stroke (`arrow_mark`)
HEAD = 8.0           # points: about an arrow's head's length (`arrow_mark`'s size 15): what it may share with a line
GAP = 2.0            # points of paper between a line and an arrow set beside it (`off_lines`)


@dataclass
class Arrow:
    """A vector's arrow on the page: from `start` to `end`, `enlarged` when drawn at the
    shortest length, `zero` when only its label is shown."""

    view: VectorView
    start: np.ndarray
    end: np.ndarray
    enlarged: bool
    zero: bool = False
    tip_at_point: bool = False           # drawn ending at its point (off a bar)

    @property
    def drawn(self) -> bool:
        """Whether the arrow has a length to draw (a zero vector only has its label)."""
        return bool(np.linalg.norm(self.end - self.start) > 0)


def arrow_scales(vectors: list[VectorView]) -> dict[str, float]:
    """For each kind, the largest magnitude among its vectors (what LONGEST stands for)."""
    out: dict[str, float] = {}
    for v in vectors:
        out[v.kind] = max(out.get(v.kind, 0.0), v.magnitude)
    return out


def arrow_for(view: VectorView, largest: float, size: float, origin=None, value=None,
              magnitude=None) -> Arrow:
    """The arrow of `view`, or of `value` (page) of `magnitude` (model) at `origin`.

    Lengths follow the model magnitude (a 3D vector is then projected like the drawing)."""
    origin = view.origin if origin is None else np.asarray(origin, dtype=float)
    value = view.value if value is None else np.asarray(value, dtype=float)
    magnitude = view.magnitude if magnitude is None else float(magnitude)
    if largest <= 0 or magnitude <= ZERO * largest or not np.all(np.isfinite(value)):
        return Arrow(view, origin, origin.copy(), False, zero=True)
    factor = LONGEST * size / largest
    enlarged = magnitude * factor < SHORTEST * size
    if enlarged:
        factor = SHORTEST * size / magnitude
    return Arrow(view, origin, origin + value * factor, enlarged)


def arrows(vectors: list[VectorView], size: float, bars: Optional[list] = None,
           grounds: Optional[list] = None) -> list[Arrow]:
    """Every vector's arrow, each kind to its own scale (the longest of a kind is `LONGEST` of
    the drawing size); an acceleration that would lie along a bar from its point (a
    centripetal acceleration along its crank) is drawn ending at the point instead, beyond
    the bar, where it can be seen. A velocity always starts at its point, as the notes draw
    it (issue 30, sixteenth round (f): C5-2.2's v_O and v_P, along the chassis, ended at
    their points and read as velocities of other points): along a bar it is drawn over the
    bar, above it (`arrow_mark`'s zorder), and into the ground across its line, over it
    (its value kept off the ground: `draw.labels.GROUND`). Drawn ending at its point, as
    round 27 (f) drew one that ran into the ground, it was read as applied elsewhere
    (C5-1.2's v_J∈OJ, C5-E.3's v_B; issue 30, twenty-eighth round (g)). An acceleration
    that would run from its point into the ground (across one of `grounds`) is drawn
    ending at its point instead (`off_ground`)."""
    largest = arrow_scales(vectors)
    out = [arrow_for(v, largest[v.kind], size) for v in vectors]
    out = [off_bars(a, bars or [], size) if a.view.kind == "acceleration" else a for a in out]
    return [off_ground(a, grounds or [], bars or [], size) if a.view.kind == "acceleration" else a
            for a in out]


def off_ground(arrow: Arrow, grounds: list, bars: list, size: float) -> Arrow:
    """`arrow` turned to end at its point when, starting there, it would cross one of the
    ground's edges (`grounds`: each by its two ends, `figure.grounds`) into the ground's
    material, and ending there it would neither cross one nor run along a bar: an arrow
    through the hatching, its value set under the ground, reads as no part of the mechanism
    (C5-E.3's v_B, the rod's end down into the track; issue 30, twenty-seventh round (f)). As
    it is otherwise: a velocity starts at its point wherever it can."""
    if not arrow.drawn or arrow.tip_at_point or not _crosses(arrow.start, arrow.end, grounds, size):
        return arrow
    tail = 2 * arrow.start - arrow.end
    if _crosses(tail, arrow.start, grounds, size) or _along(arrow.start, unit(tail - arrow.start), bars, size):
        return arrow
    return Arrow(arrow.view, tail, arrow.start.copy(), arrow.enlarged, arrow.zero, tip_at_point=True)


def _crosses(p: np.ndarray, q: np.ndarray, edges: list, size: float) -> bool:
    """Whether the segment pq crosses one of `edges` (their two ends), p clear of it (a point
    on the ground starts on it)."""
    tol = 1e-6 * size
    for a, b in edges:
        d = unit(b - a)
        n = np.array([-d[1], d[0]])
        sp, sq = float((p - a) @ n), float((q - a) @ n)
        if abs(sp) <= tol or abs(sq) <= tol or sp * sq >= 0:
            continue
        x = p + (q - p) * sp / (sp - sq)                  # where pq meets the edge's line
        if -tol <= float((x - a) @ d) <= float(np.linalg.norm(b - a)) + tol:
            return True
    return False


def off_bars(arrow: Arrow, bars: list, size: float) -> Arrow:
    """`arrow` turned to end at its point when, starting there, it would run along one of
    `bars` ((p, q) segments of the bodies); as it is otherwise."""
    if not arrow.drawn:
        return arrow
    d = unit(arrow.end - arrow.start)
    if _along(arrow.start, d, bars, size) and not _along(arrow.start, -d, bars, size):
        return Arrow(arrow.view, 2 * arrow.start - arrow.end, arrow.start.copy(), arrow.enlarged,
                     arrow.zero, tip_at_point=True)
    return arrow          # free, or a bar both ways (a point inside a slot): it cannot be helped


def _along(point: np.ndarray, d: np.ndarray, bars: list, size: float) -> bool:
    """Whether a bar leaves `point` in the direction d (within 8°), or passes through it
    that way."""
    for p, q in bars:
        for a, b in ((p, q), (q, p)):
            ab = b - a
            length = float(np.linalg.norm(ab))
            if length <= 1e-9 * size:
                continue
            t = float((point - a) @ ab) / length ** 2
            across = float(np.linalg.norm(a + t * ab - point))
            if across > 1e-6 * size or not -1e-9 <= t < 1 - 1e-6:
                continue
            if float(unit(ab) @ d) > math.cos(math.radians(8)):
                return True
    return False


def side_shifts(drawn: list[Arrow], size: float) -> list[float]:
    """Sideways shifts (points) that keep arrows from one point along one direction side by
    side instead of one hiding the other (a ram's velocity and acceleration)."""
    shifts: list[float] = []
    for i, a in enumerate(drawn):
        shift = 0.0
        if a.drawn:
            d = unit(a.end - a.start)
            for b, s in zip(drawn[:i], shifts):
                if b.drawn and np.linalg.norm(b.view.origin - a.view.origin) <= 1e-9 * size and \
                        abs(float(unit(b.end - b.start) @ d)) > math.cos(math.radians(SIDE_ANGLE)):
                    shift = max(shift, s + SIDE)
        shifts.append(shift)
    return shifts


def arrow_mark(arrow: Arrow, gid: str, shift: float = 0.0) -> dict:
    """The arrow of `arrow` as a mark's fields, in its kind's colour (velocities above
    accelerations), set `shift` points sideways, cased in white (`HALO`): a velocity starts
    at its point and may run along the body's bar or strand (C5-1.3's v_E along the bar and
    through the sleeve, C5-1.5's v_K and v_T2 on their strands, C5-2.2's v_O and v_P on the
    chassis; issue 30, twenty-seventh round (f)); the casing parts the arrow from the bar
    under it, as a draughtsman leaves a gap, and keeps both seen."""
    return dict(head="-|>", size=15, width=WIDTH, colour=KIND_COLOURS[arrow.view.kind],
                zorder=10 if arrow.view.kind == "velocity" else 9, gid=gid, shift=shift, halo=HALO)


def draw_vectors(ctx: Context, drawn: list[Arrow]) -> None:
    """The arrows, each labelled at its tip (`v_B = …`, "enlarged" when it is); arrows from
    one point in nearly one direction are set side by side, and a zero vector gets its label at
    the point. The page moves an absolute vector's arrow over the sweep (`about`: the swept
    point, the symbol, whether it is drawn ending at its point)."""
    shifts = [side + off_lines(ctx, arrow, side) for arrow, side in zip(drawn, side_shifts(drawn, ctx.size))]
    for arrow, shift in zip(drawn, shifts):
        v = arrow.view
        colour = KIND_COLOURS[v.kind]
        name = equation(v.label, "0" if arrow.zero else v.text)
        if not ctx.words and not arrow.zero and v.text.startswith("≈"):
            # a bare figure of a symbolic page (an explanation's) whose formula is too long
            # to set: the vector's name alone, as its other labels are formulas — a sample
            # number (v_P ≈ 4,03, C5-E.6) reads as a datum the page does not have
            name = v.label
        said = {"name": name, "say": "enlarged", "args": {}} if arrow.enlarged else None
        text = name + (" (enlarged)" if arrow.enlarged and ctx.words else "")
        group, layer = f"vector:{v.key}", v.kind
        about = {"ref": v.ref, "kind": v.kind, "relative_to": v.relative_to, "symbol": v.label,
                 "at_point": arrow.tip_at_point, "origin": v.origin, "value": v.value,
                 "magnitude": v.magnitude}
        ctx.add("arrow", [arrow.start, arrow.end], layer=layer, group=group, about=about,
                **arrow_mark(arrow, v.key, shift))          # of no length: none drawn
        if arrow.drawn:
            aside = perpendicular(unit(arrow.end - arrow.start)) * ctx.pt(shift)
            ctx.avoid(arrow.start + aside, arrow.end + aside, weight=3.0)
            ctx.add("clear", [arrow.start, arrow.end], avoid=0.0, zorder=0, group=f"head:{v.key}")
            free, away = (arrow.start, arrow.start - arrow.end) if arrow.tip_at_point else \
                (arrow.end, arrow.end - arrow.start)                # the label beyond the free end
            ctx.label(free + aside, text, colour, 1, v.key, away, layer=layer, group=group, about=said,
                      shaft=np.array([arrow.start, arrow.end], dtype=float) + aside)
        else:
            ctx.label(arrow.start, text, colour, 1, v.key, layer=layer, group=group, about=said)


def drawn_lines(ctx: Context) -> list[tuple[np.ndarray, float]]:
    """The lines drawn so far that an arrow could lie along, each as its polyline (data; a
    polygon's closed) and its width (points): bars, strands, belts, rims' chords, the
    ground's edges, joints' blocks, construction lines — no arrow, dot, circle or text."""
    out = []
    for m in ctx.marks:
        if m.kind not in ("line", "polygon") or m.width <= 0 or m.colour == "none":
            continue
        pts = np.asarray(m.points, dtype=float)
        out.append((np.vstack([pts, pts[:1]]) if m.kind == "polygon" else pts, float(m.width)))
    return out


def _under(p: np.ndarray, q: np.ndarray, lines: list, view, per_point: Optional[float] = None) -> tuple[float, float]:
    """How long the arrow pq runs along the lines (`geometry.overlap_along`: the longest
    stretch one line shares with it, near enough to touch its stroke), and the widest such
    line's width (points)."""
    longest, wide = 0.0, 0.0
    for pts, width in lines:
        near = points_to_data(width / 2 + WIDTH / 2 + HALO, view, per_point)
        for a, b in itertools.pairwise(pts):
            run = overlap_along(p, q, a, b, near)
            if run > 0:
                longest, wide = max(longest, run), max(wide, width)
    return longest, wide


def off_lines(ctx: Context, arrow: Arrow, side: float = 0.0) -> float:
    """The sideways shift (points, along the arrow's left normal) that sets `arrow` beside
    the lines it would run along for more than its head's length (`HEAD`), parallel to
    them, clear of their stroke (`GAP`): drawn over C5-2.2's chassis bars (v_O, v_P),
    C5-1.5's strands (v_T2, v_K), C5-E.6's chain and frame tube (v_H), the line vanished
    under the arrow and its value read as written on the line, white casing or not (issue
    30, twenty-ninth round (e): round 27 (f) drew it over the bar, cased). The arrow keeps
    its point's place along the line, beside the point's dot, on the side where it lies
    along fewer lines, away from the mechanism when both are clear, farther out (up to three
    times) when a line beside the first one is in the way; 0 when it runs along
    none (a wheel's cross-hair leaves room for it: `bodies.cross_hair`)."""
    if not arrow.drawn:
        return 0.0
    lines = drawn_lines(ctx)
    start, end = arrow.start, arrow.end
    n = perpendicular(unit(end - start))
    run, wide = _under(start, end, lines, ctx.view, ctx.per_point)
    if run <= ctx.pt(HEAD):
        return 0.0
    away = wide / 2 + WIDTH / 2 + HALO + GAP
    best: tuple[float, float] = (math.inf, 0.0)
    signs = sorted((1.0, -1.0), key=lambda k: -k * float(n @ ((start + end) / 2 - ctx.centroid())))
    for reach in (1.0, 1.5, 2.0, 3.0):      # farther out when a line beside it (a block's edge) is in the way
        for sign in signs:
            shift = sign * reach * away
            off = n * ctx.pt(side + shift)
            left, _ = _under(start + off, end + off, lines, ctx.view, ctx.per_point)
            if reach == 1.0 and left < best[0] - 1e-9 * ctx.size:
                best = (left, shift)
            if left <= ctx.pt(HEAD) and (reach == 1.0 or not _jumps(start, end, n * ctx.pt(shift), lines, ctx)):
                return shift
    return best[1]           # no side clear: the side it shares least with


def _jumps(start: np.ndarray, end: np.ndarray, off: np.ndarray, lines: list, ctx: Context) -> bool:
    """Whether setting the arrow start→end `off` sideways takes it across a line parallel to
    it (a guide's edge, a wall): beyond it, it would lie in the ground or on another body. A
    block it starts in is left behind, not jumped (C5-1.5's v_K, set beside its strand and
    its block's edge, clear of both)."""
    length = float(np.linalg.norm(off))
    if length <= 0:
        return False
    d, n = unit(end - start), off / length
    for pts, width in lines:
        if np.allclose(pts[0], pts[-1]) and len(pts) > 3 and Path(pts).contains_point((float(start[0]), float(start[1]))):
            continue         # a block the arrow starts in (its point's slider): it leaves it anyway
        for a, b in itertools.pairwise(pts):
            if np.linalg.norm(b - a) <= 0 or abs(float(unit(b - a) @ d)) < math.cos(math.radians(8)):
                continue
            ta, tb = sorted((float((a - start) @ d), float((b - start) @ d)))
            if min(tb, float(np.linalg.norm(end - start))) - max(ta, 0.0) <= ctx.pt(HEAD):
                continue
            across = float((0.5 * (a + b) - start) @ n)
            if ctx.pt(width / 2 + WIDTH / 2 + HALO) < across < length:
                return True
    return False
