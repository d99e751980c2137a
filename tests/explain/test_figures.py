"""The explanation's own figures (velocity and acceleration polygons) are legible: no label
over another by more than a fifth of the smaller one, none outside the figure, measured on
the laid-out boxes (matplotlib's text extents, as the figures' tests measure them) — on one
example of each kind and two of the notes' largest seeds (every example in a deep run)."""
from __future__ import annotations

import pytest

from kinematika.explain.catalogue import catalogue
from kinematika.explain.document import Figure
from kinematika.explain.render.html import HtmlRenderer
from kinematika.explain.render.svg import WIDTH, layout

from tests.conftest import KINDS, sampled

from .helpers import ALL, explained


def figures(doc) -> list[Figure]:
    out = [b for b in doc.blocks() if isinstance(b, Figure)]
    return out + [e.polygon for e in doc.equations() if e.polygon is not None]


def overlap(a, b) -> float:
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return max(w, 0) * max(h, 0)


# the upper wheel and the pulley block: the two seeds whose explanations took longest here
@pytest.mark.parametrize("name", sampled(ALL, KINDS | {"seed_c5_e4_upper_wheel", "seed_c5_1_5_pulley_block"}))
def test_polygon_labels_clear_of_each_other(name):
    sol, doc = explained(name)
    renderer = HtmlRenderer(doc, catalogue("en"))
    for fig in figures(doc):
        lay = layout(fig, renderer.svg_label)
        boxes = [lb.box for lb in lay.labels]
        for i, a in enumerate(boxes):
            assert a[0] >= -1 and a[2] <= WIDTH + 1 and a[1] >= -1 and a[3] <= lay.height + 1, \
                (name, lay.labels[i].text.markup, a)
            for j in range(i):
                b = boxes[j]
                smaller = min((a[2] - a[0]) * (a[3] - a[1]), (b[2] - b[0]) * (b[3] - b[1]))
                assert overlap(a, b) <= smaller / 5, (name, lay.labels[i].text.markup, lay.labels[j].text.markup)


def test_a_crowded_pole_is_untangled():
    """Eight terms ending near the pole with their images (the triad's Assur-point polygon
    had its labels piled there): every label placed apart, inside the figure."""
    import math

    from kinematika.explain.document import Arrow, Sym, msg

    fig = Figure(msg("fig.level_v"), unit="speed")
    fig.arrows.append(Arrow((0.0, 0.0), (10.0, 0.0), Sym("v", "C"), "result"))
    for k in range(8):
        t = 2 * math.pi * k / 8
        end = (0.6 * math.cos(t), 0.6 * math.sin(t))
        fig.arrows.append(Arrow((0.0, 0.0), end, Sym("v", f"P{k}O"), "known"))
        fig.points.append((f"p{k}", end, "image"))
    fig.points.append(("o", (0.0, 0.0), "pole"))
    _, doc = explained("four_bar")
    lay = layout(fig, HtmlRenderer(doc, catalogue("en")).svg_label)
    boxes = [lb.box for lb in lay.labels]
    assert len(boxes) == 18
    worst = max(overlap(a, b) / min((a[2] - a[0]) * (a[3] - a[1]), (b[2] - b[0]) * (b[3] - b[1]))
                for i, a in enumerate(boxes) for b in boxes[:i])
    assert worst <= 0.2
    naive = [(lb.centre[0] - 1, lb.centre[1] - 1, lb.centre[0] + 1, lb.centre[1] + 1) for lb in lay.labels]
    assert len(set(naive)) == len(naive)


def _images(doc, key: str) -> dict:
    figs = [b for b in doc.blocks() if isinstance(b, Figure) and b.caption.key == key]
    return {name: xy for f in figs for name, xy, style in f.points if style == "image"}


def test_polygon_letters_sit_on_the_images_they_name():
    """P pair (seed 001 §4.3): the block's own B (written B∈N, the point it shares with
    the rocker, twenty-first round (e)) and the guide's point under it, B∈M (the drag velocity), each lettered at
    its own tip; the quick-return's slot point A∈rocker has its letter."""
    from kinematika.model.model import PointRef

    sol, doc = explained("seed_001_p_pair_coriolis")
    images = _images(doc, "fig.level_v")
    v_b = tuple(sol.inst.numvec(sol.velocity(PointRef("B", "N"))))
    v_guide = tuple(sol.inst.numvec(sol.velocity(PointRef("B", "M"))))
    assert images["b∈N"] == pytest.approx(tuple(v_b))
    assert images["b∈M"] == pytest.approx(tuple(v_guide))
    sol, doc = explained("quick_return")
    images = _images(doc, "fig.level_v")
    assert images["a∈rocker"] == pytest.approx(tuple(sol.inst.numvec(sol.velocity(PointRef("A", "rocker")))))
