"""Issue 30, fourteenth round (a): what an English and Spanish teacher still edited on main's
pages after the thirteenth round, each a rule checked over the seeds in every language where
it applies (each test fails on the pages main wrote at a75cf3b):

1. the drag is the motion of the point of the moving frame that coincides with the point;
2. a reference to what a step found names the step by its number (a centre from a rate, a
   contact's material point, a centre a vehicle's step placed, the models' notes);
3. a shortened subscript tells its body from the page's others: among meshing wheels the
   word "wheel" does not (ω_sun, ω_central); a body's index is no other language's initial;
4. Willis: a fixed wheel's axis is the fixed axis through O, it does not "turn about" it;
5. the Spanish models' words (manguito, eje del pedalier, se desplaza lateralmente);
6. a strand translates when its ends have the same velocity *component* across it;
7. a parameter inside a formula is a symbol, not an emphasised word; a spin is said
   "at r φ̇, where φ̇ is its spin";
8. C5-2.2's note: "by equiprojectivity with O".
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered, over

COMPOSITION = ("seed_001_p_pair_coriolis", "seed_001_rolling_pair", "seed_c5_1_3_bar_in_sleeve")
# the drag lines say the word alone: the section's intro defines it once (twenty-first round (a))
# (each half says which it opens, twenty-fourth round (c): "Velocities. Drag:")
DRAG = {"en": ". Drag:\n", "es": ". Arrastre:\n", "ca": ". Arrossegament:\n", "eu": ". Arrastrea:\n"}
WHERE_IT_IS = ("where the point is", "where it is)", "donde está el punto", "donde está)",
               "on és el punt", "on és)")


def page(name: str, lang: str) -> str:
    return rendered(name, lang, "md", drawings=False)


@over(name=SEEDS, lang=LANGS)
def test_the_drag_is_the_coinciding_point(name, lang):
    """Rule 1: every composition section says the drag twice (velocities, accelerations) as
    the point of the moving frame that coincides with the point; never "where the point is"."""
    text = page(name, lang)
    for old in WHERE_IT_IS:
        assert old not in text, (name, lang, old)
    assert text.count(DRAG[lang]) == (2 if name in COMPOSITION else 0), (name, lang)


# the vague "above" a step's finding was referred to by, and a reference by number
ABOVE = ("found above through", "hallada arriba a través", "trobada més amunt a través",
         "spin found above", "hallada arriba es", "trobada a dalt", "goian aurkitutako",
         "written in step", "escrita en el paso", "escrita al pas", "urratsean idatzia",
         "in the velocity step of", "en el paso de velocidades", "al pas de velocitats", "abiadura-urratsean")
STEP_REF = {"en": r"(?:in|In) Step (\d+)", "es": r"en el paso (\d+)", "ca": r"al pas (\d+)", "eu": r"(\d+)\. urratsean"}
STEP_TITLE = {"en": r"^### Step (\d+):", "es": r"^### Paso (\d+):", "ca": r"^### Pas (\d+):",
              "eu": r"^### (\d+)\. urratsa:"}


@over(name=SEEDS, lang=LANGS)
def test_what_a_step_found_is_referred_to_by_its_number(name, lang):
    """Rule 2: no "found above" for what a step found; each step a reference names is on the page."""
    text = page(name, lang)
    for old in ABOVE:
        assert old not in text, (name, lang, old)
    titles = {int(n) for n in re.findall(STEP_TITLE[lang], text, re.M)}
    for n in re.findall(STEP_REF[lang], text.split("\n## ", 3)[-1]):
        assert int(n) in titles, (name, lang, n)


# by hand: which step finds each rate a centre is placed from, and the rest of rule 2
# (C5-E.5: wheel 1 is asked first, so its step comes before wheel 2's: the sixteenth round (b))
BY_NUMBER = [("seed_c5_1_6_belt", {"en": "found in Step 2 through the *belt*", "es": "hallada en el paso 2 a través de la *correa*"}),
             ("seed_c5_e5_unequal_wheels", {"en": "found in Step 3 through the *rear wheel*",
                                            "es": "hallada en el paso 3 a través de la *rueda trasera*"}),
             ("seed_c5_e6_bicycle", {"en": "found in Step 4 through the *chain*", "es": "hallada en el paso 4 a través de la *cadena*"}),
             ("seed_c5_2_1_tricycle", {"en": "the wheel C1 (rear left) found in Step 1",
                                       "es": "rueda C1 (trasera izquierda) hallada en el paso 1"}),
             ("seed_001_rolling_pair", {"en": "m/s, found in Step 3.", "es": "m/s, hallada en el paso 3."})]


@pytest.mark.parametrize("name,said", BY_NUMBER)
@pytest.mark.parametrize("lang", ("en", "es"))
def test_the_steps_named_by_hand(name, said, lang):
    """C5-1.6's moving pulley gets its ω through the belt in Step 2 (the only step after the
    arm's), E.5's wheel 1 in Step 4 (its own step), E.6's chainring in Step 4 (the chain's,
    after the front wheel's since round 27b);
    C5-2.1 has one step; 001's contact point F is written in Step 3 (the roller's)."""
    assert said[lang] in page(name, lang)


WHEEL_WORDS = {"en": "wheel", "es": "rueda", "ca": "roda", "eu": "gurpila"}


@over(name=("seed_c5_1_4_epicyclic", "seed_c5_e2_gear_change"), lang=LANGS)
def test_no_meshing_wheel_is_written_by_the_word_wheel(name, lang):
    """Rule 3: where wheels mesh with wheels, ω_wheel (ω_roda, ω_rueda, ω_gurpila) does not
    tell the sun / the fixed central wheel from the planets, which are wheels too."""
    text = page(name, lang)
    assert f"ω_{WHEEL_WORDS[lang]} " not in text and f"ω_{WHEEL_WORDS[lang]})" not in text, (name, lang)


@pytest.mark.parametrize("name,lang,symbol", [
    ("seed_c5_1_4_epicyclic", "en", "ω_sun"),
    ("seed_c5_1_4_epicyclic", "ca", "ω_central"),
    ("seed_c5_1_4_epicyclic", "eu", "ω_zentrala"),
    ("seed_c5_e2_gear_change", "en", "ω_central"),
    ("seed_c5_e2_gear_change", "es", "ω_central")])
def test_the_meshing_wheels_symbol_is_its_distinguishing_word(name, lang, symbol):
    """The sun wheel's ω_sun, E.2's fixed central wheel's ω_central: written on the page (the
    fifteenth round (b) writes no legend for a subscript read off the name)."""
    assert symbol in page(name, lang)


def test_a_wheel_word_stays_where_no_wheels_mesh():
    """Rule 3 is narrow: C5-1.8's single wheel keeps ω_wheel; E.4's wheels, which share the
    word, are that word with their ranks (ω_wheel3 for the upper wheel: twenty-seventh round
    (g), where they kept their whole names, ω_{upper wheel})."""
    assert "ω_wheel" in page("seed_c5_1_8_contact_points", "en")
    assert "ω_wheel3 " in page("seed_c5_e4_upper_wheel", "en")


@pytest.mark.parametrize("lang", LANGS)
def test_the_slider_is_not_written_by_an_english_s(lang):
    """Rule 3: 001's slider was ω_S on every page, the S of "slider" (and the slides' S is
    the axes turning with N, ω_S = ω_N): each language writes it by its own word."""
    text = page("seed_001_rolling_pair", lang)
    assert "ω_S " not in text and "α_S " not in text
    word = {"en": "slider", "es": "corredera", "ca": "corredora", "eu": "irristagailua"}[lang]
    assert f"ω_{word} = " in text


WILLIS_TURN = {"en": "which turn about the fixed axis", "es": "que giran alrededor del eje fijo",
               "ca": "que giren al voltant de l’eix fix", "eu": "ardatz finkoaren inguruan biratzen dira"}
WILLIS_AXIS = {"en": "whose axis is the fixed axis through O", "es": "cuyo eje es el eje fijo por O",
               "ca": "l’eix de les quals és l’eix fix que passa per O",
               "eu": "horien ardatza O puntutik pasatzen den ardatz finkoa da"}


@pytest.mark.parametrize("lang", LANGS)
def test_a_fixed_wheel_does_not_turn_about_its_axis(lang):
    """Rule 4: E.2's central wheel is fixed: its axis is the fixed axis; C5-1.4's sun and
    ring both turn (7ω, −ω), so they turn about it."""
    fixed, turning = page("seed_c5_e2_gear_change", lang), page("seed_c5_1_4_epicyclic", lang)
    assert WILLIS_AXIS[lang] in fixed and WILLIS_TURN[lang] not in fixed
    assert WILLIS_TURN[lang] in turning and WILLIS_AXIS[lang] not in turning


@pytest.mark.parametrize("name,old,new", [
    ("seed_c5_1_3_bar_in_sleeve", "pasador del soporte", "| S | manguito (centro del *soporte*) |"),
    ("seed_c5_e6_bicycle", "eje de los pedales", "| C | eje del pedalier |"),
    ("seed_c5_1_1_pulley_on_cable", "hacia el lado", "se desplaza lateralmente con celeridad v")])
def test_the_spanish_models_words(name, old, new):
    """Rule 5, the models' own Spanish words."""
    text = page(name, "es")
    assert old not in text and new in text


