"""The ninth round: the notation and wording rules after the seventh independent audit
(docs/explain.md, "Ninth round"). Each test fails on main's output before the round.

- Catalan "relative to" in a subscript is rel (relatiu a; rel. until the twenty-fourth round (c)), never resp. (read as
  "respectivament") nor a slash (read as a division); es/en/eu rel as their notes (the Basque slides write v_rel).
- The symbols' legend ("Notació: ω_X és la velocitat angular …", once "En els símbols, ω_X: …") defines only the bodies whose own symbol
  the page writes; a relative centre no question asks and no construction names is not listed.
- A normal acceleration's magnitude is never set equal to a vector.
- Step titles go on in lower case after the colon (one style a page).
- Basque: "solido" is said at a body's first mention, then the case ending goes on the name.
- C5-1.6: the absolute rate on the left of the composition, ω_fixed = … = 0.
- A body's subscript never equals a parameter's name (C5-E.5: ω_rodaR, not ω_R beside R).
"""
from __future__ import annotations

import re

import pytest

from .helpers import SEEDS, rendered, over

RELATIVE_SUB = re.compile(r"_\{([^}]*)\}")


@over(name=["seed_001_p_pair_coriolis", "seed_c5_1_6_belt", "seed_c5_1_3_bar_in_sleeve"])
def test_catalan_relative_subscript_is_rel(name):
    """v_{B∈N rel. M}, ω_{politja fixa rel. braç}: the Catalan notes' REL in lower case with
    the abbreviation's point, or the model's own word (the 001 slides' rel, nineteenth round
    (a)); "resp." reads as "respectivament", a slash as a division."""
    from .helpers import explained

    word = explained(name)[0].model.wording.relative_word("ca")
    text = rendered(name, "ca", "md", drawings=False)
    subs = RELATIVE_SUB.findall(text)
    assert word in ("rel.", "rel") and any(f" {word} " in s for s in subs), name
    assert not any("resp." in s or "/" in s for s in subs), [s for s in subs if "resp." in s or "/" in s][:3]


@pytest.mark.parametrize("lang,word", [("es", " rel "), ("en", " rel "), ("eu", " rel ")])
def test_relative_subscript_in_the_other_languages(lang, word):
    """The same symbol in es/en/eu (rel: the Basque slides write v_rel, a_rel)."""
    text = rendered("seed_001_p_pair_coriolis", lang, "md", drawings=False)
    subs = RELATIVE_SUB.findall(text)
    assert any(word in s for s in subs)
    assert not any("/" in s for s in subs)


def test_catalan_centres_intro_says_rel():
    """How two names are joined is said with the same word, «rel», where the page first
    writes such a symbol (since the twenty-fifth round (a): the notation line, before the
    steps, not the centres' section, which wrote no centre with «rel»): C5-1.6's fixed
    pulley seen from the arm."""
    text = rendered("seed_c5_1_6_belt", "ca", "md", drawings=False)
    assert "(dos noms units per «rel», relatiu a: el primer sòlid respecte del segon)" in text
    first = text.index("rel braç}")              # the symbol's first writing: the line that defines it
    assert text.rfind("\n", 0, first) == text.rfind("\n", 0, text.index("«rel», relatiu a"))
    assert first < text.index("## Velocitats")
    assert "resp." not in text
    assert "units per «rel»" not in rendered("seed_c5_1_3_bar_in_sleeve", "ca", "md", drawings=False)


@over(name=SEEDS)
def test_symbols_legend_only_for_symbols_written(name):
    """Each "Notació: ω_X és la velocitat angular …" entry names a symbol the page writes
    elsewhere (C5-1.8's ω_terra was defined and never written)."""
    text = rendered(name, "ca", "md", drawings=False)
    for line in text.splitlines():
        if line.startswith("Notació: "):
            rest = text.replace(line, "")
            for sym in re.findall(r"(ω_(?:\{[^}]*\}|\S+?)) és la velocitat angular", line):
                assert sym in rest, (name, sym)


def test_unused_relative_centres_not_listed():
    """C5-1.2: the centres of the bar relative to each wheel (joints O and Q) and of OJ
    relative to OQ were listed and never used: I_OQ follows from the perpendiculars to v_O
    and v_Q, I_OJ from v_O and the floor's normal."""
    text = rendered("seed_c5_1_2_bar_on_inclined_wheels", "ca", "md", drawings=False)
    listed = re.findall(r"^(I_\{[^}]* (?:rel\.|resp\.) [^}]*\}):", text, re.M)
    assert listed == []
    assert re.search(r"^I_\{OQ\}: ", text, re.M) and re.search(r"^I_\{OJ\}: ", text, re.M)


def test_epicyclic_keeps_the_frame_centres_it_reasons_with():
    """C5-1.4: the planet's centre from the carrier's and the ring's (both at O), the
    relative centres at A1 and N not listed (the note names the points)."""
    text = rendered("seed_c5_1_4_epicyclic", "ca", "md", drawings=False)
    assert re.search(r"^I_\{portador\}: ", text, re.M) and re.search(r"^I_\{corona\}: ", text, re.M)
    assert not re.search(r"^I_\{rodeta1 (rel\.|resp\.) ", text, re.M)


