"""A centre placed as a point is written with its body-named symbol, never a number (issue 30,
fourth audit: C5-1.2's "I_OQ ≡ I16 … v_I16 = 0"). Over the 19 seeds in the four languages,
Markdown and HTML, text, tables and the figures' labels: no centre is I and digits (I16,
v_OI16, $I_{16}$ as a point), none is left as the document's token, and a segment to a centre
runs into its other point with the symbol's subscript closed (C5-E.5's arm DI_{roda1}: the
thirteenth round, where it was "D I_roda1")."""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, explained, rendered
from .helpers import words_of as _words

# I and digits as a name, alone or run into a segment or a subscript (I16, OI16, v_I16, I17J)
NUMBERED_CENTRE = re.compile(r"(?<![A-Za-z])I\d+")
# a centre's symbol run into another point's name with its subscript open: DI_roda1, OI_OQ
# (DI_{roda1}, OI_{OQ} is the segment, `test_thirteenth_round_a`)
GLUED = re.compile(r"(?<![\s(|·×/⊥∥{>$,])(?<=[A-Za-z0-9′'])I_(?!\{)")
TOKEN = re.compile("[\ue010\ue011]|\\\\ue01[01]")


@pytest.mark.parametrize("fmt", ["md", "html"])
@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_no_centre_is_written_by_a_number(name, lang, fmt):
    """Every centre the page writes as a point is I (the notes' CIR ≡ I) or its symbol."""
    words = _words(rendered(name, lang, fmt))
    assert not NUMBERED_CENTRE.findall(words), (name, lang, fmt, sorted(set(NUMBERED_CENTRE.findall(words))))
    assert not TOKEN.search(words), (name, lang, fmt)
    glued = [words[max(0, m.start() - 20):m.end() + 10] for m in GLUED.finditer(words)]
    assert not glued, (name, lang, fmt, glued[:3])


@pytest.mark.parametrize("lang", LANGS)
def test_the_two_bars_centres_are_their_symbols(lang):
    """C5-1.2, by hand: the bars OQ and OJ have their centres placed before the velocities,
    two on one page, so each is written as its own symbol, I_OQ and I_OJ (the subscripts the
    model's Basque, Catalan, Spanish and English names give: OQ barra, barra OQ …), in the
    velocity steps: v_{I_{OQ}} = 0 and the segment OI_{OQ}, a velocity to it v_{OI_{OQ}} (one
    style for the centre on the page, its subscript in braces: twenty-seventh round (g), where
    the sixteenth round wrote v_{O,I_OQ} beside I_{OQ}O); never "I_OQ ≡ I_OQ"."""
    text = rendered("seed_c5_1_2_bar_on_inclined_wheels", lang, "md", drawings=False)
    for bar in ("OQ", "OJ"):
        assert f"v_{{I_{{{bar}}}}} = (0" in text, (lang, bar)
        # the direction in the term's own order, O then I (twenty-fourth round (c))
        assert f"v_{{OI_{{{bar}}}}}" in text and f"⊥ OI_{{{bar}}}" in text, (lang, bar)
        assert f"I_{{{bar}}} ≡" not in text and f"I_{bar}" not in text
    html = rendered("seed_c5_1_2_bar_on_inclined_wheels", lang, "html", drawings=False)
    assert '<sub><i>I</i><sub>OQ</sub></sub>' in html          # v with the subscript I_OQ, nested


def test_the_document_holds_one_token_per_centre():
    """The document is one for every language: C5-1.2's two centres are points named by
    their bodies' ids (the token), resolved per language by the renderer."""
    from kinematika.explain.document import CENTRE_POINT_RE

    _, doc = explained("seed_c5_1_2_bar_on_inclined_wheels")
    found = {m.group(1) for eq in doc.equations() for t in [eq.target] + [t for s in eq.sides for t in s]
             for m in CENTRE_POINT_RE.finditer(t.sym.sub)}
    assert found == {"OQ", "OJ"}, found