# since the twenty-ninth round (b), as the notes say it: the strand stays vertical, it translates
COMPONENT = {"en": "it stays vertical, tangent to",
             "es": "se mantiene vertical, tangente a",
             "ca": "es manté vertical, tangent a",
             "eu": "bertikal mantentzen da"}


@pytest.mark.parametrize("lang", LANGS)
def test_a_strand_translates_by_its_velocity_component(lang):
    """Rule 6: C5-1.5's strands 2-4 (the ends' velocities differ along the strand; their
    components across it are equal)."""
    assert page("seed_c5_1_5_pulley_block", lang).count(COMPONENT[lang]) == 3


EMPHASISED_IN_FORMULA = re.compile(r"(?:[=/·×+−(]|\bat|\ba) \*[^\s*]{1,6}\*(?=\s*[=/·×+−)φω])")


@over(name=SEEDS, lang=LANGS)
def test_no_parameter_is_emphasised_inside_a_formula(name, lang):
    """Rule 7: "/ *r*", "*s* = 0.4 m", "at *r* φ̇": a parameter in a formula is a symbol."""
    text = "\n".join(line for line in page(name, lang).splitlines() if not line.startswith("|"))
    assert not EMPHASISED_IN_FORMULA.search(text), (name, lang, EMPHASISED_IN_FORMULA.search(text))


SPIN = {"en": "with the speed r φ̇, where φ̇ is its spin about its axle, so:",       # sixteenth round
        "es": "con celeridad r φ̇, donde φ̇ es su rotación propia alrededor de su eje, de modo que:",
        "ca": "amb celeritat r φ̇, on φ̇ és la seva rotació pròpia al voltant del seu eix, de manera que:",
        "eu": "r φ̇ abiaduraz, φ̇ gurpilak bere ardatzaren inguruan duen biraketa propioa izanik"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_spin_is_named_where_it_is_used(lang):
    text = page("seed_c5_2_1_tricycle", lang)
    assert SPIN[lang] in text
    assert re.search(r"φ̇ = \|v_\{C1∈[^}]+\}\| / r = ", text)        # a magnitude (sixteenth round)


def test_the_articulated_vehicles_note_says_equiprojectivity_with_o():
    """Rule 8, and rule 2 in the model's note: P's speed is derived in Step 1, the page's only step."""
    text = page("seed_c5_2_2_articulated", "en")
    assert "(by equiprojectivity with O), as derived in Step 1." in text and "P moves with O" not in text
