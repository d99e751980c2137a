"""Issue 30, twenty-ninth round (e): an arrow or a label never lies along another line of the
drawing (docs/explain.md, "Twenty-ninth round (e)").

The sixth reading's most repeated figure item: a velocity drawn ALONG another line, so that
the line vanished under the arrow and the arrow's value sat on it — a wheel's horizontal
cross-hair (C5-1.7's v_C, C5-E.4's v_U), a bar or strand (C5-2.2's v_O and v_P on the
chassis, C5-1.5's v_T2 and v_K on their strands), and arrows starting inside a knife edge's
black rectangle (C5-2.2's v_C1, v_C2, v_C4); and values and names set on a wheel's centre
lines ("v_C = rω" on C5-1.7's horizontal diameter). The checks read the drawings as the page
drew them (`helpers.figures`), in display pixels.
"""
from __future__ import annotations

import itertools

import matplotlib
from matplotlib.path import Path
import numpy as np

from .helpers import NOTES_SEEDS, RECORDED_LANGS, figures, over

PX = matplotlib.rcParams["figure.dpi"] / 72.0      # display pixels a point (a figure's own dpi)


def _segments(m) -> list:
    """A drawn line's or polygon's segments (data): a polygon's closed."""
    pts = np.asarray(m.points, float)
    if m.kind == "polygon":
        pts = np.vstack([pts, pts[:1]])
    return list(itertools.pairwise(pts))


def _shared(p, q, a, b, near: float, degrees: float = 8.0) -> float:
    """How long the segment ab lies along pq (display): parallel within `degrees` and within
    `near` of pq's line over the stretch of pq it covers; 0 otherwise. Written here from the
    definition, not taken from the drawing code."""
    d = q - p
    length = float(np.hypot(*d))
    if length == 0 or float(np.hypot(*(b - a))) == 0:
        return 0.0
    d = d / length
    if abs(float(d @ (b - a))) / float(np.hypot(*(b - a))) < np.cos(np.radians(degrees)):
        return 0.0
    n = np.array([-d[1], d[0]])
    ts = sorted([float((a - p) @ d), float((b - p) @ d)])
    lo, hi = max(ts[0], 0.0), min(ts[1], length)
    if hi <= lo:
        return 0.0
    for t in (lo, hi):                         # ab's distance from pq's line at the stretch's ends
        s = (t - float((a - p) @ d)) / (float((b - p) @ d) - float((a - p) @ d) or 1.0)
        x = a + s * (b - a)
        if abs(float((x - p) @ n)) > near:
            return 0.0
    return hi - lo


def _drawn_arrow(m, transform) -> tuple:
    """An arrow's ends on the page (display), set its `shift` points sideways as painted."""
    p, q = transform.transform(np.asarray(m.points[:2], float))
    d = (q - p) / np.hypot(*(q - p))
    side = np.array([-d[1], d[0]]) * (m.shift or 0.0) * PX
    return p + side, q + side


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_no_velocity_runs_along_a_drawn_line(name, lang):
    """No velocity's arrow, as painted (its sideways shift too), shares more than its head's
    length (0.6 of its head's size: 9 points) with a drawn line of another mark — a bar, a
    strand, a belt, a wheel's cross-hair, a ground's edge, a joint's block — near enough that
    their strokes touch (half of each one's width)."""
    bad = []
    for _, marks, _, transform in figures(name, lang):
        lines = [m for m in marks if m.kind in ("line", "polygon") and m.width > 0 and m.colour != "none"]
        for m in marks:
            if m.kind != "arrow" or m.layer != "velocity" or np.allclose(m.points[0], m.points[1]):
                continue
            p, q = _drawn_arrow(m, transform)
            for line in lines:
                near = (line.width + m.width) / 2 * PX
                for a, b in _segments(line):
                    run = _shared(p, q, *transform.transform(np.array([a, b])), near)
                    if run > 0.6 * m.size * PX:
                        bad.append(f"{m.gid} along {line.gid or line.kind} for {run / PX:.0f} pt")
                        break
    assert not bad, sorted(set(bad))


