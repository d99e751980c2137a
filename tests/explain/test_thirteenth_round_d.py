"""Issue 30, thirteenth round (d): what an English and Spanish teacher still edited on main's
pages, each a rule checked over the seeds in every language where it applies:

- a reference to an earlier step names the step by its number ("found in Step 1"), never
  "the steps above" / "los pasos anteriores" / "goiko urratsetan";
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered

# the old vague references to an earlier step, in the four languages
VAGUE = ("found in the steps above", "in the step above", "relative motion found above",
         "hallado en los pasos anteriores", "en el paso anterior", "movimiento relativo hallado arriba",
         "trobat en els passos anteriors", "al pas anterior", "moviment relatiu trobat més amunt",
         "goiko urratsetan", "goiko urratsean", "guztiek goian aurkitutako")
# a reference by number, as each language writes it
STEP_REF = {"en": r"Step (\d+)", "es": r"(?:el|del) paso (\d+)", "ca": r"(?:al|del) pas (\d+)",
            "eu": r"(\d+)\. urrats(?:ean|eko)"}
STEP_TITLE = {"en": r"^### Step (\d+):", "es": r"^### Paso (\d+):", "ca": r"^### Pas (\d+):",
              "eu": r"^### (\d+)\. urratsa:"}


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_an_earlier_step_is_named_by_its_number(name, lang):
    """No page refers to "the step(s) above"; every step a reference names exists on the page."""
    text = rendered(name, lang, "md", drawings=False)
    for old in VAGUE:
        assert old not in text, (name, lang, old)
    titles = {int(n) for n in re.findall(STEP_TITLE[lang], text, re.M)}
    for n in re.findall(STEP_REF[lang], text.split("\n## ", 3)[-1]):
        assert int(n) in titles, (name, lang, n)


@pytest.mark.parametrize("lang", LANGS)
def test_the_drags_steps_by_hand(lang):
    """By hand from the slides: 4.3's v_B∈M = v_A + v_BA is written in Step 1 (the guide M,
    the input), the block's slide v_B∈N/M in Step 2 (the RRP dyad); 4.4's drag of A,
    v_B + v_AB, is the first terms of the lever's equation, Step 2."""
    coriolis = rendered("seed_001_p_pair_coriolis", lang, "md", drawings=False)
    rolling = rendered("seed_001_rolling_pair", lang, "md", drawings=False)
    ref = STEP_REF[lang]
    drag = [m for line in coriolis.splitlines() if line.startswith(("v_{", "a_{")) and "= v_{B∈M} =" in line
            or "= a_{B∈M} =" in line for m in re.findall(ref, line)]
    assert drag == ["1", "1"], drag
    slide = [m for line in coriolis.splitlines() if "B∈N" in line and line.startswith("B ")
             for m in re.findall(ref, line)]
    assert slide == ["2", "2"], slide
    terms = [m for line in rolling.splitlines() if "= v_B + v_AB =" in line or "= a_B + a_AB^n + a_AB^t =" in line
             for m in re.findall(ref, line)]
    assert terms == ["2", "2"], terms
