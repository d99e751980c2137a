"""Issue 30, twenty-fifth round (b): a scale bar's symbols set as the labels' are.

The four readers saw C5-E.6's acceleration bar print "|a_P|/5", a raw underscore: the bar's
formula was written in plain Unicode, its symbols as a name's plain-text spelling. A bar's
symbols are now set as a label's (`explain.render.svg.name_markup`, `sym_markup`): an
italic letter and a smaller, shifted subscript, in HTML and Markdown (SVG); TikZ writes
them as math.
"""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, over, rendered

BAR = re.compile(r'<text x="[0-9.]+" y="[0-9.]+" fill="#222">(.*?)</text>')
TAG = re.compile(r"<[^>]+>")
SET = re.compile(r'<tspan (font-style="italic"|baseline-shift="(sub|super)" font-size="70%")>[^<]+</tspan>')


@over(name=SEEDS, lang=LANGS)
def test_a_scale_bars_symbols_are_set_as_symbols(name, lang):
    """No bar's text holds an underscore outside its markup (a_P), and each letter of a
    symbolic page's bar formula is set in italics, its subscript as a subscript."""
    for bar in BAR.findall(rendered(name, lang, "html")):
        text = TAG.sub("", bar)
        assert "_" not in text, (text, bar)
        letters = re.findall(r"[A-Za-zα-ωΑ-Ω]", SET.sub("", bar))
        # a numeric page's unit (m/s, m/s²) is a word, not a symbol: its bar holds no tspan
        assert not letters or "<tspan" not in bar, (letters, bar)


def test_the_bicycles_acceleration_bar_sets_a_p_as_a_label():
    """C5-E.6 (every language): the bar reads |a_P|/5 with an italic a and a subscript P,
    as a_P reads beside its arrow; in LaTeX, as math."""
    for lang in LANGS:
        bars = BAR.findall(rendered("seed_c5_e6_bicycle", lang, "html"))
        assert any(re.fullmatch(r'[0-9]*·?\|<tspan font-style="italic">a</tspan>'
                                r'<tspan baseline-shift="sub" font-size="70%">P</tspan>\|(/[0-9]+)?', b)
                   for b in bars), (lang, bars)
    tex = rendered("seed_c5_e6_bicycle", "en", "tex")
    assert r"\left|{a_{P}}\right|" in tex
