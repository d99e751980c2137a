"""Issue 30, fifteenth round (a): what a strict English and Spanish teacher still marked on
main's pages, each a rule checked over the seeds and the four languages where it applies:

1. a centre placed as a point of no body is one symbol throughout: "I_pulley, found above,
   has no velocity: v_{I_pulley} = 0", never "the instant centre I_pulley … is the point I".
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered

# ---- 1. one symbol for a placed centre ----------------------------------------------------

FOUND = {"en": "found above, has no velocity", "es": "hallado arriba, no tiene velocidad",
         "ca": "trobat més amunt, no té velocitat", "eu": "zentroak ez du abiadurarik"}


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_a_placed_centre_is_never_renamed_i(name, lang):
    """The pulley's centre was "I_pulley … is the point I: v_I = 0" (two symbols for one
    point): no point I stands on a page beside a centre's symbol, and the equations start at
    v_{I_body}."""
    page = rendered(name, lang, "md", drawings=False)
    assert not re.search(r"\bv_I\b|\bv_I ", page)
    assert not re.search(r"(point|punto|punt|puntua) I\b", page)


@pytest.mark.parametrize("lang", LANGS)
def test_the_pulleys_centre_is_said_once_by_its_symbol(lang):
    """C5-1.1: the sentence names the centre by its symbol once, and the first equation
    starts there."""
    page = rendered("seed_c5_1_1_pulley_on_cable", lang, "md", drawings=False)
    line = next(ln for ln in page.splitlines() if FOUND[lang] in ln)
    centre = re.search(r"I_(\w+)", line).group(0)
    assert line.endswith(f"v_{{{centre}}} = 0.")
    assert line.count("I_") == 2
    assert f"v_C  =  v_{{{centre}}}  +" in page
