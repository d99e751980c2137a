"""An explanation prints on A4 (2 cm margins: a text 482 pt wide) with figure labels of at
least 9 pt: the polygons' labels at their size, the drawings set at their own width (no
wider than the text) with their 9 pt labels."""
from __future__ import annotations

import re

import pytest

from kinematika.explain import render

from .helpers import explained

TEXT_WIDTH_PT = (210 - 2 * 20) / 25.4 * 72          # A4 less two 2 cm margins
PX = 0.75                                            # pt per CSS pixel


@pytest.fixture(scope="module")
def pages():
    out = {}
    for name in ("seed_c5_1_4_epicyclic", "quick_return"):
        _, doc = explained(name)
        out[name] = render(doc, "ca", "html")
    return out


def test_polygon_labels_print_at_9_pt(pages):
    for name, page in pages.items():
        svgs = re.findall(r'<svg xmlns="http://www.w3.org/2000/svg" width="([\d.]+)" height="[\d.]+" '
                          r'viewBox="[^"]+" font-family="[^"]+" font-size="([\d.]+)"', page)
        assert svgs, name
        for width, font in svgs:
            scale = min(1.0, TEXT_WIDTH_PT / (float(width) * PX))
            assert float(font) * PX * scale >= 9, (name, width, font)


def test_drawings_print_at_their_size_with_9_pt_labels(pages):
    css = re.search(r"figure\.drawing svg\{width:([\d.]+)pt", next(iter(pages.values())))
    assert css and float(css.group(1)) <= TEXT_WIDTH_PT
    for name, page in pages.items():
        for drawing in re.findall(r'<figure class="drawing">(.*?)</figure>', page, re.S):
            box = re.search(r'viewBox="0 0 ([\d.]+) ', drawing)
            assert box and float(box.group(1)) == pytest.approx(float(css.group(1)), abs=0.5), name
            # matplotlib writes a label's glyphs scaled by its font size / 100
            sizes = [100 * float(s) for s in re.findall(r"scale\(([\d.]+) -[\d.]+\)", drawing)]
            assert sizes and min(sizes) >= 9, (name, min(sizes or [0]))
