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

from .helpers import LANGS, rendered, over

NINETEEN = ["seed_001_p_pair_coriolis", "seed_001_r_pairs", "seed_001_rolling_pair",
            "seed_c5_1_1_pulley_on_cable", "seed_c5_1_2_bar_on_inclined_wheels", "seed_c5_1_3_bar_in_sleeve",
            "seed_c5_1_4_epicyclic", "seed_c5_1_5_pulley_block", "seed_c5_1_6_belt", "seed_c5_1_7_semicylinder",
            "seed_c5_1_8_contact_points", "seed_c5_2_1_tricycle", "seed_c5_2_2_articulated", "seed_c5_e1_cavity",
            "seed_c5_e2_gear_change", "seed_c5_e3_wheels_with_rod", "seed_c5_e4_upper_wheel",
            "seed_c5_e5_unequal_wheels", "seed_c5_e6_bicycle"]


def page(name: str, lang: str) -> str:
    return rendered(name, lang, "md", drawings=False)


@over(name=NINETEEN)
def test_english_has_no_guillemets(name):
    assert "«" not in page(name, "en") and "»" not in page(name, "en")


@over(name=NINETEEN, lang=["es", "ca"])
def test_no_comma_before_entre(name, lang):
    assert not re.search(r"\), entre ", page(name, lang))


@over(name=NINETEEN)
def test_spanish_rolling_verb(name):
    text = page(name, "es").replace("*", "")
    # twentieth round (b): a wheel too "rueda sin deslizar" (round 15a's "gira" reversed)
    sentences = re.findall(r"(?:^|\. )(?:El|La|Los|Las) ([^.:,]*?) (gira|giran|rueda|ruedan) sin deslizar", text, re.M)
    for subject, verb in sentences:
        assert verb in ("rueda", "ruedan"), (subject, verb)


def test_a_gear_meshes():
    """C5-E.2's planets mesh with the fixed central wheel: never "rolls without slipping on" it.
    Since the seventeenth round (a) the step refers to the centre the CIR section placed at the
    contact of the pitch circles, so the gear's own sentence ("engrana con") is said where a
    gear contact is not a centre; here the page says the pitch circles."""
    es = page("seed_c5_e2_gear_change", "es").replace("*", "")
    assert "sin deslizar sobre la rueda central fija" not in es
    assert "I_{satélite superior}: el contacto J de las circunferencias primitivas" in es
    en = page("seed_c5_e2_gear_change", "en")
    assert not re.search(r"rolls?( without slipping)? on the \*?fixed", en)
    assert "I_{upper planet}: the contact J of the pitch circles" in en


@over(name=["seed_c5_1_4_epicyclic", "seed_c5_e2_gear_change"])
def test_willis_says_train(name):
    es, ca = page(name, "es"), page(name, "ca")
    if "Willis" in es:
        assert "el tren es ordinario" in es and "transmisión es ordinaria" not in es
        assert "el tren és ordinari" in ca and "transmissió és ordinària" not in ca


@pytest.mark.parametrize("lang", LANGS)
def test_every_language_renders_the_gear_page(lang):
    assert "Willis" in page("seed_c5_e2_gear_change", lang)
