"""Issue 30, eighteenth round (b): words the strict readers marked on main's pages.

- English quotes a section's title in its own marks (“Instant centres”), never guillemets.
- Spanish and Catalan name a joint or contact with no comma before "entre".
- Spanish: a body "rueda sin deslizar" (the textbook's verb; a wheel too since the twentieth
  round (b), which reversed round 15a's "gira"); a gear pair is not rolling: it "engrana con" its mate, in every
  language; Willis' check calls it a train ("el tren es ordinario", "el tren és ordinari").
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, NOTES_SEEDS, over, plain_page

NINETEEN = NOTES_SEEDS      # the notes' nineteen worked examples




@over(name=NINETEEN)
def test_english_has_no_guillemets(name):
    assert "«" not in plain_page(name, "en") and "»" not in plain_page(name, "en")


@over(name=NINETEEN, lang=["es", "ca"])
def test_no_comma_before_entre(name, lang):
    assert not re.search(r"\), entre ", plain_page(name, lang))


@over(name=NINETEEN)
def test_spanish_rolling_verb(name):
    text = plain_page(name, "es").replace("*", "")
    # twentieth round (b): a wheel too "rueda sin deslizar" (round 15a's "gira" reversed)
    sentences = re.findall(r"(?:^|\. )(?:El|La|Los|Las) ([^.:,]*?) (gira|giran|rueda|ruedan) sin deslizar", text, re.M)
    for subject, verb in sentences:
        assert verb in ("rueda", "ruedan"), (subject, verb)


def test_a_gear_meshes():
    """C5-E.2's planets mesh with the fixed central wheel: never "rolls without slipping on" it.
    Since the seventeenth round (a) the step refers to the centre the CIR section placed at the
    contact of the pitch circles, so the gear's own sentence ("engrana con") is said where a
    gear contact is not a centre; here the page says the pitch circles."""
    es = plain_page("seed_c5_e2_gear_change", "es").replace("*", "")
    assert "sin deslizar sobre la rueda central fija" not in es
    assert "I_{satélite1}: el contacto J de las circunferencias primitivas" in es
    en = plain_page("seed_c5_e2_gear_change", "en")
    assert not re.search(r"rolls?( without slipping)? on the \*?fixed", en)
    assert "I_{planet1}: the contact J of the pitch circles" in en


@over(name=["seed_c5_1_4_epicyclic", "seed_c5_e2_gear_change"])
def test_willis_says_train(name):
    es, ca = plain_page(name, "es"), plain_page(name, "ca")
    if "Willis" in es:
        assert "el tren es ordinario" in es and "transmisión es ordinaria" not in es
        assert "el tren és ordinari" in ca and "transmissió és ordinària" not in ca


@pytest.mark.parametrize("lang", LANGS)
def test_every_language_renders_the_gear_page(lang):
    assert "Willis" in plain_page("seed_c5_e2_gear_change", lang)
