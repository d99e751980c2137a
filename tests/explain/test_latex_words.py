"""The LaTeX page sets a symbol typed in a model's own words (C5-E.6's "r ω_pinyó = R ω_plat",
its ℜ_P) as the other formats do, from the same rule (`Renderer.typed`): the letter in math,
the subscript an upright word below it, never the text ω\\_pinyó; and it holds no character
pdflatex's utf8 input cannot set (a Greek letter, ⇒, ⁿ typed in a note)."""
from __future__ import annotations

import re

import pytest

from .helpers import SEEDS, rendered

# what pdflatex's utf8 input sets in text (T1): Latin-1 and the typographic quotes and dashes
SETTABLE = re.compile(r"[^\x00-\xff‘’“”–—]")


@pytest.mark.parametrize("lang, typed", [
    ("eu", "pinoia"),       # the statement's "(r ω_pinoia = R ω_platera)" is gone (29 b): no typed ω\_ left
    ("ca", "pinyó"),
])
def test_a_symbol_in_a_models_words_is_set_as_a_symbol(lang, typed):
    """C5-E.6's remark, by hand: ω with its body's word upright below, in math; its ℜ_P
    too; and R_roda the same in the formulas as in the words (R_{\\mathrm{roda}})."""
    page = rendered("seed_c5_e6_bicycle", lang, "tex", drawings=False)
    assert rf"\omega\_{typed}" not in page and f"ω_{typed}" not in page
    # the remark writes the page's v_P since the twenty-fourth round (e) (was the notes' v(P))
    normal = "N" if lang == "eu" else "n"        # the Basque slides' a^N (twenty-seventh round (g))
    # and the page's a_P^n since the twenty-ninth round (a)
    assert rf"$\Re_{{\mathrm{{P}}}}$ = $v_{{\mathrm{{P}}}}$$^2$/$a_{{\mathrm{{P}}}}^{{\mathrm{{{normal}}}}}$" in page
    w = {"eu": "gurpila", "ca": "roda"}[lang]         # the model's R_roda per language
    assert "R_{" + w + "}" not in page and r"R_{\mathrm{" + w + "}}" in page


@pytest.mark.parametrize("lang", ["eu", "ca"])
@pytest.mark.parametrize("name", SEEDS)
def test_no_typed_underscore_and_nothing_pdflatex_cannot_set(name, lang):
    """No underscore escaped as text (a symbol left as typed, ω\\_besoa) and no character
    the article's utf8 input has no definition for."""
    page = rendered(name, lang, "tex", drawings=False)
    assert "\\_" not in page, (name, lang, page[page.find("\\_") - 60:page.find("\\_") + 20])
    assert not SETTABLE.findall(page), (name, lang, sorted(set(SETTABLE.findall(page))))