@pytest.mark.parametrize("name,lang,towards", [
    ("seed_c5_1_7_semicylinder", "ca", "|a_C^n| = v_C² / OC, cap a O: a_C^n = (0; −r·ω²/3)"),
    ("seed_c5_1_7_semicylinder", "es", "|a_C^n| = v_C² / OC, hacia O: a_C^n = (0; −r·ω²/3)"),
    ("seed_c5_1_7_semicylinder", "en", "|a_C^n| = v_C² / OC, towards O: a_C^n = (0, −r·ω²/3)"),
])
def test_magnitude_then_vector(name, lang, towards):
    """The centre C runs on a circle about O: |a_C^n| = v_C²/OC, and the
    vector points to O. By hand (C5-1.7, J the contact, v_C = r·ω, OC = 3·r):
    v_C²/OC = r·ω²/3, towards O below C: (0; −r·ω²/3)."""
    text = rendered(name, lang, "md", drawings=False)
    assert towards in text
    assert not re.search(r"\^n = [^=\n]*(²|· [A-Z]+) = \(", text), "a magnitude set equal to a vector"


@over(name=["seed_c5_1_7_semicylinder", "seed_c5_1_8_contact_points", "seed_c5_e1_cavity",
                                  "seed_001_r_pairs"], lang=["ca", "eu"])
def test_no_magnitude_equals_vector(name, lang):
    """No term line `a^n = ω² · PC = (…)` or `= v² / OC = (…)` on any of the pages the audit named."""
    text = rendered(name, lang, "md", drawings=False)
    bad = re.search(r"^- a_\S+\^n = [^\n]*(²|² · [A-Za-z0-9]+|/ [A-Z]+) = \(", text, re.M)
    assert bad is None, bad.group(0)


@pytest.mark.parametrize("name", SEEDS)
@pytest.mark.parametrize("lang,step", [("ca", "Pas"), ("es", "Paso"), ("eu", "urratsa")])
def test_step_titles_lower_case_after_colon(name, lang, step):
    """"Pas 2: la palanca N" beside "Pas 1: entrada (sòlid motor) — la corredora"."""
    text = rendered(name, lang, "md", drawings=False)
    for line in text.splitlines():
        if line.startswith("### ") and step in line and ": " in line:
            after = line.split(": ", 1)[1].lstrip("*")
            assert not after[:1].isupper() or re.match(r"[A-Z0-9]{1,4}\b", after), line


def test_basque_solido_once_a_body():
    """C5-1.5 in Basque: "*2. polea* *2. kable-zatiaren* gainean", the word said once."""
    text = rendered("seed_c5_1_5_pulley_block", "eu", "md", drawings=False)
    assert "*2. polea* *2. kable-zatiaren* gainean errodatzen da" in text
    assert "*4. polea* *5. kable-zatiaren* gainean errodatzen da" in text     # the block's strand (eighth round)
    assert "*1. polea* solidoa *1. kable-zatia* solidoaren" not in text


def test_basque_numbered_bodies_keep_the_word():
    """A body named by its number keeps "solidoa" (3 solidoa): nothing to decline it on."""
    text = rendered("seed_001_r_pairs", "eu", "md", drawings=False)
    assert "solido" in text


@pytest.mark.parametrize("lang,absolute,relative,drag", [
    ("ca", "ω_politja1", "ω_{politja1 rel braç}", "ω_braç"),
    ("es", "ω_polea1", "ω_{polea1 rel brazo}", "ω_brazo"),
])
def test_belt_fixed_pulley_absolute_on_the_left(lang, absolute, relative, drag):
    """C5-1.6: Ω_AB = Ω_REL + Ω_ar with the fixed pulley's absolute rate on the left and its
    value 0 after the sum, not "0 = ω_{… rel braç} + ω_braç"."""
    text = rendered("seed_c5_1_6_belt", lang, "md", drawings=False)
    assert f"{absolute} = {relative} + {drag} = 0 ⇒ {relative} = −{drag}" in text
    assert f"0 = {relative}" not in text


@pytest.mark.parametrize("lang,label", [("ca", "roda3"), ("es", "rueda3"), ("en", "wheel3")])
def test_body_subscript_is_not_a_parameter(lang, label):
    """C5-E.5: the wheel of radius R is never ω_R beside R (since the twenty-ninth round (d)
    the *rear wheel*, ω_roda3 beside *roda 1* and *roda 2*, no longer ω_rodaR); by hand its rate is −v/R (its centre at v, its contact at rest, radius R)."""
    text = rendered("seed_c5_e5_unequal_wheels", lang, "md", drawings=False)
    assert not re.search(r"ω_R\b|ω_\{R ", text)
    assert f"ω_{label} = " in text and "−v/R" in text


@pytest.mark.parametrize("lang,named", [
    ("ca", "a J′, el peu de la perpendicular des de J a la guia"),     # twenty-fourth round (e):
    ("es", "en J′, el pie de la perpendicular desde J a la guía"),      # J′ defined where it is
    ("en", "at J′, the foot of the perpendicular from J to the guide"),  # first written
])
def test_guide_line_names_its_point(lang, named):
    """C5-1.3: the perpendicular to the guide through J holds the centre because of one point
    of the bar, the foot of that perpendicular, where v_REL ∥ v_ar (the notes); the page
    names it J′ (before: "el punt de la barra que hi és llisca …", unclear; thirteenth
    round (c): the notes' short statement, not a long bracket)."""
    text = rendered("seed_c5_1_3_bar_in_sleeve", lang, "md", drawings=False)
    assert named in text
    assert "que hi és llisca" not in text
