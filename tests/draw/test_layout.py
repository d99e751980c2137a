"""The figure fits and reads: every artist inside the axes, labels clear of each other,
the mechanism not shrunk by far-off results."""
from __future__ import annotations

import pytest

from kinematika.draw import draw

from .artists import label_boxes, label_faults, outside_faults
from .mechanisms import four_bar_tree

CROWDED = [{"velocity": "A"}, {"velocity": "B"}, {"velocity": "P"}, {"acceleration": "A"},
           {"acceleration": "B"}, {"acceleration": "P"}, {"curvature": "P"},
           {"velocity": "B@coupler", "relative_to": "crank"}]


@pytest.fixture(scope="module")
def crowded():
    return draw(four_bar_tree(CROWDED), centres=True)


def test_every_artist_lies_inside_the_axes(crowded):
    assert outside_faults(crowded) == []


def test_labels_do_not_overlap(crowded):
    # the centres at pins are written into the pins' labels ("I_12 = O2") since issue 30's
    # twenty-ninth round (g): two labels fewer, each name still drawn
    texts = [t for t, _ in label_boxes(crowded) if t]
    assert len(texts) >= 18
    assert len(texts) + sum(" = " in t and t.startswith("$I_") for t in texts) >= 20
    assert label_faults(crowded, share=0.05) == []


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
