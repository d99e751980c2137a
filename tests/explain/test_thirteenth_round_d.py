"""Issue 30, thirteenth round (d): what an English and Spanish teacher still edited on main's
pages, each a rule checked over the seeds in every language where it applies:

- a reference to an earlier step names the step by its number ("found in Step 1"), never
  "the steps above" / "los pasos anteriores" / "goiko urratsetan";
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered, over

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


@over(name=SEEDS, lang=LANGS)
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
    # the composition writes v_ar,B alone, equated with v_B∈M in the notation line
    # (twenty-fourth round (c))
    drag = [m for line in coriolis.splitlines() if re.match(r"[va]_\{\w+,B\} = \(", line)
            for m in re.findall(ref, line)]
    assert drag == ["1", "1"], drag
    slide = [m for line in coriolis.splitlines() if re.search(r"_\{B∈N \w+\.? M\}", line) and re.search(r"(B too|también B|també B|B puntuak ere)", line)
             for m in re.findall(ref, line)]
    assert slide == ["2", "2"], slide
    normal, tangential = ("N", "T") if lang == "eu" else ("n", "t")      # the slides' a^N (27th round (g))
    terms = [m for line in rolling.splitlines()
             if "= v_B + v_AB =" in line or f"= a_B + a_AB^{normal} + a_AB^{tangential} =" in line
             for m in re.findall(ref, line)]
    assert terms == ["2", "2"], terms


NEITHER = {"en": r"slips on neither the \*[^*]+\* nor the \*[^*]+\*",
           "es": r"no desliza sobre (?:el|la) \*[^*]+\* ni sobre (?:el|la) \*[^*]+\*",
           "ca": r"no llisca (?:ni )?sobre (?:el|la) \*[^*]+\* ni sobre (?:el|la) \*[^*]+\*",
           "eu": r"ez da irristatzen ez \*[^*]+\* [^,;:]*? ez \*[^*]+\*"}


@over(name=SEEDS, lang=LANGS)
def test_a_belt_slips_on_neither_pulley(name, lang):
    """Never "does not slip on X nor on Y"; where a page says a belt or chain keeps to both
    wheels (C5-1.6's belt, C5-E.6's chain), it says it in its language's neither … nor."""
    text = rendered(name, lang, "md", drawings=False)
    assert "nor on" not in text
    if name in ("seed_c5_1_6_belt", "seed_c5_e6_bicycle"):
        assert re.search(NEITHER[lang], text), (name, lang)


APOSTROPHE = {"en": "'", "ca": "’"}
APOSTROPHES = re.compile(r"(?<=\w)['’]")


@over(name=SEEDS, lang=LANGS)
def test_one_apostrophe_a_page(name, lang):
    """A page's apostrophes (a catalogue's and the model's own words) are one character:
    English straight, Catalan typographic; C5-2.2 wrote "wheel’s" and "wheel's"."""
    found = set(APOSTROPHES.findall(rendered(name, lang, "md", drawings=False)))
    assert len(found) <= 1 and found <= {APOSTROPHE.get(lang, "'"), *APOSTROPHE.values()}, (name, lang, found)
    if lang in APOSTROPHE:
        assert found <= {APOSTROPHE[lang]}, (name, lang, found)


@pytest.mark.parametrize("lang", APOSTROPHE)
def test_each_catalogue_writes_one_apostrophe(lang):
    """Outside comments, a catalogue's apostrophes are all its language's one."""
    from pathlib import Path

    import kinematika.explain

    path = Path(kinematika.explain.__file__).parent / "locales" / f"{lang}.ftl"
    lines = [line for line in path.read_text(encoding="utf-8").splitlines() if not line.startswith("#")]
    assert set(APOSTROPHES.findall("\n".join(lines))) == {APOSTROPHE[lang]}


@pytest.mark.parametrize("lang", LANGS)
def test_the_tricycles_units_do_not_match(lang):
    """C5-2.1's note: the notes' √(2L) is a misprint since with √L the units do not match."""
    text = rendered("seed_c5_2_1_tricycle", lang, "md", drawings=False)
    said = {"en": "since with √L the units do not match", "es": "con √L las unidades no cuadran",
            "ca": "amb √L les unitats no quadren", "eu": "√L-rekin unitateak ez baitatoz bat"}
    assert said[lang] in text and "length's unit" not in text


# what a Spanish teacher edited on the HTML pages: old wording -> the teacher's
SPANISH = {"que halla el paso": "permite hallar dos incógnitas",
           "Conocidas las velocidades": "Una vez halladas las velocidades",
           "una fórmula exacta en ellos": "una fórmula exacta en función de ellos"}


@pytest.mark.parametrize("fmt", ["md", "html"])
@pytest.mark.parametrize("name", SEEDS)
def test_the_spanish_teachers_wording(name, fmt):
    """Spanish: an equation lets one find two unknowns (it "solves" none, and no step "finds"
    in the passive's place); "Conocidas … son conocidos" says known twice; a result is a
    formula "en función de" the symbols, never "en ellos" (a calque of "in them")."""
    text = rendered(name, "es", fmt, drawings=False)
    for old in SPANISH:
        assert old not in text, (name, old)
    assert "permite hallar dos incógnitas" in text, name
    if re.search(r"(?:^## |<h2[^>]*>)Aceleraciones\b", text, re.M):
        assert "Una vez halladas las velocidades" in text, name
