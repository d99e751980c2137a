"""Issue 30, twenty-ninth round (f): the polygons' crowded corners.

The sixth reading (all four readers) could not follow the polygons where short terms meet the
pole or an image: 001's rolling pair (a_AB^n, a_FB^n, o and a_Cor,A piled at o), r_pairs (at e,
a_BE^n and three arrowheads; a_BA^t touching arrowheads at b), C5-1.3 (a_S, a_EQ^t touching at
o), C5-1.7 ("o" on a_C^t's head), C5-E.5 ("o" on "a, b, c"). Read on the layouts recorded while
the notes' pages were written (en, ca):

- no two labels' boxes overlap, and none covers an arrow's shaft or its head (the marker
  `render.svg` draws: 7 line widths long and wide, at the tip), its own arrow's included;
- a polygon whose shortest term would be drawn shorter than `render.svg.SHORT` is drawn larger,
  as tall as `render.svg.TALL` allows.
"""
from __future__ import annotations

import math

import numpy as np

from kinematika.explain.document import Arrow, Sym
from kinematika.explain.render import svg
from .helpers import NOTES_SEEDS, over, recorded_pages

MARKER = 7.0        # the SVG marker's size in line widths (markerWidth = markerHeight = 7, orient auto)


def _head(p: tuple, q: tuple, width: float) -> np.ndarray:
    """Points filling arrow pq's head (figure units): a triangle `MARKER` line widths long
    back from the tip q, as wide, sampled on a grid."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    u = q - p
    n = np.linalg.norm(u)
    if n == 0:
        return np.empty((0, 2))
    u /= n
    v = np.array([-u[1], u[0]])
    long = MARKER * width
    out = []
    for s in np.linspace(0, 1, 15):             # from the tip back
        half = 0.5 * long * s
        for t in np.linspace(-1, 1, 9):
            out.append(q - s * long * u + t * half * v)
    return np.array(out)


def _inside(box, pts: np.ndarray) -> bool:
    return bool(np.any((pts[:, 0] > box[0]) & (pts[:, 0] < box[2]) & (pts[:, 1] > box[1]) & (pts[:, 1] < box[3])))


def _shaft(p, q) -> np.ndarray:
    p, q = np.asarray(p, float), np.asarray(q, float)
    n = max(2, int(np.linalg.norm(q - p) / 0.25) + 1)
    return p + np.linspace(0, 1, n)[:, None] * (q - p)


def _overlap(a, b) -> bool:
    return min(a[2], b[2]) > max(a[0], b[0]) and min(a[3], b[3]) > max(a[1], b[1])


@over(name=NOTES_SEEDS)
def test_a_polygon_label_overlaps_no_label_shaft_or_head(name):
    """In every polygon of the notes' pages (en, ca) no two labels' boxes overlap, and no
    label's box covers an arrow's shaft or its head (001's a_BA^t on the heads at b, C5-1.7's
    "o" on a_C^t's head, a_PC^t on its own head at p)."""
    pages = recorded_pages("polygons")
    for lang in ("en", "ca"):
        for lay, _, placed in pages[(name, lang)]:
            for i, a in enumerate(placed):
                for b in placed[i + 1:]:
                    assert not _overlap(a.box, b.box), (lang, a.text.markup, b.text.markup)
            for arrow in lay.fig.arrows:
                p, q = lay.at(arrow.start), lay.at(arrow.end)
                width = 2.2 if arrow.style == "result" else 1.8
                for spot in placed:
                    assert not _inside(spot.box, _shaft(p, q)), (lang, spot.text.markup, "shaft", arrow.label)
                    assert not _inside(spot.box, _head(p, q, width)), (lang, spot.text.markup, "head", arrow.label)


def _term(length: float) -> Arrow:
    """A labelled term `length` long, upwards."""
    return Arrow((0.0, 0.0), (0.0, length), Sym("a", "X"))


def test_a_polygon_with_a_short_term_is_drawn_larger():
    """A polygon 1 × 10 units (a tall one) with a term 0.25 long: at 420 points high its
    scale is (420 - 60) / 10 = 36 points a unit, the term 9 points; it is drawn at most
    `TALL` high instead, (TALL - 60) / 10 points a unit (the width 460 - 60 = 400 points
    allows 400), and a term 1.0 long as far as it needs: SHORT points. With no short term
    it keeps its 36; a wide polygon (10 × 1) keeps its 40, its width filling the page."""
    plain = svg.points_per_unit(0.0, 0.0, 1.0, 10.0)
    assert math.isclose(plain, (420 - 60) / 10)
    tallest = (svg.TALL - 60) / 10
    assert svg.TALL > 420 and 0.25 * tallest >= svg.MARKER * 1.8        # a 0.25 term is seen at the tallest
    assert math.isclose(svg.points_per_unit(0.0, 0.0, 1.0, 10.0, [_term(5.0), _term(0.25)]), tallest)
    assert math.isclose(svg.points_per_unit(0.0, 0.0, 1.0, 10.0, [_term(1.0)]), svg.SHORT / 1.0)
    assert math.isclose(svg.points_per_unit(0.0, 0.0, 1.0, 10.0, [_term(5.0)]), plain)
    assert math.isclose(svg.points_per_unit(0.0, 0.0, 10.0, 1.0, [_term(0.25)]), 40.0)


def test_a_term_too_short_to_see_does_not_grow_the_polygon():
    """A term that even `TALL` high is shorter than its head (0.01 units: 0.62 points at
    (TALL - 60) / 10 a unit) is named in the caption without its label
    (`polygon.short_arrows`): the polygon is not grown for it, so its scale is the same with
    its label or without (the caption's "too short to be seen" and the drawing agree)."""
    assert math.isclose(svg.points_per_unit(0.0, 0.0, 1.0, 10.0, [_term(5.0), _term(0.01)]), (420 - 60) / 10)
