"""Issue 30, twenty-fifth round (c): the velocity and acceleration polygons.

- An absolute motion (blue) runs from the pole o to the dot of its image, always: the
  twenty-fourth round moved blue arrows aside, and they ended beside their dots (C5-2.2,
  C5-E.1's o′ a dot no arrow reached), while the caption says each "ends at its image".
  Only terms (black) move aside, and a term moved keeps its ends joined (thin lines) to the
  points it runs between; a term out of the pole or into an image within about 11° of the
  blue arrow there moves aside too (001's a_EO2^n under o→e).
- No label sits in the scale bar's row (C5-1.1's "k∈polea, …" beside "v/5").
"""
from __future__ import annotations

import math

from kinematika.explain.document import Figure
from .helpers import LANGS, NOTES_SEEDS, explained, over, rendered

POLYGONS = ("fig.level", "fig.step", "fig.polygon")


def _polygons(doc) -> list[Figure]:
    return [b for b in doc.blocks() if isinstance(b, Figure) and b.arrows and b.caption.key.startswith(POLYGONS)]


def _size(fig: Figure) -> float:
    return max(abs(c) for a in fig.arrows for p in (a.start, a.end) for c in p)


@over(name=NOTES_SEEDS)
def test_an_absolute_motion_runs_from_the_pole_to_its_image(name):
    """Every blue arrow of a level polygon starts at the pole o and ends on the dot of an
    image (a lettered point of the figure)."""
    _, doc = explained(name)
    for fig in _polygons(doc):
        if not fig.caption.key.startswith("fig.level"):
            continue
        size = _size(fig)
        dots = [p for label, p, kind in fig.points if kind == "image"]
        for a in fig.arrows:
            if a.style != "result":
                continue
            assert math.hypot(*a.start) <= 1e-9 * size, (fig.caption.key, "starts off the pole", a.start)
            assert any(math.dist(a.end, d) <= 1e-9 * size for d in dots), (fig.caption.key, "ends off its image", a.end)


@over(name=NOTES_SEEDS)
def test_a_term_moved_aside_is_joined_to_its_ends(name):
    """Every end of a black arrow of a polygon lies on the figure's construction: the pole, an
    image, an end of another arrow, or the end of a thin line that joins it back there; no
    end of a term moved aside floats free of the points it runs between."""
    _, doc = explained(name)
    for fig in _polygons(doc):
        size = _size(fig)
        for a in fig.arrows:
            if a.style == "result":
                continue
            for end in (a.start, a.end):
                spots = [p for _, p, _ in fig.points] + [p for q in fig.lines for p in q]
                spots += [p for b in fig.arrows if b is not a for p in (b.start, b.end)]
                assert any(math.dist(end, p) <= 1e-9 * size for p in spots), (fig.caption.key, a.label, end)


BAR_ROW = 24        # points from a polygon's bottom: the scale bar's row (its line and its text)


@over(name=NOTES_SEEDS)
def test_no_polygon_label_sits_on_the_scale_bar_row(name):
    """No label of a polygon, in any language, sits in the scale bar's row, where it read as
    the bar's (C5-1.1 in Basque: "k∈polea, k∈eskuineko kable-zatia" beside "v/5")."""
    _, doc = explained(name)
    figs = _polygons(doc)
    for lang in LANGS:
        rendered(name, lang, "md")          # each language's layouts, kept by the figures
    for fig in figs:
        for lay in fig.layouts.values():
            for lb in lay.labels:
                assert lb.box[3] <= lay.height - BAR_ROW, (fig.caption.key, lb.text.raw, lb.box, lay.height)


SIN_ALONG = 0.17    # about 10°: a term out of (into) a blue arrow's end within it reads as drawn over it
APART = 0.05        # of a polygon's size: the least gap between arrows side by side (twenty-fourth round (g))


def _off_line(p, a) -> float:
    ux, uy = a.end[0] - a.start[0], a.end[1] - a.start[1]
    return abs(ux * (p[1] - a.start[1]) - uy * (p[0] - a.start[0])) / math.hypot(ux, uy)


@over(name=NOTES_SEEDS)
def test_no_term_leaves_or_enters_a_blue_arrow_along_it(name):
    """No black arrow of a level polygon runs out of the pole, or into an image, beside the
    blue arrow there (its middle within the blue's extent), within about 10° of it and less
    than `APART` of the polygon's size off it (001's
    a_EO2^n, 4.6° off o→e: the blue drawn over it and the heads piled up at e)."""
    _, doc = explained(name)
    for fig in _polygons(doc):
        if not fig.caption.key.startswith("fig.level"):
            continue
        size = _size(fig)
        blue = [b for b in fig.arrows if b.style == "result"]
        for a in fig.arrows:
            if a.style == "result":
                continue
            for b in blue:
                shared = math.dist(a.start, b.start) <= 1e-9 * size or math.dist(a.end, b.end) <= 1e-9 * size
                ux, uy = a.end[0] - a.start[0], a.end[1] - a.start[1]
                vx, vy = b.end[0] - b.start[0], b.end[1] - b.start[1]
                sin = abs(ux * vy - uy * vx) / (math.hypot(ux, uy) * math.hypot(vx, vy))
                far = max(_off_line(a.start, b), _off_line(a.end, b))
                mx, my = (a.start[0] + a.end[0]) / 2 - b.start[0], (a.start[1] + a.end[1]) / 2 - b.start[1]
                over = 0 < (mx * vx + my * vy) / (vx * vx + vy * vy) < 1        # beside it, not beyond its end
                assert not (shared and over and sin < SIN_ALONG and far < APART * size), (fig.caption.key, a.label, far / size)
