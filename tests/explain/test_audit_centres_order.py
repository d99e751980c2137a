"""The teacher's audit of the seeds: a centre found from one velocity is placed as the notes
place it (on the perpendicular to v_Q through Q, at |v_Q| / |ω|), never by an undefined k or
a vector divided by a scalar; and Catalan/Spanish repeat the contracted preposition before
each body a step is found from ("a partir del pla esquerre i del pla dret")."""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered

# tests/explain is one unit of work (its pages are drawn once in one worker, tests/conftest.py's
# ONE_WORKER) and the longest of the run: handed out first among the long units, so that no
# other file waits in its worker before it
pytestmark = pytest.mark.early

# the sentence that places a centre from one velocity, per language
PERPENDICULAR = {"en": "on the perpendicular to", "es": "en la perpendicular a", "ca": "a la perpendicular a",
                 "eu": "perpendikularrean"}


def _text(name: str, lang: str) -> str:
    return rendered(name, lang)


def _centre_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if re.match(r"(Check|Comprobación|Comprovació|Egiaztapena|I_)", line)]


@pytest.mark.parametrize("lang", LANGS)
def test_a_centre_from_one_velocity_is_placed_by_its_distance_not_by_k(lang):
    """C5-1.6's I_13, E.5, E.6: "AI_13 = |v_A| / |ω| = …", never "k × v_A / ω" (2.1 and
    2.2 place their chassis' centres in the velocity step and do not check them again; 1.5's
    third pulley goes by the notes' midpoint: `test_the_belt_pulley_centre_is_at_r_over_2_from_c3`)."""
    placed = set()
    for name in SEEDS:
        for line in _centre_lines(_text(name, lang)):
            assert "k ×" not in line, (name, line)
            assert not re.search(r"× v_\S+ / ω", line), (name, line)
            if "|v_" in line and PERPENDICULAR[lang] in line:
                placed.add(name)
    assert {"seed_c5_1_6_belt", "seed_c5_e5_unequal_wheels", "seed_c5_e6_bicycle"} <= placed


def test_the_belt_pulley_centre_is_at_r_over_2_from_c3():
    """C5-1.5: T4 rises at 2v and C3 falls at 2v, so the centre is midway between them, as the
    notes say ("el CIR d'aquesta politja estarà en el punt mig"): C3I = r/2 (the pulley turns
    at ω = −4v/r, and 2v / (4v/r) = r/2 too), by the construction, not by |v_C3| / |ω|."""
    text = _text("seed_c5_1_5_pulley_block", "en")
    assert "at r/2 from C3" in text and "lies between them" in text     # eleventh round: the distance plainly
    assert "|v_C3| / |ω_pulley3|" not in text


@pytest.mark.parametrize("lang,wrong", [("ca", r"a partir .*\* i (?:el|la|l’|els|les) ?\*"),
                                        ("es", r"a partir .*\* y (?:el|la|los|las) \*")])
def test_each_body_a_step_starts_from_takes_the_preposition(lang, wrong):
    """"a partir del *pla esquerre* i del *pla dret*", not "… i el *pla dret*"."""
    lists = 0
    for name in SEEDS:
        for line in _text(name, lang).splitlines():
            if re.match(r"\d+\. ", line) and "a partir" in line:
                assert not re.search(wrong, line), (name, line)
                lists += " i d" in line or " y d" in line
    assert lists >= 3


def test_an_order_item_begins_with_a_capital():
    """C5-1.2 in Catalan: "1. La *barra OQ*, la *roda esquerra* i la *roda dreta*, a partir del
    *pla esquerre* i del *pla dret*." (the wheels found in the bar's step since round 27b, each
    by its vector equation about its contact)."""
    text = _text("seed_c5_1_2_bar_on_inclined_wheels", "ca")
    assert "1. La *barra OQ*, la *roda esquerra* i la *roda dreta*, a partir del *pla esquerre* i del *pla dret*." in text
    items = [line for line in text.splitlines() if re.match(r"\d+\. ", line) and "a partir" in line]
    assert items and all(line.split(". ", 1)[1][0].isupper() for line in items)
