"""Labels read and the drawing fits, on one example of each kind (every example in a deep
run) and on random linkages drawn with
every instant centre and every acceleration (the most crowded figure a model gives): no
label covers another by more than a fifth of the smaller (text extents as matplotlib
measures them), no leader line runs through a label, nothing lies outside the figure.
Also the placement step itself: measuring each text once, and keeping clear of lines."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from kinematika.draw import DrawOptions, draw
from kinematika.draw.labels import LabelBoard, text_extent
from kinematika.errors import KinematikaError

from properties.mechanisms import linkages
from tests.conftest import DEEP, KINDS, sampled
from .artists import label_faults, outside_faults

pytestmark = pytest.mark.early      # minutes of work: handed to a worker before the shorter files (tests/conftest.py)

EXAMPLES = sorted((Path(__file__).parents[2] / "examples").glob("*.yaml"))
CROWDED = DrawOptions(centres=True, accelerations=True)
# a crowded figure takes a second or more to lay out: two random ones by default (the
# examples above already draw one of each kind at its own proportions)
DRAWN = 12 if DEEP else 2


@pytest.mark.parametrize("path", sampled(EXAMPLES, KINDS), ids=lambda p: p.stem)
def test_every_example_reads(path):
    fig = draw(path, options=CROWDED)
    assert label_faults(fig) == []
    assert outside_faults(fig) == []


@settings(max_examples=DRAWN)
@given(linkages)
def test_random_linkages_read(m):
    fig = draw(m.tree, options=CROWDED)
    assert label_faults(fig) == []
    assert outside_faults(fig) == []


SYMBOLIC = [p for p in EXAMPLES if "draw_at" in p.read_text(encoding="utf-8")]


@settings(max_examples=DRAWN if DEEP else 2)
@given(st.sampled_from(SYMBOLIC), st.data())
def test_symbolic_examples_at_other_sizes_read(path, data):
    """Models of the examples' kinds: each symbolic example drawn at its draw_at values
    scaled by random factors (other proportions of the same mechanism)."""
    import dataclasses

    from kinematika.api import as_model

    model = as_model(path)
    scaled = {name: value * data.draw(st.floats(0.6, 1.6), label=name)
              for name, value in model.draw_at.items()}
    try:
        fig = draw(dataclasses.replace(model, draw_at=scaled), options=CROWDED)
    except KinematikaError:
        assume(False)                     # proportions at which the mechanism cannot be
    assert label_faults(fig) == []
    assert outside_faults(fig) == []


def _axes(width: float = 4.0):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, width))
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 10)
    return ax


def test_labels_at_one_anchor_spread_out_inside_the_axes():
    ax = _axes()
    board = LabelBoard()
    for k in range(8):
        board.add((5, 5), f"label {k}", "k", 1, f"l{k}")
    placed = board.layout(ax)
    frame = ax.get_window_extent()
    for i, p in enumerate(placed):
        x0, y0, x1, y1 = p.box
        assert frame.x0 <= x0 and x1 <= frame.x1 and frame.y0 <= y0 and y1 <= frame.y1
        for q in placed[i + 1:]:
            w = min(x1, q.box[2]) - max(x0, q.box[0])
            h = min(y1, q.box[3]) - max(y0, q.box[1])
            assert w <= 0 or h <= 0, (p.label.text, q.label.text)


def test_a_label_keeps_off_a_drawn_line():
    """A label whose anchor sits on a horizontal bar goes above or below it, not across."""
    ax = _axes()
    board = LabelBoard()
    board.avoid((0, 5), (10, 5), weight=3.0)
    board.add((5, 5), "v = 1", "k", 1, "v")
    (p,) = board.layout(ax)
    y = ax.transData.transform((5, 5))[1]
    assert p.box[1] > y or p.box[3] < y


def test_each_text_is_measured_once():
    text_extent.cache_clear()
    opts = DrawOptions(centres=True, accelerations=True)
    draw(EXAMPLES[0].parent / "four_bar.yaml", options=opts)
    first = text_extent.cache_info()
    draw(EXAMPLES[0].parent / "four_bar.yaml", options=opts)
    second = text_extent.cache_info()
    assert first.misses > 10
    assert second.misses == first.misses          # the second figure measured nothing anew


def test_measured_extents_match_the_drawn_text():
    """The cached size (points, at 72 dpi) is what the figure draws at its own dpi."""
    ax = _axes()
    ax.figure.set_dpi(110)
    text = r"$v_{\mathrm{A}{\in}2/3}$ = 0.721"
    t = ax.text(1, 1, text, fontsize=9)
    drawn = t.get_window_extent(ax.figure.canvas.get_renderer())
    w, h = text_extent(text, 9.0)
    assert np.allclose([drawn.width, drawn.height], [w * 110 / 72, h * 110 / 72], rtol=0.04)