def _cross_hairs(marks: list) -> list:
    """A wheel's centre lines as drawn: thin straight lines of the wheel's colour from or
    through the centre of a drawn circle, no longer than its diameter."""
    circles = [m for m in marks if m.kind == "circle" and m.colour != "none" and m.width > 0]
    out = []
    for m in marks:
        if m.kind != "line" or len(m.points) != 2 or m.width > 1.5:
            continue
        a, b = np.asarray(m.points, float)
        for c in circles:
            centre = np.asarray(c.points[0], float)
            at = min(np.hypot(*(a - centre)), np.hypot(*(b - centre)), np.hypot(*((a + b) / 2 - centre)))
            if m.colour == c.colour and at <= 1e-9 * max(c.r, 1.0) and np.hypot(*(b - a)) <= 2 * c.r:
                out.append((a, b))
                break
    return out


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_no_value_or_name_lies_on_a_wheel_centre_line(name, lang):
    """No vector's value or body's name has a wheel's centre line through the middle of its
    text: the line within a quarter of the box's height of the box's centre, across its
    middle half ("v_C = rω" on C5-1.7's horizontal diameter)."""
    bad = []
    for _, marks, placed, transform in figures(name, lang):
        hairs = [transform.transform(np.array(h)) for h in _cross_hairs(marks)]
        for p in placed:
            if not p.label.gid.startswith(("velocity:", "acceleration:", "body:")):
                continue
            x0, y0, x1, y1 = p.box
            c = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
            w, h = (x1 - x0) / 2, (y1 - y0) / 2
            for a, b in hairs:
                # the middle half of the box, shrunk to a quarter of its height: what the line crosses
                core = (c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)
                if _segment_meets_box(a, b, core):
                    bad.append(p.label.text)
                    break
    assert not bad, bad


def _segment_meets_box(a, b, box) -> bool:
    """Whether the segment ab passes through the box (x0, y0, x1, y1), sampled finely."""
    t = np.linspace(0.0, 1.0, 201)[:, None]
    pts = a + t * (b - a)
    x0, y0, x1, y1 = box
    return bool(((pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)).any())


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_no_arrow_starts_under_a_black_block(name, lang):
    """No velocity starts inside a joint's block filled black (a knife edge's wheel seen from
    above filled with ink hid the first half of C5-2.2's v_C1): a block an arrow starts in is
    filled light enough to see it on."""
    bad = []
    for _, marks, _, _ in figures(name, lang):
        blocks = [m for m in marks if m.kind == "polygon" and str(m.gid).startswith("joint:")
                  and str(m.fill).lower() in ("#212121", "#000000", "black", "k")]
        for m in marks:
            if m.kind != "arrow" or m.layer != "velocity" or np.allclose(m.points[0], m.points[1]):
                continue
            start = np.asarray(m.points[0], float)
            for b in blocks:
                if Path(np.asarray(b.points, float)).contains_point(start):
                    bad.append(f"{m.gid} in {b.gid}")
    assert not bad, bad


def test_a_cross_hair_is_broken_where_an_arrow_leaves_the_centre_along_it():
    """`bodies.cross_hair`: a wheel of radius 1 at the origin with an arrow from its centre
    to the right keeps three arms (left, down, up), none reaching right of the centre; with
    no arrow, two whole centre lines 1.6 long."""
    from kinematika.draw.bodies import cross_hair
    from kinematika.draw.geometry import Box

    class Ctx:
        view = Box(-5.0, -5.0, 5.0, 5.0)
        arrows: list = []

    ctx = Ctx()
    whole = cross_hair(ctx, np.zeros(2), 1.0)
    assert sorted(round(float(np.hypot(*(b - a))), 9) for a, b in whole) == [1.6, 1.6]
    ctx.arrows = [(np.zeros(2), np.array([1.2, 0.0]))]
    arms = cross_hair(ctx, np.zeros(2), 1.0)
    assert max(float(max(a[0], b[0])) for a, b in arms) <= 1e-12
    assert sorted(round(float(np.hypot(*(b - a))), 9) for a, b in arms) == [0.8, 1.6]
