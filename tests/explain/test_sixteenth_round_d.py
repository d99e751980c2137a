"""Issue 30, sixteenth round (d): the figures of the explanations.

- A fixed guide through a wheel (001's slider carrying the roller on its axle): now a slot, see
  test_eighteenth_round_d.py.
- No two labels of a figure come within `GAP` of each other, and none covers an arrow's tip:
  every label layout of every seed's figures (the mechanism's, the polygons') is recorded
  while the page is written, and its boxes (display units) are checked pairwise here.
"""
from __future__ import annotations

import pytest

from tests.explain.helpers import NOTES_SEEDS, recorded_pages, over



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
                inside = [(x, y) for x, y in tips if x0 - 5 * px < x < x1 + 5 * px and y0 - 5 * px < y < y1 + 5 * px]
                assert not inside, (lang, p.label.text, inside)
