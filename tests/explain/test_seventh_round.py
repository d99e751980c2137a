"""Issue 30, seventh round: the fifth audit's items, each a rule or a model change that
matches the course notes (seed 002), checked on the pages a student reads."""
from __future__ import annotations

import re

import pytest


from .helpers import LANGS, explained, rendered, over, model_tree

# -- (a) the vehicles ask what the notes ask: no acceleration part -----------------------------------------------------
# C5-2.1 asks the chassis' centre, the precession ψ̇, the rear left wheel's centre velocity and
# its spin φ̇; C5-2.2 the spin ω′ of S2's wheels (through v_O, v_P, S2's centre and ω_S2).
# Nothing there is an acceleration, so the page has no acceleration part and states no
# acceleration datum (the drivers' "a_F along (1; 1) is 0", "a_W1 = (0; 0)").
VEHICLES = ("seed_c5_2_1_tricycle", "seed_c5_2_2_articulated")


@over(name=VEHICLES)
def test_a_vehicle_asks_no_acceleration(name):
    asks = model_tree(name)["ask"]
    assert not {kind for ask in asks for kind in ask} & {"acceleration", "intrinsic", "alpha", "curvature"}
    _, doc = explained(name)
    assert not any(s.title.key == "sec.accelerations" for s in doc.sections), name
    for lang in LANGS:
        page = rendered(name, lang, drawings=False)
        assert not re.search(r"\ba_\{?[A-Z]", page), (name, lang)


# -- (b) C5-2.2's wheel centres read as wheel centres, not as joints ---------------------------------------------------
# C1, C2 on S1 (heading +x: C1 at +a/2 is on its left) and C3, C4 on S2 (heading (1; 1), C3 on
# its left) are the four wheels' centres, as the notes call C4 ("the centre of the right wheel").
CENTRE_WORDS = {"en": "wheel of S", "es": "rueda", "ca": "roda", "eu": "gurpilaren zentroa"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_articulated_vehicles_wheels_are_centres(lang):
    page = rendered("seed_c5_2_2_articulated", lang, drawings=False)
    rows = {m.group(1): m.group(2) for m in re.finditer(r"^\| (C\d) \| ([^|]+) \|", page, re.M)}
    assert sorted(rows) == ["C1", "C2", "C3", "C4"], rows
    for point, words in rows.items():
        assert CENTRE_WORDS[lang] in words and "*" not in words, (lang, point, words)


# -- (c) a model's own words write its symbols as the page does --------------------------------------------------------
# C5-E.6's remark ties the chainring and sprocket by their rates as the page writes them (ω,
# not the notes' Ω); in HTML the symbols typed X_sub in a model's words (its remark's ω_pinyó,
# its note's ℜ_P, the slides' v_B) are set as the page sets symbols, with a <sub>; Markdown
# writes a subscript with _ itself, so its text stays as typed.
def _html_text(name: str, lang: str) -> str:
    page = rendered(name, lang, "html", drawings=False)
    return re.sub(r"<svg.*?</svg>", "", page, flags=re.S)


RATES = {"en": ("sprocket", "chainring"), "es": ("piñón", "plato"), "ca": ("pinyó", "plat"), "eu": ("pinoia", "platera")}


@pytest.mark.parametrize("lang", LANGS)
def test_the_bicycles_remark_writes_the_pages_rates(lang):
    small, big = RATES[lang]
    # the statement's "(r ω_sprocket = R ω_chainring)" is gone (twenty-ninth round (b): the Data
    # write no shortened subscript before the notation line); the page writes no Ω nor ω_ raw
    html = _html_text("seed_c5_e6_bicycle", lang)
    assert "Ω" not in html and f"ω_{small}" not in html
    # the remark writes the page's v_P since the twenty-fourth round (e) (was the notes' v(P))
    normal = "N" if lang == "eu" else "n"        # the Basque slides' a^N (twenty-seventh round (g)),
    # with its point as the page writes it since the twenty-ninth round (a): a_P^N, not aᴺ
    assert (f"<i>ℜ</i><sub>P</sub> = <i>v</i><sub>P</sub>²/<i>a</i><sub>P</sub><sup>{normal}</sup>" in html
            and "ℜ_P" not in html)


def test_a_data_remarks_symbol_is_subscripted_in_html():
    html = _html_text("seed_001_p_pair_coriolis", "ca")
    assert "direcció de <i>v</i><sub>B</sub> (perpendicular a EB)" in html and "v_B" not in html
    assert "direcció de v_B (perpendicular a EB)" in rendered("seed_001_p_pair_coriolis", "ca", drawings=False)


# -- (d) the ground's word is introduced where the fixed part is listed ------------------------------------------------
# A ground named after a part with a shape (C5-1.6's fixed pulley …) is the reference of the
# motions later, "*lurra* solidoarekiko": the structure's table says that word at the part.
# A ground with no shape (C5-1.5's ceiling) keeps its one name and its "fixed" mark.
GROUND = {"en": "*ground*", "es": "*suelo*", "ca": "*terra*", "eu": "*lurra*"}
PARTS = {"seed_c5_1_6_belt": {"en": "fixed pulley", "eu": "polea finkoa"},
         "seed_c5_1_7_semicylinder": {"en": "semicylinder", "eu": "euskarri erdizilindrikoa"},
         "seed_c5_1_8_contact_points": {"en": "fixed cylinder", "eu": "zilindro finkoa"},
         "seed_c5_e1_cavity": {"en": "cylindrical track", "eu": "pista zilindrikoa"},
         "seed_c5_e2_gear_change": {"en": "fixed central wheel", "eu": "gurpil zentral finkoa"}}


@over(name=sorted(PARTS), lang=("en", "eu"))
def test_the_ground_word_is_introduced_at_the_part(name, lang):
    """Twenty-ninth round (b) reverses this: the fixed part is the reference by its own name
    ("relative to the *fixed pulley*"); no "(*ground*)" beside it, no ground the problem lacks."""
    page = rendered(name, lang, drawings=False)
    assert f"| 1 | *{PARTS[name][lang]}* (" in page
    assert GROUND[lang] not in page, (name, lang)


@pytest.mark.parametrize("lang", LANGS)
def test_a_shapeless_ground_keeps_its_fixed_mark(lang):
    page = rendered("seed_c5_1_5_pulley_block", lang, drawings=False)
    # twenty-seventh round (e): the mark kept; its own name is the text's reference, no tie
    assert re.search(r"^\| 1 \| \*[^*]+\* \((fixed|fijo|fix|finkoa)\)[ ,]", page, re.M)   # (, with strand 1: 29 b)


@pytest.mark.parametrize("lang,row", [("eu", "| 1 | *lurra* (finkoa) |"), ("ca", "| 1 | *terra* (fix) |")])
def test_a_ground_already_called_the_ground_is_not_named_twice(lang, row):
    """C5-E.6's ground carries its road's line but is already called *lurra* / *el terra*:
    its structure row says it is fixed, never "*lurra* (*lurra*)" (the sixth audit)."""
    text = rendered("seed_c5_e6_bicycle", lang, "md", False)
    assert row in text and "*lurra* (*lurra*)" not in text and "*terra* (*terra*)" not in text
