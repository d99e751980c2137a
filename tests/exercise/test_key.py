"""The answer key as a teacher prints and searches it: contents first, the parts of the
worked solution every variant shares printed once, figures that print as vector drawings
without transparency or patterns (no images in the PDF), ids unique in the page, each glyph
defined once."""
from __future__ import annotations

import re

import pytest

from kinematika.exercise.sheets import key_html
from kinematika.exercise.solutions import printable, solution_html

from .conftest import P_PAIR, P_PAIR_VARY, make


@pytest.fixture(scope="module")
def key():
    ex = make(P_PAIR, P_PAIR_VARY, 3, 5, "ca")
    solutions = {v.number: solution_html(ex, v, "ca") for v in ex.variants}
    return ex, solutions, key_html(ex, {v.number: b"" for v in ex.variants}, solutions)


def test_the_parts_every_variant_shares_are_printed_once(key):
    ex, solutions, page = key
    assert page.count('id="common"') == 1
    common = page.split('id="common"')[1].split("</section>")[0]
    shared_headings = re.findall(r"<h2[^>]*>(.*?)</h2>", common)
    assert shared_headings                                # the structure, at least, is the same
    for v in ex.variants:
        own = page.split(f'id="variant-{v.number}"')[1].split("</section>")[0]
        for heading in shared_headings:                   # not repeated in a variant's pages
            assert f">{heading}</h2>" not in own
        assert re.findall(r"<h2[^>]*>(.*?)</h2>", solutions[v.number])   # the variant's own are there


def test_the_key_prints_without_transparency_or_patterns_and_its_ids_are_unique(key):
    _, _, page = key
    assert "opacity" not in page and "<pattern" not in page and "url(#" not in page.replace("url(#v", "")
    ids = re.findall(r'\bid="([^"]+)"', page)
    assert len(ids) == len(set(ids))
    glyphs = re.findall(r'<path id="[^"]+"((?: [a-z-]+="[^"]*")*)\s*/>', page)
    assert glyphs and len(glyphs) == len(set(glyphs))     # each glyph (shape and style) defined once
    used = set(re.findall(r'href="#([^"]+)"', page))
    assert used <= set(ids) | {f"variant-{n}" for n in range(1, 4)}


def test_printable_folds_opacity_into_the_colour_on_white():
    out = printable('<line stroke="#000000" opacity="0.5"/><path style="fill: #ff0000; fill-opacity: 0.25"/>'
                    '<path style="fill: url(#v001-d1-h4)"/><pattern id="v001-d1-h4"></pattern>')
    # 255 − α (255 − c): black at ½ is #808080 (127.5 rounds to even, 128); red at ¼ is #ffbfbf
    assert out == ('<line stroke="#808080"/><path style="fill: #ffbfbf"/><path style="fill: #d5d5d5"/>')
