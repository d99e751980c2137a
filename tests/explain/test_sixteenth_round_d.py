"""Issue 30, sixteenth round (d): the figures of the explanations.

- A fixed guide through a wheel (001's slider carrying the roller on its axle): now a slot, see
  test_eighteenth_round_d.py.
- No two labels of a figure come within `GAP` of each other, and none covers an arrow's tip
  (nor comes within 5 px of another arrow's; its own arrow's head may be near, not inside):
  every label layout of every seed's figures (the mechanism's, the polygons') is recorded
  while the page is written, and its boxes (display units) are checked pairwise here.
"""
from __future__ import annotations

import numpy as np
import pytest

from .helpers import NOTES_SEEDS, recorded_pages, over



@pytest.fixture(scope="module")
def layouts():
    """Every label layout (boxes and the arrows' tips, display units) of the seeds' pages in
    English and Catalan (whose words are the longest), recorded as the pages were drawn."""
    return recorded_pages("labels")


@over(name=NOTES_SEEDS)
def test_no_two_labels_touch_and_none_covers_a_tip(layouts, name):
    for lang in ("en", "ca"):
        for placed, tips, px in layouts[(name, lang)]:
            boxes = [p.box for p in placed]
            for i in range(len(boxes)):
                for j in range(i + 1, len(boxes)):
                    a, b = boxes[i], boxes[j]
                    w = min(a[2], b[2]) - max(a[0], b[0])
                    h = min(a[3], b[3]) - max(a[1], b[1])
                    assert not (w > -5 * px and h > -5 * px), \
                        (lang, placed[i].label.text, placed[j].label.text, w, h)
            for p in placed:
                x0, y0, x1, y1 = p.box
                # its own arrow's head (a polygon term's `along` end) may be near, never inside:
                # a label beside its own head reads as that arrow's (C5-E.1's a_C^t, 4 px off
                # its head in a corner the twenty-fourth round (g) filled with side-by-side terms)
                own = p.label.along[1] if p.label.along is not None else (np.nan, np.nan)
                inside = []
                for x, y in tips:
                    m = 0.0 if abs(x - own[0]) + abs(y - own[1]) < 1e-6 else 5 * px
                    if x0 - m < x < x1 + m and y0 - m < y < y1 + m:
                        inside.append((x, y))
                assert not inside, (lang, p.label.text, inside)
