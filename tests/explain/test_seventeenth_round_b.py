"""Issue 30, seventeenth round (b): what two teachers read on main (98eae38). Each test is a rule
over the 19 seeds in the four languages and fails on that output: back-references that point
"above" ("the equations above", "with the angular velocities found above", "ecuaciones
anteriores", "equacions anteriors", "aurreko ekuazioen", "velocidades angulares halladas"; the notes' errata "as derived above")
instead of naming the step or the section the reader turns to."""
from __future__ import annotations

import re


from .helpers import SEEDS, rendered, over

LANGS = ("en", "es", "ca", "eu")

# A back-reference by position, as each language writes it (not "above A": a centre's side).
ABOVE = {
    "en": r"\b(found|placed|worked out|obtained|derived) above\b|\bequations above\b",
    "es": r"\b(hallad[oa]s?|obtenid[oa]s?|se \w+) (arriba|antes)\b|\becuaciones anteriores\b",
    "ca": r"\bmés amunt\b|\ba dalt\b|\b(trobad?[eao]s?) abans\b|\bequacions anteriors\b",
    "eu": r"\bgoian\b|\baurreko ekuazio|\blehen aurkitu",
}
# The angular velocities a check compares with, named by their section (no bare "found").
CHECK = {
    "en": r"[Ww]ith the angular velocities found(?! in “Velocities”)",
    "es": r"[Cc]on las velocidades angulares halladas(?! en «Velocidades»)",
    "ca": r"[Aa]mb les velocitats angulars trobades(?! a «Velocitats»)",
    "eu": r"(?<!«Abiadurak» atalean )aurkitutako abiadura angeluarrekin",
}
# A polygon caption's steps, read by hand from each language's wording.
STEPS = {
    "en": r"equations of Steps? (\d+)(?: (?:to|and) (\d+))?",
    "es": r"ecuaciones (?:del paso|de los pasos) (\d+)(?: [ay] (\d+))?",
    "ca": r"equacions (?:del pas|dels passos) (\d+)(?: [ai] (\d+))?",
    "eu": r"(\d+)\.(?:(?:–| eta )(\d+)\.)? urrats(?:eko|etako) ekuazioen",
}
HEADING = {"en": r"### Step (\d+)", "es": r"### Paso (\d+)", "ca": r"### Pas (\d+)", "eu": r"### (\d+)\. urratsa"}


@over(name=SEEDS, lang=LANGS)
def test_no_back_reference_points_above(name: str, lang: str) -> None:
    """No sentence or caption sends the reader "above": it names the step (Step 3) or the
    section («Velocities», «Instant centres») where the quantity was found."""
    page = rendered(name, lang, "md", drawings=False)
    assert not re.search(ABOVE[lang], page), (name, lang, re.search(ABOVE[lang], page))
    assert not re.search(CHECK[lang], page), (name, lang, re.search(CHECK[lang], page))


@over(name=SEEDS, lang=LANGS)
def test_a_polygon_caption_names_steps_the_page_has(name: str, lang: str) -> None:
    """A level polygon's caption names the steps whose equations it draws, and each is a step
    heading of the page (a caption naming Step 0 or a step not written is a broken reference)."""
    page = rendered(name, lang, "md", drawings=False)
    headings = {int(n) for n in re.findall(HEADING[lang], page)}
    for first, last in re.findall(STEPS[lang], page):
        named = {int(first)} | ({int(last)} if last else set())
        assert named <= headings and min(named) >= 1, (name, lang, named, headings)


def test_the_readers_cases_by_hand() -> None:
    """C5-1.4's Willis check and polygon caption, read by hand: five velocity steps, the check
    names «Velocities»."""
    page = rendered("seed_c5_1_4_epicyclic", "en", "md", drawings=False)
    assert "With the angular velocities found in “Velocities”, (7·ω − ω) / (−ω − ω) = −3" in page
    # the steps whose equations draw the polygon's black arrows (nineteenth round (d)): none
    # since round 27b (every planet turns about its centre, the sun about O); C5-E.6's Step 4
    assert "of the equations of Step" not in page
    ca = rendered("seed_c5_e6_bicycle", "ca", "md", drawings=False)
    assert "les velocitats relatives de les equacions dels passos 2 a 4" in ca     # Step 2: v_C = v_CJ (round 29a)
    eu = rendered("seed_c5_1_7_semicylinder", "eu", "md", drawings=False)
    assert "1. urratseko ekuazioen terminoak" in eu
