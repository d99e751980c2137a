"""Issue 30, twelfth round: what the final audits of this stop (Catalan and Basque; English
and Spanish) still edited, each a rule checked on the pages written before it:

- a step found from no other body is found "from the data", never "from —" (C5-E.4, E.5,
  E.6: the chassis, which translates at the given velocity, came first in the order with an
  empty list of known bodies);
- the legend of shortened subscripts is a sentence ("Notation: ω_wheel is the angular velocity
  of the *fixed central wheel*"), not the terse "In the symbols, ω_wheel: …" every audit
  asked to rewrite;
- Spanish names a joint as a pair ("par de rotación (R), entre …"), English a vehicle's
  centre as the instant centre.
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered, over

ORDER = {"en": "## Order of solution", "es": "## Orden de resolución", "ca": "## Ordre de resolució",
         "eu": "## Ebazpen-ordena"}
DATA = {"en": "from the data.", "es": "a partir de los datos.", "ca": "a partir de les dades.", "eu": "datuetatik."}
LEGEND = {"en": "Notation: ", "es": "Notación: ", "ca": "Notació: ", "eu": "Notazioa: "}
OLD_LEGEND = ("In the symbols", "En los símbolos", "En els símbols", "Ikurretan")


@over(name=SEEDS, lang=LANGS)
def test_no_step_is_found_from_an_empty_list(name, lang):
    """No line of the order of solution ends "from —." (or its translation)."""
    text = rendered(name, lang, "md", drawings=False)
    assert not re.search(r"—\s*(?:solidoetatik|solidotik)?\.$", text, re.M), name
    assert "a partir —" not in text and "from —" not in text


@over(name=["seed_c5_e4_upper_wheel", "seed_c5_e5_unequal_wheels", "seed_c5_e6_bicycle"], lang=LANGS)
def test_the_translating_chassis_is_found_from_the_data(name, lang):
    """By hand from the notes: the chassis (frame) translates at the given velocity v, so it is
    the first body found, and from the data alone."""
    text = rendered(name, lang, "md", drawings=False)
    first = re.search(r"^1\. (.*)$", text.split(ORDER[lang], 1)[1] if ORDER[lang] in text else text, re.M)
    assert first and first.group(1).endswith(DATA[lang]), (name, first and first.group(1))


@over(name=SEEDS, lang=LANGS)
def test_the_subscripts_legend_is_a_sentence(name, lang):
    """The legend, where a page has one, says what each short symbol is in a sentence."""
    text = rendered(name, lang, "md", drawings=False)
    assert not any(line.startswith(OLD_LEGEND) for line in text.splitlines())
    for line in text.splitlines():
        if line.startswith(LEGEND[lang]):
            # ω's shortened subscripts first (or the symbol the model's notation writes a rate
            # with, C5-2.1's ψ̇: round 27b), then what v_{J∈b} is (nineteenth round (c))
            assert line.endswith(".") and re.search(r": (ω_|v_\{\w+∈|ψ̇ )", line), line
            assert not re.search(r"ω_\S+:", line), line


def test_the_sun_wheels_symbol_by_hand():
    """C5-E.2: the fixed central wheel's symbol is ω_central (fourteenth round: among meshing
    wheels "wheel" does not tell it from the planets); one word of its name, it is said once in
    the notation line (sixteenth round (e): both readers found ω_central "never defined")."""
    for lang, legend in (("en", "Notation: ω_central"), ("ca", "Notació: ω_central")):
        text = rendered("seed_c5_e2_gear_change", lang, "md", drawings=False)
        assert "ω_central" in text and text.count(legend) == 1


def test_spanish_joints_are_pairs_and_english_vehicle_centres_instant():
    """001's crank O1A is pinned to the frame at O1: "par de rotación (R)" as the slides say."""
    es = rendered("seed_001_r_pairs", "es", "md", drawings=False)
    assert "| O1 | par de rotación (R) entre el *bastidor* y la *manivela O1A* |" in es
    for name in ("seed_c5_2_1_tricycle", "seed_c5_2_2_articulated"):
        en = rendered(name, "en", "md", drawings=False)
        assert "The centre of the" not in en
        assert "The instant centre of the" in en, name


def test_a_held_pin_said_as_the_bodies_motion():
    """C5-2.1: the steering held at this instant is said of the fork and the chassis, not as a
    pin that "does not turn"."""
    en = rendered("seed_c5_2_1_tricycle", "en", "md", drawings=False)
    assert "At this instant the *front fork* does not turn relative to the *chassis* about the pin F: δ̇ = 0." in en
    assert "The pin F does not turn" not in en


@pytest.mark.parametrize("lang,said", [("en", "The image of the point C is c′"),
                                       ("ca", "La imatge del punt C és c′"),
                                       ("es", "La imagen del punto C es c′")])
def test_a_primed_image_says_what_the_letter_is_not_the_page(lang, said):
    """C5-E.6: c′ beside the wheelbase c was said by what c is; since the fourteenth round
    the wheelbase is e, so C's image is c and no note is needed (the rule that primes an
    image whose letter is a parameter stays: test_no_polygon_image_is_a_symbol_of_the_page)."""
    text = rendered("seed_c5_e6_bicycle", lang, "md", drawings=False)
    assert said not in text
    assert "símbol de la pàgina" not in text and "símbolo de la página" not in text


@pytest.mark.parametrize("lang,slip", [("en", "The notes print φ̇ = v₀/√(2L) · (L − s)/r"),
                                       ("ca", "Els apunts imprimeixen φ̇ = v₀/√(2L) · (L − s)/r")])
def test_the_tricycles_note_quotes_the_notes_as_printed(lang, slip):
    """The notes (002, C5-2.1) print φ̇ = v₀/√(2L)·(L − s)/r, where the root covers 2L: a
    slip (√L is no unit of a length); the page quotes the print and says which is meant."""
    assert slip in rendered("seed_c5_2_1_tricycle", lang, "md", drawings=False)
