"""The figure fits and reads: every artist inside the axes, labels clear of each other,
the mechanism not shrunk by far-off results."""
from __future__ import annotations

from itertools import combinations

import numpy as np
import pytest

from kinematika.draw import draw

from .artists import label_boxes, overlap
from .mechanisms import four_bar_tree

CROWDED = [{"velocity": "A"}, {"velocity": "B"}, {"velocity": "P"}, {"acceleration": "A"},
           {"acceleration": "B"}, {"acceleration": "P"}, {"curvature": "P"},
           {"velocity": "B@coupler", "relative_to": "crank"}]


@pytest.fixture(scope="module")
def crowded():
    return draw(four_bar_tree(CROWDED), centres=True)


def test_every_artist_lies_inside_the_axes(crowded):
    fig = crowded
    renderer = fig.canvas.get_renderer()
    ax = fig.axes[0]
    box = ax.get_window_extent(renderer)
    for artist in ax.lines + ax.patches:
        ext = artist.get_window_extent(renderer)
        if ext.width == 0 and ext.height == 0 or not np.isfinite(ext.x0):
            continue
        assert ext.x0 >= box.x0 - 1 and ext.x1 <= box.x1 + 1, artist.get_gid()
        assert ext.y0 >= box.y0 - 1 and ext.y1 <= box.y1 + 1, artist.get_gid()
    for text, ext in label_boxes(fig):
        assert box.x0 - 1 <= ext.x0 and ext.x1 <= box.x1 + 1, text
        assert box.y0 - 1 <= ext.y0 and ext.y1 <= box.y1 + 1, text
    page = fig.bbox
    for text in fig.texts:                     # title and notes stay on the page
        ext = text.get_window_extent(renderer)
        assert page.x0 <= ext.x0 and ext.x1 <= page.x1 and page.y0 <= ext.y0 and ext.y1 <= page.y1


def test_labels_do_not_overlap(crowded):
    boxes = [(t, b) for t, b in label_boxes(crowded) if t]
    assert len(boxes) >= 20
    for (t1, b1), (t2, b2) in combinations(boxes, 2):
        smaller = min(b1.width * b1.height, b2.width * b2.height)
        assert overlap(b1, b2) <= 0.05 * smaller, (t1, t2)


def test_far_results_do_not_shrink_the_mechanism():
    """The example-style four-bar has its coupler centre 23 units up; the drawing stays 4 wide."""
    tree = four_bar_tree([{"icr": "coupler"}, {"velocity": "B"}])
    tree["points"]["B"] = [3.0, 1.0]
    tree["points"]["O4"] = [2.0, 0.02]
    tree["points"]["P"] = [2.0, 1.5]
    fig = draw(tree)
    ax = fig.axes[0]
    width = ax.get_xlim()[1] - ax.get_xlim()[0]
    height = ax.get_ylim()[1] - ax.get_ylim()[0]
    assert max(width, height) < 3 * 3.0       # the mechanism is 3 wide
